/**
 * The paper's claim, measured: `npm run experiment -- --scene <basic|sponza|sibenik> [--out DIR]`.
 *
 * In headless Chromium (scripts/experiment/page.ts builds the scene with its own scene module and
 * captures SH9 with one `ProbeCapturer`), for one scene (measure.ts):
 *
 * 1. Ground truths: M points (default 500) per seed (`--seed`, `--check-seeds`) drawn uniformly in
 *    the scene module's grid box and kept when in open space (samples.ts), each captured like a probe.
 * 2. Layouts (buildLayouts.ts), each captured with the same capturer and settings or fitted: the grid
 *    curves (several grid sizes, trilinear and tetrahedralized; fitted), the scene module's
 *    hand-made layout (captured, fitted), and automatic layouts chosen from a dense candidate set
 *    (a jittered grid and vertex candidates, seed `--dense-seed`) — captured cuts of `reduceProbes`
 *    and of a mean-greedy selection, and `reduceProbes` re-fitting at every insertion, without and
 *    with swaps, plain and with gradients, over the whole volume and where characters go. The fits
 *    use the dense set and extra fit points (`--fit-points`, seed `--fit-seed`), never a ground truth.
 * 3. Each layout's error against every truth with the library's `irradianceError` (evaluate.ts), the
 *    verdict and the targets (targets.ts), DIR/<scene>.json, DIR/<scene>.md and the plot
 *    DIR/<scene>.svg / .png (report.ts, plot.ts).
 *
 * With `--save-captures` every capture is kept in DIR/<scene>.captures.json and reused by later runs;
 * `--offline` re-evaluates from it without the browser (seconds instead of minutes).
 */

import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import { join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { assetsFolder } from '../assetsPlugin.mjs';
import { startSession } from './browser.js';
import { CaptureSource } from './CaptureSource.js';
import { CaptureStore } from './captureStore.js';
import { USAGE, parseArguments, type ExperimentOptions } from './cli.js';
import { CONFIGS } from './config.js';
import { measure } from './measure.js';
import { plotSVG } from './plot.js';
import { layoutTable, markdownReport, validateResult } from './report.js';

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );

async function main(): Promise<number> {

	let options: ExperimentOptions | 'help';
	try {

		options = parseArguments( process.argv.slice( 2 ) );

	} catch ( error ) {

		console.error( `experiment: ${( error as Error ).message}\n\n${USAGE}` );
		return 2;

	}

	if ( options === 'help' ) {

		console.log( USAGE );
		return 0;

	}

	const config = CONFIGS[ options.scene ];
	const capturesFile = options.captures !== null ? resolve( ROOT, options.captures ) : null;
	if ( options.offline && ( capturesFile === null || ! existsSync( capturesFile ) ) ) {

		console.error( `experiment: --offline needs the saved captures ${capturesFile}, which do not exist; run once with --save-captures.` );
		return 3;

	}

	const missing = options.offline ? [] : config.assets.filter( ( file ) => ! existsSync( join( assetsFolder, file ) ) );
	if ( missing.length > 0 ) {

		console.error( `experiment: the ${options.scene} scene needs ${missing.join( ', ' )} in the asset folder ${assetsFolder}, which ${missing.length > 1 ? 'are' : 'is'} missing. Get ${config.source} of that folder, or point CAPTURE_LIGHTING_ASSETS at a folder that has them.` );
		return 3;

	}

	const runStart = performance.now();
	const log = ( message: string ) => console.log( `[${( ( performance.now() - runStart ) / 1000 ).toFixed( 0 ).padStart( 4 )} s] ${message}` );
	const load = [ loadavg()[ 0 ] ];
	const store = capturesFile ? CaptureStore.read( capturesFile, options.scene ) : new CaptureStore( options.scene );
	const source = new CaptureSource( store, {
		offline: options.offline, log,
		saved: capturesFile ? () => store.write( capturesFile ) : undefined,
		start: async () => {

			const session = await startSession( log );
			log( `${session.browserVersion}; loading ${options.scene}` );
			return session;

		},
	} );
	try {

		const measured = await measure( source, options, log, runStart );
		if ( capturesFile && source.newCaptures > 0 ) {

			store.write( capturesFile );
			log( `saved ${store.captures.length} captures in ${relative( process.cwd(), capturesFile )}` );

		}

		if ( ! measured ) return 0;
		const { result } = measured;
		load.push( loadavg()[ 0 ] );
		result.environment.loadAverage = load.map( ( v ) => v.toFixed( 2 ) ).join( ' → ' );
		const problems = validateResult( result );
		if ( problems.length > 0 ) throw new Error( `the result has the wrong shape: ${problems.join( '; ' )}` );
		const out = resolve( ROOT, options.out );
		mkdirSync( out, { recursive: true } );
		const svg = plotSVG( result, { title: `${options.scene[ 0 ].toUpperCase() + options.scene.slice( 1 )}: irradiance error vs probe count (${result.samples} ground-truth points)` } );
		writeFileSync( join( out, `${options.scene}.svg` ), svg );
		const png = await source.rasterize( svg, 1200, 640, join( out, `${options.scene}.png` ) );
		if ( ! png ) log( 'offline: no PNG drawn (the SVG is written)' );
		writeFileSync( join( out, `${options.scene}.json` ), JSON.stringify( result, null, '\t' ) + '\n' );
		writeFileSync( join( out, `${options.scene}.md` ), markdownReport( result, `${options.scene}.png` ) );
		console.log( `\n${layoutTable( result.layouts.filter( ( row ) => ! row.fitted ) )}\n\n${result.verdict.text}\n` );
		for ( const check of result.targets ) console.log( `${check.holds ? 'holds' : 'fails'}: ${check.text}: ${check.layout} ${check.value !== null ? check.value.toFixed( 4 ) : '–'}` );
		log( `wrote ${[ 'json', 'md', ...( png ? [ 'png' ] : [] ), 'svg' ].map( ( ext ) => relative( process.cwd(), join( out, `${options.scene}.${ext}` ) ) ).join( ', ' )}` );
		return 0;

	} catch ( error ) {

		// Whatever was captured before the failure is kept for the next run.
		if ( capturesFile && source.newCaptures > 0 ) store.write( capturesFile );
		console.error( `experiment: ${( error as Error ).stack ?? error}` );
		return 1;

	} finally {

		await source.close();

	}

}

process.exitCode = await main();
