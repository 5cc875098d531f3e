import { orient3d, insphere } from 'robust-predicates';

/*
 * Independent, brute-force checks of a tetrahedralization, written against robust-predicates
 * directly (not the library's predicate wrappers) so a sign slip in the library cannot hide here.
 *
 * Any scale: the checks run on a copy of the points scaled by a power of two to unit size (exact;
 * every sign is the same as on the input), and where robust-predicates could under- or overflow
 * (a coordinate below 2^−150 of the extent, but not 0) the signs come from BigInt arithmetic of
 * this file's own. Volumes are summed on the copy and reported in the input's units.
 */

// robust-predicates is exact when every coordinate is 0 or of magnitude in [LOW, HIGH] (no
// product of up to five factors under- or overflows).
const LOW = 2 ** - 150, HIGH = 2 ** 180;

/** The exponent k with 2^k ≤ v < 2^(k+1), for a finite v > 0 (by search, not by bit tricks: independent of the library). */
function floorLog2( v: number ): number {

	let k = Math.floor( Math.log2( v ) );
	while ( pow2( k ) > v ) k --;
	while ( pow2( k + 1 ) <= v ) k ++;
	return k;

}

/** 2^k as a product of two doubles (x · 2^k exact when the result is representable). */
function times2( x: number, k: number ): number {

	const half = Math.trunc( k / 2 );
	return x * pow2( half ) * pow2( k - half );

}

function pow2( k: number ): number {

	return k >= - 1074 ? 2 ** k : 0;

}

/**
 * The points scaled by 2^−k, k from the largest side of their bounding box (into [1, 2)), and k.
 * @throws Error when a coordinate does not scale exactly (the check would then not be exact).
 */
export function normalizedCopy( p: Float64Array ): { points: Float64Array; exponent: number } {

	let side = 0;
	for ( let a = 0; a < 3; a ++ ) {

		let min = Infinity, max = - Infinity;
		for ( let i = a; i < p.length; i += 3 ) { min = Math.min( min, p[ i ] ); max = Math.max( max, p[ i ] ); }
		side = Math.max( side, max / 2 - min / 2 );

	}

	if ( ! Number.isFinite( side ) ) throw new Error( 'checkDelaunay: the points are not all finite.' );
	const exponent = side > 0 ? floorLog2( side ) + 1 : 0;
	const points = new Float64Array( p.length );
	for ( let i = 0; i < p.length; i ++ ) {

		points[ i ] = times2( p[ i ], - exponent );
		if ( times2( points[ i ], exponent ) !== p[ i ] ) throw new Error( `checkDelaunay: coordinate ${i} (${p[ i ]}) does not scale exactly by 2^${- exponent}.` );

	}

	return { points, exponent };

}

function inWindow( values: number[] ): boolean {

	for ( const v of values ) {

		const a = Math.abs( v );
		if ( a > HIGH || ( a < LOW && a !== 0 ) ) return false;

	}

	return true;

}

/** Exact integers m · 2^(q − lowest) for doubles (a double is an integer times a power of two). */
function bigIntegers( values: number[] ): bigint[] {

	const parts = values.map( ( v ) => {

		if ( v === 0 ) return { m: 0n, q: 0 };
		let q = floorLog2( Math.abs( v ) ) - 52;
		if ( q < - 1074 ) q = - 1074;
		return { m: BigInt( times2( v, - q ) ), q };

	} );
	const lowest = Math.min( ...parts.filter( ( x ) => x.m !== 0n ).map( ( x ) => x.q ) );
	return parts.map( ( x ) => x.m === 0n ? 0n : x.m << BigInt( x.q - lowest ) );

}

function coordinates( p: Float64Array, ids: number[] ): number[] {

	return ids.flatMap( ( i ) => [ p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ] ] );

}

/**
 * Exact sign of det[b − a, c − a, d − a] (robust-predicates' orient3d has the opposite sign);
 * `allInWindow`: every coordinate of p is in robust-predicates' window (no BigInt needed).
 */
function volumeSign( p: Float64Array, allInWindow: boolean, a: number, b: number, c: number, d: number ): number {

	if ( allInWindow ) {

		return - Math.sign( orient3d(
			p[ 3 * a ], p[ 3 * a + 1 ], p[ 3 * a + 2 ], p[ 3 * b ], p[ 3 * b + 1 ], p[ 3 * b + 2 ],
			p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ], p[ 3 * d ], p[ 3 * d + 1 ], p[ 3 * d + 2 ] ) );

	}

	const v = coordinates( p, [ a, b, c, d ] );
	if ( inWindow( v ) ) {

		const [ ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz ] = v;
		return - Math.sign( orient3d( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz ) );

	}

	const [ ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz ] = bigIntegers( v );
	const ux = bx - ax, uy = by - ay, uz = bz - az, vx = cx - ax, vy = cy - ay, vz = cz - az, wx = dx - ax, wy = dy - ay, wz = dz - az;
	const det = ux * ( vy * wz - vz * wy ) - uy * ( vx * wz - vz * wx ) + uz * ( vx * wy - vy * wx );
	return det > 0n ? 1 : det < 0n ? - 1 : 0;

}

/** Exact: > 0 when e is strictly inside the circumsphere of the positive tetrahedron abcd. */
function inSphereSign( p: Float64Array, allInWindow: boolean, a: number, b: number, c: number, d: number, e: number ): number {

	// robust-predicates: > 0 inside for a tetrahedron with det[b−a, c−a, d−a] > 0.
	if ( allInWindow ) {

		return Math.sign( insphere(
			p[ 3 * a ], p[ 3 * a + 1 ], p[ 3 * a + 2 ], p[ 3 * b ], p[ 3 * b + 1 ], p[ 3 * b + 2 ],
			p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ], p[ 3 * d ], p[ 3 * d + 1 ], p[ 3 * d + 2 ],
			p[ 3 * e ], p[ 3 * e + 1 ], p[ 3 * e + 2 ] ) );

	}

	const v = coordinates( p, [ a, b, c, d, e ] );
	if ( inWindow( v ) ) {

		const [ ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez ] = v;
		return Math.sign( insphere( ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz, ex, ey, ez ) );

	}

	// The 4×4 determinant of the rows (x − ex, y − ey, z − ez, |· − e|²) of a, b, c, d, expanded by
	// its last column; its sign is − (inside) for a positive tetrahedron, so the result is negated.
	const w = bigIntegers( v );
	const rows: bigint[][] = [];
	for ( let r = 0; r < 4; r ++ ) {

		const x = w[ 3 * r ] - w[ 12 ], y = w[ 3 * r + 1 ] - w[ 13 ], z = w[ 3 * r + 2 ] - w[ 14 ];
		rows.push( [ x, y, z, x * x + y * y + z * z ] );

	}

	const det3 = ( [ r0, r1, r2 ]: bigint[][] ) => r0[ 0 ] * ( r1[ 1 ] * r2[ 2 ] - r1[ 2 ] * r2[ 1 ] )
		- r0[ 1 ] * ( r1[ 0 ] * r2[ 2 ] - r1[ 2 ] * r2[ 0 ] ) + r0[ 2 ] * ( r1[ 0 ] * r2[ 1 ] - r1[ 1 ] * r2[ 0 ] );
	let det = 0n;
	for ( let r = 0; r < 4; r ++ ) {

		const minor = rows.filter( ( _, i ) => i !== r ).map( ( row ) => row.slice( 0, 3 ) );
		const term = rows[ r ][ 3 ] * det3( minor );
		det += ( r + 3 ) % 2 === 0 ? term : - term;

	}

	return det > 0n ? - 1 : det < 0n ? 1 : 0;

}

function volume( p: Float64Array, a: number, b: number, c: number, d: number ): number {

	const ax = p[ 3 * a ], ay = p[ 3 * a + 1 ], az = p[ 3 * a + 2 ];
	const ux = p[ 3 * b ] - ax, uy = p[ 3 * b + 1 ] - ay, uz = p[ 3 * b + 2 ] - az;
	const vx = p[ 3 * c ] - ax, vy = p[ 3 * c + 1 ] - ay, vz = p[ 3 * c + 2 ] - az;
	const wx = p[ 3 * d ] - ax, wy = p[ 3 * d + 1 ] - ay, wz = p[ 3 * d + 2 ] - az;
	return ( ux * ( vy * wz - vz * wy ) - uy * ( vx * wz - vz * wx ) + uz * ( vx * wy - vy * wx ) ) / 6;

}

export interface DelaunayReport {

	tetrahedra: number;
	nonPositive: number;
	asymmetricNeighbors: number;
	mismatchedFaces: number;
	unusedPoints: number;
	hullViolations: number;
	emptySphereViolations: number;
	/** Sum of the tetrahedra's volumes, in the input's units (may overflow or underflow at extreme scales). */
	volumeSum: number;
	/** Volume enclosed by the hull faces, in the input's units (likewise). */
	hullVolume: number;
	/**
	 * |volumeSum − hullVolume| relative to the sum of the magnitudes of the hull's cone volumes (the
	 * scale of the rounding in hullVolume), computed at unit scale; for hulls too thin for floating
	 * point, 0 or 1 as the exact identity holds or not (meaningful at any scale).
	 */
	tilingError: number;

}

/**
 * Runs every check; `skip` holds point indices that were merged as duplicates (not vertices).
 */
export function checkDelaunay(
	input: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array, skip: Set<number> = new Set(),
): DelaunayReport {

	const { points: p, exponent } = normalizedCopy( input );
	const safe = inWindow( Array.from( p ) );
	const n = p.length / 3, count = tetrahedra.length / 4;
	const report: DelaunayReport = {
		tetrahedra: count, nonPositive: 0, asymmetricNeighbors: 0, mismatchedFaces: 0, unusedPoints: 0,
		hullViolations: 0, emptySphereViolations: 0, volumeSum: 0, hullVolume: 0, tilingError: 0,
	};

	let volumeSum = 0, hullVolume = 0, coneMagnitudes = 0;
	const used = new Uint8Array( n );
	for ( let t = 0; t < count; t ++ ) {

		const [ a, b, c, d ] = tetrahedra.subarray( 4 * t, 4 * t + 4 );
		used[ a ] = used[ b ] = used[ c ] = used[ d ] = 1;
		if ( volumeSign( p, safe, a, b, c, d ) <= 0 ) report.nonPositive ++;
		volumeSum += volume( p, a, b, c, d );

		for ( let i = 0; i < 4; i ++ ) {

			const u = neighbors[ 4 * t + i ];
			if ( u === - 1 ) continue;
			let back = - 1;
			for ( let j = 0; j < 4; j ++ ) if ( neighbors[ 4 * u + j ] === t ) back = j;
			if ( back === - 1 ) { report.asymmetricNeighbors ++; continue; }
			const mine = faceKey( tetrahedra, t, i ), theirs = faceKey( tetrahedra, u, back );
			if ( mine !== theirs ) report.mismatchedFaces ++;

		}

	}

	for ( let i = 0; i < n; i ++ ) if ( ! used[ i ] && ! skip.has( i ) ) report.unusedPoints ++;

	// Hull faces: every point on the inner side; their enclosed volume by the divergence theorem,
	// as cones from the centroid (near the hull, so far-away coordinates do not cancel).
	const centroid = [ 0, 0, 0 ];
	for ( let i = 0; i < n; i ++ ) for ( let a = 0; a < 3; a ++ ) centroid[ a ] += p[ 3 * i + a ] / n;
	for ( let t = 0; t < count; t ++ ) {

		for ( let i = 0; i < 4; i ++ ) {

			if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
			const v = Array.from( tetrahedra.subarray( 4 * t, 4 * t + 4 ) );
			// Replace the inner vertex by a test point: positive means the same side as the inner vertex.
			for ( let q = 0; q < n; q ++ ) {

				if ( skip.has( q ) ) continue;
				const w = v.slice(); w[ i ] = q;
				if ( volumeSign( p, safe, w[ 0 ], w[ 1 ], w[ 2 ], w[ 3 ] ) < 0 ) { report.hullViolations ++; break; }

			}

			// The cell with its inner vertex moved to the apex: the signed volume of the cone from the
			// apex over this face, positive when the apex is on the inner side. Summed over a closed
			// outward surface, these give the enclosed volume wherever the apex is.
			const cone = coneVolume( p, v, i, centroid );
			hullVolume += cone;
			coneMagnitudes += Math.abs( cone );

		}

	}

	report.volumeSum = times2( volumeSum, 3 * exponent );
	report.hullVolume = times2( hullVolume, 3 * exponent );
	report.tilingError = Math.abs( volumeSum - hullVolume ) / coneMagnitudes;
	// A hull too thin for floating-point volumes: the same identity in exact arithmetic.
	if ( ! ( report.tilingError <= 1e-9 ) ) report.tilingError = exactTiling( p, tetrahedra, neighbors ) ? 0 : 1;
	report.emptySphereViolations = countEmptySphereViolations( p, safe, tetrahedra, skip );
	return report;

}

/**
 * Whether the tetrahedra's volumes sum exactly (BigInt) to the cones from point 0 over the hull
 * faces (neighbour −1): the divergence theorem, an identity for cells that tile their hull.
 */
function exactTiling( p: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array ): boolean {

	const w = bigIntegers( Array.from( p ) );
	const det = ( v: number[] ) => {

		const [ a, b, c, d ] = v.map( ( i ) => [ w[ 3 * i ], w[ 3 * i + 1 ], w[ 3 * i + 2 ] ] );
		const u = [ 0, 1, 2 ].map( ( k ) => b[ k ] - a[ k ] ), s = [ 0, 1, 2 ].map( ( k ) => c[ k ] - a[ k ] );
		const t = [ 0, 1, 2 ].map( ( k ) => d[ k ] - a[ k ] );
		return u[ 0 ] * ( s[ 1 ] * t[ 2 ] - s[ 2 ] * t[ 1 ] ) - u[ 1 ] * ( s[ 0 ] * t[ 2 ] - s[ 2 ] * t[ 0 ] )
			+ u[ 2 ] * ( s[ 0 ] * t[ 1 ] - s[ 1 ] * t[ 0 ] );

	};

	let cells = 0n, cones = 0n;
	for ( let t = 0; t < tetrahedra.length / 4; t ++ ) {

		const v = Array.from( tetrahedra.subarray( 4 * t, 4 * t + 4 ) );
		cells += det( v );
		for ( let i = 0; i < 4; i ++ ) {

			if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
			const cone = v.slice();
			cone[ i ] = 0;
			cones += det( cone );

		}

	}

	return cells === cones;

}

function faceKey( tetrahedra: Uint32Array, t: number, i: number ): string {

	const f: number[] = [];
	for ( let k = 0; k < 4; k ++ ) if ( k !== i ) f.push( tetrahedra[ 4 * t + k ] );
	return f.sort( ( a, b ) => a - b ).join( ',' );

}

function coneVolume( p: Float64Array, v: number[], i: number, apex: number[] ): number {

	const q = new Float64Array( 12 ); // slot i is the apex, at the origin of these coordinates
	for ( let k = 0; k < 4; k ++ ) {

		if ( k === i ) continue;
		for ( let a = 0; a < 3; a ++ ) q[ 3 * k + a ] = p[ 3 * v[ k ] + a ] - apex[ a ];

	}

	return volume( q, 0, 1, 2, 3 );

}

/**
 * Counts tetrahedra with an input point strictly inside their circumsphere (exact insphere), with a
 * uniform grid over the points to find the candidates inside each sphere's bounding box.
 */
function countEmptySphereViolations( p: Float64Array, safe: boolean, tetrahedra: Uint32Array, skip: Set<number> ): number {

	const n = p.length / 3;
	let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
	for ( let i = 0; i < n; i ++ ) {

		minX = Math.min( minX, p[ 3 * i ] ); maxX = Math.max( maxX, p[ 3 * i ] );
		minY = Math.min( minY, p[ 3 * i + 1 ] ); maxY = Math.max( maxY, p[ 3 * i + 1 ] );
		minZ = Math.min( minZ, p[ 3 * i + 2 ] ); maxZ = Math.max( maxZ, p[ 3 * i + 2 ] );

	}

	const cells = Math.max( 1, Math.round( Math.cbrt( n / 2 ) ) );
	const sx = ( maxX - minX ) / cells || 1, sy = ( maxY - minY ) / cells || 1, sz = ( maxZ - minZ ) / cells || 1;
	const bucket: number[][] = Array.from( { length: cells ** 3 }, () => [] );
	const cell = ( v: number, min: number, s: number ) => Math.min( cells - 1, Math.max( 0, Math.floor( ( v - min ) / s ) ) );
	for ( let i = 0; i < n; i ++ ) {

		if ( skip.has( i ) ) continue;
		const k = cell( p[ 3 * i ], minX, sx ) + cells * ( cell( p[ 3 * i + 1 ], minY, sy ) + cells * cell( p[ 3 * i + 2 ], minZ, sz ) );
		bucket[ k ].push( i );

	}

	let violations = 0;
	for ( let t = 0, count = tetrahedra.length / 4; t < count; t ++ ) {

		const [ a, b, c, d ] = tetrahedra.subarray( 4 * t, 4 * t + 4 );
		const [ cx, cy, cz, r ] = circumsphere( p, a, b, c, d );
		// A sphere too flat to locate in floating point (an invalid cell) is checked against every point.
		const everywhere = ! Number.isFinite( cx + cy + cz + r );
		const pad = r * ( 1 + 1e-6 ) + 1e-12;
		const range = ( v: number, min: number, s: number, lo: boolean ) => {

			return everywhere ? ( lo ? 0 : cells - 1 ) : cell( v + ( lo ? - pad : pad ), min, s );

		};

		for ( let k = range( cz, minZ, sz, true ); k <= range( cz, minZ, sz, false ); k ++ ) {

			for ( let j = range( cy, minY, sy, true ); j <= range( cy, minY, sy, false ); j ++ ) {

				for ( let i = range( cx, minX, sx, true ); i <= range( cx, minX, sx, false ); i ++ ) {

					for ( const q of bucket[ i + cells * ( j + cells * k ) ] ) {

						if ( q === a || q === b || q === c || q === d ) continue;
						if ( inSphereSign( p, safe, a, b, c, d, q ) > 0 ) violations ++;

					}

				}

			}

		}

	}

	return violations;

}

function circumsphere( p: Float64Array, a: number, b: number, c: number, d: number ): [ number, number, number, number ] {

	const ax = p[ 3 * a ], ay = p[ 3 * a + 1 ], az = p[ 3 * a + 2 ];
	const bx = p[ 3 * b ] - ax, by = p[ 3 * b + 1 ] - ay, bz = p[ 3 * b + 2 ] - az;
	const cx = p[ 3 * c ] - ax, cy = p[ 3 * c + 1 ] - ay, cz = p[ 3 * c + 2 ] - az;
	const dx = p[ 3 * d ] - ax, dy = p[ 3 * d + 1 ] - ay, dz = p[ 3 * d + 2 ] - az;
	const b2 = bx * bx + by * by + bz * bz, c2 = cx * cx + cy * cy + cz * cz, d2 = dx * dx + dy * dy + dz * dz;
	const det = 2 * ( bx * ( cy * dz - cz * dy ) - by * ( cx * dz - cz * dx ) + bz * ( cx * dy - cy * dx ) );
	const ox = ( b2 * ( cy * dz - cz * dy ) - c2 * ( by * dz - bz * dy ) + d2 * ( by * cz - bz * cy ) ) / det;
	const oy = ( bx * ( c2 * dz - cz * d2 ) - cx * ( b2 * dz - bz * d2 ) + dx * ( b2 * cz - bz * c2 ) ) / det;
	const oz = ( bx * ( cy * d2 - c2 * dy ) - cx * ( by * d2 - b2 * dy ) + dx * ( by * c2 - b2 * cy ) ) / det;
	return [ ax + ox, ay + oy, az + oz, Math.hypot( ox, oy, oz ) ];

}
