/**
 * Pure parts of the experiment's measurement: a layout's interpolated SH at the ground-truth
 * samples, its error against the captured truth (the library's `irradianceError`), the rows of
 * the result JSON, and the verdict on the paper's claim.
 */

import { GridInterpolator, blendSH, createProbeInterpolator, irradianceError, type ProbeInterpolator } from '../../src/math.js';
import { evaluateGradientField } from '../../src/fitting/index.js';
import { summarizeErrors } from '../../src/placement/irradianceError.js';

/** How a layout turns positions into weights. */
export type Interpolation = 'trilinear' | 'tetrahedral';

/** What kind of layout a row is. */
export type LayoutKind = 'grid' | 'hand' | 'auto' | 'dense';

/**
 * Which automatic placement made a layout: the library's `reduceProbes` (captured SH), the
 * experiment's mean-greedy selection, or `reduceProbes` re-fitting at every insertion, without or
 * with swap passes.
 */
export type AutoMethod = 'reduceProbes' | 'mean-greedy' | 'greedy-fit' | 'greedy-fit + swaps';

/** How a fitted layout's SH were fitted (from `fitProbeSH` or `reduceProbes`' fit). */
export interface LayoutFit {

	/** Fit samples (dense candidates plus extra fit points). */
	samples: number;
	lambda: number;
	gradientLambda: number;
	/** Mean irradiance error over the held-out folds at the chosen λ (null when λ was given). */
	crossValidationError: number | null;
	/** Wall time of the fit (and of the placement, for automatic layouts), ms. */
	ms: number;

}

/** One row of the result JSON's `layouts`. */
export interface LayoutResult {

	name: string;
	interpolation: Interpolation;
	/** Probe count. */
	probes: number;
	/** Boxes (trilinear) or tetrahedra (tetrahedral): the paper's Table 4 columns. */
	cells: number;
	/** Mean over the samples of the per-sample irradiance error (`irradianceError`). */
	meanError: number;
	/** 95th percentile of the per-sample errors. */
	p95Error: number;
	/** Time to capture this layout's probes (ms, one `ProbeCapturer`, the same settings for all). */
	captureMs: number;
	kind: LayoutKind;
	/** Largest per-sample error. */
	maxError: number;
	/** Probes per axis, for grids. */
	counts?: number[];
	/** Probes the open-space test rejects (inside geometry, against a surface, or outside the interior). */
	probesNotInOpenSpace: number;
	/** Automatic layouts: the placement that made it. */
	method?: AutoMethod;
	/** Automatic layouts: its mean error over the dense candidate set (what the placement saw; not the ground truth). */
	denseMeanError?: number;
	/** True when `captureMs` is the dense capture's time per probe × probes instead of a capture of its own. */
	captureMsEstimated?: boolean;
	/**
	 * Mean and p95 error over only the samples whose paper's-grid cell has all its probes in open
	 * space (present when some samples are not): where the grid is not handicapped by probes in
	 * walls or outside the interior. Same per-sample errors, same normaliser.
	 */
	meanErrorGridValid?: number;
	p95ErrorGridValid?: number;
	/** True when the probes' SH were fitted to the fit samples (not the captured ones). */
	fitted: boolean;
	/** True when the probes carry fitted gradients (108 floats per probe). */
	gradients: boolean;
	/** SH floats stored: 27 per plain probe, 108 (27 + 81) per gradient probe. */
	shFloats: number;
	/**
	 * Captures a bake of this layout needs: its probes; for automatic layouts the dense candidates
	 * they are chosen from; for fitted layouts also the fit samples.
	 */
	bakeCaptures: number;
	/** Fitted layouts: how. */
	fit?: LayoutFit;
	/** Automatic layouts placed with a region of interest: which. */
	region?: 'walkable';
	/**
	 * Mean error over the fit samples (dense candidates plus extra fit points), no ground truth:
	 * what the judged layouts are chosen by, with the cross-validation error where there is one.
	 */
	fitSetError?: number;
	/**
	 * Mean and p95 error over the ground-truth points inside the walkable region ("where characters
	 * go": `WalkableRegion` of the scene's floors), normalised by those points' own mean irradiance.
	 */
	meanErrorWalkable?: number;
	p95ErrorWalkable?: number;

}

/** A layout ready to evaluate: positions, their captured SH and how to interpolate them. */
export interface EvaluatedLayout {

	name: string;
	kind: LayoutKind;
	interpolation: Interpolation;
	positions: ArrayLike<number>;
	sh: Float32Array;
	captureMs: number;
	/** For a trilinear grid: its box and counts (probe order that of `GridInterpolator`). */
	grid?: { min: ArrayLike<number>; max: ArrayLike<number>; counts: ArrayLike<number> };
	probesNotInOpenSpace?: number;
	method?: AutoMethod;
	denseMeanError?: number;
	captureMsEstimated?: boolean;
	/** Fitted gradients, 81 per probe (contracts: gradients[ 81 i + 27 a + k ]); null or absent: plain probes. */
	gradients?: Float32Array | null;
	/** Present when `sh` was fitted. */
	fit?: LayoutFit;
	region?: 'walkable';
	fitSetError?: number;
	/** See {@link LayoutResult.bakeCaptures}; default the probe count. */
	bakeCaptures?: number;

}

/** The interpolator of a layout: a `GridInterpolator` for trilinear grids, else the library's tetrahedralization. */
export function interpolatorOf( layout: Pick<EvaluatedLayout, 'interpolation' | 'positions' | 'grid'> ): ProbeInterpolator {

	if ( layout.interpolation === 'trilinear' ) {

		if ( ! layout.grid ) throw new Error( 'interpolatorOf: a trilinear layout needs its grid (min, max, counts).' );
		return new GridInterpolator( layout.grid.min, layout.grid.max, layout.grid.counts );

	}

	return createProbeInterpolator( layout.positions );

}

/** Interpolated SH (27 floats per sample) of the layout at each sample position, as the runtime blends them. */
export function predictSH( interpolator: ProbeInterpolator, probeSH: ArrayLike<number>, samples: ArrayLike<number> ): Float32Array {

	const count = samples.length / 3;
	if ( probeSH.length !== 27 * interpolator.probeCount ) throw new RangeError( `predictSH: ${probeSH.length / 27} probes of SH for an interpolator of ${interpolator.probeCount}.` );
	const out = new Float32Array( 27 * count );
	const indices = new Uint32Array( 8 ), weights = new Float64Array( 8 ), sh = new Float64Array( 27 );
	let hint = - 1;
	for ( let i = 0; i < count; i ++ ) {

		hint = interpolator.interpolate( samples[ 3 * i ], samples[ 3 * i + 1 ], samples[ 3 * i + 2 ], indices, weights, hint );
		blendSH( indices, weights, probeSH, sh, interpolator.weightCount );
		for ( let k = 0; k < 27; k ++ ) out[ 27 * i + k ] = sh[ k ];

	}

	return out;

}

/**
 * The samples (indices) whose trilinear cell in `grid` uses only probes for which `usable` is true
 * (probes with zero weight do not count).
 */
export function gridValidSamples( grid: GridInterpolator, usable: ArrayLike<boolean>, samples: ArrayLike<number> ): Uint32Array {

	const indices = new Uint32Array( 8 ), weights = new Float64Array( 8 ), out: number[] = [];
	for ( let i = 0; 3 * i < samples.length; i ++ ) {

		grid.interpolate( samples[ 3 * i ], samples[ 3 * i + 1 ], samples[ 3 * i + 2 ], indices, weights );
		let valid = true;
		for ( let k = 0; k < 8; k ++ ) if ( weights[ k ] > 0 && ! usable[ indices[ k ] ] ) valid = false;
		if ( valid ) out.push( i );

	}

	return Uint32Array.from( out );

}

/** Sample subsets a layout is also measured on (indices into the samples). */
export interface SampleSubsets {

	/** Samples whose paper's-grid cell has all its probes in open space. */
	gridValid?: ArrayLike<number>;

	/** Samples inside the walkable region. */
	walkable?: ArrayLike<number>;

}

/**
 * The layout's field at the samples, 27 floats each: blended SH, plus each probe's gradient term
 * (`evaluateGradientField`, the runtime's formula) when it has gradients.
 */
export function layoutField( layout: EvaluatedLayout, interpolator: ProbeInterpolator, samples: ArrayLike<number> ): Float32Array {

	if ( ! layout.gradients ) return predictSH( interpolator, layout.sh, samples );
	return evaluateGradientField( interpolator, layout.positions, layout.sh, layout.gradients, samples );

}

/**
 * Measures one layout against the truth at the samples: one row of the result. With subsets (sample
 * indices), also its errors over those: `gridValid` with the whole set's normaliser, `walkable` with
 * its own.
 */
export function evaluateLayout(
	layout: EvaluatedLayout, samples: ArrayLike<number>, trueSH: ArrayLike<number>, subsets: SampleSubsets = {}
): LayoutResult {

	const interpolator = interpolatorOf( layout );
	const predicted = layoutField( layout, interpolator, samples );
	const error = irradianceError( predicted, trueSH );
	const probes = layout.positions.length / 3;
	const row: LayoutResult = {
		name: layout.name,
		interpolation: layout.interpolation,
		probes,
		cells: interpolator.cellCount,
		meanError: error.mean,
		p95Error: error.p95,
		captureMs: layout.captureMs,
		kind: layout.kind,
		maxError: error.max,
		probesNotInOpenSpace: layout.probesNotInOpenSpace ?? 0,
		fitted: layout.fit !== undefined,
		gradients: !! layout.gradients,
		shFloats: ( layout.gradients ? 108 : 27 ) * probes,
		bakeCaptures: layout.bakeCaptures ?? probes,
	};
	if ( layout.grid ) row.counts = Array.from( layout.grid.counts );
	if ( layout.method ) row.method = layout.method;
	if ( layout.denseMeanError !== undefined ) row.denseMeanError = layout.denseMeanError;
	if ( layout.captureMsEstimated ) row.captureMsEstimated = true;
	if ( layout.fit ) row.fit = layout.fit;
	if ( layout.region ) row.region = layout.region;
	if ( layout.fitSetError !== undefined ) row.fitSetError = layout.fitSetError;
	const { gridValid, walkable } = subsets;
	if ( gridValid && gridValid.length > 0 && gridValid.length < samples.length / 3 ) {

		const part = summarizeErrors( Array.from( gridValid, ( i ) => error.perPoint[ i ] ) );
		row.meanErrorGridValid = part.mean;
		row.p95ErrorGridValid = part.p95;

	}

	if ( walkable && walkable.length > 0 ) {

		const part = irradianceError( subsetSH( predicted, walkable ), subsetSH( trueSH, walkable ) );
		row.meanErrorWalkable = part.mean;
		row.p95ErrorWalkable = part.p95;

	}

	return row;

}

/** The SH of probes `indices` of a set, 27 floats each, in that order. */
export function subsetSH( sh: ArrayLike<number>, indices: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 27 * indices.length );
	for ( let i = 0; i < indices.length; i ++ ) for ( let k = 0; k < 27; k ++ ) out[ 27 * i + k ] = sh[ 27 * indices[ i ] + k ];
	return out;

}

/** The positions of probes `indices` of a set, x, y, z each, in that order. */
export function subsetPositions( positions: ArrayLike<number>, indices: ArrayLike<number> ): Float64Array {

	const out = new Float64Array( 3 * indices.length );
	for ( let i = 0; i < indices.length; i ++ ) for ( let a = 0; a < 3; a ++ ) out[ 3 * i + a ] = positions[ 3 * indices[ i ] + a ];
	return out;

}

/** The paper's figures for a scene (Table 4). */
export interface PaperFigures {

	gridCounts: number[];
	gridProbes: number;
	handProbes: number;
	boxes: number;
	tetrahedra: number;

}

/** The answer to the paper's claim on one scene. */
export interface Verdict {

	/** The probe budget: 20 % of the paper's grid, rounded down. */
	budget: number;
	/** The paper's grid with trilinear interpolation. */
	grid: { name: string; probes: number; meanError: number; p95Error: number };
	/**
	 * The automatic layout judged: the largest count within the budget (the most the claim allows)
	 * and, of the placements at that count, the one with the lowest error over the dense set — chosen
	 * without looking at the ground truth.
	 */
	auto: { name: string; probes: number; meanError: number; p95Error: number; method?: AutoMethod } | null;
	/** The whole dense candidate set as one layout (what the automatic layouts are cut from), if measured. */
	dense: { probes: number; meanError: number; p95Error: number } | null;
	/** auto.meanError ≤ grid.meanError. */
	holds: boolean;
	/** auto.meanError / grid.meanError (< 1: better than the grid). */
	ratio: number | null;
	/** The hand-made layout, measured the same way. */
	hand: { name: string; probes: number; meanError: number; p95Error: number; ratio: number } | null;
	/**
	 * The same comparison over only the samples whose paper's-grid cell has all its probes in open
	 * space, when some samples are not: the grid where it is not handicapped by misplaced probes.
	 */
	gridValid: { samples: number; gridMeanError: number; autoMeanError: number | null; ratio: number | null; holds: boolean } | null;
	/** The fewest probes among the automatic layouts measured whose mean error is ≤ the grid's, or null. */
	fewestAutoMatchingGrid: number | null;
	/** The same for the p95 error. */
	fewestAutoMatchingGridP95: number | null;
	/** One sentence. */
	text: string;

}

/** The verdict on "arbitrary probes + tetrahedra reach the grid with ≤ 20 % of its probes". */
export function verdictOf( layouts: readonly LayoutResult[], paper: PaperFigures, gridValidSamples = 0 ): Verdict {

	const grid = layouts.find( ( row ) => row.kind === 'grid' && ! row.fitted && row.interpolation === 'trilinear' && sameCounts( row.counts, paper.gridCounts ) );
	if ( ! grid ) throw new Error( `verdictOf: no trilinear grid ${paper.gridCounts.join( 'x' )} among the layouts.` );
	const budget = Math.floor( 0.2 * grid.probes );
	// The paper's claim is about captured probes: fitted layouts are judged by the targets (targets.ts).
	const autos = layouts.filter( ( row ) => row.kind === 'auto' && ! row.fitted ).sort( ( a, b ) => a.probes - b.probes );
	const within = autos.filter( ( row ) => row.probes <= budget );
	const largest = within.length > 0 ? within[ within.length - 1 ].probes : - 1;
	const atLargest = within.filter( ( row ) => row.probes === largest )
		.sort( ( a, b ) => ( a.denseMeanError ?? Infinity ) - ( b.denseMeanError ?? Infinity ) );
	const auto = atLargest.length > 0 ? atLargest[ 0 ] : null;
	const hand = layouts.find( ( row ) => row.kind === 'hand' && ! row.fitted ) ?? null;
	const pick = ( row: LayoutResult ) => ( { name: row.name, probes: row.probes, meanError: row.meanError, p95Error: row.p95Error } );
	const denseRow = layouts.find( ( row ) => row.kind === 'dense' );
	const holds = auto !== null && auto.meanError <= grid.meanError;
	const ratio = auto ? auto.meanError / grid.meanError : null;
	const fewest = autos.find( ( row ) => row.meanError <= grid.meanError )?.probes ?? null;
	const fewestP95 = autos.find( ( row ) => row.p95Error <= grid.p95Error )?.probes ?? null;
	const pct = ( value: number ) => `${( 100 * value ).toFixed( 1 )} %`;
	let text: string;
	if ( ! auto ) {

		text = `No automatic layout within ${budget} probes was measured.`;

	} else if ( holds ) {

		text = `Holds: ${auto.probes} automatically placed probes (${auto.method ? auto.method + ', ' : ''}${pct( auto.probes / grid.probes )} of the grid's ${grid.probes}) reach a mean error of ${pct( auto.meanError )} against the grid's ${pct( grid.meanError )} (${( ratio! ).toFixed( 2 )}× the grid's error).`;

	} else {

		text = `Does not hold: ${auto.probes} automatically placed probes (${auto.method ? auto.method + ', ' : ''}${pct( auto.probes / grid.probes )} of the grid's ${grid.probes}) have a mean error of ${pct( auto.meanError )} against the grid's ${pct( grid.meanError )} (${( ratio! ).toFixed( 2 )}× the grid's error); ${fewest !== null ? `the automatic layouts match the grid from ${fewest} probes (${pct( fewest / grid.probes )})` : 'no automatic layout measured matches the grid'}.`;

	}

	return {
		budget,
		grid: pick( grid ),
		auto: auto ? { ...pick( auto ), ...( auto.method ? { method: auto.method } : {} ) } : null,
		dense: denseRow ? { probes: denseRow.probes, meanError: denseRow.meanError, p95Error: denseRow.p95Error } : null,
		holds,
		ratio,
		hand: hand ? { ...pick( hand ), ratio: hand.meanError / grid.meanError } : null,
		gridValid: grid.meanErrorGridValid !== undefined ? {
			samples: gridValidSamples,
			gridMeanError: grid.meanErrorGridValid,
			autoMeanError: auto?.meanErrorGridValid ?? null,
			ratio: auto?.meanErrorGridValid !== undefined ? auto.meanErrorGridValid / grid.meanErrorGridValid : null,
			holds: auto?.meanErrorGridValid !== undefined && auto.meanErrorGridValid <= grid.meanErrorGridValid,
		} : null,
		fewestAutoMatchingGrid: fewest,
		fewestAutoMatchingGridP95: fewestP95,
		text,
	};

}

function sameCounts( a: ArrayLike<number> | undefined, b: ArrayLike<number> ): boolean {

	return a !== undefined && a.length === b.length && Array.from( a ).every( ( v, i ) => v === b[ i ] );

}
