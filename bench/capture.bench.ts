/**
 * GPU capture, side by side with three.js r187's own probe tools, in headless Chromium (1280×720,
 * WebGL2 through whatever GPU Chromium is given; SwiftShader on CI), on the Basic room:
 *
 * 1. SH projection of an already rendered cube map, per probe: ours (SHProjector begin / add ×
 *    64 / finish, batch time ÷ 64) vs `LightProbeGenerator.fromCubeRenderTarget`, at 32², 128²,
 *    256²; plus a check that both give the same SH on the same cube maps.
 * 2. Whole bake of a 4 × 4 × 4 grid (64 probes): ours (`ProbeCapturer.capture`) vs
 *    `LightProbeGridWebGL.bake`, at 8², 32², 128², same positions, near and far, each run beside
 *    the floor both share: the 64 cube renders alone.
 * 3. Frame time with 500 moving spheres: ours (`LightProbeVolume.update()` + render) vs one
 *    global `THREE.LightProbe`, vs no probe, vs three's per-pixel `LightProbeGridWebGL`.
 * 4. Capture with a shadow-casting light (page bench/pages/captureShadows.ts): the demo's Basic room
 *    with its lamp casting shadows vs the same room without, and Sponza with its shadowed sun vs
 *    without; a floor row shades the same faces with the maps drawn beforehand, another times one
 *    render of the maps, and a diagnostic row redraws the shadow maps per cube face, as captures
 *    did before (bench/captureShadowsDecompose.ts splits the extra time further).
 *
 * The page is bench/pages/capture.ts, served by a Vite dev server started here; puppeteer calls
 * its functions and this file summarises their raw timings. Every timing ends in a GPU → CPU
 * read-back that depends on the timed work.
 *
 *   npm run bench -- capture            (BENCH_QUICK=1: a smoke run with few repetitions;
 *                                        BENCH_CAPTURE_PARTS=frames,shadows: only some of the parts)
 */

import { readFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { CHROMIUM_ARGS, checkChromium, launchChromium, resolveChromiumPath } from '../cli/chromium.js';
import { libraryAliases } from '../cli/libraryAliases.js';
import { assetsPlugin } from '../scripts/assetsPlugin.mjs';
import type { CaptureBenchApi } from './pages/capture.js';
import { cpuSnapshot } from './cpuSnapshot.js';
import { captureShadows } from './captureShadows.js';
import { summarize, type Summary } from './stats.js';
import type { BenchRow, Target } from './types.js';

const BENCH_DIR = fileURLToPath( new URL( '.', import.meta.url ) );
const QUICK = process.env.BENCH_QUICK === '1';
/** BENCH_CAPTURE_PARTS=projection,bake,frames,shadows (default all) runs only those parts. */
const PARTS = ( process.env.BENCH_CAPTURE_PARTS ?? 'projection,bake,frames,shadows' ).split( ',' ).map( ( part ) => part.trim() );

/** Repetitions; BENCH_QUICK=1 for a smoke run. */
const PLAN = {
	projection: {
		sizes: [ 32, 128, 256 ],
		cubes: 8, // distinct cube maps rendered per size, cycled through by the batches
		batchProbes: 64,
		oursBatches: QUICK ? 2 : 7,
		peerRuns: ( size: number ) => QUICK ? 2 : size <= 32 ? 15 : size <= 128 ? 7 : 5,
		portRuns: ( size: number ) => QUICK ? 1 : size <= 32 ? 7 : 3,
	},
	bake: {
		sizes: [ 8, 32, 128 ],
		runs: ( size: number ) => QUICK ? 1 : size <= 32 ? 5 : 3,
	},
	frames: {
		spheres: 500,
		cubeSize: 32,
		rounds: QUICK ? 1 : 6,
		warmUp: 2, // steps (of 4 frames) before each round's timed steps
		frames: QUICK ? 6 : 15, // timed steps per round
	},
};

// Figures from the issue, printed beside ours; targets are printed, never asserted.
const FILER = {
	generatorMsAt128: 53,
	gridMsPerProbe: { 8: 5.4, 32: 17.6, 128: 162 } as Record<number, number>,
	frameGlobal: 1.2,
	frameGrid: 1.7,
};

export const title = 'GPU capture vs three.js probe tools, headless Chromium 1280×720 (ms, lower is better)';

export const notes: string[] = [
	'Scene: the Basic room, 4 × 3 × 4 m — red (−x), green (+x), blue (−z) walls, white floor, ceiling and back wall, MeshStandardMaterial roughness 1 — lit by one PointLight under a glowing ceiling panel. Probes: LightProbeGridWebGL\'s own 4 × 4 × 4 cell-centre positions, for ours too; cube camera near 0.05, far 20 for both.',
	'1 (projection): 8 cube maps rendered once per size (HalfFloat, NearestFilter: ProbeCapturer\'s defaults) and waited for; then only the projection is timed. Ours: one SHProjector batch = begin + 64 × add of the cube render target (cycling the 8 maps; from 128² on add copies its faces to 2D textures, included) + finish (reduction, gather and the one read-back of 27 floats per probe, which waits for the GPU); figure = batch time ÷ 64, median / min / max over batches after a warm-up batch. Peer: one awaited LightProbeGenerator.fromCubeRenderTarget per run (r187 reads each face with readRenderTargetPixelsAsync — a fence polled every 4 ms by setTimeout — then a CPU loop), after a warm-up call; ours\' batches and the peer\'s runs alternate. The "sync read-back (bench port)" row is a diagnostic: the same loop with synchronous readRenderTargetPixels, to show how much of the peer is polling latency.',
	'2 (bake): whole bake of the 64 probes, median / min / max over runs after a warm-up of each (a full bake; at 128² the grid warms up on 4 probes). Ours: ProbeCapturer.capture (cube renders + GPU projection + read-back of the SH; it also yields to the event loop with setTimeout(0) about every 30 ms so a page can paint progress — included). Peer: LightProbeGridWebGL.bake, then a 1-texel read of a target drawn from its atlas, so the time includes its GPU work. Check: ours\' L00 vs the grid\'s L00 read back from its atlas, per probe. Diagnostic row: the 64 cube renders alone (what both bakes share, the floor of a bake), timed the same way. Each run times ours, the grid and the cube renders back to back, in an order rotated per run; "paired" = median over runs of ours ÷ the cube renders of the same run.',
	'3 (frames): five scenes, one per variant, each with the room (walls unlit — MeshBasicMaterial — so only the spheres pay for probe lighting in every variant), the ceiling panel, a PointLight and 500 spheres (radius 0.08 m, 16 × 12 segments) each with its own MeshStandardMaterial, moving on the same Lissajous paths through the probe hull. none: no probe. global: one THREE.LightProbe holding the volume\'s SH at the room centre. grid: LightProbeGridWebGL baked at 32², in the scene. ours: LightProbeVolume over the same 64 probes captured at 32², the spheres added with volume.add (each sphere\'s own material patched in place — no clones; one shared program). ours with gradient probes: a second LightProbeVolume with the same positions and SH made gradient probes by setGradients (random gradients, each float uniform in ±|L00 of its channel| / 4 m, the room\'s largest side), its own 500 spheres; the "paired" figure is its frame ÷ ours\' frame of the same step (issue 14\'s target ≤ 1.1×). Per frame timed: [volume.update(), ours and ours with gradients only] + renderer.render + a 1-pixel canvas readPixels (GPU sync); moving the spheres is not timed. Frames interleave: each animation step renders one frame of every variant, in an order rotated per step, so all five see the same machine load. 6 rounds of 2 warm-up + 15 timed steps; a round\'s figure is the median of its 15 frames; figure = median of the round medians, min / max of the round medians.',
];

type Browser = import( 'puppeteer-core' ).Browser;
type Page = import( 'puppeteer-core' ).Page;

const loads: string[] = [];

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const chromium = resolveChromiumPath();
	const missing = checkChromium( chromium.path, chromium.source );
	if ( missing ) throw new Error( `capture bench: ${missing}` );
	const { createServer } = await import( 'vite' );
	const ours = process.env.BENCH_OURS ? resolve( process.env.BENCH_OURS ) : null;

	const server = await createServer( {
		configFile: false,
		root: BENCH_DIR + 'pages',
		cacheDir: BENCH_DIR + 'build/vite-cache',
		logLevel: 'warn',
		// The page imports ../../src/index.js (relative, for the type-check); BENCH_OURS swaps it.
		// The scenes (part 4) import the package's subpaths and load their assets from /assets/.
		resolve: { alias: [ ...( ours ? [ { find: /^\.\.\/\.\.\/src\/index\.js$/, replacement: ours } ] : [] ), ...libraryAliases( BENCH_DIR + '..' ) ] },
		plugins: [ assetsPlugin() ],
		optimizeDeps: {
			include: [
				'three', 'three/examples/jsm/lights/LightProbeGenerator.js', 'three/examples/jsm/lighting/LightProbeGridWebGL.js',
				'three/addons/loaders/MTLLoader.js', 'three/addons/loaders/OBJLoader.js',
			],
		},
		// No file watching or HMR: edits elsewhere in the repository must not reload the page mid-run.
		server: { host: '127.0.0.1', port: 5199, strictPort: false, hmr: false, watch: null },
	} );
	await server.listen();
	const url = `${server.resolvedUrls!.local[ 0 ]}capture.html`;

	const errors: string[] = [];
	const rows: BenchRow[] = [];
	let browser: Browser | null = null;

	try {

		browser = await launchChromium( {
			browser: chromium.path, protocolTimeout: 900_000, defaultViewport: { width: 1280, height: 720, deviceScaleFactor: 1 },
		} );
		const page = await browser.newPage();
		page.on( 'pageerror', ( error ) => errors.push( 'page error: ' + ( error as Error ).message ) );
		page.on( 'console', ( message ) => { if ( message.type() === 'error' || message.type() === 'warn' ) errors.push( `console.${message.type()}: ${message.text()}` ); } );
		log( `loading ${url}` );
		await page.goto( url, { waitUntil: 'load' } );
		const ready = () => ( window as unknown as { captureBenchReady?: boolean } ).captureBenchReady === true;
		await page.waitForFunction( ready, { timeout: 120_000 } );

		const info = await call( page, 'info' );
		const version = await browser.version();
		notes.push( `Browser: ${version} (headless, ${CHROMIUM_ARGS.join( ' ' )}); WebGL: ${String( info.version )}; ${String( info.vendor )} / ${String( info.renderer )}; EXT_color_buffer_float ${info.colorBufferFloat ? 'yes' : 'no'}; three r${String( info.three )}; puppeteer-core ${packageVersion( 'puppeteer-core' )}, vite ${packageVersion( 'vite' )}; canvas ${( info.canvas as number[] ).join( '×' )} at devicePixelRatio ${String( info.devicePixelRatio )}, antialias off.${QUICK ? ' BENCH_QUICK=1: smoke run, few repetitions.' : ''}` );
		log( `${version}; ${String( info.renderer )}` );

		const pid = browser.process()?.pid ?? null;
		if ( PARTS.includes( 'projection' ) ) await section( 'projection', pid, rows, log, () => projection( page, rows, log ) );
		if ( PARTS.includes( 'bake' ) ) await section( 'bake', pid, rows, log, () => bake( page, rows, log ) );
		if ( PARTS.includes( 'frames' ) ) await section( 'frames', pid, rows, log, () => frames( page, rows, log ) );
		await page.close();
		if ( PARTS.includes( 'shadows' ) ) {

			const base = server.resolvedUrls!.local[ 0 ];
			await section( 'shadows', pid, rows, log, () => captureShadows( browser!, base, rows, notes, errors, log ) );

		}

	} finally {

		await browser?.close().catch( () => undefined );
		await server.close().catch( () => undefined );

	}

	if ( loads.length ) notes.push( `CPU taken by other processes during each part (${cpus().length} logical CPUs, shared with Chromium's SwiftShader "GPU"; a large share makes the figures noisy and slow): ${loads.join( '; ' )}.` );
	const unique = [ ...new Set( errors ) ];
	if ( unique.length ) notes.push( `The page reported ${errors.length} error/warning message(s): ${unique.slice( 0, 8 ).join( ' | ' ).slice( 0, 1500 )}` );
	return rows;

}

function packageVersion( name: string ): string {

	try {

		return ( JSON.parse( readFileSync( `${BENCH_DIR}../node_modules/${name}/package.json`, 'utf8' ) ) as { version: string } ).version;

	} catch {

		return '?';

	}

}

/**
 * Runs one part; a failure becomes a note and a row, and the next part still runs. Records how
 * much CPU other processes took meanwhile (the machine's busy time minus this process and its
 * Chromium's), since Chromium's "GPU" here is the CPU.
 */
async function section(
	name: string, browserPid: number | null, rows: BenchRow[], log: ( message: string ) => void, body: () => Promise<void>,
): Promise<void> {

	const start = performance.now();
	const before = cpuSnapshot( browserPid );
	try {

		await body();
		const after = cpuSnapshot( browserPid );
		if ( before && after ) {

			const wall = ( performance.now() - start ) / 1000;
			const others = Math.max( 0, ( after.busy - before.busy ) - ( after.ours - before.ours ) );
			const ours = after.ours - before.ours;
			loads.push( `${name}: ${wall.toFixed( 0 )} s wall, bench ${ours.toFixed( 0 )} CPU-s, other processes ${others.toFixed( 0 )} CPU-s (${( 100 * others / ( wall * cpus().length ) ).toFixed( 0 )} % of the machine)` );
			log( `${name}: other processes took ${others.toFixed( 1 )} CPU-s` );

		}

	} catch ( error ) {

		const message = ( error as Error ).message?.split( '\n' )[ 0 ] ?? String( error );
		log( `${name} failed: ${( error as Error ).stack ?? error}` );
		notes.push( `Part "${name}" failed: ${message}` );
		rows.push( { case: name, subject: '—', unit: 'ms', median: null, min: null, max: null, runs: 0, status: 'failed: ' + message.slice( 0, 200 ) } );

	}

	log( `${name}: ${( ( performance.now() - start ) / 1000 ).toFixed( 0 )} s` );

}

/** Calls `window.captureBench[ name ]( ...args )` in the page and returns its (JSON) result. */
async function call<K extends keyof CaptureBenchApi>(
	page: Page, name: K, ...args: Parameters<CaptureBenchApi[ K ]>
): Promise<Awaited<ReturnType<CaptureBenchApi[ K ]>>> {

	return page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

		const api = ( window as unknown as { captureBench: Record<string, ( ...a: unknown[] ) => unknown> } ).captureBench;
		return api[ fn ]( ...fnArgs );

	}, name, args as unknown[] ) as Promise<Awaited<ReturnType<CaptureBenchApi[ K ]>>>;

}

// ---------------------------------------------------------------------------------------------
// 1. Projection

async function projection( page: Page, rows: BenchRow[], log: ( message: string ) => void ): Promise<void> {

	const plan = PLAN.projection;
	const checks: string[] = [];

	for ( const size of plan.sizes ) {

		const label = `1 SH projection, ${size}² cube (ms/probe)`;
		log( `projection ${size}²: rendering ${plan.cubes} cube maps` );
		await call( page, 'prepareCubes', size, plan.cubes, 'half' );

		// Ours: warm-up batch (compiles, allocates targets and the solid-angle texture), then timed batches.
		const warm = await call( page, 'oursProjectBatch', plan.batchProbes, 'exact' );
		const oursSH = warm.sh;
		const paperSH = ( await call( page, 'oursProjectBatch', plan.cubes, 'paper' ) ).sh;

		// Peer: warm-up call, then one probe per run, cycling through the cube maps. Ours' batches
		// and the peer's runs alternate, so a load change on the machine hits both alike.
		const peerSH: number[][] = [];
		peerSH[ 0 ] = ( await call( page, 'peerProjectOne', 0 ) ).sh;
		const oursTimes: number[] = [], peerTimes: number[] = [];
		for ( let r = 0; r < Math.max( plan.oursBatches, plan.peerRuns( size ) ); r ++ ) {

			if ( r < plan.oursBatches ) oursTimes.push( ( await call( page, 'oursProjectBatch', plan.batchProbes, 'exact' ) ).ms / plan.batchProbes );
			if ( r >= plan.peerRuns( size ) ) continue;
			const index = ( r + 1 ) % plan.cubes;
			const result = await call( page, 'peerProjectOne', index );
			peerTimes.push( result.ms );
			peerSH[ index ] = result.sh;

		}

		const oursSummary = summarize( oursTimes ), peerSummary = summarize( peerTimes );
		log( `projection ${size}²: ours ${oursSummary.median.toFixed( 3 )} ms/probe, LightProbeGenerator ${peerSummary.median.toFixed( 1 )} ms/probe` );

		// Diagnostic: the same loop with synchronous read-back.
		const portTimes: number[] = [], portRead: number[] = [];
		let portSH: number[] | null = null;
		for ( let r = 0; r < plan.portRuns( size ); r ++ ) {

			const result = await call( page, 'peerPortSyncOne', 0 );
			portTimes.push( result.ms ); portRead.push( result.readMs );
			portSH = result.sh;

		}

		// Same SH? Every cube map both projected; differences relative to |L00| of that map.
		let l00Exact = 0, allExact = 0, l00Paper = 0, allPaper = 0, compared = 0;
		for ( let i = 0; i < plan.cubes; i ++ ) {

			if ( ! peerSH[ i ] ) continue;
			compared ++;
			const exact = compare( oursSH[ i ], peerSH[ i ] ), paper = compare( paperSH[ i ], peerSH[ i ] );
			l00Exact = Math.max( l00Exact, exact.l00 ); allExact = Math.max( allExact, exact.all );
			l00Paper = Math.max( l00Paper, paper.l00 ); allPaper = Math.max( allPaper, paper.all );

		}

		const portMatch = portSH ? compare( portSH, peerSH[ 0 ] ).all : NaN;
		const same = l00Exact < 3e-3 && allExact < 1e-2;
		const check = `${same ? 'same SH' : 'SH DIFFER'} as LightProbeGenerator on ${compared} maps: L00 Δ ≤ ${l00Exact.toExponential( 1 )}, all 27 Δ ≤ ${allExact.toExponential( 1 )} (rel. to L00; 'paper' weights: ${l00Paper.toExponential( 1 )} / ${allPaper.toExponential( 1 )})`;
		checks.push( `${size}²: ours (exact texel solid angles, the default) vs LightProbeGenerator, max over ${compared} cube maps, relative to |L00|: L00 ${l00Exact.toExponential( 2 )}, any coefficient ${allExact.toExponential( 2 )}; ours with solidAngle 'paper' (LightProbeGenerator's weights): L00 ${l00Paper.toExponential( 2 )}, any ${allPaper.toExponential( 2 )}; L00 of map 0 ours ${fmtRGB( oursSH[ 0 ] )} vs LightProbeGenerator ${fmtRGB( peerSH[ 0 ] )}; sync port vs LightProbeGenerator ${portMatch.toExponential( 1 )}` );

		const speedup = peerSummary.median / oursSummary.median;
		const targets: Target[] = [ { text: '≥ 10× faster', met: speedup >= 10 } ];
		if ( size === 128 ) targets.unshift( { text: '≤ 5 ms', met: oursSummary.median <= 5 } );
		rows.push( row( label, `ours: SHProjector, batch of ${plan.batchProbes} ÷ ${plan.batchProbes}`, oursSummary, {
			output: `${speedup.toFixed( 1 )}× faster`, status: check, peer: 'LightProbeGenerator', ratio: oursSummary.median / peerSummary.median, targets,
		} ) );
		rows.push( row( label, 'three LightProbeGenerator.fromCubeRenderTarget (awaited)', peerSummary, {
			output: size === 128 ? `filer: ~${FILER.generatorMsAt128} ms` : '',
		} ) );
		const port = summarize( portTimes );
		rows.push( row( label, 'diagnostic: its loop with sync read-back (bench port)', port, {
			output: `read-back ${summarize( portRead ).median.toFixed( 2 )} ms of it`,
		} ) );

	}

	await call( page, 'disposeCubes' );
	notes.push( 'SH check (1): ' + checks.join( '; ' ) + '.' );

}

/** Largest difference of L00 and of all 27 floats, relative to the largest |L00| channel of `b`. */
function compare( a: number[], b: number[] ): { l00: number, all: number } {

	const scale = Math.max( Math.abs( b[ 0 ] ), Math.abs( b[ 1 ] ), Math.abs( b[ 2 ] ), 1e-12 );
	let l00 = 0, all = 0;
	for ( let i = 0; i < 27; i ++ ) {

		const d = Math.abs( a[ i ] - b[ i ] ) / scale;
		if ( i < 3 ) l00 = Math.max( l00, d );
		all = Math.max( all, d );

	}

	return { l00, all };

}

function fmtRGB( sh: number[] ): string {

	return `(${sh.slice( 0, 3 ).map( ( v ) => v.toFixed( 4 ) ).join( ', ' )})`;

}

// ---------------------------------------------------------------------------------------------
// 2. Bake

async function bake( page: Page, rows: BenchRow[], log: ( message: string ) => void ): Promise<void> {

	const plan = PLAN.bake;
	const checks: string[] = [];

	for ( const size of plan.sizes ) {

		const label = `2 Bake 64 probes (4×4×4), ${size}² cubes (ms/bake)`;
		log( `bake ${size}²: warm-up` );
		await call( page, 'bakeOurs', size );
		await call( page, 'bakePeer', size, size >= 128 ? 4 : 64 );
		await call( page, 'renderCubesOnly', size );

		// Each run: ours, the grid, and the cube renders alone (the floor both share), back to
		// back in an order rotated per run, so the three see the same machine load.
		const oursTimes: number[] = [], peerTimes: number[] = [], renderTimes: number[] = [], floorPairs: number[] = [];
		let oursL00: number[] = [], peerL00: number[] = [];
		for ( let r = 0; r < plan.runs( size ); r ++ ) {

			let oursMs = 0, rendersMs = 0;
			for ( let k = 0; k < 3; k ++ ) {

				const which = ( k + r ) % 3;
				if ( which === 0 ) {

					const a = await call( page, 'bakeOurs', size );
					oursTimes.push( oursMs = a.ms ); oursL00 = a.l00;

				} else if ( which === 1 ) {

					const b = await call( page, 'bakePeer', size );
					peerTimes.push( b.ms ); peerL00 = b.l00;

				} else {

					renderTimes.push( rendersMs = ( await call( page, 'renderCubesOnly', size ) ).ms );

				}

			}

			floorPairs.push( oursMs / rendersMs );
			log( `bake ${size}²: ours ${oursMs.toFixed( 0 )} ms, LightProbeGridWebGL ${peerTimes[ r ].toFixed( 0 )} ms, cube renders ${rendersMs.toFixed( 0 )} ms` );

		}

		// Ours vs the grid, L00 per probe, relative to that probe's largest L00 channel.
		let worst = 0, worstProbe = - 1;
		for ( let p = 0; p < oursL00.length / 3; p ++ ) {

			const scale = Math.max( ...peerL00.slice( 3 * p, 3 * p + 3 ).map( Math.abs ), 1e-12 );
			for ( let c = 0; c < 3; c ++ ) {

				const d = Math.abs( oursL00[ 3 * p + c ] - peerL00[ 3 * p + c ] ) / scale;
				if ( d > worst ) { worst = d; worstProbe = p; }

			}

		}

		checks.push( `${size}²: max ${worst.toExponential( 2 )} (probe ${worstProbe})` );
		const ours = summarize( oursTimes ), peer = summarize( peerTimes ), renders = summarize( renderTimes );
		const speedup = peer.median / ours.median;
		const floor = ours.median / renders.median, pairedFloor = summarize( floorPairs ).median;
		const targets: Target[] = [ { text: '≤ 1.15× the cube renders', met: floor <= 1.15 } ];
		if ( size === 8 || size === 32 ) targets.push( { text: '≥ 1.3× faster', met: speedup >= 1.3 } );
		if ( size === 128 ) targets.push( { text: '≥ 6× faster', met: speedup >= 6 } );
		rows.push( row( label, 'ours: ProbeCapturer.capture', ours, {
			output: `${( ours.median / 64 ).toFixed( 2 )} ms/probe, ${speedup.toFixed( 2 )}× faster; ${floor.toFixed( 2 )}× the cube renders (paired ${pairedFloor.toFixed( 2 )}×)`,
			status: `L00 vs grid's: max Δ ${worst.toExponential( 1 )} rel.`, peer: 'LightProbeGridWebGL', ratio: ours.median / peer.median,
			ratios: [ { peer: 'cube renders', ratio: floor } ], targets,
		} ) );
		rows.push( row( label, 'three LightProbeGridWebGL.bake', peer, {
			output: `${( peer.median / 64 ).toFixed( 2 )} ms/probe (filer: ${FILER.gridMsPerProbe[ size ]})`,
		} ) );
		rows.push( row( label, 'diagnostic: the 64 cube renders alone (CubeCamera.update)', renders, {
			output: `${( renders.median / 64 ).toFixed( 2 )} ms/probe`,
		} ) );

	}

	notes.push( 'SH check (2): ours\' L00 vs LightProbeGridWebGL\'s L00 (read from its atlas) per probe, relative to the probe\'s largest L00 channel — ' + checks.join( '; ' ) + '. (Different texel weights: exact solid angles vs the grid\'s normalised (r·n)/|r|³; ~1e-3 at 8², less above.)' );

}

// ---------------------------------------------------------------------------------------------
// 3. Frames

type Variant = 'none' | 'global' | 'grid' | 'ours' | 'oursGradients';

async function frames( page: Page, rows: BenchRow[], log: ( message: string ) => void ): Promise<void> {

	const plan = PLAN.frames;
	log( `frames: capturing the volume and baking the grid at ${plan.cubeSize}², ${plan.spheres} spheres per variant` );
	const setup = await call( page, 'setupFrames', plan.spheres, plan.cubeSize );
	const variants: Variant[] = [ 'none', 'global', 'grid', 'ours', 'oursGradients' ];
	const stats: Record<string, { mean: number[], drawCalls: number, triangles: number }> = {};
	for ( const variant of variants ) stats[ variant ] = await call( page, 'frameStats', variant );

	// Rounds of interleaved frames (each step: one frame of every variant, order rotating).
	const medians: Record<Variant, number[]> = { none: [], global: [], grid: [], ours: [], oursGradients: [] };
	const pairs: number[] = [], gridPairs: number[] = [], globalPairs: number[] = [], updates: number[] = [];
	const gradientPairs: number[] = [], gradientUpdates: number[] = [];
	for ( let round = 0; round < plan.rounds; round ++ ) {

		const times = await call( page, 'runFrames', plan.warmUp, plan.frames );
		for ( const v of variants ) medians[ v ].push( summarize( times[ v ] ).median );
		updates.push( ...times.oursUpdate );
		gradientUpdates.push( ...times.gradientUpdate );
		// Per step ratios: the frames of one step ran back to back, under the same load.
		times.ours.forEach( ( t, i ) => {

			pairs.push( t / times.global[ i ] );
			gradientPairs.push( times.oursGradients[ i ] / t );
			globalPairs.push( times.global[ i ] / times.none[ i ] );
			gridPairs.push( times.grid[ i ] / times.none[ i ] );

		} );
		log( `frames round ${round + 1}/${plan.rounds}: ` + variants.map( ( v ) => `${v} ${medians[ v ][ round ].toFixed( 1 )}` ).join( ', ' ) + ' ms' );

	}

	const s = Object.fromEntries( variants.map( ( v ) => [ v, summarize( medians[ v ] ) ] ) ) as Record<Variant, Summary>;
	const paired = ( values: number[] ) => summarize( values ).median.toFixed( 2 );
	const label = `3 Frame, ${plan.spheres} moving spheres, 1280×720 (ms/frame)`;
	const seen = ( v: Variant ) => `mean RGB ${stats[ v ].mean.map( ( c ) => c.toFixed( 1 ) ).join( '/' )}`;
	rows.push( row( label, 'no probe (baseline)', s.none, { status: seen( 'none' ), output: `${stats.none.drawCalls} draw calls` } ) );
	rows.push( row( label, 'one global THREE.LightProbe', s.global, {
		status: seen( 'global' ), peer: 'no probe', ratio: s.global.median / s.none.median, output: `paired ${paired( globalPairs )}×; filer: ${FILER.frameGlobal}×`,
	} ) );
	rows.push( row( label, 'three LightProbeGridWebGL in scene (per pixel, reference)', s.grid, {
		status: seen( 'grid' ), peer: 'no probe', ratio: s.grid.median / s.none.median, output: `paired ${paired( gridPairs )}×; filer: ${FILER.frameGrid}×`,
	} ) );
	const oursRatio = s.ours.median / s.global.median;
	rows.push( row( label, 'ours: LightProbeVolume.update() + render', s.ours, {
		status: seen( 'ours' ), peer: 'global LightProbe', ratio: oursRatio,
		output: `paired ${paired( pairs )}×; ${( s.ours.median / s.none.median ).toFixed( 2 )}× no probe; update() ${summarize( updates ).median.toFixed( 2 )} ms of it`,
		targets: [ { text: '≤ 1.05× global LightProbe', met: oursRatio <= 1.05 } ],
	} ) );
	const gradientRatio = summarize( gradientPairs ).median;
	rows.push( row( label, 'ours with gradient probes: update() + render', s.oursGradients, {
		status: seen( 'oursGradients' ), peer: 'ours without gradients', ratio: s.oursGradients.median / s.ours.median,
		output: `paired ${gradientRatio.toFixed( 3 )}×; update() ${summarize( gradientUpdates ).median.toFixed( 2 )} ms of it`,
		targets: [ { text: '≤ 1.1× without gradients (paired)', met: gradientRatio <= 1.1 } ],
	} ) );
	notes.push( `Frames (3): ${setup.sphereTriangles} triangles per sphere, ${stats.none.drawCalls} draw calls per frame (spheres outside the view are culled), ${setup.tetrahedra} tetrahedra in the volume, ${setup.programs} shader programs in the renderer after compiling the five scenes. "paired": median over all timed steps of the ratio of two variants' frames rendered back to back in the same step (robust to load changes). Mean canvas RGB per variant (Check column) shows the probes light the spheres: ours close to the global probe and the grid, no probe darker.` );

}

function row( caseName: string, subject: string, summary: Summary, extra: Partial<BenchRow> = {} ): BenchRow {

	return { case: caseName, subject, unit: 'ms', median: summary.median, min: summary.min, max: summary.max, runs: summary.runs, ...extra };

}
