import { assertArrayLike, assertInteger, assertNumber, assertOutput, assertPoints } from '../validate.js';
import { tetrahedralize, type TetrahedralizeOptions } from '../tetrahedra/tetrahedralize.js';
import type { validateTetrahedralization } from '../tetrahedra/validateTetrahedralization.js';
import { closestPointOnTriangle } from '../geometry/closestPointOnTriangle.js';
import { exactBarycentric } from './exactBarycentric.js';
import { walkExactly } from './exactWalk.js';
import type { OuterCells } from './OuterCells.js';
import { buildMeshParts, storedDuplicates, storedTetrahedralization, type TetrahedralMeshParts } from './tetrahedralMeshParts.js';
import type { ProbeInterpolator } from './ProbeInterpolator.js';

/**
 * What {@link TetrahedralMesh.interpolate} does outside the probes' convex hull:
 * - `'outerCells'` (default): extrapolation by outer cells ({@link OuterCells}) — each hull
 *   triangle swept outwards along its vertices' normals; continuous with the inside and across
 *   cells, varying with the direction, found by a walk (cost independent of the hull's size).
 * - `'nearestFace'`: the weights of the nearest point on the hull (a scan of every hull face);
 *   constant along the outward direction.
 */
export type OutsideMode = 'outerCells' | 'nearestFace';

/** Options of {@link TetrahedralMesh}. */
export interface TetrahedralMeshOptions extends TetrahedralizeOptions {

	/** Behaviour outside the convex hull. Default `'outerCells'`. */
	outside?: OutsideMode;

}

/** Options of {@link TetrahedralMesh.fromTetrahedralization}. */
export interface FromTetrahedralizationOptions {

	/** Behaviour outside the convex hull. Default `'outerCells'`. */
	outside?: OutsideMode;

	/** Pairs (merged probe, probe it was merged into), as `tetrahedralize` reported them. Default none. */
	duplicates?: ArrayLike<number>;

	/**
	 * Skip {@link validateTetrahedralization}: only for data it (e.g. `decodeBakedVolume`) already
	 * accepted. The hull's closed-surface and convexity checks still run. Default false.
	 */
	trusted?: boolean;

}

// Barycentric slack for points on shared faces: a point rounding 1e-12 outside a face still
// belongs to the tetrahedron, or a walk could bounce between the two cells sharing it.
const INSIDE_EPSILON = 1e-12;

const _weights = new Float64Array( 4 );
const _closest = new Float64Array( 6 );
const _outer = new Float64Array( 4 );
const _exit = new Int32Array( 2 );

const FROM = 'TetrahedralMesh.fromTetrahedralization';

/**
 * Probe positions tetrahedralized for interpolation (paper section 2.4): a 3D Delaunay
 * tetrahedralization with each tetrahedron's inverse barycentric matrix precomputed once — probes
 * do not move in game, so finding the weights for a position costs one 3x3 product.
 *
 * Inside the convex hull of the probes the weights are the barycentric coordinates of the
 * containing tetrahedron: ≥ 0, summing to 1, exact for linear fields, continuous across faces.
 *
 * Outside the hull, by default, the weights come from outer cells ({@link OuterCells}): each hull
 * triangle extended outwards along its vertices' averaged normals; the point's weights are its
 * barycentric coordinates in the moved triangle whose plane it lies in (three probes, the fourth
 * weight 0). They equal the inside weights on the hull, are continuous everywhere, follow the
 * direction in which an object leaves (rather than freezing at the nearest hull point), and tend
 * to a finite limit far away. The cell is found by walking from the hull face the interior walk
 * left through (or from last frame's outer cell), so an outside query costs a few cells, not a
 * scan of the hull. Where no outer cell's sweep reaches a point (possible only when the rays of
 * a very irregular hull fold), the weights of the nearest point on the hull answer instead.
 * `{ outside: 'nearestFace' }` selects that nearest-point behaviour everywhere outside (constant
 * along the outward direction).
 *
 * Hints: {@link TetrahedralMesh.interpolate} returns a tetrahedron index (< `cellCount`) inside,
 * and `cellCount + f` for outer cell f (the hull triangle `hullFaces[3f..3f+2]`) outside; pass it
 * back next frame. {@link TetrahedralMesh.locate} accepts either kind of hint.
 *
 * ```js
 * const mesh = new TetrahedralMesh( positions );
 * let hint = - 1;
 * hint = mesh.interpolate( x, y, z, indices, weights, hint ); // each frame
 * blendSH( indices, weights, probeSH, sh );
 * ```
 *
 * Incremental edits (moving, adding, removing probes) are the subclass
 * `IncrementalTetrahedralMesh`'s; its array fields are replaced by every edit.
 */
export class TetrahedralMesh implements ProbeInterpolator {

	/** Probe positions, x, y, z per probe (a copy of the constructor argument; incremental meshes: replaced by each edit). */
	positions: Float64Array;

	/** Four probe indices per tetrahedron, positively oriented (incremental meshes: replaced by each edit). */
	tetrahedra: Uint32Array;

	/**
	 * `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1 on the hull
	 * (incremental meshes: replaced by each edit).
	 */
	neighbors: Int32Array;

	/** Pairs (merged probe, probe it was merged into) found while tetrahedralizing. */
	readonly duplicates: Uint32Array;

	/**
	 * Per tetrahedron, the row-major inverse of [p0 − p3, p1 − p3, p2 − p3] (9 floats), so that
	 * (w0, w1, w2) = inverse · (p − p3) and w3 = 1 − w0 − w1 − w2 (paper eq. in section 2.4).
	 * Nine NaN for a tetrahedron too flat in floating point for its inverse (`isIllConditioned`):
	 * its weights come from exact sub-volumes instead.
	 */
	inverseMatrices: Float64Array;

	/** Hull triangles, 3 probe indices each, counter-clockwise seen from outside. */
	hullFaces: Uint32Array;

	/** For each hull triangle, the tetrahedron it belongs to (ascending, except in incremental meshes). */
	hullFaceTetrahedra: Uint32Array;

	/** For each hull triangle, the slot (0..3) in its tetrahedron of the vertex opposite it. */
	hullFaceSlots: Uint8Array;

	/** The outer cells over the hull triangles (cell f extends `hullFaces[3f..3f+2]`). */
	outerCells: OuterCells;

	/** Behaviour outside the convex hull. */
	readonly outside: OutsideMode;

	/** Always 4. */
	readonly weightCount = 4;

	// Where the last locate() that returned −1 left the mesh: the tetrahedron and the slot of the
	// hull face it stepped out through (−1 when a scan, not a walk, answered).
	private exitTetrahedron = - 1;
	private exitSlot = 0;

	/**
	 * @param positions Flat x, y, z per probe; at least 4 probes not all in one plane.
	 * @param options Behaviour outside the hull, and options passed to {@link tetrahedralize}.
	 * @param parts Internal: the arrays of a mesh already built (then `positions` is not read).
	 */
	constructor( positions: ArrayLike<number>, options: TetrahedralMeshOptions = {}, parts?: TetrahedralMeshParts ) {

		const where = parts ? parts.where : 'TetrahedralMesh';
		const outside = this.outside = options.outside ?? 'outerCells';
		if ( outside !== 'outerCells' && outside !== 'nearestFace' ) {

			throw new RangeError( `${where}: options.outside must be 'outerCells' or 'nearestFace', got ${String( outside )}.` );

		}

		if ( parts === undefined ) {

			assertPoints( where, 'positions', positions );
			const p = Float64Array.from( positions );
			const { tetrahedra, neighbors, duplicates } = tetrahedralize( p, options );
			parts = buildMeshParts( where, p, tetrahedra, neighbors, duplicates );

		}

		this.positions = parts.positions;
		this.tetrahedra = parts.tetrahedra;
		this.neighbors = parts.neighbors;
		this.duplicates = parts.duplicates;
		this.inverseMatrices = parts.inverseMatrices;
		this.hullFaces = parts.hullFaces;
		this.hullFaceTetrahedra = parts.hullFaceTetrahedra;
		this.hullFaceSlots = parts.hullFaceSlots;
		this.outerCells = parts.outerCells;

	}

	/**
	 * A mesh from a stored tetrahedralization (e.g. baked data), without tetrahedralizing again.
	 * Checks in O(n), naming the first problem: lengths, non-finite positions, then
	 * {@link validateTetrahedralization} (indices, orientation, neighbour links), then that the hull
	 * faces (neighbour −1) form one closed convex surface. It does not check the Delaunay property.
	 * `tetrahedra` and `neighbors` are kept by reference when they are already a `Uint32Array` and
	 * an `Int32Array`.
	 * @param positions Flat x, y, z per probe.
	 * @param tetrahedra Four probe indices per tetrahedron, positively oriented.
	 * @param neighbors `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1.
	 * @throws RangeError for lengths and indices, Error (a `TetrahedralizationError` for the links
	 * and orientation) for the rest, naming the argument and the problem.
	 */
	static fromTetrahedralization(
		positions: ArrayLike<number>, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number>,
		options: FromTetrahedralizationOptions = {},
	): TetrahedralMesh {

		assertPoints( FROM, 'positions', positions, 4 );
		assertArrayLike( FROM, 'tetrahedra', tetrahedra );
		assertArrayLike( FROM, 'neighbors', neighbors );
		if ( tetrahedra.length === 0 || tetrahedra.length % 4 !== 0 ) throw new RangeError( `${FROM}: tetrahedra must hold 4 indices per tetrahedron (a positive multiple of 4), got length ${tetrahedra.length}.` );
		if ( neighbors.length !== tetrahedra.length ) throw new RangeError( `${FROM}: neighbors must have one entry per tetrahedron face (length ${tetrahedra.length}), got length ${neighbors.length}.` );
		const p = Float64Array.from( positions );
		const { tetrahedra: tets, neighbors: adjacent } =
			storedTetrahedralization( FROM, p, tetrahedra, neighbors, options.trusted === true );
		const duplicates = storedDuplicates( FROM, options.duplicates, p.length / 3 );
		return new TetrahedralMesh( p, { outside: options.outside }, buildMeshParts( FROM, p, tets, adjacent, duplicates ) );

	}

	/** Whether probe id `index` is a vertex of the mesh (false for removed ids and merged duplicates). */
	isActive( index: number ): boolean {

		if ( ! Number.isInteger( index ) || index < 0 || index >= this.probeCount ) return false;
		for ( let i = 0; i < this.duplicates.length; i += 2 ) if ( this.duplicates[ i ] === index ) return false;
		return true;

	}

	/** Number of probes (incremental meshes: of probe id slots, removed ones included). */
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
	 * full scan answers. In ill-conditioned tetrahedra (and wherever a weight is not finite) exact
	 * sub-volumes decide: a NaN is never read as a step.
	 * @param hint A tetrahedron near the point (e.g. last frame's), a hint returned by
	 * {@link TetrahedralMesh.interpolate} (an outer cell starts from its hull face's tetrahedron), or −1.
	 * @returns The tetrahedron index, or −1 when the point is outside the convex hull.
	 */
	locate( x: number, y: number, z: number, hint = - 1 ): number {

		const count = this.tetrahedra.length / 4;
		let t = hint >= 0 && hint < count ? hint | 0 : 0;
		if ( hint >= count && hint - count < this.hullFaceTetrahedra.length ) t = this.hullFaceTetrahedra[ hint - count ];
		const neighbors = this.neighbors, m = this.inverseMatrices, p = this.positions, tetrahedra = this.tetrahedra;
		let steps = 0;
		for ( ; steps <= count; steps ++ ) {

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
			// w3 is NaN whenever a weight is (or two overflowed with opposite signs).
			if ( worstValue >= - INSIDE_EPSILON && w3 === w3 ) return t;
			// A NaN: the walk stops (and goes on below).
			if ( ! ( worstValue < - INSIDE_EPSILON ) ) break;
			const next = neighbors[ 4 * t + worst ];
			// Beyond a hull face's plane means outside the (convex) hull; remember the face for the
			// outer-cell walk.
			if ( next === - 1 ) { this.exitTetrahedron = t; this.exitSlot = worst; return - 1; }
			t = next;

		}

		if ( steps <= count ) {

			// A NaN — the sentinel of an ill-conditioned cell, or an overflow — is never read as a
			// step: the walk goes on with exact sub-volumes where the float weights fail.
			const found = walkExactly( p, tetrahedra, neighbors, m, x, y, z, t, count - steps, INSIDE_EPSILON, _weights, _exit );
			if ( found === - 1 ) { this.exitTetrahedron = _exit[ 0 ]; this.exitSlot = _exit[ 1 ]; }
			if ( found !== - 2 ) return found;

		}

		this.exitTetrahedron = - 1;
		return this.locateByScan( x, y, z );

	}
	/** Checks every tetrahedron; the fallback when a walk runs out of steps. */
	private locateByScan( x: number, y: number, z: number ): number {

		for ( let t = 0, n = this.tetrahedra.length / 4; t < n; t ++ ) {

			this.barycentric( t, x, y, z, _weights );
			if ( _weights[ 0 ] >= - INSIDE_EPSILON && _weights[ 1 ] >= - INSIDE_EPSILON
				&& _weights[ 2 ] >= - INSIDE_EPSILON && _weights[ 3 ] >= - INSIDE_EPSILON ) return t;

		}

		return - 1;

	}

	/**
	 * Writes the barycentric coordinates of (x, y, z) in tetrahedron t: `out[k]` is the weight of
	 * probe `tetrahedra[4t + k]`. Negative entries mean the point is outside t. From the inverse
	 * matrix, or from exact sub-volumes where it is ill-conditioned.
	 * @throws RangeError when t is not a tetrahedron index.
	 */
	barycentric<T extends Float32Array | Float64Array | number[]>( t: number, x: number, y: number, z: number, out: T ): T {

		if ( t >>> 0 !== t || 4 * t >= this.tetrahedra.length ) throw new RangeError( `TetrahedralMesh.barycentric: t = ${t} is not a tetrahedron index (0..${this.tetrahedra.length / 4 - 1}).` );
		const m = this.inverseMatrices, k = 9 * t;
		// The NaN sentinel of an ill-conditioned tetrahedron (see inverseMatrices).
		if ( m[ k ] !== m[ k ] ) {

			exactBarycentric( this.positions, this.tetrahedra, t, x, y, z, out );
			return out;

		}

		const r = 3 * this.tetrahedra[ 4 * t + 3 ], p = this.positions;
		const dx = x - p[ r ], dy = y - p[ r + 1 ], dz = z - p[ r + 2 ];
		const a = m[ k ] * dx + m[ k + 1 ] * dy + m[ k + 2 ] * dz;
		const b = m[ k + 3 ] * dx + m[ k + 4 ] * dy + m[ k + 5 ] * dz;
		const c = m[ k + 6 ] * dx + m[ k + 7 ] * dy + m[ k + 8 ] * dz;
		out[ 0 ] = a; out[ 1 ] = b; out[ 2 ] = c; out[ 3 ] = 1 - a - b - c;
		return out;

	}

	/**
	 * Probes and weights for (x, y, z): inside the hull the containing tetrahedron's barycentric
	 * weights; outside, the outer cell's three weights (or, with `outside: 'nearestFace'`, those of
	 * the nearest point on the hull) and a fourth probe with weight 0. Weights are ≥ 0 and sum to 1.
	 * Allocation-free.
	 * @param hint The value this method returned last time for a nearby point, or −1.
	 * @returns The hint for next time: the tetrahedron containing the point (< `cellCount`), or
	 * `cellCount + f` for outer cell f; with `'nearestFace'`, the tetrahedron owning the nearest hull face.
	 * @throws RangeError when a coordinate is NaN or infinite.
	 */
	interpolate(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1,
	): number {

		// x − x is 0 for every finite number and NaN for NaN and ±Infinity: one test for all three.
		if ( ! ( x - x === 0 && y - y === 0 && z - z === 0 ) ) {

			assertNumber( 'TetrahedralMesh.interpolate', 'x', x );
			assertNumber( 'TetrahedralMesh.interpolate', 'y', y );
			assertNumber( 'TetrahedralMesh.interpolate', 'z', z );

		}

		const tetrahedra = this.tetrahedra, count = tetrahedra.length / 4;
		let face = - 1;
		if ( hint >= count && this.outside === 'outerCells' ) {

			// Last time outside: while the point is beyond that hull face's plane it is still
			// outside (the hull is convex), and the interior walk can be skipped.
			const f = hint - count;
			if ( f < this.hullFaceTetrahedra.length && this.outerCells.isBeyond( f, x, y, z ) ) face = f;

		}

		if ( face < 0 ) {

			const t = this.locate( x, y, z, hint ); // leaves t's weights in _weights
			if ( t >= 0 ) {

				// Clamp the slack the walk allowed, so weights stay ≥ 0 and sum to 1.
				const w0 = _weights[ 0 ] > 0 ? _weights[ 0 ] : 0, w1 = _weights[ 1 ] > 0 ? _weights[ 1 ] : 0;
				const w2 = _weights[ 2 ] > 0 ? _weights[ 2 ] : 0, w3 = _weights[ 3 ] > 0 ? _weights[ 3 ] : 0;
				const s = 1 / ( w0 + w1 + w2 + w3 ), k = 4 * t;
				indices[ 0 ] = tetrahedra[ k ]; indices[ 1 ] = tetrahedra[ k + 1 ];
				indices[ 2 ] = tetrahedra[ k + 2 ]; indices[ 3 ] = tetrahedra[ k + 3 ];
				weights[ 0 ] = w0 * s; weights[ 1 ] = w1 * s; weights[ 2 ] = w2 * s; weights[ 3 ] = w3 * s;
				return t;

			}

			if ( this.outside === 'nearestFace' ) return this.interpolateNearestFace( x, y, z, indices, weights, false );
			face = this.exitTetrahedron >= 0 ? this.hullFaceOf( this.exitTetrahedron, this.exitSlot ) : 0;

		}

		const f = this.outerCells.locate( x, y, z, face, _outer );
		const u0 = _outer[ 1 ], u1 = _outer[ 2 ], u2 = _outer[ 3 ];
		// No outer cell reaches the point, or (guarding the final weights: finite, ≥ 0, summing to
		// 1) the outer cell's weights are not finite: the nearest hull face answers.
		if ( f < 0 || ! ( u0 - u0 + u1 - u1 + u2 - u2 === 0 ) ) return this.interpolateNearestFace( x, y, z, indices, weights, true );

		// Clamp the slack the walk allowed (as inside).
		const w0 = u0 > 0 ? u0 : 0, w1 = u1 > 0 ? u1 : 0, w2 = u2 > 0 ? u2 : 0;
		const s = 1 / ( w0 + w1 + w2 );
		this.writeFace( f, indices );
		weights[ 0 ] = w0 * s; weights[ 1 ] = w1 * s; weights[ 2 ] = w2 * s; weights[ 3 ] = 0;
		return count + f;

	}

	/**
	 * Same as {@link TetrahedralMesh.interpolate} with argument checks; for tools and tests rather
	 * than per-frame loops.
	 */
	interpolateChecked(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1,
	): number {

		assertNumber( 'TetrahedralMesh.interpolate', 'x', x );
		assertNumber( 'TetrahedralMesh.interpolate', 'y', y );
		assertNumber( 'TetrahedralMesh.interpolate', 'z', z );
		assertOutput( 'TetrahedralMesh.interpolate', 'indices', indices, 4 );
		assertOutput( 'TetrahedralMesh.interpolate', 'weights', weights, 4 );
		assertInteger( 'TetrahedralMesh.interpolate', 'hint', hint, - 1 );
		return this.interpolate( x, y, z, indices, weights, hint );

	}

	/**
	 * The weights of the nearest point on the hull (a scan of every hull face).
	 * @param outerHint Return `cellCount + face` (the outer-cell fallback) rather than the face's tetrahedron.
	 */
	private interpolateNearestFace(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[],
		outerHint: boolean,
	): number {

		const face = this.nearestHullFace( x, y, z );
		this.writeFace( face, indices );
		const u0 = _closest[ 3 ], u1 = _closest[ 4 ], u2 = _closest[ 5 ];
		if ( u0 - u0 + u1 - u1 + u2 - u2 === 0 ) {

			weights[ 0 ] = u0; weights[ 1 ] = u1; weights[ 2 ] = u2;

		} else {

			// Squared distances that overflowed (coordinates beyond ~1e154): the face's centroid.
			weights[ 0 ] = 1 / 3; weights[ 1 ] = 1 / 3; weights[ 2 ] = 1 / 3;

		}

		weights[ 3 ] = 0;
		return outerHint ? this.tetrahedra.length / 4 + face : this.hullFaceTetrahedra[ face ];

	}

	/** Writes hull face f's three probes, then its tetrahedron's vertex off the face (the zero-weight slot). */
	private writeFace( f: number, indices: Uint32Array | number[] ): void {

		const faces = this.hullFaces;
		indices[ 0 ] = faces[ 3 * f ]; indices[ 1 ] = faces[ 3 * f + 1 ]; indices[ 2 ] = faces[ 3 * f + 2 ];
		indices[ 3 ] = this.tetrahedra[ 4 * this.hullFaceTetrahedra[ f ] + this.hullFaceSlots[ f ] ];

	}

	/** The hull face opposite slot `slot` of tetrahedron t (a binary search: hull faces are stored by tetrahedron). */
	protected hullFaceOf( t: number, slot: number ): number {

		const owners = this.hullFaceTetrahedra;
		let lo = 0, hi = owners.length - 1;
		while ( lo < hi ) {

			const mid = ( lo + hi ) >>> 1;
			if ( owners[ mid ] < t ) lo = mid + 1; else hi = mid;

		}

		for ( let f = lo; f < owners.length && owners[ f ] === t; f ++ ) if ( this.hullFaceSlots[ f ] === slot ) return f;
		return 0;

	}

	/** Index of the hull triangle nearest to (x, y, z); leaves its closest point in `_closest`. */
	private nearestHullFace( x: number, y: number, z: number ): number {

		const faces = this.hullFaces, p = this.positions;
		let best = - 1, bestDistance = Infinity;
		let u0 = 0, u1 = 0, u2 = 0;
		for ( let f = 0, n = faces.length / 3; f < n; f ++ ) {

			const a = 3 * faces[ 3 * f ], b = 3 * faces[ 3 * f + 1 ], c = 3 * faces[ 3 * f + 2 ];
			const d = closestPointOnTriangle(
				x, y, z, p[ a ], p[ a + 1 ], p[ a + 2 ], p[ b ], p[ b + 1 ], p[ b + 2 ], p[ c ], p[ c + 1 ], p[ c + 2 ], _closest );
			// The first face always counts, so a distance that overflowed to Infinity still answers.
			if ( d < bestDistance || best < 0 ) {

				bestDistance = d;
				best = f;
				u0 = _closest[ 3 ]; u1 = _closest[ 4 ]; u2 = _closest[ 5 ];

			}

		}

		_closest[ 3 ] = u0; _closest[ 4 ] = u1; _closest[ 5 ] = u2;
		return best;

	}

}
