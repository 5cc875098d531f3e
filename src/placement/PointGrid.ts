import { boundsOf } from '../geometry/boundsOf.js';

/**
 * A uniform grid over a fixed point set (about 2 points per cell), for "which points lie in this
 * box?" — the points a local edit of a tetrahedralization can have moved into other cells.
 * Compressed rows: the points of cell c are `points[ start[ c ] … start[ c + 1 ] − 1 ]`.
 */
export class PointGrid {

	/** The points, x, y, z each (kept by reference). */
	readonly positions: Float64Array;

	private readonly min: Float64Array;
	private readonly inverse: Float64Array;
	private readonly dims: Int32Array;
	/** Per cell, where its points begin in `points` (one entry more than cells). */
	readonly start: Int32Array;

	/** Point indices, cell by cell. */
	readonly points: Int32Array;

	/** The points' coordinates in the order of `points` (x, y, z of `points[ q ]` at 3q): a cell's points read in sequence. */
	readonly sorted: Float64Array;

	/** @param positions x, y, z per point (at least one). */
	constructor( positions: Float64Array ) {

		const count = positions.length / 3;
		const b = boundsOf( positions );
		const size = [ b[ 3 ] - b[ 0 ], b[ 4 ] - b[ 1 ], b[ 5 ] - b[ 2 ] ];
		const extent = Math.max( size[ 0 ], size[ 1 ], size[ 2 ] );
		// Cells of side `cell`: the volume (flat axes counted one cell thick) over count / 2 cells.
		const thick = size.map( ( s ) => Math.max( s, 1e-9 * extent, Number.MIN_VALUE ) );
		const cell = Math.cbrt( thick[ 0 ] * thick[ 1 ] * thick[ 2 ] / Math.max( 1, count / 2 ) );
		this.positions = positions;
		this.min = Float64Array.of( b[ 0 ], b[ 1 ], b[ 2 ] );
		this.dims = Int32Array.from( size, ( s ) => Math.min( 256, Math.max( 1, Math.ceil( s / cell ) ) ) );
		this.inverse = Float64Array.from( size, ( s, a ) => s > 0 ? this.dims[ a ] / s : 0 );
		const cells = this.dims[ 0 ] * this.dims[ 1 ] * this.dims[ 2 ];
		this.start = new Int32Array( cells + 1 );
		const cellOf = new Int32Array( count );
		for ( let p = 0; p < count; p ++ ) {

			const x = this.axisCell( positions[ 3 * p ], 0 ), y = this.axisCell( positions[ 3 * p + 1 ], 1 );
			cellOf[ p ] = this.cellIndex( x, y, this.axisCell( positions[ 3 * p + 2 ], 2 ) );
			this.start[ cellOf[ p ] + 1 ] ++;

		}

		for ( let c = 0; c < cells; c ++ ) this.start[ c + 1 ] += this.start[ c ];
		this.points = new Int32Array( count );
		const fill = this.start.slice( 0, cells );
		for ( let p = 0; p < count; p ++ ) this.points[ fill[ cellOf[ p ] ] ++ ] = p;
		this.sorted = new Float64Array( 3 * count );
		for ( let q = 0; q < count; q ++ ) this.sorted.set( positions.subarray( 3 * this.points[ q ], 3 * this.points[ q ] + 3 ), 3 * q );

	}

	/**
	 * Writes the cell range the box [min, max] overlaps to `out`: x0, y0, z0, x1, y1, z1 (inclusive).
	 * Its points (a superset of those inside the box) are `points[ start[ c ] … start[ c + 1 ] − 1 ]`
	 * for each `c = cellIndex( x, y, z )` in it, visited z, then y, then x outermost first.
	 */
	cellRange( minX: number, minY: number, minZ: number, maxX: number, maxY: number, maxZ: number, out: Int32Array ): void {

		out[ 0 ] = this.axisCell( minX, 0 ); out[ 1 ] = this.axisCell( minY, 1 ); out[ 2 ] = this.axisCell( minZ, 2 );
		out[ 3 ] = this.axisCell( maxX, 0 ); out[ 4 ] = this.axisCell( maxY, 1 ); out[ 5 ] = this.axisCell( maxZ, 2 );

	}

	/** The index of grid cell (x, y, z) into `start`. */
	cellIndex( x: number, y: number, z: number ): number {

		return x + this.dims[ 0 ] * ( y + this.dims[ 1 ] * z );

	}

	/** The cell of coordinate v on axis a, clamped to the grid. */
	private axisCell( v: number, a: number ): number {

		const c = Math.floor( ( v - this.min[ a ] ) * this.inverse[ a ] );
		return c < 0 ? 0 : c >= this.dims[ a ] ? this.dims[ a ] - 1 : c;

	}

}
