import { describe, expect, it } from 'vitest';
import { DynamicTetrahedralization } from '../../src/tetrahedra/DynamicTetrahedralization.js';
import { IncrementalTetrahedralMesh } from '../../src/interpolation/IncrementalTetrahedralMesh.js';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { irradianceError } from '../../src/placement/irradianceError.js';
import { evaluateGradientField, fitProbeSH, type FitProbeSHOptions, type FitSamples } from '../../src/fitting/index.js';
import { jitteredLattice, maxDifference, perturbed, pointLightField, randomPoints, sample } from './fields.js';

/*
 * λ at its edges, sample weights, probes no sample reaches, determinism, and the rule that the
 * fit never sees evaluation data.
 */

const field = pointLightField();
const probes = jitteredLattice();
const mesh = new TetrahedralMesh( probes );
const captured = sample( field, probes );
const fitPoints = randomPoints( 600, - 2.2, 2.2, 31 );
const fitSH = sample( field, fitPoints );
const samples: FitSamples = { positions: fitPoints, sh: fitSH };

const bits = ( a: Float32Array | null ): number[] => ( a === null ? [] : [ ...new Uint32Array( a.buffer, a.byteOffset, a.length ) ] );
function expectIdentical( a: ReturnType<typeof fitProbeSH>, b: ReturnType<typeof fitProbeSH> ): void {

	expect( bits( a.sh ) ).toEqual( bits( b.sh ) );
	expect( bits( a.gradients ) ).toEqual( bits( b.gradients ) );
	const scalars = ( r: ReturnType<typeof fitProbeSH> ): unknown[] => [ r.lambda, r.gradientLambda, r.crossValidationError, r.fitError ];
	expect( scalars( a ) ).toEqual( scalars( b ) );

}

describe( 'fitProbeSH: λ', () => {

	it( 'a huge λ keeps the captured SH (and zero gradients); the squared residual the fit minimises falls as λ does', () => {

		for ( const gradients of [ false, true ] ) {

			const huge = fitProbeSH( mesh, probes, captured, samples, { gradients, lambda: 1e12, gradientLambda: 1e12 } );
			expect( maxDifference( huge.sh, captured ) ).toBeLessThan( 1e-6 );
			if ( gradients ) expect( maxDifference( huge.gradients!, new Float32Array( 81 * 64 ) ) ).toBeLessThan( 1e-6 );
			const residuals = [ 1e12, 1, 1e-2, 1e-4, 0 ].map( ( lambda ) => {

				const fit = fitProbeSH( mesh, probes, captured, samples, { gradients, lambda, gradientLambda: lambda } );
				const predicted = evaluateGradientField( mesh, probes, fit.sh, fit.gradients, fitPoints );
				return predicted.reduce( ( sum, v, k ) => sum + ( v - samples.sh[ k ] ) ** 2, 0 );

			} );
			for ( let i = 1; i < residuals.length; i ++ ) expect( residuals[ i ], `${gradients} ${i}` ).toBeLessThan( residuals[ i - 1 ] );

		}

	} );

	it( '\'auto\' is the default, reports the λ it chose and a cross-validation error; fixed λ report null', () => {

		const auto = fitProbeSH( mesh, probes, captured, samples );
		expect( auto.lambda ).toBeGreaterThan( 0 );
		expect( auto.crossValidationError ).toBeGreaterThan( 0 );
		// The chosen λ, given back, gives the same fit without cross-validation.
		const again = fitProbeSH( mesh, probes, captured, samples, { lambda: auto.lambda } );
		expect( bits( again.sh ) ).toEqual( bits( auto.sh ) );
		expect( again.crossValidationError ).toBeNull();
		// One λ given, the other chosen.
		const half = fitProbeSH( mesh, probes, captured, samples, { gradients: true, lambda: 0.5 } );
		expect( half.lambda ).toBe( 0.5 );
		expect( half.gradientLambda ).toBeGreaterThan( 0 );
		expect( half.crossValidationError ).not.toBeNull();
		const other = fitProbeSH( mesh, probes, captured, samples, { gradients: true, gradientLambda: 0.5 } );
		expect( other.gradientLambda ).toBe( 0.5 );
		expect( other.lambda ).not.toBe( 0.5 );
		// gradientLambda is ignored without gradients.
		expect( fitProbeSH( mesh, probes, captured, samples, { lambda: 0.5, gradientLambda: 3 } ).gradientLambda ).toBe( 0 );

	} );

	it( 'λ = 0 with unknowns no sample pins down (one sample) stays finite: the ridge keeps the rest captured', () => {

		const one = { positions: [ 0.1, 0.2, 0.3 ], sh: fitSH.slice( 0, 27 ) };
		for ( const gradients of [ false, true ] ) {

			const result = fitProbeSH( mesh, probes, captured, one, { gradients, lambda: 0, gradientLambda: 0 } );
			expect( result.sh.every( Number.isFinite ) ).toBe( true );
			expect( result.fitError ).toBeLessThan( 1e-6 );
			if ( gradients ) expect( result.gradients!.every( Number.isFinite ) ).toBe( true );

		}

	} );

} );

describe( 'fitProbeSH: probes without samples', () => {

	it( 'probes no sample reaches keep their captured SH exactly, with zero gradient', () => {

		// Samples only in the octant x, y, z < −0.8: the probes far from it get no weight.
		const corner = randomPoints( 200, - 2, - 0.8, 41 );
		const result = fitProbeSH( mesh, probes, captured, { positions: corner, sh: sample( field, corner ) }, { gradients: true } );
		let far = 0;
		for ( let i = 0; i < 64; i ++ ) {

			if ( probes[ 3 * i ] < 0 || probes[ 3 * i + 1 ] < 0 || probes[ 3 * i + 2 ] < 0 ) continue;
			far ++;
			expect( result.sh.subarray( 27 * i, 27 * i + 27 ) ).toEqual( Float32Array.from( captured.subarray( 27 * i, 27 * i + 27 ) ) );
			expect( result.gradients!.subarray( 81 * i, 81 * i + 81 ).every( ( g ) => g === 0 ) ).toBe( true );

		}

		expect( far ).toBeGreaterThan( 5 );
		expect( maxDifference( result.sh, captured ) ).toBeGreaterThan( 1e-3 ); // the others were fitted

	} );

	it( 'a removed probe of an incremental mesh keeps its captured SH', () => {

		const incremental = new IncrementalTetrahedralMesh( new DynamicTetrahedralization( probes ) );
		incremental.removeProbe( 21 );
		const result = fitProbeSH( incremental, probes, captured, samples, { lambda: 0.1, gradients: true, gradientLambda: 0.1 } );
		expect( result.sh.subarray( 27 * 21, 27 * 22 ) ).toEqual( Float32Array.from( captured.subarray( 27 * 21, 27 * 22 ) ) );
		expect( result.gradients!.subarray( 81 * 21, 81 * 22 ).every( ( g ) => g === 0 ) ).toBe( true );
		expect( result.sh.every( Number.isFinite ) ).toBe( true );

	} );

} );

describe( 'fitProbeSH: sample weights', () => {

	const options: FitProbeSHOptions = { gradients: true, lambda: 0.05, gradientLambda: 0.02 };

	it( 'zero-weight samples change nothing, even in cross-validation (they are left out before the folds)', () => {

		const extra = randomPoints( 50, - 2, 2, 42 );
		const junk = perturbed( sample( field, extra ), 5, 43 );
		const merged: FitSamples = {
			positions: Float64Array.from( [ ...fitPoints, ...extra ] ),
			sh: Float64Array.from( [ ...fitSH, ...junk ] ),
			weights: Float64Array.from( { length: 650 }, ( _, j ) => ( j < 600 ? 1 : 0 ) ),
		};
		expectIdentical( fitProbeSH( mesh, probes, captured, merged, options ), fitProbeSH( mesh, probes, captured, samples, options ) );
		expectIdentical( fitProbeSH( mesh, probes, captured, merged ), fitProbeSH( mesh, probes, captured, samples ) );

	} );

	it( 'weights all ×10 give the same fit: λ does not depend on the weights\' scale', () => {

		const heavy = { ...samples, weights: new Float64Array( 600 ).fill( 10 ) };
		const a = fitProbeSH( mesh, probes, captured, heavy, options ), b = fitProbeSH( mesh, probes, captured, samples, options );
		expect( maxDifference( a.sh, b.sh ) ).toBeLessThan( 1e-6 );
		expect( maxDifference( a.gradients!, b.gradients! ) ).toBeLessThan( 1e-6 );
		expect( a.fitError ).toBeCloseTo( b.fitError, 12 );

	} );

	it( 'a sample given twice equals the sample once with weight 2 (fixed λ); weights move the fit', () => {

		const twice: FitSamples = {
			positions: Float64Array.from( [ ...fitPoints, ...fitPoints.subarray( 0, 90 ) ] ),
			sh: Float64Array.from( [ ...fitSH, ...fitSH.subarray( 0, 27 * 30 ) ] ),
		};
		const weighted: FitSamples = { ...samples, weights: Float64Array.from( { length: 600 }, ( _, j ) => ( j < 30 ? 2 : 1 ) ) };
		const a = fitProbeSH( mesh, probes, captured, twice, options ), b = fitProbeSH( mesh, probes, captured, weighted, options );
		expect( maxDifference( a.sh, b.sh ) ).toBeLessThan( 1e-5 );
		expect( maxDifference( a.gradients!, b.gradients! ) ).toBeLessThan( 1e-5 );
		expect( Math.abs( a.fitError - b.fitError ) ).toBeLessThan( 1e-9 );
		expect( maxDifference( b.sh, fitProbeSH( mesh, probes, captured, samples, options ).sh ) ).toBeGreaterThan( 1e-4 );

	} );

} );

describe( 'fitProbeSH: determinism and evaluation data', () => {

	it( 'the same inputs give bit-identical results; another seed deals other folds', () => {

		const options: FitProbeSHOptions = { gradients: true, seed: 7 };
		expectIdentical( fitProbeSH( mesh, probes, captured, samples, options ), fitProbeSH( mesh, probes, captured, samples, options ) );
		const seeds = [ 1, 2, 3 ].map( ( seed ) => fitProbeSH( mesh, probes, captured, samples, { seed } ).crossValidationError );
		expect( new Set( seeds ).size ).toBeGreaterThan( 1 );

	} );

	it( 'never uses evaluation samples: the fit is bit-identical whatever the evaluation set holds', () => {

		// The harness of an experiment: fit on the fit set, judge on the evaluation set.
		const fitAndEvaluate = ( evaluation: FitSamples ): { fit: ReturnType<typeof fitProbeSH>; error: number } => {

			const fit = fitProbeSH( mesh, probes, captured, samples, { gradients: true } );
			const predicted = evaluateGradientField( mesh, probes, fit.sh, fit.gradients, evaluation.positions );
			return { fit, error: irradianceError( predicted, evaluation.sh ).mean };

		};

		const points = randomPoints( 300, - 2, 2, 51 );
		const first = fitAndEvaluate( { positions: points, sh: sample( field, points ) } );
		const other = randomPoints( 300, - 1, 1, 52 );
		const second = fitAndEvaluate( { positions: other, sh: perturbed( sample( pointLightField( [ - 1, 0, 1 ] ), other ), 0.1, 53 ) } );
		expectIdentical( first.fit, second.fit );
		expect( first.error ).not.toBe( second.error ); // the evaluation did change

	} );

} );
