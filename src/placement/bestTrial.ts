/**
 * The trial edit (of `candidates`) that lowers the fitted error most: each estimated by
 * `estimate( c )` (NaN: no estimate, so `exact( c )` fits it), ties by seeded rank; edits that
 * cannot be made (estimate +Infinity: a candidate coinciding with a probe) are left out.
 * @returns The chosen candidate and its estimated change of the error, or null when no trial can be made.
 */
export function bestTrial(
	candidates: readonly number[], rank: Uint32Array, estimate: ( c: number ) => number, exact: ( c: number ) => number,
): { c: number; change: number } | null {

	let best: { c: number; change: number } | null = null;
	for ( const c of candidates ) {

		let change = estimate( c );
		if ( Number.isNaN( change ) ) change = exact( c );
		if ( ! ( change < Infinity ) ) continue;
		if ( best === null || change < best.change || ( change === best.change && rank[ c ] < rank[ best.c ] ) ) best = { c, change };

	}

	return best;

}
