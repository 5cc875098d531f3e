import { describe, expect, it } from 'vitest';
import { hilbertIndex3, insertionOrder, mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * The insertion order decides which cell slots the builder hands out, so it is part of the output
 * bytes: a faster sort must give the same order. The reference below is the definition: the indices
 * shuffled with mulberry32( seed ) (Fisher–Yates from the end), rounds [0, n/2^r) … [n/2, n), each
 * round sorted by Hilbert index over the bounding cube (10 bits per axis), equal indices in shuffled
 * order — written with a comparator sort, independent of the radix and packed sorts it checks.
 */
function referenceOrder( points: Float64Array, indices: Uint32Array, seed: number ): number[] {

	const n = indices.length, order = Array.from( indices ), random = mulberry32( seed );
	for ( let i = n - 1; i > 0; i -- ) {

		const j = Math.floor( random() * ( i + 1 ) );
		[ order[ i ], order[ j ] ] = [ order[ j ], order[ i ] ];

	}

	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( const v of order ) for ( let a = 0; a < 3; a ++ ) {

		min[ a ] = Math.min( min[ a ], points[ 3 * v + a ] );
		max[ a ] = Math.max( max[ a ], points[ 3 * v + a ] );

	}

	const scale = 1023 / ( Math.max( max[ 0 ] - min[ 0 ], max[ 1 ] - min[ 1 ], max[ 2 ] - min[ 2 ] ) || 1 );
	const cellOf = ( v: number, a: number ) => Math.min( 1023, Math.floor( ( points[ 3 * v + a ] - min[ a ] ) * scale ) );
	const keys = order.map( ( v ) => hilbertIndex3( cellOf( v, 0 ), cellOf( v, 1 ), cellOf( v, 2 ), 10 ) );

	const bounds: number[] = [];
	for ( let end = n; ; end >>>= 1 ) {

		bounds.unshift( end );
		if ( end <= 64 ) break;

	}

	const result: number[] = [];
	let start = 0;
	for ( const stop of bounds ) {

		const positions = Array.from( { length: stop - start }, ( _, i ) => start + i );
		positions.sort( ( a, b ) => keys[ a ] - keys[ b ] || a - b );
		for ( const position of positions ) result.push( order[ position ] );
		start = stop;

	}

	return result;

}

/** Points in tight clumps around a few sites, so that many share a Hilbert cell (equal keys). */
function clumpedPoints( n: number, seed: number ): Float64Array {

	const random = seededRandom( seed );
	const points = new Float64Array( 3 * n );
	for ( let i = 0; i < n; i ++ ) {

		const site = Math.floor( random() * 12 );
		for ( let a = 0; a < 3; a ++ ) points[ 3 * i + a ] = ( ( site * ( a + 3 ) ) % 7 ) / 6 + random() * 1e-5;

	}

	return points;

}

describe( 'hilbertIndex3', () => {

	it( 'numbers every cell of a 2^b grid once, consecutive numbers on neighbouring cells (b = 1 … 5)', () => {

		for ( let bits = 1; bits <= 5; bits ++ ) {

			const side = 1 << bits, cellAt = new Int32Array( side ** 3 ).fill( - 1 );
			for ( let x = 0; x < side; x ++ ) for ( let y = 0; y < side; y ++ ) for ( let z = 0; z < side; z ++ ) {

				const h = hilbertIndex3( x, y, z, bits );
				expect( cellAt[ h ], `bits ${bits}: index ${h} given twice` ).toBe( - 1 );
				cellAt[ h ] = ( x * side + y ) * side + z;

			}

			for ( let h = 1; h < side ** 3; h ++ ) {

				const a = cellAt[ h - 1 ], b = cellAt[ h ];
				const steps = Math.abs( Math.floor( a / side / side ) - Math.floor( b / side / side ) ) +
					Math.abs( Math.floor( a / side ) % side - Math.floor( b / side ) % side ) + Math.abs( ( a % side ) - ( b % side ) );
				expect( steps, `bits ${bits}: indices ${h - 1}, ${h}` ).toBe( 1 );

			}

		}

	} );

} );

describe( 'insertionOrder', () => {

	it( 'is the shuffled, round-wise Hilbert-sorted order, equal keys in shuffled order (small and radix-sorted rounds)', () => {

		const cases: [ Float64Array, number ][] = [
			[ randomPoints( 5, 1 ), 1 ], [ randomPoints( 100, 2 ), 3 ], [ randomPoints( 1000, 3 ), 1 ], [ randomPoints( 20000, 4 ), 7 ],
			[ clumpedPoints( 3000, 5 ), 1 ], [ clumpedPoints( 9000, 6 ), 2 ],
		];
		for ( const [ points, seed ] of cases ) {

			const n = points.length / 3;
			// A subset of the ids, as insertAll passes (the initial tetrahedron's four left out).
			const indices = Uint32Array.from( { length: n - Math.min( 4, n - 1 ) }, ( _, i ) => i + Math.min( 4, n - 1 ) );
			expect( Array.from( insertionOrder( points, indices, seed ) ), `${n} points, seed ${seed}` ).toEqual( referenceOrder( points, indices, seed ) );

		}

	} );

	it( 'the clumped sets do have rounds with equal keys (the tie order is exercised)', () => {

		const points = clumpedPoints( 3000, 5 );
		const keys = new Set<number>();
		for ( let i = 0; i < 3000; i ++ ) {

			const cell = ( a: number ) => Math.min( 1023, Math.floor( points[ 3 * i + a ] * 1023 ) );
			keys.add( hilbertIndex3( cell( 0 ), cell( 1 ), cell( 2 ), 10 ) );

		}

		expect( keys.size ).toBeLessThan( 100 );

	} );

} );
