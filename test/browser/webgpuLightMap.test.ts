import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/*
 * Issue 15 interop: the lightmapper example (the Basic room's light map baked from the volume by
 * three's LightMapper through ProbeVolumeIrradiance) loads, captures and bakes without page errors.
 * The source itself is checked exactly, and the bake on both backends, in webgpuLightMapExact.test.ts.
 *
 * renderer=webgpu: the page captures and bakes, then its first frame on the canvas loses the
 * device ("Device was destroyed", then "Instance dropped in popErrorScope"). That is headless
 * Chromium's WebGPU canvas on SwiftShader, not three or this library: a page of raw WebGPU that
 * configures a canvas context and submits one clear pass loses its device the same way, while
 * rendering only into render targets (the exact test, the shading suite) keeps it.
 */

const WEBGPU_CANVAS = 'headless Chromium\'s WebGPU canvas on SwiftShader loses the device on the first presented frame (raw WebGPU too)';

describe.skipIf( browserSkipReason !== '' )( `lightmapper example${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	it.skip( `renderer=webgpu: captures, bakes a light map and renders without page errors — SKIPPED: ${WEBGPU_CANVAS}`, async () => {

		const { page, errors } = await session.open( 'examples/lightmapper.html?renderer=webgpu', { width: 320, height: 180 } );
		await page.waitForFunction( 'window.lightmapper', { timeout: 150_000 } );
		const samples = await page.evaluate( 'window.lightmapper.lightMapper.samples' );
		await new Promise( ( resolve ) => setTimeout( resolve, 1000 ) );
		await page.close();
		expect( errors ).toEqual( [] );
		expect( samples ).toBe( 16 );

	}, 180_000 );

	it( 'renderer=webgl2: captures, bakes a light map and renders without page errors', async () => {

		const { page, errors } = await session.open( 'examples/lightmapper.html?renderer=webgl2', { width: 320, height: 180 } );
		await page.waitForFunction( 'window.lightmapper || document.getElementById( "status" ).textContent.includes( "only" )', { timeout: 150_000 } );
		const samples = await page.evaluate( 'window.lightmapper?.lightMapper.samples ?? -1' );
		await new Promise( ( resolve ) => setTimeout( resolve, 1000 ) );
		await page.close();
		expect( errors ).toEqual( [] );
		expect( samples ).toBe( 16 );

	}, 180_000 );

	it( 'renderer=webgl2: the lightmapped walls render as the same walls probe-lit per object (same source of light)', async () => {

		const { page, errors } = await session.open( 'examples/lightmapper.html?renderer=webgl2', { width: 160, height: 90 } );
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
		for ( let c = 0; c < 3; c ++ ) expect( Math.abs( baked[ c ] - lit[ c ] ) ).toBeLessThan( 0.03 * lit[ c ] + 0.002 );

	}, 180_000 );

} );
