import { describe, expect, it } from 'vitest';
import { GridInterpolator } from '../../src/interpolation/GridInterpolator.js';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import type { ProbeInterpolator } from '../../src/interpolation/ProbeInterpolator.js';
import { minIrradiance } from '../../src/sh/minimumOverSphere.js';
import { evaluateGradientField, fitProbeSH, type FitProbeSHOptions } from '../../src/fitting/index.js';
import { jitteredLattice, pointLightField, randomPoints, sample } from './fields.js';

/*
 * nonNegative: the exact minimum of irradiance over all directions (minIrradiance, docs/ringing.md)
 * is ≥ 0 at every probe and, with gradients, everywhere inside the probes' cells and at every fit
 * sample. Weakly regularised fits to a point light close to the probes overshoot below zero, so
 * each case first checks that the fit without the option does go negative.
 */

const field = pointLightField( [ 1.5, 1.5, 1.5 ] );
const fitPoints = randomPoints( 800, - 2.2, 2.2, 21 );
const samples = { positions: fitPoints, sh: sample( field, fitPoints ) };
const inside = randomPoints( 4000, - 2, 2, 22 );

/** How many of the SH (27 floats each) have irradiance below zero in some direction, and the lowest minimum. */
function negatives( sh: ArrayLike<number> ): { count: number; lowest: number } {

	let count = 0, lowest = Infinity;
	for ( let i = 0; i < sh.length / 27; i ++ ) {

		const m = minIrradiance( sh, 27 * i );
		if ( m < 0 ) count ++;
		lowest = Math.min( lowest, m );

	}

	return { count, lowest };

}

describe( 'fitProbeSH with nonNegative', () => {

	const mesh = new TetrahedralMesh( jitteredLattice() );
	const grid = new GridInterpolator( [ - 2, - 2, - 2 ], [ 2, 2, 2 ], [ 4, 4, 4 ] );
	const cases: [ string, ProbeInterpolator, Float64Array, FitProbeSHOptions, 'probes' | 'field' ][] = [
		[ 'plain, tetrahedra, λ = 0', mesh, mesh.positions, { lambda: 0 }, 'probes' ],
		[ 'gradients, tetrahedra, λ = 10⁻⁴', mesh, mesh.positions, { gradients: true, lambda: 1e-4, gradientLambda: 1e-4 }, 'field' ],
		[ 'plain, grid, λ = 10⁻⁴', grid, grid.positions, { lambda: 1e-4 }, 'probes' ],
		[ 'gradients, grid, λ = 10⁻⁴', grid, grid.positions, { gradients: true, lambda: 1e-4, gradientLambda: 1e-4 }, 'field' ],
	];

	for ( const [ name, interpolator, positions, options, where ] of cases ) {

		it( `${name}: negative without the option (at the ${where}), non-negative with it`, () => {

			const captured = sample( field, positions );
			const free = fitProbeSH( interpolator, positions, captured, samples, options );
			const freeField = evaluateGradientField( interpolator, positions, free.sh, free.gradients, inside );
			expect( negatives( where === 'probes' ? free.sh : freeField ).count ).toBeGreaterThan( 0 );

			const safe = fitProbeSH( interpolator, positions, captured, samples, { ...options, nonNegative: true } );
			// At every probe, inside every cell and at every fit sample (a float32 rounding below 0 allowed).
			expect( negatives( safe.sh ).lowest ).toBeGreaterThanOrEqual( 0 );
			for ( const points of [ inside, fitPoints ] ) {

				const values = evaluateGradientField( interpolator, positions, safe.sh, safe.gradients, points );
				expect( negatives( values ).lowest ).toBeGreaterThan( - 1e-6 );

			}

			// Only what is negative changes: a probe whose fitted SH was non-negative keeps it.
			let kept = 0;
			for ( let i = 0; i < positions.length / 3; i ++ ) {

				if ( minIrradiance( free.sh, 27 * i ) < 0 ) continue;
				kept ++;
				expect( safe.sh.subarray( 27 * i, 27 * i + 27 ) ).toEqual( free.sh.subarray( 27 * i, 27 * i + 27 ) );

			}

			expect( kept ).toBeGreaterThan( 40 );
			expect( Number.isFinite( safe.fitError ) ).toBe( true );

		} );

	}

} );
