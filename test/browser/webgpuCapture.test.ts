import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

// WebGPURenderer capture (issue 15) in Chromium, on its WebGPU backend (SwiftShader's adapter) and
// its WebGL2 fallback: test/browser/pages/webgpu-capture.ts runs each check on one backend.
describe.skipIf( browserSkipReason !== '' )( `WebGPURenderer capture (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); } );
	afterAll( async () => { await session?.close(); } );

	for ( const backend of [ 'webgpu', 'webgl2' ] ) {

		it( `${backend}: analytic SH, the WebGLRenderer's SH, panoramas, freed resources, a lost ${backend === 'webgpu' ? 'device' : 'context'}`, async () => {

			const { page, errors } = await session.open( `test/browser/pages/webgpu-capture.html?backend=${backend}`, { width: 64, height: 64 } );
			await page.waitForFunction( 'window.__result !== undefined', { timeout: 120_000 } );
			const result = await page.evaluate( 'window.__result' ) as Record<string, unknown>;
			expect( result.error ).toBeUndefined();
			expect( result.adapter ).toBe( true );
			expect( result.isWebGPUBackend ).toBe( backend === 'webgpu' );
			expect( result.analyticError, 'painted SH environment' ).toBeLessThan( 5e-3 );
			expect( result.progressCalls ).toBe( 4 );
			expect( result.projectionError, 'projection = CPU projection of the read-back faces' ).toBeLessThan( 1e-5 );
			// WebGL2 backend: the WebGLRenderer's SH to 1e-8. WebGPU backend: probes 1 and 3 to 1e-8; probes 0 and 2 are
			// 1.5 % off because 3 and 8 face texels differ, all on box edges (read back texel by texel, session 21):
			// probe 0's +X face has the red box's far edge at column 11.478, 0.022 texel from the centre 11.5, which
			// WebGL covers (correct) and WebGPU does not. Likely (unproven) cause: three's WebGPU cube camera renders
			// each face mirrored, and SwiftShader's vertex snapping / tie rules then cover edge texels differently.
			// Not a mirrored face or half-texel offset: every other texel is equal. Rotated boxes still leave 1-2 edge
			// texels (4e-3). See docs/webgpu-capture.md. The bound is loose until the faces rasterise alike.
			const perProbe = result.webglPerProbe as number[];
			if ( backend === 'webgl2' ) expect( result.webglError, 'same room, WebGLRenderer' ).toBeLessThan( 1e-4 );
			else {

				expect( perProbe[ 1 ], 'probe without edge texels' ).toBeLessThan( 1e-4 );
				expect( perProbe[ 3 ], 'probe without edge texels' ).toBeLessThan( 1e-4 );
				expect( result.webglError, 'same room, WebGLRenderer (edge texels)' ).toBeLessThan( 3e-2 );

			}

			// 3.3e-4, on both backends and on WebGLRenderer's SHProjector too (same number): all of it in the
			// quadratic coefficients 6 (3z² − 1) and 8 (x² − y²), linear ones ≤ 3e-5, so the likely cause is the shader's
			// float32 sin/cos of the texel directions, not the weights (the row solid angles match the CPU's). Goal 1e-4.
			expect( result.panoramaError, 'panorama against the CPU projection' ).toBeLessThan( 1e-3 );
			expect( result.memoryAfter ).toEqual( result.memoryBefore );
			expect( result.lossError ).toMatch( backend === 'webgpu' ? /^WebGPUProbeCapturer\.capture: the WebGPU device was lost/ : /^WebGPUProbeCapturer\.capture: the WebGL context was lost/ );
			expect( result.shKept ).toBe( true );
			expect( result.lostError ).toMatch( /was lost/ );
			expect( errors.filter( ( e ) => ! /lost|CONTEXT_LOST|destroyed/i.test( e ) ) ).toEqual( [] );

		} );

	}

} );
