import { CELL, CELL_SHIFT, type DelaunayBuilder, FREE, INF } from './DelaunayBuilder.js';
import { growInt32, growUint32 } from './growArrays.js';

/**
 * What the last edit of a {@link DynamicTetrahedralization} changed, for consumers that keep
 * per-tetrahedron data (inverse barycentric matrices) and per-hull-face data in step with it at a
 * cost proportional to the change. The arrays are views valid until the next edit.
 */
export interface TetrahedralEdit {

	/**
	 * Tetrahedron ids (< `cellCount`) whose four vertices are new: created cells, and surviving cells
	 * renumbered into a freed id. Every other id < min( cellCount, previousCellCount ) holds the same
	 * vertices as before the edit (its `neighbors` entries may have changed: read them again).
	 */
	changedCells: Int32Array;

	/** Hull-face ids (< `hullFaceCount`) whose vertices or owning tetrahedron are new. */
	changedHullFaces: Int32Array;

	/** Number of tetrahedra before the edit; ids ≥ `cellCount` are gone. */
	previousCellCount: number;

	/** Number of tetrahedra after the edit. */
	cellCount: number;

	/** Number of hull faces after the edit. */
	hullFaceCount: number;

	/** Cells (tetrahedra and ghost cells on hull faces) deleted by the edit: the locality of the edit. */
	removedCellCount: number;

	/** Cells (tetrahedra and ghost cells) created by the edit. */
	createdCellCount: number;

	/** True when the edit rebuilt everything (construction, or a move that needed a rebuild); then every id changed. */
	rebuilt: boolean;

}

/**
 * The dense numbering of a {@link DelaunayBuilder}'s cells for {@link DynamicTetrahedralization}:
 * tetrahedron ids 0 … cellCount − 1 and hull-face ids 0 … hullFaceCount − 1 with their arrays,
 * kept dense by swap-remove, and the {@link TetrahedralEdit} of each edit (the cells it marked dirty).
 * An edit is `beginEdit`, then `dropSlot` before a slot is released and `addSlot` for each new cell,
 * then `endEdit`. Internal to src/tetrahedra; see docs/incremental-delaunay.md.
 */
export class DenseCells {

	/** The builder whose slots are numbered (set by `reset`). */
	builder: DelaunayBuilder;

	/** Four point ids per tetrahedron id (capacity-sized; the first `4 · cellCount` are live). */
	tetrahedra = new Uint32Array( 256 );

	/** Dense neighbours per tetrahedron id, −1 on the hull (capacity-sized). */
	neighbors = new Int32Array( 256 );

	/** Number of tetrahedra. */
	cellCount = 0;

	/** Three point ids per hull-face id, counter-clockwise from outside (capacity-sized). */
	hullFaces = new Uint32Array( 192 );

	/** Tetrahedron id per hull-face id (capacity-sized). */
	hullFaceCells = new Uint32Array( 64 );

	/** Number of hull faces. */
	hullFaceCount = 0;

	/** Cells deleted by the open edit (tetrahedra and ghosts). */
	removedCount = 0;

	/** Cells created by the open edit (tetrahedra and ghosts). */
	createdCount = 0;

	// cellIndex[slot] ≥ 0 is a tetrahedron id, ≤ −2 the hull face id −(value + 2) of a ghost, −1 none.
	private cellIndex = new Int32Array( 0 );
	private cellSlot = new Int32Array( 64 );
	private hullSlot = new Int32Array( 64 );

	// Edit bookkeeping.
	private dirty = new Int32Array( 256 );
	private dirtyCount = 0;
	private slotStamp = new Int32Array( 0 );
	private reportStamp = new Int32Array( 0 );
	private editStamp = 0;
	private previousCellCount = 0;
	private changedCells = new Int32Array( 256 );
	private changedHullFaces = new Int32Array( 256 );

	constructor( builder: DelaunayBuilder ) {

		this.builder = builder;

	}

	/**
	 * Forgets the numbering and opens an edit that numbers `builder`'s cells from scratch (the
	 * caller adds every live slot, then calls `endEdit( true )`).
	 */
	reset( builder: DelaunayBuilder ): void {

		this.builder = builder;
		this.previousCellCount = this.cellCount;
		this.cellCount = 0;
		this.hullFaceCount = 0;
		this.cellIndex = new Int32Array( builder.capacity ).fill( - 1 );
		this.slotStamp = new Int32Array( builder.capacity );
		this.reportStamp = new Int32Array( builder.capacity );
		this.dirtyCount = 0;
		this.removedCount = this.previousCellCount;
		this.createdCount = 0;
		this.editStamp ++;

	}

	/** Opens an edit. */
	beginEdit(): void {

		this.editStamp ++;
		this.dirtyCount = 0;
		this.removedCount = 0;
		this.createdCount = 0;
		this.previousCellCount = this.cellCount;

	}

	private markDirty( slot: number ): void {

		if ( this.slotStamp[ slot ] === this.editStamp ) return;
		this.slotStamp[ slot ] = this.editStamp;
		if ( this.dirtyCount === this.dirty.length ) this.dirty = growInt32( this.dirty, this.dirtyCount * 2 );
		this.dirty[ this.dirtyCount ++ ] = slot;

	}

	/** Takes a cell out of the dense numbering (before its slot is released), filling its id with the last one. */
	dropSlot( slot: number ): void {

		const c = this.cellIndex[ slot ];
		if ( c >= 0 ) {

			const last = -- this.cellCount;
			const moved = this.cellSlot[ last ];
			if ( moved !== slot ) {

				this.cellSlot[ c ] = moved;
				this.cellIndex[ moved ] = c;
				this.markDirty( moved );

			}

		} else if ( c <= - 2 ) {

			const h = - c - 2;
			const last = -- this.hullFaceCount;
			const moved = this.hullSlot[ last ];
			if ( moved !== slot ) {

				this.hullSlot[ h ] = moved;
				this.cellIndex[ moved ] = - h - 2;
				this.markDirty( moved );

			}

		}

		this.cellIndex[ slot ] = - 1;

	}

	/** Gives a new cell the next dense id (tetrahedron or hull face). */
	addSlot( slot: number ): void {

		if ( this.builder.isGhost( slot ) ) {

			const h = this.hullFaceCount ++;
			if ( h === this.hullSlot.length ) {

				this.hullSlot = growInt32( this.hullSlot, 2 * h );
				this.hullFaces = growUint32( this.hullFaces, 6 * h );
				this.hullFaceCells = growUint32( this.hullFaceCells, 2 * h );

			}

			this.hullSlot[ h ] = slot;
			this.cellIndex[ slot ] = - h - 2;

		} else {

			const c = this.cellCount ++;
			if ( c === this.cellSlot.length ) {

				this.cellSlot = growInt32( this.cellSlot, 2 * c );
				this.tetrahedra = growUint32( this.tetrahedra, 8 * c );
				this.neighbors = growInt32( this.neighbors, 8 * c );

			}

			this.cellSlot[ c ] = slot;
			this.cellIndex[ slot ] = c;

		}

		this.markDirty( slot );

	}

	/** Rewrites the dense arrays of every changed cell and its neighbours, and returns the edit. */
	endEdit( rebuilt: boolean ): TetrahedralEdit {

		const v = this.builder.cells, index = this.cellIndex;
		const report = this.reportStamp, stamp = this.editStamp;
		if ( this.changedCells.length < this.dirtyCount ) this.changedCells = new Int32Array( 2 * this.dirtyCount );
		if ( this.changedHullFaces.length < 5 * this.dirtyCount ) this.changedHullFaces = new Int32Array( 10 * this.dirtyCount );
		let changed = 0, changedHull = 0;
		for ( let d = 0; d < this.dirtyCount; d ++ ) {

			const slot = this.dirty[ d ];
			if ( v[ CELL * slot ] === FREE || index[ slot ] === - 1 ) continue;
			this.writeSlot( slot );
			const c = index[ slot ];
			if ( c >= 0 ) this.changedCells[ changed ++ ] = c;
			else if ( report[ slot ] !== stamp ) { report[ slot ] = stamp; this.changedHullFaces[ changedHull ++ ] = - c - 2; }

			for ( let i = 0; i < 4; i ++ ) {

				const u = v[ CELL * slot + 4 + i ] >> CELL_SHIFT;
				this.writeSlot( u );
				const cu = index[ u ];
				if ( cu <= - 2 && report[ u ] !== stamp ) { report[ u ] = stamp; this.changedHullFaces[ changedHull ++ ] = - cu - 2; }

			}

		}

		return {
			changedCells: this.changedCells.subarray( 0, changed ),
			changedHullFaces: this.changedHullFaces.subarray( 0, changedHull ),
			previousCellCount: this.previousCellCount,
			cellCount: this.cellCount,
			hullFaceCount: this.hullFaceCount,
			removedCellCount: this.removedCount,
			createdCellCount: this.createdCount,
			rebuilt,
		};

	}

	/** Writes one live cell's dense entries from its slot. */
	private writeSlot( slot: number ): void {

		const v = this.builder.cells, index = this.cellIndex;
		const c = index[ slot ];
		if ( c >= 0 ) {

			for ( let i = 0; i < 4; i ++ ) {

				this.tetrahedra[ 4 * c + i ] = v[ CELL * slot + i ];
				const n = index[ v[ CELL * slot + 4 + i ] >> CELL_SHIFT ];
				this.neighbors[ 4 * c + i ] = n >= 0 ? n : - 1;

			}

		} else if ( c <= - 2 ) {

			const h = - c - 2;
			let g = 0;
			while ( v[ CELL * slot + g ] !== INF ) g ++;
			const face = v[ CELL * slot + 4 + g ], t = face >> CELL_SHIFT, i = face & 3, k = CELL * t;
			// Counter-clockwise from outside: the face without vertex i of the positive tetrahedron t,
			// ordered so that vertex i is on its negative side (TetrahedralMesh's convention).
			let a: number, b: number, d: number;
			if ( i === 0 ) {

				a = v[ k + 1 ];
				b = v[ k + 2 ];
				d = v[ k + 3 ];

			} else if ( i === 1 ) {

				a = v[ k ];
				b = v[ k + 3 ];
				d = v[ k + 2 ];

			} else if ( i === 2 ) {

				a = v[ k ];
				b = v[ k + 1 ];
				d = v[ k + 3 ];

			} else {

				a = v[ k ];
				b = v[ k + 2 ];
				d = v[ k + 1 ];

			}

			this.hullFaces[ 3 * h ] = a; this.hullFaces[ 3 * h + 1 ] = b; this.hullFaces[ 3 * h + 2 ] = d;
			this.hullFaceCells[ h ] = index[ t ];

		}

	}

	/** Grows the per-slot arrays to the builder's slot capacity (after it may have grown). */
	ensureSlotCapacity(): void {

		const capacity = this.builder.capacity;
		if ( this.cellIndex.length >= capacity ) return;
		const index = new Int32Array( capacity ).fill( - 1 );
		index.set( this.cellIndex );
		this.cellIndex = index;
		this.slotStamp = growInt32( this.slotStamp, capacity );
		this.reportStamp = growInt32( this.reportStamp, capacity );

	}

}
