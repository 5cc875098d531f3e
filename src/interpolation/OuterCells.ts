import { orient } from '../tetrahedra/predicates.js';

// A point whose weights in a cell are all ≥ −OUTER_EPSILON belongs to it (rounding on shared quads).
const OUTER_EPSILON = 1e-10;

// Points closer to a face's plane than this fraction of the hull's size count as on it (t = 0), so a
// point the interior walk rounded to "just outside" does not look for a root far away.
const ON_PLANE_EPSILON = 1e-12;

// Queries farther than this many hull sizes from the hull's centre are pulled in along the same
// direction: the weights have converged to their limit there (to ~1e-12), and the cubic's
// coefficients stay far from overflow.
const FAR_LIMIT = 1e12;

const _solve = new Float64Array( 4 );

// The helpers of a query take the point and the cubic, and hand back the root, through these
// rather than as arguments and return values: a double passed to or returned from a function V8
// does not inline is boxed, a heap allocation per call.
const _root = new Float64Array( 1 );
const _query = new Float64Array( 3 );
const _cubic = new Float64Array( 4 );

/**
 * Extrapolation outside the convex hull of the probes by "outer cells" (what Unity's light probes
 * do): every hull vertex gets an outward normal, and every hull triangle (a, b, c) sweeps the
 * region covered by the moved triangle { a + t·na, b + t·nb, c + t·nc }, t ≥ 0. A point q of that
 * region lies in the plane of exactly one moved triangle near the hull; its barycentric weights in
 * that triangle are the interpolation weights. At t = 0 they are the hull triangle's own weights,
 * which are the tetrahedron's weights on the hull, so the field is continuous from inside to
 * outside; neighbouring cells share the ruled quad swept by their common edge, on which both give
 * the same two weights, so it is continuous across outer cells too. Along a vertex's ray the
 * weights are that vertex's alone, and far away they tend to the barycentric weights of the
 * direction in the triangle of normals (a limit, not a blow-up).
 *
 * Vertex normals are angle-weighted averages of the adjacent hull faces' normals: the weight of a
 * face is its corner angle at the vertex, so the normal does not depend on how a flat part of the
 * hull happens to be triangulated (a grid's side gets its face normal, a box corner the diagonal
 * (1, 1, 1)/√3 whatever the split) nor on the faces' sizes — area weighting would let the large
 * faces of a thin slab swamp its narrow rim, so the rim's rays would run almost parallel to the
 * slab and its outer cells would be slivers.
 *
 * The cells tile the outside (every outside point in exactly one cell, no gaps, no overlaps)
 * when every cell's sweep is one-to-one — its Jacobian N(t) · nᵢ stays positive for t ≥ 0 at its
 * three vertices, a test on three quadratics per cell (see `folds`, which also proves the tiling).
 * On very flat, irregular hulls angle-weighted normals of neighbouring rim vertices can point so
 * differently that rays cross each other's cells (gaps answered by the fallback, or two cells with
 * different weights: jumps in the light). Those normals alone are then smoothed until no cell
 * folds (`untangle`), and where smoothing does not get there, pulled step by step towards the
 * radial direction from the hull's centroid, which never folds (`unfold`, guaranteed to
 * terminate). Grids, slabs and ordinary volumes keep their angle-weighted normals exactly.
 *
 * The walk from cell to cell ({@link OuterCells.locate}) crosses the edge of the most negative
 * weight, so a point costs a few cells, not a scan of the hull; the cells are built in O(hull
 * faces). Pure math: no three.js. Used by `TetrahedralMesh`; exposed for tests and tools.
 */
export class OuterCells {

	/**
	 * Probe positions, x, y, z per probe (shared with the mesh, not copied). An incremental
	 * `TetrahedralMesh` points it at its new positions array after an edit that changed no hull
	 * face (the hull vertices' coordinates are then the same).
	 */
	positions: Float64Array;

	/** Hull triangles, 3 probe indices each, counter-clockwise seen from outside. */
	readonly faces: Uint32Array;

	/**
	 * `adjacency[3f + k]`: the hull triangle across the edge of f opposite its vertex k (the edge
	 * between vertices k + 1 and k + 2) — the outer cell that shares that swept quad.
	 */
	readonly adjacency: Int32Array;

	/**
	 * Unit outward normal per probe: the angle-weighted average of its hull faces' normals (smoothed,
	 * then blended towards radial, where a cell would fold, see the class comment); 0, 0, 0 off the
	 * hull.
	 */
	readonly normals: Float64Array;

	/**
	 * Per hull triangle, 12 numbers giving the cubic in τ = t / scale whose roots put a query q in
	 * the plane of the moved triangle: c0 = V0·(q − a), c1 = V1·(q − a) + k1,
	 * c2 = V2·(q − a) + k2, c3 = k3, stored as V0, V1, V2, k1, k2, k3 and scaled so that c0 is the
	 * signed distance of q from the face's plane in units of `scale`.
	 */
	readonly coefficients: Float64Array;

	/** The hull's size (bounding-box diagonal of the hull vertices, i.e. of the probes): the unit of τ. */
	readonly scale: number;

	/** Centre of the probes' bounding box (where far queries are pulled towards). */
	readonly center: Float64Array;

	/**
	 * @param positions Probe positions (kept by reference).
	 * @param faces Hull triangles, counter-clockwise seen from outside, forming a closed surface.
	 * @param where Function name for error messages.
	 * @throws Error when the triangles do not form one closed convex surface (an edge not shared by
	 * exactly two faces, several surfaces, or a reflex edge).
	 */
	constructor( positions: Float64Array, faces: Uint32Array, where = 'OuterCells' ) {

		this.positions = positions;
		this.faces = faces;
		const faceCount = faces.length / 3, p = positions;

		// The bounding box of the hull's vertices is the probes' (extremes are hull vertices), and
		// ignores positions that are in no face (probes removed from an incremental mesh).
		let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
		for ( let j = 0; j < faces.length; j ++ ) {

			const i = 3 * faces[ j ], x = p[ i ], y = p[ i + 1 ], z = p[ i + 2 ];
			if ( x < minX ) minX = x; if ( x > maxX ) maxX = x;
			if ( y < minY ) minY = y; if ( y > maxY ) maxY = y;
			if ( z < minZ ) minZ = z; if ( z > maxZ ) maxZ = z;

		}

		if ( faces.length === 0 ) minX = minY = minZ = maxX = maxY = maxZ = 0;
		this.scale = Math.hypot( maxX - minX, maxY - minY, maxZ - minZ ) || 1;
		this.center = Float64Array.of( ( minX + maxX ) / 2, ( minY + maxY ) / 2, ( minZ + maxZ ) / 2 );

		// Angle-weighted vertex normals (see the class comment for why angles).
		const normals = this.normals = new Float64Array( p.length );
		const faceNormals = new Float64Array( 3 * faceCount ), angles = new Float64Array( 3 * faceCount );
		for ( let f = 0; f < faceCount; f ++ ) {

			const ia = 3 * faces[ 3 * f ], ib = 3 * faces[ 3 * f + 1 ], ic = 3 * faces[ 3 * f + 2 ];
			const abx = p[ ib ] - p[ ia ], aby = p[ ib + 1 ] - p[ ia + 1 ], abz = p[ ib + 2 ] - p[ ia + 2 ];
			const acx = p[ ic ] - p[ ia ], acy = p[ ic + 1 ] - p[ ia + 1 ], acz = p[ ic + 2 ] - p[ ia + 2 ];
			const bcx = p[ ic ] - p[ ib ], bcy = p[ ic + 1 ] - p[ ib + 1 ], bcz = p[ ic + 2 ] - p[ ib + 2 ];
			let nx = aby * acz - abz * acy, ny = abz * acx - abx * acz, nz = abx * acy - aby * acx;
			const length = Math.hypot( nx, ny, nz );
			if ( length === 0 ) continue;
			nx /= length; ny /= length; nz /= length;
			faceNormals[ 3 * f ] = nx; faceNormals[ 3 * f + 1 ] = ny; faceNormals[ 3 * f + 2 ] = nz;
			// Corner angles by atan2(|u × v|, u · v): accurate for thin triangles, unlike acos.
			const angleA = Math.atan2( length, abx * acx + aby * acy + abz * acz );
			const angleB = Math.atan2( length, - ( abx * bcx + aby * bcy + abz * bcz ) );
			const angleC = Math.max( 0, Math.PI - angleA - angleB );
			angles[ 3 * f ] = angleA; angles[ 3 * f + 1 ] = angleB; angles[ 3 * f + 2 ] = angleC;
			normals[ ia ] += angleA * nx; normals[ ia + 1 ] += angleA * ny; normals[ ia + 2 ] += angleA * nz;
			normals[ ib ] += angleB * nx; normals[ ib + 1 ] += angleB * ny; normals[ ib + 2 ] += angleB * nz;
			normals[ ic ] += angleC * nx; normals[ ic + 1 ] += angleC * ny; normals[ ic + 2 ] += angleC * nz;

		}

		for ( let i = 0; i < normals.length; i += 3 ) {

			const length = Math.hypot( normals[ i ], normals[ i + 1 ], normals[ i + 2 ] );
			if ( length > 0 ) { normals[ i ] /= length; normals[ i + 1 ] /= length; normals[ i + 2 ] /= length; }

		}

		if ( untangle( p, faces, faceNormals, angles, normals, this.scale ) ) unfold( p, faces, normals, this.scale );

		// Edge adjacency: the directed edge (u → v) of one face is (v → u) in its neighbour.
		const probeCount = p.length / 3;
		const edges = new Map<number, number>();
		for ( let f = 0; f < faceCount; f ++ ) {

			for ( let k = 0; k < 3; k ++ ) {

				const u = faces[ 3 * f + ( k + 1 ) % 3 ], v = faces[ 3 * f + ( k + 2 ) % 3 ];
				const key = u * probeCount + v;
				if ( edges.has( key ) ) throw new Error( `${where}: hull edge (${u}, ${v}) belongs to more than one hull face in the same direction; the hull is not a closed surface (bad tetrahedra or neighbours).` );
				edges.set( key, 3 * f + k );

			}

		}

		const adjacency = this.adjacency = new Int32Array( 3 * faceCount );
		for ( let f = 0; f < faceCount; f ++ ) {

			for ( let k = 0; k < 3; k ++ ) {

				const u = faces[ 3 * f + ( k + 1 ) % 3 ], v = faces[ 3 * f + ( k + 2 ) % 3 ];
				const other = edges.get( v * probeCount + u );
				if ( other === undefined ) throw new Error( `${where}: hull edge (${u}, ${v}) has a hull face on one side only; the hull is not a closed surface (bad tetrahedra or neighbours).` );
				adjacency[ 3 * f + k ] = ( other / 3 ) | 0;

			}

		}

		// Convex at every edge (exact): the neighbour's far vertex is not above this face's plane.
		// With one connected closed surface (below) that makes the hull convex, which the walks
		// (leaving through a hull face means outside) rely on.
		for ( let f = 0; f < faceCount; f ++ ) {

			const a = faces[ 3 * f ], b = faces[ 3 * f + 1 ], c = faces[ 3 * f + 2 ];
			for ( let k = 0; k < 3; k ++ ) {

				const g = adjacency[ 3 * f + k ], key = 3 * g;
				let far = faces[ key ];
				if ( far === faces[ 3 * f + ( k + 1 ) % 3 ] || far === faces[ 3 * f + ( k + 2 ) % 3 ] ) far = faces[ key + 1 ];
				if ( far === faces[ 3 * f + ( k + 1 ) % 3 ] || far === faces[ 3 * f + ( k + 2 ) % 3 ] ) far = faces[ key + 2 ];
				if ( orient( p, a, b, c, far ) > 0 ) throw new Error( `${where}: the hull is not convex at edge (${faces[ 3 * f + ( k + 1 ) % 3 ]}, ${faces[ 3 * f + ( k + 2 ) % 3 ]}): the tetrahedra do not fill the probes' convex hull.` );

			}

		}

		// One connected surface: a face pair wrongly marked as hull inside the volume closes up on
		// itself and would pass the edge test above. Depth-first over the adjacency, O(faces).
		if ( faceCount > 0 ) {

			const seen = new Uint8Array( faceCount ), stack = new Int32Array( faceCount );
			let top = 0, reached = 1;
			stack[ top ++ ] = 0; seen[ 0 ] = 1;
			while ( top > 0 ) {

				const f = stack[ -- top ];
				for ( let k = 0; k < 3; k ++ ) {

					const g = adjacency[ 3 * f + k ];
					if ( seen[ g ] === 0 ) { seen[ g ] = 1; reached ++; stack[ top ++ ] = g; }

				}

			}

			if ( reached !== faceCount ) throw new Error( `${where}: the hull faces form more than one closed surface (${reached} of ${faceCount} faces reachable from the first); some faces marked as hull (neighbour −1) are inside the volume.` );

		}

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
			const f1x = normals[ ib ] - normals[ ia ], f1y = normals[ ib + 1 ] - normals[ ia + 1 ], f1z = normals[ ib + 2 ] - normals[ ia + 2 ];
			const f2x = normals[ ic ] - normals[ ia ], f2y = normals[ ic + 1 ] - normals[ ia + 1 ], f2z = normals[ ic + 2 ] - normals[ ia + 2 ];
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

	/** Number of outer cells (= hull triangles). */
	get count(): number {

		return this.faces.length / 3;

	}

	/**
	 * Signed distance of (x, y, z) from the plane of hull triangle f, positive outside. Since the
	 * hull is convex, a positive value means the point is outside the hull.
	 */
	signedDistance( f: number, x: number, y: number, z: number ): number {

		const c = this.coefficients, k = 12 * f, a = 3 * this.faces[ 3 * f ], p = this.positions;
		return ( c[ k ] * ( x - p[ a ] ) + c[ k + 1 ] * ( y - p[ a + 1 ] ) + c[ k + 2 ] * ( z - p[ a + 2 ] ) ) * this.scale;

	}

	/** Whether (x, y, z) is strictly beyond the plane of hull triangle f (so outside the hull). */
	isBeyond( f: number, x: number, y: number, z: number ): boolean {

		const c = this.coefficients, k = 12 * f, a = 3 * this.faces[ 3 * f ], p = this.positions;
		return c[ k ] * ( x - p[ a ] ) + c[ k + 1 ] * ( y - p[ a + 1 ] ) + c[ k + 2 ] * ( z - p[ a + 2 ] ) > 0;

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

		_query[ 0 ] = x; _query[ 1 ] = y; _query[ 2 ] = z;
		return this.solveQuery( f, out );

	}

	/**
	 * Barycentric weights of (x, y, z) projected on the plane of triangle f moved to t (out[1..3];
	 * out[0] = t).
	 */
	weightsAt( f: number, t: number, x: number, y: number, z: number, out: Float64Array | number[] ): void {

		_query[ 0 ] = x; _query[ 1 ] = y; _query[ 2 ] = z; _root[ 0 ] = t;
		this.weightsAtRoot( f, out );

	}

	/** {@link OuterCells.solve} for the point in `_query`. */
	private solveQuery( f: number, out: Float64Array | number[] ): boolean {

		const c = this.coefficients, k = 12 * f, a = 3 * this.faces[ 3 * f ], p = this.positions;
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

	/** Weights of the point in `_query` in triangle f moved to t = `_root[0]`. */
	private weightsAtRoot( f: number, out: Float64Array | number[] ): void {

		const faces = this.faces, p = this.positions, n = this.normals, t = _root[ 0 ];
		const x = _query[ 0 ], y = _query[ 1 ], z = _query[ 2 ];
		const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
		// Relative to a(t), so large t loses nothing to the probes' absolute coordinates.
		const e1x = p[ b ] - p[ a ] + t * ( n[ b ] - n[ a ] ), e1y = p[ b + 1 ] - p[ a + 1 ] + t * ( n[ b + 1 ] - n[ a + 1 ] ), e1z = p[ b + 2 ] - p[ a + 2 ] + t * ( n[ b + 2 ] - n[ a + 2 ] );
		const e2x = p[ c ] - p[ a ] + t * ( n[ c ] - n[ a ] ), e2y = p[ c + 1 ] - p[ a + 1 ] + t * ( n[ c + 1 ] - n[ a + 1 ] ), e2z = p[ c + 2 ] - p[ a + 2 ] + t * ( n[ c + 2 ] - n[ a + 2 ] );
		const dx = x - p[ a ] - t * n[ a ], dy = y - p[ a + 1 ] - t * n[ a + 1 ], dz = z - p[ a + 2 ] - t * n[ a + 2 ];
		const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
		const nn = nx * nx + ny * ny + nz * nz;
		// (d × e2)·n / n·n and (e1 × d)·n / n·n.
		let v = ( ( dy * e2z - dz * e2y ) * nx + ( dz * e2x - dx * e2z ) * ny + ( dx * e2y - dy * e2x ) * nz ) / nn;
		let w = ( ( e1y * dz - e1z * dy ) * nx + ( e1z * dx - e1x * dz ) * ny + ( e1x * dy - e1y * dx ) * nz ) / nn;
		// A moved triangle collapsed to a segment (rays crossing) has no weights; report it as outside.
		if ( ! ( v - v === 0 && w - w === 0 ) ) { v = - 1; w = - 1; }
		out[ 0 ] = t; out[ 1 ] = 1 - v - w; out[ 2 ] = v; out[ 3 ] = w;

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
		const cx = this.center[ 0 ], cy = this.center[ 1 ], cz = this.center[ 2 ];
		const rx = x - cx, ry = y - cy, rz = z - cz, limit = FAR_LIMIT * this.scale;
		const r2 = rx * rx + ry * ry + rz * rz;
		if ( r2 > limit * limit ) {

			const s = limit / Math.sqrt( r2 );
			x = cx + rx * s; y = cy + ry * s; z = cz + rz * s;

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

			if ( this.solveQuery( f, _solve ) && _solve[ 1 ] >= - OUTER_EPSILON && _solve[ 2 ] >= - OUTER_EPSILON && _solve[ 3 ] >= - OUTER_EPSILON ) {

				out[ 0 ] = _solve[ 0 ]; out[ 1 ] = _solve[ 1 ]; out[ 2 ] = _solve[ 2 ]; out[ 3 ] = _solve[ 3 ];
				return f;

			}

		}

		return - 1;

	}

}

// Rounds of smoothing untangle() may take (a round costs O(hull faces) and runs only while some
// cell still folds; very flat random layouts need a dozen or more).
const UNTANGLE_ROUNDS = 40;

// How steep over each adjacent face a smoothed normal must stay, as a fraction of the
// angle-weighted normal's steepness there.
const MIN_STEEPNESS = 0.1;

// Least cosine between a ray and the normal of a hull face it starts from: the sweep must leave the
// face (a ray along the face would give a cell of zero thickness there).
const MIN_OUTWARD = 1e-9;

// Weights of the radial direction in the normals of the vertices of cells that still fold after
// smoothing (see `unfold`), step by step; the last, 1, is the purely radial normal.
const RADIAL_BLENDS = [ 0, 0.125, 0.25, 0.5, 1 ];

// Rounds of `unfold` before every hull vertex is made radial (a bound on the build's time: each
// round costs O(hull faces); the survey's flat layouts need a few).
const RADIAL_ROUNDS = 64;

/**
 * Whether outer cell f is not a one-to-one sweep: the map (w, t) ↦ Σ wᵢ (pᵢ + t nᵢ) (w in the
 * triangle, t ≥ 0) must have a positive Jacobian everywhere. That Jacobian is
 * det[E1 + tF1, E2 + tF2, Σ wᵢ nᵢ] = N(t) · Σ wᵢ nᵢ with N(t) = N0 + t N1 + t² N2 the moved
 * triangle's normal; it is linear in w, so it is positive on the triangle iff the three quadratics
 * qᵢ(t) = N(t) · nᵢ are positive for t ≥ 0. At t = 0 that says each ray leaves the face
 * (nᵢ · N0 > 0); far away, since (F1 × F2) · nᵢ = det[na, nb, nc] for each i, that the triangle of
 * normals keeps its orientation (the sweep keeps moving outwards). When every cell passes, the
 * sweep of the whole hull surface S is a local homeomorphism S × [0, ∞) → outside that is the
 * identity on S and proper (|q| → ∞ with t, as every ray leaves its faces), hence a covering of
 * the outside (connected, simply connected) that is one-to-one near S: a bijection. So the cells
 * tile the outside with neither gaps nor overlaps, and the point of each cell is reached at a
 * single t. This is what the older test (the moved triangle's normal against its original one,
 * N(t) · N0 > 0) missed: two rays of a thin rim can cross each other's cells while each moved
 * triangle keeps its orientation. τ = t / L for scale-free tolerances; only τ ≤ FAR_LIMIT matters
 * (farther queries are pulled in), which absorbs rounding in flat parts (C ≈ 0, B ≈ 0).
 */
function folds( p: Float64Array, faces: Uint32Array, n: Float64Array, f: number, L: number ): boolean {

	const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
	const e1x = p[ b ] - p[ a ], e1y = p[ b + 1 ] - p[ a + 1 ], e1z = p[ b + 2 ] - p[ a + 2 ];
	const e2x = p[ c ] - p[ a ], e2y = p[ c + 1 ] - p[ a + 1 ], e2z = p[ c + 2 ] - p[ a + 2 ];
	const f1x = n[ b ] - n[ a ], f1y = n[ b + 1 ] - n[ a + 1 ], f1z = n[ b + 2 ] - n[ a + 2 ];
	const f2x = n[ c ] - n[ a ], f2y = n[ c + 1 ] - n[ a + 1 ], f2z = n[ c + 2 ] - n[ a + 2 ];
	const n0x = e1y * e2z - e1z * e2y, n0y = e1z * e2x - e1x * e2z, n0z = e1x * e2y - e1y * e2x;
	const n1x = ( f1y * e2z - f1z * e2y ) + ( e1y * f2z - e1z * f2y );
	const n1y = ( f1z * e2x - f1x * e2z ) + ( e1z * f2x - e1x * f2z );
	const n1z = ( f1x * e2y - f1y * e2x ) + ( e1x * f2y - e1y * f2x );
	const n2x = f1y * f2z - f1z * f2y, n2y = f1z * f2x - f1x * f2z, n2z = f1x * f2y - f1y * f2x;
	const area = Math.hypot( n0x, n0y, n0z );
	if ( ! ( area > 0 ) ) return false;
	const s0 = 1 / area, s1 = L / area, s2 = L * L / area, T = FAR_LIMIT;
	for ( let k = 0; k < 3; k ++ ) {

		const v = k === 0 ? a : k === 1 ? b : c, x = n[ v ], y = n[ v + 1 ], z = n[ v + 2 ];
		const A = ( n0x * x + n0y * y + n0z * z ) * s0;
		const B = ( n1x * x + n1y * y + n1z * z ) * s1;
		const C = ( n2x * x + n2y * y + n2z * z ) * s2;
		if ( ! ( A > MIN_OUTWARD ) ) return true;
		if ( ! ( A + T * ( B + T * C ) > 0 ) ) return true;
		// Interior minimum of the quadratic at τ = −B / 2C.
		if ( C > 0 && B < 0 && - B < 2 * C * T && B * B >= 4 * A * C ) return true;

	}

	return false;

}

/**
 * Where angle-weighted normals make some outer cell fold (thin, irregular hulls: a flat box of
 * random probes has thin rim faces whose vertex normals point every which way), smooths the
 * normals of those cells' vertices towards the angle-weighted average of their neighbours' normals,
 * round by round until no cell folds. Each move is shortened as far as needed to keep the ray at
 * least MIN_STEEPNESS as steep over every adjacent face as the angle-weighted normal was
 * (n·n_f ≥ 0.1 × its minimum), so the sweeps still leave the hull. Hulls without folds (grids,
 * slabs, most volumes) keep their angle-weighted normals exactly. O(hull faces) per round.
 * @returns Whether some cell still folds (then `unfold` takes over).
 */
function untangle( p: Float64Array, faces: Uint32Array, faceNormals: Float64Array, angles: Float64Array, normals: Float64Array, L: number ): boolean {

	const faceCount = faces.length / 3, vertexCount = normals.length / 3;
	let any = false;
	for ( let f = 0; f < faceCount && ! any; f ++ ) any = folds( p, faces, normals, f, L );
	if ( ! any ) return false;

	// Faces around each vertex (compressed rows), and each vertex's least steepness over them.
	const start = new Int32Array( vertexCount + 1 ), incident = new Int32Array( 3 * faceCount );
	for ( let i = 0; i < faces.length; i ++ ) start[ faces[ i ] + 1 ] ++;
	for ( let v = 0; v < vertexCount; v ++ ) start[ v + 1 ] += start[ v ];
	const fill = start.slice( 0, vertexCount );
	for ( let i = 0; i < faces.length; i ++ ) incident[ fill[ faces[ i ] ] ++ ] = ( i / 3 ) | 0;
	const steepness = ( v: number, x: number, y: number, z: number ): number => {

		let least = Infinity;
		for ( let i = start[ v ]; i < start[ v + 1 ]; i ++ ) {

			const f = 3 * incident[ i ];
			least = Math.min( least, x * faceNormals[ f ] + y * faceNormals[ f + 1 ] + z * faceNormals[ f + 2 ] );

		}

		return least;

	};

	const floor = new Float64Array( vertexCount );
	for ( let v = 0; v < vertexCount; v ++ ) {

		const least = steepness( v, normals[ 3 * v ], normals[ 3 * v + 1 ], normals[ 3 * v + 2 ] );
		floor[ v ] = least > 0 ? MIN_STEEPNESS * least : least;

	}

	// The vertices that move this round, as flags and as a list: rounds cost O(hull faces), not
	// O(probes) (probes inside the hull are never mobile).
	const mobile = new Uint8Array( vertexCount ), target = new Float64Array( normals.length ), moving = new Int32Array( vertexCount );
	let movingCount = 0;
	for ( let round = 0; round <= UNTANGLE_ROUNDS; round ++ ) {

		for ( let m = 0; m < movingCount; m ++ ) {

			const v = moving[ m ];
			mobile[ v ] = 0;
			target[ 3 * v ] = target[ 3 * v + 1 ] = target[ 3 * v + 2 ] = 0;

		}

		movingCount = 0;
		let count = 0;
		for ( let f = 0; f < faceCount; f ++ ) {

			if ( ! folds( p, faces, normals, f, L ) ) continue;
			for ( let k = 0; k < 3; k ++ ) {

				const v = faces[ 3 * f + k ];
				if ( mobile[ v ] === 0 ) { mobile[ v ] = 1; moving[ movingCount ++ ] = v; }

			}

			count ++;

		}

		if ( count === 0 ) return false;
		if ( round === UNTANGLE_ROUNDS ) break;
		for ( let f = 0; f < faceCount; f ++ ) {

			const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
			const mx = normals[ a ] + normals[ b ] + normals[ c ], my = normals[ a + 1 ] + normals[ b + 1 ] + normals[ c + 1 ], mz = normals[ a + 2 ] + normals[ b + 2 ] + normals[ c + 2 ];
			for ( let k = 0; k < 3; k ++ ) {

				const v = faces[ 3 * f + k ], w = angles[ 3 * f + k ];
				if ( mobile[ v ] === 0 ) continue;
				target[ 3 * v ] += w * mx; target[ 3 * v + 1 ] += w * my; target[ 3 * v + 2 ] += w * mz;

			}

		}

		for ( let m = 0; m < movingCount; m ++ ) {

			const v = moving[ m ], i = 3 * v;
			const tl = Math.hypot( target[ i ], target[ i + 1 ], target[ i + 2 ] );
			if ( tl === 0 ) continue;
			// Full step, then halves of it, back towards the current normal until steep enough.
			for ( let step = 1; step > 1 / 16; step *= 0.5 ) {

				const x = normals[ i ] + step * ( target[ i ] / tl - normals[ i ] ), y = normals[ i + 1 ] + step * ( target[ i + 1 ] / tl - normals[ i + 1 ] ), z = normals[ i + 2 ] + step * ( target[ i + 2 ] / tl - normals[ i + 2 ] );
				const l = Math.hypot( x, y, z );
				if ( l === 0 || steepness( v, x / l, y / l, z / l ) < floor[ v ] ) continue;
				normals[ i ] = x / l; normals[ i + 1 ] = y / l; normals[ i + 2 ] = z / l;
				break;

			}

		}

	}

	return true;

}

/**
 * The guaranteed end of the normals' repair, for cells smoothing left folded: raises the normals
 * of their vertices, round by round, one step of RADIAL_BLENDS towards the radial direction from
 * the hull vertices' centroid c (strictly inside the hull), until no cell folds. Radial normals
 * never fold: with uᵢ = pᵢ − c and nᵢ = uᵢ / |uᵢ|, the moved vertex is c + sᵢ(t) uᵢ with
 * sᵢ(t) = 1 + t / |uᵢ|, so the moved triangle stays on the three edges of the cone from c over the
 * face, and qₐ(t) = N(t) · nₐ = s_b(t) s_c(t) det[uₐ, u_b, u_c] / |uₐ| > 0 (likewise for b and c):
 * those cells are the cones from c beyond their faces. Whether a cell folds depends on its three
 * normals only, so a folded cell always has a vertex below the radial step, and every round raises
 * the total of the steps: at most (RADIAL_BLENDS.length − 1) × hull vertices rounds, of O(hull
 * faces) each. Past RADIAL_ROUNDS every hull vertex takes its radial normal (all cones: a tiling).
 * Only the neighbourhood of the folds moves, by as little as this ladder allows.
 */
function unfold( p: Float64Array, faces: Uint32Array, normals: Float64Array, L: number ): void {

	const faceCount = faces.length / 3, vertexCount = normals.length / 3;
	const onHull = new Uint8Array( vertexCount );
	let cx = 0, cy = 0, cz = 0, hullCount = 0;
	for ( let i = 0; i < faces.length; i ++ ) {

		const v = faces[ i ];
		if ( onHull[ v ] ) continue;
		onHull[ v ] = 1; hullCount ++;
		cx += p[ 3 * v ]; cy += p[ 3 * v + 1 ]; cz += p[ 3 * v + 2 ];

	}

	cx /= hullCount; cy /= hullCount; cz /= hullCount;
	const base = normals.slice(), level = new Uint8Array( vertexCount ), top = RADIAL_BLENDS.length - 1;
	const blend = ( v: number, s: number ): void => {

		const i = 3 * v, ux = p[ i ] - cx, uy = p[ i + 1 ] - cy, uz = p[ i + 2 ] - cz, ul = Math.hypot( ux, uy, uz );
		if ( s === 1 ) { normals[ i ] = ux / ul; normals[ i + 1 ] = uy / ul; normals[ i + 2 ] = uz / ul; return; }
		const x = ( 1 - s ) * base[ i ] + s * ux / ul, y = ( 1 - s ) * base[ i + 1 ] + s * uy / ul, z = ( 1 - s ) * base[ i + 2 ] + s * uz / ul;
		const l = Math.hypot( x, y, z );
		normals[ i ] = x / l; normals[ i + 1 ] = y / l; normals[ i + 2 ] = z / l;

	};

	for ( let round = 0; round < RADIAL_ROUNDS; round ++ ) {

		// Raise this round from the folds seen at its start (the same for every face of the round).
		let any = false;
		for ( let f = 0; f < faceCount; f ++ ) {

			if ( ! folds( p, faces, normals, f, L ) ) continue;
			any = true;
			for ( let k = 0; k < 3; k ++ ) {

				const v = faces[ 3 * f + k ];
				// 128 + level marks "raise once this round".
				if ( level[ v ] < top ) level[ v ] |= 128;

			}

		}

		if ( ! any ) return;
		for ( let v = 0; v < vertexCount; v ++ ) {

			if ( level[ v ] < 128 ) continue;
			level[ v ] = ( level[ v ] & 127 ) + 1;
			blend( v, RADIAL_BLENDS[ level[ v ] ] );

		}

	}

	for ( let f = 0; f < faceCount; f ++ ) if ( folds( p, faces, normals, f, L ) ) {

		for ( let v = 0; v < vertexCount; v ++ ) if ( onHull[ v ] ) blend( v, 1 );
		return;

	}

}

/**
 * Smallest root τ ≥ 0 of c0 + c1 τ + c2 τ² + c3 τ³ (from `_cubic`), left in `_root[0]`; false when
 * there is none. Works on s = τ / (1 + τ) ∈ [0, 1), where the cubic becomes the bounded
 * Bernstein-like form g(s) = c0 u³ + c1 s u² + c2 s² u + c3 s³ (u = 1 − s): any of the coefficients
 * may vanish (flat parts of the hull give a linear equation) without special cases. The interval is
 * split at g's critical points into monotone pieces; the first piece whose ends differ in sign
 * holds the root, found by Newton steps kept inside the bracket, then polished by Newton in τ
 * (exact far away, where s ≈ 1). One function, so nothing is passed as a boxed double.
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
