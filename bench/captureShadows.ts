/**
 * Part 4 of bench/capture.bench.ts: probe captures of scenes lit by a shadow-casting light, with
 * and without its shadows, in the same run (page: bench/pages/captureShadows.ts). ProbeCapturer
 * draws the shadow maps once per capture, so shadows should cost little: goal ≤ 1.15× the same
 * room without shadows. A floor row shades the same faces with the maps drawn beforehand (what is
 * left is the receivers' shading), another times one render of the maps. A diagnostic row captures
 * the way it was done before — three's default `shadowMap.autoUpdate = true`, every cube face
 * drawing every shadow map again.
 */

import { existsSync } from 'node:fs';
import { assetsFolder } from '../scripts/assetsPlugin.mjs';
import { cpuSnapshot } from './cpuSnapshot.js';
import type { CaptureShadowsBenchApi } from './pages/captureShadows.js';
import { summarize, type Summary } from './stats.js';
import type { BenchRow, Target } from './types.js';

type Browser = import( 'puppeteer-core' ).Browser;
type Page = import( 'puppeteer-core' ).Page;

const QUICK = process.env.BENCH_QUICK === '1';

/** Repetitions (captures with and without shadows alternate, after a warm-up of each). */
const PLAN = {
	basic: { sizes: [ 16, 32 ], runs: QUICK ? 1 : 5, perFaceRuns: QUICK ? 1 : 3 },
	sponza: { size: 32, runs: QUICK ? 1 : 3, perFaceProbes: 4, perFaceRuns: QUICK ? 1 : 2 },
};

/** The goal of issue 13 for a capture with shadows, as a multiple of the same capture without. */
const GOAL = 1.15;

/**
 * Runs part 4 on a new page of `browser` served from `base` (the capture bench's Vite server);
 * pushes rows and notes; page errors and warnings go to `errors`.
 */
export async function captureShadows(
	browser: Browser, base: string, rows: BenchRow[], notes: string[], errors: string[], log: ( message: string ) => void,
): Promise<void> {

	browserPid = browser.process()?.pid ?? null;
	const page = await browser.newPage();
	page.on( 'pageerror', ( error ) => errors.push( 'page error: ' + ( error as Error ).message ) );
	page.on( 'console', ( message ) => { if ( message.type() === 'error' || message.type() === 'warn' ) errors.push( `console.${message.type()}: ${message.text()}` ); } );
	try {

		await page.goto( `${base}captureShadows.html`, { waitUntil: 'load' } );
		const ready = () => ( window as unknown as { captureShadowsBenchReady?: boolean } ).captureShadowsBenchReady === true;
		await page.waitForFunction( ready, { timeout: 120_000 } );

		const basic = await call( page, 'loadBasic' );
		log( `shadows: Basic room, ${basic.probes} probes, ${basic.shadowLights} shadow-casting light(s), ${basic.triangles} triangles` );
		for ( const size of PLAN.basic.sizes ) {

			await compare( page, rows, log, {
				scene: 'basic', size, runs: PLAN.basic.runs,
				label: `4 Capture with a shadow-casting light: Basic room, ${basic.probes} probes, ${size}² (ms/capture)`,
			} );
			await perFace( page, rows, log, {
				scene: 'basic', size, runs: PLAN.basic.perFaceRuns, probes: - 1,
				label: `4 Capture with a shadow-casting light: Basic room, ${basic.probes} probes, ${size}² (ms/capture)`,
			} );

		}

		notes.push( `Shadows (4): the Basic room of the demo (scenes/basic.ts, ${basic.triangles} triangles), its PointLight lamp casting shadows into a 512² cube map (three's default size; the walls cast and receive), probes on its 4 × 4 × 4 grid; "no shadows" = the same scene with renderer.shadowMap.enabled and the lamp's castShadow false. Inside the closed room nothing stands between the lamp and the walls, so the SH do not change (Check column); the figure is what shadows cost a capture. ProbeCapturer draws the shadow maps at the first cube face of a capture and restores shadowMap.autoUpdate / needsUpdate after; the "per cube face" row renders the same probes with CubeCamera.update and three's default autoUpdate = true, as captures did before, then the same GPU projection. Captures with and without shadows alternate (order swapped every run) after a warm-up capture of each; figure = median over runs; "paired" = median of the per-run ratios; "browser CPU" = median CPU seconds of the Chromium process tree (and the bench process) per capture, which other processes' load inflates less than wall time. "shadow pass … draws" counts the shadow casters drawn by three's shadow pass (renderBufferDirect with its depth or distance material) during the capture, beside the draws of one render of the maps. With the maps drawn once, what shadows still cost is the receivers' shading (shadow coordinates per vertex, five PCF taps per fragment), which SwiftShader runs on the CPU. "floor" = the same faces rendered by the page's copy of the capture loop with the shadow maps drawn (and waited for) before the timer and never redrawn: the shading with shadows alone, what no capture that draws these shadows can go below; "one render of the shadow maps" is the only part a capture could still skip (bench/captureShadowsDecompose.ts splits the rest by face size, map size, process and WebGL calls).` );

		const sponzaFile = `${assetsFolder}/sponza/sponza.obj`;
		if ( ! existsSync( sponzaFile ) ) {

			const why = `skipped: ${sponzaFile} not found (set CAPTURE_LIGHTING_ASSETS; README "Assets")`;
			log( `shadows: Sponza ${why}` );
			rows.push( { case: '4 Capture with a shadow-casting light: Sponza', subject: '—', unit: 'ms', median: null, min: null, max: null, runs: 0, status: why } );
			return;

		}

		log( 'shadows: loading Sponza' );
		const sponza = await call( page, 'loadSponza', '/assets/' );
		if ( 'error' in sponza ) throw new Error( `Sponza did not load: ${sponza.error}` );
		log( `shadows: Sponza, ${sponza.probes} probes, ${sponza.shadowLights} shadow-casting light(s), ${sponza.triangles} triangles` );
		const size = PLAN.sponza.size;
		await compare( page, rows, log, {
			scene: 'sponza', size, runs: PLAN.sponza.runs,
			label: `4 Capture with a shadow-casting light: Sponza, ${sponza.probes} probes, ${size}² (ms/capture)`,
		} );
		const probes = PLAN.sponza.perFaceProbes;
		await perFace( page, rows, log, {
			scene: 'sponza', size, runs: PLAN.sponza.perFaceRuns, probes,
			label: `4 Capture with a shadow-casting light: Sponza, its first ${probes} probes, ${size}² (ms/capture)`,
		} );
		notes.push( `Shadows (4), Sponza: the demo's scene (scenes/sponza.ts: ${sponza.triangles} triangles, the sun's 2048² shadow map over a 40 m frustum, the sky dome, the 0.3 ambient stand-in), its ${sponza.probes} hand-placed probes at ${size}², with vs without the sun's shadow (shadowMap.enabled and castShadow off: the sun then lights the arcades through the walls). The per-face diagnostic (every face redrawing the 2048² map) is slow, so it runs on the first ${probes} probes only, beside ours on the same ${probes}.` );

	} finally {

		await page.close().catch( () => undefined );

	}

}

interface Case { scene: string, size: number, runs: number, label: string }

/** The Chromium process whose tree's CPU time is measured per capture (SwiftShader renders on the CPU). */
let browserPid: number | null = null;

/** Runs a capture in the page; adds the CPU seconds of the browser (and this process) it took. */
async function timed<K extends 'captureOnce' | 'capturePerFace' | 'captureLoop'>(
	page: Page, name: K, ...args: Parameters<CaptureShadowsBenchApi[ K ]>
): Promise<Awaited<ReturnType<CaptureShadowsBenchApi[ K ]>> & { cpu: number }> {

	const before = cpuSnapshot( browserPid );
	const result = await call( page, name, ...args );
	const after = cpuSnapshot( browserPid );
	return { ...result, cpu: before && after ? after.ours - before.ours : NaN };

}

/**
 * Ours with shadows vs ours without vs the floor (the same faces shaded with maps drawn beforehand),
 * alternating; rows for the three and for one render of the shadow maps.
 */
async function compare(
	page: Page, rows: BenchRow[], log: ( message: string ) => void, { scene, size, runs, label }: Case,
): Promise<void> {

	await call( page, 'captureOnce', scene, size, true );
	await call( page, 'captureOnce', scene, size, false );
	await call( page, 'captureLoop', scene, size, 'frozen' );
	const perRender = await call( page, 'drawsPerShadowRender', scene );
	const mapMs = await call( page, 'shadowMapRender', scene, 5 );
	const variants = [ 'with', 'without', 'floor' ] as const;
	const times = { with: [] as number[], without: [] as number[], floor: [] as number[] };
	const cpu = { with: [] as number[], without: [] as number[], floor: [] as number[] };
	const pairs: number[] = [];
	let withSH: number[] = [], withoutSH: number[] = [], floorSH: number[] = [], draws = 0;
	for ( let r = 0; r < runs; r ++ ) {

		// Rotate the order every run, so no variant always runs after the same one on a warmer machine.
		for ( let k = 0; k < variants.length; k ++ ) {

			const variant = variants[ ( k + r ) % variants.length ];
			const result = variant === 'floor'
				? await timed( page, 'captureLoop', scene, size, 'frozen' )
				: await timed( page, 'captureOnce', scene, size, variant === 'with' );
			times[ variant ].push( result.ms );
			cpu[ variant ].push( result.cpu );
			if ( variant === 'with' ) { withSH = result.sh; draws = result.shadowDraws; } else if ( variant === 'without' ) withoutSH = result.sh;
			else floorSH = result.sh;

		}

		pairs.push( times.with[ r ] / times.without[ r ] );
		log( `shadows: ${scene} ${size}²: with ${times.with[ r ].toFixed( 0 )} ms, without ${times.without[ r ].toFixed( 0 )} ms, `
			+ `floor ${times.floor[ r ].toFixed( 0 )} ms` );

	}

	const withShadows = summarize( times.with ), without = summarize( times.without ), floor = summarize( times.floor );
	const ratio = withShadows.median / without.median;
	const change = l00Change( withSH, withoutSH );
	const targets: Target[] = [ { text: `≤ ${GOAL}× without shadows`, met: ratio <= GOAL } ];
	const cpuOf = ( variant: keyof typeof cpu ) => summarize( cpu[ variant ] ).median;
	rows.push( row( label, 'ours: ProbeCapturer.capture, shadows (maps drawn once per capture)', withShadows, {
		peer: 'no shadows', ratio, targets,
		ratios: [ { peer: 'floor', ratio: withShadows.median / floor.median } ],
		output: `paired ${summarize( pairs ).median.toFixed( 2 )}×; browser CPU ${cpuOf( 'with' ).toFixed( 2 )} s, ${( cpuOf( 'with' ) / cpuOf( 'without' ) ).toFixed( 2 )}×`,
		status: `shadow pass ${draws} draws per capture (one map render: ${perRender}); shadows change L00 by `
			+ `${( 100 * change.mean ).toFixed( 2 )} % on average, ${( 100 * change.max ).toFixed( 1 )} % at most`,
	} ) );
	rows.push( row( label, 'ours: the same scene without shadows', without, { output: `browser CPU ${cpuOf( 'without' ).toFixed( 2 )} s` } ) );
	rows.push( row( label, 'floor: the same faces, shadow maps drawn beforehand and kept (no map render, no yields)', floor, {
		peer: 'no shadows', ratio: floor.median / without.median,
		output: `browser CPU ${cpuOf( 'floor' ).toFixed( 2 )} s, ${( cpuOf( 'floor' ) / cpuOf( 'without' ) ).toFixed( 2 )}× without`,
		status: `same SH as ours: max Δ ${maxDifference( floorSH, withSH ).toExponential( 1 )} of L00`,
	} ) );
	rows.push( {
		case: label, subject: 'diagnostic: one render of the shadow maps (one-texel renders with the maps redrawn minus without)',
		unit: 'ms', median: mapMs, min: null, max: null, runs: 5,
		output: `without shadows + one map render = ${( ( without.median + mapMs ) / without.median ).toFixed( 2 )}× without`,
	} );

}

/** Diagnostic: the shadow maps redrawn for every cube face (the capture before), vs ours on the same probes. */
async function perFace(
	page: Page, rows: BenchRow[], log: ( message: string ) => void, { scene, size, runs, probes, label }: Case & { probes: number },
): Promise<void> {

	await call( page, 'capturePerFace', scene, size, 1 ); // warm-up
	const oursTimes: number[] = [], perFaceTimes: number[] = [];
	let oursSH: number[] = [], perFaceSH: number[] = [], draws = 0;
	for ( let r = 0; r < runs; r ++ ) {

		const ours = await call( page, 'captureOnce', scene, size, true, probes );
		const before = await call( page, 'capturePerFace', scene, size, probes );
		oursTimes.push( ours.ms ); perFaceTimes.push( before.ms );
		oursSH = ours.sh; perFaceSH = before.sh; draws = before.shadowDraws;
		log( `shadows: ${scene} ${size}²${probes > 0 ? `, ${probes} probes` : ''}: per face ${before.ms.toFixed( 0 )} ms, ours ${ours.ms.toFixed( 0 )} ms` );

	}

	const ours = summarize( oursTimes ), before = summarize( perFaceTimes );
	if ( probes > 0 ) rows.push( row( label, 'ours: ProbeCapturer.capture, shadows (maps drawn once per capture)', ours ) );
	rows.push( row( label, 'diagnostic: shadow maps redrawn per cube face (three\'s default autoUpdate, the capture before)', before, {
		peer: 'ours, shadows', ratio: before.median / ours.median,
		output: `${( before.median / ours.median ).toFixed( 1 )}× ours`,
		status: `shadow pass ${draws} draws; same SH as ours: max Δ ${maxDifference( perFaceSH, oursSH ).toExponential( 1 )} of L00`,
	} ) );

}

/** Mean and largest |ΔL00| / L00 over probes and channels. */
function l00Change( a: number[], b: number[] ): { mean: number, max: number } {

	let sum = 0, max = 0, n = 0;
	for ( let p = 0; p < a.length / 27; p ++ ) for ( let c = 0; c < 3; c ++ ) {

		const d = Math.abs( a[ 27 * p + c ] - b[ 27 * p + c ] ) / Math.max( Math.abs( b[ 27 * p + c ] ), 1e-12 );
		sum += d; max = Math.max( max, d ); n ++;

	}

	return { mean: sum / Math.max( n, 1 ), max };

}

/** Largest |a − b| over all floats, relative to that probe's largest |L00| channel of `b`. */
export function maxDifference( a: number[], b: number[] ): number {

	let worst = 0;
	for ( let p = 0; p < b.length / 27; p ++ ) {

		const scale = Math.max( Math.abs( b[ 27 * p ] ), Math.abs( b[ 27 * p + 1 ] ), Math.abs( b[ 27 * p + 2 ] ), 1e-12 );
		for ( let i = 0; i < 27; i ++ ) worst = Math.max( worst, Math.abs( a[ 27 * p + i ] - b[ 27 * p + i ] ) / scale );

	}

	return worst;

}

function row( caseName: string, subject: string, summary: Summary, extra: Partial<BenchRow> = {} ): BenchRow {

	return { case: caseName, subject, unit: 'ms', median: summary.median, min: summary.min, max: summary.max, runs: summary.runs, ...extra };

}

/** Calls `window.captureShadowsBench[ name ]( ...args )` in the page and returns its (JSON) result. */
async function call<K extends keyof CaptureShadowsBenchApi>(
	page: Page, name: K, ...args: Parameters<CaptureShadowsBenchApi[ K ]>
): Promise<Awaited<ReturnType<CaptureShadowsBenchApi[ K ]>>> {

	return page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

		const api = ( window as unknown as { captureShadowsBench: Record<string, ( ...a: unknown[] ) => unknown> } ).captureShadowsBench;
		return api[ fn ]( ...fnArgs );

	}, name, args as unknown[] ) as Promise<Awaited<ReturnType<CaptureShadowsBenchApi[ K ]>>>;

}
