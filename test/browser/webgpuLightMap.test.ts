import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/*
 * Issue 15 interop: the lightmapper example (the Basic room's light map baked from the volume by
 * three's LightMapper through ProbeVolumeIrradiance) loads, captures and bakes without page errors.
 * renderer=webgpu is left out for the "popErrorScope" rejection pagesWebGPU.test.ts skips too.
 */

describe.skipIf( browserSkipReason !== '' )( `lightmapper example${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	it( 'renderer=webgl2: captures, bakes a light map and renders without page errors', async () => {

		const { page, errors } = await session.open( 'examples/lightmapper.html?renderer=webgl2', { width: 320, height: 180 } );
		await page.waitForFunction( 'window.lightmapper || document.getElementById( "status" ).textContent.includes( "only" )', { timeout: 150_000 } );
		const samples = await page.evaluate( 'window.lightmapper?.lightMapper.samples ?? -1' );
		await new Promise( ( resolve ) => setTimeout( resolve, 1000 ) );
		await page.close();
		expect( errors ).toEqual( [] );
		expect( samples ).toBe( 16 );

	}, 180_000 );

} );
