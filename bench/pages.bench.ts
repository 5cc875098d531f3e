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
	'Capture: all probes of the layout rendered and projected to SH on the GPU, timed by the page (its ProbeVolumeDemo.recapture, window.__demo.captureMs). The page opens with the layout and captures it at 32² (cold: "first capture"); then, in the same page with its render loop stopped (as during the first capture, so frames do not compete with the capture), warm recaptures at 32² and 128², median / min / max of 3 each. Layouts over 100 probes (the 432-probe grids) are skipped unless BENCH_PAGES_ALL=1, and then get the cold 32² capture only: one takes 1–1.5 minutes in SwiftShader, and the suite should stay within minutes. BENCH_PAGES=basic,kyoto runs only those pages. Kyoto (panoramas, no cube renders): 3 fresh page loads per resolution.',
	'Frame: median time between animation frames (requestAnimationFrame deltas, so GPU work is included) with the character and 100 probe-lit spheres moving; min/max are of those frames. Warm-up 20 frames and 60 timed frames, fewer on slow pages (5 warm-up, and as many as fit in about 20 s, at least 15) so the suite stays within minutes.',
	'No peer: these figures compare layouts and track the demos; the peer comparisons are in the capture bench. SwiftShader renders on the CPU: not figures for a real GPU.',
];

/** Warm recaptures per resolution; layouts above MAX_WARM_PROBES get only the cold capture. */
const WARM_RUNS = 3;
const MAX_WARM_PROBES = 100;

/** BENCH_PAGES=basic,kyoto runs only those pages; BENCH_PAGES_ALL=1 includes the layouts over MAX_WARM_PROBES. */
const ONLY = ( process.env.BENCH_PAGES ?? '' ).split( ',' ).filter( Boolean );
const ALL_LAYOUTS = process.env.BENCH_PAGES_ALL === '1';

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
	// The shared test server watches the repository and reloads pages on edits (other work in the
	// checkout would kill a capture mid-run): the bench serves the files as they are now.
	await session.server.watcher.close();
	try {

		for ( const { page, needs } of PAGES.filter( ( { page } ) => ONLY.length === 0 || ONLY.includes( page ) ) ) {

			const missing = needs.filter( ( file ) => ! existsSync( `${ASSETS}/${file}` ) );
			if ( ! existsSync( `examples/${page}.html` ) || missing.length > 0 ) {

				rows.push( { case: page, subject: '—', unit: 'ms', median: null, min: null, max: null, runs: 0, status: missing.length ? `assets missing: ${missing.join( ', ' )}` : 'no page yet' } );
				continue;

			}

			const layouts = await layoutNames( session, page );
			for ( const layout of layouts ) {

				try {

					rows.push( ...await captureRows( session, page, layout, log ) );

				} catch ( error ) {

					rows.push( { case: `${page}: ${layout}`, subject: 'capture', unit: 'ms', median: null, min: null, max: null, runs: 0, status: 'failed: ' + ( error as Error ).message.split( '\n' )[ 0 ] } );

				}

			}

			log( `${page}: frame time with the character and 100 spheres` );
			const demo = await openAndWait( session, `examples/${page}.html?hide=gui&resolution=16&spheres=100`, 10 );
			const frames = await frameIntervals( session, demo );
			const summary = frames.length ? summarize( frames ) : null;
			rows.push( {
				case: `${page}: ${layouts[ 0 ]}`, subject: 'frame, character + 100 spheres', unit: 'ms',
				median: summary?.median ?? null, min: summary?.min ?? null, max: summary?.max ?? null, runs: frames.length,
				output: `${demo.report.probes} probes`, status: demo.report.error || undefined,
			} );
			await demo.page.close();

		}

	} finally {

		await session.close();

	}

	return rows;

}

/** Probe count from a layout name such as '12x6x6 grid (432 probes)' or '85 probes placed …'; 0 when it does not say. */
function layoutProbeCount( layout: string ): number {

	const match = /(\d+) probes/.exec( layout );
	return match ? Number( match[ 1 ] ) : 0;

}

/** The layout names a page offers (read from its ProbeVolumeDemo, window.__demoApp, or its Kyoto frame). */
async function layoutNames( session: BrowserSession, page: string ): Promise<string[]> {

	const { page: tab } = await session.open( `examples/${page}.html?hide=gui&resolution=8`, { width: 320, height: 180 } );
	await tab.waitForFunction( 'window.__demo && ( window.__demo.ready || window.__demo.error )', { timeout: 600_000 } );
	const names = await tab.evaluate( `( window.__demoApp?.layoutNames?.() ?? window.__kyoto?.layoutNames?.() ?? [] )` ) as string[];
	await tab.close();
	return names.length ? names : [ 'default' ];

}

type Tab = Awaited<ReturnType<BrowserSession[ 'open' ]>>[ 'page' ];

/** Opens a page and waits until it is ready (and has `frames` frame intervals); the caller closes it. */
async function openAndWait( session: BrowserSession, path: string, frames: number ): Promise<{ page: Tab, report: Demo }> {

	const { page } = await session.open( path, { width: 1280, height: 720 } );
	await page.waitForFunction( 'window.__demo && ( window.__demo.ready || window.__demo.error )', { timeout: 600_000 } );
	if ( frames > 0 ) await page.waitForFunction( `window.__demo.error || window.__demo.intervalMs.length >= ${frames}`, { timeout: 600_000, polling: 500 } );
	return { page, report: await page.evaluate( 'window.__demo' ) as Demo };

}

/**
 * The frame intervals after a warm-up: 20 + 60 frames on a fast page; on a slow one (judged by
 * the first 10) 5 warm-up frames and as many as fit in about 20 s, at least 15.
 */
async function frameIntervals( session: BrowserSession, demo: { page: Tab, report: Demo } ): Promise<number[]> {

	if ( demo.report.error ) return [];
	const first = summarize( ( demo.report.intervalMs ?? [] ).slice( 0, 10 ) ).median;
	const warmUp = first > 200 ? 5 : 20;
	const timed = first > 200 ? Math.max( 15, Math.min( 60, Math.round( 20_000 / first ) ) ) : 60;
	await demo.page.waitForFunction( `window.__demo.error || window.__demo.intervalMs.length >= ${warmUp + timed}`, { timeout: 600_000, polling: 500 } );
	const intervals = await demo.page.evaluate( 'window.__demo.intervalMs' ) as number[];
	return intervals.slice( warmUp, warmUp + timed );

}

/** Capture rows of one layout: the cold capture when the page opens, then warm recaptures in it. */
async function captureRows( session: BrowserSession, page: string, layout: string, log: ( message: string ) => void ): Promise<BenchRow[]> {

	const caseName = `${page}: ${layout}`;
	const row = ( subject: string, times: number[], report: Demo, status?: string ): BenchRow => ( {
		case: caseName, subject, unit: 'ms', ...( times.length ? summarize( times ) : { median: null, min: null, max: null, runs: 0 } ),
		output: `${report.probes} probes, ${report.cells} cells`, status: report.error || status,
	} );

	if ( page === 'kyoto' ) {

		// Kyoto projects panoramas (no cube renders) and has no recapture(): fresh loads.
		const rows: BenchRow[] = [];
		for ( const resolution of [ 32, 128 ] ) {

			log( `${caseName} / capture at ${resolution}², ${WARM_RUNS} page loads` );
			const times: number[] = [];
			let report: Demo | null = null;
			for ( let r = 0; r < WARM_RUNS; r ++ ) {

				const demo = await openAndWait( session, `examples/${page}.html?hide=gui&resolution=${resolution}&layout=${encodeURIComponent( layout )}`, 0 );
				report = demo.report;
				await demo.page.close();
				if ( report.error ) break;
				times.push( report.captureMs );

			}

			rows.push( row( `capture at ${resolution}² (fresh page each)`, times, report! ) );

		}

		return rows;

	}

	const probes = layoutProbeCount( layout );
	if ( ! ALL_LAYOUTS && probes > MAX_WARM_PROBES ) {

		return [ { case: caseName, subject: 'capture at 32²', unit: 'ms', median: null, min: null, max: null, runs: 0, output: `${probes} probes`, status: `skipped: > ${MAX_WARM_PROBES} probes (BENCH_PAGES_ALL=1 includes it: 1–1.5 min per capture in SwiftShader)` } ];

	}

	log( `${caseName} / first capture at 32²` );
	const demo = await openAndWait( session, `examples/${page}.html?hide=gui&resolution=32&character=0&layout=${encodeURIComponent( layout )}`, 0 );
	try {

		const rows = [ row( 'first capture at 32² (cold, 1 run)', demo.report.error ? [] : [ demo.report.captureMs ], demo.report ) ];
		if ( demo.report.error ) return rows;

		for ( const resolution of [ 32, 128 ] ) {

			if ( demo.report.probes > MAX_WARM_PROBES ) {

				rows.push( row( `capture at ${resolution}²`, [], demo.report, `skipped: > ${MAX_WARM_PROBES} probes (minutes per capture in SwiftShader)` ) );
				continue;

			}

			log( `${caseName} / capture at ${resolution}² × ${WARM_RUNS}` );
			const times: number[] = [];
			for ( let r = 0; r < WARM_RUNS; r ++ ) {

				times.push( await demo.page.evaluate( `( async () => {
					const app = window.__demoApp;
					app.renderer.setAnimationLoop( null );
					app.params.resolution = ${resolution};
					await app.recapture();
					return window.__demo.captureMs;
				} )()` ) as number );

			}

			rows.push( row( `capture at ${resolution}² (warm, in page)`, times, demo.report ) );

		}

		return rows;

	} finally {

		await demo.page.close();

	}

}
