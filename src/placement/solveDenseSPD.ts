// A pivot below this fraction of its diagonal entry counts as singular: the caller adds a ridge.
const PIVOT_TOLERANCE = 1e-12;

/**
 * Solves A·X = B in place for a small symmetric positive definite A (n × n, row-major; its lower
 * triangle is overwritten by the Cholesky factor) and `columns` right-hand sides (`b[ columns · r + k ]`,
 * overwritten by X). When a pivot is not clearly positive, a ridge of 1e-9 × the mean diagonal (then
 * 1000 times more) is added to a fresh copy of A and the factorisation retried.
 * @param scratch At least n × n floats, for the copy of A a retry needs.
 * @returns false when A stayed singular (X is then undefined).
 */
export function solveDenseSPD( a: Float64Array, n: number, b: Float64Array, columns: number, scratch: Float64Array ): boolean {

	scratch.set( a.subarray( 0, n * n ) );
	let mean = 0;
	for ( let r = 0; r < n; r ++ ) mean += a[ n * r + r ] / n;
	let ridge = 0;
	for ( let attempt = 0; ! factor( a, n, ridge ); attempt ++ ) {

		if ( attempt === 3 ) return false;
		ridge = ridge === 0 ? 1e-9 * ( mean > 0 ? mean : 1 ) : 1000 * ridge;
		a.set( scratch.subarray( 0, n * n ) );

	}

	for ( let r = 0; r < n; r ++ ) {

		const row = columns * r;
		for ( let c = 0; c < r; c ++ ) {

			const l = a[ n * r + c ];
			if ( l !== 0 ) for ( let k = 0; k < columns; k ++ ) b[ row + k ] -= l * b[ columns * c + k ];

		}

		const inverse = 1 / a[ n * r + r ];
		for ( let k = 0; k < columns; k ++ ) b[ row + k ] *= inverse;

	}

	for ( let r = n - 1; r >= 0; r -- ) {

		const row = columns * r, inverse = 1 / a[ n * r + r ];
		for ( let k = 0; k < columns; k ++ ) b[ row + k ] *= inverse;
		for ( let c = 0; c < r; c ++ ) {

			const l = a[ n * r + c ];
			if ( l !== 0 ) for ( let k = 0; k < columns; k ++ ) b[ columns * c + k ] -= l * b[ row + k ];

		}

	}

	return true;

}

/** In-place Cholesky factor L (lower triangle) of A + ridge·I; false when a pivot is not clearly positive. */
function factor( a: Float64Array, n: number, ridge: number ): boolean {

	for ( let r = 0; r < n; r ++ ) {

		for ( let c = 0; c < r; c ++ ) {

			let sum = a[ n * r + c ];
			for ( let k = 0; k < c; k ++ ) sum -= a[ n * r + k ] * a[ n * c + k ];
			a[ n * r + c ] = sum / a[ n * c + c ];

		}

		const original = a[ n * r + r ] + ridge;
		let pivot = original;
		for ( let k = 0; k < r; k ++ ) pivot -= a[ n * r + k ] * a[ n * r + k ];
		if ( ! ( original > 0 ) || ! ( pivot > PIVOT_TOLERANCE * original ) ) return false;
		a[ n * r + r ] = Math.sqrt( pivot );

	}

	return true;

}
