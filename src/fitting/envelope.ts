/**
 * Envelope (profile) storage of a symmetric matrix's lower triangle: row r keeps columns
 * `first[ r ] … r` contiguously, so a Cholesky factor fills nothing outside it. The normal
 * matrices of a fit are sparse (a sample couples only the ≤ 8 probes it blends) and banded once
 * the probes are numbered along space: the envelope keeps the band and drops the rest.
 */
export interface Envelope {

	/** Rows (= columns). */
	readonly size: number;

	/** Per row, its first stored column (≤ the row). */
	readonly first: Int32Array;

	/** Per row, the index of its diagonal entry in the value array: entry (r, c) is at `diagonal[ r ] − r + c`. */
	readonly diagonal: Int32Array;

	/** Floats the value array holds. */
	readonly length: number;

}

/** The envelope whose row r starts at column `first[ r ]` (kept by reference). */
export function createEnvelope( first: Int32Array ): Envelope {

	const size = first.length;
	const diagonal = new Int32Array( size );
	let length = 0;
	for ( let r = 0; r < size; r ++ ) {

		length += r - first[ r ] + 1;
		diagonal[ r ] = length - 1;

	}

	return { size, first, diagonal, length };

}
