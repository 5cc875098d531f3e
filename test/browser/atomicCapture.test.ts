import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

// Captures are all or nothing, with a real lost context (headless-gl has no WEBGL_lose_context;
// test/runtime/atomicCapture.gpu.test.ts injects failures there instead).
describe.skipIf( browserSkipReason !== '' )( `a capture that loses its context changes nothing (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser(); } );
	afterAll( async () => { await session?.close(); } );

	it( 'lost during the first role pass, at its end, during the second, during a bounce pass, before recaptureDirty: SH, dirty set and settings kept; restored, the capture succeeds', async () => {

		const { page, errors } = await session.open( 'test/browser/pages/atomic-capture.html', { width: 200, height: 200 } );
		await page.waitForFunction( () => ( window as unknown as { __result?: unknown } ).__result !== undefined, { timeout: 120_000 } );
		const result = await page.evaluate( () => ( window as unknown as { __result: Record<string, unknown> } ).__result );
		expect( result.error ).toBeUndefined();
		const attempts = result.attempts as { point: string; lost: boolean; error: string; unchanged: boolean }[];
		expect( attempts.map( ( a ) => a.point ) ).toEqual( [
			'during the first role pass', 'at the end of the first role pass', 'during the second role pass', 'during a bounce pass', 'before recaptureDirty',
		] );
		for ( const attempt of attempts ) {

			expect( attempt.lost, attempt.point ).toBe( true );
			expect( attempt.error, attempt.point ).toMatch( /^ProbeCapturer\.capture: the WebGL context was lost; the SH already held are kept/ );
			expect( attempt.unchanged, attempt.point ).toBe( true );

		}

		expect( result.keptThroughout ).toBe( true );
		expect( result.finalChanged ).toBe( true );
		expect( result.finalFinite ).toBe( true );
		expect( result.finalDirty ).toEqual( [] );
		expect( result.finalSkyFar ).toBe( 40 );
		expect( errors.filter( ( e ) => ! /CONTEXT_LOST|context lost/i.test( e ) ) ).toEqual( [] );

	} );

} );
