import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';

/*
 * The demo pages' renderer switch (issue 15): Basic with ?renderer=webgpu (WebGPURenderer, WebGPU
 * backend) and ?renderer=webgl2 (forceWebGL) in Chromium with WebGPU enabled — it finishes its
 * capture without page errors and says on the page which backend runs.
 */

const LABELS: Record<string, string> = { webgpu: 'WebGPU', webgl2: 'WebGPURenderer (WebGL2 backend)' };
// renderer=webgpu: the page's unhandled-rejection handler catches "Instance dropped in popErrorScope"
// from three's WebGPU backend in headless Chromium (SwiftShader's adapter), also for a plain
// MeshBasicNodeMaterial sphere; skipped until that is understood.
const KNOWN: Record<string, string> = { webgpu: 'three\'s WebGPU backend rejects with "Instance dropped in popErrorScope" here', webgl2: '' };

describe.skipIf( browserSkipReason !== '' )( `demo pages on WebGPURenderer (Chromium)${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser( { webgpu: true } ); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	for ( const renderer of [ 'webgpu', 'webgl2' ] ) {

		it.skipIf( KNOWN[ renderer ] !== '' )( `basic with renderer=${renderer}: captures, renders without page errors and shows "${LABELS[ renderer ]}"${KNOWN[ renderer ] ? ' — SKIPPED: ' + KNOWN[ renderer ] : ''}`, async () => {

			const { page, errors } = await session.open( `examples/basic.html?resolution=8&t=4&probes=0&renderer=${renderer}`, { width: 320, height: 180 } );
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
