/*
 * Exact power-of-two scaling, the normalisation under every scale-sensitive computation of
 * src/tetrahedra and the outer cells (why and what it guarantees: docs/robustness.md). Multiplying
 * a double by 2^k is exact unless the result overflows or falls below 2^−1022 with bits to lose.
 */

const _bits = new Float64Array( 1 );
const _words = new Uint32Array( _bits.buffer );
// Index of the word holding the sign and exponent (little-endian machines keep it second).
const HIGH = new Uint8Array( Uint16Array.of( 1 ).buffer )[ 0 ] === 1 ? 1 : 0;

/** ⌊log2 |x|⌋ exactly, for a finite x ≠ 0 (subnormals included). */
export function exponentOf( x: number ): number {

	_bits[ 0 ] = x;
	const biased = ( _words[ HIGH ] >>> 20 ) & 0x7ff;
	if ( biased !== 0 ) return biased - 1023;
	_bits[ 0 ] = x * 2 ** 64;
	return ( ( _words[ HIGH ] >>> 20 ) & 0x7ff ) - 1023 - 64;

}

/** x · 2^k, in two steps when 2^k alone is not a double (|k| up to 2 × 1023); exact when the result is. */
export function timesPowerOfTwo( x: number, k: number ): number {

	if ( k >= - 1022 && k <= 1023 ) return x * 2 ** k;
	const half = Math.trunc( k / 2 );
	return x * 2 ** half * 2 ** ( k - half );

}

/**
 * The exponent k that brings the largest side of the bounding box `[ minX, minY, minZ, maxX,
 * maxY, maxZ ]` into [1, 2) when the coordinates are multiplied by 2^−k, computed without
 * overflow (a side may exceed the largest double); 0 when every side is 0.
 */
export function extentExponent( bounds: ArrayLike<number> ): number {

	// Halving first: (max/2 − min/2) is the rounded half side, exactly, unless a bound is subnormal.
	const side = Math.max( bounds[ 3 ] / 2 - bounds[ 0 ] / 2, bounds[ 4 ] / 2 - bounds[ 1 ] / 2, bounds[ 5 ] / 2 - bounds[ 2 ] / 2 );
	return side > 0 ? exponentOf( side ) + 1 : 0;

}

/**
 * Multiplies the first `length` entries of `values` by 2^−k in place (scaling up, k < 0, must
 * keep them finite: callers pick k from the values' own extent).
 * @returns The index of the first entry that did not scale exactly (its scaled value fell below
 *   2^−1022 and lost bits; the entries before it are scaled, it and the rest are not), or −1.
 */
export function scaleInPlace( values: Float64Array, length: number, k: number ): number {

	if ( k === 0 ) return - 1;
	if ( k >= - 1022 && k <= 1022 ) {

		const factor = 2 ** - k, inverse = 2 ** k;
		for ( let i = 0; i < length; i ++ ) {

			const v = values[ i ], s = v * factor;
			if ( k > 0 && s * inverse !== v ) return i;
			values[ i ] = s;

		}

		return - 1;

	}

	for ( let i = 0; i < length; i ++ ) {

		const v = values[ i ], s = timesPowerOfTwo( v, - k );
		if ( k > 0 && timesPowerOfTwo( s, k ) !== v ) return i;
		values[ i ] = s;

	}

	return - 1;

}
