import { orient3d, insphere, orient2d } from 'robust-predicates';
import { inSphereSign, orient2dSign, orient3dSign, outsideWindow } from './anyScalePredicates.js';
import { inSphereDoubleDouble } from './inSphereDoubleDouble.js';

/*
 * Exact geometric predicates on points stored as a flat Float64Array (x, y, z per point), plus
 * the symbolic perturbation that makes co-spherical and co-circular ties consistent.
 *
 * Sign conventions used throughout src/tetrahedra (note robust-predicates' orient3d has the
 * opposite sign):
 *   orient( a, b, c, d ) > 0  ⇔  det[ b − a, c − a, d − a ] > 0 (a positively oriented tetrahedron)
 *   inSphere( a, b, c, d, e ) > 0  ⇔  e strictly inside the circumsphere of the positive tetrahedron abcd
 *
 * The perturbation follows Devillers & Teillaud, "Perturbations for Delaunay and weighted Delaunay
 * 3D triangulations" (2011), the scheme CGAL uses: every point is lifted by an infinitesimal that
 * grows with its rank in lexicographic (x, y, z) order, so ties are broken by the same rule whatever
 * the insertion order, and the result is the Delaunay triangulation of the perturbed set — a valid
 * Delaunay triangulation of the input in which no tetrahedron is flat.
 *
 * Scale: orient, inSphere and the tests built on them are exact for coordinates of magnitude at most
 * PREDICATE_RANGE, which the point sets of src/tetrahedra are normalised into (a power-of-two
 * scaling); `orientAnyScale` takes any finite coordinates. Why: docs/robustness.md.
 */

/** Largest coordinate magnitude `orient` and `inSphere` accept (see `orientAnyScale` beyond it). */
export const PREDICATE_RANGE = 2 ** 64;

// robust-predicates' first-stage error bounds (Shewchuk 1997), with its machine epsilon 2^−53.
const EPSILON = 1.1102230246251565e-16;
const O3D_BOUND_A = ( 7 + 56 * EPSILON ) * EPSILON;
const ISP_BOUND_A = ( 16 + 224 * EPSILON ) * EPSILON;

// Added to the first-stage bounds: Shewchuk's bounds assume no product underflows, and an
// underflowed product errs by up to 2^−1075 absolutely, times the factors it is multiplied by later
// (coordinate differences ≤ 2^66, one factor in orient, up to three in inSphere). Beyond these
// margins a first-stage sign is right even then; for the usual magnitudes they change nothing.
const O3D_UNDERFLOW = 2 ** - 1000;
const ISP_UNDERFLOW = 2 ** - 800;

/*
 * orient and inSphere repeat robust-predicates' first (floating-point) stage inline, expression for
 * expression, so they give the library's sign whenever that stage is conclusive, and call the
 * library (which redoes the cheap stage, then escalates) only when it is not: this saves the 12–15
 * argument call on the hot path of the walk and the conflict flood. inSphere adds two cheaper exact
 * steps before the library's expansion arithmetic (see inSphereNearZero).
 *
 * Both take an optional static bound (orientStaticBound, inSphereStaticBound of the points' extent):
 * the first stage's error bound is at most the "permanent" (the determinant's terms in absolute
 * value) times a constant, and for points within a box of diagonal Δ the permanent is at most
 * 6Δ³ (orient) or 72Δ⁵ (inSphere); a value beyond that bound is decided before the permanent is
 * computed. Why it is safe and what it saves: docs/tetrahedralize-speed.md.
 */

/**
 * A bound on orient's first-stage error for any four points whose coordinate differences are at
 * most `extent` (e.g. the diagonal of their bounding box), for orient's `staticBound`.
 */
export function orientStaticBound( extent: number ): number {

	// The permanent is at most 6 Δ³ with the rounded differences, up to (1 + ε)⁹ of rounding.
	return O3D_BOUND_A * 6 * extent ** 3 * ( 1 + 2 ** - 30 ) + O3D_UNDERFLOW;

}

/** As {@link orientStaticBound}, for inSphere's `staticBound`. */
export function inSphereStaticBound( extent: number ): number {

	// The permanent is at most 4 lifts · 3 Δ² · 6 Δ³ = 72 Δ⁵, up to (1 + ε)¹² of rounding.
	return ISP_BOUND_A * 72 * extent ** 5 * ( 1 + 2 ** - 30 ) + ISP_UNDERFLOW;

}

/**
 * Sign of det[ b − a, c − a, d − a ], exact: 1, −1 or 0. (Signs rather than values: a double
 * returned from a call that is not inlined is boxed, one allocation per predicate.)
 * @param staticBound {@link orientStaticBound} of an extent that holds the four points, or Infinity.
 */
export function orient( p: Float64Array, a: number, b: number, c: number, d: number, staticBound = Infinity ): number {

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c, d3 = 3 * d;
	const ax = p[ a3 ], ay = p[ a3 + 1 ], az = p[ a3 + 2 ];
	const bx = p[ b3 ], by = p[ b3 + 1 ], bz = p[ b3 + 2 ];
	const cx = p[ c3 ], cy = p[ c3 + 1 ], cz = p[ c3 + 2 ];
	const dx = p[ d3 ], dy = p[ d3 + 1 ], dz = p[ d3 + 2 ];

	const adx = ax - dx, bdx = bx - dx, cdx = cx - dx;
	const ady = ay - dy, bdy = by - dy, cdy = cy - dy;
	const adz = az - dz, bdz = bz - dz, cdz = cz - dz;
	const bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
	const cdxady = cdx * ady, adxcdy = adx * cdy;
	const adxbdy = adx * bdy, bdxady = bdx * ady;
	const det = adz * ( bdxcdy - cdxbdy ) + bdz * ( cdxady - adxcdy ) + cdz * ( adxbdy - bdxady );
	if ( det > staticBound || - det > staticBound ) return det > 0 ? - 1 : 1;
	const permanent =
		( Math.abs( bdxcdy ) + Math.abs( cdxbdy ) ) * Math.abs( adz ) +
		( Math.abs( cdxady ) + Math.abs( adxcdy ) ) * Math.abs( bdz ) +
		( Math.abs( adxbdy ) + Math.abs( bdxady ) ) * Math.abs( cdz );
	const bound = O3D_BOUND_A * permanent + O3D_UNDERFLOW;
	if ( det > bound || - det > bound ) return det > 0 ? - 1 : 1;
	return orientNearZero( p, a3, b3, c3, d3 );

}

/** orient beyond its first stage (kept out of line so that the hot first stage stays small enough to inline). */
function orientNearZero( p: Float64Array, a3: number, b3: number, c3: number, d3: number ): number {

	const ax = p[ a3 ], ay = p[ a3 + 1 ], az = p[ a3 + 2 ];
	const bx = p[ b3 ], by = p[ b3 + 1 ], bz = p[ b3 + 2 ];
	const cx = p[ c3 ], cy = p[ c3 + 1 ], cz = p[ c3 + 2 ];
	const dx = p[ d3 ], dy = p[ d3 + 1 ], dz = p[ d3 + 2 ];

	// Four points with one coordinate in common lie in an axis-aligned plane (grids, mostly): exactly 0.
	if ( ( az === bz && bz === cz && cz === dz ) || ( ax === bx && bx === cx && cx === dx ) ) return 0;
	if ( ay === by && by === cy && cy === dy ) return 0;

	// The library's expansion arithmetic is exact unless a tiny coordinate makes a product underflow.
	if ( outsideWindow( ax ) || outsideWindow( ay ) || outsideWindow( az ) || outsideWindow( bx ) || outsideWindow( by ) ||
		outsideWindow( bz ) || outsideWindow( cx ) || outsideWindow( cy ) || outsideWindow( cz ) || outsideWindow( dx ) ||
		outsideWindow( dy ) || outsideWindow( dz ) ) return - orient3dSign( p, a3 / 3, b3 / 3, c3 / 3, d3 / 3 );
	const o = orient3d( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz );
	return o > 0 ? - 1 : ( o < 0 ? 1 : 0 );

}

/** {@link orient} for any finite coordinates (beyond PREDICATE_RANGE too), e.g. stored probe positions. */
export function orientAnyScale( p: Float64Array, a: number, b: number, c: number, d: number ): number {

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c, d3 = 3 * d;
	const largest = Math.max(
		Math.abs( p[ a3 ] ), Math.abs( p[ a3 + 1 ] ), Math.abs( p[ a3 + 2 ] ), Math.abs( p[ b3 ] ), Math.abs( p[ b3 + 1 ] ),
		Math.abs( p[ b3 + 2 ] ), Math.abs( p[ c3 ] ), Math.abs( p[ c3 + 1 ] ), Math.abs( p[ c3 + 2 ] ), Math.abs( p[ d3 ] ),
		Math.abs( p[ d3 + 1 ] ), Math.abs( p[ d3 + 2 ] ) );
	return largest <= PREDICATE_RANGE ? orient( p, a, b, c, d ) : - orient3dSign( p, a, b, c, d );

}

/**
 * Exact in-sphere sign for a positively oriented tetrahedron abcd: 1 when e is strictly inside, −1 outside, 0 on the sphere.
 * @param staticBound {@link inSphereStaticBound} of an extent that holds the five points, or Infinity.
 */
export function inSphere( p: Float64Array, a: number, b: number, c: number, d: number, e: number, staticBound = Infinity ): number {

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c, d3 = 3 * d, e3 = 3 * e;
	const ax = p[ a3 ], ay = p[ a3 + 1 ], az = p[ a3 + 2 ];
	const bx = p[ b3 ], by = p[ b3 + 1 ], bz = p[ b3 + 2 ];
	const cx = p[ c3 ], cy = p[ c3 + 1 ], cz = p[ c3 + 2 ];
	const dx = p[ d3 ], dy = p[ d3 + 1 ], dz = p[ d3 + 2 ];
	const ex = p[ e3 ], ey = p[ e3 + 1 ], ez = p[ e3 + 2 ];

	const aex = ax - ex, bex = bx - ex, cex = cx - ex, dex = dx - ex;
	const aey = ay - ey, bey = by - ey, cey = cy - ey, dey = dy - ey;
	const aez = az - ez, bez = bz - ez, cez = cz - ez, dez = dz - ez;

	const aexbey = aex * bey, bexaey = bex * aey;
	const ab = aexbey - bexaey;
	const bexcey = bex * cey, cexbey = cex * bey;
	const bc = bexcey - cexbey;
	const cexdey = cex * dey, dexcey = dex * cey;
	const cd = cexdey - dexcey;
	const dexaey = dex * aey, aexdey = aex * dey;
	const da = dexaey - aexdey;
	const aexcey = aex * cey, cexaey = cex * aey;
	const ac = aexcey - cexaey;
	const bexdey = bex * dey, dexbey = dex * bey;
	const bd = bexdey - dexbey;

	const alift = aex * aex + aey * aey + aez * aez;
	const blift = bex * bex + bey * bey + bez * bez;
	const clift = cex * cex + cey * cey + cez * cez;
	const dlift = dex * dex + dey * dey + dez * dez;

	const det =
		( clift * ( dez * ab + aez * bd + bez * da ) - dlift * ( aez * bc - bez * ac + cez * ab ) ) +
		( alift * ( bez * cd - cez * bd + dez * bc ) - blift * ( cez * da + dez * ac + aez * cd ) );
	if ( det > staticBound || - det > staticBound ) return det > 0 ? 1 : - 1;

	const aezplus = Math.abs( aez ), bezplus = Math.abs( bez ), cezplus = Math.abs( cez ), dezplus = Math.abs( dez );
	const aexbeyplus = Math.abs( aexbey ) + Math.abs( bexaey );
	const bexceyplus = Math.abs( bexcey ) + Math.abs( cexbey );
	const cexdeyplus = Math.abs( cexdey ) + Math.abs( dexcey );
	const dexaeyplus = Math.abs( dexaey ) + Math.abs( aexdey );
	const aexceyplus = Math.abs( aexcey ) + Math.abs( cexaey );
	const bexdeyplus = Math.abs( bexdey ) + Math.abs( dexbey );
	const permanent =
		( cexdeyplus * bezplus + bexdeyplus * cezplus + bexceyplus * dezplus ) * alift +
		( dexaeyplus * cezplus + aexceyplus * dezplus + cexdeyplus * aezplus ) * blift +
		( aexbeyplus * dezplus + bexdeyplus * aezplus + dexaeyplus * bezplus ) * clift +
		( bexceyplus * aezplus + aexceyplus * bezplus + aexbeyplus * cezplus ) * dlift;
	const bound = ISP_BOUND_A * permanent + ISP_UNDERFLOW;
	if ( det > bound || - det > bound ) return det > 0 ? 1 : - 1;

	return inSphereNearZero( p, a3, b3, c3, d3, e3, permanent );

}

/** inSphere beyond its first stage (kept out of line so that the hot first stage stays small). */
function inSphereNearZero( p: Float64Array, a3: number, b3: number, c3: number, d3: number, e3: number, permanent: number ): number {

	const ax = p[ a3 ], ay = p[ a3 + 1 ], az = p[ a3 + 2 ];
	const bx = p[ b3 ], by = p[ b3 + 1 ], bz = p[ b3 + 2 ];
	const cx = p[ c3 ], cy = p[ c3 + 1 ], cz = p[ c3 + 2 ];
	const dx = p[ d3 ], dy = p[ d3 + 1 ], dz = p[ d3 + 2 ];
	const ex = p[ e3 ], ey = p[ e3 + 1 ], ez = p[ e3 + 2 ];

	// Five corners of one axis-aligned box (at most two distinct values per coordinate) lie exactly
	// on the sphere through all eight, whatever rounding made the box: the value is exactly 0.
	// Regular grids hit this case most of the time, and it spares the library's expansion arithmetic.
	if ( twoValues( ax, bx, cx, dx, ex ) && twoValues( ay, by, cy, dy, ey ) && twoValues( az, bz, cz, dz, ez ) ) return 0;

	const sign = inSphereDoubleDouble(
		ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez,
		ax - ex, ay - ey, az - ez, bx - ex, by - ey, bz - ez, cx - ex, cy - ey, cz - ez, dx - ex, dy - ey, dz - ez, permanent,
	);
	if ( sign !== 0 ) return sign;

	if ( outsideWindow( ax ) || outsideWindow( ay ) || outsideWindow( az ) || outsideWindow( bx ) || outsideWindow( by ) ||
		outsideWindow( bz ) || outsideWindow( cx ) || outsideWindow( cy ) || outsideWindow( cz ) || outsideWindow( dx ) ||
		outsideWindow( dy ) || outsideWindow( dz ) || outsideWindow( ex ) || outsideWindow( ey ) || outsideWindow( ez ) ) {

		return inSphereSign( p, a3 / 3, b3 / 3, c3 / 3, d3 / 3, e3 / 3 );

	}

	const s = insphere( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez );
	return s > 0 ? 1 : ( s < 0 ? - 1 : 0 );

}

/** True when the five numbers take at most two distinct values. */
function twoValues( v0: number, v1: number, v2: number, v3: number, v4: number ): boolean {

	let w = v0;
	if ( v1 !== v0 ) w = v1;
	else if ( v2 !== v0 ) w = v2;
	else if ( v3 !== v0 ) w = v3;
	else return true; // v4 alone may differ
	return ( v1 === v0 || v1 === w ) && ( v2 === v0 || v2 === w ) && ( v3 === v0 || v3 === w ) && ( v4 === v0 || v4 === w );

}

/** Lexicographic (x, y, z) comparison: the perturbation's rank order. */
function lexLess( p: Float64Array, a: number, b: number ): boolean {

	const a3 = 3 * a, b3 = 3 * b;
	if ( p[ a3 ] !== p[ b3 ] ) return p[ a3 ] < p[ b3 ];
	if ( p[ a3 + 1 ] !== p[ b3 + 1 ] ) return p[ a3 + 1 ] < p[ b3 + 1 ];
	return p[ a3 + 2 ] < p[ b3 + 2 ];

}

const _sorted = new Int32Array( 5 );

function sortByRank( p: Float64Array, count: number ): void {

	// Insertion sort of at most five indices.
	for ( let i = 1; i < count; i ++ ) {

		const v = _sorted[ i ];
		let j = i - 1;
		while ( j >= 0 && lexLess( p, v, _sorted[ j ] ) ) {

			_sorted[ j + 1 ] = _sorted[ j ];
			j --;

		}

		_sorted[ j + 1 ] = v;

	}

}

/**
 * In-sphere test with symbolic perturbation for a positively oriented tetrahedron abcd:
 * +1 when e is inside the perturbed circumsphere, −1 when outside; never 0 for distinct points.
 */
export function inSpherePerturbed( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

	const s = inSphere( p, a, b, c, d, e );
	if ( s > 0 ) return 1;
	if ( s < 0 ) return - 1;
	return inSphereTieBreak( p, a, b, c, d, e );

}

/**
 * The perturbed in-sphere sign when the exact in-sphere value is 0 (e on the circumsphere of the
 * positive tetrahedron abcd): +1 inside, −1 outside.
 */
export function inSphereTieBreak( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

	_sorted[ 0 ] = a; _sorted[ 1 ] = b; _sorted[ 2 ] = c; _sorted[ 3 ] = d; _sorted[ 4 ] = e;
	sortByRank( p, 5 );

	// The leading non-zero term of the perturbed determinant belongs to the highest-ranked point;
	// its cofactor is the orientation of the other four.
	for ( let i = 4; i > 1; i -- ) {

		const q = _sorted[ i ];
		if ( q === e ) return - 1;
		let o = 0;
		if ( q === d ) o = orient( p, a, b, c, e );
		else if ( q === c ) o = orient( p, a, b, e, d );
		else if ( q === b ) o = orient( p, a, e, c, d );
		else if ( q === a ) o = orient( p, e, b, c, d );
		if ( o !== 0 ) return o > 0 ? 1 : - 1;

	}

	return - 1;

}

/**
 * Orientation of three points inside their common plane, exact: the first coordinate-plane
 * projection (xy, yz, xz) in which they are not collinear. Which projection is used depends only
 * on the plane, so signs are comparable between triples of one plane. 0 when collinear.
 */
export function coplanarOrient( p: Float64Array, a: number, b: number, c: number ): number {

	let o = orient2dProjected( p, a, b, c, 0, 1 );
	if ( o !== 0 ) return o;
	o = orient2dProjected( p, a, b, c, 1, 2 );
	if ( o !== 0 ) return o;
	return orient2dProjected( p, a, b, c, 0, 2 );

}

/** Sign of robust-predicates' orient2d of a, b, c projected on coordinates i, j; exact. */
function orient2dProjected( p: Float64Array, a: number, b: number, c: number, i: number, j: number ): number {

	const ax = p[ 3 * a + i ], ay = p[ 3 * a + j ], bx = p[ 3 * b + i ], by = p[ 3 * b + j ], cx = p[ 3 * c + i ], cy = p[ 3 * c + j ];
	if ( outsideWindow( ax ) || outsideWindow( ay ) || outsideWindow( bx ) || outsideWindow( by ) || outsideWindow( cx ) ||
		outsideWindow( cy ) ) {

		return orient2dSign( p, a, b, c, i, j );

	}

	const o = orient2d( ax, ay, bx, by, cx, cy );
	return o > 0 ? 1 : ( o < 0 ? - 1 : 0 );

}

// Scratch point slot for the auxiliary off-plane point of inCircleCoplanar.
const _aux = new Float64Array( 18 );

/**
 * Exact: +1 when e (coplanar with abc) is strictly inside the circumcircle of abc, −1 outside, 0 on it.
 * Any sphere through a, b, c cuts their plane in exactly that circle, so an in-sphere test against
 * a, b, c and any point q off the plane decides it exactly; q only has to be off the plane, which
 * orient() checks exactly.
 */
export function inCircleCoplanar( p: Float64Array, a: number, b: number, c: number, e: number, extent: number ): number {

	for ( let k = 0; k < 3; k ++ ) {

		_aux[ k ] = p[ 3 * a + k ];
		_aux[ 3 + k ] = p[ 3 * b + k ];
		_aux[ 6 + k ] = p[ 3 * c + k ];
		_aux[ 12 + k ] = p[ 3 * e + k ];

	}

	// Push q along the axis where the plane's normal is largest; try the others if rounding made q coplanar.
	const ux = _aux[ 3 ] - _aux[ 0 ], uy = _aux[ 4 ] - _aux[ 1 ], uz = _aux[ 5 ] - _aux[ 2 ];
	const vx = _aux[ 6 ] - _aux[ 0 ], vy = _aux[ 7 ] - _aux[ 1 ], vz = _aux[ 8 ] - _aux[ 2 ];
	const nx = Math.abs( uy * vz - uz * vy ), ny = Math.abs( uz * vx - ux * vz ), nz = Math.abs( ux * vy - uy * vx );
	const first = nx >= ny && nx >= nz ? 0 : ( ny >= nz ? 1 : 2 );

	for ( let k = 0; k < 3; k ++ ) {

		const axis = ( first + k ) % 3;
		_aux[ 9 ] = _aux[ 0 ]; _aux[ 10 ] = _aux[ 1 ]; _aux[ 11 ] = _aux[ 2 ];
		// Far coordinates (an edited mesh's) would absorb a push of `extent`: push relative to them then.
		_aux[ 9 + axis ] += Math.max( extent, Math.abs( _aux[ 9 + axis ] ) * 2 ** - 40 );
		const o = orient( _aux, 0, 1, 2, 3 );
		if ( o === 0 ) continue;
		const s = inSphere( _aux, 0, 1, 2, 3, 4 );
		if ( s === 0 ) return 0;
		return ( s > 0 ) === ( o > 0 ) ? 1 : - 1;

	}

	return 0; // abc collinear: no circle

}

/**
 * In-circle test with symbolic perturbation for e coplanar with the non-collinear triangle abc:
 * +1 inside the perturbed circumcircle, −1 outside. Used for points on the plane of a hull face.
 */
export function inCirclePerturbed( p: Float64Array, a: number, b: number, c: number, e: number, extent: number ): number {

	const s = inCircleCoplanar( p, a, b, c, e, extent );
	if ( s !== 0 ) return s;

	_sorted[ 0 ] = a; _sorted[ 1 ] = b; _sorted[ 2 ] = c; _sorted[ 3 ] = e;
	sortByRank( p, 4 );
	const local = coplanarOrient( p, a, b, c );

	for ( let i = 3; i > 0; i -- ) {

		const q = _sorted[ i ];
		if ( q === e ) return - 1;
		let o = 0;
		if ( q === c ) o = coplanarOrient( p, a, b, e );
		else if ( q === b ) o = coplanarOrient( p, a, e, c );
		else if ( q === a ) o = coplanarOrient( p, e, b, c );
		if ( o !== 0 ) return o * local > 0 ? 1 : - 1;

	}

	return - 1;

}
