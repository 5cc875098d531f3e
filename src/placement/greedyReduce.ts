import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import { bestInsertion } from './bestInsertion.js';
import { blendRows, irradianceAtNormals, irradianceErrorScale, pointIrradianceError, summarizeErrors, type IrradianceErrorSummary } from './irradianceError.js';
import type { ReduceSettings } from './reduceOptions.js';
import { hilbertOrder, type Subset } from './startingSet.js';

/** What a reduction run leaves: the final subset's error and the error after each step. */
export interface ReductionRun {

	/** The final subset's error summary over the fit set (weighted when it is). */
	summary: IrradianceErrorSummary;

	/** Error of every point of the fit set (dense candidates first) under the final subset. */
	perPoint: Float64Array;

	/** After each step: the subset size and its error. */
	history: { count: number[]; mean: number[]; p95: number[]; max: number[] };

}

/**
 * `reduceProbes` without `fit`: the probes keep their captured SH. Grows `subset` in place —
 * insert the worst-predicted candidate (`strategy: 'worst'`) or the best of the `trials` worst
 * (`'mean'`) — until `targetError` or `targetCount` is met. Errors are measured over the fit set
 * (the dense candidates, plus `fitSamples`), weighted by its weights: a candidate's claim to be
 * inserted is its weighted error.
 */
export function greedyReduce( where: string, settings: ReduceSettings, subset: Subset, rank: Uint32Array ): ReductionRun {

	const { targetCount, targetError, statistic, strategy, trials, normals, directions, fitSet } = settings;
	const { order, selected } = subset;
	const count = fitSet.positions.length / 3, denseCount = fitSet.denseCount, points = fitSet.positions;
	const weights = fitSet.weights ?? undefined;
	const truth = irradianceAtNormals( fitSet.sh, normals );
	const tableStride = 3 * directions;
	const { scale } = irradianceErrorScale( truth, directions, where, weights );
	const visitOrder = hilbertOrder( points );
	const history: ReductionRun[ 'history' ] = { count: [], mean: [], p95: [], max: [] };
	const perPoint = new Float64Array( count );
	// Per point, the dense indices (ascending; 0xFFFFFFFE for a zero weight) it was last
	// interpolated from, all 0xFFFFFFFF before the first evaluation, and their weights. A point whose
	// tetrahedron survived the last insertion has the same weights, hence the same error: only the
	// changed ones are re-blended. (Outside the hull the same three probes can weigh differently once
	// the hull changes elsewhere: the weights are compared too, beyond rounding.)
	const lastSources = new Uint32Array( 4 * count ).fill( 0xFFFFFFFF ), lastWeights = new Float64Array( 4 * count );
	const row = new Float64Array( tableStride );
	const indices = new Uint32Array( 4 ), blendWeights = new Float64Array( 4 ), sources = new Uint32Array( 4 );
	const subsetPositions = new Float64Array( 3 * denseCount );
	const claim = ( p: number ): number => weights === undefined ? perPoint[ p ] : weights[ p ] * perPoint[ p ];
	let summary: IrradianceErrorSummary;

	for ( ;; ) {

		// Interpolate every point from the current subset, as the runtime would.
		const size = order.length;
		for ( let s = 0; s < size; s ++ ) subsetPositions.set( points.subarray( 3 * order[ s ], 3 * order[ s ] + 3 ), 3 * s );
		const interpolator = createProbeInterpolator( subsetPositions.subarray( 0, 3 * size ) );
		let hint = - 1;
		for ( let v = 0; v < count; v ++ ) {

			// Visiting along a Hilbert curve keeps each walk from the previous cell short.
			const p = visitOrder[ v ];
			hint = interpolator.interpolate( points[ 3 * p ], points[ 3 * p + 1 ], points[ 3 * p + 2 ], indices, blendWeights, hint );
			for ( let k = 0; k < 4; k ++ ) sources[ k ] = blendWeights[ k ] === 0 ? 0xFFFFFFFE : order[ indices[ k ] ];
			sources.sort();
			const c = 4 * p;
			if ( sources[ 0 ] === lastSources[ c ] && sources[ 1 ] === lastSources[ c + 1 ] && sources[ 2 ] === lastSources[ c + 2 ]
				&& sources[ 3 ] === lastSources[ c + 3 ] && sameWeights( sources, order, indices, blendWeights, lastWeights, c ) ) continue;
			lastSources.set( sources, c );
			for ( let k = 0; k < 4; k ++ ) lastWeights[ c + k ] = weightOf( sources[ k ], order, indices, blendWeights );

			blendRows( truth, tableStride, order, indices, blendWeights, row );
			perPoint[ p ] = pointIrradianceError( row, 0, truth, tableStride * p, directions, scale );

		}

		summary = summarizeErrors( perPoint, weights );
		history.count.push( size ); history.mean.push( summary.mean ); history.p95.push( summary.p95 ); history.max.push( summary.max );

		if ( targetError !== undefined && summary[ statistic ] <= targetError ) break;
		if ( targetCount !== undefined && size >= targetCount ) break;
		if ( size === denseCount ) break;

		// The worst candidate not yet in the subset; ties go to the lower seeded rank.
		let worst = - 1, worstClaim = - 1;
		for ( let p = 0; p < denseCount; p ++ ) {

			if ( selected[ p ] === 1 ) continue;
			const e = claim( p );
			if ( e > worstClaim || ( e === worstClaim && rank[ p ] < rank[ worst ] ) ) {

				worst = p;
				worstClaim = e;

			}

		}

		// Only probes already in the subset are wrong (coincident probes with different SH, merged by
		// the tetrahedralization), or only points of weight 0: no insertion can help.
		if ( worstClaim <= 0 ) break;
		const context = { points, truth, stride: tableStride, scale, visitOrder, rank, weights: fitSet.weights };
		const next = strategy === 'mean' ? bestInsertion( context, order, selected, perPoint, trials ) : worst;
		selected[ next ] = 1;
		order.push( next );

	}

	return { summary, perPoint, history };

}

/** The weight the blend gives dense probe `source` (0 for none). */
function weightOf( source: number, order: readonly number[], indices: Uint32Array, weights: Float64Array ): number {

	for ( let k = 0; k < 4; k ++ ) if ( weights[ k ] !== 0 && order[ indices[ k ] ] === source ) return weights[ k ];
	return 0;

}

/** Whether each of `sources` (sorted) gets the weight stored for it at `offset`, within 1e-12. */
function sameWeights(
	sources: Uint32Array, order: readonly number[], indices: Uint32Array, weights: Float64Array, lastWeights: Float64Array, offset: number,
): boolean {

	for ( let k = 0; k < 4; k ++ ) {

		if ( Math.abs( weightOf( sources[ k ], order, indices, weights ) - lastWeights[ offset + k ] ) > 1e-12 ) return false;

	}

	return true;

}
