import { DynamicTetrahedralization } from '../tetrahedra/DynamicTetrahedralization.js';
import { OuterCells } from './OuterCells.js';
import { writeInverse } from './inverseMatrices.js';
import { TetrahedralMesh, type OutsideMode } from './TetrahedralMesh.js';

/** Options of {@link IncrementalTetrahedralMesh}. */
export interface IncrementalTetrahedralMeshOptions {

	/** Behaviour outside the convex hull. Default `'outerCells'`. */
	outside?: OutsideMode;

}

const WHERE = 'IncrementalTetrahedralMesh';

/**
 * A {@link TetrahedralMesh} that follows a {@link DynamicTetrahedralization}:
 * {@link IncrementalTetrahedralMesh.moveProbe}, {@link IncrementalTetrahedralMesh.addProbe} and
 * {@link IncrementalTetrahedralMesh.removeProbe} update it locally — the tetrahedralization and
 * the inverse matrices of the changed tetrahedra only; the outer cells are rebuilt over the hull
 * (O(hull faces)) only when the edit changed a hull face (rebuilt rather than patched: their
 * vertex normals are smoothed globally where cells would fold; costs in bench/incremental.bench.ts).
 * Interpolation is the same as a mesh built from
 * scratch on the active probes (same Delaunay tetrahedralization, same outer cells), with the
 * dynamic tetrahedralization's probe ids.
 *
 * The array fields (`positions`, `tetrahedra`, `neighbors`, `inverseMatrices`, `hullFaces`,
 * `hullFaceTetrahedra`, `hullFaceSlots`, `outerCells`) are views replaced by every edit: read
 * them again after one. Probe ids never shift: `probeCount` counts id slots, and a removed probe's
 * id stays, in no tetrahedron ({@link IncrementalTetrahedralMesh.isActive} is false). Hints kept
 * from before an edit stay safe to pass (any value is a valid start), just slower the first time.
 */
export class IncrementalTetrahedralMesh extends TetrahedralMesh {

	/**
	 * The dynamic tetrahedralization this mesh follows. Edit through the mesh's `moveProbe`,
	 * `addProbe` and `removeProbe`, not directly: the mesh updates from its `lastEdit`.
	 */
	readonly dynamic: DynamicTetrahedralization;

	// Capacity-doubling stores behind inverseMatrices and hullFaceSlots, and the hull face of each
	// (tetrahedron, slot) — hull faces are not sorted by tetrahedron here, so the base class's
	// binary search cannot find them.
	private inverseStore = new Float64Array( 0 );
	private slotStore = new Uint8Array( 0 );
	private cellHullFace = new Int32Array( 0 );

	/**
	 * @param dynamic The tetrahedralization to follow (kept by reference, in its current state);
	 * edit it only through this mesh from now on.
	 * @param options Behaviour outside the hull.
	 * @throws TypeError when `dynamic` is not a `DynamicTetrahedralization`.
	 */
	constructor( dynamic: DynamicTetrahedralization, options: IncrementalTetrahedralMeshOptions = {} ) {

		if ( ! ( dynamic instanceof DynamicTetrahedralization ) ) throw new TypeError( `${WHERE}: dynamic must be a DynamicTetrahedralization.` );
		// Inverse matrices and slots start empty: syncArrays( true ) fills them in the stores.
		super( dynamic.positions, { outside: options.outside }, {
			where: WHERE,
			positions: dynamic.positions,
			tetrahedra: dynamic.tetrahedra,
			neighbors: dynamic.neighbors,
			duplicates: dynamic.duplicates,
			inverseMatrices: new Float64Array( 0 ),
			hullFaces: dynamic.hullFaces,
			hullFaceTetrahedra: dynamic.hullFaceCells,
			hullFaceSlots: new Uint8Array( 0 ),
			outerCells: new OuterCells( dynamic.positions, dynamic.hullFaces, WHERE ),
		} );
		this.dynamic = dynamic;
		this.syncArrays( true );

	}

	/**
	 * Moves probe `index` to (x, y, z): a local removal and insertion in the tetrahedralization,
	 * then the inverse matrices of the changed tetrahedra, and the outer cells when the hull
	 * changed. The array fields are replaced: read them again. Nothing changes when it throws.
	 * @throws RangeError for an inactive index or a non-finite coordinate; `DegenerateInputError`
	 * when the new position coincides with another probe or makes the probes coplanar.
	 */
	moveProbe( index: number, x: number, y: number, z: number ): void {

		this.dynamic.move( index, x, y, z );
		this.syncEdit();

	}

	/**
	 * Adds a probe at (x, y, z) and returns its id: the next id slot, = the previous `probeCount`.
	 * Updates locally, as {@link IncrementalTetrahedralMesh.moveProbe}.
	 * @throws RangeError for a non-finite coordinate; `DegenerateInputError` when it coincides
	 * with an existing probe.
	 */
	addProbe( x: number, y: number, z: number ): number {

		const index = this.dynamic.insert( x, y, z );
		this.syncEdit();
		return index;

	}

	/**
	 * Removes probe `index`. Its id stays (`probeCount` does not change, other ids do not shift);
	 * it is in no tetrahedron any more and gets no weight.
	 * @throws RangeError for an inactive index; `DegenerateInputError` when fewer than 4 probes,
	 * or only coplanar ones, would remain.
	 */
	removeProbe( index: number ): void {

		this.dynamic.remove( index );
		this.syncEdit();

	}

	/** Whether probe id `index` is a vertex of the mesh (false for removed ids and merged duplicates). */
	override isActive( index: number ): boolean {

		return this.dynamic.isActive( index );

	}

	/** The hull face opposite slot `slot` of tetrahedron t (a lookup: hull faces are not sorted by tetrahedron here). */
	protected override hullFaceOf( t: number, slot: number ): number {

		return this.cellHullFace[ 4 * t + slot ];

	}

	/**
	 * Re-reads the dynamic tetrahedralization after an edit, and rebuilds the outer cells (over the
	 * whole hull) when a hull face changed; otherwise they are kept, over the new positions array.
	 */
	private syncEdit(): void {

		if ( this.syncArrays( false ) ) this.outerCells = new OuterCells( this.positions, this.hullFaces, WHERE );
		else this.outerCells.positions = this.positions;

	}

	/**
	 * Re-reads the arrays of the dynamic tetrahedralization after an edit (or at construction,
	 * `all`): inverse matrices of `lastEdit.changedCells` only, slots of the changed hull faces.
	 * @returns Whether the outer cells must be rebuilt: the hull faces, or their vertices, changed.
	 */
	private syncArrays( all: boolean ): boolean {

		const dynamic = this.dynamic, edit = dynamic.lastEdit;
		all ||= edit.rebuilt;
		const p = this.positions = dynamic.positions;
		const tetrahedra = this.tetrahedra = dynamic.tetrahedra;
		this.neighbors = dynamic.neighbors;
		const count = tetrahedra.length / 4;

		let store = this.inverseStore;
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
		let slots = this.slotStore, lookup = this.cellHullFace;
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
		return all || n > 0 || this.outerCells.faces.length !== faces.length;

	}

}
