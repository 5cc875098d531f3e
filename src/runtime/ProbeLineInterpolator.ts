import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { assertPoints } from '../validate.js';

/**
 * Interpolation for probes that span no plane — one probe, two, or a row along a corridor:
 * piecewise linear along their line, constant across it, and the end probe's value beyond either
 * end. A volume or zone gets it when its probes are too few or collinear for a tetrahedral or
 * planar mesh (see `createVolumeInterpolator`), so every layout the baked format accepts loads.
 *
 * The line runs through the two probes farthest apart (found by two farthest-point passes);
 * probes are ordered by their projection on it, and probes with the same projection (duplicates)
 * are represented by the first of them. Output has 2 slots: the two probes around the point.
 */
export class ProbeLineInterpolator implements ProbeInterpolator {

	/** Probe positions, x, y, z per probe. */
	readonly positions: Float64Array;

	/** A point of the line (one end probe). */
	readonly origin: Float64Array;

	/** Unit direction of the line; zero when every probe is at one position. */
	readonly direction: Float64Array;

	/** The probes used, in order along the line (one per distinct projection). */
	readonly order: Uint32Array;

	/** Their projections on the line (distance from `origin`), increasing. */
	readonly stations: Float64Array;

	/** Always 2. */
	readonly weightCount = 2;

	/**
	 * @param positions Flat x, y, z per probe; at least one probe.
	 */
	constructor( positions: ArrayLike<number> ) {

		const count = assertPoints( 'ProbeLineInterpolator', 'positions', positions, 1 );
		const p = this.positions = Float64Array.from( positions );
		const farthest = ( from: number ): number => {

			let best = from, distance = - 1;
			for ( let i = 0; i < count; i ++ ) {

				const d = Math.hypot( p[ 3 * i ] - p[ 3 * from ], p[ 3 * i + 1 ] - p[ 3 * from + 1 ], p[ 3 * i + 2 ] - p[ 3 * from + 2 ] );
				if ( d > distance ) { distance = d; best = i; }

			}

			return best;

		};

		const a = farthest( 0 ), b = farthest( a );
		this.origin = p.slice( 3 * a, 3 * a + 3 );
		const dx = p[ 3 * b ] - p[ 3 * a ], dy = p[ 3 * b + 1 ] - p[ 3 * a + 1 ], dz = p[ 3 * b + 2 ] - p[ 3 * a + 2 ];
		const length = Math.hypot( dx, dy, dz );
		this.direction = length > 0 ? Float64Array.of( dx / length, dy / length, dz / length ) : new Float64Array( 3 );

		const t = new Float64Array( count );
		for ( let i = 0; i < count; i ++ ) t[ i ] = this.project( p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ] );
		const sorted = Array.from( { length: count }, ( _, i ) => i ).sort( ( i, j ) => t[ i ] - t[ j ] || i - j );
		const order: number[] = [];
		for ( const i of sorted ) if ( order.length === 0 || t[ i ] > t[ order[ order.length - 1 ] ] ) order.push( i );
		this.order = Uint32Array.from( order );
		this.stations = Float64Array.from( order, ( i ) => t[ i ] );

	}

	/** Number of probes indexed. */
	get probeCount(): number {

		return this.positions.length / 3;

	}

	/** Segments between consecutive stations (at least 1). */
	get cellCount(): number {

		return Math.max( 1, this.order.length - 1 );

	}

	/**
	 * Writes the two probes around (x, y, z) along the line and their weights (≥ 0, summing to 1).
	 * Allocation-free.
	 * @param hint The segment of a nearby earlier query (tried first).
	 * @returns The segment used.
	 */
	interpolate(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1,
	): number {

		const order = this.order, stations = this.stations, last = order.length - 1;
		const t = this.project( x, y, z );
		if ( last === 0 || ! ( t > stations[ 0 ] ) ) return this.write( indices, weights, 0, 0, 0, 0 );
		if ( ! ( t < stations[ last ] ) ) return this.write( indices, weights, last, last, 0, last - 1 );
		let k: number;
		if ( hint >= 0 && hint < last && t >= stations[ hint ] && t < stations[ hint + 1 ] ) {

			k = hint;

		} else {

			// Largest k with stations[ k ] ≤ t (stations[ 0 ] < t < stations[ last ]).
			let low = 0, high = last;
			while ( high - low > 1 ) {

				const middle = ( low + high ) >> 1;
				if ( stations[ middle ] <= t ) low = middle; else high = middle;

			}

			k = low;

		}

		const w = ( t - stations[ k ] ) / ( stations[ k + 1 ] - stations[ k ] );
		return this.write( indices, weights, k, k + 1, Math.min( 1, Math.max( 0, w ) ), k );

	}

	/** Slot 0: station `a` with weight 1 − w; slot 1: station `b` with weight w. Returns `segment`. */
	private write(
		indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], a: number, b: number, w: number, segment: number,
	): number {

		indices[ 0 ] = this.order[ a ];
		weights[ 0 ] = 1 - w;
		indices[ 1 ] = this.order[ b ];
		weights[ 1 ] = w;
		return segment;

	}

	/** The projection of (x, y, z) on the line. */
	private project( x: number, y: number, z: number ): number {

		const o = this.origin, d = this.direction;
		return ( x - o[ 0 ] ) * d[ 0 ] + ( y - o[ 1 ] ) * d[ 1 ] + ( z - o[ 2 ] ) * d[ 2 ];

	}

}
