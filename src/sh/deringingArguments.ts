/**
 * Argument checks shared by the de-ringing functions (window, minimum over the sphere,
 * non-negative search); errors name the function and the argument.
 * @internal
 */

import { SH_FLOATS, assertArrayLike, assertInteger, assertNumber } from '../validate.js';

/** Throws unless `value` is a window strength, a number in [0, 1]. */
export function assertStrength( where: string, name: string, value: unknown ): asserts value is number {

	assertNumber( where, name, value );
	if ( value < 0 || value > 1 ) {

		throw new RangeError( `${where}: ${name} must be in [0, 1] (0 = no window, 1 = only L00 kept), got ${value}.` );

	}

}

/** Throws unless `sh` is array-like with a length that is a positive multiple of 27. */
export function assertSHArray( where: string, sh: unknown ): asserts sh is ArrayLike<number> {

	assertArrayLike( where, 'sh', sh );
	if ( sh.length === 0 || sh.length % SH_FLOATS !== 0 ) {

		throw new RangeError(
			`${where}: sh must have a length that is a positive multiple of 27 (9 RGB coefficients per probe), got ${sh.length}.`,
		);

	}

}

/**
 * Validates `sh` and the probe range; checks only the probes in the range for finiteness.
 * @returns The number of probes in the range.
 */
export function assertProbeRange( where: string, sh: unknown, firstProbe: unknown, probeCount: unknown ): number {

	assertSHArray( where, sh );
	const total = sh.length / SH_FLOATS;
	assertInteger( where, 'firstProbe', firstProbe, 0, total - 1 );
	const count = probeCount ?? total - firstProbe;
	assertInteger( where, 'probeCount', count, 0, total - firstProbe );
	for ( let p = firstProbe; p < firstProbe + count; p ++ ) assertProbeFinite( where, sh, p * SH_FLOATS );
	return count;

}

/** Throws unless the 27 values of the probe starting at `o` are finite numbers. */
export function assertProbeFinite( where: string, sh: ArrayLike<number>, o: number ): void {

	for ( let i = o; i < o + SH_FLOATS; i ++ ) {

		const v = sh[ i ];
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) {

			throw new RangeError( `${where}: sh[${i}] is ${String( v )}; all values must be finite numbers.` );

		}

	}

}
