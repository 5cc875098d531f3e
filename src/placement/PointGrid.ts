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
	private readonly start: Int32Array;
	private readonly points: Int32Array;

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

	}

	/**
	 * Writes the points in the cells the box [min, max] overlaps (a superset of those inside it) to
	 * `out`, growing it when full.
	 * @returns The (possibly new) output array and the count written.
	 */
	query(
		minX: number, minY: number, minZ: number, maxX: number, maxY: number, maxZ: number, out: Int32Array,
	): { out: Int32Array; count: number } {

		const x0 = this.axisCell( minX, 0 ), y0 = this.axisCell( minY, 1 ), z0 = this.axisCell( minZ, 2 );
		const x1 = this.axisCell( maxX, 0 ), y1 = this.axisCell( maxY, 1 ), z1 = this.axisCell( maxZ, 2 );
		let count = 0;
		for ( let z = z0; z <= z1; z ++ ) for ( let y = y0; y <= y1; y ++ ) for ( let x = x0; x <= x1; x ++ ) {

			const c = this.cellIndex( x, y, z );
			for ( let k = this.start[ c ], end = this.start[ c + 1 ]; k < end; k ++ ) {

				if ( count === out.length ) {

					const grown = new Int32Array( 2 * out.length + 64 );
					grown.set( out );
					out = grown;

				}

				out[ count ++ ] = this.points[ k ];

			}

		}

		return { out, count };

	}

	/** The cell of coordinate v on axis a, clamped to the grid. */
	private axisCell( v: number, a: number ): number {

		const c = Math.floor( ( v - this.min[ a ] ) * this.inverse[ a ] );
		return c < 0 ? 0 : c >= this.dims[ a ] ? this.dims[ a ] - 1 : c;

	}

	private cellIndex( x: number, y: number, z: number ): number {

		return x + this.dims[ 0 ] * ( y + this.dims[ 1 ] * z );

	}

}
