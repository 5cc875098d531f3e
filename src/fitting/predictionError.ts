import { differenceError } from './irradianceMeasure.js';
import type { SampleDesign } from './sampleDesign.js';

// Scratch for one sample's predicted SH minus its truth.
const difference = new Float64Array( 27 );

/**
 * Σⱼ sⱼ · errorⱼ over the samples (all, or with `folds` those of fold `fold`), errorⱼ the library's
 * irradiance error of the field `solution` predicts at sample j against its captured SH.
 * @param solution `stride` unknowns per local probe, 27 floats each (as {@link solveRegularised} returns).
 * @param truth 27 floats per sample.
 * @param scale 1 / (K · Ē).
 * @param perSample Receives errorⱼ at index j when given.
 */
export function weightedPredictionError(
	design: SampleDesign, solution: Float64Array, truth: Float64Array, weights: Float64Array, scale: number,
	folds: Uint8Array | null = null, fold = 0, perSample?: Float64Array,
): number {

	const { slots, stride, probes, factors } = design;
	let sum = 0;
	for ( let j = 0; j < design.count; j ++ ) {

		if ( folds !== null && folds[ j ] !== fold ) continue;
		for ( let k = 0; k < 27; k ++ ) difference[ k ] = - truth[ 27 * j + k ];
		for ( let s = 0; s < slots; s ++ ) {

			const t = probes[ slots * j + s ];
			if ( t < 0 ) continue;
			for ( let a = 0; a < stride; a ++ ) {

				const f = factors[ stride * ( slots * j + s ) + a ];
				if ( f === 0 ) continue;
				const source = 27 * ( stride * t + a );
				for ( let k = 0; k < 27; k ++ ) difference[ k ] += f * solution[ source + k ];

			}

		}

		const error = differenceError( difference, 0, scale );
		if ( perSample !== undefined ) perSample[ j ] = error;
		sum += weights[ j ] * error;

	}

	return sum;

}
