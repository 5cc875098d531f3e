/**
 * Barycentric weights from exact sub-volumes, for tetrahedra whose float inverse matrix is
 * ill-conditioned (see `inverseMatrices.ts`): weight i is det(t with vertex i replaced by the
 * point) / det(t), each determinant evaluated exactly (Shewchuk's expansion arithmetic on the
 * error-free coordinate differences, scaled by a power of two to the tetrahedron's size) and then
 * rounded once. The signs are exact and the values good to a few ulps, however flat the
 * tetrahedron is in floating point. Allocation-free; slow compared with the inverse matrix
 * (hundreds of operations), which is why only flagged cells use it.
 */

// Shewchuk's splitter for exact products: 2^27 + 1.
const SPLITTER = 134217729;

// Coordinate differences as (hi, lo) pairs, hi + lo exact: 7 vectors × 3 components × 2. Vectors
// 0–2: p0 − p3, p1 − p3, p2 − p3; 3: q − p3; 4: q − p0; 5, 6: p1 − p0, p2 − p0. Every sub-volume
// is linear in q's difference (no product of two), so none overflows or cancels for a far point.
const _d = new Float64Array( 42 );

// The expansion a determinant is accumulated in: nonoverlapping components, increasing magnitude.
// 48 triple products of 4 exact parts each bound its length by 193.
const _sum = new Float64Array( 256 );

/**
 * Writes the barycentric weights of (x, y, z) in tetrahedron t to `out[0..3]` (`out[k]` for
 * vertex `tetrahedra[4t + k]`), from exact sub-volumes.
 * @returns −1 when the point is inside t or on its boundary (every sub-volume ≥ 0; the weights are
 * then ≥ 0 and sum to 1 within rounding), else the slot of the most negative weight (the face to
 * step across).
 */
export function exactBarycentric(
	p: Float64Array, tetrahedra: Uint32Array, t: number, x: number, y: number, z: number,
	out: Float32Array | Float64Array | number[],
): number {

	const k = 4 * t, a = 3 * tetrahedra[ k ], r = 3 * tetrahedra[ k + 3 ];
	let largest = 0;
	for ( let i = 0; i < 3; i ++ ) {

		const v = 3 * tetrahedra[ k + i ];
		for ( let c = 0; c < 3; c ++ ) {

			largest = Math.max( largest, difference( p[ v + c ], p[ r + c ], 6 * i + 2 * c ) );
			if ( i > 0 ) largest = Math.max( largest, difference( p[ v + c ], p[ a + c ], 24 + 6 * i + 2 * c ) );

		}

	}

	difference( x, p[ r ], 18 ); difference( y, p[ r + 1 ], 20 ); difference( z, p[ r + 2 ], 22 );
	difference( x, p[ a ], 24 ); difference( y, p[ a + 1 ], 26 ); difference( z, p[ a + 2 ], 28 );

	// A power of two that brings the tetrahedron's edges near 1: exact, and it keeps the products
	// of three differences clear of overflow and underflow at any scale.
	if ( largest > 0 && largest < Infinity ) {

		const e = - Math.floor( Math.log2( largest ) ), half = e >> 1;
		const s1 = 2 ** half, s2 = 2 ** ( e - half );
		for ( let i = 0; i < 42; i ++ ) _d[ i ] = _d[ i ] * s1 * s2;

	}

	// det[ p0 − p3, p1 − p3, p2 − p3 ] is negative for a positively oriented tetrahedron: the signs
	// are flipped so that volume and sub-volumes are positive inside (either orientation works).
	// det[ p0 − q, p1 − q, p2 − q ] = − det[ q − p0, p1 − p0, p2 − p0 ] (columns 1, 2 minus column 0).
	let volume = determinant( 0, 1, 2 );
	let v0 = determinant( 3, 1, 2 ), v1 = determinant( 0, 3, 2 ), v2 = determinant( 0, 1, 3 ), v3 = - determinant( 4, 5, 6 );
	if ( volume < 0 ) {

		volume = - volume; v0 = - v0; v1 = - v1; v2 = - v2; v3 = - v3;

	}

	if ( v0 >= 0 && v1 >= 0 && v2 >= 0 && v3 >= 0 ) {

		// Inside: the sub-volumes sum to the volume exactly; dividing by their float sum (no
		// cancellation, all ≥ 0) makes the weights sum to 1 within rounding.
		const sum = v0 + v1 + v2 + v3;
		if ( sum > 0 && sum < Infinity ) {

			out[ 0 ] = v0 / sum; out[ 1 ] = v1 / sum; out[ 2 ] = v2 / sum; out[ 3 ] = v3 / sum;

		} else {

			// Only for a tetrahedron flat in exact arithmetic (not in a valid mesh): equal weights.
			out[ 0 ] = 0.25; out[ 1 ] = 0.25; out[ 2 ] = 0.25; out[ 3 ] = 0.25;

		}

		return - 1;

	}

	// Outside: exact signs; divided by the volume, the values the inverse matrix would give (a
	// tetrahedron flat in exact arithmetic, not in a valid mesh, keeps the signs only).
	const s = volume > 0 ? 1 / volume : 1;
	out[ 0 ] = v0 * s; out[ 1 ] = v1 * s; out[ 2 ] = v2 * s; out[ 3 ] = v3 * s;
	// The most negative; NaN (a point ~1e290 tetrahedron sizes away overflows the products) only
	// when no sub-volume is negative: the face not proven to have the point on its inner side.
	let worst = - 1, worstValue = 0;
	if ( v0 < worstValue ) { worstValue = v0; worst = 0; }
	if ( v1 < worstValue ) { worstValue = v1; worst = 1; }
	if ( v2 < worstValue ) { worstValue = v2; worst = 2; }
	if ( v3 < worstValue ) { worstValue = v3; worst = 3; }
	if ( worst < 0 ) worst = ! ( v0 >= 0 ) ? 0 : ! ( v1 >= 0 ) ? 1 : ! ( v2 >= 0 ) ? 2 : 3;
	return worst;

}

/** Writes a − b as an exact (hi, lo) pair to `_d[at]`, `_d[at + 1]` (Shewchuk's Two-Diff); returns |hi|. */
function difference( a: number, b: number, at: number ): number {

	const x = a - b, bv = a - x, av = x + bv;
	_d[ at ] = x;
	_d[ at + 1 ] = ( a - av ) + ( bv - b );
	return Math.abs( x );

}

/**
 * det[ u, v, w ] of the difference vectors u, v, w (indices 0–6 into `_d`), exactly, rounded to a double.
 */
function determinant( u: number, v: number, w: number ): number {

	const a = 6 * u, b = 6 * v, c = 6 * w;
	// x, y, z components are at offsets 0, 2, 4 of a vector.
	let n = triple( a, b + 2, c + 4, 1, 0 );
	n = triple( a, b + 4, c + 2, - 1, n );
	n = triple( a + 2, b + 4, c, 1, n );
	n = triple( a + 2, b, c + 4, - 1, n );
	n = triple( a + 4, b, c + 2, 1, n );
	n = triple( a + 4, b + 2, c, - 1, n );
	// Nonoverlapping, smallest first: summing in that order rounds the exact value faithfully.
	let value = 0;
	for ( let i = 0; i < n; i ++ ) value += _sum[ i ];
	return value;

}

/**
 * Adds sign · (a.hi + a.lo)(b.hi + b.lo)(c.hi + c.lo) to the expansion of length n in `_sum`,
 * exactly (zero parts skipped); returns its new length.
 */
function triple( a: number, b: number, c: number, sign: number, n: number ): number {

	for ( let i = 0; i < 2; i ++ ) {

		const x = _d[ a + i ];
		if ( x === 0 ) continue;
		for ( let j = 0; j < 2; j ++ ) {

			const y = _d[ b + j ];
			if ( y === 0 ) continue;
			// x · y = hi + lo exactly, then each times z, exactly.
			const hi = x * y, lo = productError( x, y, hi );
			for ( let l = 0; l < 2; l ++ ) {

				const zc = sign * _d[ c + l ];
				if ( zc === 0 ) continue;
				const h1 = hi * zc, l1 = lo * zc;
				n = grow( n, productError( hi, zc, h1 ) );
				n = grow( n, h1 );
				if ( lo !== 0 ) {

					n = grow( n, productError( lo, zc, l1 ) );
					n = grow( n, l1 );

				}

			}

		}

	}

	return n;

}

/** The rounding error of the product a · b = `product` (Shewchuk's Two-Product tail, without FMA). */
function productError( a: number, b: number, product: number ): number {

	let c = SPLITTER * a;
	const ahi = c - ( c - a ), alo = a - ahi;
	c = SPLITTER * b;
	const bhi = c - ( c - b ), blo = b - bhi;
	return alo * blo - ( product - ahi * bhi - alo * bhi - ahi * blo );

}

/**
 * Adds b to the expansion of length `length` in `_sum` exactly (Shewchuk's Grow-Expansion, zero
 * components dropped); returns its new length.
 */
function grow( length: number, b: number ): number {

	if ( b === 0 ) return length;
	let q = b, n = 0;
	for ( let i = 0; i < length; i ++ ) {

		const e = _sum[ i ], x = q + e, bv = x - q, av = x - bv;
		const h = ( q - av ) + ( e - bv );
		q = x;
		if ( h !== 0 ) _sum[ n ++ ] = h;

	}

	if ( q !== 0 ) _sum[ n ++ ] = q;
	return n;

}
