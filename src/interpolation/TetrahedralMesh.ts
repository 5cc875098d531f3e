import { assertArrayLike, assertInteger, assertNumber, assertOutput, assertPoints } from '../validate.js';
import { tetrahedralize, type Tetrahedralization, type TetrahedralizeOptions } from '../tetrahedra/tetrahedralize.js';
import { orient } from '../tetrahedra/predicates.js';
import { DynamicTetrahedralization } from '../tetrahedra/DynamicTetrahedralization.js';
import { closestPointOnTriangle } from '../geometry/closestPointOnTriangle.js';
import { OuterCells } from './OuterCells.js';
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

/** Options of {@link TetrahedralMesh.fromDynamic}. */
export interface FromDynamicOptions {

	/** Behaviour outside the convex hull. Default `'outerCells'`. */
	outside?: OutsideMode;

}

/** Options of {@link TetrahedralMesh.fromTetrahedralization}. */
export interface FromTetrahedralizationOptions {

	/** Behaviour outside the convex hull. Default `'outerCells'`. */
	outside?: OutsideMode;

	/** Pairs (merged probe, probe it was merged into), as `tetrahedralize` reported them. Default none. */
	duplicates?: ArrayLike<number>;

}

// Barycentric slack for points on shared faces: a point rounding 1e-12 outside a face still
// belongs to the tetrahedron, or a walk could bounce between the two cells sharing it.
const INSIDE_EPSILON = 1e-12;

const _weights = new Float64Array( 4 );
const _closest = new Float64Array( 6 );
const _outer = new Float64Array( 4 );

// Where the last locate() that returned −1 left the mesh: the tetrahedron and the slot of the
// hull face it stepped out through (−1 when a scan, not a walk, answered).
let _exitTetrahedron = - 1, _exitSlot = 0;

// Set by fromTetrahedralization for the constructor it calls: the stored arrays to use instead of
// tetrahedralizing. Module state rather than a constructor argument keeps `new TetrahedralMesh`'s
// public signature plain.
let _stored: Tetrahedralization | null = null;

// Set by fromDynamic for the constructor it calls, likewise.
let _dynamic: DynamicTetrahedralization | null = null;

const FROM = 'TetrahedralMesh.fromTetrahedralization';
const FROM_DYNAMIC = 'TetrahedralMesh.fromDynamic';

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
 * Incremental mode ({@link TetrahedralMesh.fromDynamic}): the mesh follows a
 * {@link DynamicTetrahedralization}, and {@link TetrahedralMesh.moveProbe},
 * {@link TetrahedralMesh.addProbe} and {@link TetrahedralMesh.removeProbe} update it locally —
 * the tetrahedralization and the inverse matrices of the changed tetrahedra only; the outer cells
 * are rebuilt over the hull (O(hull faces)) only when the edit changed a hull face. (Rebuilding
 * rather than patching them: their vertex normals are smoothed globally where cells would fold —
 * on 5,000 random probes every rebuild runs those rounds, ~0.3 ms, but only ~10 % of moves touch
 * the hull; on the 85-probe Sponza layout a rebuild is ~50 µs. See bench/incremental.bench.ts.) The array
 * fields (`positions`, `tetrahedra`, `neighbors`, `inverseMatrices`, `hullFaces`,
 * `hullFaceTetrahedra`, `hullFaceSlots`, `outerCells`) are then views replaced by every edit:
 * read them again after one. Probe ids never shift: `probeCount` counts id slots, and a removed
 * probe's id stays, in no tetrahedron ({@link TetrahedralMesh.isActive} is false). Hints kept
 * from before an edit stay safe to pass (any value is a valid start), just slower the first time.
 */
export class TetrahedralMesh implements ProbeInterpolator {

	/**
	 * Probe positions, x, y, z per probe (a copy of the constructor argument; in incremental mode a
	 * view of the dynamic tetrahedralization's, replaced by each edit, removed ids keeping their
	 * last position).
	 */
	positions: Float64Array;

	/** Four probe indices per tetrahedron, positively oriented (incremental mode: replaced by each edit). */
	tetrahedra: Uint32Array;

	/**
	 * `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1 on the hull
	 * (incremental mode: replaced by each edit).
	 */
	neighbors: Int32Array;

	/** Pairs (merged probe, probe it was merged into) found while tetrahedralizing. */
	readonly duplicates: Uint32Array;

	/**
	 * Per tetrahedron, the row-major inverse of [p0 − p3, p1 − p3, p2 − p3] (9 floats), so that
	 * (w0, w1, w2) = inverse · (p − p3) and w3 = 1 − w0 − w1 − w2 (paper eq. in section 2.4).
	 * Incremental mode: a view of a capacity-doubling store, replaced by each edit.
	 */
	inverseMatrices: Float64Array;

	/** Hull triangles, 3 probe indices each, counter-clockwise seen from outside (incremental mode: replaced by each edit). */
	hullFaces: Uint32Array;

	/**
	 * For each hull triangle, the tetrahedron it belongs to (ascending, except in incremental mode,
	 * where it is the dynamic tetrahedralization's `hullFaceCells`, replaced by each edit).
	 */
	hullFaceTetrahedra: Uint32Array;

	/** For each hull triangle, the slot (0..3) in its tetrahedron of the vertex opposite it (incremental mode: replaced by each edit). */
	hullFaceSlots: Uint8Array;

	/** The outer cells over the hull triangles (cell f extends `hullFaces[3f..3f+2]`; incremental mode: rebuilt when the hull changes). */
	outerCells: OuterCells;

	/** Behaviour outside the convex hull. */
	readonly outside: OutsideMode;

	/** Always 4. */
	readonly weightCount = 4;

	/**
	 * The dynamic tetrahedralization this mesh follows in incremental mode
	 * ({@link TetrahedralMesh.fromDynamic}), or null. Edit through the mesh's `moveProbe`,
	 * `addProbe` and `removeProbe`, not directly: the mesh updates from its `lastEdit`.
	 */
	readonly dynamic: DynamicTetrahedralization | null;

	// Incremental mode: capacity-doubling stores behind inverseMatrices and hullFaceSlots, and the
	// hull face of each (tetrahedron, slot) — hull faces are not sorted by tetrahedron there, so
	// hullFaceOf cannot binary-search.
	private inverseStore: Float64Array | null = null;
	private slotStore: Uint8Array | null = null;
	private cellHullFace: Int32Array | null = null;

	/**
	 * @param positions Flat x, y, z per probe; at least 4 probes not all in one plane.
	 * @param options Behaviour outside the hull, and options passed to {@link tetrahedralize}.
	 */
	constructor( positions: ArrayLike<number>, options: TetrahedralMeshOptions = {} ) {

		const stored = _stored, dynamic = _dynamic;
		_stored = null;
		_dynamic = null;
		const outside = this.outside = options.outside ?? 'outerCells';
		if ( outside !== 'outerCells' && outside !== 'nearestFace' ) throw new RangeError( `${dynamic ? FROM_DYNAMIC : 'TetrahedralMesh'}: options.outside must be 'outerCells' or 'nearestFace', got ${String( outside )}.` );
		this.dynamic = dynamic;
		if ( dynamic !== null ) {

			this.positions = dynamic.positions;
			this.tetrahedra = dynamic.tetrahedra;
			this.neighbors = dynamic.neighbors;
			this.duplicates = dynamic.duplicates;
			this.hullFaces = dynamic.hullFaces;
			this.hullFaceTetrahedra = dynamic.hullFaceCells;
			this.inverseMatrices = this.inverseStore = new Float64Array( 0 );
			this.hullFaceSlots = this.slotStore = new Uint8Array( 0 );
			this.cellHullFace = new Int32Array( 0 );
			this.outerCells = this.syncEdit( true )!;
			return;

		}

		if ( stored === null ) assertPoints( 'TetrahedralMesh', 'positions', positions );
		this.positions = Float64Array.from( positions );
		const { tetrahedra, neighbors, duplicates } = stored ?? tetrahedralize( this.positions, options );
		this.tetrahedra = tetrahedra;
		this.neighbors = neighbors;
		this.duplicates = duplicates;
		this.inverseMatrices = computeInverseMatrices( this.positions, tetrahedra, stored !== null );

		// Hull faces: count first, so the arrays are allocated once (100,000-probe volumes load here).
		const count = tetrahedra.length / 4;
		let hullCount = 0;
		for ( let i = 0; i < neighbors.length; i ++ ) if ( neighbors[ i ] === - 1 ) hullCount ++;
		const faces = this.hullFaces = new Uint32Array( 3 * hullCount );
		const owners = this.hullFaceTetrahedra = new Uint32Array( hullCount );
		const slots = this.hullFaceSlots = new Uint8Array( hullCount );
		let o = 0;
		for ( let t = 0; t < count; t ++ ) {

			for ( let i = 0; i < 4; i ++ ) {

				if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
				// The face without vertex i, ordered so that vertex i is on its negative side: for a
				// positive tetrahedron that makes it counter-clockwise seen from outside.
				const k = 4 * t, f = 3 * o;
				const v0 = tetrahedra[ k ], v1 = tetrahedra[ k + 1 ], v2 = tetrahedra[ k + 2 ], v3 = tetrahedra[ k + 3 ];
				if ( i === 0 ) { faces[ f ] = v1; faces[ f + 1 ] = v2; faces[ f + 2 ] = v3; }
				else if ( i === 1 ) { faces[ f ] = v0; faces[ f + 1 ] = v3; faces[ f + 2 ] = v2; }
				else if ( i === 2 ) { faces[ f ] = v0; faces[ f + 1 ] = v1; faces[ f + 2 ] = v3; }
				else { faces[ f ] = v0; faces[ f + 1 ] = v2; faces[ f + 2 ] = v1; }
				owners[ o ] = t; slots[ o ] = i;
				o ++;

			}

		}

		this.outerCells = new OuterCells( this.positions, faces, stored ? FROM : 'TetrahedralMesh' );

	}

	/**
	 * A mesh from a stored tetrahedralization (e.g. baked data), without tetrahedralizing again.
	 * Checks in O(n), naming the first problem: lengths, indices out of range, non-finite positions,
	 * neighbours that are not symmetric or do not share the face, tetrahedra that are not
	 * positively oriented, hull faces (neighbour −1) that do not form one closed convex surface. It
	 * does not check the Delaunay property or that the tetrahedra do not overlap. `tetrahedra` and `neighbors` are kept
	 * by reference when they are already a `Uint32Array` and an `Int32Array`.
	 * @param positions Flat x, y, z per probe.
	 * @param tetrahedra Four probe indices per tetrahedron, positively oriented.
	 * @param neighbors `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1.
	 * @throws Error naming the argument and the problem.
	 */
	static fromTetrahedralization( positions: ArrayLike<number>, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number>, options: FromTetrahedralizationOptions = {} ): TetrahedralMesh {

		const probeCount = assertPoints( FROM, 'positions', positions, 4 );
		assertArrayLike( FROM, 'tetrahedra', tetrahedra );
		assertArrayLike( FROM, 'neighbors', neighbors );
		if ( tetrahedra.length === 0 || tetrahedra.length % 4 !== 0 ) throw new RangeError( `${FROM}: tetrahedra must hold 4 indices per tetrahedron (a positive multiple of 4), got length ${tetrahedra.length}.` );
		if ( neighbors.length !== tetrahedra.length ) throw new RangeError( `${FROM}: neighbors must have one entry per tetrahedron face (length ${tetrahedra.length}), got length ${neighbors.length}.` );
		const count = tetrahedra.length / 4;
		const tets = tetrahedra instanceof Uint32Array ? tetrahedra : new Uint32Array( tetrahedra.length );
		const adjacent = neighbors instanceof Int32Array ? neighbors : new Int32Array( neighbors.length );
		for ( let i = 0; i < tetrahedra.length; i ++ ) {

			const v = tetrahedra[ i ];
			if ( ! Number.isInteger( v ) || v < 0 || v >= probeCount ) throw new RangeError( `${FROM}: tetrahedra[${i}] = ${v} is not a probe index (0..${probeCount - 1}).` );
			tets[ i ] = v;
			const u = neighbors[ i ];
			if ( ! Number.isInteger( u ) || u < - 1 || u >= count ) throw new RangeError( `${FROM}: neighbors[${i}] = ${u} is neither −1 nor a tetrahedron index (0..${count - 1}).` );
			adjacent[ i ] = u;

		}

		for ( let t = 0; t < count; t ++ ) {

			const k = 4 * t;
			for ( let i = 0; i < 4; i ++ ) {

				const u = adjacent[ k + i ];
				if ( u === - 1 ) continue;
				// The slot j of u whose vertex is not on t's face; the other three must be that face.
				let j = - 1, shared = 0;
				for ( let m = 0; m < 4; m ++ ) {

					const v = tets[ 4 * u + m ];
					let onFace = false;
					for ( let n = 0; n < 4; n ++ ) if ( n !== i && tets[ k + n ] === v ) onFace = true;
					if ( onFace ) shared ++; else j = m;

				}

				if ( shared !== 3 || j < 0 || tets[ 4 * u + j ] === tets[ k + i ] ) throw new Error( `${FROM}: neighbors[${k + i}] = ${u}, but tetrahedron ${u} does not share the face opposite vertex ${i} of tetrahedron ${t}.` );
				if ( adjacent[ 4 * u + j ] !== t ) throw new Error( `${FROM}: neighbours are not symmetric: neighbors[${k + i}] = ${u} but neighbors[${4 * u + j}] = ${adjacent[ 4 * u + j ]}, not ${t}.` );

			}

		}

		const duplicates = options.duplicates ? Uint32Array.from( options.duplicates ) : new Uint32Array( 0 );
		_stored = { tetrahedra: tets, neighbors: adjacent, duplicates };
		try {

			return new TetrahedralMesh( positions, { outside: options.outside } );

		} finally {

			_stored = null;

		}

	}

	/**
	 * An incremental mesh over a {@link DynamicTetrahedralization} (kept by reference, in its
	 * current state): {@link TetrahedralMesh.moveProbe}, {@link TetrahedralMesh.addProbe} and
	 * {@link TetrahedralMesh.removeProbe} then update the mesh locally instead of rebuilding it.
	 * Interpolation is the same as a mesh built from scratch on the active probes (same Delaunay
	 * tetrahedralization, same outer cells), with the dynamic tetrahedralization's probe ids.
	 * @param dynamic The tetrahedralization to follow; edit it only through this mesh from now on.
	 * @throws TypeError when `dynamic` is not a `DynamicTetrahedralization`.
	 */
	static fromDynamic( dynamic: DynamicTetrahedralization, options: FromDynamicOptions = {} ): TetrahedralMesh {

		if ( ! ( dynamic instanceof DynamicTetrahedralization ) ) throw new TypeError( `${FROM_DYNAMIC}: dynamic must be a DynamicTetrahedralization.` );
		_dynamic = dynamic;
		try {

			return new TetrahedralMesh( dynamic.positions, { outside: options.outside } );

		} finally {

			_dynamic = null;

		}

	}

	/**
	 * Moves probe `index` to (x, y, z) (incremental mode): a local removal and insertion in the
	 * tetrahedralization, then the inverse matrices of the changed tetrahedra, and the outer cells
	 * when the hull changed. The array fields are replaced: read them again. Nothing changes when
	 * it throws.
	 * @throws Error when the mesh is not incremental; RangeError for an inactive index or a
	 * non-finite coordinate; `DegenerateInputError` when the new position coincides with another
	 * probe or makes the probes coplanar.
	 */
	moveProbe( index: number, x: number, y: number, z: number ): void {

		this.requireDynamic( 'moveProbe' ).move( index, x, y, z );
		this.syncEdit( false );

	}

	/**
	 * Adds a probe at (x, y, z) (incremental mode) and returns its id: the next id slot, =
	 * the previous `probeCount`. Updates locally, as {@link TetrahedralMesh.moveProbe}.
	 * @throws Error when the mesh is not incremental; RangeError for a non-finite coordinate;
	 * `DegenerateInputError` when it coincides with an existing probe.
	 */
	addProbe( x: number, y: number, z: number ): number {

		const index = this.requireDynamic( 'addProbe' ).insert( x, y, z );
		this.syncEdit( false );
		return index;

	}

	/**
	 * Removes probe `index` (incremental mode). Its id stays (`probeCount` does not change, other
	 * ids do not shift); it is in no tetrahedron any more and gets no weight.
	 * @throws Error when the mesh is not incremental; RangeError for an inactive index;
	 * `DegenerateInputError` when fewer than 4 probes, or only coplanar ones, would remain.
	 */
	removeProbe( index: number ): void {

		this.requireDynamic( 'removeProbe' ).remove( index );
		this.syncEdit( false );

	}

	/** Whether probe id `index` is a vertex of the mesh (false for removed ids and merged duplicates). */
	isActive( index: number ): boolean {

		if ( this.dynamic !== null ) return this.dynamic.isActive( index );
		if ( ! Number.isInteger( index ) || index < 0 || index >= this.probeCount ) return false;
		for ( let i = 0; i < this.duplicates.length; i += 2 ) if ( this.duplicates[ i ] === index ) return false;
		return true;

	}

	private requireDynamic( name: string ): DynamicTetrahedralization {

		if ( this.dynamic === null ) throw new Error( `TetrahedralMesh.${name}: this mesh is not incremental; build it with TetrahedralMesh.fromDynamic( new DynamicTetrahedralization( positions ) ).` );
		return this.dynamic;

	}

	/**
	 * Re-reads the dynamic tetrahedralization after an edit (or at construction, `all`): inverse
	 * matrices of `lastEdit.changedCells` only, slots of the changed hull faces, and the outer cells
	 * (over the whole hull) when a hull face changed.
	 * @returns The new outer cells, or null when they were kept.
	 */
	private syncEdit( all: boolean ): OuterCells | null {

		const dynamic = this.dynamic!, edit = dynamic.lastEdit;
		all ||= edit.rebuilt;
		const p = this.positions = dynamic.positions;
		const tetrahedra = this.tetrahedra = dynamic.tetrahedra;
		this.neighbors = dynamic.neighbors;
		const count = tetrahedra.length / 4;

		let store = this.inverseStore!;
		if ( store.length < 9 * count ) {

			const grown = new Float64Array( 9 * Math.max( 16, 2 * count ) );
			if ( ! all ) grown.set( store.subarray( 0, 9 * Math.min( count, edit.previousCellCount ) ) );
			store = this.inverseStore = grown;

		}

		if ( all ) {

			for ( let t = 0; t < count; t ++ ) writeInverse( p, tetrahedra, t, store );

		} else {

			const changed = edit.changedCells;
			for ( let i = 0; i < changed.length; i ++ ) writeInverse( p, tetrahedra, changed[ i ], store );

		}

		this.inverseMatrices = store.subarray( 0, 9 * count );

		const faces = this.hullFaces = dynamic.hullFaces, owners = this.hullFaceTetrahedra = dynamic.hullFaceCells;
		const hullCount = owners.length;
		let slots = this.slotStore!, lookup = this.cellHullFace!;
		if ( slots.length < hullCount ) {

			const grown = new Uint8Array( Math.max( 16, 2 * hullCount ) );
			grown.set( slots );
			slots = this.slotStore = grown;

		}

		if ( lookup.length < 4 * count ) {

			const grown = new Int32Array( 4 * Math.max( 16, 2 * count ) );
			grown.set( lookup );
			lookup = this.cellHullFace = grown;

		}

		const changedFaces = edit.changedHullFaces, n = all ? hullCount : changedFaces.length;
		for ( let i = 0; i < n; i ++ ) {

			const f = all ? i : changedFaces[ i ], t = owners[ f ], k = 4 * t;
			const a = faces[ 3 * f ], b = faces[ 3 * f + 1 ], c = faces[ 3 * f + 2 ];
			let slot = 0;
			while ( slot < 3 ) {

				const v = tetrahedra[ k + slot ];
				if ( v !== a && v !== b && v !== c ) break;
				slot ++;

			}

			slots[ f ] = slot;
			lookup[ k + slot ] = f;

		}

		this.hullFaceSlots = slots.subarray( 0, hullCount );

		// Outer cells depend on the hull faces, their vertices' positions and normals: unchanged
		// unless a hull face changed (a moved hull vertex changes all its faces).
		if ( all || n > 0 || this.outerCells.faces.length !== faces.length ) {

			return this.outerCells = new OuterCells( p, faces, FROM_DYNAMIC );

		}

		this.outerCells.positions = p;
		return null;

	}

	/** Number of probes (incremental mode: of probe id slots, removed ones included). */
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
	 * @param hint A tetrahedron near the point (e.g. last frame's), a hint returned by
	 * {@link TetrahedralMesh.interpolate} (an outer cell starts from its hull face's tetrahedron), or −1.
	 * @returns The tetrahedron index, or −1 when the point is outside the convex hull.
	 */
	locate( x: number, y: number, z: number, hint = - 1 ): number {

		const count = this.tetrahedra.length / 4;
		let t = hint >= 0 && hint < count ? hint | 0 : 0;
		if ( hint >= count && hint - count < this.hullFaceTetrahedra.length ) t = this.hullFaceTetrahedra[ hint - count ];
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
			// Beyond a hull face's plane means outside the (convex) hull; remember the face for the
			// outer-cell walk.
			if ( next === - 1 ) { _exitTetrahedron = t; _exitSlot = worst; return - 1; }
			t = next;

		}

		_exitTetrahedron = - 1;
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
	 * Probes and weights for (x, y, z): inside the hull the containing tetrahedron's barycentric
	 * weights; outside, the outer cell's three weights (or, with `outside: 'nearestFace'`, those of
	 * the nearest point on the hull) and a fourth probe with weight 0. Weights are ≥ 0 and sum to 1.
	 * Allocation-free.
	 * @param hint The value this method returned last time for a nearby point, or −1.
	 * @returns The hint for next time: the tetrahedron containing the point (< `cellCount`), or
	 * `cellCount + f` for outer cell f; with `'nearestFace'`, the tetrahedron owning the nearest hull face.
	 * @throws RangeError when a coordinate is NaN or infinite.
	 */
	interpolate( x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1 ): number {

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
				indices[ 0 ] = tetrahedra[ k ]; indices[ 1 ] = tetrahedra[ k + 1 ]; indices[ 2 ] = tetrahedra[ k + 2 ]; indices[ 3 ] = tetrahedra[ k + 3 ];
				weights[ 0 ] = w0 * s; weights[ 1 ] = w1 * s; weights[ 2 ] = w2 * s; weights[ 3 ] = w3 * s;
				return t;

			}

			if ( this.outside === 'nearestFace' ) return this.interpolateNearestFace( x, y, z, indices, weights, false );
			face = _exitTetrahedron >= 0 ? this.hullFaceOf( _exitTetrahedron, _exitSlot ) : 0;

		}

		const f = this.outerCells.locate( x, y, z, face, _outer );
		if ( f < 0 ) return this.interpolateNearestFace( x, y, z, indices, weights, true );

		// Clamp the slack the walk allowed (as inside).
		const w0 = _outer[ 1 ] > 0 ? _outer[ 1 ] : 0, w1 = _outer[ 2 ] > 0 ? _outer[ 2 ] : 0, w2 = _outer[ 3 ] > 0 ? _outer[ 3 ] : 0;
		const s = 1 / ( w0 + w1 + w2 );
		this.writeFace( f, indices );
		weights[ 0 ] = w0 * s; weights[ 1 ] = w1 * s; weights[ 2 ] = w2 * s; weights[ 3 ] = 0;
		return count + f;

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

	/**
	 * The weights of the nearest point on the hull (a scan of every hull face).
	 * @param outerHint Return `cellCount + face` (the outer-cell fallback) rather than the face's tetrahedron.
	 */
	private interpolateNearestFace( x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], outerHint: boolean ): number {

		const face = this.nearestHullFace( x, y, z );
		this.writeFace( face, indices );
		weights[ 0 ] = _closest[ 3 ]; weights[ 1 ] = _closest[ 4 ]; weights[ 2 ] = _closest[ 5 ]; weights[ 3 ] = 0;
		return outerHint ? this.tetrahedra.length / 4 + face : this.hullFaceTetrahedra[ face ];

	}

	/** Writes hull face f's three probes, then its tetrahedron's vertex off the face (the zero-weight slot). */
	private writeFace( f: number, indices: Uint32Array | number[] ): void {

		const faces = this.hullFaces;
		indices[ 0 ] = faces[ 3 * f ]; indices[ 1 ] = faces[ 3 * f + 1 ]; indices[ 2 ] = faces[ 3 * f + 2 ];
		indices[ 3 ] = this.tetrahedra[ 4 * this.hullFaceTetrahedra[ f ] + this.hullFaceSlots[ f ] ];

	}

	/** The hull face opposite slot `slot` of tetrahedron t (a binary search: hull faces are stored by tetrahedron). */
	private hullFaceOf( t: number, slot: number ): number {

		if ( this.cellHullFace !== null ) return this.cellHullFace[ 4 * t + slot ];
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
			const d = closestPointOnTriangle( x, y, z, p[ a ], p[ a + 1 ], p[ a + 2 ], p[ b ], p[ b + 1 ], p[ b + 2 ], p[ c ], p[ c + 1 ], p[ c + 2 ], _closest );
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

/**
 * Per tetrahedron, the inverse of [p0 − p3, p1 − p3, p2 − p3].
 * @param check Throw when a tetrahedron is not positively oriented (stored data; tetrahedralize's
 * own output is positive by construction).
 */
function computeInverseMatrices( p: Float64Array, tetrahedra: Uint32Array, check: boolean ): Float64Array {

	const count = tetrahedra.length / 4;
	const out = new Float64Array( 9 * count );
	for ( let t = 0; t < count; t ++ ) {

		if ( check ) checkOrientation( p, tetrahedra, t );
		writeInverse( p, tetrahedra, t, out );

	}

	return out;

}

/** Throws when stored tetrahedron t is not positively oriented. */
function checkOrientation( p: Float64Array, tetrahedra: Uint32Array, t: number ): void {

	const i0 = 3 * tetrahedra[ 4 * t ], i1 = 3 * tetrahedra[ 4 * t + 1 ], i2 = 3 * tetrahedra[ 4 * t + 2 ], i3 = 3 * tetrahedra[ 4 * t + 3 ];
	const a = p[ i0 ] - p[ i3 ], d = p[ i0 + 1 ] - p[ i3 + 1 ], g = p[ i0 + 2 ] - p[ i3 + 2 ];
	const b = p[ i1 ] - p[ i3 ], e = p[ i1 + 1 ] - p[ i3 + 1 ], h = p[ i1 + 2 ] - p[ i3 + 2 ];
	const c = p[ i2 ] - p[ i3 ], f = p[ i2 + 1 ] - p[ i3 + 1 ], i = p[ i2 + 2 ] - p[ i3 + 2 ];
	const det = a * ( e * i - f * h ) - b * ( d * i - f * g ) + c * ( d * h - e * g );
	// det M = −det[p1 − p0, p2 − p0, p3 − p0]; a rounded det of the wrong sign is settled exactly.
	if ( ! ( det < 0 ) && orient( p, i0 / 3, i1 / 3, i2 / 3, i3 / 3 ) <= 0 ) {

		throw new Error( `${FROM}: tetrahedron ${t} (probes ${i0 / 3}, ${i1 / 3}, ${i2 / 3}, ${i3 / 3}) is not positively oriented (det[p1 − p0, p2 − p0, p3 − p0] ≤ 0).` );

	}

}

/** Writes the inverse of [p0 − p3, p1 − p3, p2 − p3] of tetrahedron t to `out[9t..9t+8]`. */
function writeInverse( p: Float64Array, tetrahedra: Uint32Array, t: number, out: Float64Array ): void {

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
