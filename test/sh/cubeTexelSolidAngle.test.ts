import { describe, expect, it } from 'vitest';
import { cubeTexelSolidAngle, getCubeProjectionTable, paperTexelSolidAngle } from '../../src/sh/index.js';

function faceSum( size: number, solidAngle: ( i: number, j: number, size: number ) => number ): number {

	let sum = 0;
	for ( let j = 0; j < size; j ++ ) for ( let i = 0; i < size; i ++ ) sum += solidAngle( i, j, size );
	return sum;

}

describe( 'cube texel solid angle', () => {

	it( 'a whole face (size 1) is 4π/6: the six faces are congruent and tile the sphere', () => {

		expect( cubeTexelSolidAngle( 0, 0, 1 ) ).toBeCloseTo( 4 * Math.PI / 6, 14 );

	} );

	it( 'exact texel solid angles sum to 4π at any size (7, 64, 255)', () => {

		// The corner formula telescopes to the face's solid angle, so the sum is exact up to rounding.
		for ( const size of [ 7, 64, 255 ] ) expect( 6 * faceSum( size, cubeTexelSolidAngle ) ).toBeCloseTo( 4 * Math.PI, 11 );

	} );

	it( 'exact solid angle of a corner texel matches a 400×400 sub-sampled integral of dA/|r|³', () => {

		// Independent numeric integration of the area element over the texel [−1, −0.75]² (size 8).
		const n = 400, x0 = - 1, h = 0.25 / n;
		let integral = 0;
		for ( let b = 0; b < n; b ++ ) {

			for ( let a = 0; a < n; a ++ ) {

				const x = x0 + ( a + 0.5 ) * h, y = x0 + ( b + 0.5 ) * h;
				integral += h * h / Math.pow( 1 + x * x + y * y, 1.5 );

			}

		}

		expect( cubeTexelSolidAngle( 0, 0, 8 ) ).toBeCloseTo( integral, 8 );
		// The centre texel subtends more than the corner one (it is nearer and faces the centre).
		expect( cubeTexelSolidAngle( 4, 4, 8 ) ).toBeGreaterThan( 2.5 * cubeTexelSolidAngle( 0, 0, 8 ) );

	} );

	it( 'the paper\'s raw A(ω) sums to slightly MORE than 4π (midpoint rule on a convex integrand) and converges', () => {

		const excess8 = 6 * faceSum( 8, paperTexelSolidAngle ) / ( 4 * Math.PI ) - 1;
		const excess32 = 6 * faceSum( 32, paperTexelSolidAngle ) / ( 4 * Math.PI ) - 1;
		expect( excess8 ).toBeGreaterThan( 3e-3 );
		expect( excess8 ).toBeLessThan( 5e-3 );
		// Second-order convergence: 4× the resolution, ~16× less excess.
		expect( excess8 / excess32 ).toBeGreaterThan( 14 );
		expect( excess8 / excess32 ).toBeLessThan( 18 );

	} );

	it( 'projection tables: exact and paper modes total 4π, paper-unnormalized keeps the raw excess', () => {

		expect( getCubeProjectionTable( 8, 'exact' ).totalSolidAngle ).toBeCloseTo( 4 * Math.PI, 12 );
		expect( getCubeProjectionTable( 8, 'paper' ).totalSolidAngle ).toBeCloseTo( 4 * Math.PI, 12 );
		expect( getCubeProjectionTable( 8, 'paper-unnormalized' ).totalSolidAngle ).toBeCloseTo( 6 * faceSum( 8, paperTexelSolidAngle ), 12 );

	} );

} );
