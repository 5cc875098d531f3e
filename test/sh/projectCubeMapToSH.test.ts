import { describe, expect, it } from 'vitest';
import { evaluateIrradiance, evaluateSHBasis, getCubeProjectionTable, projectCubeMapToSH } from '../../src/sh/index.js';
import { cubeFacesFrom, random, randomDirection, selfProjection } from './helpers.js';

const COLOUR = [ 0.5, 1, 2 ];

describe( 'projectCubeMapToSH', () => {

	const basis = new Float64Array( 9 );
	for ( const [ size, offTolerance ] of [ [ 64, 1e-3 ], [ 256, 1e-4 ] ] ) {

		it( `an environment equal to one basis function Y_k projects to coefficient k only (${size}², others < ${offTolerance})`, () => {

			// ∫ Y_j Y_k dω = δ_jk (orthonormality); with three's 6-digit constants the diagonal is
			// selfProjection(k) = 1 ± 3e-6. The remaining error is quadrature error, O(1/size²).
			let faces: Float32Array[] | undefined;
			for ( let k = 0; k < 9; k ++ ) {

				faces = cubeFacesFrom( size, ( x, y, z ) => evaluateSHBasis( x, y, z, basis )[ k ], COLOUR, faces );
				const sh = projectCubeMapToSH( faces, size );
				for ( let j = 0; j < 9; j ++ ) {

					for ( let c = 0; c < 3; c ++ ) {

						const value = sh[ j * 3 + c ] / COLOUR[ c ];
						if ( j === k ) {

							expect( value ).toBeGreaterThanOrEqual( 0.999 );
							expect( Math.abs( value - selfProjection( k ) ) ).toBeLessThan( offTolerance );

						} else {

							expect( Math.abs( value ) ).toBeLessThan( offTolerance );

						}

					}

				}

			}

		} );

	}

	it( 'constant radiance c: L00 = 4π·0.282095·c (= 2√π·c to 7.4e-7), other coefficients < 2e-5·c at 64²', () => {

		// Y00 is constant and the exact weights sum to exactly 4π, so L00 has no quadrature error at
		// all: only float32 storage (~1e-7). Against the ideal 2√π·c it is off by three's truncation
		// 0.282095 vs 1/(2√π) = 0.28209479: relative 7.4e-7.
		const c = 0.75;
		const sh = projectCubeMapToSH( cubeFacesFrom( 64, () => c ), 64 );
		expect( Math.abs( sh[ 0 ] / ( 4 * Math.PI * 0.282095 * c ) - 1 ) ).toBeLessThan( 2e-7 );
		expect( Math.abs( sh[ 0 ] / ( 2 * Math.sqrt( Math.PI ) * c ) - 1 ) ).toBeLessThan( 1e-6 );
		// Odd functions cancel exactly between opposite faces; band-2 ones only up to quadrature error.
		for ( let k = 3; k < 27; k ++ ) expect( Math.abs( sh[ k ] ) ).toBeLessThan( 2e-5 * c );

	} );

	it( 'constant radiance c: E(n) = π·c for 200 random normals (≤ 1e-6 analytic SH, ≤ 2e-5 projected at 128²)', () => {

		// E(n) = ∫ c·max(0, n·ω) dω = πc. Via SH: 0.886227 · 4π·0.282095·c = πc·(1 + 8.2e-7) — the
		// truncated constants cost 8.2e-7, hence 1e-6 for the analytic SH. The projected SH adds the
		// small band-2 quadrature residue (×0.43 in E), hence 2e-5.
		const c = 1.25;
		const analytic = new Float32Array( 27 );
		analytic[ 0 ] = analytic[ 1 ] = analytic[ 2 ] = 4 * Math.PI * 0.282095 * c;
		const projected = projectCubeMapToSH( cubeFacesFrom( 128, () => c ), 128 );
		const next = random( 2 );
		const e = new Float32Array( 3 );
		for ( let n = 0; n < 200; n ++ ) {

			const normal = randomDirection( next );
			evaluateIrradiance( analytic, normal, e );
			for ( let ch = 0; ch < 3; ch ++ ) expect( Math.abs( e[ ch ] / ( Math.PI * c ) - 1 ) ).toBeLessThan( 1e-6 );
			evaluateIrradiance( projected, normal, e );
			for ( let ch = 0; ch < 3; ch ++ ) expect( Math.abs( e[ ch ] / ( Math.PI * c ) - 1 ) ).toBeLessThan( 2e-5 );

		}

	} );

	it( 'clamped cosine max(0, z): L00 = √π/2, L10 (index 2) = √(π/3), L20 (index 6) = √(5π)/8, rest 0 (128², 5e-5·L00)', () => {

		// Analytic: ∫max(0,z)dω = π, ∫z·max(0,z) = 2π/3, ∫(3z²−1)max(0,z) = π/2, and the other
		// polynomials integrate to 0 against it by symmetry (odd in x or y). With three's constants:
		// L00 = 0.282095π, L10 = 0.488603·2π/3, L20 = 0.315392·π/2 — equal to √π/2, √(π/3), √(5π)/8
		// within 2e-6 relative (truncation: 0.488603 vs √3/(2√π) = 0.4886025). The kink at z = 0 lies on texel edges (even size),
		// so each texel is smooth and the quadrature error stays second order: measured 3.1e-5·L00 at 128².
		const sh = projectCubeMapToSH( cubeFacesFrom( 128, ( x, y, z ) => Math.max( 0, z ) ), 128 );
		const ideal = [ Math.sqrt( Math.PI ) / 2, 0, Math.sqrt( Math.PI / 3 ), 0, 0, 0, Math.sqrt( 5 * Math.PI ) / 8, 0, 0 ];
		const truncated = [ 0.282095 * Math.PI, 0, 0.488603 * 2 * Math.PI / 3, 0, 0, 0, 0.315392 * Math.PI / 2, 0, 0 ];
		for ( let k = 0; k < 9; k ++ ) {

			expect( Math.abs( truncated[ k ] - ideal[ k ] ) ).toBeLessThanOrEqual( 2e-6 * ideal[ k ] );
			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( sh[ k * 3 + c ] - truncated[ k ] ) ).toBeLessThan( 5e-5 * ideal[ 0 ] );

		}

	} );

	it( 'reads RGB (channels: 3) the same as RGBA, and writes into target at targetOffset', () => {

		const size = 16;
		const rgba = cubeFacesFrom( size, ( x, y, z ) => 1 + x - 0.5 * y * z, COLOUR );
		const rgb = rgba.map( ( face ) => face.filter( ( _, i ) => i % 4 !== 3 ) );
		const fromRGBA = projectCubeMapToSH( rgba, size );
		const target = new Float32Array( 27 * 3 ).fill( 9 );
		const fromRGB = projectCubeMapToSH( rgb, size, { channels: 3, target, targetOffset: 27 } );
		expect( fromRGB ).toBe( target );
		expect( Array.from( target.subarray( 27, 54 ) ) ).toEqual( Array.from( fromRGBA ) );
		expect( target[ 26 ] ).toBe( 9 );
		expect( target[ 54 ] ).toBe( 9 );
		// The alpha channel must not leak in: a different alpha gives the same result.
		for ( const face of rgba ) for ( let i = 3; i < face.length; i += 4 ) face[ i ] = 1e6;
		expect( Array.from( projectCubeMapToSH( rgba, size ) ) ).toEqual( Array.from( fromRGBA ) );

	} );

	it( 'caches one table per size and mode (LRU of 4): repeated calls reuse it', () => {

		const table = getCubeProjectionTable( 24 );
		expect( getCubeProjectionTable( 24 ) ).toBe( table );
		expect( getCubeProjectionTable( 24, 'paper' ) ).not.toBe( table );
		expect( table.weights.length ).toBe( 6 * 24 * 24 * 9 );
		// Four newer entries push size 24 out; it is then rebuilt (a new, equal table).
		for ( const size of [ 3, 5, 6, 7 ] ) getCubeProjectionTable( size );
		const rebuilt = getCubeProjectionTable( 24 );
		expect( rebuilt ).not.toBe( table );
		expect( rebuilt.weights ).toEqual( table.weights );

	} );

} );
