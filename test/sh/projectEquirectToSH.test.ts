import { describe, expect, it } from 'vitest';
import { ShaderChunk } from 'three';
import { evaluateSHBasis, projectEquirectToSH } from '../../src/sh/index.js';
import { equirectFrom, random, randomDirection, selfProjection } from './helpers.js';

const COLOUR = [ 2, 0.5, 1 ];

describe( 'projectEquirectToSH', () => {

	const basis = new Float64Array( 9 );
	for ( const [ width, height, tolerance ] of [ [ 128, 64, 1e-3 ], [ 512, 256, 1e-4 ] ] ) {

		it( `an environment equal to one basis function Y_k projects to coefficient k only (${width}×${height}, others < ${tolerance})`, () => {

			// Orthonormality as in the cube test. In longitude the uniform samples integrate these
			// low-order trigonometric terms exactly; the residue is the latitude midpoint error.
			let pixels: Float32Array | undefined;
			for ( let k = 0; k < 9; k ++ ) {

				pixels = equirectFrom( width, height, ( x, y, z ) => evaluateSHBasis( x, y, z, basis )[ k ], COLOUR, pixels );
				const sh = projectEquirectToSH( pixels, width, height );
				for ( let j = 0; j < 9; j ++ ) {

					for ( let c = 0; c < 3; c ++ ) {

						const value = sh[ j * 3 + c ] / COLOUR[ c ];
						if ( j === k ) {

							expect( value ).toBeGreaterThanOrEqual( 0.999 );
							expect( Math.abs( value - selfProjection( k ) ) ).toBeLessThan( tolerance );

						} else {

							expect( Math.abs( value ) ).toBeLessThan( tolerance );

						}

					}

				}

			}

		} );

	}

	it( 'constant radiance c: L00 = 4π·0.282095·c exactly (row solid angles sum to 4π), band 1 = 0', () => {

		// Σ_rows W·(2π/W)(sin top − sin bottom) telescopes to 2π·(1 − (−1)) = 4π.
		const c = 3;
		const sh = projectEquirectToSH( equirectFrom( 64, 32, () => c ), 64, 32 );
		expect( Math.abs( sh[ 0 ] / ( 4 * Math.PI * 0.282095 * c ) - 1 ) ).toBeLessThan( 2e-7 );
		for ( let k = 3; k < 12; k ++ ) expect( Math.abs( sh[ k ] ) ).toBeLessThan( 1e-6 );

	} );

	it( 'clamped cosine max(0, z): L00 = √π/2, L10 = √(π/3), L20 = √(5π)/8, rest 0 (512×256, 1e-4·L00)', () => {

		// Same analytic values as the cube test. z = 0 is the great circle through ±X; with W a
		// multiple of 4 it lies on column edges (longitudes ±π/2 are at u = ¼, ¾), so pixels are
		// smooth and the error is second order.
		const sh = projectEquirectToSH( equirectFrom( 512, 256, ( x, y, z ) => Math.max( 0, z ) ), 512, 256 );
		const expected = [ 0.282095 * Math.PI, 0, 0.488603 * 2 * Math.PI / 3, 0, 0, 0, 0.315392 * Math.PI / 2, 0, 0 ];
		for ( let k = 0; k < 9; k ++ ) {

			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( sh[ k * 3 + c ] - expected[ k ] ) ).toBeLessThan( 1e-4 * expected[ 0 ] );

		}

	} );

	it( 'orientation follows three\'s equirectUv: a single bright pixel put where three samples direction d gives band-1 pointing at d', () => {

		// three (common.glsl.js): u = atan(dir.z, dir.x)/(2π) + ½, v = asin(dir.y)/π + ½, and an image
		// texture has v = 1 on its top row. Assert the shader still says so, then place a pixel with
		// that formula (not with the library's own mapping) and read the direction back from the
		// linear band: (L11, L1−1, L10) = (x, y, z) ∝ the pixel's direction.
		expect( ShaderChunk.common ).toContain( 'float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;' );
		expect( ShaderChunk.common ).toContain( 'float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;' );
		const width = 256, height = 128;
		const pixels = new Float32Array( width * height * 4 );
		const next = random( 3 );
		for ( let n = 0; n < 40; n ++ ) {

			const d = randomDirection( next );
			const u = Math.atan2( d[ 2 ], d[ 0 ] ) / ( 2 * Math.PI ) + 0.5;
			const v = Math.asin( d[ 1 ] ) / Math.PI + 0.5;
			const column = Math.min( width - 1, Math.floor( u * width ) );
			const row = Math.min( height - 1, Math.floor( ( 1 - v ) * height ) );
			pixels.fill( 0 );
			pixels.fill( 1, ( row * width + column ) * 4, ( row * width + column ) * 4 + 3 );
			const sh = projectEquirectToSH( pixels, width, height );
			const x = sh[ 9 ], y = sh[ 3 ], z = sh[ 6 ];
			const cosine = ( x * d[ 0 ] + y * d[ 1 ] + z * d[ 2 ] ) / Math.hypot( x, y, z );
			// Within a pixel diagonal (≈ 2π/256 · √2 ≈ 0.035 rad at the equator): cos > 0.998.
			expect( cosine ).toBeGreaterThan( 0.998 );

		}

	} );

	it( 'rowOrder \'bottom-up\' on row-reversed pixels equals the default top-down result; channels: 3 equals 4', () => {

		const width = 32, height = 16;
		const topDown = equirectFrom( width, height, ( x, y, z ) => 1 + y + 0.3 * x * z - 0.2 * z, COLOUR );
		const bottomUp = new Float32Array( topDown.length );
		for ( let row = 0; row < height; row ++ ) {

			bottomUp.set( topDown.subarray( row * width * 4, ( row + 1 ) * width * 4 ), ( height - 1 - row ) * width * 4 );

		}

		const reference = projectEquirectToSH( topDown, width, height );
		expect( Array.from( projectEquirectToSH( bottomUp, width, height, { rowOrder: 'bottom-up' } ) ) ).toEqual( Array.from( reference ) );
		// Not symmetric in y, so reading the flipped data as top-down must differ (the option matters).
		expect( Math.abs( projectEquirectToSH( bottomUp, width, height )[ 3 ] - reference[ 3 ] ) ).toBeGreaterThan( 0.1 );
		const rgb = topDown.filter( ( _, i ) => i % 4 !== 3 );
		const target = new Float32Array( 30 );
		projectEquirectToSH( rgb, width, height, { channels: 3, target, targetOffset: 3 } );
		expect( Array.from( target.subarray( 3 ) ) ).toEqual( Array.from( reference ) );

	} );

} );
