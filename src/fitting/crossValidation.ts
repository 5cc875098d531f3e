import { mulberry32 } from '../tetrahedra/spatialOrder.js';
import type { Envelope } from './envelope.js';
import { accumulateNormalEquations, addNormalEquations, createNormalEquations, type NormalEquations } from './normalEquations.js';
import { weightedPredictionError } from './predictionError.js';
import type { SampleDesign } from './sampleDesign.js';
import { createSolveScratch, solveRegularised } from './solveRegularised.js';
import { searchLine, searchPlane } from './lambdaSearch.js';

/** What {@link chooseLambdas} needs besides the design. */
export interface CrossValidationInput {

	/** The samples' design rows. */
	design: SampleDesign;

	/** The normal matrix's layout. */
	envelope: Envelope;

	/** 27 floats per sample. */
	truth: Float64Array;

	/** One > 0 per sample. */
	weights: Float64Array;

	/** c̄ per local probe, 27 each. */
	captured: Float64Array;

	/** 1 / (K · Ē), Ē over all samples. */
	scale: number;

	/** A fixed λ, or 'auto' to choose it. */
	lambda: number | 'auto';

	/** A fixed gradient λ, or 'auto' (ignored without gradients). */
	gradientLambda: number | 'auto';

	/** Folds (at most the sample count is used). */
	folds: number;

	/** Fold assignment seed. */
	seed: number;

}

/** The λ chosen and its cross-validation error. */
export interface LambdaChoice {

	/** The λ chosen (or given). */
	lambda: number;

	/** The gradient λ chosen (or given); 0 without gradients. */
	gradientLambda: number;

	/** Σ sⱼ errorⱼ / Σ sⱼ over every sample, each predicted by the fit without its fold. */
	error: number;

}

/**
 * k-fold cross-validation of the regularised fit: samples shuffled with `seed` (mulberry32) and
 * dealt to the folds in turn; each fold's samples are predicted by the fit to the other folds and
 * judged with the library's irradiance error; the λ (and gradient λ) with the lowest pooled
 * weighted error over all held-out samples wins.
 */
export function chooseLambdas( input: CrossValidationInput ): LambdaChoice {

	const { design, envelope, captured, truth, weights, scale } = input;
	const count = design.count, folds = Math.min( input.folds, count );
	const foldOf = assignFolds( count, folds, input.seed );
	const heldOut: NormalEquations[] = [];
	for ( let f = 0; f < folds; f ++ ) {

		const equations = createNormalEquations( envelope );
		accumulateNormalEquations( design, envelope, truth, weights, equations, foldOf, f );
		heldOut.push( equations );

	}

	const training = heldOut.map( ( _, f ) => {

		const equations = createNormalEquations( envelope );
		heldOut.forEach( ( other, g ) => {

			if ( g !== f ) addNormalEquations( equations, other );

		} );
		return equations;

	} );

	let totalWeight = 0;
	for ( let j = 0; j < count; j ++ ) totalWeight += weights[ j ];
	const scratch = createSolveScratch( envelope );
	const cache = new Map<string, number>();
	const gradients = design.stride > 1;
	const error = ( lambda: number, gradientLambda: number ): number => {

		const key = `${lambda} ${gradientLambda}`;
		const known = cache.get( key );
		if ( known !== undefined ) return known;
		let sum = 0;
		for ( let f = 0; f < folds; f ++ ) {

			const solution = solveRegularised( envelope, training[ f ], captured, design.stride, lambda, gradientLambda, scratch );
			sum += weightedPredictionError( design, solution, truth, weights, scale, foldOf, f );

		}

		const value = sum / totalWeight;
		cache.set( key, value );
		return value;

	};

	const power = ( e: number ): number => Math.pow( 10, e );
	let lambda: number, gradientLambda: number;
	if ( ! gradients ) {

		gradientLambda = 0;
		lambda = input.lambda === 'auto' ? power( searchLine( ( e ) => error( power( e ), 0 ) ) ) : input.lambda;

	} else if ( input.lambda === 'auto' && input.gradientLambda === 'auto' ) {

		const [ e1, e2 ] = searchPlane( ( a, b ) => error( power( a ), power( b ) ) );
		lambda = power( e1 );
		gradientLambda = power( e2 );

	} else if ( input.lambda === 'auto' ) {

		const fixed = input.gradientLambda as number;
		lambda = power( searchLine( ( e ) => error( power( e ), fixed ) ) );
		gradientLambda = fixed;

	} else {

		const fixed = input.lambda;
		gradientLambda = power( searchLine( ( e ) => error( fixed, power( e ) ) ) );
		lambda = fixed;

	}

	return { lambda, gradientLambda, error: error( lambda, gradientLambda ) };

}

/** Fold of each sample: a seeded shuffle dealt round-robin, so folds differ in size by at most one. */
export function assignFolds( count: number, folds: number, seed: number ): Uint8Array {

	const order = Uint32Array.from( { length: count }, ( _, j ) => j );
	const random = mulberry32( seed );
	for ( let i = count - 1; i > 0; i -- ) {

		const j = Math.floor( random() * ( i + 1 ) );
		const t = order[ i ]; order[ i ] = order[ j ]; order[ j ] = t;

	}

	const foldOf = new Uint8Array( count );
	for ( let i = 0; i < count; i ++ ) foldOf[ order[ i ] ] = i % folds;
	return foldOf;

}
