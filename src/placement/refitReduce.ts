import { LocalRefit } from './LocalRefit.js';
import { createRefitContext, fitLayout, type FittedLayout, type RefitContext } from './refitLayout.js';
import type { ReduceSettings } from './reduceOptions.js';
import type { Subset } from './startingSet.js';
import { swapPasses } from './swapPasses.js';
import { bestTrial } from './bestTrial.js';
import type { ReductionRun } from './greedyReduce.js';

/** {@link ReductionRun} of a re-fitting reduction, with the final fit. */
export interface RefitRun extends ReductionRun {

	/** The final layout's fit, probes in `subset.order` order. */
	final: FittedLayout;

}

/**
 * `reduceProbes` with `fit`: every insertion step re-fits the subset (`fitProbeSH` over the fit
 * set, at a λ fixed for the run) and inserts, of the `trials` candidates predicted worst by the
 * fitted field, the one whose insertion lowers the fitted (weighted) mean error most — each trial
 * estimated by {@link LocalRefit} (exactly fitted when it changes the hull). Then swap passes, and
 * a final fit at the asked λ ('auto': cross-validation). Grows and edits `subset` in place.
 */
export function refitReduce( where: string, settings: ReduceSettings, subset: Subset, rank: Uint32Array ): RefitRun {

	const { targetCount, targetError, statistic, strategy, trials, fitSet, fit } = settings;
	const { order, selected } = subset;
	const context = createRefitContext( where, settings );
	const { lambda, gradientLambda } = stepLambdas( context, settings, subset, rank );
	const history: ReductionRun[ 'history' ] = { count: [], mean: [], p95: [], max: [] };
	let layout = fitLayout( context, order, lambda, gradientLambda );
	const local = LocalRefit.create( context, layout, settings.hullTrials === 'local' );
	const cache = new TrialCache( context.denseCount );

	for ( ;; ) {

		const { summary } = layout;
		history.count.push( order.length );
		history.mean.push( summary.mean ); history.p95.push( summary.p95 ); history.max.push( summary.max );
		if ( targetError !== undefined && summary[ statistic ] <= targetError ) break;
		if ( targetCount !== undefined && order.length >= targetCount ) break;
		if ( order.length === fitSet.denseCount ) break;

		const candidates = worstCandidates( context, layout, selected, rank, strategy === 'worst' ? 1 : trials );
		if ( candidates.length === 0 ) break; // no candidate left out has any (weighted) error: no insertion can help
		const trial = candidates.length === 1 ? null : bestTrial( candidates, rank,
			( c ) => local === null ? NaN : cache.get( c, () => local.tryInsert( c ) ),
			( c ) => fitLayout( context, [ ...order, c ], lambda, gradientLambda ).summary.mean - summary.mean );
		const best = trial === null ? candidates[ 0 ] : trial.c;

		const hullMoved = layout.outside[ best ] === 1;
		local?.commitInsert( best );
		selected[ best ] = 1;
		order.push( best );
		layout = fitLayout( context, order, lambda, gradientLambda );
		local?.reset( layout );
		cache.afterInsert( context, layout, hullMoved );

	}

	if ( settings.swapPasses > 0 ) {

		layout = swapPasses( context, layout, subset, settings, rank, local, lambda, gradientLambda );

	}

	// The final fit at the asked λ (cross-validation when 'auto'), unless it is the one already made.
	const final = fit!.lambda === lambda && ( ! fit!.gradients || fit!.gradientLambda === gradientLambda )
		? layout : fitLayout( context, order, fit!.lambda, fit!.gradientLambda );
	return { summary: final.summary, perPoint: final.errors, history, final };

}

/**
 * The candidates not in the subset with the largest weighted error under the fitted field, at most
 * `count`, worst first (ties by seeded rank); only those with an error > 0.
 */
function worstCandidates( context: RefitContext, layout: FittedLayout, selected: Uint8Array, rank: Uint32Array, count: number ): number[] {

	const claimOf = candidateClaims( context, layout );
	const claims: number[] = [];
	for ( let p = 0; p < context.denseCount; p ++ ) {

		if ( selected[ p ] === 0 && claimOf[ p ] > 0 ) claims.push( p );

	}

	const claim = ( p: number ): number => claimOf[ p ];
	return claims.sort( ( a, b ) => claim( b ) - claim( a ) || rank[ a ] - rank[ b ] ).slice( 0, count );

}

/**
 * The λ of the insertion steps and swaps: the given ones, or — for each given as 'auto' — the one
 * cross-validation chooses once, at a layout of the size the run aims at: the starting set grown
 * by farthest-point sampling to `targetCount` (without one, to 1/8 of the candidates, at least
 * twice the starting set), whose spacing is about the result's.
 */
function stepLambdas(
	context: RefitContext, settings: ReduceSettings, subset: Subset, rank: Uint32Array,
): { lambda: number; gradientLambda: number } {

	const fit = settings.fit!;
	const needsGradientLambda = fit.gradients && fit.gradientLambda === 'auto';
	if ( fit.lambda !== 'auto' && ! needsGradientLambda ) {

		return { lambda: fit.lambda, gradientLambda: fit.gradients ? fit.gradientLambda as number : 0 };

	}

	const denseCount = context.denseCount;
	const size = Math.min( denseCount, settings.targetCount ?? Math.max( 2 * subset.order.length, Math.round( denseCount / 8 ) ) );
	const probe = farthestPointLayout( context, subset.order, size, rank );
	const chosen = fitLayout( context, probe, fit.lambda, fit.gradientLambda ).result;
	return { lambda: chosen.lambda, gradientLambda: chosen.gradientLambda };

}

/**
 * `start` grown to `size` candidates, each new one the candidate (of positive weight, when any)
 * farthest from those chosen: an even layout of that size.
 */
function farthestPointLayout( context: RefitContext, start: readonly number[], size: number, rank: Uint32Array ): number[] {

	const { positions, denseCount, weights } = context;
	const layout = start.slice();
	const distance = new Float64Array( denseCount ).fill( Infinity );
	const update = ( i: number ): void => {

		for ( let p = 0; p < denseCount; p ++ ) {

			const d = ( positions[ 3 * p ] - positions[ 3 * i ] ) ** 2 + ( positions[ 3 * p + 1 ] - positions[ 3 * i + 1 ] ) ** 2
				+ ( positions[ 3 * p + 2 ] - positions[ 3 * i + 2 ] ) ** 2;
			if ( d < distance[ p ] ) distance[ p ] = d;

		}

	};

	layout.forEach( update );
	let anyWeighted = false;
	for ( let p = 0; p < denseCount && ! anyWeighted; p ++ ) anyWeighted = weights[ p ] > 0 && distance[ p ] > 0;
	while ( layout.length < size ) {

		let best = - 1;
		for ( let p = 0; p < denseCount; p ++ ) {

			if ( distance[ p ] === 0 || ( anyWeighted && weights[ p ] === 0 ) ) continue;
			const farther = best < 0 || distance[ p ] > distance[ best ]
				|| ( distance[ p ] === distance[ best ] && rank[ p ] < rank[ best ] );
			if ( farther ) best = p;

		}

		if ( best < 0 ) break;
		layout.push( best );
		update( best );

	}

	return layout;

}

/** Each dense candidate's claim: its weighted error under the fitted field (computed once per layout). */
export function candidateClaims( context: RefitContext, layout: FittedLayout ): Float64Array {

	const known = claimCache.get( layout );
	if ( known ) return known;
	const { denseCount, weights } = context, errors = layout.errors;
	const out = new Float64Array( denseCount );
	for ( let p = 0; p < denseCount; p ++ ) out[ p ] = weights[ p ] * errors[ p ];
	claimCache.set( layout, out );
	return out;

}

const claimCache = new WeakMap<FittedLayout, Float64Array>();

/** Steps an insertion trial's estimate is reused for while no insertion came near it. */
const TRIAL_AGE = 3;

/**
 * Insertion trial estimates kept between steps: an insertion changes the fitted field near it
 * (the global re-fit moves the rest very little), so a candidate's estimate is reused while no
 * insertion came within the new probe's reach of it (the farthest point it blends) and the hull
 * stayed, for at most {@link TRIAL_AGE} steps. About a third fewer trials, the same layouts on the
 * benchmark's set (docs/placement.md).
 */
class TrialCache {

	private readonly change: Float64Array;
	private readonly step: Int32Array;
	private now = 0;

	constructor( count: number ) {

		this.change = new Float64Array( count );
		this.step = new Int32Array( count ).fill( - 1 );

	}

	/** Candidate c's estimate: the kept one, else `estimate()` (kept unless NaN). */
	get( c: number, estimate: () => number ): number {

		if ( this.step[ c ] >= 0 && this.now - this.step[ c ] <= TRIAL_AGE ) return this.change[ c ];
		const value = estimate();
		if ( ! Number.isNaN( value ) ) {

			this.change[ c ] = value;
			this.step[ c ] = this.now;

		}

		return value;

	}

	/** Forgets the estimates near the probe just inserted (the layout's last), or all when the hull moved. */
	afterInsert( context: RefitContext, layout: FittedLayout, hullMoved: boolean ): void {

		this.now ++;
		if ( hullMoved ) {

			this.step.fill( - 1 );
			return;

		}

		const { positions, denseCount } = context, i = layout.order.length - 1;
		const x = layout.positions[ 3 * i ], y = layout.positions[ 3 * i + 1 ], z = layout.positions[ 3 * i + 2 ];
		const distance2 = ( j: number ): number => ( positions[ 3 * j ] - x ) ** 2 + ( positions[ 3 * j + 1 ] - y ) ** 2
			+ ( positions[ 3 * j + 2 ] - z ) ** 2;
		let reach = 0;
		const { adjacency, adjacencyStart } = layout;
		for ( let k = adjacencyStart[ i ]; k < adjacencyStart[ i + 1 ]; k ++ ) reach = Math.max( reach, distance2( adjacency[ k ] ) );
		for ( let p = 0; p < denseCount; p ++ ) if ( distance2( p ) <= reach ) this.step[ p ] = - 1;

	}

}
