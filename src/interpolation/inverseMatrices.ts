/**
 * Inverse barycentric matrices of tetrahedra (paper section 2.4): per tetrahedron the row-major
 * inverse of [p0 − p3, p1 − p3, p2 − p3], so that (w0, w1, w2) = inverse · (p − p3).
 */

/** Per tetrahedron, the inverse of [p0 − p3, p1 − p3, p2 − p3] (9 floats each). */
export function computeInverseMatrices( p: Float64Array, tetrahedra: Uint32Array ): Float64Array {

	const count = tetrahedra.length / 4;
	const out = new Float64Array( 9 * count );
	for ( let t = 0; t < count; t ++ ) writeInverse( p, tetrahedra, t, out );
	return out;

}

/** Writes the inverse of [p0 − p3, p1 − p3, p2 − p3] of tetrahedron t to `out[9t..9t+8]`. */
export function writeInverse( p: Float64Array, tetrahedra: Uint32Array, t: number, out: Float64Array ): void {

	const i0 = 3 * tetrahedra[ 4 * t ], i1 = 3 * tetrahedra[ 4 * t + 1 ];
	const i2 = 3 * tetrahedra[ 4 * t + 2 ], i3 = 3 * tetrahedra[ 4 * t + 3 ];
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
