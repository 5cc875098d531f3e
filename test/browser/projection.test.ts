import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

// headless-gl accepts multiple render targets but fills only the first, so the GPU projection's
// usual path (one draw, four targets) is tested here, in Chromium; the Node GPU tests run the
// four-draw fallback.
describe.skipIf( browserSkipReason !== '' )( `GPU SH projection with multiple render targets (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser(); } );
	afterAll( async () => { await session?.close(); } );

	it( 'Chromium supports them, and both paths equal the CPU projection of the read-back faces (< 1e-4 of L00) at 8², 32², 100², 128²; panoramas equal the CPU projection', async () => {

		const { page, errors } = await session.open( 'test/browser/pages/projection.html', { width: 64, height: 64 } );
		await page.waitForFunction( 'window.__result !== undefined', { timeout: 120_000 } );
		const result = await page.evaluate( 'window.__result' ) as Record<string, number | boolean>;
		expect( errors ).toEqual( [] );
		expect( result.supportsMultipleTargets ).toBe( true );
		expect( result.glError ).toBe( 0 );
		for ( const size of [ 8, 32, 100, 128 ] ) {

			expect( result[ `${size}:mrt` ], `${size}² with multiple targets` ).toBeLessThan( 1e-4 );
			expect( result[ `${size}:single` ], `${size}² in four draws` ).toBeLessThan( 1e-4 );

		}

		// projectEquirectToSHGPU against projectEquirectToSH on the same texels (its directions come from a
		// float64 table: with SwiftShader's own sin / cos the quadratic coefficients were 3.3e-4 of L00 off).
		for ( const size of [ '64x32', '100x49', '256x128' ] ) {

			expect( result[ `panorama ${size}` ], `panorama ${size}` ).toBeLessThan( 1e-4 );

		}

	} );

} );
