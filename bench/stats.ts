/**
 * Timing helpers: repeated runs summarized as median / min / max.
 */

import { setFlagsFromString } from 'node:v8';
import { runInNewContext } from 'node:vm';

export interface Summary {
	median: number;
	min: number;
	max: number;
	runs: number;
}

export function summarize( values: number[] ): Summary {

	const sorted = [ ...values ].sort( ( a, b ) => a - b );
	const middle = sorted.length >> 1;
	const median = sorted.length % 2 ? sorted[ middle ] : ( sorted[ middle - 1 ] + sorted[ middle ] ) / 2;
	return { median, min: sorted[ 0 ], max: sorted[ sorted.length - 1 ], runs: sorted.length };

}

setFlagsFromString( '--expose-gc' );
const gc = runInNewContext( 'gc' ) as () => void;

/** Runs a full garbage collection, so that one run's garbage is not collected during the next. */
export function collectGarbage(): void {

	gc();

}

/**
 * Times `fn` in milliseconds: warm-up calls (the last one's result is returned, for checking),
 * then as many runs as fit in `budgetMs` judging by the last warm-up, between 3 and `maxRuns`
 * (1 when one call takes over 10 s).
 */
export function timeRuns<T>( fn: () => T, maxRuns: number, budgetMs: number ): { summary: Summary, result: T } {

	// Warm up (JIT) with up to 10 calls or 300 ms; the last call's time sizes the runs.
	let result: T, warmUp = 0, spent = 0;
	for ( let calls = 0; calls < 10 && spent < 300; calls ++ ) {

		collectGarbage();
		const start = performance.now();
		result = fn();
		warmUp = performance.now() - start;
		spent += warmUp;

	}

	const runs = warmUp > 10_000 ? 1 : Math.max( 3, Math.min( maxRuns, Math.floor( budgetMs / Math.max( warmUp, 1e-3 ) ) ) );
	const times: number[] = [];
	for ( let i = 0; i < runs; i ++ ) {

		collectGarbage();
		const start = performance.now();
		fn();
		times.push( performance.now() - start );

	}

	return { summary: summarize( times ), result: result! };

}
