import { describe, expect, it } from 'vitest';
import { GridInterpolator } from '../../src/interpolation/GridInterpolator.js';
import { PlanarMesh } from '../../src/interpolation/PlanarMesh.js';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { blendSH } from '../../src/interpolation/blendSH.js';
import { evaluateGradientField, fitProbeSH } from '../../src/fitting/index.js';
import type { ProbeInterpolator } from '../../src/interpolation/ProbeInterpolator.js';
import { jitteredLattice, linearField, maxDifference, perturbed, randomPoints, sample } from './fields.js';

type Fit = { sh: Float32Array; gradients: Float32Array | null };
const fieldOf = (
	interpolator: ProbeInterpolator, positions: ArrayLike<number>, fit: Fit, points: ArrayLike<number>,
): Float32Array => evaluateGradientField( interpolator, positions, fit.sh, fit.gradients, points );

/*
 * Fields the layout can represent are reproduced exactly. Truth: a field linear in position, f(q) =
 * a + B·q per SH float. Barycentric (and trilinear) weights reproduce linear functions inside the
 * cells, so plain probes holding f(pᵢ) give f(q) there; gradient probes holding f(pᵢ) and B give
 * Σ wᵢ (f(pᵢ) + B(q − pᵢ)) = f(q) for any weights summing to 1 — outside the hull too.
 */

const probes = jitteredLattice();
const mesh = new TetrahedralMesh( probes );
const truthAtProbes = sample( linearField, probes );
// The field's gradient: ∂f/∂axis per SH float, in the 81-float layout.
const gradientOfField = ( count: number ): Float32Array => {

	const one = new Float64Array( 27 ), shifted = new Float64Array( 27 ), out = new Float32Array( 81 * count );
	linearField( 0, 0, 0, one, 0 );
	for ( let a = 0; a < 3; a ++ ) {

		linearField( a === 0 ? 1 : 0, a === 1 ? 1 : 0, a === 2 ? 1 : 0, shifted, 0 );
		for ( let i = 0; i < count; i ++ ) for ( let k = 0; k < 27; k ++ ) out[ 81 * i + 27 * a + k ] = shifted[ k ] - one[ k ];

	}

	return out;

};

// Inside the hull (the cube ±2), and a shell outside it reaching ±3 (outer cells).
const inside = randomPoints( 1500, - 1.95, 1.95, 11 );
const around = randomPoints( 1500, - 3, 3, 12 );
const evaluation = randomPoints( 400, - 1.9, 1.9, 13 );
const evaluationAround = randomPoints( 400, - 3, 3, 14 );

describe( 'fitProbeSH on a field linear in position', () => {

	it( 'plain probes, λ = 0, from noisy captures: the fit recovers f(pᵢ) and reproduces f inside the hull', () => {

		const noisy = perturbed( truthAtProbes, 0.5, 3 );
		const result = fitProbeSH( mesh, probes, noisy, { positions: inside, sh: sample( linearField, inside ) }, { lambda: 0 } );
		expect( maxDifference( result.sh, truthAtProbes ) ).toBeLessThan( 1e-5 );
		const predicted = evaluateGradientField( mesh, probes, result.sh, null, evaluation );
		expect( maxDifference( predicted, sample( linearField, evaluation ) ) ).toBeLessThan( 1e-5 );
		expect( result.fitError ).toBeLessThan( 1e-6 );
		expect( result.crossValidationError ).toBeNull();
		expect( result.gradients ).toBeNull();
		expect( result.gradientLambda ).toBe( 0 );
		// The noisy captures alone are far off: the test can fail.
		expect( maxDifference( noisy, truthAtProbes ) ).toBeGreaterThan( 0.4 );

	} );

	it( 'plain probes with their true captures keep them for every λ, and \'auto\' reports a zero cross-validation error', () => {

		const samples = { positions: inside, sh: sample( linearField, inside ) };
		for ( const lambda of [ 0, 1e-3, 1, 1e3 ] ) {

			const { sh } = fitProbeSH( mesh, probes, truthAtProbes, samples, { lambda } );
			expect( maxDifference( sh, truthAtProbes ) ).toBeLessThan( 1e-5 );

		}

		const auto = fitProbeSH( mesh, probes, truthAtProbes, samples );
		expect( maxDifference( auto.sh, truthAtProbes ) ).toBeLessThan( 1e-5 );
		expect( auto.crossValidationError ).toBeLessThan( 1e-6 );
		expect( auto.lambda ).toBeGreaterThan( 0 );

	} );

	it( 'gradient probes, λg = 0: exact at points inside and outside the hull (outer cells), for any λc', () => {

		const samples = { positions: around, sh: sample( linearField, around ) };
		const truth = sample( linearField, evaluationAround );
		for ( const lambda of [ 0, 0.01, 1, 100 ] ) {

			const result = fitProbeSH( mesh, probes, truthAtProbes, samples, { gradients: true, lambda, gradientLambda: 0 } );
			expect( result.gradients ).not.toBeNull();
			expect( maxDifference( result.gradients!, gradientOfField( probes.length / 3 ) ), `λc ${lambda}` ).toBeLessThan( 1e-5 );
			expect( maxDifference( fieldOf( mesh, probes, result, evaluationAround ), truth ) ).toBeLessThan( 1e-5 );

		}

		// From noisy captures with no pull at all, the data alone fix c and G.
		const noisy = perturbed( truthAtProbes, 0.5, 4 );
		const free = fitProbeSH( mesh, probes, noisy, samples, { gradients: true, lambda: 0, gradientLambda: 0 } );
		expect( maxDifference( fieldOf( mesh, probes, free, evaluationAround ), truth ) ).toBeLessThan( 1e-4 );
		// Plain probes cannot follow the field outside the hull (outer cells use 3 hull probes): the
		// test above is not trivially true.
		const plain = fitProbeSH( mesh, probes, truthAtProbes, samples, { lambda: 0 } );
		expect( maxDifference( fieldOf( mesh, probes, plain, evaluationAround ), truth ) ).toBeGreaterThan( 0.01 );

	} );

	it( 'on a grid (8 trilinear weights, clamped outside the box) and on a planar mesh', () => {

		const grid = new GridInterpolator( [ - 2, - 2, - 2 ], [ 2, 2, 2 ], [ 3, 4, 3 ] );
		const gridTruth = sample( linearField, grid.positions );
		const noisy = perturbed( gridTruth, 0.5, 5 );
		const plain = fitProbeSH( grid, grid.positions, noisy, { positions: inside, sh: sample( linearField, inside ) }, { lambda: 0 } );
		expect( maxDifference( plain.sh, gridTruth ) ).toBeLessThan( 1e-5 );
		const gradient = fitProbeSH( grid, grid.positions, gridTruth, { positions: around, sh: sample( linearField, around ) }, {
			gradients: true, lambda: 1, gradientLambda: 0,
		} );
		const truth = sample( linearField, evaluationAround );
		expect( maxDifference( fieldOf( grid, grid.positions, gradient, evaluationAround ), truth ) ).toBeLessThan( 1e-5 );

		// A floor of probes at y = 0; samples around it, above and below: only gradients follow y.
		const floor = Float64Array.from( [ - 2, 0, - 2, 2, 0, - 2, - 2, 0, 2, 2, 0, 2, 0, 0, 0, 0.7, 0, - 1.1 ] );
		const planar = new PlanarMesh( floor );
		const aroundSamples = { positions: around, sh: sample( linearField, around ) };
		const planarFit = fitProbeSH( planar, floor, sample( linearField, floor ), aroundSamples, {
			gradients: true, lambda: 1, gradientLambda: 0,
		} );
		expect( maxDifference( fieldOf( planar, floor, planarFit, evaluationAround ), truth ) ).toBeLessThan( 1e-5 );

	} );

} );

describe( 'evaluateGradientField', () => {

	it( 'with probes holding f(pᵢ) and ∇f gives f(q) anywhere; with null gradients it is blendSH', () => {

		const field = evaluateGradientField( mesh, probes, truthAtProbes, gradientOfField( probes.length / 3 ), evaluationAround );
		expect( maxDifference( field, sample( linearField, evaluationAround ) ) ).toBeLessThan( 1e-5 );

		const plain = evaluateGradientField( mesh, probes, truthAtProbes, null, evaluationAround );
		const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 ), out = new Float64Array( 27 );
		for ( let j = 0; j < 400; j ++ ) {

			mesh.interpolate( evaluationAround[ 3 * j ], evaluationAround[ 3 * j + 1 ], evaluationAround[ 3 * j + 2 ], indices, weights );
			blendSH( indices, weights, truthAtProbes, out );
			for ( let k = 0; k < 27; k ++ ) expect( plain[ 27 * j + k ] ).toBe( Math.fround( out[ k ] ) );

		}

	} );

	it( 'names wrong arguments', () => {

		const g = new Float32Array( 81 * 64 );
		const name = /^evaluateGradientField: /;
		expect( () => evaluateGradientField( {} as never, probes, truthAtProbes, null, evaluation ) ).toThrow( /interpolator must be/ );
		expect( () => evaluateGradientField( {} as never, probes, truthAtProbes, null, evaluation ) ).toThrow( name );
		expect( () => evaluateGradientField( mesh, probes.subarray( 3 ), truthAtProbes, null, evaluation ) ).toThrow( /probePositions holds 63 probes/ );
		expect( () => evaluateGradientField( mesh, probes, truthAtProbes, g.subarray( 1 ), evaluation ) ).toThrow( /gradients must have length 5184/ );
		expect( () => evaluateGradientField( mesh, probes, truthAtProbes, g, [ 0, 0 ] ) ).toThrow( RangeError );
		expect( () => evaluateGradientField( mesh, probes, truthAtProbes, g, [ 0, NaN, 0 ] ) ).toThrow( /points\[1\] is NaN/ );

	} );

} );
