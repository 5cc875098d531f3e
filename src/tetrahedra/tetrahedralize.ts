import { assertPoints } from '../validate.js';
import { orient, inSphere, inSphereTieBreak, inCirclePerturbed } from './predicates.js';
import { insertionOrder } from './spatialOrder.js';
import { mergeDuplicates } from './mergeDuplicates.js';

/** Options of {@link tetrahedralize}. */
export interface TetrahedralizeOptions {

	/**
	 * Points closer than this fraction of the bounding-box diagonal are merged into one; the merged
	 * ones are reported in `duplicates`. Default 1e-9.
	 */
	duplicateTolerance?: number;

	/**
	 * When every point lies within this fraction of the bounding-box diagonal of one plane, the set
	 * is rejected as coplanar (a {@link DegenerateInputError} with `reason: 'coplanar'`). Default 1e-9.
	 */
	planarTolerance?: number;

	/** Seed of the randomized insertion order; the output does not depend on it. Default 1. */
	seed?: number;

}

/** Result of {@link tetrahedralize}. */
export interface Tetrahedralization {

	/** Four point indices per tetrahedron, positively oriented: det[p1 − p0, p2 − p0, p3 − p0] > 0. */
	tetrahedra: Uint32Array;

	/** `neighbors[4t + i]` is the tetrahedron across the face opposite vertex i of t, or −1 on the convex hull. */
	neighbors: Int32Array;

	/** Pairs (merged point, point it was merged into), flat; empty when no point was merged. */
	duplicates: Uint32Array;

}

/** Why a point set cannot be tetrahedralized. */
export type DegenerateReason = 'too-few-points' | 'coincident' | 'collinear' | 'coplanar';

/**
 * Thrown by {@link tetrahedralize} when the points do not span a volume. Coplanar layouts (a
 * single floor of probes) can still be interpolated with a planar mesh; see `createProbeInterpolator`.
 */
export class DegenerateInputError extends Error {

	/** Which degeneracy was found. */
	readonly reason: DegenerateReason;

	constructor( reason: DegenerateReason, message: string ) {

		super( message );
		this.name = 'DegenerateInputError';
		this.reason = reason;

	}

}

const INF = - 1; // the vertex at infinity of ghost tetrahedra
const FREE = - 2; // marks a released slot

// SLOT_PAIR[8i + 2j], [8i + 2j + 1]: the two slots of a tetrahedron other than i and j.
const SLOT_PAIR = new Int8Array( 32 );
for ( let i = 0; i < 4; i ++ ) for ( let j = 0; j < 4; j ++ ) {

	const rest = [ 0, 1, 2, 3 ].filter( ( m ) => m !== i && m !== j );
	SLOT_PAIR[ 8 * i + 2 * j ] = rest[ 0 ] ?? 0;
	SLOT_PAIR[ 8 * i + 2 * j + 1 ] = rest[ 1 ] ?? 0;

}

/**
 * Builds the 3D Delaunay tetrahedralization of a point set.
 *
 * Bowyer–Watson insertion in a biased randomized Hilbert order, with ghost tetrahedra on the hull,
 * exact predicates and symbolic perturbation: regular grids (co-spherical everywhere), co-planar
 * subsets and clustered points all give a valid result — tetrahedra that exactly tile the convex
 * hull, none flat, none with an input point strictly inside its circumsphere.
 *
 * @param points Flat x, y, z coordinates.
 * @throws {RangeError} on NaN/Infinity or a length that is not a multiple of 3.
 * @throws {DegenerateInputError} for fewer than 4 distinct points, or points that are all coplanar.
 */
export function tetrahedralize( points: ArrayLike<number>, options: TetrahedralizeOptions = {} ): Tetrahedralization {

	const count = assertPoints( 'tetrahedralize', 'points', points );
	if ( count < 4 ) {

		throw new DegenerateInputError( 'too-few-points', `tetrahedralize: points needs at least 4 points to span a volume, got ${count}.` );

	}

	const p = Float64Array.from( points );
	const { duplicateTolerance = 1e-9, planarTolerance = 1e-9, seed = 1 } = options;

	const { unique, duplicates, diagonal } = mergeDuplicates( p, duplicateTolerance );
	if ( unique.length < 4 ) {

		throw new DegenerateInputError( 'too-few-points', `tetrahedralize: points has only ${unique.length} distinct points (${duplicates.length / 2} merged as duplicates); at least 4 are needed.` );

	}

	const initial = findInitialTetrahedron( p, unique, diagonal, planarTolerance );
	const builder = new DelaunayBuilder( p, count, diagonal );
	builder.start( initial );

	const rest = new Uint32Array( unique.length - 4 );
	for ( let i = 0, j = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		if ( v !== initial[ 0 ] && v !== initial[ 1 ] && v !== initial[ 2 ] && v !== initial[ 3 ] ) rest[ j ++ ] = v;

	}

	const order = insertionOrder( p, rest, seed );
	for ( let i = 0; i < order.length; i ++ ) builder.insert( order[ i ] );

	return { ...builder.finish(), duplicates };

}

/**
 * Four affinely independent points, far apart: the first of the extreme points in x, then the
 * farthest from it, from their line, from their plane. Tolerances make near-degenerate sets fail
 * loudly here instead of producing a mesh of slivers.
 */
function findInitialTetrahedron( p: Float64Array, unique: Uint32Array, diagonal: number, planarTolerance: number ): [ number, number, number, number ] {

	let i0 = unique[ 0 ];
	for ( let i = 1; i < unique.length; i ++ ) if ( p[ 3 * unique[ i ] ] < p[ 3 * i0 ] ) i0 = unique[ i ];
	const ax = p[ 3 * i0 ], ay = p[ 3 * i0 + 1 ], az = p[ 3 * i0 + 2 ];

	let i1 = - 1, best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const dx = p[ 3 * v ] - ax, dy = p[ 3 * v + 1 ] - ay, dz = p[ 3 * v + 2 ] - az;
		const d = dx * dx + dy * dy + dz * dz;
		if ( d > best ) { best = d; i1 = v; }

	}

	const ux = p[ 3 * i1 ] - ax, uy = p[ 3 * i1 + 1 ] - ay, uz = p[ 3 * i1 + 2 ] - az;
	let i2 = - 1;
	best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const dx = p[ 3 * v ] - ax, dy = p[ 3 * v + 1 ] - ay, dz = p[ 3 * v + 2 ] - az;
		const cx = uy * dz - uz * dy, cy = uz * dx - ux * dz, cz = ux * dy - uy * dx;
		const d = cx * cx + cy * cy + cz * cz; // |u × d|² = |u|² · distance² to the line
		if ( d > best ) { best = d; i2 = v; }

	}

	const lineDistance = Math.sqrt( best / ( ux * ux + uy * uy + uz * uz ) );
	if ( lineDistance <= planarTolerance * diagonal ) {

		throw new DegenerateInputError( 'collinear', `tetrahedralize: all ${unique.length} distinct points lie on one line (within ${planarTolerance} of the extent); they span no area or volume.` );

	}

	const vx = p[ 3 * i2 ] - ax, vy = p[ 3 * i2 + 1 ] - ay, vz = p[ 3 * i2 + 2 ] - az;
	let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
	const nl = Math.hypot( nx, ny, nz );
	nx /= nl; ny /= nl; nz /= nl;

	let i3 = - 1;
	best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const d = Math.abs( ( p[ 3 * v ] - ax ) * nx + ( p[ 3 * v + 1 ] - ay ) * ny + ( p[ 3 * v + 2 ] - az ) * nz );
		if ( d > best ) { best = d; i3 = v; }

	}

	if ( best <= planarTolerance * diagonal || orient( p, i0, i1, i2, i3 ) === 0 ) {

		throw new DegenerateInputError( 'coplanar', `tetrahedralize: all ${unique.length} distinct points lie in one plane (within ${planarTolerance} of the extent); a volume needs at least one point off that plane. Use createProbeInterpolator for planar layouts.` );

	}

	return orient( p, i0, i1, i2, i3 ) > 0 ? [ i0, i1, i2, i3 ] : [ i0, i2, i1, i3 ];

}

/**
 * Incremental Delaunay state in flat typed arrays. Tetrahedron t has vertices `vertices[4t..4t+3]`
 * (INF for the vertex at infinity) and `adjacency[4t+i] = 4u + j`: the face opposite vertex i of t
 * is the face opposite vertex j of u. A ghost tetrahedron replaces one vertex of a hull face's
 * outside by INF, ordered so that putting any point beyond that face in INF's slot gives a positive
 * tetrahedron; that makes "replace the opposite vertex by the new point" valid for ghosts too.
 */
class DelaunayBuilder {

	private readonly p: Float64Array;
	private readonly extent: number;
	private vertices: Int32Array;
	private adjacency: Int32Array;
	private mark: Int32Array;
	private capacity: number;
	private used = 0;
	private freeList: Int32Array;
	private freeCount = 0;
	private stamp = 0;
	private last = 0;
	private random = 0x2545F491;

	// Per-insertion scratch, grown on demand.
	private stack = new Int32Array( 256 );
	private cavity = new Int32Array( 256 );
	private boundary = new Int32Array( 256 );
	private created = new Int32Array( 256 );
	private edgeKeyA = new Int32Array( 1024 );
	private edgeKeyB = new Int32Array( 1024 );
	private edgeValue = new Int32Array( 1024 );
	private edgeStamp = new Int32Array( 1024 );

	constructor( p: Float64Array, pointCount: number, diagonal: number ) {

		this.p = p;
		this.extent = diagonal;
		this.capacity = Math.max( 64, Math.ceil( pointCount * 7.5 ) );
		this.vertices = new Int32Array( 4 * this.capacity );
		this.adjacency = new Int32Array( 4 * this.capacity );
		this.mark = new Int32Array( this.capacity );
		this.freeList = new Int32Array( 64 );

	}

	start( [ a, b, c, d ]: [ number, number, number, number ] ): void {

		const t = this.allocate();
		this.setVertices( t, a, b, c, d );

		// Ghost opposite vertex k: the tetrahedron with vertex k replaced by INF has the new point
		// on the wrong side, so swap two of the remaining slots to flip the orientation.
		const ghosts = [ 0, 0, 0, 0 ];
		for ( let k = 0; k < 4; k ++ ) {

			const g = this.allocate();
			const v = [ a, b, c, d ];
			v[ k ] = INF;
			const i = ( k + 1 ) & 3, j = ( k + 2 ) & 3;
			const s = v[ i ]; v[ i ] = v[ j ]; v[ j ] = s;
			this.setVertices( g, v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ] );
			ghosts[ k ] = g;

		}

		// Five cells, linked by comparing their faces; done once, so brute force is fine.
		const cells = [ t, ...ghosts ];
		for ( const u of cells ) {

			for ( let i = 0; i < 4; i ++ ) {

				for ( const w of cells ) {

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

		const fu: number[] = [], fw: number[] = [];
		for ( let k = 0; k < 4; k ++ ) {

			if ( k !== i ) fu.push( this.vertices[ 4 * u + k ] );
			if ( k !== j ) fw.push( this.vertices[ 4 * w + k ] );

		}

		fu.sort(); fw.sort();
		return fu[ 0 ] === fw[ 0 ] && fu[ 1 ] === fw[ 1 ] && fu[ 2 ] === fw[ 2 ];

	}

	private setVertices( t: number, a: number, b: number, c: number, d: number ): void {

		const v = this.vertices, k = 4 * t;
		v[ k ] = a; v[ k + 1 ] = b; v[ k + 2 ] = c; v[ k + 3 ] = d;

	}

	private allocate(): number {

		if ( this.freeCount > 0 ) return this.freeList[ -- this.freeCount ];
		if ( this.used === this.capacity ) this.grow();
		return this.used ++;

	}

	private release( t: number ): void {

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

	private isGhost( t: number ): boolean {

		const v = this.vertices, k = 4 * t;
		return v[ k ] === INF || v[ k + 1 ] === INF || v[ k + 2 ] === INF || v[ k + 3 ] === INF;

	}

	/**
	 * Visibility walk to a cell whose closure contains q (finite) or a ghost whose hull face q is
	 * strictly beyond. Stochastic face order rules out cycles (Devillers, Pion & Teillaud 2002).
	 */
	private locate( q: number ): number {

		const v = this.vertices, adj = this.adjacency, p = this.p;
		let t = this.last;
		if ( v[ 4 * t ] === FREE ) t = 0;
		while ( v[ 4 * t ] === FREE ) t ++;
		if ( this.isGhost( t ) ) {

			for ( let i = 0; i < 4; i ++ ) if ( v[ 4 * t + i ] === INF ) t = adj[ 4 * t + i ] >> 2;

		}

		let previous = - 1;
		walk: for ( ;; ) {

			this.random ^= this.random << 13; this.random ^= this.random >>> 17; this.random ^= this.random << 5;
			const offset = this.random & 3;
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
		if ( a === INF ) { o = orient( p, q, b, c, d ); f0 = b; f1 = c; f2 = d; }
		else if ( b === INF ) { o = orient( p, a, q, c, d ); f0 = a; f1 = c; f2 = d; }
		else if ( c === INF ) { o = orient( p, a, b, q, d ); f0 = a; f1 = b; f2 = d; }
		else { o = orient( p, a, b, c, q ); f0 = a; f1 = b; f2 = c; }
		if ( o !== 0 ) return o > 0;
		return inCirclePerturbed( p, f0, f1, f2, q, this.extent ) > 0;

	}

	insert( q: number ): void {

		const start = this.locate( q );
		const mark = this.mark;
		const inStamp = ( this.stamp += 2 );
		const outStamp = inStamp + 1;

		// Flood the conflict region (connected, star-shaped from q) and collect its boundary faces.
		let adj = this.adjacency;
		let stackSize = 0, cavitySize = 0, boundarySize = 0;
		mark[ start ] = inStamp;
		this.stack[ stackSize ++ ] = start;
		while ( stackSize > 0 ) {

			const t = this.stack[ -- stackSize ];
			if ( cavitySize === this.cavity.length ) this.cavity = growInt32( this.cavity, cavitySize * 2 );
			this.cavity[ cavitySize ++ ] = t;
			for ( let i = 0; i < 4; i ++ ) {

				const u = adj[ 4 * t + i ] >> 2;
				const m = mark[ u ];
				if ( m === inStamp ) continue;
				if ( m !== outStamp && this.inConflict( u, q ) ) {

					mark[ u ] = inStamp;
					if ( stackSize === this.stack.length ) this.stack = growInt32( this.stack, stackSize * 2 );
					this.stack[ stackSize ++ ] = u;

				} else {

					mark[ u ] = outStamp;
					if ( boundarySize === this.boundary.length ) this.boundary = growInt32( this.boundary, boundarySize * 2 );
					this.boundary[ boundarySize ++ ] = 4 * t + i;

				}

			}

		}

		// One new cell per boundary face: the conflict cell with its vertex opposite that face
		// replaced by q, which keeps the orientation (q sees the face from the same side).
		this.reserve( boundarySize );
		const v = this.vertices;
		adj = this.adjacency;
		if ( this.created.length < boundarySize ) this.created = new Int32Array( boundarySize * 2 );
		const mask = this.prepareEdgeTable( boundarySize * 3 ) - 1;
		const edgeStamp = this.stamp;
		const keyA = this.edgeKeyA, keyB = this.edgeKeyB, value = this.edgeValue, used = this.edgeStamp;
		for ( let f = 0; f < boundarySize; f ++ ) {

			const face = this.boundary[ f ];
			const t = face >> 2, i = face & 3;
			const outside = adj[ face ];
			const n = this.allocate();
			const k = 4 * n;
			for ( let j = 0; j < 4; j ++ ) v[ k + j ] = v[ 4 * t + j ];
			v[ k + i ] = q;
			adj[ k + i ] = outside;
			adj[ outside ] = k + i;
			this.created[ f ] = n;

			// The three faces through q are shared with other new cells; pair them by the edge they
			// have besides q (the two slots other than i and j).
			for ( let j = 0; j < 4; j ++ ) {

				if ( j === i ) continue;
				const m0 = SLOT_PAIR[ 8 * i + 2 * j ], m1 = SLOT_PAIR[ 8 * i + 2 * j + 1 ];
				let e0 = v[ k + m0 ], e1 = v[ k + m1 ];
				if ( e0 > e1 ) { const s = e0; e0 = e1; e1 = s; }
				let h = ( Math.imul( e0 + 2, 0x9E3779B1 ) ^ Math.imul( e1 + 2, 0x85EBCA77 ) ) & mask;
				for ( ;; ) {

					if ( used[ h ] !== edgeStamp ) {

						used[ h ] = edgeStamp;
						keyA[ h ] = e0;
						keyB[ h ] = e1;
						value[ h ] = k + j;
						break;

					}

					if ( keyA[ h ] === e0 && keyB[ h ] === e1 ) {

						const other = value[ h ];
						adj[ k + j ] = other;
						adj[ other ] = k + j;
						// Each edge is shared by exactly two new cells; retire the entry.
						keyA[ h ] = keyB[ h ] = FREE - 1;
						break;

					}

					h = ( h + 1 ) & mask;

				}

			}

		}

		for ( let c = 0; c < cavitySize; c ++ ) this.release( this.cavity[ c ] );
		this.last = this.created[ boundarySize - 1 ];

	}

	/** Makes room for `count` more cells so that arrays stay put while new cells are linked. */
	private reserve( count: number ): void {

		while ( this.used + Math.max( 0, count - this.freeCount ) > this.capacity ) this.grow();

	}

	private prepareEdgeTable( entries: number ): number {

		let size = this.edgeStamp.length;
		if ( size < entries * 2 ) {

			while ( size < entries * 2 ) size *= 2;
			this.edgeKeyA = new Int32Array( size );
			this.edgeKeyB = new Int32Array( size );
			this.edgeValue = new Int32Array( size );
			this.edgeStamp = new Int32Array( size );

		}

		return size;

	}

	/** Compacts the finite cells into the output arrays. */
	finish(): { tetrahedra: Uint32Array; neighbors: Int32Array } {

		const v = this.vertices, adj = this.adjacency;
		const index = new Int32Array( this.used ).fill( - 1 );
		let count = 0;
		for ( let t = 0; t < this.used; t ++ ) {

			if ( v[ 4 * t ] !== FREE && ! this.isGhost( t ) ) index[ t ] = count ++;

		}

		const tetrahedra = new Uint32Array( 4 * count );
		const neighbors = new Int32Array( 4 * count );
		for ( let t = 0; t < this.used; t ++ ) {

			const o = index[ t ];
			if ( o < 0 ) continue;
			for ( let i = 0; i < 4; i ++ ) {

				tetrahedra[ 4 * o + i ] = v[ 4 * t + i ];
				neighbors[ 4 * o + i ] = index[ adj[ 4 * t + i ] >> 2 ];

			}

		}

		return { tetrahedra, neighbors };

	}

}

function growInt32( array: Int32Array, length: number ): Int32Array<ArrayBuffer> {

	const grown = new Int32Array( length );
	grown.set( array.subarray( 0, Math.min( array.length, length ) ) );
	return grown;

}
