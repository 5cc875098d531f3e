import { IRRADIANCE_ROW, irradianceRow, pointError } from './irradianceMeasure.js';
import { SH_COLUMNS } from './normalEquations.js';
import type { SampleDesign } from './sampleDesign.js';

// Scratch for one sample's predicted SH and its irradiance row (one sample at a time).
const predicted = new Float64Array( SH_COLUMNS );
const predictedRow = new Float64Array( IRRADIANCE_ROW );

/**
 * Σⱼ sⱼ · errorⱼ over the samples (all, or with `folds` those of fold `fold`), errorⱼ the library's
 * irradiance error of the field `solution` predicts at sample j against its true irradiance row.
 * @param solution `stride` unknowns per local probe, 27 floats each (as {@link solveRegularised} returns).
 * @param truthTable {@link IRRADIANCE_ROW} floats per sample.
 * @param scale 1 / (K · Ē).
 * @param perSample Receives errorⱼ at index j when given.
 */
export function weightedPredictionError(
	design: SampleDesign, solution: Float64Array, truthTable: Float64Array, weights: Float64Array, scale: number,
	folds: Uint8Array | null = null, fold = 0, perSample?: Float64Array,
): number {

	const { slots, stride, probes, factors } = design;
	let sum = 0;
	for ( let j = 0; j < design.count; j ++ ) {

		if ( folds !== null && folds[ j ] !== fold ) continue;
		predicted.fill( 0 );
		for ( let s = 0; s < slots; s ++ ) {

			const t = probes[ slots * j + s ];
			if ( t < 0 ) continue;
			for ( let a = 0; a < stride; a ++ ) {

				const f = factors[ stride * ( slots * j + s ) + a ];
				if ( f === 0 ) continue;
				const source = SH_COLUMNS * ( stride * t + a );
				for ( let k = 0; k < SH_COLUMNS; k ++ ) predicted[ k ] += f * solution[ source + k ];

			}

		}

		irradianceRow( predicted, 0, predictedRow, 0 );
		const error = pointError( predictedRow, 0, truthTable, IRRADIANCE_ROW * j, scale );
		if ( perSample !== undefined ) perSample[ j ] = error;
		sum += weights[ j ] * error;

	}

	return sum;

}
