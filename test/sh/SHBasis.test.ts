import { describe, expect, it } from 'vitest';
import { SphericalHarmonics3, Vector3 } from 'three';
import {
	evaluateSHBasis, SH_Y00, SH_Y1, SH_Y2_PRODUCT, SH_Y20, SH_Y22,
	IRRADIANCE_C1, IRRADIANCE_C2, IRRADIANCE_C3, IRRADIANCE_C4, IRRADIANCE_C5,
} from '../../src/sh/index.js';
import { random, randomDirection } from './helpers.js';

describe( 'SH basis', () => {

	it( 'evaluateSHBasis equals three SphericalHarmonics3.getBasisAt for 500 random directions', () => {

		// Same formulas in the same float64 arithmetic, so the values must agree to the last bits;
		// a swapped index or sign would show up as an O(1) difference.
		const next = random( 1 );
		const ours = new Float64Array( 9 );
		const theirs = new Array<number>( 9 );
		const v = new Vector3();
		for ( let n = 0; n < 500; n ++ ) {

			const [ x, y, z ] = randomDirection( next );
			evaluateSHBasis( x, y, z, ours );
			SphericalHarmonics3.getBasisAt( v.set( x, y, z ), theirs );
			for ( let k = 0; k < 9; k ++ ) expect( ours[ k ] ).toBeCloseTo( theirs[ k ], 14 );

		}

	} );

	it( 'writes at an offset into a plain array and leaves the rest alone', () => {

		const out = new Array<number>( 12 ).fill( - 7 );
		evaluateSHBasis( 0, 0, 1, out, 2 );
		// At the +Z pole only Y00, Y10 (z) and Y20 (3z²−1 = 2) are non-zero.
		expect( out.slice( 0, 2 ) ).toEqual( [ - 7, - 7 ] );
		expect( out.slice( 2, 11 ) ).toEqual( [ SH_Y00, 0, SH_Y1, 0, 0, 0, SH_Y20 * 2, 0, 0 ] );
		expect( out[ 11 ] ).toBe( - 7 );

	} );

	it( 'basis constants are the 6-digit truncations of the normalisation constants', () => {

		// Y00 = 1/(2√π), Y1m = √3/(2√π), Y2(±2,±1 products) = √15/(2√π), Y20 = √5/(4√π), Y22 = √15/(4√π).
		const s = 2 * Math.sqrt( Math.PI );
		expect( Math.abs( SH_Y00 - 1 / s ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( SH_Y1 - Math.sqrt( 3 ) / s ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( SH_Y2_PRODUCT - Math.sqrt( 15 ) / s ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( SH_Y20 - Math.sqrt( 5 ) / ( 2 * s ) ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( SH_Y22 - Math.sqrt( 15 ) / ( 2 * s ) ) ).toBeLessThan( 1e-6 );

	} );

	it( 'irradiance constants are Â_l (π, 2π/3, π/4) times the basis constants (Ramamoorthi & Hanrahan eq. 12)', () => {

		// The clamped-cosine kernel has band factors Â0 = π, Â1 = 2π/3, Â2 = π/4.
		expect( Math.abs( IRRADIANCE_C4 - Math.PI * SH_Y00 ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( 2 * IRRADIANCE_C2 - ( 2 * Math.PI / 3 ) * SH_Y1 ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( 2 * IRRADIANCE_C1 - ( Math.PI / 4 ) * SH_Y2_PRODUCT ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( IRRADIANCE_C1 - ( Math.PI / 4 ) * SH_Y22 ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( IRRADIANCE_C3 - ( Math.PI / 4 ) * 3 * SH_Y20 ) ).toBeLessThan( 1e-6 );
		expect( Math.abs( IRRADIANCE_C5 - ( Math.PI / 4 ) * SH_Y20 ) ).toBeLessThan( 1e-6 );

	} );

} );
