import { describe, expect, it } from 'vitest';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { fitProbeSH, type FitSamples } from '../../src/fitting/index.js';
import { jitteredLattice, linearField, randomPoints, sample } from './fields.js';

/* Bad input gets a named error (TypeError for wrong types, RangeError for wrong values). */

const probes = jitteredLattice();
const mesh = new TetrahedralMesh( probes );
const captured = sample( linearField, probes );
const points = randomPoints( 40, - 1.5, 1.5, 61 );
const pointSH = sample( linearField, points );
const samples: FitSamples = { positions: points, sh: pointSH };

type Overrides = { samples?: unknown; options?: unknown; positions?: unknown; sh?: unknown; interpolator?: unknown };
const call = ( overrides: Overrides ) => () => fitProbeSH(
	( overrides.interpolator ?? mesh ) as TetrahedralMesh, ( overrides.positions ?? probes ) as ArrayLike<number>,
	( overrides.sh ?? captured ) as ArrayLike<number>, ( 'samples' in overrides ? overrides.samples : samples ) as FitSamples, overrides.options as never,
);

describe( 'fitProbeSH: named errors', () => {

	it( 'mismatched lengths', () => {

		expect( call( { positions: probes.subarray( 3 ) } ) ).toThrow( /^fitProbeSH: probePositions holds 63 probes; the interpolator has 64/ );
		expect( call( { sh: captured.subarray( 1 ) } ) ).toThrow( /^fitProbeSH: probeSH must have length 1728/ );
		expect( call( { samples: { positions: points.subarray( 1 ), sh: pointSH } } ) ).toThrow( /^fitProbeSH: samples.positions must hold x, y, z per point/ );
		expect( call( { samples: { positions: points, sh: pointSH.slice( 27 ) } } ) ).toThrow( /^fitProbeSH: samples.sh must have length 1080/ );
		expect( call( { samples: { ...samples, weights: new Float64Array( 39 ) } } ) ).toThrow( /^fitProbeSH: samples.weights must hold one weight per sample \(40\)/ );

	} );

	it( 'NaN samples, negative weights, no samples', () => {

		const nanSH = Float64Array.from( pointSH );
		nanSH[ 100 ] = NaN;
		expect( call( { samples: { positions: points, sh: nanSH } } ) ).toThrow( /^fitProbeSH: samples.sh\[100\] is NaN/ );
		const nanPosition = Float64Array.from( points );
		nanPosition[ 7 ] = Infinity;
		expect( call( { samples: { positions: nanPosition, sh: pointSH } } ) ).toThrow( /^fitProbeSH: samples.positions\[7\] is Infinity/ );
		const weights = new Float64Array( 40 ).fill( 1 );
		weights[ 3 ] = - 0.5;
		expect( call( { samples: { ...samples, weights } } ) ).toThrow( /^fitProbeSH: samples.weights\[3\] is -0.5; weights must be ≥ 0/ );
		expect( call( { samples: { ...samples, weights: new Float64Array( 40 ) } } ) ).toThrow( /^fitProbeSH: every sample has weight 0/ );
		expect( call( { samples: { positions: [], sh: [] } } ) ).toThrow( /^fitProbeSH: samples.positions is empty/ );
		expect( call( { samples: null } ) ).toThrow( TypeError );
		expect( call( { samples: { positions: points } } ) ).toThrow( /^fitProbeSH: samples.sh must be an array/ );
		// Cross-validation needs two samples (a fixed λ does not).
		const one = { positions: points.subarray( 0, 3 ), sh: pointSH.subarray( 0, 27 ) };
		expect( call( { samples: one } ) ).toThrow( /^fitProbeSH: choosing λ by cross-validation needs at least 2 samples/ );
		expect( call( { samples: one, options: { lambda: 1 } } ) ).not.toThrow();

	} );

	it( 'bad options and a bad interpolator', () => {

		expect( call( { options: { lambda: - 1 } } ) ).toThrow( /^fitProbeSH: options.lambda must be 'auto' or a finite number ≥ 0, got -1/ );
		expect( call( { options: { lambda: NaN } } ) ).toThrow( RangeError );
		expect( call( { options: { gradientLambda: 'yes' } } ) ).toThrow( TypeError );
		expect( call( { options: { folds: 1 } } ) ).toThrow( /^fitProbeSH: options.folds must be an integer in 2..255/ );
		expect( call( { options: { seed: 0.5 } } ) ).toThrow( /^fitProbeSH: options.seed must be an integer/ );
		expect( call( { options: { gradients: 1 } } ) ).toThrow( /^fitProbeSH: options.gradients must be true or false/ );
		expect( call( { options: { nonNegative: 'no' } } ) ).toThrow( TypeError );
		expect( call( { options: { lamda: 1 } } ) ).toThrow( /^fitProbeSH: unknown option "lamda"/ );
		expect( call( { options: 3 } ) ).toThrow( /^fitProbeSH: options must be an object/ );
		expect( call( { interpolator: { probeCount: 64 } } ) ).toThrow( /^fitProbeSH: interpolator must be a ProbeInterpolator/ );
		const interpolate = ( _x: number, _y: number, _z: number, i: number[], w: number[] ): number => {

			i[ 0 ] = 99; w[ 0 ] = 1; return 0;

		};

		const lying = { probeCount: 64, cellCount: 1, weightCount: 4, interpolate };
		expect( call( { interpolator: lying, options: { lambda: 1 } } ) ).toThrow( /^fitProbeSH: the interpolator gave probe 99/ );
		// All-black truth: the relative error means nothing, so no cross-validation.
		const black = { positions: points, sh: new Float64Array( 27 * 40 ) };
		expect( call( { samples: black } ) ).toThrow( /^fitProbeSH: the samples' irradiance averages 0/ );
		expect( Number.isNaN( fitProbeSH( mesh, probes, captured, black, { lambda: 1 } ).fitError ) ).toBe( true );

	} );

} );
