import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/*
 * The demo pages' renderer switch (issue 15): Basic with ?renderer=webgpu (WebGPURenderer, WebGPU
 * backend) and ?renderer=webgl2 (forceWebGL) in Chromium with WebGPU enabled — it finishes its
 * capture without page errors and says on the page which backend runs.
 *
 * renderer=webgpu runs with present=0 (the Viewer draws its frames into a render target): in this
 * headless Chromium (156, SwiftShader's adapter) a GPUDevice that presents to a 'webgpu' canvas is
 * lost ("Device was destroyed." or "A valid external Instance reference no longer exists."), and
 * raw WebGPU without three does the same (session 22: a clear pass a frame, lost 50–300 ms after the
 * first present following 3 s of offscreen passes, never without a canvas present). Every
 * popErrorScope then pending rejects with "Instance dropped in popErrorScope", which three's
 * createRenderPipeline leaves uncaught: the rejection the page's handler reported. The loss is
 * Chromium's (docs/webgpu.md, "Limits found"); presenting to a canvas is left to a real GPU.
 */

const LABELS: Record<string, string> = { webgpu: 'WebGPU', webgl2: 'WebGPURenderer (WebGL2 backend)' };
const PRESENT: Record<string, string> = { webgpu: '&present=0', webgl2: '' };

describe.skipIf( browserSkipReason !== '' )( `demo pages on WebGPURenderer (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	for ( const renderer of [ 'webgpu', 'webgl2' ] ) {

		const how = PRESENT[ renderer ] ? ' (frames offscreen: this Chromium loses a WebGPU device at its first canvas present)' : '';
		it( `basic with renderer=${renderer}: captures, renders without page errors and shows "${LABELS[ renderer ]}"${how}`, async () => {

			const { page, errors } = await session.open( `examples/basic.html?resolution=8&t=4&probes=0&renderer=${renderer}${PRESENT[ renderer ]}`, { width: 320, height: 180 } );
			await page.waitForFunction( 'window.__demo?.ready || window.__demo?.error', { timeout: 150_000 } );
			const demo = await page.evaluate( 'window.__demo' ) as { error: string; renderer: string; probes: number };
			const label = await page.$eval( '#renderer', ( element ) => element.textContent );
			await page.close();
			expect( demo.error ).toBe( '' );
			expect( errors ).toEqual( [] );
			expect( demo.probes ).toBe( 13 );
			expect( demo.renderer ).toBe( LABELS[ renderer ] );
			expect( label ).toBe( LABELS[ renderer ] );

		}, 180_000 );

	}

} );
