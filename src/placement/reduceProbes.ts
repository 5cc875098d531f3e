import { assertFinite, assertInteger, assertNumber, assertPoints, assertSH, assertArrayLike } from '../validate.js';
import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import { hilbertIndex3, mulberry32 } from '../tetrahedra/spatialOrder.js';
import { boundsOf } from '../geometry/boundsOf.js';
import { bestInsertion } from './bestInsertion.js';
import { completeSpan } from './completeSpan.js';
import {
	IRRADIANCE_ERROR_NORMALS, blendRows, irradianceAtNormals, irradianceErrorScale, pointIrradianceError, summarizeErrors,
	type IrradianceErrorSummary,
} from './irradianceError.js';

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
	 * Which probe each step inserts: `'worst'` (default) the one predicted worst — fast; `'mean'`
	 * the one, of the `trials` predicted worst, whose insertion lowers the mean error most — about
	 * `trials` times slower, and better layouts where one bright spot (a lamp) would draw every
	 * insertion to itself (figures in docs/placement.md).
	 */
	strategy?: 'worst' | 'mean';

	/** Candidates tried per step by `strategy: 'mean'` (an integer ≥ 1, default 16). */
	trials?: number;

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
	 * algorithm had at size n, so `history` lets you pick another trade-off without rerunning.
	 */
	order: Uint32Array;

	/** The chosen subset's error over the whole dense set (mean, p95, max). */
	error: IrradianceErrorSummary;

	/** Error of each dense probe under the chosen subset (0 at the chosen probes themselves). */
	perPoint: Float64Array;

	/** After each step: the subset size and its error. */
	history: { count: Uint32Array; mean: Float64Array; p95: Float64Array; max: Float64Array };

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
 * @param positions Dense probe positions, x, y, z each (at least 4, not all on one line).
 * @param sh Their captured SH, 27 floats per probe (three.js `SphericalHarmonics3` order).
 */
export function reduceProbes( positions: ArrayLike<number>, sh: ArrayLike<number>, options: ReduceProbesOptions ): ReduceProbesResult {

	const where = 'reduceProbes';
	const count = assertPoints( where, 'positions', positions, 4 );
	assertSH( where, 'sh', sh, count );
	if ( options === null || typeof options !== 'object' ) throw new TypeError( `${where}: options must be an object with targetCount and/or targetError.` );
	const { targetCount, targetError, seed = 1 } = options;
	if ( targetCount === undefined && targetError === undefined ) {

		throw new RangeError( `${where}: options needs targetCount, targetError or both; neither was given.` );

	}

	if ( targetCount !== undefined ) assertInteger( where, 'options.targetCount', targetCount, 4, count );
	if ( targetError !== undefined ) {

		assertNumber( where, 'options.targetError', targetError );
		if ( targetError < 0 ) throw new RangeError( `${where}: options.targetError must be ≥ 0, got ${targetError}.` );

	}

	assertNumber( where, 'options.seed', seed );
	const statistic = options.errorStatistic ?? 'mean';
	if ( statistic !== 'mean' && statistic !== 'p95' && statistic !== 'max' ) {

		throw new RangeError( `${where}: options.errorStatistic must be 'mean', 'p95' or 'max', got ${JSON.stringify( statistic )}.` );

	}

	const strategy = options.strategy ?? 'worst', trials = options.trials ?? 16;
	if ( strategy !== 'worst' && strategy !== 'mean' ) {

		throw new RangeError( `${where}: options.strategy must be 'worst' or 'mean', got ${JSON.stringify( strategy )}.` );

	}

	assertInteger( where, 'options.trials', trials, 1 );
	const normals = options.normals ?? IRRADIANCE_ERROR_NORMALS;
	const directions = assertPoints( where, 'options.normals', normals, 1 );
	const required = readKeep( where, options.keep, count );
	if ( targetCount !== undefined && required.length > targetCount ) {

		throw new RangeError( `${where}: options.keep has ${required.length} probes, more than options.targetCount (${targetCount}).` );

	}

	const points = Float64Array.from( positions );
	const rank = seededRanks( count, seed );
	const truth = irradianceAtNormals( sh, normals );
	const tableStride = 3 * directions;

	const selected = new Uint8Array( count );
	const order: number[] = [];
	const add = ( i: number ): void => {

		if ( selected[ i ] === 0 ) {

			selected[ i ] = 1;
			order.push( i );

		}

	};

	// Required probes first, then as few as needed to span the set's dimension (so the subset can
	// be tetrahedralized, or triangulated when the set is flat), then the box corners' extremes
	// while room is left: on a box-shaped set those cover the whole hull.
	required.forEach( add );
	completeSpan( where, points, rank, order ).forEach( add );
	if ( targetCount !== undefined && order.length > targetCount ) {

		throw new RangeError( `${where}: options.keep needs ${order.length - required.length} more probes to span a volume, which exceeds options.targetCount (${targetCount}).` );

	}

	for ( const i of boxExtremes( points, rank ) ) {

		if ( targetCount !== undefined && order.length >= targetCount ) break;
		add( i );

	}

	const { scale } = irradianceErrorScale( truth, directions, where );
	const visitOrder = hilbertOrder( points );
	const historyCount: number[] = [], historyMean: number[] = [], historyP95: number[] = [], historyMax: number[] = [];
	const perPoint = new Float64Array( count );
	// Per dense probe, the dense indices (ascending; 0xFFFFFFFE for a zero weight) it was last
	// interpolated from, all 0xFFFFFFFF before the first evaluation. A probe whose tetrahedron (or hull face) survived the last
	// insertion has the same weights, hence the same error: only the changed ones are re-blended.
	const lastSources = new Uint32Array( 4 * count ).fill( 0xFFFFFFFF );
	const row = new Float64Array( tableStride );
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 ), sources = new Uint32Array( 4 );
	const subsetPositions = new Float64Array( 3 * count );
	let summary: IrradianceErrorSummary;

	for ( ;; ) {

		// Interpolate every dense probe from the current subset, as the runtime would.
		const size = order.length;
		for ( let s = 0; s < size; s ++ ) {

			const i = order[ s ];
			subsetPositions[ 3 * s ] = points[ 3 * i ];
			subsetPositions[ 3 * s + 1 ] = points[ 3 * i + 1 ];
			subsetPositions[ 3 * s + 2 ] = points[ 3 * i + 2 ];

		}

		const interpolator = createProbeInterpolator( subsetPositions.subarray( 0, 3 * size ) );
		let hint = - 1;
		for ( let v = 0; v < count; v ++ ) {

			// Visiting along a Hilbert curve keeps each walk from the previous cell short.
			const p = visitOrder[ v ];
			hint = interpolator.interpolate( points[ 3 * p ], points[ 3 * p + 1 ], points[ 3 * p + 2 ], indices, weights, hint );
			for ( let k = 0; k < 4; k ++ ) sources[ k ] = weights[ k ] === 0 ? 0xFFFFFFFE : order[ indices[ k ] ];
			sources.sort();
			const c = 4 * p;
			if ( sources[ 0 ] === lastSources[ c ] && sources[ 1 ] === lastSources[ c + 1 ]
				&& sources[ 2 ] === lastSources[ c + 2 ] && sources[ 3 ] === lastSources[ c + 3 ] ) continue;
			lastSources.set( sources, c );

			blendRows( truth, tableStride, order, indices, weights, row );
			perPoint[ p ] = pointIrradianceError( row, 0, truth, tableStride * p, directions, scale );

		}

		summary = summarizeErrors( perPoint );
		historyCount.push( size ); historyMean.push( summary.mean ); historyP95.push( summary.p95 ); historyMax.push( summary.max );

		if ( targetError !== undefined && summary[ statistic ] <= targetError ) break;
		if ( targetCount !== undefined && size >= targetCount ) break;
		if ( size === count ) break;

		if ( strategy === 'mean' ) {

			// No probe left out has any error: no insertion can help (see below).
			if ( maxLeftOut( perPoint, selected ) <= 0 ) break;
			add( bestInsertion( { points, truth, stride: tableStride, scale, visitOrder, rank }, order, selected, perPoint, trials ) );
			continue;

		}

		// The worst probe not yet in the subset; ties go to the lower seeded rank.
		let worst = - 1, worstError = - 1;
		for ( let p = 0; p < count; p ++ ) {

			if ( selected[ p ] === 1 ) continue;
			const e = perPoint[ p ];
			if ( e > worstError || ( e === worstError && rank[ p ] < rank[ worst ] ) ) {

				worst = p;
				worstError = e;

			}

		}

		// Only probes already in the subset are wrong (coincident probes with different SH, merged by
		// the tetrahedralization): no insertion can help.
		if ( worstError <= 0 ) break;
		add( worst );

	}

	const chosen = Uint32Array.from( order );
	const keep = chosen.slice().sort();
	const keptPositions = new Float64Array( 3 * keep.length );
	keep.forEach( ( i, k ) => keptPositions.set( points.subarray( 3 * i, 3 * i + 3 ), 3 * k ) );
	return {
		keep,
		positions: keptPositions,
		order: chosen,
		error: summary,
		perPoint,
		history: {
			count: Uint32Array.from( historyCount ), mean: Float64Array.from( historyMean ),
			p95: Float64Array.from( historyP95 ), max: Float64Array.from( historyMax ),
		},
	};

}

/** The largest error of a probe not in the subset (−1 when all are in). */
function maxLeftOut( perPoint: Float64Array, selected: Uint8Array ): number {

	let max = - 1;
	for ( let p = 0; p < perPoint.length; p ++ ) if ( selected[ p ] === 0 && perPoint[ p ] > max ) max = perPoint[ p ];
	return max;

}

/** Validated, de-duplicated `keep` indices. */
function readKeep( where: string, keep: ArrayLike<number> | undefined, count: number ): number[] {

	if ( keep === undefined ) return [];
	assertArrayLike( where, 'options.keep', keep );
	assertFinite( where, 'options.keep', keep );
	const out: number[] = [];
	for ( let k = 0; k < keep.length; k ++ ) {

		assertInteger( where, `options.keep[${k}]`, keep[ k ], 0, count - 1 );
		if ( ! out.includes( keep[ k ] ) ) out.push( keep[ k ] );

	}

	return out;

}

/**
 * The probe farthest towards each of the 8 corners of the bounding box, in coordinates scaled to
 * the box (so a long, flat set still gets its real corners). On a box-shaped set these are its
 * corners, whose hull is the whole set's.
 */
function boxExtremes( points: Float64Array, rank: Uint32Array ): number[] {

	const count = points.length / 3;
	const { min, max } = boxOf( points );

	const scale = [ 0, 1, 2 ].map( ( a ) => max[ a ] > min[ a ] ? 2 / ( max[ a ] - min[ a ] ) : 0 );
	const out: number[] = [];
	for ( let corner = 0; corner < 8; corner ++ ) {

		const sx = corner & 1 ? 1 : - 1, sy = corner & 2 ? 1 : - 1, sz = corner & 4 ? 1 : - 1;
		let best = - 1, bestValue = - Infinity;
		for ( let p = 0; p < count; p ++ ) {

			const value = sx * ( points[ 3 * p ] - min[ 0 ] ) * scale[ 0 ] + sy * ( points[ 3 * p + 1 ] - min[ 1 ] ) * scale[ 1 ]
				+ sz * ( points[ 3 * p + 2 ] - min[ 2 ] ) * scale[ 2 ];
			if ( value > bestValue || ( value === bestValue && rank[ p ] < rank[ best ] ) ) {

				best = p;
				bestValue = value;

			}

		}

		out.push( best );

	}

	return out;

}

/** A seeded random rank per probe, used only to break exact ties. */
function seededRanks( count: number, seed: number ): Uint32Array {

	const random = mulberry32( seed );
	const keys = new Float64Array( count );
	for ( let i = 0; i < count; i ++ ) keys[ i ] = random();
	// Equal keys (1 in 2³² per pair) fall back to the index, so ranks are always a permutation.
	const byKey = Array.from( { length: count }, ( _, i ) => i ).sort( ( i, j ) => keys[ i ] - keys[ j ] || i - j );
	const rank = new Uint32Array( count );
	byKey.forEach( ( i, r ) => { rank[ i ] = r; } );
	return rank;

}

/** Dense probe indices sorted along a 3D Hilbert curve over their bounding box (10 bits per axis). */
function hilbertOrder( points: Float64Array ): Uint32Array {

	const count = points.length / 3, bits = 10, cells = ( 1 << bits ) - 1;
	const { min, max } = boxOf( points );

	const cell = ( p: number, a: number ) => max[ a ] > min[ a ]
		? Math.round( ( points[ 3 * p + a ] - min[ a ] ) / ( max[ a ] - min[ a ] ) * cells ) : 0;
	const keys = new Float64Array( count );
	for ( let p = 0; p < count; p ++ ) keys[ p ] = hilbertIndex3( cell( p, 0 ), cell( p, 1 ), cell( p, 2 ), bits );
	return Uint32Array.from( { length: count }, ( _, i ) => i ).sort( ( i, j ) => keys[ i ] - keys[ j ] || i - j );

}

/** The points' bounding box as [x, y, z] corners (`boundsOf`). */
function boxOf( points: Float64Array ): { min: number[]; max: number[] } {

	const b = boundsOf( points );
	return { min: [ b[ 0 ], b[ 1 ], b[ 2 ] ], max: [ b[ 3 ], b[ 4 ], b[ 5 ] ] };

}
