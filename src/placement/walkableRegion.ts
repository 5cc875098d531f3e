import { assertArrayLike, assertCoordinates, assertFinite, assertOptions, assertOptionalNumber } from '../validate.js';
import { TriangleBVH, type RayHit } from '../geometry/TriangleBVH.js';

/** Options of {@link WalkableRegion}. */
export interface WalkableRegionOptions {

	/** The world's up direction (non-zero; normalised). Default +y. */
	up?: ArrayLike<number>;

	/** How far above a floor a point still counts (> 0, in the triangles' units). Default 2: about a character's height in metres. */
	height?: number;

	/** Steepest floor, in degrees from horizontal (0 ≤ maxSlope < 90). Default 45. */
	maxSlope?: number;

	/**
	 * Per triangle, the side its material draws, as `gatherDrawnSides` reports it: 1 the front
	 * (counter-clockwise) side, −1 the back, 0 both. Default all 1.
	 */
	sides?: ArrayLike<number>;

}

/**
 * "Where characters go", derived from the level: floor-facing triangles plus a height band above
 * them. A triangle is floor-facing when its drawn side faces up — normal · up ≥ cos( maxSlope ) on
 * that side (either side for a double-sided one). A point is walkable when the first surface
 * straight below it (a ray along −up through every triangle) is floor-facing and at most `height`
 * below: the air above floors, stairs, ramps and table tops (and under a table, where the floor is
 * the first surface below), not inside a slab (its underside is first), high above the floor, over
 * a steep slope or outside the level with nothing below. Use it as `region.walkable` of
 * `reduceProbes` and `regionWeights`.
 */
export class WalkableRegion {

	/** Every triangle of the level (floors and the rest: what a downward ray can meet first). */
	readonly bvh: TriangleBVH;

	/** Per triangle: 1 when it is floor-facing. */
	readonly floorFacing: Uint8Array;

	/** How many triangles are floor-facing (at least 1). */
	readonly floorTriangleCount: number;

	/** The unit up direction. */
	readonly up: Float64Array;

	/** The height band above the floors. */
	readonly height: number;

	private readonly hit: RayHit = { t: - 1, triangle: - 1 };

	/**
	 * @param triangles 9 floats per triangle (a, b, c), in world space — e.g. `gatherWorldGeometry( level ).triangles`.
	 * @param options Up direction, height band, steepest slope and drawn sides.
	 * @throws RangeError when no triangle is floor-facing (the region would be empty), or for bad options.
	 */
	constructor( triangles: ArrayLike<number>, options: WalkableRegionOptions = {} ) {

		const where = 'WalkableRegion';
		assertArrayLike( where, 'triangles', triangles );
		if ( triangles.length % 9 !== 0 ) {

			throw new RangeError( `${where}: triangles must hold 9 floats (a, b, c) per triangle, got length ${triangles.length}.` );

		}

		assertFinite( where, 'triangles', triangles );
		assertOptions( where, 'options', options );
		const { up = [ 0, 1, 0 ], height = 2, maxSlope = 45, sides } = options;
		assertOptionalNumber( where, 'options.height', height, 0 );
		if ( ! ( height > 0 ) ) throw new RangeError( `${where}: options.height must be > 0, got ${height}.` );
		assertOptionalNumber( where, 'options.maxSlope', maxSlope, 0 );
		if ( ! ( maxSlope < 90 ) ) throw new RangeError( `${where}: options.maxSlope must be in 0..90 degrees (90 excluded), got ${maxSlope}.` );
		this.up = readUp( where, up );
		const count = triangles.length / 9;
		const drawn = readSides( where, sides, count );

		const cosine = Math.cos( maxSlope * Math.PI / 180 );
		const [ ux, uy, uz ] = this.up;
		this.floorFacing = new Uint8Array( count );
		let floors = 0;
		for ( let t = 0; t < count; t ++ ) {

			const k = 9 * t, ax = triangles[ k ], ay = triangles[ k + 1 ], az = triangles[ k + 2 ];
			const e1x = triangles[ k + 3 ] - ax, e1y = triangles[ k + 4 ] - ay, e1z = triangles[ k + 5 ] - az;
			const e2x = triangles[ k + 6 ] - ax, e2y = triangles[ k + 7 ] - ay, e2z = triangles[ k + 8 ] - az;
			const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
			const length = Math.hypot( nx, ny, nz );
			if ( ! ( length > 0 ) ) continue; // degenerate: faces nowhere
			const upness = ( nx * ux + ny * uy + nz * uz ) / length; // of the front (counter-clockwise) side
			const side = drawn[ t ];
			const faces = side === 1 ? upness : side === - 1 ? - upness : Math.abs( upness );
			if ( faces >= cosine ) {

				this.floorFacing[ t ] = 1;
				floors ++;

			}

		}

		if ( floors === 0 ) {

			throw new RangeError( `${where}: none of the ${count} triangles faces up (within ${maxSlope}° of up on its drawn side): the walkable region would be empty.` );

		}

		this.floorTriangleCount = floors;
		this.height = height;
		this.bvh = new TriangleBVH( triangles );

	}

	/** Whether (x, y, z) is walkable: the first surface straight below it is floor-facing and within `height`. */
	contains( x: number, y: number, z: number ): boolean {

		assertCoordinates( 'WalkableRegion.contains', x, y, z );
		const up = this.up;
		this.bvh.raycastFirst( x, y, z, - up[ 0 ], - up[ 1 ], - up[ 2 ], this.height, this.hit );
		return this.hit.triangle >= 0 && this.floorFacing[ this.hit.triangle ] === 1;

	}

}

/** The up option as a unit vector. */
function readUp( where: string, up: ArrayLike<number> ): Float64Array {

	assertArrayLike( where, 'options.up', up );
	if ( up.length !== 3 ) throw new RangeError( `${where}: options.up must hold x, y, z, got length ${up.length}.` );
	assertFinite( where, 'options.up', up );
	const length = Math.hypot( up[ 0 ], up[ 1 ], up[ 2 ] );
	if ( ! ( length > 0 ) ) throw new RangeError( `${where}: options.up must be a non-zero direction.` );
	return Float64Array.of( up[ 0 ] / length, up[ 1 ] / length, up[ 2 ] / length );

}

/** The sides option, checked: one of 1, −1, 0 per triangle (default all 1). */
function readSides( where: string, sides: ArrayLike<number> | undefined, count: number ): ArrayLike<number> {

	if ( sides === undefined ) return new Int8Array( count ).fill( 1 );
	assertArrayLike( where, 'options.sides', sides );
	if ( sides.length !== count ) {

		throw new RangeError( `${where}: options.sides must have one entry per triangle (${count}), got length ${sides.length}.` );

	}

	for ( let t = 0; t < count; t ++ ) {

		const s = sides[ t ];
		if ( s !== 1 && s !== - 1 && s !== 0 ) throw new RangeError( `${where}: options.sides[${t}] must be 1, -1 or 0, got ${String( s )}.` );

	}

	return sides;

}
