import type { RayHit, TriangleBVH } from '../geometry/TriangleBVH.js';
import { findClosedShells, type ClosedShells } from '../geometry/findClosedShells.js';
import { facing, windingAlongRay } from '../geometry/windingAlongRay.js';

/**
 * "Is this point inside a solid?" for scenes as three.js draws them — closed props, walls with
 * thickness, rooms drawn from inside (`BackSide`), rooms of open single- or double-sided quads —
 * by a majority vote over fixed rays. A ray votes "inside" when
 *
 * 1. it leaves more closed shells than it enters (the winding number of the point with respect to
 *    the scene's closed shells, oriented by `findClosedShells`, is positive): the point is inside a
 *    closed prop, a wall slab, the solid around a room drawn from inside, or several overlapping
 *    solids; or
 * 2. its first hit is a single-sided surface seen from its undrawn side — the side three culls, so
 *    a probe there would see through it: the point is behind a wall of open quads, inside loose
 *    facades, or outside a room drawn from inside.
 *
 * A double-sided surface has no undrawn side: rays that first hit one vote by rule 1 alone, so an
 * open double-sided wall has no inside, and a closed double-sided (or inconsistently drawn) shell
 * counts as a solid unless {@link InsideTest.treatAsRooms} was told that a point of open space
 * lies in it.
 */
export class InsideTest {

	/** The triangles. */
	readonly bvh: TriangleBVH;

	/** Per triangle: 1 front (counter-clockwise) side drawn, −1 back side drawn, 0 both. */
	readonly sides: Int8Array;

	/** The closed shells and their orientation (changed by {@link InsideTest.treatAsRooms}). */
	readonly shells: ClosedShells;

	/** Ray directions of the vote, x, y, z each (an odd count, so the vote cannot tie). */
	readonly directions: ArrayLike<number>;

	private readonly hit: RayHit = { t: - 1, triangle: - 1 };

	/**
	 * @param bvh The scene's triangles.
	 * @param sides Per triangle, in `bvh.triangles` order (checked by the caller).
	 * @param directions Ray directions, non-zero (checked by the caller).
	 */
	constructor( bvh: TriangleBVH, sides: Int8Array, directions: ArrayLike<number> ) {

		this.bvh = bvh;
		this.sides = sides;
		this.directions = directions;
		this.shells = findClosedShells( bvh.triangles, sides );

	}

	/** Whether more than half of the rays from (x, y, z) vote "inside". Allocation-free. */
	isInside( x: number, y: number, z: number ): boolean {

		const d = this.directions, rays = d.length / 3;
		let inside = 0;
		for ( let r = 0; r < rays; r ++ ) {

			if ( this.rayVotesInside( x, y, z, d[ 3 * r ], d[ 3 * r + 1 ], d[ 3 * r + 2 ] ) ) inside ++;
			// Stop as soon as the vote is decided either way: saves up to half the rays.
			if ( 2 * inside > rays || 2 * ( r + 1 - inside ) >= rays ) break;

		}

		return 2 * inside > rays;

	}

	/**
	 * Turns every closed shell whose orientation was chosen (double-sided, inconsistently drawn)
	 * and which encloses one of `points` inside out: its inside becomes a room — open space — and
	 * its outside solid. For a room modelled as a closed double-sided box, given the player's spawn.
	 * @param points x, y, z each.
	 * @returns The number of shells turned.
	 */
	treatAsRooms( points: ArrayLike<number> ): number {

		const { orientation, shell, count, fromSides } = this.shells;
		const tri = this.bvh.triangles, triangleCount = shell.length;
		const winding = new Float64Array( count );
		let turned = 0;
		for ( let p = 0; p < points.length; p += 3 ) {

			winding.fill( 0 );
			for ( let t = 0; t < triangleCount; t ++ ) {

				const s = shell[ t ];
				if ( s < 0 || fromSides[ s ] === 1 ) continue;
				winding[ s ] += orientation[ t ] * solidAngle( tri, t, points[ p ], points[ p + 1 ], points[ p + 2 ] );

			}

			for ( let s = 0; s < count; s ++ ) {

				// 4π inside an outward shell (its chosen orientation), 0 outside it.
				if ( fromSides[ s ] === 1 || ! ( winding[ s ] > 2 * Math.PI ) ) continue;
				for ( let t = 0; t < triangleCount; t ++ ) if ( shell[ t ] === s ) orientation[ t ] = - orientation[ t ];
				turned ++;

			}

		}

		return turned;

	}

	/** One ray's vote (rules 1 and 2 of the class). */
	private rayVotesInside( x: number, y: number, z: number, dx: number, dy: number, dz: number ): boolean {

		const hit = this.hit;
		if ( windingAlongRay( this.bvh, this.shells.orientation, x, y, z, dx, dy, dz, hit ) > 0 ) return true;
		const t = hit.triangle;
		if ( t < 0 || this.sides[ t ] === 0 ) return false;
		// Undrawn side seen: the back of a front-drawn triangle, or the front of a back-drawn one.
		return ( facing( this.bvh.triangles, t, dx, dy, dz ) > 0 ) === ( this.sides[ t ] > 0 );

	}

}

/**
 * Signed solid angle of triangle t seen from p (Van Oosterom & Strackee, 1983): positive when p is
 * on the side its winding normal points away from, so an outward closed shell sums to 4π inside.
 */
function solidAngle( tri: ArrayLike<number>, t: number, px: number, py: number, pz: number ): number {

	const k = 9 * t;
	const ax = tri[ k ] - px, ay = tri[ k + 1 ] - py, az = tri[ k + 2 ] - pz;
	const bx = tri[ k + 3 ] - px, by = tri[ k + 4 ] - py, bz = tri[ k + 5 ] - pz;
	const cx = tri[ k + 6 ] - px, cy = tri[ k + 7 ] - py, cz = tri[ k + 8 ] - pz;
	const la = Math.hypot( ax, ay, az ), lb = Math.hypot( bx, by, bz ), lc = Math.hypot( cx, cy, cz );
	const triple = ax * ( by * cz - bz * cy ) - ay * ( bx * cz - bz * cx ) + az * ( bx * cy - by * cx );
	const denominator = la * lb * lc + ( ax * bx + ay * by + az * bz ) * lc + ( ax * cx + ay * cy + az * cz ) * lb
		+ ( bx * cx + by * cy + bz * cz ) * la;
	return 2 * Math.atan2( triple, denominator );

}
