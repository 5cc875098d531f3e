import { assertInteger } from '../validate.js';
import { coplanarOrient, orient } from './predicates.js';
import { DelaunayBuilder, FREE, INF, growInt32 } from './DelaunayBuilder.js';
import { FaceTable } from './FaceTable.js';
import { buildDelaunay, DegenerateInputError, findInitialTetrahedron, insertAll, type TetrahedralizeOptions } from './tetrahedralize.js';

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

const CALLER = 'DynamicTetrahedralization';
const INSERT = `${CALLER}.insert`, REMOVE = `${CALLER}.remove`, MOVE = `${CALLER}.move`;

/**
 * A 3D Delaunay tetrahedralization that can be edited one point at a time: `insert`, `remove` and
 * `move` update only the cells around the edited point, with the same exact predicates and
 * symbolic perturbation as {@link tetrahedralize} — so after any sequence of edits the mesh is the
 * one `tetrahedralize` would build from scratch for the same points (the perturbation ranks points
 * by their coordinates, never by insertion order or index).
 *
 * Point ids are stable: `insert` returns the next unused id, `remove( i )` retires id i for good
 * (its slot stays, `isActive( i )` turns false; ids never shift or get reused), `move` keeps the id.
 * Tetrahedron ids are dense (0 … cellCount − 1) so the arrays can be used directly; an edit
 * deletes and creates a few tetrahedra and fills freed ids by moving the last ones (swap-remove),
 * all of which `lastEdit.changedCells` lists.
 *
 * Insertion: a walk from the last edited cell locates the point, its conflict region is replaced
 * by the cells joining it to the region's boundary (Bowyer–Watson). Removal: the Delaunay
 * tetrahedralization of the removed vertex's link (the other vertices of its star, ghost cells on
 * the hull included) is built with the same perturbation, and its cells inside the hole, found by a
 * flood from a hole face that stops at the hole's boundary faces, fill the hole exactly; a hull
 * vertex whose link is flat leaves only hull faces behind.
 *
 * Keeping per-tetrahedron data (e.g. inverse barycentric matrices) in step costs O(change): after
 * each edit re-read the array getters (they are views that an edit may reallocate or shorten),
 * resize the data to `lastEdit.cellCount`, and recompute the entries listed in
 * `lastEdit.changedCells` — or all of them when `lastEdit.rebuilt`. Per-hull-face data likewise
 * with `hullFaceCount` and `changedHullFaces`. Tetrahedron ids kept elsewhere (walk hints) may point
 * at other cells or past the end after an edit; any id < cellCount is still a valid start.
 *
 * ```js
 * const mesh = new DynamicTetrahedralization( positions );
 * const id = mesh.insert( 1, 2, 3 );
 * mesh.move( id, 1.5, 2, 3 );
 * for ( const t of mesh.lastEdit.changedCells ) recomputeInverseMatrix( t, mesh.tetrahedra );
 * ```
 *
 * Tolerances are fixed at construction: `duplicateTolerance` and `planarTolerance` are relative
 * to the initial bounding-box diagonal. The planar tolerance is applied to a removal only when
 * every remaining tetrahedron touched the removed point (otherwise the rest spans a volume exactly).
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
	private readonly linkBuilder: DelaunayBuilder;

	// Dense numbering: cellIndex[slot] ≥ 0 is a tetrahedron id, ≤ −2 the hull face id −(value + 2) of a ghost, −1 none.
	private cellIndex = new Int32Array( 0 );
	private cellSlot = new Int32Array( 64 );
	private _tetrahedra = new Uint32Array( 256 );
	private _neighbors = new Int32Array( 256 );
	private _cellCount = 0;
	private hullSlot = new Int32Array( 64 );
	private _hullFaces = new Uint32Array( 192 );
	private _hullFaceCells = new Uint32Array( 64 );
	private _hullFaceCount = 0;

	// Edit bookkeeping.
	private dirty = new Int32Array( 256 );
	private dirtyCount = 0;
	private slotStamp = new Int32Array( 0 );
	private reportStamp = new Int32Array( 0 );
	private stamp = 0;
	private editStamp = 0;
	private removedCount = 0;
	private createdCount = 0;
	private previousCellCount = 0;
	private changedCells = new Int32Array( 256 );
	private changedHullFaces = new Int32Array( 256 );

	// Removal scratch.
	private readonly boundaryFaces = new FaceTable();
	private readonly innerFaces = new FaceTable();
	private star = new Int32Array( 256 );
	private boundaryHandle = new Int32Array( 256 );
	private boundaryHits = new Int32Array( 256 );
	private fill = new Int32Array( 1024 );
	private fillLinks = new Int32Array( 1024 );
	private fillSlots = new Int32Array( 256 );
	private link = new Uint32Array( 256 );
	private linkCount = 0;
	private finiteStarCount = 0;
	private pointStamp: Int32Array;
	private visit = new Int32Array( 0 );

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
		this.pointStamp = new Int32Array( capacity );

		this.builder = builder;
		builder.p = this.p;
		this.linkBuilder = new DelaunayBuilder( this.p, 64, diagonal );
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

		return this._cellCount;

	}

	/**
	 * Four point ids per tetrahedron, positively oriented (a view, valid until the next edit).
	 */
	get tetrahedra(): Uint32Array {

		return this._tetrahedra.subarray( 0, 4 * this._cellCount );

	}

	/**
	 * `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i of t, or −1 on the
	 * convex hull (a view, valid until the next edit).
	 */
	get neighbors(): Int32Array {

		return this._neighbors.subarray( 0, 4 * this._cellCount );

	}

	/** Number of convex-hull triangles. */
	get hullFaceCount(): number {

		return this._hullFaceCount;

	}

	/**
	 * Convex-hull triangles, three point ids each, counter-clockwise seen from outside (a view, valid
	 * until the next edit).
	 */
	get hullFaces(): Uint32Array {

		return this._hullFaces.subarray( 0, 3 * this._hullFaceCount );

	}

	/** For each hull triangle, the tetrahedron it belongs to (a view, valid until the next edit). */
	get hullFaceCells(): Uint32Array {

		return this._hullFaceCells.subarray( 0, this._hullFaceCount );

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

		this.beginEdit();
		this._pointCount ++;
		this.insertLocated( q, true );
		this.endEdit( false );
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

			this.beginEdit();
			this.endEdit( false );
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
		if ( ( x - ox ) ** 2 + ( y - oy ) ** 2 + ( z - oz ) ** 2 <= 4 * this.tolerance2 ) this.checkDuplicateBruteForce( where, x, y, z, index );

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
		this.endEdit( false );

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

		const builder = this.builder;
		if ( ! conflictsFound ) builder.findConflicts( q, builder.locate( q ) );
		for ( let c = 0; c < builder.cavitySize; c ++ ) this.dropSlot( builder.cavity[ c ] );
		builder.fillConflicts( q );
		this.removedCount += builder.cavitySize;
		this.createdCount += builder.boundarySize;
		this.ensureSlotCapacity();
		const v = builder.vertices;
		for ( let c = 0; c < builder.boundarySize; c ++ ) {

			const t = builder.created[ c ];
			this.addSlot( t );
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
	 * Collects the star of vertex `index`: cells into `star` (returned count), its faces opposite
	 * `index` into `boundaryHandle` (the outside cell's side, `4u + j`) and `boundaryFaces`, the
	 * other finite vertices into `link` (count in `linkCount`); counts its tetrahedra in `finiteStarCount`.
	 */
	private collectStar( index: number ): number {

		const builder = this.builder, v = builder.vertices, adj = builder.adjacency;
		this.ensureSlotCapacity();
		const visit = this.visit, stamp = ++ this.stamp;
		let count = 0;
		const first = this.vertexCell[ index ];
		visit[ first ] = stamp;
		this.star[ count ++ ] = first;
		for ( let head = 0; head < count; head ++ ) {

			const t = this.star[ head ];
			for ( let j = 0; j < 4; j ++ ) {

				// Faces through `index` lead to the rest of the star.
				if ( v[ 4 * t + j ] === index ) continue;
				const u = adj[ 4 * t + j ] >> 2;
				if ( visit[ u ] === stamp ) continue;
				visit[ u ] = stamp;
				if ( count === this.star.length ) this.star = growInt32( this.star, count * 2 );
				this.star[ count ++ ] = u;

			}

		}

		if ( this.boundaryHandle.length < count ) {

			this.boundaryHandle = new Int32Array( 2 * count );
			this.boundaryHits = new Int32Array( 2 * count );

		}

		const pointStamp = this.pointStamp;
		let linkCount = 0, finite = 0;
		this.boundaryFaces.clear( count );
		for ( let b = 0; b < count; b ++ ) {

			const t = this.star[ b ];
			let k = 0, ghost = false;
			for ( let j = 0; j < 4; j ++ ) {

				const w = v[ 4 * t + j ];
				if ( w === index ) { k = j; continue; }
				if ( w === INF ) { ghost = true; continue; }
				if ( pointStamp[ w ] !== stamp ) {

					pointStamp[ w ] = stamp;
					if ( linkCount === this.link.length ) this.link = growUint32( this.link, linkCount * 2 );
					this.link[ linkCount ++ ] = w;

				}

			}

			if ( ! ghost ) finite ++;
			this.boundaryHandle[ b ] = adj[ 4 * t + k ];
			this.boundaryHits[ b ] = 0;
			otherThree( v, t, k );
			this.boundaryFaces.set( _three[ 0 ], _three[ 1 ], _three[ 2 ], b );

		}

		this.linkCount = linkCount;
		this.finiteStarCount = finite;
		return count;

	}

	/**
	 * Removes vertex `index` (active): checks, computes the filling cells, then replaces the star.
	 * Opens an edit; closes it unless `keepOpen` (`move` inserts into the same edit).
	 */
	private removeVertex( where: string, index: number, keepOpen: boolean ): void {

		if ( this._activeCount <= 4 ) {

			throw new DegenerateInputError( 'too-few-points', `${where}: removing point ${index} would leave ${this._activeCount - 1} points; at least 4 are needed.` );

		}

		const starCount = this.collectStar( index );
		const link = this.link.subarray( 0, this.linkCount );

		// Every remaining tetrahedron touches `index`: the others are all in its link, and must span a volume.
		if ( this.finiteStarCount === this._cellCount ) findInitialTetrahedron( where, this.p, link, this.diagonal, this.planarTolerance );

		const fillCount = this.computeFill( index, starCount );

		// Commit: release the star, create the filling cells, link them.
		this.beginEdit();
		const builder = this.builder;
		for ( let s = 0; s < starCount; s ++ ) {

			this.dropSlot( this.star[ s ] );
			builder.release( this.star[ s ] );

		}

		builder.reserve( fillCount );
		this.ensureSlotCapacity();
		if ( this.fillSlots.length < fillCount ) this.fillSlots = new Int32Array( 2 * fillCount );
		const v = builder.vertices, adj = builder.adjacency, fill = this.fill, links = this.fillLinks, slots = this.fillSlots;
		for ( let n = 0; n < fillCount; n ++ ) {

			const t = builder.allocate();
			slots[ n ] = t;
			for ( let i = 0; i < 4; i ++ ) v[ 4 * t + i ] = fill[ 4 * n + i ];

		}

		let lastFinite = slots[ 0 ];
		for ( let n = 0; n < fillCount; n ++ ) {

			const t = slots[ n ];
			for ( let j = 0; j < 4; j ++ ) {

				const l = links[ 4 * n + j ];
				if ( l >= 0 ) {

					adj[ 4 * t + j ] = 4 * slots[ l >> 2 ] + ( l & 3 );

				} else {

					const h = this.boundaryHandle[ - l - 1 ];
					adj[ 4 * t + j ] = h;
					adj[ h ] = 4 * t + j;

				}

				const w = v[ 4 * t + j ];
				if ( w !== INF ) this.vertexCell[ w ] = t;

			}

			this.addSlot( t );
			if ( ! builder.isGhost( t ) ) lastFinite = t;

		}

		builder.last = lastFinite;
		this.removedCount += starCount;
		this.createdCount += fillCount;
		this.active[ index ] = 0;
		this.vertexCell[ index ] = - 1;
		this._activeCount --;
		if ( ! keepOpen ) this.endEdit( false );

	}

	/**
	 * The cells that fill the star's hole once `index` is gone, into `fill` (4 vertices each) and
	 * their face links into `fillLinks` (`4m + j` for a face shared with filling cell m, −(b + 1)
	 * for star boundary face b). Changes nothing in the mesh; throws if the filling does not close.
	 */
	private computeFill( index: number, starCount: number ): number {

		const v = this.builder.vertices;
		const link = this.link.subarray( 0, this.linkCount );
		let fillCount = 0;

		const initial = exactInitialTetrahedron( this.p, link );
		if ( initial === null ) {

			// A flat link: `index` is a hull vertex over a planar patch, which becomes hull faces.
			for ( let s = 0; s < starCount; s ++ ) {

				const t = this.star[ s ];
				if ( this.builder.isGhost( t ) ) continue;
				this.ensureFill( fillCount + 1 );
				for ( let i = 0; i < 4; i ++ ) {

					const w = v[ 4 * t + i ];
					this.fill[ 4 * fillCount + i ] = w === index ? INF : w;

				}

				fillCount ++;

			}

		} else {

			fillCount = this.linkTriangulationInsideHole( index, initial, link );

		}

		// Link the filling cells to each other and to the hole's boundary.
		const fill = this.fill, links = this.fillLinks, inner = this.innerFaces, boundary = this.boundaryFaces;
		inner.clear( 4 * fillCount );
		for ( let n = 0; n < fillCount; n ++ ) {

			for ( let j = 0; j < 4; j ++ ) {

				otherThree( fill, n, j );
				const a = _three[ 0 ], b = _three[ 1 ], c = _three[ 2 ];
				const bf = boundary.get( a, b, c );
				if ( bf >= 0 ) {

					this.boundaryHits[ bf ] ++;
					links[ 4 * n + j ] = - bf - 1;
					continue;

				}

				const other = inner.pair( a, b, c, 4 * n + j );
				if ( other >= 0 ) {

					links[ 4 * n + j ] = other;
					links[ other ] = 4 * n + j;

				}

			}

		}

		let closed = inner.size === 0 && fillCount > 0;
		for ( let b = 0; b < starCount; b ++ ) if ( this.boundaryHits[ b ] !== 1 ) closed = false;
		if ( ! closed ) {

			throw new Error( `${CALLER}.remove: internal error, the re-triangulated hole of point ${index} does not match its boundary; the mesh is unchanged.` );

		}

		return fillCount;

	}

	/**
	 * Builds the Delaunay tetrahedralization of the link and copies its cells inside the hole of
	 * `index` (flooded from the cell behind one of the hole's faces) into `fill`.
	 */
	private linkTriangulationInsideHole( index: number, initial: [ number, number, number, number ], link: Uint32Array ): number {

		const small = this.linkBuilder;
		small.p = this.p;
		small.reset();
		small.start( initial );
		for ( let i = 0; i < link.length; i ++ ) {

			const w = link[ i ];
			if ( w !== initial[ 0 ] && w !== initial[ 1 ] && w !== initial[ 2 ] && w !== initial[ 3 ] ) small.insert( w );

		}

		// A hole face behind a tetrahedron of the star: find it in the small triangulation and
		// take the cell on the side where `index` was.
		const v = this.builder.vertices, sv = small.vertices, sadj = small.adjacency;
		let s = 0, k = 0;
		for ( ; ; s ++ ) {

			const t = this.star[ s ];
			if ( ! this.builder.isGhost( t ) ) {

				while ( v[ 4 * t + k ] !== index ) k ++;
				break;

			}

		}

		const t = this.star[ s ];
		otherThree( v, t, k );
		const f0 = _three[ 0 ], f1 = _three[ 1 ], f2 = _three[ 2 ];
		let start = - 1;
		search: for ( let u = 0; u < small.used; u ++ ) {

			if ( sv[ 4 * u ] === FREE ) continue;
			for ( let j = 0; j < 4; j ++ ) {

				otherThree( sv, u, j );
				const a = _three[ 0 ], b = _three[ 1 ], c = _three[ 2 ];
				if ( ! sameTriangle( a, b, c, f0, f1, f2 ) ) continue;
				const apex = sv[ 4 * u + j ];
				if ( apex !== INF ) {

					// Same side as `index` ⇔ the star cell stays positive with `index` replaced by apex.
					start = orientReplaced( this.p, v, t, k, apex ) > 0 ? u : sadj[ 4 * u + j ] >> 2;

				} else {

					// A ghost: decide by the finite cell behind the face.
					const behind = sadj[ 4 * u + j ];
					start = orientReplaced( this.p, v, t, k, sv[ behind ] ) > 0 ? behind >> 2 : u;

				}

				break search;

			}

		}

		if ( start < 0 ) throw new Error( `${CALLER}.remove: internal error, a face of the hole of point ${index} is missing from its link's triangulation; the mesh is unchanged.` );

		// Flood inside the hole, never crossing one of its boundary faces.
		if ( this.visit.length < small.used ) this.visit = growInt32( this.visit, small.capacity );
		const visit = this.visit, stamp = ++ this.stamp;
		let stack = this.fillSlots, top = 0, fillCount = 0;
		visit[ start ] = stamp;
		stack[ top ++ ] = start;
		while ( top > 0 ) {

			const u = stack[ -- top ];
			this.ensureFill( fillCount + 1 );
			for ( let i = 0; i < 4; i ++ ) this.fill[ 4 * fillCount + i ] = sv[ 4 * u + i ];
			fillCount ++;
			for ( let j = 0; j < 4; j ++ ) {

				otherThree( sv, u, j );
				const a = _three[ 0 ], b = _three[ 1 ], c = _three[ 2 ];
				if ( this.boundaryFaces.get( a, b, c ) >= 0 ) continue;
				const w = sadj[ 4 * u + j ] >> 2;
				if ( visit[ w ] === stamp ) continue;
				visit[ w ] = stamp;
				if ( top === stack.length ) stack = this.fillSlots = growInt32( stack, top * 2 );
				stack[ top ++ ] = w;

			}

		}

		return fillCount;

	}

	private ensureFill( count: number ): void {

		if ( this.fill.length < 4 * count ) {

			this.fill = growInt32( this.fill, 8 * count );
			this.fillLinks = growInt32( this.fillLinks, 8 * count );

		}

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
		this.previousCellCount = this._cellCount;
		this._cellCount = 0;
		this._hullFaceCount = 0;
		this.cellIndex = new Int32Array( builder.capacity ).fill( - 1 );
		this.slotStamp = new Int32Array( builder.capacity );
		this.reportStamp = new Int32Array( builder.capacity );
		this.visit = new Int32Array( builder.capacity );
		this.vertexCell.fill( - 1 );
		this.dirtyCount = 0;
		this.removedCount = this.previousCellCount;
		this.createdCount = 0;
		const v = builder.vertices;
		this.editStamp ++;
		for ( let t = 0; t < builder.used; t ++ ) {

			if ( v[ 4 * t ] === FREE ) continue;
			this.addSlot( t );
			this.createdCount ++;
			for ( let i = 0; i < 4; i ++ ) if ( v[ 4 * t + i ] !== INF ) this.vertexCell[ v[ 4 * t + i ] ] = t;

		}

		return this.endEdit( true );

	}

	// --- Dense numbering ---------------------------------------------------------------------

	private beginEdit(): void {

		this.editStamp ++;
		this.dirtyCount = 0;
		this.removedCount = 0;
		this.createdCount = 0;
		this.previousCellCount = this._cellCount;

	}

	private markDirty( slot: number ): void {

		if ( this.slotStamp[ slot ] === this.editStamp ) return;
		this.slotStamp[ slot ] = this.editStamp;
		if ( this.dirtyCount === this.dirty.length ) this.dirty = growInt32( this.dirty, this.dirtyCount * 2 );
		this.dirty[ this.dirtyCount ++ ] = slot;

	}

	/** Takes a cell out of the dense numbering (before its slot is released), filling its id with the last one. */
	private dropSlot( slot: number ): void {

		const c = this.cellIndex[ slot ];
		if ( c >= 0 ) {

			const last = -- this._cellCount;
			const moved = this.cellSlot[ last ];
			if ( moved !== slot ) {

				this.cellSlot[ c ] = moved;
				this.cellIndex[ moved ] = c;
				this.markDirty( moved );

			}

		} else if ( c <= - 2 ) {

			const h = - c - 2;
			const last = -- this._hullFaceCount;
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
	private addSlot( slot: number ): void {

		if ( this.builder.isGhost( slot ) ) {

			const h = this._hullFaceCount ++;
			if ( h === this.hullSlot.length ) {

				this.hullSlot = growInt32( this.hullSlot, 2 * h );
				this._hullFaces = growUint32( this._hullFaces, 6 * h );
				this._hullFaceCells = growUint32( this._hullFaceCells, 2 * h );

			}

			this.hullSlot[ h ] = slot;
			this.cellIndex[ slot ] = - h - 2;

		} else {

			const c = this._cellCount ++;
			if ( c === this.cellSlot.length ) {

				this.cellSlot = growInt32( this.cellSlot, 2 * c );
				this._tetrahedra = growUint32( this._tetrahedra, 8 * c );
				this._neighbors = growInt32( this._neighbors, 8 * c );

			}

			this.cellSlot[ c ] = slot;
			this.cellIndex[ slot ] = c;

		}

		this.markDirty( slot );

	}

	/** Rewrites the dense arrays of every changed cell and its neighbours, and fills `lastEdit`. */
	private endEdit( rebuilt: boolean ): TetrahedralEdit {

		const v = this.builder.vertices, adj = this.builder.adjacency, index = this.cellIndex;
		const report = this.reportStamp, stamp = this.editStamp;
		if ( this.changedCells.length < this.dirtyCount ) this.changedCells = new Int32Array( 2 * this.dirtyCount );
		if ( this.changedHullFaces.length < 5 * this.dirtyCount ) this.changedHullFaces = new Int32Array( 10 * this.dirtyCount );
		let changed = 0, changedHull = 0;
		for ( let d = 0; d < this.dirtyCount; d ++ ) {

			const slot = this.dirty[ d ];
			if ( v[ 4 * slot ] === FREE || index[ slot ] === - 1 ) continue;
			this.writeSlot( slot );
			const c = index[ slot ];
			if ( c >= 0 ) this.changedCells[ changed ++ ] = c;
			else if ( report[ slot ] !== stamp ) { report[ slot ] = stamp; this.changedHullFaces[ changedHull ++ ] = - c - 2; }
			for ( let i = 0; i < 4; i ++ ) {

				const u = adj[ 4 * slot + i ] >> 2;
				this.writeSlot( u );
				const cu = index[ u ];
				if ( cu <= - 2 && report[ u ] !== stamp ) { report[ u ] = stamp; this.changedHullFaces[ changedHull ++ ] = - cu - 2; }

			}

		}

		this.lastEdit = {
			changedCells: this.changedCells.subarray( 0, changed ),
			changedHullFaces: this.changedHullFaces.subarray( 0, changedHull ),
			previousCellCount: this.previousCellCount,
			cellCount: this._cellCount,
			hullFaceCount: this._hullFaceCount,
			removedCellCount: this.removedCount,
			createdCellCount: this.createdCount,
			rebuilt,
		};
		return this.lastEdit;

	}

	/** Writes one live cell's dense entries from its slot. */
	private writeSlot( slot: number ): void {

		const v = this.builder.vertices, adj = this.builder.adjacency, index = this.cellIndex;
		const c = index[ slot ];
		if ( c >= 0 ) {

			for ( let i = 0; i < 4; i ++ ) {

				this._tetrahedra[ 4 * c + i ] = v[ 4 * slot + i ];
				const n = index[ adj[ 4 * slot + i ] >> 2 ];
				this._neighbors[ 4 * c + i ] = n >= 0 ? n : - 1;

			}

		} else if ( c <= - 2 ) {

			const h = - c - 2;
			let g = 0;
			while ( v[ 4 * slot + g ] !== INF ) g ++;
			const face = adj[ 4 * slot + g ], t = face >> 2, i = face & 3, k = 4 * t;
			// Counter-clockwise from outside: the face without vertex i of the positive tetrahedron t,
			// ordered so that vertex i is on its negative side (TetrahedralMesh's convention).
			let a: number, b: number, d: number;
			if ( i === 0 ) { a = v[ k + 1 ]; b = v[ k + 2 ]; d = v[ k + 3 ]; }
			else if ( i === 1 ) { a = v[ k ]; b = v[ k + 3 ]; d = v[ k + 2 ]; }
			else if ( i === 2 ) { a = v[ k ]; b = v[ k + 1 ]; d = v[ k + 3 ]; }
			else { a = v[ k ]; b = v[ k + 2 ]; d = v[ k + 1 ]; }
			this._hullFaces[ 3 * h ] = a; this._hullFaces[ 3 * h + 1 ] = b; this._hullFaces[ 3 * h + 2 ] = d;
			this._hullFaceCells[ h ] = index[ t ];

		}

	}

	// --- Storage -----------------------------------------------------------------------------

	private ensureSlotCapacity(): void {

		const capacity = this.builder.capacity;
		if ( this.cellIndex.length >= capacity ) return;
		const index = new Int32Array( capacity ).fill( - 1 );
		index.set( this.cellIndex );
		this.cellIndex = index;
		this.slotStamp = growInt32( this.slotStamp, capacity );
		this.reportStamp = growInt32( this.reportStamp, capacity );
		this.visit = growInt32( this.visit, capacity );

	}

	private ensurePointCapacity( count: number ): void {

		if ( 3 * count <= this.p.length ) return;
		const capacity = Math.max( 2 * count, 16 );
		const p = new Float64Array( 3 * capacity );
		p.set( this.p );
		this.p = p;
		this.builder.p = p;
		this.linkBuilder.p = p;
		const active = new Uint8Array( capacity );
		active.set( this.active );
		this.active = active;
		const cells = new Int32Array( capacity ).fill( - 1 );
		cells.set( this.vertexCell );
		this.vertexCell = cells;
		this.pointStamp = growInt32( this.pointStamp, capacity );

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

const _three = new Int32Array( 3 );

function assertCoordinates( where: string, x: number, y: number, z: number ): void {

	if ( Number.isFinite( x ) && Number.isFinite( y ) && Number.isFinite( z ) ) return;
	const [ name, value ] = ! Number.isFinite( x ) ? [ 'x', x ] : ! Number.isFinite( y ) ? [ 'y', y ] : [ 'z', z ];
	throw new RangeError( `${where}: ${name} is ${String( value )}; coordinates must be finite numbers.` );

}

/** Writes the three vertices of cell t other than slot j to `_three`. */
function otherThree( v: Int32Array, t: number, j: number ): void {

	const k = 4 * t;
	if ( j === 0 ) { _three[ 0 ] = v[ k + 1 ]; _three[ 1 ] = v[ k + 2 ]; _three[ 2 ] = v[ k + 3 ]; }
	else if ( j === 1 ) { _three[ 0 ] = v[ k ]; _three[ 1 ] = v[ k + 2 ]; _three[ 2 ] = v[ k + 3 ]; }
	else if ( j === 2 ) { _three[ 0 ] = v[ k ]; _three[ 1 ] = v[ k + 1 ]; _three[ 2 ] = v[ k + 3 ]; }
	else { _three[ 0 ] = v[ k ]; _three[ 1 ] = v[ k + 1 ]; _three[ 2 ] = v[ k + 2 ]; }

}

function sameTriangle( a: number, b: number, c: number, d: number, e: number, f: number ): boolean {

	return ( a === d || a === e || a === f ) && ( b === d || b === e || b === f ) && ( c === d || c === e || c === f );

}

/** Orientation of finite cell t with its vertex in slot k replaced by point w. */
function orientReplaced( p: Float64Array, v: Int32Array, t: number, k: number, w: number ): number {

	const o = 4 * t;
	const a = k === 0 ? w : v[ o ], b = k === 1 ? w : v[ o + 1 ], c = k === 2 ? w : v[ o + 2 ], d = k === 3 ? w : v[ o + 3 ];
	return orient( p, a, b, c, d );

}

/** Four points of `ids` spanning a volume, positively ordered (exact), or null when all are coplanar. */
function exactInitialTetrahedron( p: Float64Array, ids: Uint32Array ): [ number, number, number, number ] | null {

	if ( ids.length < 4 ) return null;
	const a = ids[ 0 ], b = ids[ 1 ];
	let c = - 1;
	for ( let i = 2; i < ids.length && c < 0; i ++ ) if ( coplanarOrient( p, a, b, ids[ i ] ) !== 0 ) c = ids[ i ];
	if ( c < 0 ) return null;
	for ( let i = 2; i < ids.length; i ++ ) {

		const d = ids[ i ];
		const o = orient( p, a, b, c, d );
		if ( o > 0 ) return [ a, b, c, d ];
		if ( o < 0 ) return [ a, c, b, d ];

	}

	return null;

}

function growUint32( array: Uint32Array, length: number ): Uint32Array<ArrayBuffer> {

	const grown = new Uint32Array( length );
	grown.set( array.subarray( 0, Math.min( array.length, length ) ) );
	return grown;

}
