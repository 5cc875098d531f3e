import { describe, expect, it } from 'vitest';
import { toFloat16Bits, fromFloat16Bits, FLOAT16_MAX } from '../../src/io/float16.js';
import { crc32 } from '../../src/io/crc32.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { referenceCRC32, tableCRC32 } from './helpers.js';

// Independent truth for decoding: the IEEE 754 binary16 definition written out per class.
function halfValue( bits: number ): number {

	const s = bits >> 15 ? - 1 : 1, e = ( bits >> 10 ) & 31, m = bits & 1023;
	if ( e === 31 ) return m ? NaN : s * Infinity;
	return e === 0 ? s * m / 16777216 : s * Math.pow( 2, e - 15 ) * ( 1024 + m ) / 1024;

}

describe( 'float16', () => {

	it( 'decodes every one of the 65,536 bit patterns as IEEE 754 binary16 defines them, and re-encodes each finite one to the same bits', () => {

		const failures: number[] = [];
		for ( let bits = 0; bits < 65536; bits ++ ) {

			const v = fromFloat16Bits( bits );
			if ( ! ( Object.is( v, halfValue( bits ) ) || ( Number.isNaN( v ) && Number.isNaN( halfValue( bits ) ) ) ) ) failures.push( bits );
			if ( Number.isFinite( v ) && toFloat16Bits( v ) !== bits ) failures.push( bits );

		}

		expect( failures ).toEqual( [] );

	} );

	it( 'edge values: ±0, largest 65504, smallest normal 2^−14, smallest subnormal 2^−24, ties to even at 2^−25', () => {

		expect( toFloat16Bits( 0 ) ).toBe( 0 );
		expect( toFloat16Bits( - 0 ) ).toBe( 0x8000 );
		expect( toFloat16Bits( 65504 ) ).toBe( 0x7BFF );
		expect( toFloat16Bits( 65519 ) ).toBe( 0x7BFF ); // below the midpoint to 65536: rounds down
		expect( toFloat16Bits( 2 ** - 14 ) ).toBe( 0x0400 );
		expect( toFloat16Bits( 2 ** - 24 ) ).toBe( 0x0001 );
		expect( toFloat16Bits( 2 ** - 25 ) ).toBe( 0 ); // exactly half the smallest subnormal: ties to even (0)
		expect( toFloat16Bits( 1.5 * 2 ** - 25 ) ).toBe( 1 );
		expect( toFloat16Bits( 3 * 2 ** - 25 ) ).toBe( 2 ); // 1.5 units: ties to even (2)
		expect( toFloat16Bits( 1e-10 ) ).toBe( 0 );
		expect( toFloat16Bits( - 1e-10 ) ).toBe( 0x8000 );
		expect( toFloat16Bits( 1 + 2 ** - 11 ) ).toBe( 0x3C00 ); // tie between 1 and 1 + 2^−10: even mantissa
		expect( toFloat16Bits( 1 + 3 * 2 ** - 11 ) ).toBe( 0x3C02 );
		expect( FLOAT16_MAX ).toBe( fromFloat16Bits( 0x7BFF ) );

	} );

	it( 'overflow and non-finite values are reported (−1), not written as Infinity', () => {

		expect( toFloat16Bits( 65520 ) ).toBe( - 1 ); // the midpoint to 65536 rounds to even = overflow
		expect( toFloat16Bits( - 1e6 ) ).toBe( - 1 );
		expect( toFloat16Bits( Infinity ) ).toBe( - 1 );
		expect( toFloat16Bits( NaN ) ).toBe( - 1 );

	} );

	it( 'rounds 100,000 random float32 values of every magnitude to the nearest half (brute force over the two neighbours)', () => {

		const random = mulberry32( 11 );
		const f = new Float32Array( 1 );
		const failures: string[] = [];
		let checked = 0;
		for ( let k = 0; k < 100_000; k ++ ) {

			f[ 0 ] = ( random() - 0.5 ) * 2 ** ( 40 * random() - 26 );
			const v = f[ 0 ];
			const bits = toFloat16Bits( v );
			if ( Math.abs( v ) > 65504 ) {

				if ( bits >= 0 && Math.abs( v ) >= 65520 ) failures.push( `${v} → ${bits}` );
				continue;

			}

			checked ++;
			const h = halfValue( bits ), err = Math.abs( h - v );
			// Neighbouring halves (one ulp either way, across zero by sign) are not closer; ties go to even.
			for ( const other of [ bits + 1, bits - 1, bits ^ 0x8000 ] ) {

				if ( other < 0 || other > 0xFFFF || ( other & 0x7C00 ) === 0x7C00 ) continue;
				const e2 = Math.abs( halfValue( other ) - v );
				if ( e2 < err || ( e2 === err && ( bits & 1 ) ) ) failures.push( `${v} → ${bits}, ${other} is closer` );

			}

			const bound = Math.abs( v ) >= 2 ** - 14 ? Math.abs( v ) * 2 ** - 11 : 2 ** - 25;
			if ( err > bound ) failures.push( `${v}: error ${err} > ${bound}` );

		}

		expect( failures.slice( 0, 5 ) ).toEqual( [] );
		expect( checked ).toBeGreaterThan( 90_000 );

	} );

} );

describe( 'crc32', () => {

	it( 'gives the standard check value 0xCBF43926 for "123456789"', () => {

		expect( crc32( new TextEncoder().encode( '123456789' ) ) ).toBe( 0xCBF43926 );
		expect( crc32( new Uint8Array( 0 ) ) ).toBe( 0 );

	} );

	it( 'equals the bit-at-a-time definition on random data of every length 0..100 and on sub-ranges', () => {

		const random = mulberry32( 3 );
		const bytes = Uint8Array.from( { length: 4099 }, () => Math.floor( random() * 256 ) );
		for ( let n = 0; n <= 100; n ++ ) expect( crc32( bytes, 0, n ) ).toBe( referenceCRC32( bytes, 0, n ) );
		expect( tableCRC32( bytes ) ).toBe( referenceCRC32( bytes ) ); // the tests' fast helper is the same function
		for ( let k = 0; k < 50; k ++ ) {

			const a = Math.floor( random() * 4099 ), b = a + Math.floor( random() * ( 4099 - a ) );
			expect( crc32( bytes, a, b ) ).toBe( referenceCRC32( bytes, a, b ) );

		}

	} );

} );
