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
	const local = LocalRefit.create( context, layout );

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
			( c ) => local === null ? NaN : local.tryInsert( c ),
			( c ) => fitLayout( context, [ ...order, c ], lambda, gradientLambda ).summary.mean - summary.mean );
		const best = trial === null ? candidates[ 0 ] : trial.c;

		local?.commitInsert( best );
		selected[ best ] = 1;
		order.push( best );
		layout = fitLayout( context, order, lambda, gradientLambda );
		local?.reset( layout );

	}

	if ( settings.swapPasses > 0 ) {

		layout = swapPasses( context, layout, subset, settings, rank, local, lambda, gradientLambda, history.count[ 0 ] );

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

	const claims: number[] = [];
	for ( let p = 0; p < context.denseCount; p ++ ) {

		if ( selected[ p ] === 0 && context.weights[ p ] * layout.errors[ p ] > 0 ) claims.push( p );

	}

	const claim = ( p: number ): number => context.weights[ p ] * layout.errors[ p ];
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
