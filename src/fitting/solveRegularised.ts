import { factorCholesky, solveCholesky } from './cholesky.js';
import type { Envelope } from './envelope.js';
import type { NormalEquations } from './normalEquations.js';

/** Reusable buffers for {@link solveRegularised}: the factor and the solution. */
export interface SolveScratch {

	/** Envelope values: the regularised matrix, then its Cholesky factor. */
	readonly matrix: Float64Array;

	/** The right-hand side, then the solution: 27 columns per unknown. */
	readonly solution: Float64Array;

}

/** Buffers for systems over `envelope`. */
export function createSolveScratch( envelope: Envelope ): SolveScratch {

	return { matrix: new Float64Array( envelope.length ), solution: new Float64Array( 27 * envelope.size ) };

}

// The ridge added when the regularised matrix is singular (λ = 0 and unknowns no sample pins down),
// as a fraction of the mean diagonal entry; raised 1000-fold per retry.
const RIDGE = 1e-9;

/**
 * Minimises (1/Σs)·Σⱼ sⱼ‖uⱼ·X − yⱼ‖² + (λc/n)·Σᵢ‖cᵢ − c̄ᵢ‖² + (λg/n)·Σᵢ‖h·Gᵢ‖² (n local probes):
 * solves (B/Σs + D)·X = R/Σs + D_c·C̄ with one Cholesky factor for all 27 columns. When that
 * matrix is singular to working precision a small ridge (1e-9 of the mean diagonal, toward the
 * captured SH and zero gradient) is added, so the result is always finite.
 * @param captured c̄ of each local probe, 27 floats each.
 * @returns `scratch.solution`: `stride` unknowns per local probe, 27 floats each.
 */
export function solveRegularised(
	envelope: Envelope, equations: NormalEquations, captured: Float64Array, stride: number,
	lambda: number, gradientLambda: number, scratch: SolveScratch,
): Float64Array {

	const { matrix, solution } = scratch;
	const { size, diagonal } = envelope;
	const probes = size / stride, inverse = 1 / equations.weightSum;
	let meanDiagonal = 0;
	for ( let r = 0; r < size; r ++ ) meanDiagonal += equations.matrix[ diagonal[ r ] ] * inverse / size;
	let ridge = 0;
	for ( let attempt = 0; ; attempt ++ ) {

		const pullC = lambda / probes + ridge, pullG = gradientLambda / probes + ridge;
		for ( let i = 0; i < envelope.length; i ++ ) matrix[ i ] = equations.matrix[ i ] * inverse;
		for ( let i = 0; i < solution.length; i ++ ) solution[ i ] = equations.rhs[ i ] * inverse;
		for ( let r = 0; r < size; r ++ ) {

			const gradient = r % stride !== 0;
			matrix[ diagonal[ r ] ] += gradient ? pullG : pullC;
			if ( gradient ) continue;
			const row = 27 * r, source = 27 * ( r / stride );
			for ( let k = 0; k < 27; k ++ ) solution[ row + k ] += pullC * captured[ source + k ];

		}

		if ( factorCholesky( envelope, matrix ) ) break;
		if ( attempt === 3 ) throw new Error( 'solveRegularised: the normal matrix stayed singular with a ridge; the samples or probes hold values beyond float64.' );
		ridge = ridge === 0 ? RIDGE * ( meanDiagonal > 0 ? meanDiagonal : 1 ) : ridge * 1000;

	}

	solveCholesky( envelope, matrix, solution, 27 );
	return solution;

}
