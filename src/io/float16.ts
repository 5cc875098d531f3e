/*
 * IEEE 754 binary16 ("half") conversion, independent of Math.f16round (not in Node 20).
 * Encoding rounds to nearest, ties to even, including into the subnormal range (smallest positive
 * value 2^−24 ≈ 5.96e−8; values below half of it become ±0). Values that round beyond the largest
 * finite half (65504) are reported as overflow rather than written as Infinity.
 */

const f32 = new Float32Array( 1 );
const u32 = new Uint32Array( f32.buffer );

/** Largest finite float16 value. */
export const FLOAT16_MAX = 65504;

/**
 * The binary16 bits of `value` (rounded first to float32, then to half, nearest-even).
 * @returns The 16 bits, or −1 when the value is NaN, infinite, or rounds beyond ±65504.
 */
export function toFloat16Bits( value: number ): number {

	if ( typeof value !== 'number' ) throw new TypeError( `toFloat16Bits: value must be a number, got ${typeof value}.` );
	f32[ 0 ] = value;
	const x = u32[ 0 ];
	const sign = ( x >>> 16 ) & 0x8000;
	const e = ( x >>> 23 ) & 0xFF;
	const m = x & 0x7FFFFF;
	if ( e === 0xFF ) return - 1;
	const exponent = e - 127;
	if ( exponent > 15 ) return - 1;
	if ( exponent >= - 14 ) {

		let h = ( ( exponent + 15 ) << 10 ) + ( m >>> 13 );
		const rest = m & 0x1FFF;
		// The carry of a round-up runs into the exponent, which is the right result.
		if ( rest > 0x1000 || ( rest === 0x1000 && ( h & 1 ) ) ) h ++;
		return h >= 0x7C00 ? - 1 : sign | h;

	}

	if ( exponent < - 25 ) return sign;
	// Subnormal half: units of 2^−24; the float32 significand (with its hidden bit) is 2^(exponent−23) per unit.
	const full = m | 0x800000;
	const shift = - exponent - 1;
	let h = full >>> shift;
	const rest = full & ( ( 1 << shift ) - 1 );
	const halfway = 1 << ( shift - 1 );
	if ( rest > halfway || ( rest === halfway && ( h & 1 ) ) ) h ++;
	return sign | h;

}

/** The value of binary16 bits (NaN and ±Infinity patterns decode to NaN and ±Infinity). */
export function fromFloat16Bits( bits: number ): number {

	if ( ! Number.isInteger( bits ) || bits < 0 || bits > 0xFFFF ) throw new RangeError( `fromFloat16Bits: bits must be an integer in 0..65535, got ${String( bits )}.` );
	const sign = bits & 0x8000 ? - 1 : 1;
	const e = ( bits >>> 10 ) & 0x1F;
	const m = bits & 0x3FF;
	if ( e === 0 ) return sign * m * 2 ** - 24;
	if ( e === 0x1F ) return m ? NaN : sign * Infinity;
	return sign * ( 1 + m / 1024 ) * 2 ** ( e - 15 );

}

let table: Float32Array | null = null;

/** All 65,536 half values as float32, built on first use (256 kB): decoding is one lookup per value. */
export function float16Table(): Float32Array {

	if ( table === null ) {

		table = new Float32Array( 65536 );
		for ( let i = 0; i < 65536; i ++ ) table[ i ] = fromFloat16Bits( i );

	}

	return table;

}
