import { TriangleBVH } from '../geometry/TriangleBVH.js';
import { assertOptionalNumber, assertPoints } from '../validate.js';
import { blockedLatticeEdges } from './blockedLatticeEdges.js';

/**
 * Default lattice resolution of {@link ReachableSpace}: the longest side of its box is divided into
 * this many cells (≤ 64³ = 262,144 lattice points).
 */
export const REACHABLE_CELLS = 64;

// Where the lattice points sit inside their cells, per axis (fractions of a cell): off the centre
// by uneven amounts so that lattice lines do not run in the planes modelled walls sit in (a
// segment in a wall's plane is parallel to it and would slip through).
const PHASE = [ 0.5123, 0.4871, 0.5347 ];

/** Options of {@link ReachableSpace}. */
export interface ReachableSpaceOptions {

	/** Lattice spacing (scene units, > 0); default: the box's longest side / {@link REACHABLE_CELLS}. */
	cellSize?: number;

	/** The box to flood, [ minX, minY, minZ, maxX, maxY, maxZ ]; default: the triangles' bounds, grown to hold the seeds. */
	bounds?: ArrayLike<number>;

}

/**
 * The open space reachable from seed points (the player's spawn, say) without crossing a triangle:
 * a flood fill over a lattice of points in a box. Two neighbouring lattice points (6-neighbours)
 * are connected when the segment between them crosses no triangle (`TriangleBVH.segmentBlocked`, answered for every edge at once);
 * a seed starts the fill at each corner of its lattice cell it sees. A point is reachable when it
 * sees a reached corner of its own cell. Points outside the box are not reachable: by default the
 * box is the scene's bounding box, so the outside of a level counts as unreachable even where
 * a window or an open side leads to it.
 *
 * What it removes: closed cavities (the inside of a sealed room, a prop or a wall, from the side
 * the player cannot get to) and everything beyond the level's walls. What it can miss: a passage
 * narrower than about one cell between lattice lines, which the fill may not find (pass a smaller
 * `cellSize`), and a crack in a mesh that a lattice segment happens to pass through, which lets
 * the fill leak.
 *
 * Cost: the lattice edges a triangle crosses are found once, in the constructor, from the
 * triangles' side (`blockedLatticeEdges`: about the lattice lines each triangle spans), then the
 * fill reads them; queries test at most 8 segments.
 */
export class ReachableSpace {

	/** Lattice points per axis. */
	readonly counts: Int32Array;

	/** Lattice spacing per axis (the box's side divided by its count, about `cellSize`). */
	readonly spacing: Float64Array;

	/** The box, [ minX, minY, minZ, maxX, maxY, maxZ ]. */
	readonly bounds: Float64Array;

	/** Per lattice point (x fastest): 1 when the fill reached it. */
	readonly reached: Uint8Array;

	private readonly bvh: TriangleBVH;

	/**
	 * @param bvh The scene's triangles.
	 * @param seeds x, y, z per seed (at least one), in open space: a seed inside a wall floods the
	 * wall (`classifyPoints` checks this with its inside test before building one).
	 * @param where, name How errors name the call and the seeds (default `ReachableSpace`, `seeds`).
	 * @throws RangeError naming the seed when one lies on a surface or sees no lattice point of its cell.
	 */
	constructor( bvh: TriangleBVH, seeds: ArrayLike<number>, options: ReachableSpaceOptions = {}, where = 'ReachableSpace', name = 'seeds' ) {

		if ( ! ( bvh instanceof TriangleBVH ) ) throw new TypeError( `${where}: bvh must be a TriangleBVH.` );
		assertPoints( where, name, seeds, 1 );
		assertOptionalNumber( where, 'options.cellSize', options.cellSize, Number.MIN_VALUE );
		this.bvh = bvh;
		const box = this.bounds = new Float64Array( 6 );
		if ( options.bounds !== undefined ) {

			assertPoints( where, 'options.bounds', options.bounds, 2 );
			if ( options.bounds.length !== 6 || ! ( options.bounds[ 0 ] <= options.bounds[ 3 ] && options.bounds[ 1 ] <= options.bounds[ 4 ]
				&& options.bounds[ 2 ] <= options.bounds[ 5 ] ) ) {

				throw new RangeError( `${where}: options.bounds must be [ minX, minY, minZ, maxX, maxY, maxZ ] with min ≤ max.` );

			}

			box.set( Array.from( options.bounds ) );

		} else {

			if ( bvh.triangleCount > 0 ) box.set( bvh.nodeBounds.subarray( 0, 6 ) );
			else box.set( [ Infinity, Infinity, Infinity, - Infinity, - Infinity, - Infinity ] );
			for ( let i = 0; i < seeds.length; i += 3 ) {

				for ( let a = 0; a < 3; a ++ ) {

					box[ a ] = Math.min( box[ a ], seeds[ i + a ] );
					box[ 3 + a ] = Math.max( box[ 3 + a ], seeds[ i + a ] );

				}

			}

		}

		const longest = Math.max( box[ 3 ] - box[ 0 ], box[ 4 ] - box[ 1 ], box[ 5 ] - box[ 2 ] );
		const cellSize = options.cellSize ?? longest / REACHABLE_CELLS;
		this.counts = new Int32Array( 3 );
		this.spacing = new Float64Array( 3 );
		for ( let a = 0; a < 3; a ++ ) {

			const side = box[ 3 + a ] - box[ a ];
			// A whole number of cells per side, so that every lattice point lies inside the box.
			this.counts[ a ] = side > 0 && cellSize > 0 ? Math.max( 1, Math.round( side / cellSize ) ) : 1;
			this.spacing[ a ] = side > 0 ? side / this.counts[ a ] : 0;

		}

		const [ nx, ny, nz ] = this.counts;
		this.reached = new Uint8Array( nx * ny * nz );
		const queue = new Int32Array( nx * ny * nz );
		let tail = 0;
		const corners = new Int32Array( 8 );
		for ( let s = 0; s < seeds.length / 3; s ++ ) {

			const x = seeds[ 3 * s ], y = seeds[ 3 * s + 1 ], z = seeds[ 3 * s + 2 ];
			const at = `${name}[${s}] (${x}, ${y}, ${z})`;
			// Segment hits within 1e-6 of an end do not count: a seed on a surface would see through it.
			const clearance = bvh.nearestDistance( x, y, z );
			if ( clearance <= 1e-3 * Math.max( this.spacing[ 0 ], this.spacing[ 1 ], this.spacing[ 2 ] ) ) {

				throw new RangeError( `${where}: ${at} lies on a surface (${clearance.toPrecision( 3 )} from it); lift it into open space, e.g. to the player's eye height.` );

			}

			let seen = 0;
			for ( let c = 0, n = this.cellCorners( x, y, z, corners ); c < n; c ++ ) {

				if ( ! this.sees( x, y, z, corners[ c ] ) ) continue;
				seen ++;
				if ( this.reached[ corners[ c ] ] === 0 ) {

					this.reached[ corners[ c ] ] = 1;
					queue[ tail ++ ] = corners[ c ];

				}

			}

			if ( seen === 0 ) {

				throw new RangeError( `${where}: ${at} sees none of the lattice points around it (cell ${this.spacing[ 0 ].toPrecision( 3 )}); `
					+ 'move it away from the walls or pass a smaller cell size.' );

			}

		}

		// Every lattice edge's segment test at once, from the triangles' side (blockedLatticeEdges).
		const origin = [ 0, 1, 2 ].map( ( a ) => box[ a ] + PHASE[ a ] * this.spacing[ a ] );
		const blocked = blockedLatticeEdges( bvh.triangles, { origin, spacing: this.spacing, counts: this.counts } );
		const stride = [ 1, nx, nx * ny ];
		for ( let head = 0; head < tail; head ++ ) {

			const node = queue[ head ];
			const i = node % nx, j = Math.floor( node / nx ) % ny, k = Math.floor( node / ( nx * ny ) );
			for ( let n = 0; n < 6; n ++ ) {

				const axis = n >> 1, up = ( n & 1 ) === 1;
				const at = axis === 0 ? i : axis === 1 ? j : k;
				if ( up ? at + 1 >= this.counts[ axis ] : at === 0 ) continue;
				const neighbour = up ? node + stride[ axis ] : node - stride[ axis ];
				if ( this.reached[ neighbour ] === 1 ) continue;
				// The edge between the two is stored at its lower end.
				if ( blocked[ axis ][ up ? node : neighbour ] === 1 ) continue;
				this.reached[ neighbour ] = 1;
				queue[ tail ++ ] = neighbour;

			}

		}

	}

	/** Number of lattice points the fill reached. */
	get reachedCount(): number {

		let n = 0;
		for ( let i = 0; i < this.reached.length; i ++ ) n += this.reached[ i ];
		return n;

	}

	/**
	 * Whether (x, y, z) is reachable: inside the box and in sight of a reached corner of its
	 * lattice cell. Allocation-free.
	 */
	contains( x: number, y: number, z: number ): boolean {

		const b = this.bounds;
		if ( ! ( x >= b[ 0 ] && x <= b[ 3 ] && y >= b[ 1 ] && y <= b[ 4 ] && z >= b[ 2 ] && z <= b[ 5 ] ) ) return false;
		const corners = _corners;
		for ( let c = 0, n = this.cellCorners( x, y, z, corners ); c < n; c ++ ) {

			if ( this.reached[ corners[ c ] ] === 1 && this.sees( x, y, z, corners[ c ] ) ) return true;

		}

		return false;

	}

	/** Writes the lattice indices of the (up to 8) corners of the cell holding (x, y, z); returns how many. */
	private cellCorners( x: number, y: number, z: number, out: Int32Array ): number {

		const [ nx, ny, nz ] = this.counts;
		const i0 = this.lower( 0, x ), j0 = this.lower( 1, y ), k0 = this.lower( 2, z );
		let n = 0;
		for ( let dk = 0; dk < ( nz > 1 ? 2 : 1 ); dk ++ ) for ( let dj = 0; dj < ( ny > 1 ? 2 : 1 ); dj ++ ) {

			for ( let di = 0; di < ( nx > 1 ? 2 : 1 ); di ++ ) out[ n ++ ] = i0 + di + nx * ( j0 + dj + ny * ( k0 + dk ) );

		}

		return n;

	}

	/** Index along `axis` of the lattice point at or below v, clamped so that it and the next exist. */
	private lower( axis: number, v: number ): number {

		const count = this.counts[ axis ];
		if ( count === 1 ) return 0;
		const i = Math.floor( ( v - this.bounds[ axis ] ) / this.spacing[ axis ] - PHASE[ axis ] );
		return Math.min( count - 2, Math.max( 0, i ) );

	}

	/** Whether the segment from (x, y, z) to lattice point `node` crosses no triangle. */
	private sees( x: number, y: number, z: number, node: number ): boolean {

		const q = _point;
		this.pointOf( node, q );
		return ! this.bvh.segmentBlocked( x, y, z, q[ 0 ], q[ 1 ], q[ 2 ] );

	}

	/** World position of lattice point `node`. */
	private pointOf( node: number, out: Float64Array ): void {

		const [ nx, ny ] = this.counts;
		const i = node % nx, j = Math.floor( node / nx ) % ny, k = Math.floor( node / ( nx * ny ) );
		out[ 0 ] = this.bounds[ 0 ] + ( i + PHASE[ 0 ] ) * this.spacing[ 0 ];
		out[ 1 ] = this.bounds[ 1 ] + ( j + PHASE[ 1 ] ) * this.spacing[ 1 ];
		out[ 2 ] = this.bounds[ 2 ] + ( k + PHASE[ 2 ] ) * this.spacing[ 2 ];

	}

}

// Scratch of `contains` and `sees` (never live across calls).
const _corners = new Int32Array( 8 );
const _point = new Float64Array( 3 );
