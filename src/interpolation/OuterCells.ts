import { extentExponent, scaleInPlace, timesPowerOfTwo } from '../tetrahedra/powerOfTwo.js';
import { hullAdjacency, hullBounds } from './hullSurface.js';
import { FAR_LIMIT, outerCellNormals } from './outerCellNormals.js';

// Hulls whose largest side is within 2^±LOCAL_RANGE keep their coordinates (no product of the
// geometry below, up to four lengths, can over- or underflow); others work in a copy scaled by a
// power of two to unit size.
const LOCAL_RANGE = 100;

// A point whose weights in a cell are all ≥ −OUTER_EPSILON belongs to it (rounding on shared quads).
const OUTER_EPSILON = 1e-10;

// Points closer to a face's plane than this fraction of the hull's size count as on it (t = 0), so a
// point the interior walk rounded to "just outside" does not look for a root far away.
const ON_PLANE_EPSILON = 1e-12;

const _solve = new Float64Array( 4 );

// The helpers of a query take the point and the cubic, and hand back the root, through these
// rather than as arguments and return values: a double passed to or returned from a function V8
// does not inline is boxed, a heap allocation per call.
const _root = new Float64Array( 1 );
const _query = new Float64Array( 3 );
const _cubic = new Float64Array( 4 );

/**
 * Extrapolation outside the convex hull of the probes by "outer cells" (what Unity's light probes
 * do): every hull vertex gets an outward normal, and every hull triangle (a, b, c) sweeps the region
 * covered by the moved triangle { a + t·na, b + t·nb, c + t·nc }, t ≥ 0. A point of that region gets
 * its barycentric weights in the moved triangle whose plane it lies in — continuous with the
 * tetrahedra's weights on the hull and across neighbouring cells, converging far away. The cells tile
 * the outside (normals are repaired where a sweep would fold); {@link OuterCells.locate} walks from
 * cell to cell, so a point costs a few cells. Built in O(hull faces). Pure math: no three.js. Used by
 * `TetrahedralMesh`; exposed for tests and tools. Any scale: a hull far from unit size is handled in
 * a copy of the positions scaled by 2^−exponent (docs/robustness.md). Construction, proofs and
 * history: docs/outer-cells.md.
 */
export class OuterCells {

	/** Hull triangles, 3 probe indices each, counter-clockwise seen from outside. */
	readonly faces: Uint32Array;

	/**
	 * `adjacency[3f + k]`: the hull triangle across the edge of f opposite its vertex k (the edge
	 * between vertices k + 1 and k + 2) — the outer cell that shares that swept quad.
	 */
	readonly adjacency: Int32Array;

	/**
	 * Unit outward normal per probe: the angle-weighted average of its hull faces' normals (smoothed,
	 * then blended towards radial, where a cell would fold: docs/outer-cells.md); 0, 0, 0 off the
	 * hull.
	 */
	readonly normals: Float64Array;

	/**
	 * Per hull triangle, 12 numbers giving the cubic in τ = t / scale whose roots put a query q in
	 * the plane of the moved triangle: c0 = V0·(q − a), c1 = V1·(q − a) + k1,
	 * c2 = V2·(q − a) + k2, c3 = k3, stored as V0, V1, V2, k1, k2, k3 and scaled so that c0 is the
	 * signed distance of q from the face's plane in units of `scale`. In the local frame: q and a
	 * are positions × 2^−exponent.
	 */
	readonly coefficients: Float64Array;

	/**
	 * The local frame's power of two: its coordinates are the positions × 2^−exponent. 0 (the
	 * positions themselves) unless the hull's size is beyond 2^±100.
	 */
	readonly exponent: number;

	/** The hull's size (bounding-box diagonal of the hull vertices, i.e. of the probes) in the local frame: the unit of τ. */
	readonly scale: number;

	/** Centre of the probes' bounding box in the local frame (where far queries are pulled towards). */
	readonly center: Float64Array;

	// The positions (shared with the mesh), their local-frame copy (the same array when exponent is
	// 0), and the factors between the frames.
	private _positions: Float64Array;
	private local: Float64Array;
	private readonly toLocal: number;
	private readonly toGiven: number;

	/**
	 * @param positions Probe positions (kept by reference).
	 * @param faces Hull triangles, counter-clockwise seen from outside, forming a closed surface.
	 * @param where Function name for error messages.
	 * @throws Error when the triangles do not form one closed convex surface (an edge not shared by
	 * exactly two faces, several surfaces, or a reflex edge).
	 */
	constructor( positions: Float64Array, faces: Uint32Array, where = 'OuterCells' ) {

		this.faces = faces;
		const faceCount = faces.length / 3;

		// The bounding box of the hull's vertices is the probes' (extremes are hull vertices), and
		// ignores positions that are in no face (probes removed from an incremental mesh).
		const bounds = hullBounds( positions, faces );
		if ( faces.length === 0 ) bounds.fill( 0 );
		const k = extentExponent( bounds );
		// Clamped so that each factor between the frames is one double.
		const exponent = this.exponent = Math.abs( k ) <= LOCAL_RANGE ? 0 : Math.min( 1023, Math.max( - 1022, k ) );
		this.toLocal = timesPowerOfTwo( 1, - exponent );
		this.toGiven = timesPowerOfTwo( 1, exponent );
		this._positions = this.local = positions;
		this.positions = positions;
		if ( exponent !== 0 ) scaleInPlace( bounds, 6, exponent );
		const minX = bounds[ 0 ], minY = bounds[ 1 ], minZ = bounds[ 2 ], maxX = bounds[ 3 ], maxY = bounds[ 4 ], maxZ = bounds[ 5 ];
		this.scale = Math.hypot( maxX - minX, maxY - minY, maxZ - minZ ) || 1;
		this.center = Float64Array.of( ( minX + maxX ) / 2, ( minY + maxY ) / 2, ( minZ + maxZ ) / 2 );
		const p = this.local;

		const normals = this.normals = outerCellNormals( p, faces, this.scale );
		this.adjacency = hullAdjacency( positions, faces, where );

		// Cubic coefficients. With E1 = b − a, E2 = c − a, F1 = nb − na, F2 = nc − na, G = −na and
		// D = q − a, det[E1 + tF1, E2 + tF2, D + tG] expands to
		//   c0 = (E1×E2)·D
		//   c1 = (F1×E2 + E1×F2)·D + (E1×E2)·G
		//   c2 = (F1×F2)·D + (F1×E2 + E1×F2)·G
		//   c3 = (F1×F2)·G.
		// Dividing by |E1×E2|·L and substituting t = Lτ gives coefficients of similar size for any
		// scene scale, and c0 = signed distance / L.
		const L = this.scale;
		const c = this.coefficients = new Float64Array( 12 * faceCount );
		for ( let f = 0; f < faceCount; f ++ ) {

			const ia = 3 * faces[ 3 * f ], ib = 3 * faces[ 3 * f + 1 ], ic = 3 * faces[ 3 * f + 2 ];
			const e1x = p[ ib ] - p[ ia ], e1y = p[ ib + 1 ] - p[ ia + 1 ], e1z = p[ ib + 2 ] - p[ ia + 2 ];
			const e2x = p[ ic ] - p[ ia ], e2y = p[ ic + 1 ] - p[ ia + 1 ], e2z = p[ ic + 2 ] - p[ ia + 2 ];
			const f1x = normals[ ib ] - normals[ ia ], f1y = normals[ ib + 1 ] - normals[ ia + 1 ];
			const f1z = normals[ ib + 2 ] - normals[ ia + 2 ];
			const f2x = normals[ ic ] - normals[ ia ], f2y = normals[ ic + 1 ] - normals[ ia + 1 ];
			const f2z = normals[ ic + 2 ] - normals[ ia + 2 ];
			const gx = - normals[ ia ], gy = - normals[ ia + 1 ], gz = - normals[ ia + 2 ];
			// N0 = E1×E2, N1 = F1×E2 + E1×F2, N2 = F1×F2.
			const n0x = e1y * e2z - e1z * e2y, n0y = e1z * e2x - e1x * e2z, n0z = e1x * e2y - e1y * e2x;
			const n1x = ( f1y * e2z - f1z * e2y ) + ( e1y * f2z - e1z * f2y );
			const n1y = ( f1z * e2x - f1x * e2z ) + ( e1z * f2x - e1x * f2z );
			const n1z = ( f1x * e2y - f1y * e2x ) + ( e1x * f2y - e1y * f2x );
			const n2x = f1y * f2z - f1z * f2y, n2y = f1z * f2x - f1x * f2z, n2z = f1x * f2y - f1y * f2x;
			const area = Math.hypot( n0x, n0y, n0z ) || 1;
			const s0 = 1 / ( area * L ), s1 = 1 / area, s2 = L / area, s3 = L * L / area;
			const k = 12 * f;
			c[ k ] = n0x * s0; c[ k + 1 ] = n0y * s0; c[ k + 2 ] = n0z * s0;
			c[ k + 3 ] = n1x * s1; c[ k + 4 ] = n1y * s1; c[ k + 5 ] = n1z * s1;
			c[ k + 6 ] = n2x * s2; c[ k + 7 ] = n2y * s2; c[ k + 8 ] = n2z * s2;
			c[ k + 9 ] = ( n0x * gx + n0y * gy + n0z * gz ) * s1;
			c[ k + 10 ] = ( n1x * gx + n1y * gy + n1z * gz ) * s2;
			c[ k + 11 ] = ( n2x * gx + n2y * gy + n2z * gz ) * s3;

		}

	}

	/**
	 * Probe positions, x, y, z per probe (shared with the mesh, not copied). An incremental
	 * `TetrahedralMesh` points it at its new positions array after an edit that changed no hull
	 * face (the hull vertices' coordinates are then the same).
	 */
	get positions(): Float64Array {

		return this._positions;

	}

	set positions( positions: Float64Array ) {

		this._positions = positions;
		if ( this.exponent === 0 ) {

			this.local = positions;

		} else {

			this.local = positions.slice();
			scaleInPlace( this.local, this.local.length, this.exponent );

		}

	}

	/** Number of outer cells (= hull triangles). */
	get count(): number {

		return this.faces.length / 3;

	}

	/**
	 * Signed distance of (x, y, z) from the plane of hull triangle f, positive outside. Since the
	 * hull is convex, a positive value means the point is outside the hull.
	 */
	signedDistance( f: number, x: number, y: number, z: number ): number {

		const c = this.coefficients, k = 12 * f, a = 3 * this.faces[ 3 * f ], p = this.local, s = this.toLocal;
		const distance = c[ k ] * ( x * s - p[ a ] ) + c[ k + 1 ] * ( y * s - p[ a + 1 ] ) + c[ k + 2 ] * ( z * s - p[ a + 2 ] );
		return distance * this.scale * this.toGiven;

	}

	/** Whether (x, y, z) is strictly beyond the plane of hull triangle f (so outside the hull). */
	isBeyond( f: number, x: number, y: number, z: number ): boolean {

		const c = this.coefficients, k = 12 * f, a = 3 * this.faces[ 3 * f ], p = this.local, s = this.toLocal;
		return c[ k ] * ( x * s - p[ a ] ) + c[ k + 1 ] * ( y * s - p[ a + 1 ] ) + c[ k + 2 ] * ( z * s - p[ a + 2 ] ) > 0;

	}

	/**
	 * Solves outer cell f for (x, y, z): the smallest t ≥ 0 at which the point lies in the plane of
	 * the moved triangle, and the point's barycentric weights in it. Allocation-free.
	 * @param out Receives t (out[0]) and the weights of the face's vertices a, b, c (out[1..3],
	 * summing to 1, negative when the point is outside this cell).
	 * @returns false when no t ≥ 0 puts the point in the moved triangle's plane (out is then the
	 * weights of the point's projection on the face plane at t = 0, with out[0] = −1).
	 */
	solve( f: number, x: number, y: number, z: number, out: Float64Array | number[] ): boolean {

		const s = this.toLocal;
		_query[ 0 ] = x * s; _query[ 1 ] = y * s; _query[ 2 ] = z * s;
		return this.solveQuery( f, out );

	}

	/**
	 * Barycentric weights of (x, y, z) projected on the plane of triangle f moved to t (out[1..3];
	 * out[0] = t).
	 */
	weightsAt( f: number, t: number, x: number, y: number, z: number, out: Float64Array | number[] ): void {

		const s = this.toLocal;
		_query[ 0 ] = x * s; _query[ 1 ] = y * s; _query[ 2 ] = z * s; _root[ 0 ] = t * s;
		this.weightsAtRoot( f, out );

	}

	/** {@link OuterCells.solve} for the point in `_query` (local frame). */
	private solveQuery( f: number, out: Float64Array | number[] ): boolean {

		const c = this.coefficients, k = 12 * f, a = 3 * this.faces[ 3 * f ], p = this.local;
		const dx = _query[ 0 ] - p[ a ], dy = _query[ 1 ] - p[ a + 1 ], dz = _query[ 2 ] - p[ a + 2 ];
		_cubic[ 0 ] = c[ k ] * dx + c[ k + 1 ] * dy + c[ k + 2 ] * dz;
		_cubic[ 1 ] = c[ k + 3 ] * dx + c[ k + 4 ] * dy + c[ k + 5 ] * dz + c[ k + 9 ];
		_cubic[ 2 ] = c[ k + 6 ] * dx + c[ k + 7 ] * dy + c[ k + 8 ] * dz + c[ k + 10 ];
		_cubic[ 3 ] = c[ k + 11 ];
		if ( ! smallestRoot() ) {

			_root[ 0 ] = 0;
			this.weightsAtRoot( f, out );
			out[ 0 ] = - 1;
			return false;

		}

		_root[ 0 ] *= this.scale;
		this.weightsAtRoot( f, out );
		return true;

	}

	/** Weights of the point in `_query` in triangle f moved to t = `_root[0]` (local frame; out[0] = t in the positions' units). */
	private weightsAtRoot( f: number, out: Float64Array | number[] ): void {

		const faces = this.faces, p = this.local, n = this.normals, t = _root[ 0 ];
		const x = _query[ 0 ], y = _query[ 1 ], z = _query[ 2 ];
		const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
		// Relative to a(t), so large t loses nothing to the probes' absolute coordinates.
		const e1x = p[ b ] - p[ a ] + t * ( n[ b ] - n[ a ] ), e1y = p[ b + 1 ] - p[ a + 1 ] + t * ( n[ b + 1 ] - n[ a + 1 ] );
		const e1z = p[ b + 2 ] - p[ a + 2 ] + t * ( n[ b + 2 ] - n[ a + 2 ] );
		const e2x = p[ c ] - p[ a ] + t * ( n[ c ] - n[ a ] ), e2y = p[ c + 1 ] - p[ a + 1 ] + t * ( n[ c + 1 ] - n[ a + 1 ] );
		const e2z = p[ c + 2 ] - p[ a + 2 ] + t * ( n[ c + 2 ] - n[ a + 2 ] );
		const dx = x - p[ a ] - t * n[ a ], dy = y - p[ a + 1 ] - t * n[ a + 1 ], dz = z - p[ a + 2 ] - t * n[ a + 2 ];
		const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
		const nn = nx * nx + ny * ny + nz * nz;
		// (d × e2)·n / n·n and (e1 × d)·n / n·n.
		let v = ( ( dy * e2z - dz * e2y ) * nx + ( dz * e2x - dx * e2z ) * ny + ( dx * e2y - dy * e2x ) * nz ) / nn;
		let w = ( ( e1y * dz - e1z * dy ) * nx + ( e1z * dx - e1x * dz ) * ny + ( e1x * dy - e1y * dx ) * nz ) / nn;
		// A moved triangle collapsed to a segment (rays crossing) has no weights; report it as outside.
		if ( ! ( v - v === 0 && w - w === 0 ) ) { v = - 1; w = - 1; }
		out[ 0 ] = t * this.toGiven; out[ 1 ] = 1 - v - w; out[ 2 ] = v; out[ 3 ] = w;

	}

	/**
	 * Finds the outer cell containing (x, y, z), a point outside the hull, walking from cell `start`
	 * across the edge of the most negative weight (the cells sharing that edge share its swept
	 * quad). A step budget and a scan of every cell guard against fans of rays that are not convex.
	 * Allocation-free.
	 * @param out Receives t and the three weights as {@link OuterCells.solve} writes them.
	 * @returns The cell, or −1 when no cell's sweep reaches the point (the caller falls back to the
	 * nearest hull face).
	 */
	locate( x: number, y: number, z: number, start: number, out: Float64Array | number[] ): number {

		// Far away the weights have reached their limit: pull the point in so the cubic stays finite.
		const cx = this.center[ 0 ], cy = this.center[ 1 ], cz = this.center[ 2 ], s = this.toLocal;
		x *= s; y *= s; z *= s;
		const rx = x - cx, ry = y - cy, rz = z - cz, limit = FAR_LIMIT * this.scale;
		const r2 = rx * rx + ry * ry + rz * rz;
		if ( r2 > limit * limit ) {

			// hypot when r2 overflowed.
			const pull = limit / ( r2 < Infinity ? Math.sqrt( r2 ) : Math.hypot( rx, ry, rz ) );
			x = cx + rx * pull; y = cy + ry * pull; z = cz + rz * pull;

		}

		_query[ 0 ] = x; _query[ 1 ] = y; _query[ 2 ] = z;
		const count = this.faces.length / 3, adjacency = this.adjacency;
		let f = start >= 0 && start < count ? start : 0, previous = - 1;
		for ( let steps = 0; steps < count; steps ++ ) {

			const found = this.solveQuery( f, out );
			const w0 = out[ 1 ], w1 = out[ 2 ], w2 = out[ 3 ];
			let worst = 0, worstValue = w0;
			if ( w1 < worstValue ) { worstValue = w1; worst = 1; }
			if ( w2 < worstValue ) { worstValue = w2; worst = 2; }
			if ( worstValue >= - OUTER_EPSILON ) {

				if ( found ) return f;
				// No root, yet the point projects into this face: it is beside the sweep, not in it.
				break;

			}

			const next = adjacency[ 3 * f + worst ];
			// Sent back where we came from: the point is in neither cell (a gap between sweeps).
			if ( next === previous ) break;
			previous = f; f = next;

		}

		return this.scan( out );

	}

	/** Solves every cell; the fallback of {@link OuterCells.locate}. */
	private scan( out: Float64Array | number[] ): number {

		for ( let f = 0, n = this.faces.length / 3; f < n; f ++ ) {

			const found = this.solveQuery( f, _solve );
			if ( found && _solve[ 1 ] >= - OUTER_EPSILON && _solve[ 2 ] >= - OUTER_EPSILON && _solve[ 3 ] >= - OUTER_EPSILON ) {

				out[ 0 ] = _solve[ 0 ]; out[ 1 ] = _solve[ 1 ]; out[ 2 ] = _solve[ 2 ]; out[ 3 ] = _solve[ 3 ];
				return f;

			}

		}

		return - 1;

	}

}

/**
 * Smallest root τ ≥ 0 of c0 + c1 τ + c2 τ² + c3 τ³ (from `_cubic`), left in `_root[0]`; false when
 * there is none. Bracketed Newton on s = τ / (1 + τ) ∈ [0, 1), where any coefficient may vanish
 * without special cases, then polished in τ (the method: docs/outer-cells.md). One function, so
 * nothing is passed as a boxed double.
 */
function smallestRoot(): boolean {

	const c0 = _cubic[ 0 ], c1 = _cubic[ 1 ], c2 = _cubic[ 2 ], c3 = _cubic[ 3 ];
	if ( c0 <= 0 && c0 >= - ON_PLANE_EPSILON ) { _root[ 0 ] = 0; return true; }
	if ( ! ( c0 - c0 === 0 && c1 - c1 === 0 && c2 - c2 === 0 && c3 - c3 === 0 ) ) return false;

	// g(s) in powers of s, for its derivative: A0 + A1 s + A2 s² + A3 s³.
	const A1 = - 3 * c0 + c1, A2 = 3 * c0 - 2 * c1 + c2, A3 = - c0 + c1 - c2 + c3;
	// Critical points: roots of 3A3 s² + 2A2 s + A1 (stable quadratic formula; a = 0 falls out).
	const qa = 3 * A3, qb = 2 * A2, qc = A1;
	let r0 = 2, r1 = 2;
	if ( qa === 0 ) {

		if ( qb !== 0 ) r0 = - qc / qb;

	} else {

		const disc = qb * qb - 4 * qa * qc;
		if ( disc >= 0 ) {

			const q = - 0.5 * ( qb + ( qb >= 0 ? Math.sqrt( disc ) : - Math.sqrt( disc ) ) );
			if ( q !== 0 ) { r0 = q / qa; r1 = qc / q; } else r0 = 0;

		}

	}

	if ( r1 < r0 ) { const r = r0; r0 = r1; r1 = r; }

	// The first monotone piece [lo, hi] with a sign change (or a zero at hi < 1) holds the root.
	let lo = 0, gLo = c0, s = - 1;
	for ( let piece = 0; piece < 3 && s < 0; piece ++ ) {

		let hi = piece === 0 ? r0 : piece === 1 ? r1 : 1;
		if ( ! ( hi > lo && hi <= 1 ) ) continue;
		const u = 1 - hi, gHi = u * u * ( c0 * u + c1 * hi ) + hi * hi * ( c2 * u + c3 * hi );
		if ( gHi === 0 && hi < 1 ) { s = hi; break; }
		if ( ( gLo < 0 ) === ( gHi < 0 ) || gHi === 0 ) { lo = hi; gLo = gHi; continue; }

		// Newton kept inside the shrinking bracket.
		s = 0.5 * ( lo + hi );
		for ( let i = 0; i < 100; i ++ ) {

			const v = 1 - s, g = v * v * ( c0 * v + c1 * s ) + s * s * ( c2 * v + c3 * s );
			if ( g === 0 ) break;
			if ( ( g < 0 ) === ( gLo < 0 ) ) { lo = s; gLo = g; } else hi = s;
			const slope = A1 + s * ( 2 * A2 + 3 * A3 * s );
			let next = s - g / slope;
			if ( ! ( next > lo && next < hi ) ) next = 0.5 * ( lo + hi );
			if ( next === s || hi - lo <= 1e-17 ) { s = next; break; }
			s = next;

		}

	}

	if ( s < 0 ) return false;
	let tau = s / ( 1 - s );
	if ( ! ( tau - tau === 0 ) ) return false;
	if ( tau > 0 ) {

		for ( let i = 0; i < 2; i ++ ) {

			const value = c0 + tau * ( c1 + tau * ( c2 + tau * c3 ) );
			const slope = c1 + tau * ( 2 * c2 + 3 * c3 * tau );
			const next = tau - value / slope;
			// Keep a step only when it is small: near a double root Newton may wander.
			if ( next >= 0 && Math.abs( next - tau ) <= 1e-6 * ( 1 + tau ) ) tau = next;

		}

	}

	_root[ 0 ] = tau;
	return true;

}
