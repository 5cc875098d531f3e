import { orient, inSphere, inSphereTieBreak, inCirclePerturbed } from './predicates.js';
import { growInt32 } from './growArrays.js';
import { scanForCell } from './scanForCell.js';

/** The vertex at infinity of ghost tetrahedra. */
export const INF = - 1;

/** Marks a released cell slot (in its first vertex). */
export const FREE = - 2;

// FACE_EDGES[9i + 3r .. 9i + 3r + 2] = j, s1, s2 for the r-th slot j ≠ i: the face opposite j of a
// positive tetrahedron, oriented so that vertex j is on its positive side, read as the cycle
// (slot i, s1, s2). The neighbour across that face sees the same triangle in the opposite cycle, so
// with i holding the new point both name the edge they share besides it, in opposite directions.
const FACE_EDGES = new Int8Array( 36 );
for ( let i = 0; i < 4; i ++ ) {

	let r = 0;
	for ( let j = 0; j < 4; j ++ ) {

		if ( j === i ) continue;
		const [ a, b, c ] = [ 0, 1, 2, 3 ].filter( ( m ) => m !== j );
		// ( a, b, c, j ) is an even permutation of ( 0, 1, 2, 3 ) exactly when j is odd.
		const cycle = j % 2 === 1 ? [ a, b, c ] : [ a, c, b ];
		const at = cycle.indexOf( i );
		FACE_EDGES[ 9 * i + 3 * r ] = j;
		FACE_EDGES[ 9 * i + 3 * r + 1 ] = cycle[ ( at + 1 ) % 3 ];
		FACE_EDGES[ 9 * i + 3 * r + 2 ] = cycle[ ( at + 2 ) % 3 ];
		r ++;

	}

}

// Multiplier of the edge hash (Knuth's multiplicative hashing; the high bits are kept).
const EDGE_HASH = 0x9E3779B1;

const _startCells = new Int32Array( 5 );
const _startVertices = new Int32Array( 4 );

/**
 * Incremental Delaunay state in flat typed arrays, the insertion core shared by `tetrahedralize`
 * and `DynamicTetrahedralization` (internal: not exported from the package; docs/incremental-delaunay.md).
 *
 * Tetrahedron t has vertices `vertices[4t..4t+3]` (INF for the vertex at infinity) and
 * `adjacency[4t+i] = 4u + j`: the face opposite vertex i of t is the face opposite vertex j of u.
 * A ghost tetrahedron replaces one vertex of a hull face's outside by INF, ordered so that putting
 * any point beyond that face in INF's slot gives a positive tetrahedron; that makes "replace the
 * opposite vertex by the new point" valid for ghosts too.
 *
 * `vertices` and `adjacency` are reallocated when the slot capacity grows (in `allocate` /
 * `reserve`): re-read them after any call that may create cells.
 */
export class DelaunayBuilder {

	/** Flat x, y, z of every point the cells may refer to (shared with the owner, who may replace it). */
	p: Float64Array;
	/** A length of the order of the point set's extent, for the coplanar in-circle test. */
	extent: number;
	/** Four vertices per cell slot; `vertices[4t] === FREE` for a released slot. */
	vertices: Int32Array;
	/** Face links per cell slot, `4u + j` (see the class comment). */
	adjacency: Int32Array;
	/** Number of slots in use or released (slots ≥ used were never allocated). */
	used = 0;
	/** Slot capacity of `vertices` / `adjacency`. */
	capacity: number;
	/** The cell the next point-location walk starts from. */
	last = 0;

	/** Cells of the last conflict region (`findConflicts`), `cavitySize` of them. */
	cavity = new Int32Array( 256 );
	cavitySize = 0;
	/** Boundary faces of the last conflict region as `4t + i` (t in the cavity), `boundarySize` of them. */
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
		this.vertices = new Int32Array( 4 * this.capacity );
		this.adjacency = new Int32Array( 4 * this.capacity );
		this.mark = new Int32Array( this.capacity );
		this.freeList = new Int32Array( 64 );

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
		for ( let x = 0; x < 5; x ++ ) {

			const u = cells[ x ];
			for ( let i = 0; i < 4; i ++ ) {

				for ( let y = 0; y < 5; y ++ ) {

					const w = cells[ y ];
					if ( w === u ) continue;
					for ( let j = 0; j < 4; j ++ ) {

						if ( this.sameFace( u, i, w, j ) ) this.adjacency[ 4 * u + i ] = 4 * w + j;

					}

				}

			}

		}

		this.last = t;

	}

	private sameFace( u: number, i: number, w: number, j: number ): boolean {

		// Vertices within a cell are distinct, so two triples are equal when each of one is in the other.
		const v = this.vertices;
		for ( let k = 0; k < 4; k ++ ) {

			if ( k === i ) continue;
			const x = v[ 4 * u + k ];
			let found = false;
			for ( let m = 0; m < 4; m ++ ) if ( m !== j && v[ 4 * w + m ] === x ) found = true;
			if ( ! found ) return false;

		}

		return true;

	}

	private setVertices( t: number, a: number, b: number, c: number, d: number ): void {

		const v = this.vertices, k = 4 * t;
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
		this.vertices[ 4 * t ] = FREE;

	}

	private grow(): void {

		const capacity = this.capacity * 2;
		this.vertices = growInt32( this.vertices, 4 * capacity );
		this.adjacency = growInt32( this.adjacency, 4 * capacity );
		this.mark = growInt32( this.mark, capacity );
		this.capacity = capacity;

	}

	/** True when slot t is a ghost cell (one vertex is INF). */
	isGhost( t: number ): boolean {

		const v = this.vertices, k = 4 * t;
		return v[ k ] === INF || v[ k + 1 ] === INF || v[ k + 2 ] === INF || v[ k + 3 ] === INF;

	}

	/**
	 * Visibility walk to a cell whose closure contains q (finite) or a ghost whose hull face q is
	 * strictly beyond. Stochastic face order rules out cycles (Devillers, Pion & Teillaud 2002), and
	 * in a Delaunay tetrahedralization no walk visits a cell twice; past `used` steps (impossible with
	 * exact predicates) a scan of every cell answers instead.
	 */
	locate( q: number ): number {

		const v = this.vertices, adj = this.adjacency, p = this.p, random = this.random;
		let t = this.last;
		if ( t >= this.used || v[ 4 * t ] === FREE ) t = 0;
		while ( v[ 4 * t ] === FREE ) t ++;
		if ( this.isGhost( t ) ) {

			for ( let i = 0; i < 4; i ++ ) if ( v[ 4 * t + i ] === INF ) t = adj[ 4 * t + i ] >> 2;

		}

		let previous = - 1;
		walk: for ( let steps = this.used; steps >= 0; steps -- ) {

			let r = random[ 0 ];
			r ^= r << 13; r ^= r >>> 17; r ^= r << 5;
			random[ 0 ] = r;
			const offset = r & 3;
			const k = 4 * t;
			const a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
			for ( let s = 0; s < 4; s ++ ) {

				const i = ( offset + s ) & 3;
				const next = adj[ k + i ] >> 2;
				if ( next === previous ) continue;
				let o: number;
				if ( i === 0 ) o = orient( p, q, b, c, d );
				else if ( i === 1 ) o = orient( p, a, q, c, d );
				else if ( i === 2 ) o = orient( p, a, b, q, d );
				else o = orient( p, a, b, c, q );
				if ( o < 0 ) {

					previous = t;
					t = next;
					if ( this.isGhost( t ) ) return t;
					continue walk;

				}

			}

			return t;

		}

		return scanForCell( this.p, this.vertices, this.used, q );

	}

	private inConflict( t: number, q: number ): boolean {

		const v = this.vertices, p = this.p, k = 4 * t;
		const a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
		if ( a !== INF && b !== INF && c !== INF && d !== INF ) {

			const s = inSphere( p, a, b, c, d, q );
			if ( s !== 0 ) return s > 0;
			return inSphereTieBreak( p, a, b, c, d, q ) > 0;

		}

		// Ghost: in conflict when q is strictly beyond the hull face, or on its plane and inside
		// the face's perturbed circumcircle.
		let o: number, f0: number, f1: number, f2: number;
		if ( a === INF ) {

			o = orient( p, q, b, c, d );
			f0 = b;
			f1 = c;
			f2 = d;

		} else if ( b === INF ) {

			o = orient( p, a, q, c, d );
			f0 = a;
			f1 = c;
			f2 = d;

		} else if ( c === INF ) {

			o = orient( p, a, b, q, d );
			f0 = a;
			f1 = b;
			f2 = d;

		} else {

			o = orient( p, a, b, c, q );
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
		const adj = this.adjacency, v = this.vertices, p = this.p;
		let stack = this.stack, cavity = this.cavity, boundary = this.boundary;
		let stackSize = 0, cavitySize = 0, boundarySize = 0;
		mark[ start ] = inStamp;
		stack[ stackSize ++ ] = start;
		while ( stackSize > 0 ) {

			const t = stack[ -- stackSize ];
			if ( cavitySize === cavity.length ) this.cavity = cavity = growInt32( cavity, cavitySize * 2 );
			cavity[ cavitySize ++ ] = t;
			const t4 = 4 * t;
			for ( let i = 0; i < 4; i ++ ) {

				const u = adj[ t4 + i ] >> 2;
				const m = mark[ u ];
				if ( m === inStamp ) continue;
				let conflict = false;
				if ( m !== outStamp ) {

					const k = 4 * u;
					const a = v[ k ], b = v[ k + 1 ], c = v[ k + 2 ], d = v[ k + 3 ];
					if ( a !== INF && b !== INF && c !== INF && d !== INF ) {

						const s = inSphere( p, a, b, c, d, q );
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
					boundary[ boundarySize ++ ] = t4 + i;

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
		const v = this.vertices;
		const adj = this.adjacency;
		if ( this.created.length < boundarySize ) this.created = new Int32Array( boundarySize * 2 );
		const created = this.created, boundary = this.boundary;
		// 1.5 entries per boundary face (half of the 3 lookups insert) in at least 8 slots per face,
		// in a power-of-two prefix of the scratch array so that it stays small in the cache.
		let size = 64;
		while ( size < boundarySize * 8 ) size *= 2;
		const table = this.prepareEdgeTable( size );
		const mask = size - 1, shift = Math.clz32( mask );
		const edgeStamp = ++ this.stamp;
		// Slots as `allocate` hands them out (free list first, LIFO), inlined: `reserve` made room.
		const freeList = this.freeList;
		let freeCount = this.freeCount;
		for ( let f = 0; f < boundarySize; f ++ ) {

			const face = boundary[ f ];
			const t = face >> 2, i = face & 3;
			const outside = adj[ face ];
			const n = freeCount > 0 ? freeList[ -- freeCount ] : this.used ++;
			const k = 4 * n, t4 = 4 * t;
			v[ k ] = v[ t4 ]; v[ k + 1 ] = v[ t4 + 1 ]; v[ k + 2 ] = v[ t4 + 2 ]; v[ k + 3 ] = v[ t4 + 3 ];
			v[ k + i ] = q;
			adj[ k + i ] = outside;
			adj[ outside ] = k + i;
			created[ f ] = n;

			// The three faces through q are shared with other new cells; pair them by the edge they
			// have besides q, which the two cells name in opposite directions (FACE_EDGES). Entries
			// are 4 ints: stamp, edge start, edge end, face link; the hash is symmetric in the ends.
			for ( let r = 9 * i, end = r + 9; r < end; r += 3 ) {

				const j = FACE_EDGES[ r ];
				const from = v[ k + FACE_EDGES[ r + 1 ] ], to = v[ k + FACE_EDGES[ r + 2 ] ];
				let h = ( Math.imul( from, EDGE_HASH ) ^ Math.imul( to, EDGE_HASH ) ) >>> shift;
				for ( ;; ) {

					const e = 4 * h;
					if ( table[ e ] !== edgeStamp ) {

						table[ e ] = edgeStamp;
						table[ e + 1 ] = from;
						table[ e + 2 ] = to;
						table[ e + 3 ] = k + j;
						break;

					}

					// Each directed edge occurs once, so a matched entry is never looked up again.
					if ( table[ e + 1 ] === to && table[ e + 2 ] === from ) {

						const other = table[ e + 3 ];
						adj[ k + j ] = other;
						adj[ other ] = k + j;
						break;

					}

					h = ( h + 1 ) & mask;

				}

			}

		}

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
			v[ 4 * t ] = FREE;

		}

		this.freeCount = freeCount;
		this.last = created[ boundarySize - 1 ];

	}

	/**
	 * Replaces every finite vertex v of the cells by `ids[ v ]` and the points by `p` (which must hold
	 * point `ids[ v ]` where the old points held v): for a triangulation built on renumbered points.
	 */
	renumber( ids: Uint32Array, p: Float64Array ): void {

		const v = this.vertices;
		for ( let k = 0, end = 4 * this.used; k < end; k ++ ) {

			const w = v[ k ];
			if ( w >= 0 ) v[ k ] = ids[ w ];

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
		this.vertices = this.adjacency = this.mark = this.freeList = empty;
		this.cavity = this.boundary = this.created = this.stack = empty;
		this.edgeTable = empty;
		this.used = this.capacity = this.freeCount = this.cavitySize = this.boundarySize = this.last = 0;
		shapeKeeper = this;

	}

}

// See DelaunayBuilder.retire.
let shapeKeeper: DelaunayBuilder | null = null;
