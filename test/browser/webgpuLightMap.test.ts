import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/*
 * Issue 15 interop: the lightmapper example (the Basic room's light map baked from the volume by
 * three's LightMapper through ProbeVolumeIrradiance) loads, captures and bakes without page errors,
 * on both WebGPURenderer backends. The source itself is checked exactly, and the bake texel by
 * texel, in webgpuLightMapExact.test.ts.
 *
 * renderer=webgpu runs with ?present=0 (frames into a render target): headless Chromium on
 * SwiftShader loses a WebGPU device soon after its first canvas present ("Device was destroyed",
 * then "Instance dropped in popErrorScope"), raw WebGPU without three too; render targets keep it.
 */

const PAGES: Record<string, string> = {
	webgpu: 'examples/lightmapper.html?renderer=webgpu&present=0',
	webgl2: 'examples/lightmapper.html?renderer=webgl2',
};

describe.skipIf( browserSkipReason !== '' )( `lightmapper example${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	for ( const backend of [ 'webgpu', 'webgl2' ] ) {

		it( `renderer=${backend}: captures, bakes a light map and renders without page errors`, async () => {

			const { page, errors } = await session.open( PAGES[ backend ], { width: 320, height: 180 } );
			await page.waitForFunction( 'window.lightmapper || document.getElementById( "status" ).textContent.includes( "only" )', { timeout: 150_000 } );
			const samples = await page.evaluate( 'window.lightmapper?.lightMapper.samples ?? -1' );
			const running = await page.evaluate( 'window.lightmapper?.renderer.backend.isWebGPUBackend === true ? "webgpu" : "webgl2"' );
			// Frames keep running on the device a second longer.
			await new Promise( ( resolve ) => setTimeout( resolve, 1000 ) );
			await page.close();
			expect( errors ).toEqual( [] );
			expect( running ).toBe( backend );
			expect( samples ).toBe( 16 );

		}, 180_000 );

		it( `renderer=${backend}: the lightmapped walls render as the same walls probe-lit per object (same source of light)`, async () => {

			const { page, errors } = await session.open( PAGES[ backend ], { width: 160, height: 90 } );
			await page.waitForFunction( 'window.lightmapper', { timeout: 150_000 } );
			const [ baked, lit ] = await page.evaluate( async () => {

				const { THREE, renderer, scene, camera, character, volume, setScenery } = ( window as any ).lightmapper;
				renderer.setAnimationLoop( null );
				character.visible = false;
				const target = new THREE.RenderTarget( 64, 36, { type: THREE.HalfFloatType } );
				const mean = async () => {

					volume.update();
					renderer.setRenderTarget( target );
					renderer.render( scene, camera );
					renderer.setRenderTarget( null );
					const data = await renderer.readRenderTargetPixelsAsync( target, 0, 0, 64, 36 );
					const sum = [ 0, 0, 0 ];
					const half = ( h: number ) => THREE.DataUtils.fromHalfFloat( h );
					for ( let i = 0; i < data.length; i += 4 ) {

						for ( let c = 0; c < 3; c ++ ) sum[ c ] += data instanceof Uint16Array ? half( data[ i + c ] ) : data[ i + c ];

					}

					return sum.map( ( v ) => v / ( data.length / 4 ) );

				};

				const a = await mean();
				setScenery( 'probe-lit per object' );
				const b = await mean();
				return [ a, b ];

			} ) as number[][];
			await page.close();
			expect( errors ).toEqual( [] );
			// Both read one resampled field (the walls' texture mode and the light map's source), so
			// what differs is the light map's texels (half floats, bilinear in uv1) against per-pixel.
			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( baked[ c ] - lit[ c ] ) ).toBeLessThan( 0.005 * lit[ c ] + 5e-4 );
			// Not black: the comparison means something.
			expect( Math.min( ...lit ) ).toBeGreaterThan( 0.01 );
			// For docs/lightmapper.md.
			const ratios = baked.map( ( v, c ) => ( v / lit[ c ] - 1 ) * 100 );
			console.log( `${backend}: mean colour lightmapped / probe-lit per object − 1: ${ratios.map( ( r ) => r.toFixed( 2 ) + ' %' ).join( ', ' )}` );

		}, 180_000 );

	}

} );
