import type { Envelope } from './envelope.js';

// A pivot below this fraction of its diagonal entry means the matrix is singular to working
// precision (the rank deficiency of a λ = 0 fit): the caller adds a ridge and factors again.
const PIVOT_TOLERANCE = 1e-12;

/**
 * Factors the symmetric matrix stored in `values` (layout `envelope`) as L·Lᵀ in place, row by
 * row (L's rows fill only their envelope). Returns false, leaving `values` half overwritten,
 * when a pivot is not clearly positive (singular or indefinite to working precision).
 */
export function factorCholesky( envelope: Envelope, values: Float64Array ): boolean {

	const { size, first } = envelope;
	for ( let r = 0; r < size; ) {

		// The 4 unknowns of a gradient probe share their first column: their rows go together, each
		// entry of an earlier row loaded once for all four (the same arithmetic, in the same order).
		const f = first[ r ];
		const block = r + 3 < size && first[ r + 1 ] === f && first[ r + 2 ] === f && first[ r + 3 ] === f ? 4 : 1;
		if ( block === 4 ) eliminateFourRows( envelope, values, r ); else eliminateRow( envelope, values, r, f, r );
		for ( let row = r; row < r + block; row ++ ) if ( ! finishRow( envelope, values, row, r ) ) return false;
		r += block;

	}

	return true;

}

/** L[ r, c ] for c in [ first[ r ], until ): the dot products with the rows above. */
function eliminateRow( envelope: Envelope, values: Float64Array, r: number, from: number, until: number ): void {

	const { first, diagonal } = envelope;
	const baseR = diagonal[ r ] - r;
	for ( let c = from; c < until; c ++ ) {

		const baseC = diagonal[ c ] - c;
		let sum = values[ baseR + c ];
		for ( let k = Math.max( first[ r ], first[ c ] ); k < c; k ++ ) sum -= values[ baseR + k ] * values[ baseC + k ];
		values[ baseR + c ] = sum / values[ diagonal[ c ] ];

	}

}

/** {@link eliminateRow} for rows r … r + 3 (equal first columns) and the columns before r. */
function eliminateFourRows( envelope: Envelope, values: Float64Array, r: number ): void {

	const { first, diagonal } = envelope;
	const fr = first[ r ];
	const b0 = diagonal[ r ] - r, b1 = diagonal[ r + 1 ] - r - 1, b2 = diagonal[ r + 2 ] - r - 2, b3 = diagonal[ r + 3 ] - r - 3;
	for ( let c = fr; c < r; c ++ ) {

		const baseC = diagonal[ c ] - c;
		let s0 = values[ b0 + c ], s1 = values[ b1 + c ], s2 = values[ b2 + c ], s3 = values[ b3 + c ];
		for ( let k = Math.max( fr, first[ c ] ); k < c; k ++ ) {

			const l = values[ baseC + k ];
			s0 -= values[ b0 + k ] * l;
			s1 -= values[ b1 + k ] * l;
			s2 -= values[ b2 + k ] * l;
			s3 -= values[ b3 + k ] * l;

		}

		const d = values[ diagonal[ c ] ];
		values[ b0 + c ] = s0 / d;
		values[ b1 + c ] = s1 / d;
		values[ b2 + c ] = s2 / d;
		values[ b3 + c ] = s3 / d;

	}

}

/**
 * Row `row`'s entries from column `from` (the block's first row) up to its diagonal, then the
 * pivot: false when it is not clearly positive.
 */
function finishRow( envelope: Envelope, values: Float64Array, row: number, from: number ): boolean {

	const { first, diagonal } = envelope;
	eliminateRow( envelope, values, row, from, row );
	const baseR = diagonal[ row ] - row;
	const original = values[ diagonal[ row ] ];
	let pivot = original;
	for ( let k = first[ row ]; k < row; k ++ ) pivot -= values[ baseR + k ] * values[ baseR + k ];
	if ( ! ( original > 0 ) || ! ( pivot > PIVOT_TOLERANCE * original ) ) return false;
	values[ diagonal[ row ] ] = Math.sqrt( pivot );
	return true;

}

// Four right-hand side columns at a time, interleaved (x[ 4r + q ]): each entry of L is loaded once
// for four columns, and a row of L runs in memory order (dot products forward, axpys back).
let block = new Float64Array( 0 );

/**
 * Solves L·Lᵀ·X = B in place for `columns` right-hand sides (`rhs[ columns · r + k ]`), with L
 * from {@link factorCholesky}.
 */
export function solveCholesky( envelope: Envelope, values: Float64Array, rhs: Float64Array, columns: number ): void {

	const { size, first, diagonal } = envelope;
	if ( block.length < 4 * size ) block = new Float64Array( 4 * size );
	const x = block;
	for ( let k0 = 0; k0 < columns; k0 += 4 ) {

		const width = Math.min( 4, columns - k0 );
		for ( let r = 0; r < size; r ++ ) {

			for ( let q = 0; q < 4; q ++ ) x[ 4 * r + q ] = q < width ? rhs[ columns * r + k0 + q ] : 0;

		}

		for ( let r = 0; r < size; r ++ ) {

			const baseR = diagonal[ r ] - r;
			let s0 = x[ 4 * r ], s1 = x[ 4 * r + 1 ], s2 = x[ 4 * r + 2 ], s3 = x[ 4 * r + 3 ];
			for ( let c = first[ r ]; c < r; c ++ ) {

				const l = values[ baseR + c ];
				s0 -= l * x[ 4 * c ];
				s1 -= l * x[ 4 * c + 1 ];
				s2 -= l * x[ 4 * c + 2 ];
				s3 -= l * x[ 4 * c + 3 ];

			}

			const d = values[ diagonal[ r ] ];
			x[ 4 * r ] = s0 / d; x[ 4 * r + 1 ] = s1 / d; x[ 4 * r + 2 ] = s2 / d; x[ 4 * r + 3 ] = s3 / d;

		}

		for ( let r = size - 1; r >= 0; r -- ) {

			const baseR = diagonal[ r ] - r;
			const d = values[ diagonal[ r ] ];
			const x0 = x[ 4 * r ] / d, x1 = x[ 4 * r + 1 ] / d, x2 = x[ 4 * r + 2 ] / d, x3 = x[ 4 * r + 3 ] / d;
			x[ 4 * r ] = x0; x[ 4 * r + 1 ] = x1; x[ 4 * r + 2 ] = x2; x[ 4 * r + 3 ] = x3;
			for ( let c = first[ r ]; c < r; c ++ ) {

				const l = values[ baseR + c ];
				x[ 4 * c ] -= l * x0;
				x[ 4 * c + 1 ] -= l * x1;
				x[ 4 * c + 2 ] -= l * x2;
				x[ 4 * c + 3 ] -= l * x3;

			}

		}

		for ( let r = 0; r < size; r ++ ) for ( let q = 0; q < width; q ++ ) rhs[ columns * r + k0 + q ] = x[ 4 * r + q ];

	}

}
