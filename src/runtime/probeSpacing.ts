/*
 * The typical distance between probes of a layout: the median over probes of the distance to the
 * nearest other probe. `LightProbeVolume.add( scene )` compares mesh sizes and tessellation with
 * it. Pure (no three.js).
 */

/**
 * The median nearest-neighbour distance of the points of `positions` (x, y, z each) for which
 * `isActive( i )` holds. Points closer than 1e-9 of the layout's diagonal to each other count as
 * one (duplicates merged). Infinity when fewer than two distinct points remain. A uniform grid
 * of about one point per cell (in the dimensions the layout spans) finds each nearest neighbour
 * in rings of cells around the point's own, so the cost is near-linear for spread-out layouts.
 */
export function medianProbeSpacing( positions: ArrayLike<number>, isActive: ( index: number ) => boolean = () => true ): number {

	const ids: number[] = [];
	for ( let i = 0, n = Math.floor( positions.length / 3 ); i < n; i ++ ) if ( isActive( i ) ) ids.push( i );
	if ( ids.length < 2 ) return Infinity;
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( const i of ids ) {

		for ( let c = 0; c < 3; c ++ ) {

			min[ c ] = Math.min( min[ c ], positions[ 3 * i + c ] );
			max[ c ] = Math.max( max[ c ], positions[ 3 * i + c ] );

		}

	}

	const extent = [ max[ 0 ] - min[ 0 ], max[ 1 ] - min[ 1 ], max[ 2 ] - min[ 2 ] ];
	const diagonal = Math.hypot( extent[ 0 ], extent[ 1 ], extent[ 2 ] );
	if ( ! ( diagonal > 0 ) ) return Infinity;
	const grid = new PointGrid( positions, ids, min, extent, diagonal );
	const tolerance = 1e-9 * diagonal;
	const nearest: number[] = [];
	for ( const i of ids ) {

		const d = grid.nearest( i, tolerance );
		if ( d < Infinity ) nearest.push( d );

	}

	if ( nearest.length === 0 ) return Infinity;
	nearest.sort( ( a, b ) => a - b );
	const middle = nearest.length >> 1;
	return nearest.length % 2 === 1 ? nearest[ middle ] : 0.5 * ( nearest[ middle - 1 ] + nearest[ middle ] );

}

/** Points bucketed in a uniform grid (counting sort by cell), for nearest-neighbour queries. */
class PointGrid {

	private readonly positions: ArrayLike<number>;
	private readonly min: number[];
	private readonly cell: number;
	private readonly size: number[];
	private readonly start: Uint32Array;
	private readonly sorted: Uint32Array;

	constructor( positions: ArrayLike<number>, ids: number[], min: number[], extent: number[], diagonal: number ) {

		this.positions = positions;
		this.min = min;
		// About one point per cell in the dimensions the layout spans (a flat layout gets square cells in its plane).
		const spanned = extent.filter( ( e ) => e > 1e-9 * diagonal );
		const measure = spanned.reduce( ( product, e ) => product * e, 1 );
		this.cell = Math.pow( measure / ids.length, 1 / spanned.length );
		this.size = extent.map( ( e ) => Math.min( Math.floor( e / this.cell ) + 1, 1 << 10 ) );
		const cells = this.size[ 0 ] * this.size[ 1 ] * this.size[ 2 ];
		const counts = new Uint32Array( cells + 1 );
		const cellOf = ids.map( ( i ) => this.cellIndex( i ) );
		for ( const c of cellOf ) counts[ c + 1 ] ++;
		for ( let c = 0; c < cells; c ++ ) counts[ c + 1 ] += counts[ c ];
		this.start = counts.slice();
		this.sorted = new Uint32Array( ids.length );
		ids.forEach( ( i, k ) => { this.sorted[ counts[ cellOf[ k ] ] ++ ] = i; } );

	}

	/** Distance from point `i` to the nearest point farther than `tolerance`, or Infinity. */
	nearest( i: number, tolerance: number ): number {

		const p = this.positions, x = p[ 3 * i ], y = p[ 3 * i + 1 ], z = p[ 3 * i + 2 ];
		const [ cx, cy, cz ] = [ 0, 1, 2 ].map( ( c ) => this.axisCell( p[ 3 * i + c ], c ) );
		const [ nx, ny, nz ] = this.size;
		const rings = Math.max( nx, ny, nz );
		let best = Infinity;
		for ( let r = 0; r <= rings; r ++ ) {

			// Every point outside rings 0..r - 1 is farther than (r - 1) cells from the query.
			if ( best <= ( r - 1 ) * this.cell ) break;
			for ( let iz = Math.max( 0, cz - r ); iz <= Math.min( nz - 1, cz + r ); iz ++ ) {

				for ( let iy = Math.max( 0, cy - r ); iy <= Math.min( ny - 1, cy + r ); iy ++ ) {

					for ( let ix = Math.max( 0, cx - r ); ix <= Math.min( nx - 1, cx + r ); ix ++ ) {

						// Only the shell of ring r (its inside was searched before).
						if ( Math.max( Math.abs( ix - cx ), Math.abs( iy - cy ), Math.abs( iz - cz ) ) !== r ) continue;
						const c = ix + nx * ( iy + ny * iz );
						for ( let k = this.start[ c ]; k < this.start[ c + 1 ]; k ++ ) {

							const j = this.sorted[ k ];
							const d = Math.hypot( p[ 3 * j ] - x, p[ 3 * j + 1 ] - y, p[ 3 * j + 2 ] - z );
							if ( d > tolerance && d < best ) best = d;

						}

					}

				}

			}

		}

		return best;

	}

	private axisCell( value: number, axis: number ): number {

		return Math.min( this.size[ axis ] - 1, Math.max( 0, Math.floor( ( value - this.min[ axis ] ) / this.cell ) ) );

	}

	private cellIndex( i: number ): number {

		const p = this.positions;
		const x = this.axisCell( p[ 3 * i ], 0 ), y = this.axisCell( p[ 3 * i + 1 ], 1 ), z = this.axisCell( p[ 3 * i + 2 ], 2 );
		return x + this.size[ 0 ] * ( y + this.size[ 1 ] * z );

	}

}
