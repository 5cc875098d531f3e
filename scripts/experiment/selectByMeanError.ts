/**
 * A second automatic placement, the experiment's own, to tell whether the library's `reduceProbes`
 * (insert the worst-predicted probe) or the claim itself limits the automatic layouts:
 * forward selection on the mean error. From the same starting set as `reduceProbes`, each step
 * tries the `candidatesPerStep` dense probes predicted worst and keeps the one whose insertion
 * lowers the dense set's mean error most. It measures exactly what `reduceProbes` measures (the
 * library's irradiance error over the dense set, tetrahedral interpolation as at runtime), only
 * the choice differs. Like `reduceProbes`, it never sees the ground truth.
 */

import { IRRADIANCE_ERROR_NORMALS, createProbeInterpolator } from '../../src/math.js';
import { blendRows, irradianceAtNormals, irradianceErrorScale, pointIrradianceError } from '../../src/placement/irradianceError.js';

export interface SelectOptions {

	/** Dense indices the selection starts from (e.g. `reduceProbes`'s first `history.count[0]`), spanning a volume. */
	start: ArrayLike<number>;

	/** Stop at this many probes. */
	targetCount: number;

	/** Candidates tried per step: the dense probes with the largest current error (default 32). */
	candidatesPerStep?: number;

}

export interface SelectResult {

	/** Dense indices in the order chosen; the first n are the layout of n probes. */
	order: Uint32Array;

	/** Dense mean error of each prefix, index n − start.length. */
	mean: Float64Array;

}

export function selectByMeanError( positions: ArrayLike<number>, sh: ArrayLike<number>, options: SelectOptions ): SelectResult {

	const count = positions.length / 3;
	const { targetCount, candidatesPerStep = 32 } = options;
	if ( ! ( targetCount >= options.start.length && targetCount <= count ) ) throw new RangeError( `selectByMeanError: targetCount ${targetCount} must be in ${options.start.length}..${count}.` );
	const normals = IRRADIANCE_ERROR_NORMALS, directions = normals.length / 3, stride = 3 * directions;
	const table = irradianceAtNormals( sh, normals );
	const { scale } = irradianceErrorScale( table, directions, 'selectByMeanError' );
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 ), row = new Float64Array( stride );
	const subset = new Float64Array( 3 * count );

	/** Mean dense error of the layout `chosen` (dense indices); per-point errors into `perPoint` when given. */
	const evaluate = ( chosen: readonly number[], perPoint?: Float64Array ): number => {

		for ( let s = 0; s < chosen.length; s ++ ) for ( let a = 0; a < 3; a ++ ) subset[ 3 * s + a ] = positions[ 3 * chosen[ s ] + a ];
		const interpolator = createProbeInterpolator( subset.subarray( 0, 3 * chosen.length ) );
		let hint = - 1, sum = 0;
		for ( let p = 0; p < count; p ++ ) {

			hint = interpolator.interpolate( positions[ 3 * p ], positions[ 3 * p + 1 ], positions[ 3 * p + 2 ], indices, weights, hint );
			blendRows( table, stride, chosen, indices, weights, row );
			const e = pointIrradianceError( row, 0, table, stride * p, directions, scale );
			if ( perPoint ) perPoint[ p ] = e;
			sum += e;

		}

		return sum / count;

	};

	const chosen = Array.from( options.start );
	const selected = new Uint8Array( count );
	for ( const i of chosen ) selected[ i ] = 1;
	const perPoint = new Float64Array( count );
	const means = [ evaluate( chosen, perPoint ) ];
	while ( chosen.length < targetCount ) {

		// The worst-predicted probes not yet chosen: where an insertion can help most.
		const candidates: number[] = [];
		for ( let p = 0; p < count; p ++ ) if ( selected[ p ] === 0 ) candidates.push( p );
		candidates.sort( ( a, b ) => perPoint[ b ] - perPoint[ a ] || a - b );
		let best = - 1, bestMean = Infinity;
		for ( const candidate of candidates.slice( 0, candidatesPerStep ) ) {

			chosen.push( candidate );
			const mean = evaluate( chosen );
			chosen.pop();
			if ( mean < bestMean ) { bestMean = mean; best = candidate; }

		}

		if ( best < 0 ) break;
		chosen.push( best );
		selected[ best ] = 1;
		means.push( evaluate( chosen, perPoint ) );

	}

	return { order: Uint32Array.from( chosen ), mean: Float64Array.from( means ) };

}
