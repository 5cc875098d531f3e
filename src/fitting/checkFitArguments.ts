import {
	assertArrayLike, assertFinite, assertInteger, assertOptionalBoolean, assertOptions, assertPoints, assertSH, describeValue,
} from '../validate.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { assertInterpolator } from './assertInterpolator.js';
import type { FitProbeSHOptions, FitSamples } from './fitProbeSH.js';

const OPTION_KEYS = [ 'gradients', 'lambda', 'gradientLambda', 'folds', 'seed', 'nonNegative' ];

/** The arguments of `fitProbeSH`, checked, with the samples of weight 0 dropped. */
export interface CheckedFit {

	/** The interpolator's probe count. */
	probeCount: number;

	/** Positions of the samples kept, 3 each. */
	positions: Float64Array;

	/** Their SH, 27 each. */
	sh: Float64Array;

	/** Their weights, each > 0. */
	weights: Float64Array;

	/** The options, defaults filled in. */
	gradients: boolean;

	/** λ given, or 'auto'. */
	lambda: number | 'auto';

	/** Gradient λ given, or 'auto'. */
	gradientLambda: number | 'auto';

	/** Cross-validation folds. */
	folds: number;

	/** Fold assignment seed. */
	seed: number;

	/** Whether the non-negative step runs. */
	nonNegative: boolean;

}

/** Samples of a fit, checked, those of weight 0 dropped (the `CheckedFit` fields). */
export type CheckedSamples = Pick<CheckedFit, 'positions' | 'sh' | 'weights'>;

/**
 * Checks every argument of `fitProbeSH` (named errors; nothing is read twice) and keeps the samples
 * with a positive weight, so zero-weight samples cannot change any result.
 * @param prepared The samples already checked by {@link checkFitSamples} (then `samples` is not read).
 */
export function checkFitArguments(
	where: string, interpolator: ProbeInterpolator, probePositions: ArrayLike<number>, probeSH: ArrayLike<number>,
	samples: FitSamples, options: FitProbeSHOptions | undefined, prepared?: CheckedSamples,
): CheckedFit {

	const { probeCount } = assertInterpolator( where, interpolator );
	const probes = assertPoints( where, 'probePositions', probePositions );
	if ( probes !== probeCount ) {

		throw new RangeError( `${where}: probePositions holds ${probes} probes; the interpolator has ${probeCount}.` );

	}

	assertSH( where, 'probeSH', probeSH, probeCount );
	const { positions, sh, weights } = prepared ?? checkFitSamples( where, samples );
	assertOptions( where, 'options', options );
	const o = options ?? {};
	for ( const key of Object.keys( o ) ) {

		if ( ! OPTION_KEYS.includes( key ) ) throw new TypeError( `${where}: unknown option "${key}"; the options are ${OPTION_KEYS.join( ', ' )}.` );

	}

	const { gradients = false, lambda = 'auto', gradientLambda = 'auto', folds = 5, seed = 1, nonNegative = false } = o;
	assertOptionalBoolean( where, 'options.gradients', gradients );
	assertOptionalBoolean( where, 'options.nonNegative', nonNegative );
	assertLambda( where, 'options.lambda', lambda );
	assertLambda( where, 'options.gradientLambda', gradientLambda );
	assertInteger( where, 'options.folds', folds, 2, 255 );
	assertInteger( where, 'options.seed', seed, - 0x80000000, 0xFFFFFFFF );
	return { probeCount, positions, sh, weights, gradients, lambda, gradientLambda, folds, seed, nonNegative };

}

/** Checks a fit's samples and keeps those with a positive weight, copied. */
export function checkFitSamples( where: string, samples: FitSamples ): CheckedSamples {

	if ( samples === null || typeof samples !== 'object' ) {

		throw new TypeError( `${where}: samples must be { positions, sh, weights? }, got ${describeValue( samples )}.` );

	}

	const count = assertPoints( where, 'samples.positions', samples.positions );
	if ( count === 0 ) throw new RangeError( `${where}: samples.positions is empty; the fit needs at least one sample.` );
	assertSH( where, 'samples.sh', samples.sh, count );
	const given = samples.weights;
	if ( given !== undefined ) {

		assertArrayLike( where, 'samples.weights', given );
		if ( given.length !== count ) {

			throw new RangeError( `${where}: samples.weights must hold one weight per sample (${count}), got length ${given.length}.` );

		}

		assertFinite( where, 'samples.weights', given );
		for ( let j = 0; j < count; j ++ ) {

			if ( given[ j ] < 0 ) throw new RangeError( `${where}: samples.weights[${j}] is ${given[ j ]}; weights must be ≥ 0.` );

		}

	}

	const kept: number[] = [];
	for ( let j = 0; j < count; j ++ ) if ( given === undefined || given[ j ] > 0 ) kept.push( j );
	if ( kept.length === 0 ) throw new RangeError( `${where}: every sample has weight 0; the fit needs at least one sample with a positive weight.` );
	const positions = new Float64Array( 3 * kept.length ), sh = new Float64Array( 27 * kept.length );
	const weights = new Float64Array( kept.length );
	kept.forEach( ( j, n ) => {

		for ( let a = 0; a < 3; a ++ ) positions[ 3 * n + a ] = samples.positions[ 3 * j + a ];
		for ( let k = 0; k < 27; k ++ ) sh[ 27 * n + k ] = samples.sh[ 27 * j + k ];
		weights[ n ] = given === undefined ? 1 : given[ j ];

	} );

	return { positions, sh, weights };

}

function assertLambda( where: string, name: string, value: unknown ): asserts value is number | 'auto' {

	if ( value === 'auto' || ( typeof value === 'number' && Number.isFinite( value ) && value >= 0 ) ) return;
	const message = `${where}: ${name} must be 'auto' or a finite number ≥ 0, got ${describeValue( value )}.`;
	throw typeof value === 'number' ? new RangeError( message ) : new TypeError( message );

}
