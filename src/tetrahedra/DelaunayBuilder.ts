import { orient, inSphere, inSphereTieBreak, inCirclePerturbed, inSphereStaticBound, orientStaticBound } from './predicates.js';
import { growInt32 } from './growArrays.js';
import { scanForCell } from './scanForCell.js';

/** The vertex at infinity of ghost tetrahedra. */
export const INF = - 1;

/** Marks a released cell slot (in its first vertex). */
export const FREE = - 2;

/**
 * Ints per cell record in `DelaunayBuilder.cells`: the four vertices, then the four face links.
 * A link is the index of a face's entry in `cells` (`CELL · u + 4 + j`: face j of cell u), so the
 * entry a link points at links back, `link >> CELL_SHIFT` is the cell, `link & 3` the slot, and
 * `cells[ link − 4 ]` the vertex opposite the face.
 */
export const CELL = 8;

/** log2 of {@link CELL}. */
export const CELL_SHIFT = 3;

/** Negative when x ≠ 0, else 0. */
function nonZero( x: number ): number {

	return x | - x;

}

const _startCells = new Int32Array( 5 );
const _startVertices = new Int32Array( 4 );

/**
 * Incremental Delaunay state in flat typed arrays, the insertion core shared by `tetrahedralize`
 * and `DynamicTetrahedralization` (internal: not exported from the package; docs/incremental-delaunay.md).
 *
 * Cell t is the record `cells[8t..8t+7]`: vertices `cells[8t+i]` (INF for the vertex at infinity)
 * and face links `cells[8t+4+i] = 8u + 4 + j`: the face opposite vertex i of t is the face opposite
 * vertex j of u ({@link CELL}). One record per cell keeps a cell's vertices and neighbours in one
 * cache line. A ghost tetrahedron replaces one vertex of a hull face's outside by INF, ordered so
 * that putting any point beyond that face in INF's slot gives a positive tetrahedron; that makes
 * "replace the opposite vertex by the new point" valid for ghosts too.
 *
 * `cells` is reallocated when the slot capacity grows (in `allocate` / `reserve`): re-read it after
 * any call that may create cells.
 */
export class DelaunayBuilder {

	/** Flat x, y, z of every point the cells may refer to (shared with the owner, who may replace it). */
	p: Float64Array;
	/** A length of the order of the point set's extent, for the coplanar in-circle test. */
	extent: number;
	/** One record of {@link CELL} ints per cell slot (see the class comment); `cells[8t] === FREE` for a released slot. */
	cells: Int32Array;
	/** Number of slots in use or released (slots ≥ used were never allocated). */
	used = 0;
	/** Slot capacity of `cells`. */
	capacity: number;
	/** The cell the next point-location walk starts from. */
	last = 0;
	/** Static error bounds of the predicates in the walk and the conflict tests (see `limitPoints`). */
	orientBound = Infinity;
	sphereBound = Infinity;

	/** Cells of the last conflict region (`findConflicts`), `cavitySize` of them. */
	cavity = new Int32Array( 256 );
	cavitySize = 0;
	/** Boundary faces of the last conflict region as links `8t + 4 + i` (t in the cavity), `boundarySize` of them. */
	boundary = new Int32Array( 256 );
	boundarySize = 0;
	/** Cells created by the last `fillConflicts`, one per boundary face (`boundarySize` of them). */
	created = new Int32Array( 256 );

	private mark: Int32Array;
	private freeList: Int32Array;
	private freeCount = 0;
	private stamp = 0;
	// The walk's xorshift state, in a typed array: as a plain field it would start as a small
	// integer and turn into a double on the first step, changing the instances' hidden class.
	private random = Int32Array.of( 0x2545F491 );

	// Per-insertion scratch, grown on demand.
	private stack = new Int32Array( 256 );
	private edgeTable = new Int32Array( 4 * 256 );

	constructor( p: Float64Array, pointCount: number, diagonal: number ) {

		this.p = p;
		this.extent = diagonal;
		this.capacity = Math.max( 64, Math.ceil( pointCount * 7.5 ) );
		this.cells = new Int32Array( CELL * this.capacity );
		this.mark = new Int32Array( this.capacity );
		this.freeList = new Int32Array( 64 );

	}

	/**
	 * Promises that every point the builder will see lies in a box of diagonal `extent`, so that the
	 * walk and the conflict tests may decide most signs with a static error bound (predicates.ts);
	 * Infinity withdraws the promise (before points beyond that box may come, e.g. edits).
	 */
	limitPoints( extent: number ): void {

		this.orientBound = extent === Infinity ? Infinity : orientStaticBound( extent );
		this.sphereBound = extent === Infinity ? Infinity : inSphereStaticBound( extent );

	}

	/** Forgets every cell (keeps the storage), for building another triangulation in it. */
	reset(): void {

		this.used = 0;
		this.freeCount = 0;
		this.last = 0;

	}

	/** Creates the first tetrahedron abcd (positively oriented) and its four ghosts. */
	start( [ a, b, c, d ]: [ number, number, number, number ] ): void {

		const t = this.allocate();
		this.setVertices( t, a, b, c, d );

		// Ghost opposite vertex k: the tetrahedron with vertex k replaced by INF has the new point
		// on the wrong side, so swap two of the remaining slots to flip the orientation.
		const cells = _startCells, v = _startVertices;
		cells[ 0 ] = t;
		for ( let k = 0; k < 4; k ++ ) {

			const g = this.allocate();
			v[ 0 ] = a; v[ 1 ] = b; v[ 2 ] = c; v[ 3 ] = d;
			v[ k ] = INF;
			const i = ( k + 1 ) & 3, j = ( k + 2 ) & 3;
			const s = v[ i ]; v[ i ] = v[ j ]; v[ j ] = s;
			this.setVertices( g, v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ] );
			cells[ k + 1 ] = g;

		}

		// Five cells, linked by comparing their faces; done once per triangulation, so brute force is fine.
		const record = this.cells;
		for ( let x = 0; x < 5; x ++ ) {

			const u = cells[ x ];
			for ( let i = 0; i < 4; i ++ ) {

				for ( let y = 0; y < 5; y ++ ) {

					const w = cells[ y ];
					if ( w === u ) continue;
					for ( let j = 0; j < 4; j ++ ) {

						if ( this.sameFace( u, i, w, j ) ) record[ CELL * u + 4 + i ] = CELL * w + 4 + j;

					}

				}

			}

		}

		this.last = t;

	}

	private sameFace( u: number, i: number, w: number, j: number ): boolean {

		// Vertices within a cell are distinct, so two triples are equal when each of one is in the other.
		const v = this.cells;
		for ( let k = 0; k < 4; k ++ ) {

			if ( k === i ) continue;
			const x = v[ CELL * u + k ];
			let found = false;
			for ( let m = 0; m < 4; m ++ ) if ( m !== j && v[ CELL * w + m ] === x ) found = true;
			if ( ! found ) return false;

		}

		return true;

	}

	private setVertices( t: number, a: number, b: number, c: number, d: number ): void {

		const v = this.cells, k = CELL * t;
		v[ k ] = a; v[ k + 1 ] = b; v[ k + 2 ] = c; v[ k + 3 ] = d;

	}

	/** A free cell slot (reusing released ones first); may reallocate the arrays. */
	allocate(): number {

		if ( this.freeCount > 0 ) return this.freeList[ -- this.freeCount ];
		if ( this.used === this.capacity ) this.grow();
		return this.used ++;

	}

	/** Returns slot t to the free list and marks it FREE. */
	release( t: number ): void {

		if ( this.freeCount === this.freeList.length ) this.freeList = growInt32( this.freeList, this.freeList.length * 2 );
		this.freeList[ this.freeCount ++ ] = t;
		this.cells[ CELL * t ] = FREE;

	}

	private grow(): void {

		const capacity = this.capacity * 2;
		this.cells = growInt32( this.cells, CELL * capacity );
		this.mark = growInt32( this.mark, capacity );
		this.capacity = capacity;

	}

	/** True when slot t is a ghost cell (one vertex is INF). */
	isGhost( t: number ): boolean {

		const v = this.cells, k = CELL * t;
		return v[ k ] === INF || v[ k + 1 ] === INF || v[ k + 2 ] === INF || v[ k + 3 ] === INF;

	}

	/**
	 * Visibility walk to a cell whose closure contains q (finite) or a ghost whose hull face q is
	 * strictly beyond. Stochastic face order rules out cycles (Devillers, Pion & Teillaud 2002), and
	 * in a Delaunay tetrahedralization no walk visits a cell twice; past `used` steps (impossible with
	 * exact predicates) a scan of every cell answers instead.
	 */
	locate( q: number ): number {

		const v = this.cells, p = this.p, random = this.random, bound = this.orientBound;
		let t = this.last;
		if ( t >= this.used || v[ CELL * t ] === FREE ) t = 0;
		while ( v[ CELL * t ] === FREE ) t ++;
		if ( this.isGhost( t ) ) {

			for ( let i = 0; i < 4; i ++ ) if ( v[ CELL * t + i ] === INF ) t = v[ CELL * t + 4 + i ] >> CELL_SHIFT;

		}

		let previous = - 1;
		walk: for ( let steps = this.used; steps >= 0; steps -- ) {

			let r = random[ 0 ];
			r ^= r << 13; r ^= r >>> 17; r ^= r << 5;
			random[ 0 ] = r;
			const offset = r & 3;
			const k = CELL * t;
			const a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
			for ( let s = 0; s < 4; s ++ ) {

				const i = ( offset + s ) & 3;
				const next = v[ k + 4 + i ] >> CELL_SHIFT;
				if ( next === previous ) continue;
				let o: number;
				if ( i === 0 ) o = orient( p, q, b, c, d, bound );
				else if ( i === 1 ) o = orient( p, a, q, c, d, bound );
				else if ( i === 2 ) o = orient( p, a, b, q, d, bound );
				else o = orient( p, a, b, c, q, bound );
				if ( o < 0 ) {

					previous = t;
					t = next;
					if ( this.isGhost( t ) ) return t;
					continue walk;

				}

			}

			return t;

		}

		return scanForCell( this.p, this.cells, this.used, q );

	}

	private inConflict( t: number, q: number ): boolean {

		const v = this.cells, p = this.p, k = CELL * t;
		const a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
		if ( a !== INF && b !== INF && c !== INF && d !== INF ) {

			const s = inSphere( p, a, b, c, d, q, this.sphereBound );
			if ( s !== 0 ) return s > 0;
			return inSphereTieBreak( p, a, b, c, d, q ) > 0;

		}

		// Ghost: in conflict when q is strictly beyond the hull face, or on its plane and inside
		// the face's perturbed circumcircle.
		let o: number, f0: number, f1: number, f2: number;
		if ( a === INF ) {

			o = orient( p, q, b, c, d, this.orientBound );
			f0 = b;
			f1 = c;
			f2 = d;

		} else if ( b === INF ) {

			o = orient( p, a, q, c, d, this.orientBound );
			f0 = a;
			f1 = c;
			f2 = d;

		} else if ( c === INF ) {

			o = orient( p, a, b, q, d, this.orientBound );
			f0 = a;
			f1 = b;
			f2 = d;

		} else {

			o = orient( p, a, b, c, q, this.orientBound );
			f0 = a;
			f1 = b;
			f2 = c;

		}

		if ( o !== 0 ) return o > 0;
		return inCirclePerturbed( p, f0, f1, f2, q, this.extent ) > 0;

	}

	/** Inserts point q: `findConflicts` then `fillConflicts`. */
	insert( q: number ): void {

		this.findConflicts( q, this.locate( q ) );
		this.fillConflicts( q );

	}

	/**
	 * Floods the conflict region of q from the cell `start` (which must be in conflict, e.g. from
	 * `locate`) into `cavity` and its boundary faces into `boundary`. Changes no cell.
	 */
	findConflicts( q: number, start: number ): void {

		const mark = this.mark;
		const inStamp = ( this.stamp += 2 );
		const outStamp = inStamp + 1;

		// Flood the conflict region (connected, star-shaped from q) and collect its boundary faces.
		// The scratch arrays live in locals (written back when grown) to keep the loop free of
		// property loads; finite cells call inSphere directly, ghosts go through inConflict.
		const v = this.cells, p = this.p, sphereBound = this.sphereBound;
		let stack = this.stack, cavity = this.cavity, boundary = this.boundary;
		let stackSize = 0, cavitySize = 0, boundarySize = 0;
		mark[ start ] = inStamp;
		stack[ stackSize ++ ] = start;
		while ( stackSize > 0 ) {

			const t = stack[ -- stackSize ];
			if ( cavitySize === cavity.length ) this.cavity = cavity = growInt32( cavity, cavitySize * 2 );
			cavity[ cavitySize ++ ] = t;
			const faces = CELL * t + 4;
			for ( let i = 0; i < 4; i ++ ) {

				const u = v[ faces + i ] >> CELL_SHIFT;
				const m = mark[ u ];
				if ( m === inStamp ) continue;
				let conflict = false;
				if ( m !== outStamp ) {

					const k = CELL * u;
					const a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
					if ( a !== INF && b !== INF && c !== INF && d !== INF ) {

						const s = inSphere( p, a, b, c, d, q, sphereBound );
						conflict = s !== 0 ? s > 0 : inSphereTieBreak( p, a, b, c, d, q ) > 0;

					} else {

						conflict = this.inConflict( u, q );

					}

				}

				if ( conflict ) {

					mark[ u ] = inStamp;
					if ( stackSize === stack.length ) this.stack = stack = growInt32( stack, stackSize * 2 );
					stack[ stackSize ++ ] = u;

				} else {

					mark[ u ] = outStamp;
					if ( boundarySize === boundary.length ) this.boundary = boundary = growInt32( boundary, boundarySize * 2 );
					boundary[ boundarySize ++ ] = faces + i;

				}

			}

		}

		this.cavitySize = cavitySize;
		this.boundarySize = boundarySize;

	}

	/**
	 * Replaces the conflict region found by the last `findConflicts( q )` by the cells joining q
	 * to its boundary faces (listed in `created`); the region's cells are released.
	 */
	fillConflicts( q: number ): void {

		const boundarySize = this.boundarySize, cavitySize = this.cavitySize;

		// One new cell per boundary face: the conflict cell with its vertex opposite that face
		// replaced by q, which keeps the orientation (q sees the face from the same side).
		this.reserve( boundarySize );
		const v = this.cells;
		if ( this.created.length < boundarySize ) this.created = new Int32Array( boundarySize * 2 );
		const created = this.created, boundary = this.boundary;
		// 1.5 entries per boundary face (half of the 3 lookups insert) in at least 8 slots per face,
		// in a power-of-two prefix of the scratch array so that it stays small in the cache.
		let size = 64;
		while ( size < boundarySize * 8 ) size *= 2;
		const table = this.prepareEdgeTable( size );
		const shift = Math.clz32( size - 1 ), mask = 4 * size - 1;
		const edgeStamp = ++ this.stamp;
		// Slots as `allocate` hands them out (free list first, LIFO), inlined: `reserve` made room.
		const freeList = this.freeList;
		let freeCount = this.freeCount, used = this.used;
		for ( let f = 0; f < boundarySize; f ++ ) {

			const face = boundary[ f ];
			const i = face & 3, t8 = face - 4 - i;
			const outside = v[ face ];
			const n = freeCount > 0 ? freeList[ -- freeCount ] : used ++;
			const k = CELL * n;
			v[ k ] = v[ t8 ]; v[ k + 1 ] = v[ t8 + 1 ]; v[ k + 2 ] = v[ t8 + 2 ]; v[ k + 3 ] = v[ t8 + 3 ];
			v[ k + i ] = q;
			v[ k + 4 + i ] = outside;
			v[ outside ] = k + 4 + i;
			created[ f ] = n;

			// The three faces through q are shared with other new cells; pair them by the edge they
			// have besides q, in a hash table of 4 ints per entry (stamp, edge start, edge end, face
			// link) with a hash symmetric in the ends. With x1, x2, x3 the vertices in slots i + 1,
			// i + 2, i + 3 (mod 4), the face opposite slot i + r has the edge (x2, x3), (x3, x1),
			// (x1, x2) for r = 1, 2, 3 oriented as the face seen with q first (reversed for odd i: a
			// rotation of the slots by an odd i is an odd permutation); the cell across the face names
			// the same edge in the opposite direction, which is what is looked up.
			let x1 = v[ k + ( ( i + 1 ) & 3 ) ], x2 = v[ k + ( ( i + 2 ) & 3 ) ], x3 = v[ k + ( ( i + 3 ) & 3 ) ];
			const odd = ( i << 31 ) >> 31; // −1 for odd i, else 0
			for ( let r = 1; r <= 3; r ++ ) {

				const link = k + 4 + ( ( i + r ) & 3 );
				const from = x2 ^ ( ( x2 ^ x3 ) & odd ), to = x2 ^ x3 ^ from;
				const rest = x1; x1 = x2; x2 = x3; x3 = rest;
				let e = ( ( Math.imul( from, - 1640531535 ) ^ Math.imul( to, - 1640531535 ) ) >>> shift ) << 2;
				// Step past entries of this insertion that hold another edge: "taken and not the reversed
				// edge" as one sign test (stamps are positive, so the stamp difference is 0 only when taken).
				while ( ( ( ( table[ e ] ^ edgeStamp ) - 1 ) & nonZero( ( table[ e + 1 ] ^ to ) | ( table[ e + 2 ] ^ from ) ) ) < 0 ) {

					e = ( e + 4 ) & mask;

				}

				// Whether the entry holds the face across (found: −1) or is free (0) is as good as random,
				// so both cases run the same stores: link the two faces, or link this face to itself for
				// now (the face across overwrites it). The entry is (over)written either way: a matched
				// entry is never looked up again (each directed edge occurs once) and stays taken.
				const found = ( ( table[ e ] ^ edgeStamp ) - 1 ) >> 31;
				const across = link ^ ( ( table[ e + 3 ] ^ link ) & found );
				v[ link ] = across;
				v[ across ] = link;
				table[ e ] = edgeStamp;
				table[ e + 1 ] = from;
				table[ e + 2 ] = to;
				table[ e + 3 ] = link;

			}

		}

		this.used = used;

		// Release the region's cells (as `release` does, in the same order).
		this.freeCount = freeCount;
		if ( freeCount + cavitySize > this.freeList.length ) {

			let length = this.freeList.length;
			while ( length < freeCount + cavitySize ) length *= 2;
			this.freeList = growInt32( this.freeList, length );

		}

		const list = this.freeList, cavity = this.cavity;
		for ( let c = 0; c < cavitySize; c ++ ) {

			const t = cavity[ c ];
			list[ freeCount ++ ] = t;
			v[ CELL * t ] = FREE;

		}

		this.freeCount = freeCount;
		this.last = created[ boundarySize - 1 ];

	}

	/**
	 * Replaces every finite vertex v of the cells by `ids[ v ]` and the points by `p` (which must hold
	 * point `ids[ v ]` where the old points held v): for a triangulation built on renumbered points.
	 */
	renumber( ids: Uint32Array, p: Float64Array ): void {

		const v = this.cells;
		for ( let k = 0, end = CELL * this.used; k < end; k += CELL ) {

			for ( let i = k; i < k + 4; i ++ ) {

				const w = v[ i ];
				if ( w >= 0 ) v[ i ] = ids[ w ];

			}

		}

		this.p = p;

	}

	/** Makes room for `count` more cells so that arrays stay put while new cells are linked. */
	reserve( count: number ): void {

		while ( this.used + Math.max( 0, count - this.freeCount ) > this.capacity ) this.grow();

	}

	/** The edge table with room for `size` entries of 4 ints (grown as needed, stamps kept). */
	private prepareEdgeTable( size: number ): Int32Array {

		if ( this.edgeTable.length < 4 * size ) this.edgeTable = new Int32Array( 4 * size );
		return this.edgeTable;

	}

	/**
	 * Drops the storage of a builder that is done (its cells copied out) and keeps the empty instance
	 * alive, so that V8 keeps the builder's optimized code (why: docs/incremental-delaunay.md).
	 */
	retire(): void {

		const empty = new Int32Array( 0 );
		this.p = new Float64Array( 0 );
		this.cells = this.mark = this.freeList = empty;
		this.cavity = this.boundary = this.created = this.stack = empty;
		this.edgeTable = empty;
		this.used = this.capacity = this.freeCount = this.cavitySize = this.boundarySize = this.last = 0;
		shapeKeeper = this;

	}

}

// See DelaunayBuilder.retire.
let shapeKeeper: DelaunayBuilder | null = null;
