/**
 * Inverse barycentric matrices of tetrahedra (paper section 2.4): per tetrahedron the row-major
 * inverse of [p0 − p3, p1 − p3, p2 − p3], so that (w0, w1, w2) = inverse · (p − p3).
 *
 * A tetrahedron whose float inverse cannot be trusted gets nine NaN instead (the sentinel the walk
 * branches on; its weights then come from `exactBarycentric`): when |det| < ILL_CONDITIONED · ℓ³,
 * ℓ the largest coordinate of its edge vectors, or when an entry is not finite. Such tetrahedra
 * are valid in exact arithmetic but (nearly) flat in floating point — e.g. the slivers across the
 * square faces of a rotated or offset grid, where rounding alone gives the 4 points a volume.
 */

/**
 * Smallest |det| / ℓ³ with a float inverse: above it the inverse's weights err by less than about
 * 2e-11 (measured on random, jittered and rotated grids, docs/interpolation-robustness.md), so
 * linear fields are reproduced to 1e-9; a regular tetrahedron has about 0.7, a cube's corner 1.
 */
export const ILL_CONDITIONED = 1e-5;

/** Per tetrahedron, the inverse of [p0 − p3, p1 − p3, p2 − p3] (9 floats each; 9 NaN when ill-conditioned). */
export function computeInverseMatrices( p: Float64Array, tetrahedra: Uint32Array ): Float64Array {

	const count = tetrahedra.length / 4;
	const out = new Float64Array( 9 * count );
	for ( let t = 0; t < count; t ++ ) writeInverse( p, tetrahedra, t, out );
	return out;

}

/**
 * Writes the inverse of [p0 − p3, p1 − p3, p2 − p3] of tetrahedron t to `out[9t..9t+8]`, or nine
 * NaN when it is ill-conditioned (see {@link ILL_CONDITIONED}).
 */
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

	// Divided one factor at a time, so neither ℓ³ nor the ratio overflows; NaN fails the test too,
	// and an overflowed det (whose inverse would be 0) the second.
	const l = Math.max( Math.abs( a ), Math.abs( b ), Math.abs( c ), Math.abs( d ), Math.abs( e ), Math.abs( f ),
		Math.abs( g ), Math.abs( h ), Math.abs( i ) );
	let trusted = Math.abs( det ) / l / l / l >= ILL_CONDITIONED && Math.abs( det ) < Infinity;
	for ( let j = k; j < k + 9 && trusted; j ++ ) trusted = Number.isFinite( out[ j ] );
	if ( ! trusted ) out.fill( NaN, k, k + 9 );

}

/** Whether tetrahedron t's inverse is the NaN sentinel (its weights come from `exactBarycentric`). */
export function isIllConditioned( inverseMatrices: Float64Array, t: number ): boolean {

	return Number.isNaN( inverseMatrices[ 9 * t ] );

}
