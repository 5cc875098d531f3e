import { hilbertIndex3 } from '../tetrahedra/spatialOrder.js';
import { reverseCuthillMcKee } from './probeOrdering.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';

const INDEX_RANGE = 1 << 23;

/**
 * The design of a fit: for every sample, the probes the interpolator blends there and the factors
 * their unknowns get — the rows of the least-squares matrix W, kept sparse (≤ weightCount probes
 * per sample). The probes any sample reaches are numbered locally (the only unknowns); the others
 * keep their captured SH.
 */
export interface SampleDesign {

	/** Samples. */
	readonly count: number;

	/** Slots per sample: the interpolator's `weightCount`. */
	readonly slots: number;

	/** Unknowns per probe: 1 (c) or, with gradients, 4 (c and h·∂c/∂x, ∂y, ∂z). */
	readonly stride: number;

	/** `probes[ slots · j + s ]`: local probe of sample j's slot s, or −1 for a slot with zero weight. */
	readonly probes: Int32Array;

	/**
	 * `factors[ stride · ( slots · j + s ) + a ]`: the factor of the slot probe's unknown a in sample j's
	 * prediction — the weight w, and with gradients w · (q − p) / h per axis.
	 */
	readonly factors: Float64Array;

	/** Global probe index of each local probe. */
	readonly localToGlobal: Uint32Array;

	/** Per local probe, the smallest local probe that shares a sample with it (the envelope's first column). */
	readonly firstNeighbour: Int32Array;

	/** h: the gradient unknowns are h · G, so they weigh like the SH (1 when there are no gradients). */
	readonly lengthScale: number;

	/** Per sample, the cell the interpolator returned (its `hint`). */
	readonly cells: Int32Array;

}

/**
 * Interpolates every sample (visited along a Hilbert curve, each lookup starting from the last
 * one's cell) and builds the {@link SampleDesign}. Local probes are numbered in the order the
 * visit first reaches them, then renumbered by reverse Cuthill–McKee, which keeps the normal matrix banded.
 * @param where Function name for error messages.
 * @param interpolator The runtime structure over the probes.
 * @param probePositions 3 per probe.
 * @param positions 3 per sample.
 * @param weights One > 0 per sample.
 * @param gradients Whether each probe also has the 3 gradient unknowns.
 * @param order The samples' {@link sampleVisitOrder}, when the caller keeps it between fits.
 */
export function buildSampleDesign(
	where: string, interpolator: ProbeInterpolator, probePositions: ArrayLike<number>,
	positions: Float64Array, weights: Float64Array, gradients: boolean, order = sampleVisitOrder( positions ),
): SampleDesign {

	const count = weights.length, slots = interpolator.weightCount, probeCount = interpolator.probeCount;
	const stride = gradients ? 4 : 1;
	const global = new Int32Array( slots * count );
	const slotWeights = new Float64Array( slots * count );
	const indices = new Uint32Array( slots ), values = new Float64Array( slots );
	const globalToLocal = new Int32Array( probeCount ).fill( - 1 );
	const localToGlobal: number[] = [];
	const cells = new Int32Array( count );
	let hint = - 1, spread = 0;
	for ( let v = 0; v < count; v ++ ) {

		const j = order[ v ];
		const x = positions[ 3 * j ], y = positions[ 3 * j + 1 ], z = positions[ 3 * j + 2 ];
		values.fill( 0 );
		hint = interpolator.interpolate( x, y, z, indices, values, hint );
		cells[ j ] = hint;
		for ( let s = 0; s < slots; s ++ ) {

			const w = values[ s ], i = indices[ s ];
			if ( ! ( w >= 0 && w < Infinity ) ) {

				throw new RangeError( `${where}: the interpolator gave weight ${w} at sample ${j}; weights must be finite and ≥ 0.` );

			}

			if ( w === 0 ) {

				global[ slots * j + s ] = - 1;
				continue;

			}

			if ( ! ( Number.isInteger( i ) && i >= 0 && i < probeCount ) ) {

				throw new RangeError( `${where}: the interpolator gave probe ${i} at sample ${j}; it has ${probeCount} probes.` );

			}

			global[ slots * j + s ] = i;
			slotWeights[ slots * j + s ] = w;
			if ( globalToLocal[ i ] < 0 ) {

				globalToLocal[ i ] = localToGlobal.length;
				localToGlobal.push( i );

			}

			const dx = x - probePositions[ 3 * i ], dy = y - probePositions[ 3 * i + 1 ], dz = z - probePositions[ 3 * i + 2 ];
			spread += weights[ j ] * w * ( dx * dx + dy * dy + dz * dz );

		}

	}

	// h: the weighted RMS distance from a sample to the probes that blend it (their weights sum to 1).
	let totalWeight = 0;
	for ( let j = 0; j < count; j ++ ) totalWeight += weights[ j ];
	const rms = Math.sqrt( spread / totalWeight );
	const lengthScale = gradients && rms > 0 && Number.isFinite( rms ) ? rms : 1;

	// Renumber the local probes along the layout (reverse Cuthill–McKee) to narrow the band.
	const numbering = reverseCuthillMcKee( sharedSamples( global, slots, globalToLocal, localToGlobal.length ) );
	const renumbered = Uint32Array.from( numbering, ( old ) => localToGlobal[ old ] );
	renumbered.forEach( ( i, t ) => {

		globalToLocal[ i ] = t;

	} );

	const probes = new Int32Array( slots * count );
	const factors = new Float64Array( stride * slots * count );
	const firstNeighbour = Int32Array.from( renumbered, ( _, t ) => t );
	for ( let j = 0; j < count; j ++ ) {

		const base = slots * j;
		let smallest = Infinity;
		for ( let s = 0; s < slots; s ++ ) {

			const i = global[ base + s ];
			const t = i < 0 ? - 1 : globalToLocal[ i ];
			probes[ base + s ] = t;
			if ( t < 0 ) continue;
			if ( t < smallest ) smallest = t;
			const w = slotWeights[ base + s ], f = stride * ( base + s );
			factors[ f ] = w;
			if ( ! gradients ) continue;
			factors[ f + 1 ] = w * ( positions[ 3 * j ] - probePositions[ 3 * i ] ) / lengthScale;
			factors[ f + 2 ] = w * ( positions[ 3 * j + 1 ] - probePositions[ 3 * i + 1 ] ) / lengthScale;
			factors[ f + 3 ] = w * ( positions[ 3 * j + 2 ] - probePositions[ 3 * i + 2 ] ) / lengthScale;

		}

		for ( let s = 0; s < slots; s ++ ) {

			const t = probes[ base + s ];
			if ( t >= 0 && smallest < firstNeighbour[ t ] ) firstNeighbour[ t ] = smallest;

		}

	}

	return {
		count, slots, stride, probes, factors,
		localToGlobal: renumbered, firstNeighbour, lengthScale, cells,
	};

}

/** Per first-touch local probe, the local probes it shares a sample with, ascending. */
function sharedSamples( global: Int32Array, slots: number, globalToLocal: Int32Array, localCount: number ): number[][] {

	// A bit per probe pair while that fits in 2 MB, a set per probe beyond.
	const bitmap = localCount <= 4096 ? new Uint8Array( Math.ceil( localCount * localCount / 8 ) ) : null;
	const sets = bitmap === null ? Array.from( { length: localCount }, () => new Set<number>() ) : null;
	const lists = Array.from( { length: localCount }, (): number[] => [] );
	for ( let base = 0; base < global.length; base += slots ) {

		for ( let a = 0; a < slots; a ++ ) {

			if ( global[ base + a ] < 0 ) continue;
			const ta = globalToLocal[ global[ base + a ] ];
			for ( let b = 0; b < slots; b ++ ) {

				if ( global[ base + b ] < 0 ) continue;
				const tb = globalToLocal[ global[ base + b ] ];
				if ( tb === ta ) continue;
				if ( bitmap !== null ) {

					const bit = ta * localCount + tb;
					if ( bitmap[ bit >> 3 ] & ( 1 << ( bit & 7 ) ) ) continue;
					bitmap[ bit >> 3 ] |= 1 << ( bit & 7 );

				} else {

					if ( sets![ ta ].has( tb ) ) continue;
					sets![ ta ].add( tb );

				}

				lists[ ta ].push( tb );

			}

		}

	}

	for ( const list of lists ) list.sort( ( x, y ) => x - y );
	return lists;

}

/** Sample indices sorted along a 3D Hilbert curve over their bounding box (ties by index). */
export function sampleVisitOrder( positions: Float64Array ): Uint32Array {

	const count = positions.length / 3, bits = 7, cells = ( 1 << bits ) - 1;
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let j = 0; j < count; j ++ ) for ( let a = 0; a < 3; a ++ ) {

		const v = positions[ 3 * j + a ];
		if ( v < min[ a ] ) min[ a ] = v;
		if ( v > max[ a ] ) max[ a ] = v;

	}

	const cell = ( j: number, a: number ): number => max[ a ] > min[ a ]
		? Math.round( ( positions[ 3 * j + a ] - min[ a ] ) / ( max[ a ] - min[ a ] ) * cells ) : 0;
	// 128³ cells order the lookups well enough; the key (21 bits) and the index (≤ 23 bits) packed in one
	// double: a plain numeric sort, ties by index.
	const packed = count < INDEX_RANGE;
	const keys = new Float64Array( count );
	for ( let j = 0; j < count; j ++ ) {

		const key = hilbertIndex3( cell( j, 0 ), cell( j, 1 ), cell( j, 2 ), bits );
		keys[ j ] = packed ? key * INDEX_RANGE + j : key;

	}

	if ( packed ) return Uint32Array.from( keys.sort(), ( k ) => k % INDEX_RANGE );
	return Uint32Array.from( { length: count }, ( _, j ) => j ).sort( ( i, j ) => keys[ i ] - keys[ j ] || i - j );

}
