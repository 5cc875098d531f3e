import type { LocalRefit } from './LocalRefit.js';
import { fitLayout, type FittedLayout, type RefitContext } from './refitLayout.js';
import type { ReduceSettings } from './reduceOptions.js';
import type { Subset } from './startingSet.js';
import { bestTrial } from './bestTrial.js';
import { candidateClaims } from './refitReduce.js';

// A swap must lower the fitted mean error by more than this fraction of it: rounding cannot cycle.
const MIN_GAIN = 1e-9;

/**
 * Swap passes over a fitted layout: for each probe (not a `keep` one), try replacing it by a few
 * candidates — `settings.swapTrials` of them: two thirds its nearest left out, one third the worst
 * predicted — each estimated by {@link LocalRefit} (fitted exactly when the swap changes the hull);
 * the best estimate is fitted exactly and kept only when the fitted error drops. Probes of the
 * starting set move too (a box corner's extreme need not be where a probe helps most; the fitted
 * error, outer cells included, judges a swap that shrinks the hull). Stops after a pass that
 * changed nothing, or after `settings.swapPasses` passes. Edits `subset` in place (a swapped probe
 * keeps its place in `order`).
 * @returns The layout after the last kept swap, fitted at `lambda` / `gradientLambda`.
 */
export function swapPasses(
	context: RefitContext, layout: FittedLayout, subset: Subset, settings: ReduceSettings, rank: Uint32Array,
	local: LocalRefit | null, lambda: number, gradientLambda: number,
): FittedLayout {

	const { order, selected } = subset;
	const fixed = new Set( settings.required );
	const worstCount = Math.floor( settings.swapTrials / 3 ), nearest = settings.swapTrials - worstCount;
	const near = nearestCandidates( context, 4 * nearest );
	for ( let pass = 0; pass < settings.swapPasses; pass ++ ) {

		let changed = false;
		for ( let r = 0; r < order.length; r ++ ) {

			const probe = order[ r ];
			if ( fixed.has( probe ) ) continue;
			const tried = replacements( context, layout, selected, rank, near, probe, nearest, worstCount );
			const current = layout;
			const best = bestTrial( tried, rank, ( c ) => local === null ? NaN : local.tryMove( r, c ),
				( c ) => fitLayout( context, swapped( order, r, c ), lambda, gradientLambda ).summary.mean - current.summary.mean );
			if ( best === null || ! ( best.change < - MIN_GAIN * layout.summary.mean ) ) continue;
			const next = fitLayout( context, swapped( order, r, best.c ), lambda, gradientLambda );
			if ( ! ( next.summary.mean < layout.summary.mean * ( 1 - MIN_GAIN ) ) ) continue; // the estimate was optimistic
			local?.commitMove( r, best.c );
			selected[ probe ] = 0;
			selected[ best.c ] = 1;
			order[ r ] = best.c;
			layout = next;
			local?.reset( layout );
			changed = true;

		}

		if ( ! changed ) break;

	}

	return layout;

}

/** `order` with entry r replaced by c (a copy). */
function swapped( order: readonly number[], r: number, c: number ): number[] {

	const out = order.slice();
	out[ r ] = c;
	return out;

}

/** The replacements tried for `probe`: its nearest candidates not in the subset, then the worst predicted. */
function replacements(
	context: RefitContext, layout: FittedLayout, selected: Uint8Array, rank: Uint32Array, near: Int32Array[], probe: number,
	nearest: number, worstCount: number,
): number[] {

	const out: number[] = [];
	for ( const c of near[ probe ] ) {

		if ( out.length >= nearest ) break;
		if ( selected[ c ] === 0 && context.weights[ c ] > 0 ) out.push( c );

	}

	// The worstCount largest claims, largest first (ties by rank: a strict order), by insertion.
	const claim = candidateClaims( context, layout );
	const worst: number[] = [];
	for ( let p = 0; p < context.denseCount; p ++ ) {

		if ( selected[ p ] === 1 || ! ( claim[ p ] > 0 ) || out.includes( p ) ) continue;
		let at = worst.length;
		const before = ( q: number ): boolean => claim[ q ] > claim[ p ] || ( claim[ q ] === claim[ p ] && rank[ q ] < rank[ p ] );
		while ( at > 0 && ! before( worst[ at - 1 ] ) ) at --;
		if ( at >= worstCount ) continue;
		worst.splice( at, 0, p );
		if ( worst.length > worstCount ) worst.pop();

	}

	return out.concat( worst );

}

/** Per dense candidate, its `k` nearest other candidates, nearest first (ties by index). */
function nearestCandidates( context: RefitContext, k: number ): Int32Array[] {

	const { positions, denseCount } = context;
	const out: Int32Array[] = [];
	const best = new Int32Array( k ), distance = new Float64Array( k );
	for ( let i = 0; i < denseCount; i ++ ) {

		let found = 0;
		for ( let p = 0; p < denseCount; p ++ ) {

			if ( p === i ) continue;
			const d = ( positions[ 3 * p ] - positions[ 3 * i ] ) ** 2 + ( positions[ 3 * p + 1 ] - positions[ 3 * i + 1 ] ) ** 2
				+ ( positions[ 3 * p + 2 ] - positions[ 3 * i + 2 ] ) ** 2;
			if ( found === k && d >= distance[ k - 1 ] ) continue;
			// Insertion into the sorted short list.
			let at = found < k ? found ++ : k - 1;
			while ( at > 0 && distance[ at - 1 ] > d ) {

				distance[ at ] = distance[ at - 1 ];
				best[ at ] = best[ at - 1 ];
				at --;

			}

			distance[ at ] = d;
			best[ at ] = p;

		}

		out.push( best.slice( 0, found ) );

	}

	return out;

}
