/**
 * Inverse barycentric matrices of tetrahedra (paper section 2.4): per tetrahedron the row-major
 * inverse of [p0 − p3, p1 − p3, p2 − p3], so that (w0, w1, w2) = inverse · (p − p3).
 */

import { orient } from '../tetrahedra/predicates.js';

/** Per tetrahedron, the inverse of [p0 − p3, p1 − p3, p2 − p3] (9 floats each). */
export function computeInverseMatrices( p: Float64Array, tetrahedra: Uint32Array ): Float64Array {

	const count = tetrahedra.length / 4;
	const out = new Float64Array( 9 * count );
	for ( let t = 0; t < count; t ++ ) writeInverse( p, tetrahedra, t, out );
	return out;

}

/** Throws when a stored tetrahedron is not positively oriented. */
export function checkOrientations( where: string, p: Float64Array, tetrahedra: Uint32Array ): void {

	for ( let t = 0, count = tetrahedra.length / 4; t < count; t ++ ) {

		const i0 = 3 * tetrahedra[ 4 * t ], i1 = 3 * tetrahedra[ 4 * t + 1 ], i2 = 3 * tetrahedra[ 4 * t + 2 ], i3 = 3 * tetrahedra[ 4 * t + 3 ];
		const a = p[ i0 ] - p[ i3 ], d = p[ i0 + 1 ] - p[ i3 + 1 ], g = p[ i0 + 2 ] - p[ i3 + 2 ];
		const b = p[ i1 ] - p[ i3 ], e = p[ i1 + 1 ] - p[ i3 + 1 ], h = p[ i1 + 2 ] - p[ i3 + 2 ];
		const c = p[ i2 ] - p[ i3 ], f = p[ i2 + 1 ] - p[ i3 + 1 ], i = p[ i2 + 2 ] - p[ i3 + 2 ];
		const det = a * ( e * i - f * h ) - b * ( d * i - f * g ) + c * ( d * h - e * g );
		// det M = −det[p1 − p0, p2 − p0, p3 − p0]; a rounded det of the wrong sign is settled exactly.
		if ( ! ( det < 0 ) && orient( p, i0 / 3, i1 / 3, i2 / 3, i3 / 3 ) <= 0 ) {

			throw new Error( `${where}: tetrahedron ${t} (probes ${i0 / 3}, ${i1 / 3}, ${i2 / 3}, ${i3 / 3}) is not positively oriented (det[p1 − p0, p2 − p0, p3 − p0] ≤ 0).` );

		}

	}

}

/** Writes the inverse of [p0 − p3, p1 − p3, p2 − p3] of tetrahedron t to `out[9t..9t+8]`. */
export function writeInverse( p: Float64Array, tetrahedra: Uint32Array, t: number, out: Float64Array ): void {

	const i0 = 3 * tetrahedra[ 4 * t ], i1 = 3 * tetrahedra[ 4 * t + 1 ], i2 = 3 * tetrahedra[ 4 * t + 2 ], i3 = 3 * tetrahedra[ 4 * t + 3 ];
	// Columns of M: p0 − p3, p1 − p3, p2 − p3.
	const a = p[ i0 ] - p[ i3 ], d = p[ i0 + 1 ] - p[ i3 + 1 ], g = p[ i0 + 2 ] - p[ i3 + 2 ];
	const b = p[ i1 ] - p[ i3 ], e = p[ i1 + 1 ] - p[ i3 + 1 ], h = p[ i1 + 2 ] - p[ i3 + 2 ];
	const c = p[ i2 ] - p[ i3 ], f = p[ i2 + 1 ] - p[ i3 + 1 ], i = p[ i2 + 2 ] - p[ i3 + 2 ];
	// M = [[a, b, c], [d, e, f], [g, h, i]]; inverse by cofactors.
	const A = e * i - f * h, B = - ( d * i - f * g ), C = d * h - e * g;
	const det = a * A + b * B + c * C;
	const s = 1 / det;
	const k = 9 * t;
	out[ k ] = A * s; out[ k + 1 ] = - ( b * i - c * h ) * s; out[ k + 2 ] = ( b * f - c * e ) * s;
	out[ k + 3 ] = B * s; out[ k + 4 ] = ( a * i - c * g ) * s; out[ k + 5 ] = - ( a * f - c * d ) * s;
	out[ k + 6 ] = C * s; out[ k + 7 ] = - ( a * h - b * g ) * s; out[ k + 8 ] = ( a * e - b * d ) * s;

}
