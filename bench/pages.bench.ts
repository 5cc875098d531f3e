/**
 * The demo pages in headless Chromium (SwiftShader) at 1280×720: capture time of all probes at
 * 32² and 128² per layout, and the frame time with the character plus 100 probe-lit spheres.
 * These are the figures later tuning targets come from (issue: demo pages).
 */

import { existsSync } from 'node:fs';
import { ASSETS, browserSkipReason, startBrowser, type BrowserSession } from '../test/helpers/browser.js';
import { summarize } from './stats.js';
import type { BenchRow } from './types.js';

export const title = 'Demo pages in headless Chromium (SwiftShader), 1280×720';

export const notes = [
	'Capture: all probes of the layout rendered and projected to SH on the GPU, from the page\'s own capture timer (one run per resolution; the page loads afresh each time).',
	'Frame: median time between animation frames (requestAnimationFrame deltas, so GPU work is included) over ≥ 60 frames after 20 warm-up frames, with the character and 100 probe-lit spheres moving; min/max are of those frames.',
	'SwiftShader renders on the CPU: these are figures for comparing layouts and for tracking, not for a real GPU.',
];

const PAGES = [
	{ page: 'basic', needs: [] as string[] },
	{ page: 'sponza', needs: [ 'sponza/sponza.obj' ] },
	{ page: 'sibenik', needs: [ 'sibenik/sibenik.obj' ] },
	{ page: 'kyoto', needs: [ 'panoramas/potsdamer_platz_1k.hdr' ] },
];

interface Demo { ready: boolean; error: string; probes: number; cells: number; captureMs: number; intervalMs?: number[] }

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const rows: BenchRow[] = [];
	if ( browserSkipReason ) {

		rows.push( { case: 'all pages', subject: '—', unit: 'ms', median: null, min: null, max: null, runs: 0, status: browserSkipReason } );
		return rows;

	}

	const session = await startBrowser();
	try {

		for ( const { page, needs } of PAGES ) {

			const missing = needs.filter( ( file ) => ! existsSync( `${ASSETS}/${file}` ) );
			if ( ! existsSync( `examples/${page}.html` ) || missing.length > 0 ) {

				rows.push( { case: page, subject: '—', unit: 'ms', median: null, min: null, max: null, runs: 0, status: missing.length ? `assets missing: ${missing.join( ', ' )}` : 'no page yet' } );
				continue;

			}

			const layouts = await layoutNames( session, page );
			for ( const layout of layouts ) {

				for ( const resolution of [ 32, 128 ] ) {

					log( `${page} / ${layout} / capture at ${resolution}²` );
					const demo = await openAndWait( session, `examples/${page}.html?hide=gui&resolution=${resolution}&layout=${encodeURIComponent( layout )}`, 0 );
					rows.push( {
						case: `${page}: ${layout}`, subject: `capture at ${resolution}²`, unit: 'ms',
						median: demo.error ? null : demo.captureMs, min: null, max: null, runs: 1,
						output: `${demo.probes} probes, ${demo.cells} cells`, status: demo.error || undefined,
					} );

				}

			}

			log( `${page}: frame time with the character and 100 spheres` );
			const demo = await openAndWait( session, `examples/${page}.html?hide=gui&resolution=16&spheres=100`, 80 );
			const frames = ( demo.intervalMs ?? [] ).slice( 20 );
			const summary = frames.length ? summarize( frames ) : null;
			rows.push( {
				case: `${page}: ${layouts[ 0 ]}`, subject: 'frame, character + 100 spheres', unit: 'ms',
				median: summary?.median ?? null, min: summary?.min ?? null, max: summary?.max ?? null, runs: frames.length,
				output: `${demo.probes} probes`, status: demo.error || undefined,
			} );

		}

	} finally {

		await session.close();

	}

	return rows;

}

/** The layout names a page offers (read from its DemoApp / Kyoto frame). */
async function layoutNames( session: BrowserSession, page: string ): Promise<string[]> {

	const { page: tab } = await session.open( `examples/${page}.html?hide=gui&resolution=8`, { width: 320, height: 180 } );
	await tab.waitForFunction( 'window.__demo && ( window.__demo.ready || window.__demo.error )', { timeout: 600_000 } );
	const names = await tab.evaluate( `( window.__demoApp?.layoutNames?.() ?? window.__kyoto?.layoutNames?.() ?? [] )` ) as string[];
	await tab.close();
	return names.length ? names : [ 'default' ];

}

async function openAndWait( session: BrowserSession, path: string, frames: number ): Promise<Demo> {

	const { page } = await session.open( path, { width: 1280, height: 720 } );
	await page.waitForFunction( 'window.__demo && ( window.__demo.ready || window.__demo.error )', { timeout: 600_000 } );
	if ( frames > 0 ) await page.waitForFunction( `window.__demo.error || window.__demo.intervalMs.length >= ${frames}`, { timeout: 600_000, polling: 500 } );
	const demo = await page.evaluate( 'window.__demo' ) as Demo;
	await page.close();
	return demo;

}
