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
export function inSphereDoubleDouble(
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
