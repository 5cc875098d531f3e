import { boundsOf } from '../geometry/boundsOf.js';
import { DegenerateInputError } from './DegenerateInputError.js';
import { extentExponent, scaleInPlace } from './powerOfTwo.js';

const _bounds = new Float64Array( 6 );

/**
 * Scales the first `count` points of `p` (flat x, y, z) in place by 2^−k, the power of two that
 * brings the largest side of their bounding box into [1, 2): exact, so every exact predicate keeps
 * its sign, and the same whatever power of two the input was scaled by (docs/robustness.md).
 * @param caller Function name for the error message; `name` the argument's.
 * @returns k.
 * @throws {DegenerateInputError} (`reason: 'unrepresentable'`) when a coordinate does not survive
 *   the scaling exactly: it is below 2^−1022 of the layout's extent (but not 0). `p` is then
 *   partly scaled.
 */
export function normalizePoints( caller: string, name: string, p: Float64Array, count: number ): number {

	const k = extentExponent( boundsOf( p, count, _bounds ) );
	const bad = scaleInPlace( p, 3 * count, k );
	if ( bad >= 0 ) throw unrepresentable( caller, `${name}[${bad}]`, p[ bad ], k );
	return k;

}

/** The error for a coordinate `value` that float64 cannot hold beside a layout of extent about 2^k. */
export function unrepresentable( caller: string, what: string, value: number, k: number ): DegenerateInputError {

	return new DegenerateInputError( 'unrepresentable', `${caller}: ${what} is ${value}, below 2^−1022 of the layout's extent `
		+ `(about 2^${k}) but not 0: float64 cannot hold it once the layout is scaled to unit size. Round it to 0.` );

}
