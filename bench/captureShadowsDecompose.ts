/**
 * Diagnostic, not a bench row: where the extra time of a probe capture with shadows goes, on the
 * page of part 4 of the capture bench (bench/pages/captureShadows.ts). Per scene it times, in
 * alternation, captures without shadows, with the maps drawn at the first face (ProbeCapturer's
 * way) and with the maps drawn beforehand and never redrawn (the faces' shading alone); the shadow
 * map render by itself; the face resolution and the shadow map size varied; and counts the WebGL
 * calls of each variant. CPU seconds are split into the GPU process (SwiftShader) and the renderer
 * process (JavaScript, three.js).
 *
 *   node --import tsx bench/captureShadowsDecompose.ts [basic] [sponza]
 */

import { cpuByType } from './cpuSnapshot.js';
import { fileURLToPath } from 'node:url';
import { launchChromium } from '../cli/chromium.js';
import { libraryAliases } from '../cli/libraryAliases.js';
import { assetsPlugin } from '../scripts/assetsPlugin.mjs';
import { maxDifference } from './captureShadows.js';
import type { CaptureShadowsBenchApi } from './pages/captureShadows.js';

type Page = import( 'puppeteer-core' ).Page;
type Mode = 'none' | 'once' | 'frozen';

const BENCH_DIR = fileURLToPath( new URL( '.', import.meta.url ) );
const MODES: Mode[] = [ 'none', 'once', 'frozen' ];

async function call<K extends keyof CaptureShadowsBenchApi>(
	page: Page, name: K, ...args: Parameters<CaptureShadowsBenchApi[ K ]>
): Promise<Awaited<ReturnType<CaptureShadowsBenchApi[ K ]>>> {

	return page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

		const api = ( window as unknown as { captureShadowsBench: Record<string, ( ...a: unknown[] ) => unknown> } ).captureShadowsBench;
		return api[ fn ]( ...fnArgs );

	}, name, args as unknown[] ) as Promise<Awaited<ReturnType<CaptureShadowsBenchApi[ K ]>>>;

}

function median( values: number[] ): number {

	const sorted = [ ...values ].sort( ( a, b ) => a - b );
	const mid = sorted.length >> 1;
	return sorted.length % 2 ? sorted[ mid ] : ( sorted[ mid - 1 ] + sorted[ mid ] ) / 2;

}

/** The three modes, alternating (order rotated per run); median wall ms and CPU s (GPU / renderer) per mode. */
async function modes( page: Page, root: number, scene: string, size: number, runs: number, probes: number ): Promise<void> {

	for ( const mode of MODES ) await call( page, 'captureLoop', scene, size, mode, probes ); // warm-up
	const ms: Record<string, number[]> = {}, gpu: Record<string, number[]> = {}, js: Record<string, number[]> = {};
	const sh: Record<string, number[]> = {};
	for ( let r = 0; r < runs; r ++ ) {

		for ( let k = 0; k < MODES.length; k ++ ) {

			const mode = MODES[ ( k + r ) % MODES.length ];
			const before = cpuByType( root );
			const result = await call( page, 'captureLoop', scene, size, mode, probes );
			const after = cpuByType( root );
			( ms[ mode ] ??= [] ).push( result.ms );
			( gpu[ mode ] ??= [] ).push( after.gpu - before.gpu );
			( js[ mode ] ??= [] ).push( after.renderer - before.renderer );
			sh[ mode ] = result.sh;

		}

	}

	const base = median( ms.none );
	const line = MODES.map( ( mode ) => `${mode} ${median( ms[ mode ] ).toFixed( 0 )} ms (${( median( ms[ mode ] ) / base ).toFixed( 2 )}×; `
		+ `GPU proc ${median( gpu[ mode ] ).toFixed( 2 )} s, renderer ${median( js[ mode ] ).toFixed( 2 )} s)` ).join( ' | ' );
	console.log( `${scene} ${size}²${probes > 0 ? ` ${probes} probes` : ''}, ${runs} runs: ${line}; once vs frozen SH max Δ ${maxDifference( sh.once, sh.frozen ).toExponential( 1 )}` );

}

async function main(): Promise<void> {

	const wanted = process.argv.slice( 2 );
	const scenes = wanted.length ? wanted : [ 'basic', 'sponza' ];
	const { createServer } = await import( 'vite' );
	const server = await createServer( {
		configFile: false, root: BENCH_DIR + 'pages', cacheDir: BENCH_DIR + 'build/vite-cache', logLevel: 'warn',
		resolve: { alias: libraryAliases( BENCH_DIR + '..' ) }, plugins: [ assetsPlugin() ],
		optimizeDeps: { include: [ 'three', 'three/addons/loaders/MTLLoader.js', 'three/addons/loaders/OBJLoader.js' ] },
		server: { host: '127.0.0.1', port: 5198, strictPort: false, hmr: false, watch: null },
	} );
	await server.listen();
	const viewport = { width: 1280, height: 720, deviceScaleFactor: 1 };
	const browser = await launchChromium( { protocolTimeout: 900_000, defaultViewport: viewport } );
	const root = browser.process()!.pid!;
	try {

		const page = await browser.newPage();
		page.on( 'console', ( message ) => {

			if ( message.type() === 'error' || message.type() === 'warn' ) console.log( `console.${message.type()}: ${message.text()}` );

		} );
		await page.goto( `${server.resolvedUrls!.local[ 0 ]}captureShadows.html`, { waitUntil: 'load' } );
		const ready = () => ( window as unknown as { captureShadowsBenchReady?: boolean } ).captureShadowsBenchReady === true;
		await page.waitForFunction( ready, { timeout: 120_000 } );
		console.log( JSON.stringify( await call( page, 'info' ) ) );
		for ( const scene of scenes ) {

			const loaded = scene === 'basic' ? await call( page, 'loadBasic' ) : await call( page, 'loadSponza', '/assets/' );
			console.log( scene, JSON.stringify( loaded ), JSON.stringify( await call( page, 'sceneStats', scene ) ) );
			const probes = scene === 'basic' ? - 1 : 12;
			const defaultMap = scene === 'basic' ? 512 : 2048;
			for ( const size of [ 8, 32, 128 ] ) await modes( page, root, scene, size, scene === 'basic' ? 5 : 3, probes );
			for ( const map of [ 256, 512, 1024, 2048 ] ) {

				await call( page, 'setMapSize', scene, map );
				const render = await call( page, 'shadowMapRender', scene, 5 );
				console.log( `${scene} map ${map}²: one shadow map render ${render.toFixed( 1 )} ms` );
				await modes( page, root, scene, 32, 3, probes );

			}

			await call( page, 'setMapSize', scene, defaultMap );
			for ( const mode of MODES ) {

				const counts = await call( page, 'countGL', scene, 32, mode, probes );
				const total = Object.values( counts ).reduce( ( a, b ) => a + b, 0 );
				const top = Object.entries( counts ).sort( ( a, b ) => b[ 1 ] - a[ 1 ] ).slice( 0, 14 ).map( ( [ k, v ] ) => `${k} ${v}` ).join( ', ' );
				console.log( `${scene} 32² GL calls, ${mode}: ${total} — ${top}` );

			}

		}

	} finally {

		await browser.close().catch( () => undefined );
		await server.close().catch( () => undefined );

	}

}

await main();
