import { orient3d, insphere, orient2d } from 'robust-predicates';

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
 */

// robust-predicates' first-stage error bounds (Shewchuk 1997), with its machine epsilon 2^−53.
const EPSILON = 1.1102230246251565e-16;
const O3D_BOUND_A = ( 7 + 56 * EPSILON ) * EPSILON;
const ISP_BOUND_A = ( 16 + 224 * EPSILON ) * EPSILON;

/*
 * orient and inSphere repeat robust-predicates' first (floating-point) stage inline, expression for
 * expression, so they give the library's sign whenever that stage is conclusive, and call the
 * library (which redoes the cheap stage, then escalates) only when it is not: this saves the 12–15
 * argument call on the hot path of the walk and the conflict flood. inSphere adds two cheaper exact
 * steps before the library's expansion arithmetic (see inSphereNearZero).
 */

/**
 * Sign of det[ b − a, c − a, d − a ], exact: 1, −1 or 0. (Signs rather than values: a double
 * returned from a call that is not inlined is boxed, one allocation per predicate.)
 */
export function orient( p: Float64Array, a: number, b: number, c: number, d: number ): number {

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
	const permanent =
		( Math.abs( bdxcdy ) + Math.abs( cdxbdy ) ) * Math.abs( adz ) +
		( Math.abs( cdxady ) + Math.abs( adxcdy ) ) * Math.abs( bdz ) +
		( Math.abs( adxbdy ) + Math.abs( bdxady ) ) * Math.abs( cdz );
	const bound = O3D_BOUND_A * permanent;
	if ( det > bound || - det > bound ) return det > 0 ? - 1 : 1;

	const o = orient3d( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz );
	return o > 0 ? - 1 : ( o < 0 ? 1 : 0 );

}

/** Exact in-sphere sign for a positively oriented tetrahedron abcd: 1 when e is strictly inside, −1 outside, 0 on the sphere. */
export function inSphere( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

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
	const bound = ISP_BOUND_A * permanent;
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

	const s = insphere( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez );
	return s > 0 ? 1 : ( s < 0 ? - 1 : 0 );

}

// Second filter for nearly co-spherical points (regular grids), between the first stage and the
// library's expansion arithmetic. When the twelve coordinate differences are exact (all tails 0,
// the usual case on grids), the determinant is evaluated in double-double arithmetic: every
// operation below has a relative error of at most ~7u² (u = 2^−53; Joldes, Muller & Popescu 2017),
// and the expression is at most 9 operations deep, so the error is below ~63u² · permanent ≈
// 2^−100 · permanent. The result is trusted only beyond DD_BOUND · permanent = 2^−90 · permanent,
// a 1000-fold margin. Nonzero differences are confined to [2^−100, 2^100] so that no intermediate
// value can underflow or overflow, which the relative error bounds assume.
const DD_BOUND = 2 ** - 90;
const SPLITTER = 134217729; // 2^27 + 1
const TINY = 2 ** - 100, HUGE = 2 ** 100;

// Result of the double-double helpers below: high part in dd[ 0 ], low part in dd[ 1 ]. They
// return nothing: a double returned from a call that is not inlined is boxed (an allocation),
// and a module-level `let` holding doubles would allocate on every write too.
const dd = new Float64Array( 2 );

/** Exact product a·b (Dekker) into dd. */
function twoProduct( a: number, b: number ): void {

	const x = a * b;
	let c = SPLITTER * a;
	const ahi = c - ( c - a ), alo = a - ahi;
	c = SPLITTER * b;
	const bhi = c - ( c - b ), blo = b - bhi;
	dd[ 0 ] = x;
	dd[ 1 ] = alo * blo - ( x - ahi * bhi - alo * bhi - ahi * blo );

}

/** Double-double sum (AccurateDWPlusDW) into dd. */
function ddAdd( ah: number, al: number, bh: number, bl: number ): void {

	const sh = ah + bh;
	let v = sh - ah;
	const sl = ( ah - ( sh - v ) ) + ( bh - v );
	const th = al + bl;
	v = th - al;
	const tl = ( al - ( th - v ) ) + ( bl - v );
	const c = sl + th;
	const vh = sh + c;
	const vl = c - ( vh - sh );
	const w = tl + vl;
	const zh = vh + w;
	dd[ 0 ] = zh;
	dd[ 1 ] = w - ( zh - vh );

}

/** Double-double times double (DWTimesFP1) into dd. */
function ddMulD( ah: number, al: number, b: number ): void {

	twoProduct( ah, b );
	const ch = dd[ 0 ], cl1 = dd[ 1 ];
	const cl2 = al * b;
	const th = ch + cl2;
	const tl = cl1 + ( cl2 - ( th - ch ) );
	const zh = th + tl;
	dd[ 0 ] = zh;
	dd[ 1 ] = tl - ( zh - th );

}

/** Double-double product (DWTimesDW1) into dd. */
function ddMul( ah: number, al: number, bh: number, bl: number ): void {

	twoProduct( ah, bh );
	const ch = dd[ 0 ];
	const cl = dd[ 1 ] + ( ah * bl + al * bh );
	const zh = ch + cl;
	dd[ 0 ] = zh;
	dd[ 1 ] = cl - ( zh - ch );

}

/** True when `d`, the rounded a − b, is exact (its Two-Diff tail is 0) and 0 or within [TINY, HUGE] in magnitude. */
function exactDifference( a: number, b: number, d: number ): boolean {

	const v = a - d;
	return ( a - ( d + v ) ) + ( v - b ) === 0 && ( d === 0 || ( Math.abs( d ) >= TINY && Math.abs( d ) <= HUGE ) );

}

/** 2×2 minor p·s − q·r in double-double, into dd. */
function minor( p: number, s: number, q: number, r: number ): void {

	twoProduct( p, s );
	const h1 = dd[ 0 ], l1 = dd[ 1 ];
	twoProduct( q, r );
	ddAdd( h1, l1, - dd[ 0 ], - dd[ 1 ] );

}

/** x·m1 + y·m2 + z·m3 for doubles x, y, z and double-double minors m, into dd. */
function cofactor( x: number, m1h: number, m1l: number, y: number, m2h: number, m2l: number, z: number, m3h: number, m3l: number ): void {

	ddMulD( m1h, m1l, x );
	const h1 = dd[ 0 ], l1 = dd[ 1 ];
	ddMulD( m2h, m2l, y );
	ddAdd( h1, l1, dd[ 0 ], dd[ 1 ] );
	const h = dd[ 0 ], l = dd[ 1 ];
	ddMulD( m3h, m3l, z );
	ddAdd( h, l, dd[ 0 ], dd[ 1 ] );

}

/** x² + y² + z² in double-double, into dd. */
function lift( x: number, y: number, z: number ): void {

	twoProduct( x, x );
	const h1 = dd[ 0 ], l1 = dd[ 1 ];
	twoProduct( y, y );
	ddAdd( h1, l1, dd[ 0 ], dd[ 1 ] );
	const h = dd[ 0 ], l = dd[ 1 ];
	twoProduct( z, z );
	ddAdd( h, l, dd[ 0 ], dd[ 1 ] );

}

/**
 * The exact sign (1 or −1) of the in-sphere determinant when the differences to e are exact (and
 * in range) and the double-double value is beyond its error bound; 0 when undecided (then the
 * caller asks the library, whose exact stages settle it).
 */
function inSphereDoubleDouble(
	ax: number, ay: number, az: number, bx: number, by: number, bz: number, cx: number, cy: number, cz: number,
	dx: number, dy: number, dz: number, ex: number, ey: number, ez: number,
	aex: number, aey: number, aez: number, bex: number, bey: number, bez: number,
	cex: number, cey: number, cez: number, dex: number, dey: number, dez: number, permanent: number
): number {

	if ( ! ( exactDifference( ax, ex, aex ) && exactDifference( ay, ey, aey ) && exactDifference( az, ez, aez ) &&
		exactDifference( bx, ex, bex ) && exactDifference( by, ey, bey ) && exactDifference( bz, ez, bez ) &&
		exactDifference( cx, ex, cex ) && exactDifference( cy, ey, cey ) && exactDifference( cz, ez, cez ) &&
		exactDifference( dx, ex, dex ) && exactDifference( dy, ey, dey ) && exactDifference( dz, ez, dez ) ) ) return 0;

	// The same expression as the first stage: 2×2 minors of the x, y columns, 3×3 cofactors, lifts.
	minor( aex, bey, bex, aey ); const abh = dd[ 0 ], abl = dd[ 1 ];
	minor( bex, cey, cex, bey ); const bch = dd[ 0 ], bcl = dd[ 1 ];
	minor( cex, dey, dex, cey ); const cdh = dd[ 0 ], cdl = dd[ 1 ];
	minor( dex, aey, aex, dey ); const dah = dd[ 0 ], dal = dd[ 1 ];
	minor( aex, cey, cex, aey ); const ach = dd[ 0 ], acl = dd[ 1 ];
	minor( bex, dey, dex, bey ); const bdh = dd[ 0 ], bdl = dd[ 1 ];

	cofactor( dez, abh, abl, aez, bdh, bdl, bez, dah, dal ); const dabh = dd[ 0 ], dabl = dd[ 1 ];
	cofactor( aez, bch, bcl, - bez, ach, acl, cez, abh, abl ); const abch = dd[ 0 ], abcl = dd[ 1 ];
	cofactor( bez, cdh, cdl, - cez, bdh, bdl, dez, bch, bcl ); const bcdh = dd[ 0 ], bcdl = dd[ 1 ];
	cofactor( cez, dah, dal, dez, ach, acl, aez, cdh, cdl ); const cdah = dd[ 0 ], cdal = dd[ 1 ];

	lift( aex, aey, aez ); const alh = dd[ 0 ], all = dd[ 1 ];
	lift( bex, bey, bez ); const blh = dd[ 0 ], bll = dd[ 1 ];
	lift( cex, cey, cez ); const clh = dd[ 0 ], cll = dd[ 1 ];
	lift( dex, dey, dez ); const dlh = dd[ 0 ], dll = dd[ 1 ];

	ddMul( clh, cll, dabh, dabl ); const t1h = dd[ 0 ], t1l = dd[ 1 ];
	ddMul( dlh, dll, abch, abcl ); const t2h = dd[ 0 ], t2l = dd[ 1 ];
	ddMul( alh, all, bcdh, bcdl ); const t3h = dd[ 0 ], t3l = dd[ 1 ];
	ddMul( blh, bll, cdah, cdal ); const t4h = dd[ 0 ], t4l = dd[ 1 ];
	ddAdd( t1h, t1l, - t2h, - t2l ); const uh = dd[ 0 ], ul = dd[ 1 ];
	ddAdd( t3h, t3l, - t4h, - t4l ); const vh = dd[ 0 ], vl = dd[ 1 ];
	ddAdd( uh, ul, vh, vl );
	const det = dd[ 0 ];

	const bound = DD_BOUND * permanent;
	return det > bound ? 1 : ( - det > bound ? - 1 : 0 );

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

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c;
	let o = orient2d( p[ a3 ], p[ a3 + 1 ], p[ b3 ], p[ b3 + 1 ], p[ c3 ], p[ c3 + 1 ] );
	if ( o !== 0 ) return o > 0 ? 1 : - 1;
	o = orient2d( p[ a3 + 1 ], p[ a3 + 2 ], p[ b3 + 1 ], p[ b3 + 2 ], p[ c3 + 1 ], p[ c3 + 2 ] );
	if ( o !== 0 ) return o > 0 ? 1 : - 1;
	o = orient2d( p[ a3 ], p[ a3 + 2 ], p[ b3 ], p[ b3 + 2 ], p[ c3 ], p[ c3 + 2 ] );
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
		_aux[ 9 + axis ] += extent;
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
