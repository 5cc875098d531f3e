/**
 * Every layout the experiment measures, built from the captures that are not the ground truth:
 * the captured grids and hand-made layout, the same fitted (plain and with gradients), the
 * automatic layouts cut from the dense candidates (captured SH: the library's `reduceProbes` and
 * the experiment's mean-greedy selection; fitted: `reduceProbes` re-fitting at every insertion,
 * without and with swaps, and with the walkable region), and the whole dense set. The fits use
 * the dense candidates and the extra fit points only: this function has no ground-truth input, so
 * its layouts cannot depend on it (test/experiment/buildLayouts.test.ts checks that too).
 */

import { createProbeInterpolator, GridInterpolator, irradianceError, type ProbeInterpolator } from '../../src/math.js';
import { reduceProbes } from '../../src/index.js';
import { fitProbeSH, type FitSamples } from '../../src/fitting/fitProbeSH.js';
import type { WalkableRegion } from '../../src/placement/walkableRegion.js';
import { interpolatorOf, layoutField, subsetPositions, subsetSH, type AutoMethod, type EvaluatedLayout, type LayoutFit, type PaperFigures } from './evaluate.js';
import { selectByMeanError } from './selectByMeanError.js';

/** A captured set of probes. */
export interface CapturedSet {

	positions: Float64Array;
	sh: Float32Array;
	/** Capture wall time (ms). */
	ms: number;

}

/** What the layouts are built from: no ground truth. */
export interface LayoutInputs {

	paper: PaperFigures;
	/** Counts the captured automatic layouts are cut at. */
	autoCounts: number[];
	/** Counts of the fitted automatic layouts. */
	fitCounts: number[];
	/** Pairs [N, 4N]: gradient layouts of N probes and plain fitted ones of 4N, for the equal-storage comparison. */
	equalStorage: [ number, number ][];
	/** The target's probe count: the walkable-region layouts are placed at it. */
	targetProbes: number;
	/** The placement's tie-break seed (the dense set's). */
	seed: number;
	/** The captured grids over `box` (GridInterpolator order). */
	grids: ( CapturedSet & { counts: number[] } )[];
	box: { min: ArrayLike<number>; max: ArrayLike<number> };
	hand: CapturedSet & { name: string };
	/** The dense candidates the placements choose from (and fit to). */
	dense: CapturedSet;
	/** Extra captured fit points, in open space, beyond the dense candidates (may be empty). */
	fitPoints: CapturedSet;
	/**
	 * A fitted layout of n probes fits to the first max(base, ⌈perProbe × n⌉) of `fitPoints` (at most
	 * all of them); absent: every layout to all of them.
	 */
	fitRule?: { base: number; perProbe: number };
	/** "Where characters go"; null: no walkable layouts. */
	walkable: WalkableRegion | null;
	/** Probes the open-space test rejects. */
	notOpen: ( positions: ArrayLike<number> ) => number;
	log: ( message: string ) => void;

}

/** What {@link buildLayouts} returns. */
export interface BuiltLayouts {

	layouts: EvaluatedLayout[];
	/** Size of `reduceProbes`' starting set (mean-greedy starts from it). */
	startCount: number;
	reduceMs: number;
	selectMs: number;
	/** Mean error over the dense set of each captured automatic cut ("method count"). */
	denseMeanError: Record<string, number>;
	/** Fit samples used (dense candidates + extra fit points). */
	fitSamples: number;

}

/** The fitted automatic placements measured, and which of them also runs at the grid's count and in the equal-storage pairs. */
const FITTED_METHODS: { method: AutoMethod; swaps: boolean }[] = [
	{ method: 'greedy-fit', swaps: false },
	{ method: 'greedy-fit + swaps', swaps: true },
];
const BEST_METHOD: AutoMethod = 'greedy-fit + swaps';

/**
 * The swap passes of 'greedy-fit + swaps': up to 4 passes, 12 replacements per probe (8 nearest, 4
 * predicted worst) — more thorough than `reduceProbes`' defaults (2 passes, 6), which cost half
 * the time; chosen on the fit set's cross-validation error (docs/placement.md).
 */
const SWAPS = { swaps: 4, swapTrials: 12 };

/** Every layout of the experiment (see the file comment); takes no ground truth. */
export function buildLayouts( inputs: LayoutInputs ): BuiltLayouts {

	const built = capturedLayouts( inputs );
	const samples = concatSamples( inputs.dense, inputs.fitPoints );
	const dense = built.layouts.pop()!; // the whole dense set stays last
	built.layouts.push( ...fittedLayouts( inputs ), dense );

	// The yardstick without ground truth, the same for every layout; and how many captures a bake of each takes.
	const denseCount = inputs.dense.positions.length / 3;
	for ( const layout of built.layouts ) {

		// Automatic layouts' probes are among the dense candidates; the fits also need the extra fit points.
		const own = layout.kind === 'auto' || layout.kind === 'dense' ? denseCount : layout.positions.length / 3;
		layout.bakeCaptures = layout.fit ? ( layout.kind === 'auto' ? layout.fit.samples : own + layout.fit.samples ) : own;

		const interpolator = interpolatorOf( layout );
		layout.fitSetError = irradianceError( layoutField( layout, interpolator, samples.positions ), samples.sh ).mean;

	}

	return built;

}

/**
 * The layouts with captured SH: the grids (trilinear and tetrahedralized), the hand-made layout,
 * the cuts of `reduceProbes` and of the mean-greedy selection, and, last, the whole dense set.
 */
export function capturedLayouts( inputs: LayoutInputs ): BuiltLayouts {

	const { dense, log } = inputs;
	const layouts: EvaluatedLayout[] = [];
	for ( const grid of inputs.grids ) {

		const name = `grid ${grid.counts.join( 'x' )}`;
		const captured = { kind: 'grid' as const, positions: grid.positions, sh: grid.sh, captureMs: grid.ms, probesNotInOpenSpace: inputs.notOpen( grid.positions ) };
		layouts.push( { ...captured, name, interpolation: 'trilinear', grid: { min: inputs.box.min, max: inputs.box.max, counts: grid.counts } } );
		layouts.push( { ...captured, name: `${name}, tetrahedralized`, interpolation: 'tetrahedral' } );

	}

	const { hand } = inputs;
	layouts.push( {
		name: `hand-made (${hand.name})`, kind: 'hand', interpolation: 'tetrahedral', positions: hand.positions, sh: hand.sh, captureMs: hand.ms,
		probesNotInOpenSpace: inputs.notOpen( hand.positions ),
	} );

	// Prefixes of one run of each placement.
	const autoCounts = inputs.autoCounts.filter( ( n ) => n <= dense.positions.length / 3 );
	const reduceStart = performance.now();
	const reduction = reduceProbes( dense.positions, dense.sh, { targetCount: Math.max( ...autoCounts ), seed: inputs.seed } );
	const reduceMs = performance.now() - reduceStart;
	log( `reduceProbes: ${dense.positions.length / 3} → ${reduction.order.length} in ${( reduceMs / 1000 ).toFixed( 1 )} s` );
	const start = reduction.order.subarray( 0, reduction.history.count[ 0 ] );
	const selectStart = performance.now();
	const greedy = selectByMeanError( dense.positions, dense.sh, { start, targetCount: Math.max( ...autoCounts ) } );
	const selectMs = performance.now() - selectStart;
	log( `mean-greedy selection: ${start.length} → ${greedy.order.length} in ${( selectMs / 1000 ).toFixed( 1 )} s` );
	const perProbeMs = dense.ms / ( dense.positions.length / 3 );
	const denseMeanError: Record<string, number> = {};
	const captured: [ AutoMethod, Uint32Array, ( count: number ) => number ][] = [
		[ 'reduceProbes', reduction.order, ( count ) => reduction.history.mean[ Array.from( reduction.history.count ).indexOf( count ) ] ],
		[ 'mean-greedy', greedy.order, ( count ) => greedy.mean[ count - start.length ] ],
	];
	for ( const [ method, order, denseError ] of captured ) {

		for ( const count of autoCounts ) {

			if ( count < start.length && method === 'mean-greedy' ) continue; // the same starting set as reduceProbes
			const indices = order.subarray( 0, count );
			const positions = subsetPositions( dense.positions, indices );
			denseMeanError[ `${method} ${count}` ] = denseError( count );
			layouts.push( {
				name: `automatic ${count} (${method})`, kind: 'auto', method, interpolation: 'tetrahedral', positions, sh: subsetSH( dense.sh, indices ),
				captureMs: perProbeMs * count, captureMsEstimated: true, denseMeanError: denseError( count ),
				probesNotInOpenSpace: inputs.notOpen( positions ),
			} );

		}

	}

	layouts.push( {
		name: `all ${dense.positions.length / 3} dense candidates`, kind: 'dense', interpolation: 'tetrahedral', positions: dense.positions, sh: dense.sh,
		captureMs: dense.ms, probesNotInOpenSpace: 0,
	} );
	const fitSamples = ( dense.positions.length + inputs.fitPoints.positions.length ) / 3;
	return { layouts, startCount: start.length, reduceMs, selectMs, denseMeanError, fitSamples };

}

/**
 * The fitted layouts: the grids and the hand-made layout fitted (plain, with gradients), and the
 * automatic layouts `reduceProbes` places while re-fitting (one run per count: swaps change the
 * set, so no prefixes).
 */
export function fittedLayouts( inputs: LayoutInputs ): EvaluatedLayout[] {

	const layouts: EvaluatedLayout[] = [];
	const samples = ( probes: number ) => concatSamples( inputs.dense, fitPointsOf( inputs, probes ) );
	for ( const grid of inputs.grids ) {

		const box = { min: inputs.box.min, max: inputs.box.max, counts: grid.counts };
		const outside = inputs.notOpen( grid.positions );
		for ( const gradients of [ false, true ] ) {

			layouts.push( {
				kind: 'grid', positions: grid.positions, captureMs: grid.ms, probesNotInOpenSpace: outside,
				...fitted( new GridInterpolator( box.min, box.max, box.counts ), grid, samples( grid.positions.length / 3 ), gradients ),
				name: `grid ${grid.counts.join( 'x' )}, fitted${gradients ? ' + gradients' : ''}`, interpolation: 'trilinear', grid: box,
			} );

		}

	}

	const { hand, dense } = inputs;
	for ( const gradients of [ false, true ] ) {

		layouts.push( {
			kind: 'hand', interpolation: 'tetrahedral', positions: hand.positions, captureMs: hand.ms, probesNotInOpenSpace: inputs.notOpen( hand.positions ),
			...fitted( createProbeInterpolator( hand.positions ), hand, samples( hand.positions.length / 3 ), gradients ),
			name: `hand-made (${hand.name}), fitted${gradients ? ' + gradients' : ''}`,
		} );

	}

	const maxCount = dense.positions.length / 3, perProbeMs = dense.ms / maxCount;
	for ( const { method, swaps } of FITTED_METHODS ) {

		for ( const gradients of [ false, true ] ) {

			// The best method also at the grid's count, and for equal storage: N gradient probes, 4N plain ones.
			const counts = new Set( inputs.fitCounts );
			if ( method === BEST_METHOD ) {

				counts.add( inputs.paper.gridProbes );
				for ( const [ n, fourN ] of inputs.equalStorage ) counts.add( gradients ? n : fourN );

			}

			for ( const count of [ ...counts ].filter( ( n ) => n >= 4 && n <= maxCount ).sort( ( a, b ) => a - b ) ) {

				layouts.push( placed( inputs, perProbeMs, count, method, swaps, gradients, null ) );

			}

		}

	}

	if ( inputs.walkable && inputs.targetProbes <= maxCount ) {

		for ( const gradients of [ false, true ] ) {

			layouts.push( placed( inputs, perProbeMs, inputs.targetProbes, BEST_METHOD, true, gradients, inputs.walkable ) );

		}

	}

	return layouts;

}

/** A fixed layout's SH (and gradients) fitted to the fit samples with `fitProbeSH`, λ by cross-validation. */
function fitted(
	interpolator: ProbeInterpolator, set: CapturedSet, samples: FitSamples, gradients: boolean
): Pick<EvaluatedLayout, 'sh' | 'gradients' | 'fit'> {

	const start = performance.now();
	const result = fitProbeSH( interpolator, set.positions, set.sh, samples, { gradients } );
	return {
		sh: result.sh, gradients: result.gradients,
		fit: {
			samples: samples.positions.length / 3, lambda: result.lambda, gradientLambda: result.gradientLambda,
			crossValidationError: result.crossValidationError, ms: performance.now() - start,
		},
	};

}

/** An automatic layout placed and fitted by `reduceProbes` (re-fit at every insertion). */
function placed(
	inputs: LayoutInputs, perProbeMs: number, count: number, method: AutoMethod, swaps: boolean, gradients: boolean,
	walkable: WalkableRegion | null,
): EvaluatedLayout {

	const start = performance.now();
	const fitPoints = fitPointsOf( inputs, count );
	const result = reduceProbes( inputs.dense.positions, inputs.dense.sh, {
		targetCount: count, seed: inputs.seed, fit: { gradients }, ...( swaps ? SWAPS : { swaps: false } ),
		fitSamples: { positions: fitPoints.positions, sh: fitPoints.sh },
		...( walkable ? { region: { walkable } } : {} ),
	} );
	const ms = performance.now() - start;
	const name = `automatic ${count} (${method}${gradients ? ', gradients' : ''}${walkable ? ', walkable' : ''})`;
	inputs.log( `${name}: ${( ms / 1000 ).toFixed( 1 )} s` );
	const fit = result.fit!;
	const layout: EvaluatedLayout = {
		name, kind: 'auto', method, interpolation: 'tetrahedral', positions: result.positions, sh: result.sh, gradients: result.gradients,
		captureMs: perProbeMs * count, captureMsEstimated: true, probesNotInOpenSpace: inputs.notOpen( result.positions ),
		fit: {
			samples: ( inputs.dense.positions.length + fitPoints.positions.length ) / 3,
			lambda: fit.lambda, gradientLambda: fit.gradientLambda,
			crossValidationError: fit.crossValidationError, ms,
		},
	};
	if ( walkable ) layout.region = 'walkable';
	return layout;

}

/** How many extra fit points a fitted layout of `probes` probes uses (see `LayoutInputs.fitRule`). */
export function fitPointCount( available: number, probes: number, rule?: { base: number; perProbe: number } ): number {

	return rule ? Math.min( available, Math.max( rule.base, Math.ceil( rule.perProbe * probes ) ) ) : available;

}

/** The first `fitPointCount` extra fit points (the set is drawn in order, so a shorter one is its prefix). */
function fitPointsOf( inputs: LayoutInputs, probes: number ): CapturedSet {

	const { fitPoints } = inputs;
	const n = fitPointCount( fitPoints.positions.length / 3, probes, inputs.fitRule );
	const ms = fitPoints.ms * n / Math.max( 1, fitPoints.positions.length / 3 );
	return { positions: fitPoints.positions.subarray( 0, 3 * n ), sh: fitPoints.sh.subarray( 0, 27 * n ), ms };

}

/** The dense candidates and the extra fit points as one sample set. */
export function concatSamples( a: CapturedSet, b: CapturedSet ): { positions: Float64Array; sh: Float32Array } {

	const positions = new Float64Array( a.positions.length + b.positions.length );
	positions.set( a.positions );
	positions.set( b.positions, a.positions.length );
	const sh = new Float32Array( a.sh.length + b.sh.length );
	sh.set( a.sh );
	sh.set( b.sh, a.sh.length );
	return { positions, sh };

}
