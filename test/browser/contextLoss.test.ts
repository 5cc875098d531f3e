import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

// headless-gl has no WEBGL_lose_context, so context loss is tested here, in Chromium.
describe.skipIf( browserSkipReason !== '' )( `LightProbeVolume survives a lost WebGL context (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser(); } );
	afterAll( async () => { await session?.close(); } );

	it( 'keeps its CPU-side SH, refuses to capture while lost with a clear error, and renders the same picture after restore', async () => {

		const { page, errors } = await session.open( 'test/browser/pages/context-loss.html', { width: 200, height: 200 } );
		await page.waitForFunction( () => ( window as unknown as { __result?: unknown } ).__result !== undefined, { timeout: 60_000 } );
		const result = await page.evaluate( () => ( window as unknown as { __result: Record<string, unknown> } ).__result );
		expect( result.error ).toBeUndefined();
		expect( result.shNonZero, 'the capture saw the orange room' ).toBe( true );
		expect( result.litPixels, 'the sphere is lit by the probes' ).toBeGreaterThan( 100 );
		expect( result.captureError ).toMatch( /context was lost/ );
		expect( result.shKeptDuringLoss ).toBe( true );
		// Same uniforms, same program rebuilt: the same image, to the bit or nearly.
		expect( result.maxDifference ).toBeLessThanOrEqual( 1 );
		// Chromium logs its own "WebGL: CONTEXT_LOST_WEBGL" warnings; page errors would be ours.
		expect( errors.filter( ( e ) => ! /CONTEXT_LOST|context lost/i.test( e ) ) ).toEqual( [] );

	} );

} );
