import { assertPoints, assertSH } from '../validate.js';
import type { FitSamples } from '../fitting/fitProbeSH.js';
import { greedyReduce } from './greedyReduce.js';
import type { IrradianceErrorSummary } from './irradianceError.js';
import { readReduceOptions } from './reduceOptions.js';
import { refitReduce, type RefitRun } from './refitReduce.js';
import type { RegionOfInterest } from './regionOfInterest.js';
import { seededRanks, startingSet } from './startingSet.js';

/** Options of {@link reduceProbes}. Give `targetCount`, `targetError` or both. */
export interface ReduceProbesOptions {

	/**
	 * Stop when the subset has this many probes (an integer in 4..count). Fewer are returned only
	 * when `targetError` is met first, or when no probe left out has any error.
	 */
	targetCount?: number;

	/**
	 * Stop as soon as the {@link irradianceError} over the dense set is ≤ this (≥ 0); by default its
	 * mean, see `errorStatistic`.
	 */
	targetError?: number;

	/**
	 * Which statistic of the per-point errors `targetError` bounds: `'mean'` (default), `'p95'` or
	 * `'max'`. The mean lets a small, strongly lit spot stay wrong if the rest is right; `'p95'`
	 * and `'max'` insist on it, at the cost of more probes.
	 */
	errorStatistic?: 'mean' | 'p95' | 'max';

	/** Indices of probes that must stay (e.g. the sky probe above the roof); they start the subset. */
	keep?: ArrayLike<number>;

	/** Breaks ties between equally bad candidates (default 1); the same seed gives the same subset. */
	seed?: number;

	/** Directions the error is measured in (default the 26 of {@link IRRADIANCE_ERROR_NORMALS}). */
	normals?: ArrayLike<number>;

	/**
	 * Which probe each step inserts: `'worst'` (default without `fit`) the one predicted worst — fast;
	 * `'mean'` (default with `fit`) the one, of the `trials` predicted worst, whose insertion lowers
	 * the mean error most — about `trials` times slower, and better layouts where one bright spot (a
	 * lamp) would draw every insertion to itself (figures in docs/placement.md).
	 */
	strategy?: 'worst' | 'mean';

	/** Candidates tried per step by `strategy: 'mean'` (an integer ≥ 1, default 16). */
	trials?: number;

	/**
	 * Re-fit the subset at every insertion (`fitProbeSH`: least-squares probe SH over the dense
	 * candidates and `fitSamples`, pulled toward each probe's captured SH), and judge candidates by
	 * the fitted field's error. `true` for the defaults, or `{ gradients, lambda, gradientLambda,
	 * nonNegative }` as in `fitProbeSH` (`gradients`: also fit a gradient per probe — the gradient
	 * objective). The steps use one λ (the given one, or chosen once by cross-validation); the final
	 * fit uses the given λ or 'auto'. Default off: the probes keep their captured SH. With `fit`,
	 * `strategy` defaults to `'mean'`. Costs and figures: docs/placement.md.
	 */
	fit?: boolean | { gradients?: boolean; lambda?: number | 'auto'; gradientLambda?: number | 'auto'; nonNegative?: boolean };

	/**
	 * Swap passes after the insertions (only with `fit`): each probe (starting-set ones included,
	 * not `keep` ones) is tried at a few other candidates (`swapTrials`), and moved when the fitted
	 * error drops. `true` or a number of passes at most (an integer ≥ 0); default 2 passes with `fit`.
	 */
	swaps?: boolean | number;

	/**
	 * Replacements tried per probe and swap pass (an integer ≥ 1, default 6): two thirds its nearest
	 * candidates left out, one third those predicted worst. More find better layouts, at about
	 * proportional cost (Sponza's figures: docs/placement.md).
	 */
	swapTrials?: number;

	/**
	 * How an insertion or swap trial that moves the probes' hull is estimated (only with `fit`):
	 * `'relocate'` (default) locates the points in a new interpolator of the edited layout, outer
	 * cells included; `'local'` edits the layout's tetrahedralization in place, as for a trial inside
	 * the hull, and takes only the points of its changed tetrahedra (outer cells held) — faster, a
	 * rougher ranking (the kept edit is still fitted exactly), other layouts (docs/placement.md).
	 */
	hullTrials?: 'relocate' | 'local';

	/** Where the light matters most: weights both the choice of probes and the reported error ({@link regionWeights}). */
	region?: RegionOfInterest;

	/** One weight ≥ 0 per dense probe (multiplies the region's): how much its error counts. */
	weights?: ArrayLike<number>;

	/**
	 * Extra captured points the error (and, with `fit`, the fit) also uses, beyond the dense
	 * candidates; never candidates themselves. `{ positions, sh, weights? }` as in `fitProbeSH`.
	 */
	fitSamples?: FitSamples;

}

/** Result of {@link reduceProbes}. */
export interface ReduceProbesResult {

	/** Indices into the dense set of the chosen probes, ascending: an ordinary layout to keep editing. */
	keep: Uint32Array;

	/** Positions of the chosen probes, x, y, z each, in `keep` order: `new LightProbeVolume( { positions } )`. */
	positions: Float64Array;

	/**
	 * The same indices in the order they were chosen: the starting set (`keep` option, spanning
	 * probes, box-corner extremes), then one insertion per step. The first n entries are the subset the
	 * algorithm had at size n, so `history` lets you pick another trade-off without rerunning
	 * (after swap passes, a swapped probe's entry holds its replacement).
	 */
	order: Uint32Array;

	/**
	 * The chosen subset's error over the whole dense set and `fitSamples` (mean, p95, max; weighted
	 * by `region` / `weights`) — with `fit`, of the final fitted field.
	 */
	error: IrradianceErrorSummary;

	/** Error of each dense probe under the chosen subset (0 at the chosen probes themselves without `fit`). */
	perPoint: Float64Array;

	/** After each insertion step: the subset size and its error (with `fit`, fitted at the steps' λ). */
	history: { count: Uint32Array; mean: Float64Array; p95: Float64Array; max: Float64Array };

	/** SH of the chosen probes, 27 floats each in `keep` order: fitted with `fit`, else the captured ones. */
	sh: Float32Array;

	/** With `fit: { gradients: true }`, the fitted gradients, 81 floats per probe in `keep` order (layout of `fitProbeSH`); else null. */
	gradients: Float32Array | null;

	/** With `fit`: the final fit's λ, gradient λ and cross-validation error (null when λ were given); else null. */
	fit: { lambda: number; gradientLambda: number; crossValidationError: number | null } | null;

}

/**
 * Turns a dense set of captured probes (a grid, vertex candidates, random samples) into a small
 * arbitrary layout whose tetrahedral interpolation reproduces the dense set's irradiance — the
 * automation the paper suggests in 3.4 ("cluster probes by SH similarity to turn a grid into an
 * arbitrary layout").
 *
 * Greedy refinement: start from a set spanning the dense set's hull — the `keep` probes, as few
 * more as it takes to span a volume (each the farthest from the hull of those before; an area when
 * the whole set is flat), then, while `targetCount` allows, the extreme probe towards each of the
 * 8 corners of the bounding box — then repeat: interpolate every dense probe from the subset (as the
 * runtime will: `createProbeInterpolator` + barycentric weights, hull-nearest weights outside the
 * subset's hull), measure {@link irradianceError} against its captured truth, stop when its
 * mean (or `errorStatistic`) is ≤ `targetError` or the size reaches `targetCount`, else add the
 * worst probe. Points outside the subset's hull count with their extrapolated error, so the hull
 * gets covered where it matters.
 *
 * Cost per step: one tetrahedralization of the subset (rebuilt from scratch; a few hundred probes
 * take about a millisecond) and one point location per dense probe (visited along a Hilbert curve,
 * so each walk is short). Errors come from per-probe irradiance tables blended with the weights
 * (irradiance is linear in SH) and are recomputed only for dense probes whose 4 interpolating
 * probes changed — after an insertion, those near it. 1000 probes reduce to 100 in about 0.3 s,
 * 2000 to 600 in about 2 s.
 *
 * Why insertion rather than removal: from the full set, removal must re-evaluate around every
 * candidate before each step; insertion evaluates once per step, is exact about the subset it
 * returns, and its early steps (few probes) are the cheap ones. A field that is linear in position
 * is reproduced exactly by any tetrahedralization covering the dense hull, so it stops at the
 * starting set; a localised change draws insertions to itself until it is resolved.
 *
 * Greedy insertion does not guarantee the error falls at every step (a new probe re-triangulates
 * its neighbourhood), but the returned subset's error is the one measured for it: with
 * `targetError` it is ≤ the target unless `targetCount` stopped it first or every probe is used.
 *
 * `region` and `weights` weight each point's error, in the choice (a candidate's claim is its
 * weighted error) and in the reported error; `fitSamples` add points to measure (and fit) at.
 * `fit` re-fits the probes' SH at every step and judges the layout by the fitted field; `swaps`
 * then moves probes while that lowers the fitted error. Without these options the result is
 * exactly the plain reduction's.
 * @param positions Dense probe positions, x, y, z each (at least 4, not all on one line).
 * @param sh Their captured SH, 27 floats per probe (three.js `SphericalHarmonics3` order).
 */
export function reduceProbes( positions: ArrayLike<number>, sh: ArrayLike<number>, options: ReduceProbesOptions ): ReduceProbesResult {

	const where = 'reduceProbes';
	const count = assertPoints( where, 'positions', positions, 4 );
	assertSH( where, 'sh', sh, count );
	const settings = readReduceOptions( where, positions, sh, count, options );
	const points = Float64Array.from( positions );
	const rank = seededRanks( count, settings.seed );
	const subset = startingSet( where, points, rank, settings.required, settings.targetCount );
	const run = settings.fit === null ? greedyReduce( where, settings, subset, rank ) : refitReduce( where, settings, subset, rank );

	const chosen = Uint32Array.from( subset.order );
	const keep = chosen.slice().sort();
	const keptPositions = new Float64Array( 3 * keep.length ), keptSH = new Float32Array( 27 * keep.length );
	const final = 'final' in run ? ( run as RefitRun ).final : null;
	const gradients = final?.result.gradients ? new Float32Array( 81 * keep.length ) : null;
	const local = new Map( Array.from( chosen, ( i, s ) => [ i, s ] ) );
	keep.forEach( ( i, k ) => {

		keptPositions.set( points.subarray( 3 * i, 3 * i + 3 ), 3 * k );
		const s = local.get( i )!;
		const probeSH = final === null ? settings.fitSet.sh.subarray( 27 * i, 27 * i + 27 )
			: final.result.sh.subarray( 27 * s, 27 * s + 27 );
		keptSH.set( probeSH, 27 * k );
		if ( gradients !== null ) gradients.set( final!.result.gradients!.subarray( 81 * s, 81 * s + 81 ), 81 * k );

	} );

	const h = run.history;
	return {
		keep,
		positions: keptPositions,
		order: chosen,
		error: run.summary,
		perPoint: run.perPoint.length === count ? run.perPoint : run.perPoint.slice( 0, count ),
		history: {
			count: Uint32Array.from( h.count ), mean: Float64Array.from( h.mean ),
			p95: Float64Array.from( h.p95 ), max: Float64Array.from( h.max ),
		},
		sh: keptSH,
		gradients,
		fit: final === null ? null : {
			lambda: final.result.lambda, gradientLambda: final.result.gradientLambda,
			crossValidationError: final.result.crossValidationError,
		},
	};

}
