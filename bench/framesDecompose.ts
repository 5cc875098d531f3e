/**
 * Diagnostic, not a bench row: where the frame time of 500 moving probe-lit spheres goes, beside
 * one global THREE.LightProbe (the capture bench's part 3, issue 16), on its own page
 * (bench/pages/frames.ts). Variants' frames interleave (order rotated per step, as the capture
 * bench does); printed per variant: median frame, the paired ratio to the global probe (median of
 * the per-step ratios, and the range of the per-round medians), WebGL calls of one frame (uniform
 * uploads by function), CPU seconds of Chromium's GPU process (SwiftShader) and renderer process
 * (JavaScript) per frame with the variant alone, and each image against the first ours variant.
 * The GLSL variants replace the patched shader's probe function, to time alternatives side by side.
 *
 *   node --import tsx bench/framesDecompose.ts [--variants=global,ours,oursVertex,…] [--rounds=6] [--frames=15] [--cpu]
 */

import { cpuByType } from './cpuSnapshot.js';
import { fileURLToPath } from 'node:url';
import { launchChromium } from '../cli/chromium.js';
import { libraryAliases } from '../cli/libraryAliases.js';
import type { FrameVariant, FramesBenchApi } from './pages/frames.js';

type Page = import( 'puppeteer-core' ).Page;

const BENCH_DIR = fileURLToPath( new URL( '.', import.meta.url ) );

// Probe functions to time in place of the library's (each keeps its name; its argument is the
// view-space normal). LEGACY declares what the library's shader before issue 16 read.
const LEGACY = 'uniform mat4 probeVolumeMatrices[ 3 ];\nuniform float probeVolumeIntensity;\n';
const FUNCTIONS: Record<string, string> = {
	// Before issue 16: the world normal from the view-space one, then nᵀMn by full matrix products.
	matrix: /* glsl */`${LEGACY}
vec3 probeVolumeIrradiance( const in vec3 viewNormal ) {
	vec4 n = vec4( normalize( ( vec4( viewNormal, 0.0 ) * viewMatrix ).xyz ), 1.0 );
	return probeVolumeIntensity * vec3(
		dot( n, probeVolumeMatrices[ 0 ] * n ), dot( n, probeVolumeMatrices[ 1 ] * n ), dot( n, probeVolumeMatrices[ 2 ] * n ) );
}`,
	// The world normal alone (its transform from view space and normalisation), one matrix entry as scale.
	worldNormalOnly: /* glsl */`${LEGACY}
vec3 probeVolumeIrradiance( const in vec3 viewNormal ) {
	return probeVolumeMatrices[ 0 ][ 3 ][ 3 ] * normalize( ( vec4( viewNormal, 0.0 ) * viewMatrix ).xyz );
}`,
	// Uploads kept (the coefficients read), no per-pixel arithmetic: what the uniforms alone cost.
	uploadOnly: /* glsl */`
vec3 probeVolumeIrradiance( const in vec3 viewNormal ) {
	return probeVolumeViewIrradiance[ 0 ] + probeVolumeViewIrradiance[ 8 ];
}`,
	// No probe term at all (its uniforms optimised away): the patched shader's floor.
	zero: /* glsl */`
vec3 probeVolumeIrradiance( const in vec3 viewNormal ) {
	return vec3( 0.0 );
}`,
};

/** Variant names: none, global, ours, oursVertex, ours@<function>, oursVertex@<function>, oursFrozen (no update()). */
function parseVariant( name: string ): FrameVariant {

	if ( name === 'none' || name === 'global' ) return { name, probe: name };
	const [ base, fn ] = name.split( '@' );
	if ( base !== 'ours' && base !== 'oursVertex' && base !== 'oursFrozen' ) throw new Error( `framesDecompose: unknown variant ${name}` );
	if ( fn !== undefined && FUNCTIONS[ fn ] === undefined ) throw new Error( `framesDecompose: unknown function ${fn}; known: ${Object.keys( FUNCTIONS ).join( ', ' )}` );
	return { name, probe: 'ours', perVertex: base === 'oursVertex', noUpdate: base === 'oursFrozen', fragment: fn === undefined ? undefined : FUNCTIONS[ fn ] };

}

async function call<K extends keyof FramesBenchApi>(
	page: Page, name: K, ...args: Parameters<FramesBenchApi[ K ]>
): Promise<Awaited<ReturnType<FramesBenchApi[ K ]>>> {

	return page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

		const api = ( window as unknown as { framesBench: Record<string, ( ...a: unknown[] ) => unknown> } ).framesBench;
		return api[ fn ]( ...fnArgs );

	}, name, args as unknown[] ) as Promise<Awaited<ReturnType<FramesBenchApi[ K ]>>>;

}

function median( values: number[] ): number {

	const sorted = [ ...values ].sort( ( a, b ) => a - b );
	const mid = sorted.length >> 1;
	return sorted.length % 2 ? sorted[ mid ] : ( sorted[ mid - 1 ] + sorted[ mid ] ) / 2;

}

function option( name: string, fallback: string ): string {

	const found = process.argv.find( ( arg ) => arg.startsWith( `--${name}=` ) );
	return found ? found.slice( name.length + 3 ) : fallback;

}

async function main(): Promise<void> {

	const names = option( 'variants', 'global,ours,oursVertex' ).split( ',' );
	if ( ! names.includes( 'global' ) ) names.unshift( 'global' );
	const variants = names.map( parseVariant );
	const rounds = Number( option( 'rounds', '6' ) ), frames = Number( option( 'frames', '15' ) ), warmUp = Number( option( 'warmup', '2' ) );
	const { createServer } = await import( 'vite' );
	const server = await createServer( {
		configFile: false, root: BENCH_DIR + 'pages', cacheDir: BENCH_DIR + 'build/vite-cache', logLevel: 'warn',
		resolve: { alias: libraryAliases( BENCH_DIR + '..' ) }, optimizeDeps: { include: [ 'three' ] },
		server: { host: '127.0.0.1', port: 5197, strictPort: false, hmr: false, watch: null },
	} );
	await server.listen();
	const viewport = { width: 1280, height: 720, deviceScaleFactor: 1 };
	const browser = await launchChromium( { protocolTimeout: 1_800_000, defaultViewport: viewport } );
	const root = browser.process()!.pid!;
	try {

		const page = await browser.newPage();
		page.on( 'console', ( message ) => {

			if ( message.type() === 'error' || message.type() === 'warn' ) console.log( `console.${message.type()}: ${message.text()}` );

		} );
		page.on( 'pageerror', ( error ) => console.log( `page error: ${( error as Error ).message}` ) );
		await page.goto( `${server.resolvedUrls!.local[ 0 ]}frames.html`, { waitUntil: 'load' } );
		const ready = () => ( window as unknown as { framesBenchReady?: boolean } ).framesBenchReady === true;
		await page.waitForFunction( ready, { timeout: 120_000 } );
		console.log( 'setup', JSON.stringify( await call( page, 'setup', variants ) ) );

		const g = names.indexOf( 'global' );
		const lists = (): number[][] => variants.map( () => [] );
		const all = lists(), ratios = lists(), roundRatios = lists();
		for ( let r = 0; r < rounds; r ++ ) {

			const times = await call( page, 'runFrames', warmUp, frames );
			for ( let v = 0; v < variants.length; v ++ ) {

				all[ v ].push( ...times[ v ] );
				const paired = times[ v ].map( ( t, i ) => t / times[ g ][ i ] );
				ratios[ v ].push( ...paired );
				roundRatios[ v ].push( median( paired ) );

			}

			console.log( `round ${r + 1}: ${names.map( ( n, v ) => `${n} ${median( times[ v ] ).toFixed( 1 )} ms (${roundRatios[ v ][ r ].toFixed( 3 )}×)` ).join( ' | ' )}` );

		}

		const firstOurs = variants.findIndex( ( v ) => v.probe === 'ours' );
		for ( let v = 0; v < variants.length; v ++ ) {

			const counts = await call( page, 'countGL', v );
			const uniforms = Object.entries( counts ).filter( ( [ k ] ) => k.startsWith( 'uniform' ) ).map( ( [ k, n ] ) => `${k} ${n}` ).join( ', ' );
			const total = Object.entries( counts ).filter( ( [ k ] ) => k !== 'drawCalls' ).reduce( ( a, [ , n ] ) => a + n, 0 );
			const image = firstOurs >= 0 ? await call( page, 'compare', firstOurs, v ) : null;
			const imageText = image ? `; vs ${names[ firstOurs ]}: max Δ ${image.max}/255 on ${image.pixels} px, mean RGB ${image.mean.map( ( m ) => m.toFixed( 1 ) ).join( '/' )}` : '';
			console.log( `${names[ v ]}: median ${median( all[ v ] ).toFixed( 1 )} ms, paired ${median( ratios[ v ] ).toFixed( 3 )}× global `
				+ `(rounds ${Math.min( ...roundRatios[ v ] ).toFixed( 3 )}–${Math.max( ...roundRatios[ v ] ).toFixed( 3 )}); `
				+ `${counts.drawCalls} draws, ${total} GL calls (${uniforms})${imageText}` );

		}

		const cpuRounds = Number( option( 'cpu-rounds', '0' ) );
		if ( cpuRounds > 0 ) {

			// CPU seconds per frame, each variant alone for a few frames, variants rotated per round:
			// the work each frame costs, less inflated than wall time by other processes' load.
			const n = 4, gpu: number[][] = variants.map( () => [] ), js: number[][] = variants.map( () => [] );
			for ( let r = 0; r < cpuRounds; r ++ ) {

				for ( let k = 0; k < variants.length; k ++ ) {

					const v = ( k + r ) % variants.length;
					await call( page, 'runOne', v, 1 );
					const before = cpuByType( root );
					await call( page, 'runOne', v, n );
					const after = cpuByType( root );
					gpu[ v ].push( 1000 * ( after.gpu - before.gpu ) / n );
					js[ v ].push( 1000 * ( after.renderer - before.renderer ) / n );

				}

			}

			for ( let v = 0; v < variants.length; v ++ ) {

				const paired = gpu[ v ].map( ( t, i ) => ( t + js[ v ][ i ] ) / ( gpu[ g ][ i ] + js[ g ][ i ] ) );
				console.log( `${names[ v ]} CPU per frame (${cpuRounds} rounds of ${n}): GPU process ${median( gpu[ v ] ).toFixed( 1 )} ms, `
					+ `renderer ${median( js[ v ] ).toFixed( 1 )} ms; GPU + renderer paired ${median( paired ).toFixed( 3 )}× global` );

			}

		}

		if ( process.argv.includes( '--cpu' ) ) {

			const n = 20;
			for ( let v = 0; v < variants.length; v ++ ) {

				const before = cpuByType( root );
				const ms = await call( page, 'runOne', v, n );
				const after = cpuByType( root );
				console.log( `${names[ v ]} alone, ${n} frames: ${( ms / n ).toFixed( 1 )} ms/frame wall; GPU process ${( 1000 * ( after.gpu - before.gpu ) / n ).toFixed( 1 )} ms, `
					+ `renderer ${( 1000 * ( after.renderer - before.renderer ) / n ).toFixed( 1 )} ms CPU per frame` );

			}

		}

	} finally {

		await browser.close().catch( () => undefined );
		await server.close().catch( () => undefined );

	}

}

await main();
