import { coplanarOrient, orient } from './predicates.js';
import { CELL, CELL_SHIFT, DelaunayBuilder, FREE, INF } from './DelaunayBuilder.js';
import type { DenseCells } from './DenseCells.js';
import { FaceTable } from './FaceTable.js';
import { growInt32, growUint32 } from './growArrays.js';
import { findInitialTetrahedron } from './initialTetrahedron.js';

const CALLER = 'DynamicTetrahedralization';

/**
 * Removal of one vertex from a {@link DelaunayBuilder}'s Delaunay tetrahedralization, for
 * {@link DynamicTetrahedralization} (which owns one instance, with its scratch buffers): the
 * Delaunay tetrahedralization of the vertex's link, built with the same perturbation, fills its
 * star's hole exactly; a hull vertex with a flat link leaves only hull faces behind. How and why:
 * docs/incremental-delaunay.md. Internal to src/tetrahedra.
 */
export class VertexRemoval {

	private diagonal: number;
	private readonly planarTolerance: number;
	private readonly linkBuilder: DelaunayBuilder;
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
	private stamp = 0;

	/**
	 * @param p Point coordinates (the link's triangulation is pointed at the current ones on each removal).
	 * @param pointCapacity Point slots to allocate scratch for (see `ensurePointCapacity`).
	 * @param diagonal The point set's extent (for the coplanar tests and the link's triangulation).
	 * @param planarTolerance Relative tolerance of the coplanar check on a removal that leaves only the link.
	 */
	constructor( p: Float64Array, pointCapacity: number, diagonal: number, planarTolerance: number ) {

		this.diagonal = diagonal;
		this.planarTolerance = planarTolerance;
		this.pointStamp = new Int32Array( pointCapacity );
		this.linkBuilder = new DelaunayBuilder( p, 64, diagonal );

	}

	/** Sets the point set's extent (after the owner normalised its points anew). */
	setDiagonal( diagonal: number ): void {

		this.diagonal = diagonal;
		this.linkBuilder.extent = diagonal;

	}

	/** Grows the per-point scratch to `capacity` points (when the owner's point arrays grow). */
	ensurePointCapacity( capacity: number, p: Float64Array ): void {

		this.linkBuilder.p = p;
		this.pointStamp = growInt32( this.pointStamp, capacity );

	}

	/**
	 * Removes vertex `index` (active, with `vertexCell[ index ]` a cell of its star) from `builder`:
	 * checks and computes the filling cells, then opens an edit in `cells` and replaces the star
	 * (the edit is left open; `vertexCell` is updated, `vertexCell[ index ]` set to −1).
	 * @throws {DegenerateInputError} when only coplanar points would remain; nothing changes then.
	 */
	remove( where: string, index: number, builder: DelaunayBuilder, p: Float64Array, vertexCell: Int32Array, cells: DenseCells ): void {

		const starCount = this.collectStar( index, builder, vertexCell );
		const link = this.link.subarray( 0, this.linkCount );

		// Every remaining tetrahedron touches `index`: the others are all in its link, and must span a volume.
		if ( this.finiteStarCount === cells.cellCount ) findInitialTetrahedron( where, p, link, this.diagonal, this.planarTolerance );

		const fillCount = this.computeFill( index, starCount, builder, p );

		// Commit: release the star, create the filling cells, link them.
		cells.beginEdit();
		for ( let s = 0; s < starCount; s ++ ) {

			cells.dropSlot( this.star[ s ] );
			builder.release( this.star[ s ] );

		}

		builder.reserve( fillCount );
		cells.ensureSlotCapacity();
		if ( this.fillSlots.length < fillCount ) this.fillSlots = new Int32Array( 2 * fillCount );
		const v = builder.cells, fill = this.fill, links = this.fillLinks, slots = this.fillSlots;
		for ( let n = 0; n < fillCount; n ++ ) {

			const t = builder.allocate();
			slots[ n ] = t;
			for ( let i = 0; i < 4; i ++ ) v[ CELL * t + i ] = fill[ 4 * n + i ];

		}

		let lastFinite = slots[ 0 ];
		for ( let n = 0; n < fillCount; n ++ ) {

			const t = slots[ n ];
			for ( let j = 0; j < 4; j ++ ) {

				const l = links[ 4 * n + j ];
				if ( l >= 0 ) {

					v[ CELL * t + 4 + j ] = CELL * slots[ l >> 2 ] + 4 + ( l & 3 );

				} else {

					const h = this.boundaryHandle[ - l - 1 ];
					v[ CELL * t + 4 + j ] = h;
					v[ h ] = CELL * t + 4 + j;

				}

				const w = v[ CELL * t + j ];
				if ( w !== INF ) vertexCell[ w ] = t;

			}

			cells.addSlot( t );
			if ( ! builder.isGhost( t ) ) lastFinite = t;

		}

		builder.last = lastFinite;
		cells.removedCount += starCount;
		cells.createdCount += fillCount;
		vertexCell[ index ] = - 1;

	}

	/**
	 * Collects the star of vertex `index`: cells into `star` (returned count), its faces opposite
	 * `index` into `boundaryHandle` (the outside cell's side, a link `8u + 4 + j`) and `boundaryFaces`, the
	 * other finite vertices into `link` (count in `linkCount`); counts its tetrahedra in `finiteStarCount`.
	 */
	private collectStar( index: number, builder: DelaunayBuilder, vertexCell: Int32Array ): number {

		const v = builder.cells;
		if ( this.visit.length < builder.capacity ) this.visit = growInt32( this.visit, builder.capacity );
		const visit = this.visit, stamp = ++ this.stamp;
		let count = 0;
		const first = vertexCell[ index ];
		visit[ first ] = stamp;
		this.star[ count ++ ] = first;
		for ( let head = 0; head < count; head ++ ) {

			const t = this.star[ head ];
			for ( let j = 0; j < 4; j ++ ) {

				// Faces through `index` lead to the rest of the star.
				if ( v[ CELL * t + j ] === index ) continue;
				const u = v[ CELL * t + 4 + j ] >> CELL_SHIFT;
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

				const w = v[ CELL * t + j ];
				if ( w === index ) { k = j; continue; }
				if ( w === INF ) { ghost = true; continue; }
				if ( pointStamp[ w ] !== stamp ) {

					pointStamp[ w ] = stamp;
					if ( linkCount === this.link.length ) this.link = growUint32( this.link, linkCount * 2 );
					this.link[ linkCount ++ ] = w;

				}

			}

			if ( ! ghost ) finite ++;
			this.boundaryHandle[ b ] = v[ CELL * t + 4 + k ];
			this.boundaryHits[ b ] = 0;
			otherThree( v, CELL * t, k );
			this.boundaryFaces.set( _three[ 0 ], _three[ 1 ], _three[ 2 ], b );

		}

		this.linkCount = linkCount;
		this.finiteStarCount = finite;
		return count;

	}

	/**
	 * The cells that fill the star's hole once `index` is gone, into `fill` (4 vertices each) and
	 * their face links into `fillLinks` (`4m + j` for a face shared with filling cell m, −(b + 1)
	 * for star boundary face b). Changes nothing in the mesh; throws if the filling does not close.
	 */
	private computeFill( index: number, starCount: number, builder: DelaunayBuilder, p: Float64Array ): number {

		const v = builder.cells;
		const link = this.link.subarray( 0, this.linkCount );
		let fillCount = 0;

		const initial = exactInitialTetrahedron( p, link );
		if ( initial === null ) {

			// A flat link: `index` is a hull vertex over a planar patch, which becomes hull faces.
			for ( let s = 0; s < starCount; s ++ ) {

				const t = this.star[ s ];
				if ( builder.isGhost( t ) ) continue;
				this.ensureFill( fillCount + 1 );
				for ( let i = 0; i < 4; i ++ ) {

					const w = v[ CELL * t + i ];
					this.fill[ 4 * fillCount + i ] = w === index ? INF : w;

				}

				fillCount ++;

			}

		} else {

			fillCount = this.linkTriangulationInsideHole( index, initial, link, builder, p );

		}

		// Link the filling cells to each other and to the hole's boundary.
		const fill = this.fill, links = this.fillLinks, inner = this.innerFaces, boundary = this.boundaryFaces;
		inner.clear( 4 * fillCount );
		for ( let n = 0; n < fillCount; n ++ ) {

			for ( let j = 0; j < 4; j ++ ) {

				otherThree( fill, 4 * n, j );
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
	private linkTriangulationInsideHole(
		index: number, initial: [ number, number, number, number ], link: Uint32Array, builder: DelaunayBuilder, p: Float64Array,
	): number {

		const small = this.linkBuilder;
		small.p = p;
		small.reset();
		small.start( initial );
		for ( let i = 0; i < link.length; i ++ ) {

			const w = link[ i ];
			if ( w !== initial[ 0 ] && w !== initial[ 1 ] && w !== initial[ 2 ] && w !== initial[ 3 ] ) small.insert( w );

		}

		// A hole face behind a tetrahedron of the star: find it in the small triangulation and
		// take the cell on the side where `index` was.
		const v = builder.cells, sv = small.cells;
		let s = 0, k = 0;
		for ( ; ; s ++ ) {

			const t = this.star[ s ];
			if ( ! builder.isGhost( t ) ) {

				while ( v[ CELL * t + k ] !== index ) k ++;
				break;

			}

		}

		const t = this.star[ s ];
		otherThree( v, CELL * t, k );
		const f0 = _three[ 0 ], f1 = _three[ 1 ], f2 = _three[ 2 ];
		let start = - 1;
		search: for ( let u = 0; u < small.used; u ++ ) {

			if ( sv[ CELL * u ] === FREE ) continue;
			for ( let j = 0; j < 4; j ++ ) {

				otherThree( sv, CELL * u, j );
				const a = _three[ 0 ], b = _three[ 1 ], c = _three[ 2 ];
				if ( ! sameTriangle( a, b, c, f0, f1, f2 ) ) continue;
				const apex = sv[ CELL * u + j ];
				if ( apex !== INF ) {

					// Same side as `index` ⇔ the star cell stays positive with `index` replaced by apex.
					start = orientReplaced( p, v, t, k, apex ) > 0 ? u : sv[ CELL * u + 4 + j ] >> CELL_SHIFT;

				} else {

					// A ghost: decide by the finite cell behind the face (its vertex opposite the face).
					const behind = sv[ CELL * u + 4 + j ];
					start = orientReplaced( p, v, t, k, sv[ behind - 4 ] ) > 0 ? behind >> CELL_SHIFT : u;

				}

				break search;

			}

		}

		if ( start < 0 ) {

			throw new Error( `${CALLER}.remove: internal error, a face of the hole of point ${index} is missing from its link's triangulation; the mesh is unchanged.` );

		}

		// Flood inside the hole, never crossing one of its boundary faces.
		if ( this.visit.length < small.used ) this.visit = growInt32( this.visit, small.capacity );
		const visit = this.visit, stamp = ++ this.stamp;
		let stack = this.fillSlots, top = 0, fillCount = 0;
		visit[ start ] = stamp;
		stack[ top ++ ] = start;
		while ( top > 0 ) {

			const u = stack[ -- top ];
			this.ensureFill( fillCount + 1 );
			for ( let i = 0; i < 4; i ++ ) this.fill[ 4 * fillCount + i ] = sv[ CELL * u + i ];
			fillCount ++;
			for ( let j = 0; j < 4; j ++ ) {

				otherThree( sv, CELL * u, j );
				const a = _three[ 0 ], b = _three[ 1 ], c = _three[ 2 ];
				if ( this.boundaryFaces.get( a, b, c ) >= 0 ) continue;
				const w = sv[ CELL * u + 4 + j ] >> CELL_SHIFT;
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

}

const _three = new Int32Array( 3 );

/** Writes the three vertices other than slot j of the cell whose four vertices start at v[ k ] to `_three`. */
function otherThree( v: Int32Array, k: number, j: number ): void {

	if ( j === 0 ) {

		_three[ 0 ] = v[ k + 1 ];
		_three[ 1 ] = v[ k + 2 ];
		_three[ 2 ] = v[ k + 3 ];

	} else if ( j === 1 ) {

		_three[ 0 ] = v[ k ];
		_three[ 1 ] = v[ k + 2 ];
		_three[ 2 ] = v[ k + 3 ];

	} else if ( j === 2 ) {

		_three[ 0 ] = v[ k ];
		_three[ 1 ] = v[ k + 1 ];
		_three[ 2 ] = v[ k + 3 ];

	} else {

		_three[ 0 ] = v[ k ];
		_three[ 1 ] = v[ k + 1 ];
		_three[ 2 ] = v[ k + 2 ];

	}

}

function sameTriangle( a: number, b: number, c: number, d: number, e: number, f: number ): boolean {

	return ( a === d || a === e || a === f ) && ( b === d || b === e || b === f ) && ( c === d || c === e || c === f );

}

/** Orientation of finite cell t with its vertex in slot k replaced by point w. */
function orientReplaced( p: Float64Array, v: Int32Array, t: number, k: number, w: number ): number {

	const o = CELL * t;
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
