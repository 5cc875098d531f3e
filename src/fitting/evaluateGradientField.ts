import { assertArrayLike, assertFinite, assertPoints, assertSH } from '../validate.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { assertInterpolator } from './assertInterpolator.js';

/**
 * The field of (gradient) probes at points, with the interpolator's own weights wᵢ:
 * SH(q)[k] = Σᵢ wᵢ · ( c[27i + k] + Σₐ gradients[81i + 27a + k] · (q[a] − pᵢ[a]) ); with `gradients`
 * null, plain `blendSH`. For tests and experiments (the runtime blends with `blendGradientSH`).
 * @param interpolator The structure over the probes.
 * @param probePositions 3 per probe (`interpolator.probeCount` probes).
 * @param sh 27 per probe.
 * @param gradients 81 per probe (∂ SH float k / ∂ axis a at 27a + k), or null.
 * @param points 3 per point.
 * @returns 27 floats per point.
 */
export function evaluateGradientField(
	interpolator: ProbeInterpolator, probePositions: ArrayLike<number>, sh: ArrayLike<number>,
	gradients: ArrayLike<number> | null, points: ArrayLike<number>,
): Float32Array {

	const where = 'evaluateGradientField';
	const { probeCount, weightCount } = assertInterpolator( where, interpolator );
	const probes = assertPoints( where, 'probePositions', probePositions );
	if ( probes !== probeCount ) {

		throw new RangeError( `${where}: probePositions holds ${probes} probes; the interpolator has ${probeCount}.` );

	}

	assertSH( where, 'sh', sh, probeCount );
	if ( gradients !== null ) {

		assertArrayLike( where, 'gradients', gradients );
		if ( gradients.length !== 81 * probeCount ) {

			throw new RangeError( `${where}: gradients must have length ${81 * probeCount} (81 floats × ${probeCount} probes) or be null, got ${gradients.length}.` );

		}

		assertFinite( where, 'gradients', gradients );

	}

	const count = assertPoints( where, 'points', points );
	const out = new Float32Array( 27 * count );
	const indices = new Uint32Array( weightCount ), weights = new Float64Array( weightCount ), value = new Float64Array( 27 );
	let hint = - 1;
	for ( let j = 0; j < count; j ++ ) {

		const x = points[ 3 * j ], y = points[ 3 * j + 1 ], z = points[ 3 * j + 2 ];
		weights.fill( 0 );
		hint = interpolator.interpolate( x, y, z, indices, weights, hint );
		value.fill( 0 );
		for ( let s = 0; s < weightCount; s ++ ) {

			const w = weights[ s ];
			if ( w === 0 ) continue;
			const i = indices[ s ];
			const dx = x - probePositions[ 3 * i ], dy = y - probePositions[ 3 * i + 1 ], dz = z - probePositions[ 3 * i + 2 ];
			const c = 27 * i, g = 81 * i;
			for ( let k = 0; k < 27; k ++ ) {

				let v = sh[ c + k ];
				if ( gradients !== null ) v += gradients[ g + k ] * dx + gradients[ g + 27 + k ] * dy + gradients[ g + 54 + k ] * dz;
				value[ k ] += w * v;

			}

		}

		for ( let k = 0; k < 27; k ++ ) out[ 27 * j + k ] = value[ k ];

	}

	return out;

}
