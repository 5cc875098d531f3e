import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { checkFitArguments, checkFitSamples, type CheckedSamples } from './checkFitArguments.js';
import { chooseLambdas } from './crossValidation.js';
import { createEnvelope } from './envelope.js';
import { makeFitNonNegative } from './fitNonNegative.js';
import { MEASURE_DIRECTIONS, weightedMeanIrradiance } from './irradianceMeasure.js';
import { accumulateNormalEquations, createNormalEquations } from './normalEquations.js';
import { weightedPredictionError } from './predictionError.js';
import { buildSampleDesign, sampleVisitOrder, type SampleDesign } from './sampleDesign.js';
import { createSolveScratch, solveRegularised } from './solveRegularised.js';

/** Captured points a fit matches: where, what was captured there, and how much each counts. */
export interface FitSamples {

	/** x, y, z per sample. */
	positions: ArrayLike<number>;

	/** 27 floats per sample: the captured truth at that point. */
	sh: ArrayLike<number>;

	/** One weight ≥ 0 per sample (e.g. a region of interest); default all 1. Weight 0 leaves a sample out. */
	weights?: ArrayLike<number>;

}

/** Options of {@link fitProbeSH}. */
export interface FitProbeSHOptions {

	/** Also fit a spatial gradient per probe (81 floats); default false. */
	gradients?: boolean;

	/** Pull toward each probe's captured SH (scale-free, docs/fitting.md), or 'auto' (default): k-fold cross-validation. */
	lambda?: number | 'auto';

	/** Pull toward zero gradient (scale-free), or 'auto' (default); used only with `gradients`. */
	gradientLambda?: number | 'auto';

	/** Cross-validation folds, default 5. */
	folds?: number;

	/** Fold assignment seed, default 1 (same seed, same result). */
	seed?: number;

	/** Make the fitted irradiance ≥ 0 in every direction at every probe (and, with gradients, across its cells); default false. */
	nonNegative?: boolean;

}

/** What {@link fitProbeSH} returns. */
export interface FitProbeSHResult {

	/** 27 floats per probe: fitted, or captured for probes no sample reaches. */
	sh: Float32Array;

	/** 81 floats per probe (`81i + 27a + k` = ∂ SH float k / ∂ axis a), or null without gradients. */
	gradients: Float32Array | null;

	/** The λ used (chosen or given). */
	lambda: number;

	/** The gradient λ used; 0 without gradients. */
	gradientLambda: number;

	/** Weighted mean irradiance error over held-out folds at the chosen λ; null when every λ was given. */
	crossValidationError: number | null;

	/** Weighted mean irradiance error of the fitted field over the fit samples (NaN when their irradiance averages ≤ 0). */
	fitError: number;

}

/**
 * Least-squares probe SH: the probes' SH (and optionally gradients) that make the interpolated
 * field — blended with `interpolator`'s own weights, outer cells included — best match captured
 * samples, pulled toward each probe's captured SH by λ (chosen by cross-validation unless
 * given). Probes no sample reaches keep their captured SH. Deterministic. The objective, λ's
 * normalisation, the cross-validation and the non-negative step: docs/fitting.md.
 * @param interpolator The runtime structure over the probes (TetrahedralMesh, GridInterpolator, PlanarMesh, incremental mesh).
 * @param probePositions 3 per probe, `interpolator.probeCount` probes.
 * @param probeSH 27 per probe: the captured SH (the regularisation target).
 * @param samples The fit set (never the evaluation set).
 * @param options Gradients, λ, folds, seed, non-negative.
 * @throws TypeError / RangeError named `fitProbeSH: …` for mismatched lengths, NaN, negative weights, λ < 0, no samples, unknown options.
 */
export function fitProbeSH(
	interpolator: ProbeInterpolator, probePositions: ArrayLike<number>, probeSH: ArrayLike<number>,
	samples: FitSamples, options?: FitProbeSHOptions,
): FitProbeSHResult {

	return fitProbes( interpolator, probePositions, probeSH, samples, options, null );

}

/** Fit samples checked once for many fits over them: {@link prepareFitSamples}. Not public. */
export interface PreparedFitSamples extends CheckedSamples {

	/** The order the design visits them in. */
	order: Uint32Array;

}

/** Checks `samples` (as `fitProbeSH` does) and orders them, for {@link fitProbeSHUnmeasured}. Not public. */
export function prepareFitSamples( where: string, samples: FitSamples ): PreparedFitSamples {

	const checked = checkFitSamples( where, samples );
	return { ...checked, order: sampleVisitOrder( checked.positions ) };

}

/**
 * {@link fitProbeSH} over prepared samples, without measuring `fitError` (NaN): for callers that fit
 * the same samples many times and measure the fitted field themselves (reduceProbes' steps). Not public.
 */
export function fitProbeSHUnmeasured(
	interpolator: ProbeInterpolator, probePositions: ArrayLike<number>, probeSH: ArrayLike<number>,
	samples: PreparedFitSamples, options?: FitProbeSHOptions,
): FitProbeSHResult {

	return fitProbes( interpolator, probePositions, probeSH, samples, options, samples );

}

/**
 * {@link fitProbeSHUnmeasured}, also returning the fit's sample design (every sample's blending
 * probes and weights), so the caller need not locate the samples again. Not public.
 */
export function fitProbeSHWithDesign(
	interpolator: ProbeInterpolator, probePositions: ArrayLike<number>, probeSH: ArrayLike<number>,
	samples: PreparedFitSamples, options?: FitProbeSHOptions,
): { result: FitProbeSHResult; design: SampleDesign } {

	const out: { design?: SampleDesign } = {};
	const result = fitProbes( interpolator, probePositions, probeSH, samples, options, samples, out );
	return { result, design: out.design! };

}

/** {@link fitProbeSH}; over `prepared` samples (then `fitError` is left NaN) when given. */
function fitProbes(
	interpolator: ProbeInterpolator, probePositions: ArrayLike<number>, probeSH: ArrayLike<number>,
	samples: FitSamples, options: FitProbeSHOptions | undefined, prepared: PreparedFitSamples | null,
	designOut?: { design?: SampleDesign },
): FitProbeSHResult {

	const where = 'fitProbeSH';
	const checked = checkFitArguments( where, interpolator, probePositions, probeSH, samples, options, prepared ?? undefined );
	const { positions, sh: truth, weights, gradients } = checked;
	const design = buildSampleDesign( where, interpolator, probePositions, positions, weights, gradients, prepared?.order );
	if ( designOut ) designOut.design = design;
	const { stride, localToGlobal } = design;
	const first = new Int32Array( stride * localToGlobal.length );
	for ( let r = 0; r < first.length; r ++ ) first[ r ] = stride * design.firstNeighbour[ Math.floor( r / stride ) ];
	const envelope = createEnvelope( first );
	const captured = new Float64Array( 27 * localToGlobal.length );
	localToGlobal.forEach( ( i, t ) => {

		for ( let k = 0; k < 27; k ++ ) captured[ 27 * t + k ] = probeSH[ 27 * i + k ];

	} );

	const meanIrradiance = weightedMeanIrradiance( truth, weights );
	const scale = meanIrradiance > 0 ? 1 / ( MEASURE_DIRECTIONS * meanIrradiance ) : NaN;

	let lambda = checked.lambda, gradientLambda = gradients ? checked.gradientLambda : 0;
	let crossValidationError: number | null = null;
	if ( lambda === 'auto' || gradientLambda === 'auto' ) {

		if ( ! ( meanIrradiance > 0 ) ) {

			throw new RangeError( `${where}: the samples' irradiance averages ${meanIrradiance}; choosing λ by cross-validation needs a positive mean (give lambda and gradientLambda instead).` );

		}

		if ( design.count < 2 ) throw new RangeError( `${where}: choosing λ by cross-validation needs at least 2 samples of positive weight, got ${design.count}.` );
		const choice = chooseLambdas( {
			design, envelope, truth, weights, captured, scale, lambda, gradientLambda, folds: checked.folds, seed: checked.seed,
		} );
		lambda = choice.lambda;
		gradientLambda = choice.gradientLambda;
		crossValidationError = choice.error;

	}

	const equations = createNormalEquations( envelope );
	accumulateNormalEquations( design, envelope, truth, weights, equations );
	const solution = solveRegularised( envelope, equations, captured, stride, lambda, gradientLambda, createSolveScratch( envelope ) );

	const sh = Float32Array.from( probeSH );
	const gradientField = gradients ? new Float32Array( 81 * checked.probeCount ) : null;
	const h = design.lengthScale;
	localToGlobal.forEach( ( i, t ) => {

		for ( let k = 0; k < 27; k ++ ) sh[ 27 * i + k ] = solution[ 27 * stride * t + k ];
		if ( gradientField === null ) return;
		for ( let a = 0; a < 3; a ++ ) {

			const source = 27 * ( stride * t + 1 + a );
			for ( let k = 0; k < 27; k ++ ) gradientField[ 81 * i + 27 * a + k ] = solution[ source + k ] / h;

		}

	} );

	if ( checked.nonNegative ) makeFitNonNegative( sh, gradientField, probePositions, interpolator, design, positions );

	return {
		sh, gradients: gradientField, lambda, gradientLambda, crossValidationError,
		fitError: prepared === null ? storedFitError( design, sh, gradientField, truth, weights, scale ) : NaN,
	};

}

/** The weighted mean error of the stored (float32, possibly non-negative) field over the samples. */
function storedFitError(
	design: SampleDesign, sh: Float32Array, gradients: Float32Array | null, truth: Float64Array, weights: Float64Array, scale: number,
): number {

	const { stride, localToGlobal, lengthScale } = design;
	const solution = new Float64Array( 27 * stride * localToGlobal.length );
	localToGlobal.forEach( ( i, t ) => {

		for ( let k = 0; k < 27; k ++ ) solution[ 27 * stride * t + k ] = sh[ 27 * i + k ];
		if ( gradients === null ) return;
		for ( let a = 0; a < 3; a ++ ) {

			const target = 27 * ( stride * t + 1 + a );
			for ( let k = 0; k < 27; k ++ ) solution[ target + k ] = lengthScale * gradients[ 81 * i + 27 * a + k ];

		}

	} );

	let totalWeight = 0;
	for ( let j = 0; j < weights.length; j ++ ) totalWeight += weights[ j ];
	return weightedPredictionError( design, solution, truth, weights, scale ) / totalWeight;

}
