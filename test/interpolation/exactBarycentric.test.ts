import { describe, expect, it } from 'vitest';
import { exactBarycentric } from '../../src/interpolation/exactBarycentric.js';
import { seededRandom } from '../helpers/pointSets.js';

/*
 * exactBarycentric against an independent truth: the sub-volume determinants in BigInt (every
 * double is an integer multiple of 2^−1074), their ratios by long division.
 */

const view = new DataView( new ArrayBuffer( 8 ) );

/** A double as the exact integer value · 2^1074. */
function exact( value: number ): bigint {

	view.setFloat64( 0, value );
	const bits = view.getBigUint64( 0 ), exponent = Number( ( bits >> 52n ) & 0x7ffn );
	let mantissa = bits & ( ( 1n << 52n ) - 1n );
	if ( exponent > 0 ) mantissa |= 1n << 52n;
	const scaled = mantissa << BigInt( Math.max( exponent, 1 ) - 1 );
	return bits >> 63n ? - scaled : scaled;

}

type Vector = [ bigint, bigint, bigint ];

function minus( a: Vector, b: Vector ): Vector {

	return [ a[ 0 ] - b[ 0 ], a[ 1 ] - b[ 1 ], a[ 2 ] - b[ 2 ] ];

}

/** det[ b − a, c − a, d − a ]: positive for a positively oriented tetrahedron abcd. */
function orientation( a: Vector, b: Vector, c: Vector, d: Vector ): bigint {

	const [ u, v, w ] = [ minus( b, a ), minus( c, a ), minus( d, a ) ];
	return u[ 0 ] * ( v[ 1 ] * w[ 2 ] - v[ 2 ] * w[ 1 ] ) - u[ 1 ] * ( v[ 0 ] * w[ 2 ] - v[ 2 ] * w[ 0 ] )
		+ u[ 2 ] * ( v[ 0 ] * w[ 1 ] - v[ 1 ] * w[ 0 ] );

}

/** a / b to about 60 significant bits, as a double. */
function ratio( a: bigint, b: bigint ): number {

	if ( a === 0n ) return 0;
	const negative = ( a < 0n ) !== ( b < 0n ), n = a < 0n ? - a : a, d = b < 0n ? - b : b;
	const shift = BigInt( Math.max( 0, d.toString( 2 ).length - n.toString( 2 ).length + 64 ) );
	const value = Number( ( n << shift ) / d ) / 2 ** Number( shift );
	return negative ? - value : value;

}

describe( 'exactBarycentric', () => {

	it( 'matches BigInt sub-volume ratios (signs exact, values to 4 ulps) on 1,500 near-flat and ordinary tetrahedra at scales 1e-300…1e300, 4 points each', () => {

		const random = seededRandom( 4242 ), out = new Float64Array( 4 );
		let worst = 0, checked = 0;
		for ( let trial = 0; trial < 1500; trial ++ ) {

			const scale = 10 ** ( ( random() - 0.5 ) * 600 ), offset = ( random() - 0.5 ) * 10 ** ( random() * 8 ) * scale;
			const flat = trial % 2 === 0, angle = random() * 6;
			const positions = new Float64Array( 12 );
			for ( let i = 0; i < 4; i ++ ) {

				const x = random(), y = random(), z = flat ? 0.3 * x + 0.2 * y + ( random() - 0.5 ) * 1e-15 : random();
				positions[ 3 * i ] = offset + ( Math.cos( angle ) * x - Math.sin( angle ) * z ) * scale;
				positions[ 3 * i + 1 ] = offset + y * scale;
				positions[ 3 * i + 2 ] = offset + ( Math.sin( angle ) * x + Math.cos( angle ) * z ) * scale;

			}

			const point = ( i: number ): Vector => [
				exact( positions[ 3 * i ] ), exact( positions[ 3 * i + 1 ] ), exact( positions[ 3 * i + 2 ] ),
			];
			const sign = orientation( point( 0 ), point( 1 ), point( 2 ), point( 3 ) );
			if ( sign === 0n ) continue;
			const tetrahedra = new Uint32Array( sign > 0n ? [ 0, 1, 2, 3 ] : [ 1, 0, 2, 3 ] );
			const v = Array.from( tetrahedra, point );
			const volume = orientation( v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ] );
			for ( let q = 0; q < 4; q ++ ) {

				// Inside (a convex combination) or beyond a face.
				const b = [ random(), random(), random(), random() ];
				if ( q >= 2 ) b[ q ] -= 3;
				const sum = b[ 0 ] + b[ 1 ] + b[ 2 ] + b[ 3 ];
				const [ x, y, z ] = [ 0, 1, 2 ].map(
					( c ) => b.reduce( ( s, bi, i ) => s + bi / sum * positions[ 3 * tetrahedra[ i ] + c ], 0 ) );
				const result = exactBarycentric( positions, tetrahedra, 0, x, y, z, out );
				const Q: Vector = [ exact( x ), exact( y ), exact( z ) ];
				const sub = [ 0, 1, 2, 3 ].map( ( i ) => {

					const w = v.slice() as Vector[];
					w[ i ] = Q;
					return orientation( w[ 0 ], w[ 1 ], w[ 2 ], w[ 3 ] );

				} );
				const inside = sub.every( ( s ) => s >= 0n );
				expect( result < 0 ).toBe( inside );
				if ( ! inside ) expect( sub[ result ] < 0n ).toBe( true );
				for ( let i = 0; i < 4; i ++ ) {

					const truth = ratio( sub[ i ], volume );
					expect( Math.sign( out[ i ] ) || 0 ).toBe( Math.sign( truth ) || 0 );
					worst = Math.max( worst, Math.abs( out[ i ] - truth ) / Math.max( Math.abs( truth ), inside ? 1 : 0 ) );

				}

				checked ++;

			}

		}

		expect( checked ).toBeGreaterThan( 5000 );
		expect( worst ).toBeLessThan( 4 * 2 ** - 52 );

	} );

} );
