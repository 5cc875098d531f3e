import { assertInteger } from '../validate.js';
import { DelaunayBuilder, FREE, INF } from './DelaunayBuilder.js';
import { DenseCells, type TetrahedralEdit } from './DenseCells.js';
import { buildDelaunay, DegenerateInputError, insertAll, type TetrahedralizeOptions } from './tetrahedralize.js';
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
 * Tolerances are fixed at construction, relative to the initial bounding-box diagonal. Algorithms
 * (insertion, removal through the link's triangulation, dense numbering): docs/incremental-delaunay.md.
 */
export class DynamicTetrahedralization {

	/** Pairs (merged point, point it was merged into) found by the constructor; merged ids are inactive. */
	readonly duplicates: Uint32Array;

	/** What the last edit (or the construction) changed. */
	lastEdit: TetrahedralEdit;

	private p: Float64Array;
	private _pointCount: number;
	private _activeCount = 0;
	private active: Uint8Array;
	private vertexCell: Int32Array;
	private readonly tolerance2: number;
	private readonly diagonal: number;
	private readonly planarTolerance: number;
	private readonly seed: number;

	private builder: DelaunayBuilder;
	private readonly cells: DenseCells;
	private readonly removal: VertexRemoval;

	/**
	 * @param positions Flat x, y, z per point; at least 4 distinct points not all in one plane.
	 * @param options As for {@link tetrahedralize}; `duplicateTolerance` (relative to the initial
	 *   bounding-box diagonal) also decides which later insertions and moves are rejected as duplicates.
	 * @throws {RangeError} on NaN/Infinity or a length that is not a multiple of 3.
	 * @throws {DegenerateInputError} for fewer than 4 distinct points, or points that are all coplanar.
	 */
	constructor( positions: ArrayLike<number>, options: TetrahedralizeOptions = {} ) {

		const { builder, p, count, duplicates, diagonal } = buildDelaunay( CALLER, positions, options );
		const { duplicateTolerance = 1e-9, planarTolerance = 1e-9, seed = 1 } = options;
		this.duplicates = duplicates;
		this.diagonal = diagonal;
		this.tolerance2 = ( duplicateTolerance * diagonal ) ** 2;
		this.planarTolerance = planarTolerance;
		this.seed = seed;

		const capacity = Math.max( 16, count * 2 );
		this.p = new Float64Array( 3 * capacity );
		this.p.set( p );
		this._pointCount = count;
		this.active = new Uint8Array( capacity ).fill( 1, 0, count );
		for ( let i = 0; i < duplicates.length; i += 2 ) this.active[ duplicates[ i ] ] = 0;
		this._activeCount = count - duplicates.length / 2;
		this.vertexCell = new Int32Array( capacity ).fill( - 1 );

		this.builder = builder;
		builder.p = this.p;
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

		return this.p.subarray( 0, 3 * this._pointCount );

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
	 *   tolerance of an existing one; nothing changes then.
	 */
	insert( x: number, y: number, z: number ): number {

		const where = INSERT;
		assertCoordinates( where, x, y, z );
		this.ensurePointCapacity( this._pointCount + 1 );
		const q = this._pointCount;
		this.setPoint( q, x, y, z );
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
	 * @throws {DegenerateInputError} when the new position coincides with another point, or makes
	 *   the set coplanar; nothing changes then.
	 */
	move( index: number, x: number, y: number, z: number ): void {

		const where = MOVE;
		this.assertActive( where, index );
		assertCoordinates( where, x, y, z );
		const p = this.p, k = 3 * index;
		const ox = p[ k ], oy = p[ k + 1 ], oz = p[ k + 2 ];
		if ( ox === x && oy === y && oz === z ) {

			this.cells.beginEdit();
			this.lastEdit = this.cells.endEdit( false );
			return;

		}

		// Reject a duplicate before changing anything: the new position's nearest point is one of
		// the vertices of its conflict region in the current mesh, unless that nearest point is
		// `index` itself, which only matters when the move is shorter than the tolerance.
		this.ensurePointCapacity( this._pointCount + 1 );
		const scratch = this._pointCount;
		this.setPoint( scratch, x, y, z );
		this.builder.last = this.vertexCell[ index ];
		this.checkDuplicate( where, scratch, index );
		const shortMove = ( x - ox ) ** 2 + ( y - oy ) ** 2 + ( z - oz ) ** 2 <= 4 * this.tolerance2;
		if ( shortMove ) this.checkDuplicateBruteForce( where, x, y, z, index );

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

		this.setPoint( index, x, y, z );
		this.insertLocated( index, false );
		this.lastEdit = this.cells.endEdit( false );

	}

	// --- Insertion ---------------------------------------------------------------------------

	/** Rejects point q (already written to `p`) when it is within tolerance of an active point other than `ignore`. */
	private checkDuplicate( where: string, q: number, ignore: number ): void {

		const builder = this.builder;
		builder.findConflicts( q, builder.locate( q ) );

		// q's nearest point is a vertex of its conflict region (it is a Delaunay neighbour of q).
		const v = builder.vertices, p = this.p;
		const x = p[ 3 * q ], y = p[ 3 * q + 1 ], z = p[ 3 * q + 2 ];
		for ( let c = 0; c < builder.cavitySize; c ++ ) {

			const t = builder.cavity[ c ];
			for ( let i = 0; i < 4; i ++ ) {

				const w = v[ 4 * t + i ];
				if ( w === INF || w === ignore ) continue;
				const d2 = ( p[ 3 * w ] - x ) ** 2 + ( p[ 3 * w + 1 ] - y ) ** 2 + ( p[ 3 * w + 2 ] - z ) ** 2;
				if ( d2 <= this.tolerance2 ) this.throwDuplicate( where, x, y, z, w );

			}

		}

	}

	private checkDuplicateBruteForce( where: string, x: number, y: number, z: number, ignore: number ): void {

		const p = this.p;
		for ( let w = 0; w < this._pointCount; w ++ ) {

			if ( w === ignore || ! this.active[ w ] ) continue;
			const d2 = ( p[ 3 * w ] - x ) ** 2 + ( p[ 3 * w + 1 ] - y ) ** 2 + ( p[ 3 * w + 2 ] - z ) ** 2;
			if ( d2 <= this.tolerance2 ) this.throwDuplicate( where, x, y, z, w );

		}

	}

	private throwDuplicate( where: string, x: number, y: number, z: number, w: number ): never {

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
		const v = builder.vertices;
		for ( let c = 0; c < builder.boundarySize; c ++ ) {

			const t = builder.created[ c ];
			cells.addSlot( t );
			for ( let i = 0; i < 4; i ++ ) {

				const w = v[ 4 * t + i ];
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

		const p = this.p, k = 3 * index;
		const ox = p[ k ], oy = p[ k + 1 ], oz = p[ k + 2 ];
		const ids = new Uint32Array( this._activeCount );
		for ( let i = 0, j = 0; i < this._pointCount; i ++ ) if ( this.active[ i ] ) ids[ j ++ ] = i;
		this.setPoint( index, x, y, z );
		const builder = new DelaunayBuilder( p, this._pointCount, this.diagonal );
		try {

			insertAll( where, builder, p, ids, this.diagonal, this.planarTolerance, this.seed );

		} catch ( error ) {

			this.setPoint( index, ox, oy, oz );
			throw error;

		}

		this.builder = builder;
		this.lastEdit = this.adopt( builder );

	}

	/** Numbers every cell of a freshly built `builder` and fills the dense arrays. */
	private adopt( builder: DelaunayBuilder ): TetrahedralEdit {

		this.builder = builder;
		const cells = this.cells;
		cells.reset( builder );
		this.vertexCell.fill( - 1 );
		const v = builder.vertices;
		for ( let t = 0; t < builder.used; t ++ ) {

			if ( v[ 4 * t ] === FREE ) continue;
			cells.addSlot( t );
			cells.createdCount ++;
			for ( let i = 0; i < 4; i ++ ) if ( v[ 4 * t + i ] !== INF ) this.vertexCell[ v[ 4 * t + i ] ] = t;

		}

		return cells.endEdit( true );

	}

	// --- Storage -----------------------------------------------------------------------------

	private ensurePointCapacity( count: number ): void {

		if ( 3 * count <= this.p.length ) return;
		const capacity = Math.max( 2 * count, 16 );
		const p = new Float64Array( 3 * capacity );
		p.set( this.p );
		this.p = p;
		this.builder.p = p;
		const active = new Uint8Array( capacity );
		active.set( this.active );
		this.active = active;
		const cells = new Int32Array( capacity ).fill( - 1 );
		cells.set( this.vertexCell );
		this.vertexCell = cells;
		this.removal.ensurePointCapacity( capacity, p );

	}

	private setPoint( i: number, x: number, y: number, z: number ): void {

		this.p[ 3 * i ] = x; this.p[ 3 * i + 1 ] = y; this.p[ 3 * i + 2 ] = z;

	}

	private assertActive( where: string, index: number ): void {

		assertInteger( where, 'index', index, 0 );
		if ( ! this.isActive( index ) ) {

			throw new RangeError( `${where}: index ${index} is not an active point id (0 … ${this._pointCount - 1}, not removed or merged).` );

		}

	}

}

function assertCoordinates( where: string, x: number, y: number, z: number ): void {

	if ( Number.isFinite( x ) && Number.isFinite( y ) && Number.isFinite( z ) ) return;
	const [ name, value ] = ! Number.isFinite( x ) ? [ 'x', x ] : ! Number.isFinite( y ) ? [ 'y', y ] : [ 'z', z ];
	throw new RangeError( `${where}: ${name} is ${String( value )}; coordinates must be finite numbers.` );

}
