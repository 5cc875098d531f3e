import type { Envelope } from './envelope.js';
import type { SampleDesign } from './sampleDesign.js';

/** The unnormalised normal equations of a sample set: Σ s·uuᵀ, Σ s·u·yᵀ and Σ s. */
export interface NormalEquations {

	/** Σⱼ sⱼ · uⱼ uⱼᵀ in envelope storage (uⱼ: sample j's design row). */
	readonly matrix: Float64Array;

	/** Σⱼ sⱼ · uⱼ yⱼᵀ, 27 columns per unknown (the SH floats, all fitted with the one matrix). */
	readonly rhs: Float64Array;

	/** Σⱼ sⱼ. */
	weightSum: number;

}

/** Zeroed normal equations over `envelope`. */
export function createNormalEquations( envelope: Envelope ): NormalEquations {

	return { matrix: new Float64Array( envelope.length ), rhs: new Float64Array( 27 * envelope.size ), weightSum: 0 };

}

/**
 * Adds the samples to `target`: all of them, or (with `folds`) those whose fold is `fold`. The
 * matrix is summed straight from the sparse design rows, never formed densely.
 * @param truth 27 floats per sample.
 * @param weights One per sample.
 */
export function accumulateNormalEquations(
	design: SampleDesign, envelope: Envelope, truth: Float64Array, weights: Float64Array,
	target: NormalEquations, folds: Uint8Array | null = null, fold = 0,
): void {

	const { slots, stride, probes, factors } = design;
	const { diagonal } = envelope;
	const { matrix, rhs } = target;
	for ( let j = 0; j < design.count; j ++ ) {

		if ( folds !== null && folds[ j ] !== fold ) continue;
		const s = weights[ j ], base = slots * j, y = 27 * j;
		target.weightSum += s;
		for ( let a = 0; a < slots; a ++ ) {

			const pa = probes[ base + a ];
			if ( pa < 0 ) continue;
			for ( let ua = 0; ua < stride; ua ++ ) {

				const ra = stride * pa + ua;
				const xa = s * factors[ stride * ( base + a ) + ua ];
				if ( xa === 0 ) continue;
				const row = 27 * ra;
				for ( let k = 0; k < 27; k ++ ) rhs[ row + k ] += xa * truth[ y + k ];
				const rowBase = diagonal[ ra ] - ra;
				// Every ordered slot pair adds to the lower triangle: a probe in two slots still sums right.
				for ( let b = 0; b < slots; b ++ ) {

					const pb = probes[ base + b ];
					if ( pb < 0 || pb > pa ) continue;
					for ( let ub = 0; ub < stride; ub ++ ) {

						const rb = stride * pb + ub;
						if ( rb > ra ) break;
						matrix[ rowBase + rb ] += xa * factors[ stride * ( base + b ) + ub ];

					}

				}

			}

		}

	}

}

/** `target += source`, term by term (the training set of a fold as the sum of the other folds). */
export function addNormalEquations( target: NormalEquations, source: NormalEquations ): void {

	for ( let i = 0; i < target.matrix.length; i ++ ) target.matrix[ i ] += source.matrix[ i ];
	for ( let i = 0; i < target.rhs.length; i ++ ) target.rhs[ i ] += source.rhs[ i ];
	target.weightSum += source.weightSum;

}
