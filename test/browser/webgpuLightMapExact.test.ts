import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';
import type { Page } from 'puppeteer-core';

/*
 * Issue 15 interop, exactly: ProbeVolumeIrradiance's TSL `irradiance( position, normal )` evaluated
 * on the GPU (one fragment per point, read back as float) against the CPU — E( n ) by three's
 * SphericalHarmonics3.getIrradianceAt of volume.sample( p ) — on both WebGPURenderer backends; then
 * the light map three's LightMapper bakes from it for a flat quad, texel by texel.
 *
 * Why exact: every probe's SH is affine in its position (pages/webgpu-lightmap.ts). Tetrahedral
 * weights reproduce an affine field, the texture holds it at its nodes, and trilinear filtering
 * reproduces an affine function between nodes: inside the box the GPU has no resampling error,
 * only the texels' precision and the filter's weight precision. The tolerances are those:
 * float texels — one texel's change of E times 2⁻⁸ (8 bits of sub-texel weight precision, D3D11's
 * minimum) plus float rounding; half texels (the default type) — the bound on rounding every
 * coefficient to half (2⁻¹¹ relative) plus the same filter term. A lookup half a texel off would
 * be far outside them (checked below, so the tolerance can tell).
 */

interface Row {

	kind: string; gpu: number[]; volume: number[]; field: number[]; shifted: number[]; perTexel: number; halfRounding: number[];

}

function tolerance( row: Row, c: number, type: 'float' | 'half' ): number {

	const filter = row.perTexel * 2 ** - 8;
	return type === 'float' ? filter + 1e-5 * Math.abs( row.volume[ c ] ) + 1e-6 : filter + row.halfRounding[ c ] + 1e-6;

}

describe.skipIf( browserSkipReason !== '' )( `light-map source on the GPU against the CPU${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	let page: Page;
	let errors: string[];
	beforeAll( async () => {

		session = await startBrowser( { webgpu: true } );
		( { page, errors } = await session.open( 'test/browser/pages/webgpu-lightmap.html', { width: 64, height: 64 } ) );
		await page.waitForFunction( 'window.lightmap', { timeout: 150_000 } );

	}, 180_000 );
	afterAll( async () => { await session?.close(); } );

	for ( const backend of [ 'webgpu', 'webgl2' ] as const ) {

		for ( const type of [ 'float', 'half' ] as const ) {

			it( `${backend}, ${type} texels: irradiance( p, n ) = E( n ) of volume.sample( p ) inside the box, of the nearest box point outside, the constant term for a zero normal`, async () => {

				const result = await page.evaluate( `window.lightmap.exact( '${backend}', '${type}' )` ) as { backend: string; rows: Row[] };
				expect( result.backend ).toBe( backend );
				const kinds = new Set( result.rows.map( ( row ) => row.kind ) );
				expect( [ ...kinds ] ).toEqual( [ 'inside', 'corner', 'outside', 'zero normal' ] );
				let caught = 0, inside = 0, worst = 0, worstAllowed = 0;
				for ( const row of result.rows ) {

					for ( let c = 0; c < 3; c ++ ) {

						worst = Math.max( worst, Math.abs( row.gpu[ c ] - row.volume[ c ] ) / Math.abs( row.volume[ c ] ) );
						worstAllowed = Math.max( worstAllowed, tolerance( row, c, type ) / Math.abs( row.volume[ c ] ) );

						// The field is affine in the volume, as the test's premise says.
						expect( Math.abs( row.volume[ c ] - row.field[ c ] ) ).toBeLessThan( 1e-5 * Math.abs( row.field[ c ] ) + 1e-6 );
						const message = `${row.kind} ${JSON.stringify( row )} channel ${c}`;
						expect( Math.abs( row.gpu[ c ] - row.volume[ c ] ), message ).toBeLessThanOrEqual( tolerance( row, c, type ) );

					}

					if ( row.kind === 'inside' ) {

						inside ++;
						const off = ( c: number ) => Math.abs( row.shifted[ c ] - row.volume[ c ] ) > 4 * tolerance( row, c, type );
						if ( [ 0, 1, 2 ].some( off ) ) caught ++;

					}

				}

				// A lookup half a texel off along x would fail nearly every point.
				expect( caught ).toBeGreaterThanOrEqual( inside - 2 );
				// For docs/lightmapper.md.
				console.log( `${backend} ${type}: ${result.rows.length} points, largest |gpu − cpu| / |cpu| ${worst.toExponential( 2 )} (largest allowed ${worstAllowed.toExponential( 2 )})` );

			}, 120_000 );

		}

		it( `${backend}: LightMapper's light map of a flat quad holds E( n ) at each texel's world position`, async () => {

			const result = await page.evaluate( `window.lightmap.lightMap( '${backend}', 4 )` ) as {
				backend: string; samples: number; size: number; gradient: number; radius: number;
				texels: { position: number[]; local: number[]; gpu: number[]; cpu: number[] }[];
			};
			expect( result.backend ).toBe( backend );
			expect( result.samples ).toBe( 4 );
			expect( result.texels.length ).toBe( result.size * result.size );
			// The position map is the quad: on its plane, inside it (a texel's jitter and the padding
			// fill aside), and spanning it.
			const span = [ [ Infinity, - Infinity ], [ Infinity, - Infinity ] ];
			for ( const { local } of result.texels ) {

				expect( Math.abs( local[ 2 ] ) ).toBeLessThan( 5e-3 );
				expect( Math.abs( local[ 0 ] ) ).toBeLessThan( 1 + 2 / result.size );
				expect( Math.abs( local[ 1 ] ) ).toBeLessThan( 0.75 + 1.5 / result.size );
				for ( let a = 0; a < 2; a ++ ) {

					span[ a ][ 0 ] = Math.min( span[ a ][ 0 ], local[ a ] );
					span[ a ][ 1 ] = Math.max( span[ a ][ 1 ], local[ a ] );

				}

			}

			expect( span[ 0 ][ 0 ] ).toBeLessThan( - 1 + 2 / result.size );
			expect( span[ 0 ][ 1 ] ).toBeGreaterThan( 1 - 2 / result.size );
			expect( span[ 1 ][ 0 ] ).toBeLessThan( - 0.75 + 1.5 / result.size );
			expect( span[ 1 ][ 1 ] ).toBeGreaterThan( 0.75 - 1.5 / result.size );
			// Looser than above: LightMapper sums its samples in half floats and stores half floats,
			// (samples + 1) roundings of 2⁻¹¹ relative, in the light map and in the position map
			// (there, times |∂E/∂p| · |p − centre|). A texel is a mean of samples; E is affine in
			// position along the flat quad, so the mean of E is E at the mean position.
			const rounding = ( result.samples + 1 ) * 2 ** - 11;
			let worst = 0, worstAllowed = 0;
			for ( const texel of result.texels ) {

				for ( let c = 0; c < 3; c ++ ) {

					const error = Math.abs( texel.gpu[ c ] - texel.cpu[ c ] );
					const allowed = rounding * ( Math.abs( texel.cpu[ c ] ) + result.gradient * result.radius ) + 1e-6;
					expect( error, JSON.stringify( texel ) ).toBeLessThanOrEqual( allowed );
					worst = Math.max( worst, error / Math.abs( texel.cpu[ c ] ) );
					worstAllowed = Math.max( worstAllowed, allowed / Math.abs( texel.cpu[ c ] ) );

				}

			}

			expect( worst ).toBeGreaterThan( 0 );
			console.log( `${backend} light map ${result.size}², ${result.samples} samples: largest |gpu − cpu| / |cpu| ${worst.toExponential( 2 )} (largest allowed ${worstAllowed.toExponential( 2 )})` );

		}, 120_000 );

	}

	it( 'no page errors', () => {

		expect( errors ).toEqual( [] );

	} );

} );
