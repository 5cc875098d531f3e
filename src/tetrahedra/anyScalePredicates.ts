import { orient2d, orient3d, insphere } from 'robust-predicates';
import { exponentOf, timesPowerOfTwo } from './powerOfTwo.js';

/*
 * robust-predicates' signs for any finite coordinates. Its expansion arithmetic (Shewchuk) is
 * exact as long as no product under- or overflows, which holds when every coordinate is 0 or of
 * magnitude in [WINDOW_LOW, WINDOW_HIGH]: every partial product of up to five factors (insphere's
 * degree) is then 0 or an integer multiple of ulp(WINDOW_LOW)^5 = 2^−1010, and below 2^900 times
 * the number of its terms. Points outside the window are scaled by a power of two into it (exact)
 * when their nonzero magnitudes span less than the window; otherwise the determinant is evaluated
 * in BigInt, exactly. Both are slow paths (docs/robustness.md).
 */

/** Smallest nonzero coordinate magnitude robust-predicates is exact for. */
export const WINDOW_LOW = 2 ** - 150;

/** Largest coordinate magnitude robust-predicates is exact for. */
export const WINDOW_HIGH = 2 ** 180;

/** Whether v is neither 0 nor of magnitude in [WINDOW_LOW, WINDOW_HIGH]. */
export function outsideWindow( v: number ): boolean {

	const a = Math.abs( v );
	return a > WINDOW_HIGH || ( a < WINDOW_LOW && a !== 0 );

}

/** Sign of robust-predicates' `orient3d( a, b, c, d )` (−det[b − a, c − a, d − a]), exact for any finite coordinates. */
export function orient3dSign( p: Float64Array, a: number, b: number, c: number, d: number ): number {

	const v = gather( p, a, b, c, d, - 1 );
	if ( intoWindow( v ) ) {

		return Math.sign( orient3d( v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ], v[ 4 ], v[ 5 ], v[ 6 ], v[ 7 ], v[ 8 ], v[ 9 ], v[ 10 ], v[ 11 ] ) );

	}

	const [ ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz ] = integers( v );
	return bigSign( orient3dValue( ax - dx, ay - dy, az - dz, bx - dx, by - dy, bz - dz, cx - dx, cy - dy, cz - dz ) );

}

/**
 * Sign of robust-predicates' `insphere( a, b, c, d, e )` (> 0: e inside the sphere of a positive
 * abcd), exact for any finite coordinates.
 */
export function inSphereSign( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

	const v = gather( p, a, b, c, d, e );
	if ( intoWindow( v ) ) {

		const [ ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez ] = v;
		return Math.sign( insphere( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez ) );

	}

	const [ ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez ] = integers( v );
	const aex = ax - ex, bex = bx - ex, cex = cx - ex, dex = dx - ex;
	const aey = ay - ey, bey = by - ey, cey = cy - ey, dey = dy - ey;
	const aez = az - ez, bez = bz - ez, cez = cz - ez, dez = dz - ez;
	const ab = aex * bey - bex * aey, bc = bex * cey - cex * bey, cd = cex * dey - dex * cey;
	const da = dex * aey - aex * dey, ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
	const alift = aex * aex + aey * aey + aez * aez, blift = bex * bex + bey * bey + bez * bez;
	const clift = cex * cex + cey * cey + cez * cez, dlift = dex * dex + dey * dey + dez * dez;
	return bigSign(
		( clift * ( dez * ab + aez * bd + bez * da ) - dlift * ( aez * bc - bez * ac + cez * ab ) ) +
		( alift * ( bez * cd - cez * bd + dez * bc ) - blift * ( cez * da + dez * ac + aez * cd ) ) );

}

/**
 * Sign of robust-predicates' `orient2d` of points a, b, c projected on coordinates `i`, `j`
 * (0 = x, 1 = y, 2 = z), exact for any finite coordinates.
 */
export function orient2dSign( p: Float64Array, a: number, b: number, c: number, i: number, j: number ): number {

	const v = [ p[ 3 * a + i ], p[ 3 * a + j ], p[ 3 * b + i ], p[ 3 * b + j ], p[ 3 * c + i ], p[ 3 * c + j ] ];
	if ( intoWindow( v ) ) return Math.sign( orient2d( v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ], v[ 4 ], v[ 5 ] ) );
	const [ ax, ay, bx, by, cx, cy ] = integers( v );
	return bigSign( ( ay - cy ) * ( bx - cx ) - ( ax - cx ) * ( by - cy ) );

}

/** det[ a, b, c ] of three difference vectors in BigInt, with robust-predicates' orient3d sign. */
function orient3dValue(
	adx: bigint, ady: bigint, adz: bigint, bdx: bigint, bdy: bigint, bdz: bigint, cdx: bigint, cdy: bigint, cdz: bigint,
): bigint {

	return adz * ( bdx * cdy - cdx * bdy ) + bdz * ( cdx * ady - adx * cdy ) + cdz * ( adx * bdy - bdx * ady );

}

function bigSign( value: bigint ): number {

	return value > 0n ? 1 : ( value < 0n ? - 1 : 0 );

}

/** The coordinates of points a, b, c, d (and e when ≥ 0), in order. */
function gather( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number[] {

	const v: number[] = [];
	for ( const i of e >= 0 ? [ a, b, c, d, e ] : [ a, b, c, d ] ) v.push( p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ] );
	return v;

}

/**
 * Scales `v` in place by the power of two that brings its largest magnitude into [1, 2), when
 * every nonzero entry then lies in the window (the scaling is then exact); false, unchanged, otherwise.
 */
function intoWindow( v: number[] ): boolean {

	let largest = 0, smallest = Infinity;
	for ( const x of v ) {

		const a = Math.abs( x );
		if ( a > largest ) largest = a;
		if ( a !== 0 && a < smallest ) smallest = a;

	}

	if ( largest === 0 ) return true;
	const k = - exponentOf( largest );
	if ( exponentOf( smallest ) + k < exponentOf( WINDOW_LOW ) ) return false;
	for ( let i = 0; i < v.length; i ++ ) v[ i ] = timesPowerOfTwo( v[ i ], k );
	return true;

}

/** The doubles of `v` as integers, all multiplied by one power of two (exact: a double is m · 2^q). */
function integers( v: number[] ): bigint[] {

	const mantissas: bigint[] = [], exponents: number[] = [];
	let lowest = Infinity;
	for ( const x of v ) {

		if ( x === 0 ) {

			mantissas.push( 0n );
			exponents.push( 0 );
			continue;

		}

		// x = m · 2^q with m an integer below 2^53 in magnitude (q = −1074 for subnormals).
		const q = Math.max( exponentOf( x ) - 52, - 1074 );
		mantissas.push( BigInt( timesPowerOfTwo( x, - q ) ) );
		exponents.push( q );
		if ( q < lowest ) lowest = q;

	}

	return mantissas.map( ( m, i ) => m === 0n ? 0n : m << BigInt( exponents[ i ] - lowest ) );

}
