/**
 * The paper's claim, measured: `npm run experiment -- --scene <basic|sponza|sibenik> [--out DIR]`.
 *
 * In headless Chromium (scripts/experiment/page.ts builds the scene with its own scene module and
 * captures SH9 with one `ProbeCapturer`), for one scene:
 *
 * 1. Ground truth: M points (default 500, seed `--seed`) drawn uniformly in the scene module's grid
 *    box and kept when in open space (samples.ts), each captured like a probe.
 * 2. Layouts, each captured with the same capturer and settings: the grid curves (several grid
 *    sizes over the box, trilinear and the same probes tetrahedralized), the scene module's
 *    hand-made layout, and automatic layouts: `reduceProbes` on a dense candidate set (a jittered
 *    grid and vertex candidates, seed `--dense-seed`, captured separately — never the ground
 *    truth), cut at several counts.
 * 3. Each layout's error against the truth with the library's `irradianceError` (evaluate.ts), the
 *    verdict, DIR/<scene>.json, DIR/<scene>.md and the plot DIR/<scene>.png (report.ts).
 */

import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { placeGrid, reduceProbes } from '../../src/index.js';
import { GridInterpolator } from '../../src/math.js';
import { assetsFolder } from '../assetsPlugin.mjs';
import { startSession, fromBase64, type ExperimentSession } from './browser.js';
import { USAGE, parseArguments, type ExperimentOptions } from './cli.js';
import { CONFIGS } from './config.js';
import { evaluateLayout, gridValidSamples, subsetPositions, subsetSH, verdictOf, type AutoMethod, type EvaluatedLayout, type LayoutResult } from './evaluate.js';
import { markdownReport, plotSVG, validateResult, layoutTable, type ExperimentResult } from './report.js';
import { selectByMeanError } from './selectByMeanError.js';
import { OpenSpaceTest, OPEN, jitteredGrid, keepOpen, sampleOpenSpace, thinIndices, vertexCandidates } from './samples.js';

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
	const missing = config.assets.filter( ( file ) => ! existsSync( join( assetsFolder, file ) ) );
	if ( missing.length > 0 ) {

		console.error( `experiment: the ${options.scene} scene needs ${missing.join( ', ' )} in the asset folder ${assetsFolder}, which ${missing.length > 1 ? 'are' : 'is'} missing. Get ${config.source} of that folder, or point CAPTURE_LIGHTING_ASSETS at a folder that has them.` );
		return 3;

	}

	const runStart = performance.now();
	const log = ( message: string ) => console.log( `[${( ( performance.now() - runStart ) / 1000 ).toFixed( 0 ).padStart( 4 )} s] ${message}` );
	const load = [ loadavg()[ 0 ] ];
	let session: ExperimentSession | null = null;
	try {

		session = await startSession( log );
		log( `${session.browserVersion}; loading ${options.scene}` );
		const scene = await session.load( options.scene );
		log( `${scene.info.renderer}; ${scene.info.triangles} triangles` );
		const result = await measure( session, scene, options, log, runStart );
		load.push( loadavg()[ 0 ] );
		result.environment.loadAverage = load.map( ( v ) => v.toFixed( 2 ) ).join( ' → ' );

		const problems = validateResult( result );
		if ( problems.length > 0 ) throw new Error( `the result has the wrong shape: ${problems.join( '; ' )}` );
		const out = resolve( ROOT, options.out );
		mkdirSync( out, { recursive: true } );
		const svg = plotSVG( result, { title: `${options.scene[ 0 ].toUpperCase() + options.scene.slice( 1 )}: irradiance error vs probe count (${result.samples} ground-truth points)` } );
		writeFileSync( join( out, `${options.scene}.svg` ), svg );
		await session.rasterize( svg, 1200, 560, join( out, `${options.scene}.png` ) );
		writeFileSync( join( out, `${options.scene}.json` ), JSON.stringify( result, null, '\t' ) + '\n' );
		writeFileSync( join( out, `${options.scene}.md` ), markdownReport( result, `${options.scene}.png` ) );
		console.log( `\n${layoutTable( result.layouts )}\n\n${result.verdict.text}\n` );
		log( `wrote ${[ 'json', 'md', 'png', 'svg' ].map( ( ext ) => relative( process.cwd(), join( out, `${options.scene}.${ext}` ) ) ).join( ', ' )}` );
		return 0;

	} catch ( error ) {

		console.error( `experiment: ${( error as Error ).stack ?? error}` );
		return 1;

	} finally {

		await session?.close();

	}

}

async function measure( session: ExperimentSession, scene: Awaited<ReturnType<ExperimentSession[ 'load' ]>>, options: ExperimentOptions, log: ( message: string ) => void, runStart: number ): Promise<ExperimentResult> {

	const config = CONFIGS[ options.scene ];
	const box = { min: scene.grid.min, max: scene.grid.max };
	const capture = { resolution: options.resolution, near: config.near, far: config.far };
	const triangles = fromBase64( scene.triangles, Float32Array ), sides = fromBase64( scene.sides, Int8Array );
	const open = new OpenSpaceTest( triangles, sides, { minDistance: config.minDistance, maxSky: config.maxSky } );
	const notOpen = ( positions: ArrayLike<number> ) => {

		let n = 0;
		for ( let i = 0; i < positions.length; i += 3 ) {

			if ( open.classify( positions[ i ], positions[ i + 1 ], positions[ i + 2 ] ) !== OPEN ) n ++;

		}

		return n;

	};

	// 1. Ground truth.
	const truth = sampleOpenSpace( open, box, options.samples, options.seed );
	log( `ground truth: ${options.samples} points in open space (${truth.drawn} drawn; ${truth.near} near a surface, ${truth.inside} inside geometry, ${truth.outside} outside the interior)` );
	const truthCapture = await session.capture( truth.positions, capture, 'ground truth' );

	// 2. The dense candidate set and its reduction.
	const gridCandidates = keepOpen( open, jitteredGrid( box, config.denseSpacing, 0.35, options.denseSeed ) ).positions;
	const vertexPoints = keepOpen( open, vertexCandidates( triangles, sides, box, config.vertexOffset, config.vertexSpacing ) ).positions;
	const all = new Float64Array( gridCandidates.length + vertexPoints.length );
	all.set( gridCandidates );
	all.set( vertexPoints, gridCandidates.length );
	const kept = thinIndices( all, config.denseMinSpacing );
	const densePositions = subsetPositions( all, kept );
	const fromGrid = kept.filter( ( i ) => 3 * i < gridCandidates.length ).length;
	log( `dense candidates: ${kept.length} (${fromGrid} jittered grid, ${kept.length - fromGrid} vertex)` );
	const denseCapture = await session.capture( densePositions, capture, 'dense candidates' );
	const autoCounts = config.autoCounts.filter( ( n ) => n <= kept.length );
	const reduceStart = performance.now();
	const reduction = reduceProbes( densePositions, denseCapture.sh, { targetCount: Math.max( ...autoCounts ), seed: options.denseSeed } );
	const reduceMs = performance.now() - reduceStart;
	log( `reduceProbes: ${kept.length} → ${reduction.order.length} in ${( reduceMs / 1000 ).toFixed( 1 )} s` );

	// 3. Layouts.
	const layouts: EvaluatedLayout[] = [];
	for ( const counts of config.grids ) {

		const positions = placeGrid( box.min, box.max, counts );
		const { sh, ms } = await session.capture( positions, capture, `grid ${counts.join( 'x' )}` );
		const grid = { min: box.min, max: box.max, counts };
		const outside = notOpen( positions );
		layouts.push( { name: `grid ${counts.join( 'x' )}`, kind: 'grid', interpolation: 'trilinear', positions, sh, captureMs: ms, grid, probesNotInOpenSpace: outside } );
		layouts.push( { name: `grid ${counts.join( 'x' )}, tetrahedralized`, kind: 'grid', interpolation: 'tetrahedral', positions, sh, captureMs: ms, probesNotInOpenSpace: outside } );

	}

	{

		const positions = Float64Array.from( scene.hand.positions );
		const { sh, ms } = await session.capture( positions, capture, 'hand-made layout' );
		layouts.push( { name: `hand-made (${scene.hand.name})`, kind: 'hand', interpolation: 'tetrahedral', positions, sh, captureMs: ms, probesNotInOpenSpace: notOpen( positions ) } );

	}

	// Automatic layouts: prefixes of the two placements' insertion orders. Their SH are the dense
	// capture's at those points; the layouts at the budget (the ones the verdict judges) are captured
	// again as layouts of their own, to time them and to check that the capture repeats exactly.
	const budget = Math.floor( 0.2 * config.paper.gridProbes );
	const start = reduction.order.subarray( 0, reduction.history.count[ 0 ] );
	const selectStart = performance.now();
	const greedy = selectByMeanError( densePositions, denseCapture.sh, { start, targetCount: Math.max( ...autoCounts ) } );
	const selectMs = performance.now() - selectStart;
	log( `mean-greedy selection: ${start.length} → ${greedy.order.length} in ${( selectMs / 1000 ).toFixed( 1 )} s` );
	const perProbeMs = denseCapture.ms / kept.length;
	let recaptureDifference = 0, largestL00 = 0;
	for ( let i = 0; i < denseCapture.sh.length; i += 27 ) {

		largestL00 = Math.max(
			largestL00, Math.abs( denseCapture.sh[ i ] ), Math.abs( denseCapture.sh[ i + 1 ] ), Math.abs( denseCapture.sh[ i + 2 ] )
		);

	}

	const denseMeanError: Record<string, number> = {};
	const judged = Math.max( ...autoCounts.filter( ( n ) => n <= budget ), - 1 );
	const methods: [ AutoMethod, Uint32Array, ( count: number ) => number ][] = [
		[ 'reduceProbes', reduction.order, ( count ) => reduction.history.mean[ Array.from( reduction.history.count ).indexOf( count ) ] ],
		[ 'mean-greedy', greedy.order, ( count ) => greedy.mean[ count - start.length ] ],
	];
	for ( const [ method, order, denseError ] of methods ) {

		for ( const count of autoCounts ) {

			if ( count < start.length && method === 'mean-greedy' ) continue; // the same starting set as reduceProbes
			const indices = order.subarray( 0, count );
			const positions = subsetPositions( densePositions, indices );
			let sh = subsetSH( denseCapture.sh, indices ), captureMs = perProbeMs * count, captureMsEstimated = true;
			if ( count === judged ) {

				const own = await session.capture( positions, capture, `automatic ${count} (${method})` );
				for ( let i = 0; i < sh.length; i ++ ) {

					recaptureDifference = Math.max( recaptureDifference, Math.abs( own.sh[ i ] - sh[ i ] ) / largestL00 );

				}

				sh = own.sh;
				captureMs = own.ms;
				captureMsEstimated = false;

			}

			denseMeanError[ `${method} ${count}` ] = denseError( count );
			layouts.push( {
				name: `automatic ${count} (${method})`, kind: 'auto', method, interpolation: 'tetrahedral', positions, sh, captureMs, captureMsEstimated,
				denseMeanError: denseError( count ), probesNotInOpenSpace: notOpen( positions ),
			} );

		}

	}

	layouts.push( { name: `all ${kept.length} dense candidates`, kind: 'dense', interpolation: 'tetrahedral', positions: densePositions, sh: denseCapture.sh, captureMs: denseCapture.ms, probesNotInOpenSpace: 0 } );

	if ( options.saveCaptures ) {

		const out = resolve( ROOT, options.out );
		mkdirSync( out, { recursive: true } );
		const plain = ( array: ArrayLike<number> ) => Array.from( array, ( v ) => Math.fround( v ) );
		writeFileSync( join( out, `${options.scene}.captures.json` ), JSON.stringify( {
			truth: { positions: plain( truth.positions ), sh: plain( truthCapture.sh ) },
			dense: {
				positions: plain( densePositions ), sh: plain( denseCapture.sh ),
				reduceProbesOrder: Array.from( reduction.order ), meanGreedyOrder: Array.from( greedy.order )
			},
			layouts: layouts.filter( ( layout ) => layout.kind !== 'auto' && layout.kind !== 'dense' && ! ( layout.kind === 'grid' && layout.interpolation === 'tetrahedral' ) ).map( ( layout ) => ( { name: layout.name, positions: plain( layout.positions ), sh: plain( layout.sh ) } ) ),
		} ) );

	}

	// 4. Errors against the ground truth.
	const order = ( row: EvaluatedLayout ) => ( row.kind === 'grid' ? ( row.interpolation === 'trilinear' ? 0 : 1 ) : row.kind === 'hand' ? 2 : row.kind === 'auto' ? ( row.method === 'reduceProbes' ? 3 : 4 ) : 5 );
	layouts.sort( ( a, b ) => order( a ) - order( b ) || a.positions.length - b.positions.length );
	// Where the paper's grid is not handicapped: samples whose grid cell has all its probes in open space.
	const paperGrid = new GridInterpolator( box.min, box.max, config.paper.gridCounts );
	const usable = Array.from( { length: paperGrid.probeCount }, ( _, p ) => open.classify(
		paperGrid.positions[ 3 * p ], paperGrid.positions[ 3 * p + 1 ], paperGrid.positions[ 3 * p + 2 ]
	) === OPEN );
	const gridValid = gridValidSamples( paperGrid, usable, truth.positions );
	log( `${gridValid.length} of ${options.samples} samples have all their ${config.paper.gridCounts.join( 'x' )} grid probes in open space` );
	const rows: LayoutResult[] = layouts.map( ( layout ) => evaluateLayout( layout, truth.positions, truthCapture.sh, gridValid ) );
	for ( const row of rows ) log( `${row.name.padEnd( 48 )} ${String( row.probes ).padStart( 4 )} probes ${String( row.cells ).padStart( 5 )} cells  mean ${( 100 * row.meanError ).toFixed( 2 )} %  p95 ${( 100 * row.p95Error ).toFixed( 2 )} %` );

	return {
		scene: options.scene,
		samples: options.samples,
		layouts: rows,
		verdict: verdictOf( rows, config.paper, gridValid.length ),
		paper: config.paper,
		groundTruth: {
			seed: options.seed, region: { min: Array.from( box.min ), max: Array.from( box.max ) },
			minDistance: config.minDistance, maxSky: config.maxSky,
			drawn: truth.drawn, rejectedNear: truth.near, rejectedInside: truth.inside, rejectedOutside: truth.outside,
			captureMs: truthCapture.ms, normals: 26,
			gridValidSamples: gridValid.length,
		},
		dense: {
			seed: options.denseSeed, probes: kept.length, fromGrid, fromVertices: kept.length - fromGrid,
			captureMs: denseCapture.ms, reduceMs, selectMs,
			denseMeanError, recaptureMaxDifference: recaptureDifference,
		},
		capture: { ...capture, type: 'HalfFloat', solidAngle: 'exact' },
		environment: {
			browser: session.browserVersion, renderer: String( scene.info.renderer ), three: String( scene.info.three ),
			node: process.version,
			cpus: `${cpus().length} × ${cpus()[ 0 ]?.model ?? '?'}`, date: new Date().toISOString(), triangles: Number( scene.info.triangles ),
		},
		runMs: performance.now() - runStart,
	};

}

process.exitCode = await main();
