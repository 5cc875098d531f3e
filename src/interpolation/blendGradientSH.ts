import { SH_FLOATS } from '../validate.js';

/** Floats of one probe's gradient: ∂(27 SH floats)/∂x, then /∂y, then /∂z. */
const GRADIENT_FLOATS = 3 * SH_FLOATS;

/** The grid's first four probes, summed in float64 before the second four are added (as blendSH's one sum of 8). */
const _firstFour = new Float64Array( SH_FLOATS );

/**
 * Blends gradient probes at a point: `out[ k ] = Σ weights[ j ] · ( c[ k ] + Σₐ G[ a ][ k ] · ( q[ a ] − p[ a ] ) )` over the
 * probes `indices[ j ]`, with c the probe's SH, G its gradient (`gradients[ 81·i + 27·a + k ]` = ∂(SH float k)/∂(axis a)),
 * p its position and q = (x, y, z). Exact for a field linear in space when each probe holds the field's value and
 * gradient at its position, whatever the weights (they sum to 1). Zero gradients give {@link blendSH}'s result.
 * Allocation-free, for per-object, per-frame use; like `blendSH` it checks only what keeps it from reading out of range.
 *
 * @param indices Probe indices, e.g. from {@link ProbeInterpolator.interpolate}.
 * @param weights One weight per index (after zones or the visibility guard, if any).
 * @param probeSH 27 floats per probe, three.js `SphericalHarmonics3` order.
 * @param gradients 81 floats per probe.
 * @param probePositions x, y, z per probe.
 * @param x Point where the field is evaluated.
 * @param y Point where the field is evaluated.
 * @param z Point where the field is evaluated.
 * @param target Receives 27 floats.
 * @param count How many (index, weight) pairs to use; defaults to `indices.length`.
 * @returns `target`.
 */
export function blendGradientSH<T extends Float32Array | Float64Array | number[]>(
	indices: ArrayLike<number>,
	weights: ArrayLike<number>,
	probeSH: ArrayLike<number>,
	gradients: ArrayLike<number>,
	probePositions: ArrayLike<number>,
	x: number,
	y: number,
	z: number,
	target: T,
	count: number = indices.length,
): T {

	const probes = Math.min( probeSH.length / SH_FLOATS, gradients.length / GRADIENT_FLOATS, probePositions.length / 3 );
	for ( let k = 0; k < count; k ++ ) {

		const index = indices[ k ];
		if ( ! ( index >= 0 && index < probes ) ) {

			throw new RangeError( `blendGradientSH: indices[${k}] = ${index} is not a probe of probeSH, gradients and probePositions `
				+ `(${probes} probes in all three).` );

		}

	}

	if ( count === 4 || count === 8 ) {

		// Tetrahedra (4, once per object per frame) and the grid (8): passes of 4 probes, 16 products per float.
		if ( count === 4 ) return blendFour( indices, weights, probeSH, gradients, probePositions, x, y, z, target, 0, null );
		blendFour( indices, weights, probeSH, gradients, probePositions, x, y, z, _firstFour, 0, null );
		return blendFour( indices, weights, probeSH, gradients, probePositions, x, y, z, target, 4, _firstFour );

	}

	const out = target, c = probeSH, g = gradients, p = probePositions;
	// Other counts (planar meshes' 3, a line's 2): probe by probe, each a pass of 4 products.
	for ( let k = 0; k < SH_FLOATS; k ++ ) out[ k ] = 0;
	for ( let j = 0; j < count; j ++ ) {

		const w = weights[ j ];
		if ( w === 0 ) continue;
		const i = indices[ j ];
		const dx = w * ( x - p[ 3 * i ] ), dy = w * ( y - p[ 3 * i + 1 ] ), dz = w * ( z - p[ 3 * i + 2 ] );
		const cb = SH_FLOATS * i, gb = GRADIENT_FLOATS * i;
		for ( let k = 0; k < SH_FLOATS; k ++ ) {

			out[ k ] += w * c[ cb + k ] + dx * g[ gb + k ] + dy * g[ gb + 27 + k ] + dz * g[ gb + 54 + k ];

		}

	}

	return target;

}

/**
 * Probes `first` … `first + 3` of a blend, added to `base` (null: to zero) and written into `out`: each weight times
 * each offset once, then one pass over the 27 floats — summed in blendSH's order, so zero gradients give its very result.
 */
function blendFour<T extends Float32Array | Float64Array | number[]>(
	indices: ArrayLike<number>, weights: ArrayLike<number>, c: ArrayLike<number>, g: ArrayLike<number>, p: ArrayLike<number>,
	x: number, y: number, z: number, out: T, first: number, base: Float64Array | null,
): T {

	const i0 = indices[ first ], i1 = indices[ first + 1 ], i2 = indices[ first + 2 ], i3 = indices[ first + 3 ];
	const w0 = weights[ first ], w1 = weights[ first + 1 ], w2 = weights[ first + 2 ], w3 = weights[ first + 3 ];
	const x0 = w0 * ( x - p[ 3 * i0 ] ), y0 = w0 * ( y - p[ 3 * i0 + 1 ] ), z0 = w0 * ( z - p[ 3 * i0 + 2 ] );
	const x1 = w1 * ( x - p[ 3 * i1 ] ), y1 = w1 * ( y - p[ 3 * i1 + 1 ] ), z1 = w1 * ( z - p[ 3 * i1 + 2 ] );
	const x2 = w2 * ( x - p[ 3 * i2 ] ), y2 = w2 * ( y - p[ 3 * i2 + 1 ] ), z2 = w2 * ( z - p[ 3 * i2 + 2 ] );
	const x3 = w3 * ( x - p[ 3 * i3 ] ), y3 = w3 * ( y - p[ 3 * i3 + 1 ] ), z3 = w3 * ( z - p[ 3 * i3 + 2 ] );
	const c0 = SH_FLOATS * i0, c1 = SH_FLOATS * i1, c2 = SH_FLOATS * i2, c3 = SH_FLOATS * i3;
	const g0 = GRADIENT_FLOATS * i0, g1 = GRADIENT_FLOATS * i1, g2 = GRADIENT_FLOATS * i2, g3 = GRADIENT_FLOATS * i3;
	for ( let k = 0; k < SH_FLOATS; k ++ ) {

		// Left to right, as blendSH sums: the grid's second four add onto the first four's float64 sum.
		out[ k ] = ( base !== null ? base[ k ] : 0 )
			+ w0 * c[ c0 + k ] + x0 * g[ g0 + k ] + y0 * g[ g0 + 27 + k ] + z0 * g[ g0 + 54 + k ]
			+ w1 * c[ c1 + k ] + x1 * g[ g1 + k ] + y1 * g[ g1 + 27 + k ] + z1 * g[ g1 + 54 + k ]
			+ w2 * c[ c2 + k ] + x2 * g[ g2 + k ] + y2 * g[ g2 + 27 + k ] + z2 * g[ g2 + 54 + k ]
			+ w3 * c[ c3 + k ] + x3 * g[ g3 + k ] + y3 * g[ g3 + 27 + k ] + z3 * g[ g3 + 54 + k ];

	}

	return out;

}
