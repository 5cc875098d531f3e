import { assertCoordinates, assertInteger } from '../validate.js';
import { CELL, CELL_SHIFT, DelaunayBuilder, FREE, INF } from './DelaunayBuilder.js';
import { DenseCells, type TetrahedralEdit } from './DenseCells.js';
import { PointStore } from './PointStore.js';
import { buildDelaunay, DegenerateInputError, insertAll, readOptions, type TetrahedralizeOptions } from './tetrahedralize.js';
import { VertexRemoval } from './VertexRemoval.js';

export type { TetrahedralEdit } from './DenseCells.js';

const CALLER = 'DynamicTetrahedralization';
const INSERT = `${CALLER}.insert`, REMOVE = `${CALLER}.remove`, MOVE = `${CALLER}.move`;

/**
 * A 3D Delaunay tetrahedralization edited one point at a time: `insert`, `remove` and `move` update
 * only the cells around the point, and the mesh is always the one {@link tetrahedralize} builds from
 * scratch for the same points (same exact predicates and symbolic perturbation).
 *
 * Point ids are stable: `insert` returns the next unused id, `remove( i )` retires id i for good
 * (`isActive( i )` turns false; ids never shift or get reused), `move` keeps the id. Tetrahedron ids
 * are dense (0 … cellCount − 1); an edit renumbers a few, all listed in `lastEdit.changedCells`.
 * To keep per-tetrahedron data (e.g. inverse barycentric matrices) in step at O(change), after each
 * edit re-read the array getters (views an edit may reallocate or shorten), resize the data to
 * `lastEdit.cellCount` and recompute the entries in `lastEdit.changedCells` — all of them when
 * `lastEdit.rebuilt`; per-hull-face data likewise with `hullFaceCount` and `changedHullFaces`. Walk
 * hints kept elsewhere may point at other cells after an edit; any id < cellCount is a valid start.
 *
 * ```js
 * const mesh = new DynamicTetrahedralization( positions );
 * const id = mesh.insert( 1, 2, 3 );
 * mesh.move( id, 1.5, 2, 3 );
 * for ( const t of mesh.lastEdit.changedCells ) recomputeInverseMatrix( t, mesh.tetrahedra );
 * ```
 *
 * Tolerances are fixed at construction, relative to the initial bounding-box diagonal. Any scale:
 * the points are kept scaled by a power of two to about unit size (exactly); an edit far beyond it
 * rebuilds in a new scale (`lastEdit.rebuilt`), and one float64 cannot hold beside the others throws
 * a `DegenerateInputError` (`'unrepresentable'`), changing nothing (docs/robustness.md). Algorithms
 * (insertion, removal through the link's triangulation, dense numbering): docs/incremental-delaunay.md.
 */
export class DynamicTetrahedralization {

	/** Pairs (merged point, point it was merged into) found by the constructor; merged ids are inactive. */
	readonly duplicates: Uint32Array;

	/** What the last edit (or the construction) changed. */
	lastEdit: TetrahedralEdit;

	// Points as given and in the local frame; `p` is `points.frame.local`, which the cells refer to.
	private readonly points: PointStore;
	private p: Float64Array;
	private _pointCount: number;
	private _activeCount = 0;
	private active: Uint8Array;
	private vertexCell: Int32Array;
	private readonly planarTolerance: number;
	private readonly seed: number;

	private builder: DelaunayBuilder;
	private readonly cells: DenseCells;
	private readonly removal: VertexRemoval;

	/**
	 * @param positions Flat x, y, z per point; at least 4 distinct points not all in one plane.
	 * @param options As for {@link tetrahedralize}; `duplicateTolerance` (relative to the initial
	 *   bounding-box diagonal) also decides which later insertions and moves are rejected as duplicates.
	 * @throws {RangeError} on NaN/Infinity, a length that is not a multiple of 3, or an option that
	 *   is not a finite number ≥ 0 ({@link TypeError} when it is not a number).
	 * @throws {DegenerateInputError} for fewer than 4 distinct points, points that are all coplanar,
	 *   or a coordinate float64 cannot hold beside the others (`'unrepresentable'`).
	 */
	constructor( positions: ArrayLike<number>, options: TetrahedralizeOptions = {} ) {

		const { builder, ids, p, count, duplicates, diagonal, exponent } = buildDelaunay( CALLER, positions, options );
		const { duplicateTolerance, planarTolerance, seed } = readOptions( CALLER, options );
		this.duplicates = duplicates;
		this.planarTolerance = planarTolerance;
		this.seed = seed;

		const capacity = Math.max( 16, count * 2 );
		const raw = new Float64Array( 3 * capacity ), local = new Float64Array( 3 * capacity );
		raw.set( positions );
		local.set( p );
		const tolerance = duplicateTolerance * diagonal;
		this.points = new PointStore( raw, { local, exponent, tolerance, tolerance2: tolerance * tolerance, diagonal } );
		this.p = local;
		this._pointCount = count;
		this.active = new Uint8Array( capacity ).fill( 1, 0, count );
		for ( let i = 0; i < duplicates.length; i += 2 ) this.active[ duplicates[ i ] ] = 0;
		this._activeCount = count - duplicates.length / 2;
		this.vertexCell = new Int32Array( capacity ).fill( - 1 );

		this.builder = builder;
		builder.renumber( ids, this.p );
		builder.limitPoints( Infinity ); // edits may bring points beyond the initial box
		this.cells = new DenseCells( builder );
		this.removal = new VertexRemoval( this.p, capacity, diagonal, planarTolerance );
		this.lastEdit = this.adopt( builder );

	}

	/** Number of point ids handed out so far (active or not); ids are 0 … pointCount − 1. */
	get pointCount(): number {

		return this._pointCount;

	}

	/** Number of points that are vertices of the mesh. */
	get activeCount(): number {

		return this._activeCount;

	}

	/**
	 * x, y, z per point id (a view, valid until the next edit). Inactive ids keep their last position.
	 */
	get positions(): Float64Array {

		return this.points.raw.subarray( 0, 3 * this._pointCount );

	}

	/** Number of tetrahedra. */
	get cellCount(): number {

		return this.cells.cellCount;

	}

	/**
	 * Four point ids per tetrahedron, positively oriented (a view, valid until the next edit).
	 */
	get tetrahedra(): Uint32Array {

		return this.cells.tetrahedra.subarray( 0, 4 * this.cells.cellCount );

	}

	/**
	 * `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1 on the
	 * convex hull (a view, valid until the next edit).
	 */
	get neighbors(): Int32Array {

		return this.cells.neighbors.subarray( 0, 4 * this.cells.cellCount );

	}

	/** Number of convex-hull triangles. */
	get hullFaceCount(): number {

		return this.cells.hullFaceCount;

	}

	/**
	 * Convex-hull triangles, three point ids each, counter-clockwise seen from outside (a view, valid
	 * until the next edit).
	 */
	get hullFaces(): Uint32Array {

		return this.cells.hullFaces.subarray( 0, 3 * this.cells.hullFaceCount );

	}

	/** For each hull triangle, the tetrahedron it belongs to (a view, valid until the next edit). */
	get hullFaceCells(): Uint32Array {

		return this.cells.hullFaceCells.subarray( 0, this.cells.hullFaceCount );

	}

	/** True when point id i is a vertex of the mesh (not removed, not merged as a duplicate). */
	isActive( i: number ): boolean {

		return Number.isInteger( i ) && i >= 0 && i < this._pointCount && this.active[ i ] === 1;

	}

	/**
	 * Copies of the current tetrahedra and neighbours, shaped like {@link tetrahedralize}'s result
	 * (point ids stay as they are; no duplicates are reported).
	 */
	toTetrahedralization(): { tetrahedra: Uint32Array; neighbors: Int32Array; duplicates: Uint32Array } {

		return { tetrahedra: this.tetrahedra.slice(), neighbors: this.neighbors.slice(), duplicates: new Uint32Array( 0 ) };

	}

	/**
	 * Adds a point and returns its id (the next unused one).
	 * @throws {RangeError} when a coordinate is not finite.
	 * @throws {DegenerateInputError} (`reason: 'coincident'`) when the point is within the duplicate
	 *   tolerance of an existing one, `'unrepresentable'` when float64 cannot hold it beside the
	 *   others; nothing changes then.
	 */
	insert( x: number, y: number, z: number ): number {

		const where = INSERT;
		assertCoordinates( where, x, y, z );
		this.ensurePointCapacity( this._pointCount + 1 );
		const q = this._pointCount;
		if ( ! this.points.fits( x, y, z ) ) {

			this.rebuildRescaled( where, q, x, y, z );
			return q;

		}

		this.points.set( q, x, y, z );
		this.checkDuplicate( where, q, - 1 );

		this.cells.beginEdit();
		this._pointCount ++;
		this.insertLocated( q, true );
		this.lastEdit = this.cells.endEdit( false );
		return q;

	}

	/**
	 * Removes point `index` from the mesh; its id is retired (never reused, other ids unchanged).
	 * @throws {RangeError} when `index` is not an active point id.
	 * @throws {DegenerateInputError} when fewer than 4 points, or only coplanar points, would remain;
	 *   nothing changes then.
	 */
	remove( index: number ): void {

		const where = REMOVE;
		this.assertActive( where, index );
		this.removeVertex( where, index, false );

	}

	/**
	 * Moves point `index` to (x, y, z), keeping its id: a removal and an insertion, starting the walk
	 * at the hole the removal left. When the removal alone would leave a degenerate set (4 points,
	 * or the others coplanar) the mesh is rebuilt instead (`lastEdit.rebuilt`).
	 * @throws {RangeError} when `index` is not an active point id or a coordinate is not finite.
	 * @throws {DegenerateInputError} when the new position coincides with another point, makes the
	 *   set coplanar, or is one float64 cannot hold beside the others; nothing changes then.
	 */
	move( index: number, x: number, y: number, z: number ): void {

		const where = MOVE;
		this.assertActive( where, index );
		assertCoordinates( where, x, y, z );
		const raw = this.points.raw, k = 3 * index;
		if ( raw[ k ] === x && raw[ k + 1 ] === y && raw[ k + 2 ] === z ) {

			this.cells.beginEdit();
			this.lastEdit = this.cells.endEdit( false );
			return;

		}

		if ( ! this.points.fits( x, y, z ) ) {

			this.rebuildRescaled( where, index, x, y, z );
			return;

		}

		const p = this.p, ox = p[ k ], oy = p[ k + 1 ], oz = p[ k + 2 ];

		// Reject a duplicate before changing anything: the new position's nearest point is one of
		// the vertices of its conflict region in the current mesh, unless that nearest point is
		// `index` itself, which only matters when the move is shorter than the tolerance.
		this.ensurePointCapacity( this._pointCount + 1 );
		const scratch = this._pointCount;
		this.points.set( scratch, x, y, z );
		this.builder.last = this.vertexCell[ index ];
		this.checkDuplicate( where, scratch, index );
		const lx = p[ 3 * scratch ], ly = p[ 3 * scratch + 1 ], lz = p[ 3 * scratch + 2 ];
		if ( this.points.within( lx - ox, ly - oy, lz - oz, 2 ) ) {

			const w = this.points.duplicateOf( scratch, index, this._pointCount, this.active );
			if ( w >= 0 ) this.throwDuplicate( where, scratch, w );

		}

		// The removal checks everything before changing anything; when it would leave a degenerate
		// set, the moved set may still be fine: rebuild it.
		try {

			if ( this._activeCount <= 4 ) throw new DegenerateInputError( 'too-few-points', '' );
			this.removeVertex( where, index, true );

		} catch ( error ) {

			if ( ! ( error instanceof DegenerateInputError ) ) throw error;
			this.rebuildWithMove( where, index, x, y, z );
			return;

		}

		this.points.set( index, x, y, z );
		this.insertLocated( index, false );
		this.lastEdit = this.cells.endEdit( false );

	}

	// --- Insertion ---------------------------------------------------------------------------

	/** Rejects point q (already written) when it is within tolerance of an active point other than `ignore`. */
	private checkDuplicate( where: string, q: number, ignore: number ): void {

		const builder = this.builder;
		builder.findConflicts( q, builder.locate( q ) );

		// q's nearest point is a vertex of its conflict region (it is a Delaunay neighbour of q).
		const v = builder.cells, p = this.p;
		const x = p[ 3 * q ], y = p[ 3 * q + 1 ], z = p[ 3 * q + 2 ];
		for ( let c = 0; c < builder.cavitySize; c ++ ) {

			const t = builder.cavity[ c ];
			for ( let i = 0; i < 4; i ++ ) {

				const w = v[ CELL * t + i ];
				if ( w === INF || w === ignore ) continue;
				if ( this.points.within( p[ 3 * w ] - x, p[ 3 * w + 1 ] - y, p[ 3 * w + 2 ] - z, 1 ) ) this.throwDuplicate( where, q, w );

			}

		}

	}

	/** Throws the duplicate error for point q coinciding with w; `given`: q's position when not in `positions` yet. */
	private throwDuplicate( where: string, q: number, w: number, given?: number[] ): never {

		const raw = this.points.raw;
		const [ x, y, z ] = given ?? [ raw[ 3 * q ], raw[ 3 * q + 1 ], raw[ 3 * q + 2 ] ];
		throw new DegenerateInputError( 'coincident', `${where}: ( ${x}, ${y}, ${z} ) coincides with point ${w} (within duplicateTolerance of the extent); move or remove that point instead.` );

	}

	/**
	 * Inserts point q (coordinates written, not a duplicate) inside an open edit; `conflictsFound`
	 * when the last `findConflicts` was for q in the current mesh.
	 */
	private insertLocated( q: number, conflictsFound: boolean ): void {

		const builder = this.builder, cells = this.cells;
		if ( ! conflictsFound ) builder.findConflicts( q, builder.locate( q ) );
		for ( let c = 0; c < builder.cavitySize; c ++ ) cells.dropSlot( builder.cavity[ c ] );
		builder.fillConflicts( q );
		cells.removedCount += builder.cavitySize;
		cells.createdCount += builder.boundarySize;
		cells.ensureSlotCapacity();
		const v = builder.cells;
		for ( let c = 0; c < builder.boundarySize; c ++ ) {

			const t = builder.created[ c ];
			cells.addSlot( t );
			for ( let i = 0; i < 4; i ++ ) {

				const w = v[ CELL * t + i ];
				if ( w !== INF ) this.vertexCell[ w ] = t;

			}

		}

		this.active[ q ] = 1;
		this._activeCount ++;

	}

	// --- Removal -----------------------------------------------------------------------------

	/**
	 * Removes vertex `index` (active); nothing changes when it throws. Opens an edit; closes it
	 * unless `keepOpen` (`move` inserts into the same edit).
	 */
	private removeVertex( where: string, index: number, keepOpen: boolean ): void {

		if ( this._activeCount <= 4 ) {

			throw new DegenerateInputError( 'too-few-points', `${where}: removing point ${index} would leave ${this._activeCount - 1} points; at least 4 are needed.` );

		}

		this.removal.remove( where, index, this.builder, this.p, this.vertexCell, this.cells );
		this.active[ index ] = 0;
		this._activeCount --;
		if ( ! keepOpen ) this.lastEdit = this.cells.endEdit( false );

	}

	// --- Rebuild -----------------------------------------------------------------------------

	/** Moves `index` by rebuilding from scratch (for tiny or flat sets); nothing changes if that throws. */
	private rebuildWithMove( where: string, index: number, x: number, y: number, z: number ): void {

		const raw = this.points.raw, k = 3 * index, p = this.p;
		const ox = raw[ k ], oy = raw[ k + 1 ], oz = raw[ k + 2 ];
		const ids = this.activeIds( index );
		this.points.set( index, x, y, z );
		const diagonal = this.points.frame.diagonal, builder = new DelaunayBuilder( p, this._pointCount, diagonal );
		try {

			builder.renumber( insertAll( where, builder, p, ids, diagonal, this.planarTolerance, this.seed ), p );

		} catch ( error ) {

			this.points.set( index, ox, oy, oz );
			throw error;

		}

		this.builder = builder;
		this.lastEdit = this.adopt( builder );

	}

	/**
	 * Sets point `index` (active, or the next id for an insertion) to (x, y, z) by normalising the
	 * points anew and rebuilding: for a position the current local frame cannot hold exactly.
	 * Nothing changes if it throws (a duplicate, a flat set, a coordinate float64 cannot hold).
	 */
	private rebuildRescaled( where: string, index: number, x: number, y: number, z: number ): void {

		const ids = this.activeIds( index );
		const frame = this.points.renormalized( where, ids, index, x, y, z );
		const w = this.points.duplicateOf( index, index, this._pointCount, this.active, frame );
		if ( w >= 0 ) this.throwDuplicate( where, index, w, [ x, y, z ] );
		const builder = new DelaunayBuilder( frame.local, this._pointCount + 1, frame.diagonal );
		builder.renumber( insertAll( where, builder, frame.local, ids, frame.diagonal, this.planarTolerance, this.seed ), frame.local );

		// Commit.
		this.points.frame = frame;
		this.p = frame.local;
		this.points.set( index, x, y, z );
		this.removal.ensurePointCapacity( this.active.length, frame.local );
		this.removal.setDiagonal( frame.diagonal );
		if ( index === this._pointCount ) {

			this._pointCount ++;
			this._activeCount ++;
			this.active[ index ] = 1;

		}

		this.lastEdit = this.adopt( builder );

	}

	/** The active point ids, and `extra` (an id to include, e.g. the next one; −1 for none). */
	private activeIds( extra: number ): Uint32Array {

		const add = extra >= 0 && ! this.isActive( extra ) ? 1 : 0;
		const ids = new Uint32Array( this._activeCount + add );
		let j = 0;
		for ( let i = 0; i < this._pointCount; i ++ ) if ( this.active[ i ] ) ids[ j ++ ] = i;
		if ( add ) ids[ j ] = extra;
		return ids;

	}

	/** Numbers every cell of a freshly built `builder` and fills the dense arrays. */
	private adopt( builder: DelaunayBuilder ): TetrahedralEdit {

		this.builder = builder;
		const cells = this.cells;
		cells.reset( builder );
		this.vertexCell.fill( - 1 );
		const v = builder.cells;
		for ( let t = 0; t < builder.used; t ++ ) {

			const k = CELL * t;
			if ( v[ k ] === FREE ) continue;
			cells.addSlot( t );
			cells.createdCount ++;
			for ( let i = k; i < k + 4; i ++ ) if ( v[ i ] !== INF ) this.vertexCell[ v[ i ] ] = t;

		}

		return cells.endEdit( true );

	}

	// --- Storage -----------------------------------------------------------------------------

	private ensurePointCapacity( count: number ): void {

		if ( 3 * count <= this.p.length ) return;
		const capacity = Math.max( 2 * count, 16 );
		this.points.grow( capacity, this._pointCount );
		const p = this.p = this.points.frame.local;
		this.builder.p = p;
		const active = new Uint8Array( capacity );
		active.set( this.active );
		this.active = active;
		const cells = new Int32Array( capacity ).fill( - 1 );
		cells.set( this.vertexCell );
		this.vertexCell = cells;
		this.removal.ensurePointCapacity( capacity, p );

	}

	private assertActive( where: string, index: number ): void {

		assertInteger( where, 'index', index, 0 );
		if ( ! this.isActive( index ) ) {

			throw new RangeError( `${where}: index ${index} is not an active point id (0 … ${this._pointCount - 1}, not removed or merged).` );

		}

	}

}
