/**
 * Searches for the regularisation strengths with the lowest cross-validation error, in log10 λ:
 * a coarse grid, then a local refinement with halving steps. Ties keep the larger λ (the smoother
 * fit), so a field every λ reproduces equally keeps its probes' captured values most.
 */

/** Exponents of the coarse line search: 10^−6 … 10^3 in decades, largest first. */
const LINE_GRID = Array.from( { length: 10 }, ( _, i ) => 3 - i );

/** Exponents of each coarse axis scan of the plane search: 10^−5 … 10^2 in decades, largest first. */
const PLANE_GRID = Array.from( { length: 8 }, ( _, i ) => 2 - i );

/** Refinement steps of the line search, in decades. */
const STEPS = [ 0.5, 0.25, 0.125 ];

/** Refinement steps of the plane search: each costs four fits per fold (two axes, ±). */
const PLANE_STEPS = [ 0.5, 0.25 ];

/** The exponent e minimising `error( e )`: the coarse grid, then ± each refinement step from the best so far (16 evaluations). */
export function searchLine( error: ( exponent: number ) => number ): number {

	let best = LINE_GRID[ 0 ], bestError = error( best );
	for ( const e of LINE_GRID ) {

		const value = error( e );
		if ( value < bestError ) {

			best = e;
			bestError = value;

		}

	}

	for ( const step of STEPS ) {

		for ( const e of [ best + step, best - step ] ) {

			const value = error( e );
			if ( value < bestError ) {

				best = e;
				bestError = value;

			}

		}

	}

	return best;

}

/**
 * The exponents (e₁, e₂) minimising `error( e₁, e₂ )`: coarse scans along e₂ then e₁ (each over the
 * decade grid, the other exponent held), then ± half and quarter decades along each axis in turn,
 * moving whenever one improves — 24 evaluations.
 */
export function searchPlane( error: ( first: number, second: number ) => number, start = - 2 ): [ number, number ] {

	const best: [ number, number ] = [ start, start ];
	let bestError = error( start, start );
	const consider = ( e1: number, e2: number ): void => {

		const value = error( e1, e2 );
		if ( ! ( value < bestError ) ) return;
		best[ 0 ] = e1;
		best[ 1 ] = e2;
		bestError = value;

	};

	for ( const axis of [ 1, 0 ] ) {

		const [ e1, e2 ] = best;
		for ( const e of PLANE_GRID ) consider( axis === 0 ? e : e1, axis === 0 ? e2 : e );

	}

	for ( const step of PLANE_STEPS ) {

		for ( const axis of [ 1, 0 ] ) {

			const [ e1, e2 ] = best;
			for ( const d of [ step, - step ] ) consider( axis === 0 ? e1 + d : e1, axis === 0 ? e2 : e2 + d );

		}

	}

	return [ best[ 0 ], best[ 1 ] ];

}
