/**
 * `LightProbeVolume.fromScene` beside a capture of the same candidates alone (issue 14's target:
 * within 1.3× at 32² on Sponza), in headless Chromium (SwiftShader on CI), on the demo's Basic room
 * (budget 12) and Sponza (budget 86; skipped with a message when its files are missing). Each run
 * times fromScene (placement, one capture of every candidate, the reduction with re-fits and
 * swaps, the fit) and the capture of its candidates alone (a volume over them, captured with the
 * same options) back to back, in an order rotated per run; "paired" = median of the per-run
 * ratios. fromScene's stages come from its onProgress; the candidates stage is split further by
 * timing its parts alone on the same level (page: bench/pages/fromScene.ts).
 *
 *   npm run bench -- fromScene        (BENCH_QUICK=1: one run per level; BENCH_FROMSCENE=basic: one level)
 */

import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { checkChromium, launchChromium, resolveChromiumPath } from '../cli/chromium.js';
import { libraryAliases } from '../cli/libraryAliases.js';
import { assetsFolder, assetsPlugin } from '../scripts/assetsPlugin.mjs';
import type { FromSceneBenchApi } from './pages/fromScene.js';
import { summarize } from './stats.js';
import type { BenchRow } from './types.js';

type Page = import( 'puppeteer-core' ).Page;

const BENCH_DIR = fileURLToPath( new URL( '.', import.meta.url ) );
const QUICK = process.env.BENCH_QUICK === '1';
const ONLY = ( process.env.BENCH_FROMSCENE ?? '' ).split( ',' ).filter( Boolean );

/** Cube size of every capture, and timed runs (after a warm-up) per level. */
const RESOLUTION = 32;
const RUNS: Record<string, number> = { basic: QUICK ? 1 : 5, sponza: QUICK ? 1 : 2 };

/** Issue 14's target: fromScene ≤ 1.3× the capture of its candidates alone. */
const TARGET = 1.3;

export const title = `LightProbeVolume.fromScene vs capturing its candidates alone, headless Chromium, ${RESOLUTION}² (ms, lower is better)`;

export const notes: string[] = [
	`Levels as on the demo pages: Basic (scenes/basic.ts, budget 12, reachableFrom the middle of the room at 1.6 m, near 0.02 / far 20) and Sponza (scenes/sponza.ts with its sun's shadow map and sky dome, budget 86, reachableFrom (−9, 1.6, −1.4) on the fox's path, bounds the atrium's box without the sky, near 0.05 / far 400); every capture at ${RESOLUTION}², fromScene with its defaults (fit with λ by cross-validation, swap passes). "capture alone" = new LightProbeVolume( { positions: candidates } ) and its capture with the same options, the candidates being placeCandidates' with fromScene's settings (the Check column compares the counts). Each run times both back to back, order rotated per run, after a warm-up (a fromScene of 4 probes from about 64 grid candidates: the level's shaders compiled, untimed); figure = median over runs; "paired" = median of the per-run ratios. Sponza's 770 candidates take minutes per capture in SwiftShader: BENCH_FROMSCENE=basic leaves it out.`,
	'Stages (fromScene\'s onProgress: each stage from its first report to the next stage\'s): setup (argument checks), candidates (gathering the level\'s triangles, placement with the open-space tests), capture, reduce (reduceProbes with fit and swaps), fit (VolumeFit, λ by cross-validation). Parts of the candidates stage, timed alone on the same level: gathering the triangles, the BVH, the inside test\'s closed shells, the reachability flood (ReachableSpace over the flood\'s box), and placeCandidates whole (which builds its own BVH, shells and flood).',
];

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const chromium = resolveChromiumPath();
	const missing = checkChromium( chromium.path, chromium.source );
	if ( missing ) return [ skipped( 'all levels', `skipped: ${missing}` ) ];
	const { createServer } = await import( 'vite' );
	const server = await createServer( {
		configFile: false,
		root: BENCH_DIR + 'pages',
		cacheDir: BENCH_DIR + 'build/vite-cache',
		logLevel: 'warn',
		resolve: { alias: libraryAliases( BENCH_DIR + '..' ) },
		plugins: [ assetsPlugin() ],
		optimizeDeps: { include: [ 'three', 'three/addons/loaders/MTLLoader.js', 'three/addons/loaders/OBJLoader.js' ] },
		// No file watching or HMR: edits elsewhere in the repository must not reload the page mid-run.
		server: { host: '127.0.0.1', port: 5197, strictPort: false, hmr: false, watch: null },
	} );
	await server.listen();
	const rows: BenchRow[] = [];
	const errors: string[] = [];
	const browser = await launchChromium( {
		browser: chromium.path, protocolTimeout: 1_800_000, defaultViewport: { width: 1280, height: 720, deviceScaleFactor: 1 },
	} );
	try {

		const page = await browser.newPage();
		page.on( 'pageerror', ( error ) => errors.push( 'page error: ' + ( error as Error ).message ) );
		page.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( `console.error: ${message.text()}` ); } );
		await page.goto( `${server.resolvedUrls!.local[ 0 ]}fromScene.html`, { waitUntil: 'load' } );
		const ready = () => ( window as unknown as { fromSceneBenchReady?: boolean } ).fromSceneBenchReady === true;
		await page.waitForFunction( ready, { timeout: 120_000 } );
		const info = await call( page, 'info' );
		notes.push( `Browser: ${await browser.version()}; ${info.renderer}; three r${info.three}.` );

		for ( const name of [ 'basic', 'sponza' ].filter( ( n ) => ONLY.length === 0 || ONLY.includes( n ) ) ) {

			const label = `fromScene, ${name === 'basic' ? 'Basic room, budget 12' : 'Sponza, budget 86'}, ${RESOLUTION}²`;
			if ( name === 'sponza' ) {

				const file = `${assetsFolder}/sponza/sponza.obj`;
				if ( ! existsSync( file ) ) {

					rows.push( skipped( label, `skipped: ${file} not found (set CAPTURE_LIGHTING_ASSETS; README "Assets")` ) );
					continue;

				}

				log( 'fromScene: loading Sponza' );
				const loaded = await call( page, 'loadSponza', '/assets/' );
				if ( 'error' in loaded ) throw new Error( `fromScene bench: Sponza did not load: ${loaded.error}` );
				log( `fromScene: Sponza, ${loaded.triangles} triangles` );

			} else {

				log( `fromScene: Basic room, ${( await call( page, 'loadBasic' ) ).triangles} triangles` );

			}

			rows.push( ...await level( page, name, label, log ) );

		}

		await page.close();

	} finally {

		await browser.close().catch( () => undefined );
		await server.close().catch( () => undefined );

	}

	const unique = [ ...new Set( errors ) ];
	if ( unique.length ) notes.push( `The page reported ${errors.length} error(s): ${unique.slice( 0, 5 ).join( ' | ' ).slice( 0, 1000 )}` );
	return rows;

}

/** The rows of one level: fromScene and the capture alone, paired, and the stage split. */
async function level( page: Page, name: string, label: string, log: ( message: string ) => void ): Promise<BenchRow[]> {

	log( `${label}: warm-up` );
	await call( page, 'warmUp', name, RESOLUTION );
	const totals: number[] = [], alone: number[] = [], pairs: number[] = [];
	const stages: Record<string, number[]> = {};
	const parts: Record<string, number[]> = {};
	let probes = 0, candidates = 0, captured = 0;
	for ( let r = 0; r < RUNS[ name ]; r ++ ) {

		let fromMs = 0, aloneMs = 0;
		for ( let k = 0; k < 2; k ++ ) {

			if ( ( k + r ) % 2 === 0 ) {

				const result = await call( page, 'fromScene', name, RESOLUTION, true );
				totals.push( fromMs = result.ms );
				for ( const [ stage, ms ] of Object.entries( result.stages ) ) ( stages[ stage ] ??= [] ).push( ms );
				probes = result.probes; candidates = result.candidates;

			} else {

				const result = await call( page, 'captureCandidates', name, RESOLUTION );
				alone.push( aloneMs = result.ms );
				captured = result.candidates;

			}

		}

		pairs.push( fromMs / aloneMs );
		for ( const [ part, ms ] of Object.entries( await call( page, 'placementParts', name ) ) ) ( parts[ part ] ??= [] ).push( ms );
		log( `${label}: fromScene ${fromMs.toFixed( 0 )} ms, capture alone ${aloneMs.toFixed( 0 )} ms (${( fromMs / aloneMs ).toFixed( 2 )}×)` );

	}

	const from = summarize( totals ), base = summarize( alone ), paired = summarize( pairs ).median;
	const ratio = from.median / base.median;
	const rows: BenchRow[] = [
		{
			case: label, subject: 'ours: LightProbeVolume.fromScene', unit: 'ms', ...from,
			output: `${probes} probes of ${candidates} candidates; paired ${paired.toFixed( 2 )}×`,
			status: candidates === captured ? 'same candidates' : `CANDIDATES DIFFER: ${candidates} vs ${captured}`,
			peer: 'capture alone', ratio, targets: [ { text: `≤ ${TARGET}× the capture alone`, met: paired <= TARGET } ],
		},
		{ case: label, subject: `capture of the ${captured} candidates alone`, unit: 'ms', ...base },
	];
	for ( const stage of [ 'setup', 'candidates', 'capture', 'reduce', 'recapture', 'fit' ] ) {

		if ( ! stages[ stage ] ) continue;
		const s = summarize( stages[ stage ] );
		rows.push( { case: label, subject: `stage: ${stage}`, unit: 'ms', ...s, output: `${( 100 * s.median / from.median ).toFixed( 1 )} % of fromScene` } );

	}

	for ( const [ part, times ] of Object.entries( parts ) ) {

		rows.push( { case: label, subject: `candidates part, alone: ${part}`, unit: 'ms', ...summarize( times ) } );

	}

	return rows;

}

function skipped( label: string, status: string ): BenchRow {

	return { case: label, subject: '—', unit: 'ms', median: null, min: null, max: null, runs: 0, status };

}

async function call<K extends keyof FromSceneBenchApi>(
	page: Page, name: K, ...args: Parameters<FromSceneBenchApi[ K ]>
): Promise<Awaited<ReturnType<FromSceneBenchApi[ K ]>>> {

	return page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

		const api = ( window as unknown as { fromSceneBench: Record<string, ( ...a: unknown[] ) => unknown> } ).fromSceneBench;
		return api[ fn ]( ...fnArgs );

	}, name, args as unknown[] ) as Promise<Awaited<ReturnType<FromSceneBenchApi[ K ]>>>;

}
