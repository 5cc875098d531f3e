import { assertInteger, assertNumber, assertOutput, assertPoints } from '../validate.js';
import { tetrahedralize, type TetrahedralizeOptions } from '../tetrahedra/tetrahedralize.js';
import { closestPointOnTriangle } from './closestPointOnTriangle.js';
import type { ProbeInterpolator } from './ProbeInterpolator.js';

// Barycentric slack for points on shared faces: a point rounding 1e-12 outside a face still
// belongs to the tetrahedron, or a walk could bounce between the two cells sharing it.
const INSIDE_EPSILON = 1e-12;

const _weights = new Float64Array( 4 );
const _closest = new Float64Array( 6 );

/**
 * Probe positions tetrahedralized for interpolation (paper section 2.4): a 3D Delaunay
 * tetrahedralization with each tetrahedron's inverse barycentric matrix precomputed once — probes
 * do not move in game, so finding the weights for a position costs one 3x3 product.
 *
 * Inside the convex hull of the probes the weights are the barycentric coordinates of the
 * containing tetrahedron: ≥ 0, summing to 1, exact for linear fields, continuous across faces.
 * Outside the hull the weights are those of the nearest point on the hull surface, which keeps
 * the field continuous and defined everywhere (it is constant along the outward direction).
 *
 * ```js
 * const mesh = new TetrahedralMesh( positions );
 * let hint = - 1;
 * hint = mesh.interpolate( x, y, z, indices, weights, hint ); // each frame
 * blendSH( indices, weights, probeSH, sh );
 * ```
 */
export class TetrahedralMesh implements ProbeInterpolator {

	/** Probe positions, x, y, z per probe (a copy of the constructor argument). */
	readonly positions: Float64Array;

	/** Four probe indices per tetrahedron, positively oriented. */
	readonly tetrahedra: Uint32Array;

	/** `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1 on the hull. */
	readonly neighbors: Int32Array;

	/** Pairs (merged probe, probe it was merged into) found while tetrahedralizing. */
	readonly duplicates: Uint32Array;

	/**
	 * Per tetrahedron, the row-major inverse of [p0 − p3, p1 − p3, p2 − p3] (9 floats), so that
	 * (w0, w1, w2) = inverse · (p − p3) and w3 = 1 − w0 − w1 − w2 (paper eq. in section 2.4).
	 */
	readonly inverseMatrices: Float64Array;

	/** Hull triangles, 3 probe indices each, counter-clockwise seen from outside. */
	readonly hullFaces: Uint32Array;

	/** For each hull triangle, the tetrahedron it belongs to. */
	readonly hullFaceTetrahedra: Uint32Array;

	/** Always 4. */
	readonly weightCount = 4;

	/**
	 * @param positions Flat x, y, z per probe; at least 4 probes not all in one plane.
	 * @param options Passed to {@link tetrahedralize}.
	 */
	constructor( positions: ArrayLike<number>, options?: TetrahedralizeOptions ) {

		assertPoints( 'TetrahedralMesh', 'positions', positions );
		this.positions = Float64Array.from( positions );
		const { tetrahedra, neighbors, duplicates } = tetrahedralize( this.positions, options );
		this.tetrahedra = tetrahedra;
		this.neighbors = neighbors;
		this.duplicates = duplicates;
		this.inverseMatrices = computeInverseMatrices( this.positions, tetrahedra );

		const faces: number[] = [], owners: number[] = [];
		for ( let t = 0, n = tetrahedra.length / 4; t < n; t ++ ) {

			for ( let i = 0; i < 4; i ++ ) {

				if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
				// The face without vertex i, ordered so that vertex i is on its negative side: for a
				// positive tetrahedron that makes it counter-clockwise seen from outside.
				const v = tetrahedra.subarray( 4 * t, 4 * t + 4 );
				if ( i === 0 ) faces.push( v[ 1 ], v[ 2 ], v[ 3 ] );
				else if ( i === 1 ) faces.push( v[ 0 ], v[ 3 ], v[ 2 ] );
				else if ( i === 2 ) faces.push( v[ 0 ], v[ 1 ], v[ 3 ] );
				else faces.push( v[ 0 ], v[ 2 ], v[ 1 ] );
				owners.push( t );

			}

		}

		this.hullFaces = Uint32Array.from( faces );
		this.hullFaceTetrahedra = Uint32Array.from( owners );

	}

	/** Number of probes. */
	get probeCount(): number {

		return this.positions.length / 3;

	}

	/** Number of tetrahedra. */
	get cellCount(): number {

		return this.tetrahedra.length / 4;

	}

	/**
	 * Finds the tetrahedron containing (x, y, z) by walking from `hint` towards the point, stepping
	 * each time across the face with the most negative barycentric weight. In a Delaunay mesh that
	 * walk cannot cycle in exact arithmetic; a step budget guards against rounding, after which a
	 * full scan answers.
	 * @param hint A tetrahedron near the point (e.g. last frame's), or −1.
	 * @returns The tetrahedron index, or −1 when the point is outside the convex hull.
	 */
	locate( x: number, y: number, z: number, hint = - 1 ): number {

		const count = this.tetrahedra.length / 4;
		let t = hint >= 0 && hint < count ? hint | 0 : 0;
		const neighbors = this.neighbors, m = this.inverseMatrices, p = this.positions, tetrahedra = this.tetrahedra;
		for ( let steps = 0; steps <= count; steps ++ ) {

			// Barycentric weights inline (this is the per-object, per-frame hot loop); they are left
			// in _weights for interpolate().
			const k = 9 * t, r = 3 * tetrahedra[ 4 * t + 3 ];
			const dx = x - p[ r ], dy = y - p[ r + 1 ], dz = z - p[ r + 2 ];
			const w0 = m[ k ] * dx + m[ k + 1 ] * dy + m[ k + 2 ] * dz;
			const w1 = m[ k + 3 ] * dx + m[ k + 4 ] * dy + m[ k + 5 ] * dz;
			const w2 = m[ k + 6 ] * dx + m[ k + 7 ] * dy + m[ k + 8 ] * dz;
			const w3 = 1 - w0 - w1 - w2;
			_weights[ 0 ] = w0; _weights[ 1 ] = w1; _weights[ 2 ] = w2; _weights[ 3 ] = w3;

			let worst = 0, worstValue = w0;
			if ( w1 < worstValue ) { worstValue = w1; worst = 1; }
			if ( w2 < worstValue ) { worstValue = w2; worst = 2; }
			if ( w3 < worstValue ) { worstValue = w3; worst = 3; }
			if ( worstValue >= - INSIDE_EPSILON ) return t;
			const next = neighbors[ 4 * t + worst ];
			// Beyond a hull face's plane means outside the (convex) hull.
			if ( next === - 1 ) return - 1;
			t = next;

		}

		return this.locateByScan( x, y, z );

	}

	/** Checks every tetrahedron; the fallback when a walk runs out of steps. */
	private locateByScan( x: number, y: number, z: number ): number {

		for ( let t = 0, n = this.tetrahedra.length / 4; t < n; t ++ ) {

			this.barycentric( t, x, y, z, _weights );
			if ( _weights[ 0 ] >= - INSIDE_EPSILON && _weights[ 1 ] >= - INSIDE_EPSILON && _weights[ 2 ] >= - INSIDE_EPSILON && _weights[ 3 ] >= - INSIDE_EPSILON ) return t;

		}

		return - 1;

	}

	/**
	 * Writes the barycentric coordinates of (x, y, z) in tetrahedron t: `out[k]` is the weight of
	 * probe `tetrahedra[4t + k]`. Negative entries mean the point is outside t.
	 */
	barycentric<T extends Float32Array | Float64Array | number[]>( t: number, x: number, y: number, z: number, out: T ): T {

		const m = this.inverseMatrices, k = 9 * t;
		const r = 3 * this.tetrahedra[ 4 * t + 3 ], p = this.positions;
		const dx = x - p[ r ], dy = y - p[ r + 1 ], dz = z - p[ r + 2 ];
		const a = m[ k ] * dx + m[ k + 1 ] * dy + m[ k + 2 ] * dz;
		const b = m[ k + 3 ] * dx + m[ k + 4 ] * dy + m[ k + 5 ] * dz;
		const c = m[ k + 6 ] * dx + m[ k + 7 ] * dy + m[ k + 8 ] * dz;
		out[ 0 ] = a; out[ 1 ] = b; out[ 2 ] = c; out[ 3 ] = 1 - a - b - c;
		return out;

	}

	/**
	 * Probes and weights for (x, y, z): the containing tetrahedron's barycentric weights, or outside
	 * the hull, those of the nearest point on the hull (one weight is then 0). Allocation-free.
	 * @returns The tetrahedron used (containing the point, or owning the nearest hull face): pass it
	 * back as `hint` next time.
	 */
	interpolate( x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1 ): number {

		const tetrahedra = this.tetrahedra;
		let t = this.locate( x, y, z, hint ); // leaves t's weights in _weights
		if ( t >= 0 ) {

			// Clamp the slack the walk allowed, so weights stay ≥ 0 and sum to 1.
			const w0 = _weights[ 0 ] > 0 ? _weights[ 0 ] : 0, w1 = _weights[ 1 ] > 0 ? _weights[ 1 ] : 0;
			const w2 = _weights[ 2 ] > 0 ? _weights[ 2 ] : 0, w3 = _weights[ 3 ] > 0 ? _weights[ 3 ] : 0;
			const s = 1 / ( w0 + w1 + w2 + w3 ), k = 4 * t;
			indices[ 0 ] = tetrahedra[ k ]; indices[ 1 ] = tetrahedra[ k + 1 ]; indices[ 2 ] = tetrahedra[ k + 2 ]; indices[ 3 ] = tetrahedra[ k + 3 ];
			weights[ 0 ] = w0 * s; weights[ 1 ] = w1 * s; weights[ 2 ] = w2 * s; weights[ 3 ] = w3 * s;
			return t;

		}

		const face = this.nearestHullFace( x, y, z );
		t = this.hullFaceTetrahedra[ face ];
		const f = 3 * face;
		for ( let i = 0; i < 3; i ++ ) {

			indices[ i ] = this.hullFaces[ f + i ];
			weights[ i ] = _closest[ 3 + i ];

		}

		// The fourth slot: the tetrahedron's vertex off the face, with weight 0.
		for ( let i = 0; i < 4; i ++ ) {

			const v = tetrahedra[ 4 * t + i ];
			if ( v !== indices[ 0 ] && v !== indices[ 1 ] && v !== indices[ 2 ] ) indices[ 3 ] = v;

		}

		weights[ 3 ] = 0;
		return t;

	}

	/**
	 * Same as {@link TetrahedralMesh.interpolate} with argument checks; for tools and tests rather
	 * than per-frame loops.
	 */
	interpolateChecked( x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1 ): number {

		assertNumber( 'TetrahedralMesh.interpolate', 'x', x );
		assertNumber( 'TetrahedralMesh.interpolate', 'y', y );
		assertNumber( 'TetrahedralMesh.interpolate', 'z', z );
		assertOutput( 'TetrahedralMesh.interpolate', 'indices', indices, 4 );
		assertOutput( 'TetrahedralMesh.interpolate', 'weights', weights, 4 );
		assertInteger( 'TetrahedralMesh.interpolate', 'hint', hint, - 1 );
		return this.interpolate( x, y, z, indices, weights, hint );

	}

	/** Index of the hull triangle nearest to (x, y, z); leaves its closest point in `_closest`. */
	private nearestHullFace( x: number, y: number, z: number ): number {

		const faces = this.hullFaces, p = this.positions;
		let best = - 1, bestDistance = Infinity;
		let u0 = 0, u1 = 0, u2 = 0;
		for ( let f = 0, n = faces.length / 3; f < n; f ++ ) {

			const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
			const d = closestPointOnTriangle( x, y, z, p[ a ], p[ a + 1 ], p[ a + 2 ], p[ b ], p[ b + 1 ], p[ b + 2 ], p[ c ], p[ c + 1 ], p[ c + 2 ], _closest );
			if ( d < bestDistance ) {

				bestDistance = d;
				best = f;
				u0 = _closest[ 3 ]; u1 = _closest[ 4 ]; u2 = _closest[ 5 ];

			}

		}

		_closest[ 3 ] = u0; _closest[ 4 ] = u1; _closest[ 5 ] = u2;
		return best;

	}

}

function computeInverseMatrices( p: Float64Array, tetrahedra: Uint32Array ): Float64Array {

	const count = tetrahedra.length / 4;
	const out = new Float64Array( 9 * count );
	for ( let t = 0; t < count; t ++ ) {

		const i0 = 3 * tetrahedra[ 4 * t ], i1 = 3 * tetrahedra[ 4 * t + 1 ], i2 = 3 * tetrahedra[ 4 * t + 2 ], i3 = 3 * tetrahedra[ 4 * t + 3 ];
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

	return out;

}
