import { SH_FLOATS } from '../validate.js';

/**
 * Blends the SH9 of several probes: `out = Σ weights[k] · probeSH[27·indices[k] …]`.
 * Allocation-free; meant for per-object, per-frame use, so it does not validate its arguments
 * beyond what keeps it from reading out of range — validate once, when the arrays are built.
 *
 * @param indices Probe indices, e.g. from {@link ProbeInterpolator.interpolate}.
 * @param weights One weight per index.
 * @param probeSH 27 floats per probe, three.js `SphericalHarmonics3` order.
 * @param out Receives 27 floats.
 * @param count How many (index, weight) pairs to use; defaults to `indices.length`.
 * @returns `out`.
 */
export function blendSH<T extends Float32Array | Float64Array | number[]>(
	indices: ArrayLike<number>,
	weights: ArrayLike<number>,
	probeSH: ArrayLike<number>,
	out: T,
	count: number = indices.length
): T {

	const probes = probeSH.length / SH_FLOATS;
	for ( let k = 0; k < count; k ++ ) {

		const index = indices[ k ];
		if ( ! ( index >= 0 && index < probes ) ) {

			throw new RangeError( `blendSH: indices[${k}] = ${index} is not a probe of probeSH (${probes} probes).` );

		}

	}

	if ( count === 4 ) {

		// The tetrahedral case, once per object per frame: one pass, no zero-fill.
		const w0 = weights[ 0 ], w1 = weights[ 1 ], w2 = weights[ 2 ], w3 = weights[ 3 ];
		const b0 = SH_FLOATS * indices[ 0 ], b1 = SH_FLOATS * indices[ 1 ], b2 = SH_FLOATS * indices[ 2 ], b3 = SH_FLOATS * indices[ 3 ];
		for ( let i = 0; i < SH_FLOATS; i ++ ) {

			out[ i ] = w0 * probeSH[ b0 + i ] + w1 * probeSH[ b1 + i ] + w2 * probeSH[ b2 + i ] + w3 * probeSH[ b3 + i ];

		}

		return out;

	}

	if ( count === 8 ) {

		// The trilinear grid: one pass as well (the accumulating loop below is ~8× slower here).
		const w0 = weights[ 0 ], w1 = weights[ 1 ], w2 = weights[ 2 ], w3 = weights[ 3 ];
		const w4 = weights[ 4 ], w5 = weights[ 5 ], w6 = weights[ 6 ], w7 = weights[ 7 ];
		const b0 = SH_FLOATS * indices[ 0 ], b1 = SH_FLOATS * indices[ 1 ], b2 = SH_FLOATS * indices[ 2 ], b3 = SH_FLOATS * indices[ 3 ];
		const b4 = SH_FLOATS * indices[ 4 ], b5 = SH_FLOATS * indices[ 5 ], b6 = SH_FLOATS * indices[ 6 ], b7 = SH_FLOATS * indices[ 7 ];
		for ( let i = 0; i < SH_FLOATS; i ++ ) {

			out[ i ] = w0 * probeSH[ b0 + i ] + w1 * probeSH[ b1 + i ] + w2 * probeSH[ b2 + i ] + w3 * probeSH[ b3 + i ]
				+ w4 * probeSH[ b4 + i ] + w5 * probeSH[ b5 + i ] + w6 * probeSH[ b6 + i ] + w7 * probeSH[ b7 + i ];

		}

		return out;

	}

	for ( let i = 0; i < SH_FLOATS; i ++ ) out[ i ] = 0;
	for ( let k = 0; k < count; k ++ ) {

		const w = weights[ k ];
		if ( w === 0 ) continue;
		const base = SH_FLOATS * indices[ k ];
		for ( let i = 0; i < SH_FLOATS; i ++ ) out[ i ] += w * probeSH[ base + i ];

	}

	return out;

}
