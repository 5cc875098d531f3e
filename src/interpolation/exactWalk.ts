import { exactBarycentric } from './exactBarycentric.js';

/**
 * The walk of `TetrahedralMesh.locate`, continued from tetrahedron t where a float weight was NaN
 * (an ill-conditioned cell's sentinel, see `inverseMatrices.ts`, or an overflow): each step uses
 * the inverse matrix's weights where they are all finite and the exact sub-volumes elsewhere, so
 * no step is taken on a NaN. Off the hot loop: `locate` calls it only when it meets a NaN.
 * Allocation-free; leaves the last tetrahedron's weights in `weights`.
 * @param m The mesh's inverse matrices.
 * @param budget Steps allowed.
 * @param epsilon Slack on the float weights (as the fast walk's), none on the exact ones.
 * @param exit Receives the tetrahedron and the slot of the hull face the walk left through.
 * @returns The tetrahedron containing the point, −1 beyond a hull face (outside the hull), −2
 * when `budget` steps did not suffice.
 */
export function walkExactly(
	p: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array, m: Float64Array,
	x: number, y: number, z: number, t: number, budget: number, epsilon: number, weights: Float64Array, exit: Int32Array,
): number {

	for ( let steps = 0; steps <= budget; steps ++ ) {

		const k = 9 * t, r = 3 * tetrahedra[ 4 * t + 3 ];
		const dx = x - p[ r ], dy = y - p[ r + 1 ], dz = z - p[ r + 2 ];
		const w0 = m[ k ] * dx + m[ k + 1 ] * dy + m[ k + 2 ] * dz;
		const w1 = m[ k + 3 ] * dx + m[ k + 4 ] * dy + m[ k + 5 ] * dz;
		const w2 = m[ k + 6 ] * dx + m[ k + 7 ] * dy + m[ k + 8 ] * dz;
		const w3 = 1 - w0 - w1 - w2;
		let worst: number;
		if ( w3 === w3 ) {

			// All four finite (w3 is NaN whenever one is NaN, or two overflowed with opposite signs).
			weights[ 0 ] = w0; weights[ 1 ] = w1; weights[ 2 ] = w2; weights[ 3 ] = w3;
			let worstValue = w0;
			worst = 0;
			if ( w1 < worstValue ) { worstValue = w1; worst = 1; }
			if ( w2 < worstValue ) { worstValue = w2; worst = 2; }
			if ( w3 < worstValue ) { worstValue = w3; worst = 3; }
			if ( worstValue >= - epsilon ) return t;

		} else {

			worst = exactBarycentric( p, tetrahedra, t, x, y, z, weights );
			if ( worst < 0 ) return t;

		}

		const next = neighbors[ 4 * t + worst ];
		if ( next === - 1 ) {

			exit[ 0 ] = t; exit[ 1 ] = worst;
			return - 1;

		}

		t = next;

	}

	return - 2;

}
