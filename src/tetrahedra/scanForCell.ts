import { orient } from './predicates.js';

// The vertex at infinity, the released-slot marker and the record size of DelaunayBuilder
// (repeated here: that module imports this one).
const INF = - 1, FREE = - 2, CELL = 8;

/**
 * Point location by testing every cell slot, the fallback of `DelaunayBuilder.locate` when its
 * walk exceeds its step bound: a finite cell whose closure contains point q, or a ghost whose
 * hull face q is strictly beyond. O(cells).
 * @param cells The builder's `cells` (a record of CELL ints per slot, its four vertices first; FREE in the first for a released slot).
 * @param used The builder's `used` (slots at or above it were never allocated).
 * @throws Error when no cell qualifies (only inconsistent predicates could cause that).
 */
export function scanForCell( p: Float64Array, cells: Int32Array, used: number, q: number ): number {

	const v = cells;
	for ( let t = 0; t < used; t ++ ) {

		const k = CELL * t, a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
		if ( a === FREE ) continue;
		if ( a === INF ) { if ( orient( p, q, b, c, d ) > 0 ) return t; continue; }
		if ( b === INF ) { if ( orient( p, a, q, c, d ) > 0 ) return t; continue; }
		if ( c === INF ) { if ( orient( p, a, b, q, d ) > 0 ) return t; continue; }
		if ( d === INF ) { if ( orient( p, a, b, c, q ) > 0 ) return t; continue; }
		const inside = orient( p, q, b, c, d ) >= 0 && orient( p, a, q, c, d ) >= 0 && orient( p, a, b, q, d ) >= 0;
		if ( inside && orient( p, a, b, c, q ) >= 0 ) return t;

	}

	throw new Error( `DelaunayBuilder.locate: internal error, no cell contains point ${q} (the predicates are inconsistent).` );

}
