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

	const { size, first, diagonal } = envelope;
	for ( let r = 0; r < size; r ++ ) {

		const fr = first[ r ], baseR = diagonal[ r ] - r;
		for ( let c = fr; c < r; c ++ ) {

			const baseC = diagonal[ c ] - c;
			let sum = values[ baseR + c ];
			for ( let k = Math.max( fr, first[ c ] ); k < c; k ++ ) sum -= values[ baseR + k ] * values[ baseC + k ];
			values[ baseR + c ] = sum / values[ diagonal[ c ] ];

		}

		const original = values[ diagonal[ r ] ];
		let pivot = original;
		for ( let k = fr; k < r; k ++ ) pivot -= values[ baseR + k ] * values[ baseR + k ];
		if ( ! ( original > 0 ) || ! ( pivot > PIVOT_TOLERANCE * original ) ) return false;
		values[ diagonal[ r ] ] = Math.sqrt( pivot );

	}

	return true;

}

/**
 * Solves L·Lᵀ·X = B in place for `columns` right-hand sides (`rhs[ columns · r + k ]`), with L
 * from {@link factorCholesky}.
 */
export function solveCholesky( envelope: Envelope, values: Float64Array, rhs: Float64Array, columns: number ): void {

	const { size, first, diagonal } = envelope;
	for ( let r = 0; r < size; r ++ ) {

		const baseR = diagonal[ r ] - r, row = columns * r;
		for ( let c = first[ r ]; c < r; c ++ ) {

			const l = values[ baseR + c ];
			if ( l === 0 ) continue;
			const other = columns * c;
			for ( let k = 0; k < columns; k ++ ) rhs[ row + k ] -= l * rhs[ other + k ];

		}

		const inverse = 1 / values[ diagonal[ r ] ];
		for ( let k = 0; k < columns; k ++ ) rhs[ row + k ] *= inverse;

	}

	for ( let r = size - 1; r >= 0; r -- ) {

		const baseR = diagonal[ r ] - r, row = columns * r;
		const inverse = 1 / values[ diagonal[ r ] ];
		for ( let k = 0; k < columns; k ++ ) rhs[ row + k ] *= inverse;
		for ( let c = first[ r ]; c < r; c ++ ) {

			const l = values[ baseR + c ];
			if ( l === 0 ) continue;
			const other = columns * c;
			for ( let k = 0; k < columns; k ++ ) rhs[ other + k ] -= l * rhs[ row + k ];

		}

	}

}
