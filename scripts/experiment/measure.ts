/**
 * One run of the experiment on one scene, from a {@link CaptureSource} (saved captures, else the
 * browser): the point sets, their captures, the layouts (buildLayouts.ts: no ground truth), each
 * layout's errors against every ground truth, the verdict on the paper's claim and issue 14's
 * targets. run.ts writes the result.
 */

import { cpus } from 'node:os';
import { GridInterpolator } from '../../src/math.js';
import { WalkableRegion } from '../../src/placement/walkableRegion.js';
import { buildLayouts, capturedLayouts, type LayoutInputs } from './buildLayouts.js';
import type { CaptureProvider } from './CaptureSource.js';
import type { ExperimentOptions } from './cli.js';
import { CONFIGS, type SceneConfig } from './config.js';
import { decodeBase64 } from './captureStore.js';
import { evaluateLayout, gridValidSamples, verdictOf, type EvaluatedLayout } from './evaluate.js';
import { countNotOpen, pointSets } from './pointSets.js';
import type { ExperimentResult, SeedCheck } from './report.js';
import { OPEN } from './samples.js';
import { checkTargets, equalStorage } from './targets.js';

/** What {@link measure} returns: the result file, and the layouts with their (fitted) SH and gradients. */
export interface Measurement {

	result: ExperimentResult;
	layouts: EvaluatedLayout[];

}

/**
 * Measures one scene (settings `config`, by default the scene's in config.ts); `log` gets progress
 * lines. With `options.captureOnly`, only makes the captures (null).
 */
export async function measure(
	source: CaptureProvider, options: ExperimentOptions, log: ( message: string ) => void, runStart: number,
	config: SceneConfig = CONFIGS[ options.scene ],
): Promise<Measurement | null> {

	const scene = await source.scene();
	const capture = { resolution: options.resolution, near: config.near, far: config.far };
	const triangles = decodeBase64( scene.triangles, Float32Array ), sides = decodeBase64( scene.sides, Int8Array );
	// With fit points per probe, the largest fitted layout's need is drawn and captured; smaller ones fit to a prefix.
	const fitBase = options.fitPoints ?? config.fitPoints;
	const perProbe = options.fitPointsPerProbe ?? config.fitPointsPerProbe ?? 0;
	const largestFitted = Math.max( config.paper.gridProbes, config.targets.autoProbes, ...config.fitCounts, ...config.equalStorage.flat(),
		...config.grids.map( ( counts ) => counts.reduce( ( a, b ) => a * b, 1 ) ) );
	const fitCount = perProbe > 0 ? Math.max( fitBase, Math.ceil( perProbe * largestFitted ) ) : fitBase;
	const sets = pointSets( scene, triangles, sides, config, {
		seeds: [ options.seed, ...options.checkSeeds ], samples: options.samples, denseSeed: options.denseSeed,
		fitPoints: fitCount, fitSeed: options.fitSeed,
	} );
	const notOpen = ( positions: ArrayLike<number> ) => countNotOpen( sets.open, positions );

	// 1. Captures: every ground truth, the dense candidates, the extra fit points, the fixed layouts.
	const truths = [];
	for ( const { seed, samples } of sets.truths ) {

		log( `ground truth (seed ${seed}): ${options.samples} points in open space (${samples.drawn} drawn; ${samples.near} near a surface, ${samples.inside} inside geometry, ${samples.outside} outside the interior)` );
		truths.push( { seed, samples, capture: await source.capture( samples.positions, capture, `ground truth (seed ${seed})` ) } );

	}

	log( `dense candidates: ${sets.dense.length / 3} (${sets.fromGrid} jittered grid, ${sets.dense.length / 3 - sets.fromGrid} vertex)` );
	const dense = await source.capture( sets.dense, capture, 'dense candidates' );
	const fitPoints = fitCount > 0 ? await source.capture( sets.fit.positions, capture, 'fit points' ) : { sh: new Float32Array( 0 ), ms: 0 };
	const grids = [];
	for ( const grid of sets.grids ) {

		const { sh, ms } = await source.capture( grid.positions, capture, `grid ${grid.counts.join( 'x' )}` );
		grids.push( { counts: grid.counts, positions: grid.positions, sh, ms } );

	}

	const hand = await source.capture( sets.hand.positions, capture, 'hand-made layout' );
	const walkable = new WalkableRegion( triangles, { height: config.walkableHeight, sides } );

	// 2. The layouts, from everything but the ground truths.
	const inputs: LayoutInputs = {
		paper: config.paper, autoCounts: config.autoCounts, fitCounts: config.fitCounts, equalStorage: config.equalStorage,
		targetProbes: config.targets.autoProbes, seed: options.denseSeed, box: sets.box,
		grids, hand: { name: sets.hand.name, positions: sets.hand.positions, sh: hand.sh, ms: hand.ms },
		dense: { positions: sets.dense, sh: dense.sh, ms: dense.ms },
		fitPoints: { positions: sets.fit.positions, sh: fitPoints.sh, ms: fitPoints.ms },
		...( perProbe > 0 ? { fitRule: { base: fitBase, perProbe } } : {} ),
		walkable, notOpen, log,
	};
	if ( options.captureOnly ) {

		// Only what needs the browser: the judged captured layouts' own captures.
		await recaptureJudged( source, capturedLayouts( inputs ).layouts, config.paper.gridProbes, capture, dense.sh );
		return null;

	}

	const built = buildLayouts( inputs );
	const recaptureMaxDifference = await recaptureJudged( source, built.layouts, config.paper.gridProbes, capture, dense.sh );

	// 3. Errors against each ground truth.
	const paperGrid = new GridInterpolator( sets.box.min, sets.box.max, config.paper.gridCounts );
	const usable = Array.from( { length: paperGrid.probeCount }, ( _, p ) => sets.open.classify(
		paperGrid.positions[ 3 * p ], paperGrid.positions[ 3 * p + 1 ], paperGrid.positions[ 3 * p + 2 ]
	) === OPEN );
	const evaluateAll = ( positions: Float64Array, sh: Float32Array ) => {

		const gridValid = gridValidSamples( paperGrid, usable, positions );
		const inside: number[] = [];
		for ( let i = 0; 3 * i < positions.length; i ++ ) {

			if ( walkable.contains( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] ) ) inside.push( i );

		}

		const rows = built.layouts.map( ( layout ) => evaluateLayout( layout, positions, sh, { gridValid, walkable: inside } ) );
		return { rows, gridValid: gridValid.length, walkable: inside.length };

	};

	const primary = truths[ 0 ];
	const main = evaluateAll( primary.samples.positions, primary.capture.sh );
	log( `${main.gridValid} of ${options.samples} samples have all their ${config.paper.gridCounts.join( 'x' )} grid probes in open space; ${main.walkable} are in the walkable region` );
	for ( const row of main.rows ) log( `${row.name.padEnd( 64 )} ${String( row.probes ).padStart( 4 )} probes  mean ${( 100 * row.meanError ).toFixed( 2 )} %  walkable ${( 100 * ( row.meanErrorWalkable ?? NaN ) ).toFixed( 2 )} %` );
	const checks: SeedCheck[] = truths.map( ( truth, t ) => {

		const { rows, walkable: inside } = t === 0 ? main : evaluateAll( truth.samples.positions, truth.capture.sh );
		return {
			seed: truth.seed, walkableSamples: inside, targets: checkTargets( rows, config.paper, config.targets ),
			meanError: Object.fromEntries( rows.map( ( row ) => [ row.name, row.meanError ] ) ),
			meanErrorWalkable: Object.fromEntries( rows.map( ( row ) => [ row.name, row.meanErrorWalkable ?? null ] ) ),
		};

	} );

	const result: ExperimentResult = {
		scene: options.scene,
		samples: options.samples,
		layouts: main.rows,
		verdict: verdictOf( main.rows, config.paper, main.gridValid ),
		targets: checks[ 0 ].targets,
		seeds: checks,
		equalStorage: equalStorage( main.rows, config.equalStorage ),
		paper: config.paper,
		groundTruth: {
			seed: options.seed, region: { min: Array.from( sets.box.min ), max: Array.from( sets.box.max ) },
			minDistance: config.minDistance, maxSky: config.maxSky,
			drawn: primary.samples.drawn, rejectedNear: primary.samples.near, rejectedInside: primary.samples.inside,
			rejectedOutside: primary.samples.outside,
			captureMs: primary.capture.ms, normals: 26,
			gridValidSamples: main.gridValid, walkableSamples: main.walkable,
		},
		dense: {
			seed: options.denseSeed, probes: sets.dense.length / 3, fromGrid: sets.fromGrid,
			fromVertices: sets.dense.length / 3 - sets.fromGrid,
			captureMs: dense.ms, reduceMs: built.reduceMs, selectMs: built.selectMs,
			denseMeanError: built.denseMeanError, recaptureMaxDifference,
		},
		fit: {
			seed: options.fitSeed, points: fitCount, drawn: sets.fit.drawn, captureMs: fitPoints.ms, samples: built.fitSamples,
			...( perProbe > 0 ? { base: fitBase, perProbe } : {} ),
		},
		walkable: { height: config.walkableHeight, floorTriangles: walkable.floorTriangleCount },
		capture: { ...capture, type: 'HalfFloat', solidAngle: 'exact' },
		environment: {
			browser: source.browserVersion, renderer: String( scene.info.renderer ), three: String( scene.info.three ),
			node: process.version,
			cpus: `${cpus().length} × ${cpus()[ 0 ]?.model ?? '?'}`, date: new Date().toISOString(), triangles: Number( scene.info.triangles ),
			newCaptures: source.newCaptures,
		},
		runMs: performance.now() - runStart,
	};
	return { result, layouts: built.layouts };

}

/**
 * The captured automatic layouts the paper's verdict judges (the largest count within 20 % of the
 * grid) are captured again as layouts of their own: their capture time, and a check that the
 * capture repeats (their SH replace the dense capture's). Returns the largest difference relative
 * to the largest L00 of the dense capture.
 */
async function recaptureJudged(
	source: CaptureProvider, layouts: EvaluatedLayout[], gridProbes: number, capture: { resolution: number; near: number; far: number },
	denseSH: Float32Array,
): Promise<number> {

	const budget = Math.floor( 0.2 * gridProbes );
	const captured = layouts.filter( ( layout ) => layout.kind === 'auto' && ! layout.fit );
	const judged = Math.max( ...captured.map( ( layout ) => layout.positions.length / 3 ).filter( ( n ) => n <= budget ), - 1 );
	let largestL00 = 0, difference = 0;
	for ( let i = 0; i < denseSH.length; i += 27 ) {

		largestL00 = Math.max( largestL00, Math.abs( denseSH[ i ] ), Math.abs( denseSH[ i + 1 ] ), Math.abs( denseSH[ i + 2 ] ) );

	}

	for ( const layout of captured.filter( ( l ) => l.positions.length / 3 === judged ) ) {

		const own = await source.capture( layout.positions, capture, layout.name );
		for ( let i = 0; i < own.sh.length; i ++ ) {

			difference = Math.max( difference, Math.abs( own.sh[ i ] - layout.sh[ i ] ) / largestL00 );

		}

		layout.sh = own.sh;
		layout.captureMs = own.ms;
		layout.captureMsEstimated = false;

	}

	return difference;

}
