import {
	assertArrayLike, assertFinite, assertInteger, assertNumber, assertOptionalBoolean, assertPoints, assertSH, describeValue,
} from '../validate.js';
import { IRRADIANCE_ERROR_NORMALS } from './irradianceError.js';
import { weightsInRegion } from './regionOfInterest.js';
import type { ReduceProbesOptions } from './reduceProbes.js';

/** Swap passes run by default when `fit` is on and `swaps` is not given (or `true`). */
export const DEFAULT_SWAP_PASSES = 2;

/** Replacements tried per probe and swap pass by default: its 4 nearest free candidates and the 2 predicted worst. */
export const DEFAULT_SWAP_TRIALS = 6;

const FIT_KEYS = [ 'gradients', 'lambda', 'gradientLambda', 'nonNegative' ];

/** How `reduceProbes` re-fits the subset, read from `options.fit`. */
export interface FitSettings {

	gradients: boolean;
	lambda: number | 'auto';
	gradientLambda: number | 'auto';
	nonNegative: boolean;

}

/**
 * The points the error is measured at (and, with `fit`, fitted to): the dense candidates first
 * (indices 0 … denseCount − 1), then the extra fit samples.
 */
export interface FitSet {

	/** Dense candidates in the set (the first of its points). */
	denseCount: number;

	/** Points: x, y, z each. */
	positions: Float64Array;

	/** Their captured SH, 27 floats each. */
	sh: Float64Array;

	/** One weight ≥ 0 per point (region × given weights), or null when every point counts alike. */
	weights: Float64Array | null;

}

/** Every option of `reduceProbes`, checked, with defaults filled in. */
export interface ReduceSettings {

	targetCount: number | undefined;
	targetError: number | undefined;
	statistic: 'mean' | 'p95' | 'max';
	seed: number;
	strategy: 'worst' | 'mean';
	trials: number;
	normals: ArrayLike<number>;
	directions: number;
	required: number[];
	fit: FitSettings | null;
	swapPasses: number;
	/** Replacements tried per probe and swap pass. */
	swapTrials: number;
	/** How trials that move the hull are estimated. */
	hullTrials: 'relocate' | 'local';
	fitSet: FitSet;

}

/**
 * Checks `reduceProbes`' options (named errors: `reduceProbes: options.… …`) and gathers the fit
 * set: dense candidates plus `fitSamples`, weighted by `region`, `weights` and `fitSamples.weights`.
 * @param count Number of dense candidates (positions and sh already checked).
 */
export function readReduceOptions(
	where: string, positions: ArrayLike<number>, sh: ArrayLike<number>, count: number, options: ReduceProbesOptions,
): ReduceSettings {

	if ( options === null || typeof options !== 'object' ) throw new TypeError( `${where}: options must be an object with targetCount and/or targetError.` );
	const { targetCount, targetError, seed = 1 } = options;
	if ( targetCount === undefined && targetError === undefined ) {

		throw new RangeError( `${where}: options needs targetCount, targetError or both; neither was given.` );

	}

	if ( targetCount !== undefined ) assertInteger( where, 'options.targetCount', targetCount, 4, count );
	if ( targetError !== undefined ) {

		assertNumber( where, 'options.targetError', targetError );
		if ( targetError < 0 ) throw new RangeError( `${where}: options.targetError must be ≥ 0, got ${targetError}.` );

	}

	assertNumber( where, 'options.seed', seed );
	const statistic = options.errorStatistic ?? 'mean';
	if ( statistic !== 'mean' && statistic !== 'p95' && statistic !== 'max' ) {

		throw new RangeError( `${where}: options.errorStatistic must be 'mean', 'p95' or 'max', got ${JSON.stringify( statistic )}.` );

	}

	const fit = readFit( where, options.fit );
	const strategy = options.strategy ?? ( fit !== null ? 'mean' : 'worst' ), trials = options.trials ?? 16;
	if ( strategy !== 'worst' && strategy !== 'mean' ) {

		throw new RangeError( `${where}: options.strategy must be 'worst' or 'mean', got ${JSON.stringify( strategy )}.` );

	}

	assertInteger( where, 'options.trials', trials, 1 );
	const normals = options.normals ?? IRRADIANCE_ERROR_NORMALS;
	const directions = assertPoints( where, 'options.normals', normals, 1 );
	const required = readKeep( where, options.keep, count );
	if ( targetCount !== undefined && required.length > targetCount ) {

		throw new RangeError( `${where}: options.keep has ${required.length} probes, more than options.targetCount (${targetCount}).` );

	}

	const swapTrials = options.swapTrials ?? DEFAULT_SWAP_TRIALS;
	assertInteger( where, 'options.swapTrials', swapTrials, 1 );
	const hullTrials = options.hullTrials ?? 'relocate';
	if ( hullTrials !== 'relocate' && hullTrials !== 'local' ) {

		throw new RangeError( `${where}: options.hullTrials must be 'relocate' or 'local', got ${describeValue( hullTrials )}.` );

	}

	return {
		targetCount, targetError, statistic, seed, strategy, trials, normals, directions, required, fit,
		swapTrials, hullTrials, swapPasses: readSwaps( where, options.swaps, fit !== null ),
		fitSet: readFitSet( where, positions, sh, count, options ),
	};

}

/** `options.fit`: undefined or false (off), true (defaults) or { gradients, lambda, gradientLambda, nonNegative }. */
function readFit( where: string, fit: ReduceProbesOptions[ 'fit' ] ): FitSettings | null {

	if ( fit === undefined || fit === false ) return null;
	if ( fit === true ) return { gradients: false, lambda: 'auto', gradientLambda: 'auto', nonNegative: false };
	if ( fit === null || typeof fit !== 'object' || Array.isArray( fit ) ) {

		throw new TypeError( `${where}: options.fit must be true, false or { gradients, lambda, gradientLambda, nonNegative }, got ${describeValue( fit )}.` );

	}

	for ( const key of Object.keys( fit ) ) {

		if ( ! FIT_KEYS.includes( key ) ) throw new TypeError( `${where}: options.fit has unknown option "${key}"; the options are ${FIT_KEYS.join( ', ' )}.` );

	}

	const { gradients = false, lambda = 'auto', gradientLambda = 'auto', nonNegative = false } = fit;
	assertOptionalBoolean( where, 'options.fit.gradients', gradients );
	assertOptionalBoolean( where, 'options.fit.nonNegative', nonNegative );
	assertLambda( where, 'options.fit.lambda', lambda );
	assertLambda( where, 'options.fit.gradientLambda', gradientLambda );
	return { gradients, lambda, gradientLambda, nonNegative };

}

function assertLambda( where: string, name: string, value: unknown ): asserts value is number | 'auto' {

	if ( value === 'auto' || ( typeof value === 'number' && Number.isFinite( value ) && value >= 0 ) ) return;
	const message = `${where}: ${name} must be 'auto' or a finite number ≥ 0, got ${describeValue( value )}.`;
	throw typeof value === 'number' ? new RangeError( message ) : new TypeError( message );

}

/** `options.swaps` as a number of passes (0: none). */
function readSwaps( where: string, swaps: ReduceProbesOptions[ 'swaps' ], fit: boolean ): number {

	if ( swaps === undefined ) return fit ? DEFAULT_SWAP_PASSES : 0;
	if ( swaps === false ) return 0;
	if ( swaps !== true ) {

		if ( typeof swaps !== 'number' ) throw new TypeError( `${where}: options.swaps must be true, false or a number of passes, got ${describeValue( swaps )}.` );
		assertInteger( where, 'options.swaps', swaps, 0 );

	}

	if ( ! fit ) {

		throw new RangeError( `${where}: options.swaps needs options.fit: a swap is kept when the re-fitted error drops (turn fit on, or leave swaps out).` );

	}

	return swaps === true ? DEFAULT_SWAP_PASSES : swaps;

}

/** The dense candidates plus `fitSamples`, and their weights (null when none were asked for). */
function readFitSet(
	where: string, positions: ArrayLike<number>, sh: ArrayLike<number>, count: number, options: ReduceProbesOptions,
): FitSet {

	const { fitSamples, weights, region } = options;
	let extra = 0;
	if ( fitSamples !== undefined ) {

		if ( fitSamples === null || typeof fitSamples !== 'object' ) {

			throw new TypeError( `${where}: options.fitSamples must be { positions, sh, weights? }, got ${describeValue( fitSamples )}.` );

		}

		extra = assertPoints( where, 'options.fitSamples.positions', fitSamples.positions );
		assertSH( where, 'options.fitSamples.sh', fitSamples.sh, extra );
		if ( fitSamples.weights !== undefined ) assertWeights( where, 'options.fitSamples.weights', fitSamples.weights, extra );

	}

	if ( weights !== undefined ) assertWeights( where, 'options.weights', weights, count );
	const total = count + extra;
	const allPositions = new Float64Array( 3 * total ), allSH = new Float64Array( 27 * total );
	allPositions.set( positions );
	allSH.set( sh );
	if ( fitSamples !== undefined && extra > 0 ) {

		allPositions.set( fitSamples.positions, 3 * count );
		allSH.set( fitSamples.sh, 27 * count );

	}

	const weighted = weights !== undefined || region !== undefined || fitSamples?.weights !== undefined;
	if ( ! weighted ) return { denseCount: count, positions: allPositions, sh: allSH, weights: null };
	const combined = region !== undefined ? weightsInRegion( where, 'options.region', allPositions, region ) : new Float64Array( total ).fill( 1 );
	let sum = 0;
	for ( let p = 0; p < total; p ++ ) {

		const given = p < count ? weights?.[ p ] : fitSamples?.weights?.[ p - count ];
		if ( given !== undefined ) combined[ p ] *= given;
		sum += combined[ p ];

	}

	if ( ! ( sum > 0 ) ) {

		throw new RangeError( `${where}: every point has weight 0 (options.weights, options.region and options.fitSamples.weights together); at least one must count.` );

	}

	return { denseCount: count, positions: allPositions, sh: allSH, weights: combined };

}

/** One finite weight ≥ 0 per point. */
function assertWeights( where: string, name: string, weights: unknown, count: number ): void {

	assertArrayLike( where, name, weights );
	if ( weights.length !== count ) throw new RangeError( `${where}: ${name} must have one weight per point (${count}), got length ${weights.length}.` );
	assertFinite( where, name, weights );
	for ( let p = 0; p < count; p ++ ) {

		if ( weights[ p ] < 0 ) throw new RangeError( `${where}: ${name}[${p}] is ${weights[ p ]}; weights must be ≥ 0.` );

	}

}

/** Validated, de-duplicated `keep` indices. */
function readKeep( where: string, keep: ArrayLike<number> | undefined, count: number ): number[] {

	if ( keep === undefined ) return [];
	assertArrayLike( where, 'options.keep', keep );
	assertFinite( where, 'options.keep', keep );
	const out: number[] = [];
	for ( let k = 0; k < keep.length; k ++ ) {

		assertInteger( where, `options.keep[${k}]`, keep[ k ], 0, count - 1 );
		if ( ! out.includes( keep[ k ] ) ) out.push( keep[ k ] );

	}

	return out;

}
