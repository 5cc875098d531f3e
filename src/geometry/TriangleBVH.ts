import { assertFinite, assertArrayLike, assertNumber } from '../validate.js';
import { closestPointOnTriangle } from './closestPointOnTriangle.js';
import { intersectRayTriangle } from './intersectRayTriangle.js';

// Triangles per leaf: small leaves mean more box tests but fewer triangle tests; 4 is the usual
// balance for Möller–Trumbore, whose cost is a few box tests.
const LEAF_SIZE = 4;

// Traversal stack depth. Median splits halve the triangle count per level, so the depth is about
// log2(n / LEAF_SIZE): 64 is enough for any array that fits in memory.
const STACK_SIZE = 64;

// Segment hits this close to either end (in segment-parameter units) do not count: a probe or an
// object standing exactly on a surface still sees along it.
const END_EPSILON = 1e-6;

// The node tests of `nextLeaf`: a ray or segment meets the box, the box is within a closed ball,
// the box is within an open ball (and the nearer child goes first).
const RAY = 0, BALL = 1, NEAREST = 2;

const _closest = new Float64Array( 6 );

/** A ray hit of {@link TriangleBVH.raycastFirst}: the ray parameter and the triangle's index (−1, −1: none). */
export interface RayHit {

	/** Ray parameter of the hit (point = o + t · d), or −1. */
	t: number;

	/** Index of the triangle hit, or −1. */
	triangle: number;

}

/**
 * A bounding volume hierarchy over a flat triangle array, for the queries probe placement and
 * probe visibility need in plain Node: counting ray crossings (inside/outside by parity), "is this
 * segment blocked", the first hit of a ray, "is any triangle within r of this point" and the
 * nearest distance — all through one traversal. Built once by median splits on the longest axis
 * of the triangle centroids (O(n log n)); each query then touches O(log n) nodes for a compact
 * scene, so 100k triangles × thousands of candidates × a few rays take well under a second.
 *
 * Nodes are stored depth-first in typed arrays: an inner node's left child follows it, its right
 * child index is in `rightOrStart`; a leaf has `count > 0` triangles `order[rightOrStart …]`.
 */
export class TriangleBVH {

	/** The triangles, 9 floats (a, b, c) each, as given (a copy). */
	readonly triangles: Float64Array;

	/** Per node: min x, y, z, max x, y, z of its triangles. */
	readonly nodeBounds: Float64Array;

	/** Per node: the right child (inner node) or the first entry in `order` (leaf). */
	readonly rightOrStart: Int32Array;

	/** Per node: the number of triangles (leaf), or 0 (inner node). */
	readonly nodeTriangleCounts: Int32Array;

	/** Triangle indices, grouped by leaf. */
	readonly order: Uint32Array;

	/** Per triangle: min x, y, z, max x, y, z — a cheap reject before the exact segment test. */
	readonly triangleBounds: Float64Array;

	private readonly stack = new Int32Array( STACK_SIZE );
	private top = 0;

	/**
	 * @param triangles 9 floats per triangle (a, b, c), e.g. world-space positions of a non-indexed
	 * geometry. May be empty: every query then answers "nothing".
	 */
	constructor( triangles: ArrayLike<number> ) {

		assertArrayLike( 'TriangleBVH', 'triangles', triangles );
		if ( triangles.length % 9 !== 0 ) {

			throw new RangeError( `TriangleBVH: triangles must hold 9 floats (a, b, c) per triangle, got length ${triangles.length}.` );

		}

		assertFinite( 'TriangleBVH', 'triangles', triangles );
		this.triangles = Float64Array.from( triangles );
		const count = triangles.length / 9;

		const bounds = this.triangleBounds = new Float64Array( 6 * count ), centroids = new Float64Array( 3 * count );
		for ( let t = 0; t < count; t ++ ) {

			for ( let a = 0; a < 3; a ++ ) {

				const v0 = this.triangles[ 9 * t + a ], v1 = this.triangles[ 9 * t + 3 + a ], v2 = this.triangles[ 9 * t + 6 + a ];
				bounds[ 6 * t + a ] = Math.min( v0, v1, v2 );
				bounds[ 6 * t + 3 + a ] = Math.max( v0, v1, v2 );
				centroids[ 3 * t + a ] = ( v0 + v1 + v2 ) / 3;

			}

		}

		this.order = new Uint32Array( count );
		for ( let t = 0; t < count; t ++ ) this.order[ t ] = t;
		const maxNodes = Math.max( 1, 2 * count );
		const nodeBounds = new Float64Array( 6 * maxNodes );
		const rightOrStart = new Int32Array( maxNodes ), counts = new Int32Array( maxNodes );

		let nodeCount = 0;
		const build = ( start: number, end: number ): number => {

			const node = nodeCount ++;
			const b = 6 * node;
			nodeBounds.fill( Infinity, b, b + 3 );
			nodeBounds.fill( - Infinity, b + 3, b + 6 );
			let cMinX = Infinity, cMinY = Infinity, cMinZ = Infinity, cMaxX = - Infinity, cMaxY = - Infinity, cMaxZ = - Infinity;
			for ( let i = start; i < end; i ++ ) {

				const t = this.order[ i ];
				for ( let a = 0; a < 3; a ++ ) {

					if ( bounds[ 6 * t + a ] < nodeBounds[ b + a ] ) nodeBounds[ b + a ] = bounds[ 6 * t + a ];
					if ( bounds[ 6 * t + 3 + a ] > nodeBounds[ b + 3 + a ] ) nodeBounds[ b + 3 + a ] = bounds[ 6 * t + 3 + a ];

				}

				const x = centroids[ 3 * t ], y = centroids[ 3 * t + 1 ], z = centroids[ 3 * t + 2 ];
				if ( x < cMinX ) cMinX = x; if ( x > cMaxX ) cMaxX = x;
				if ( y < cMinY ) cMinY = y; if ( y > cMaxY ) cMaxY = y;
				if ( z < cMinZ ) cMinZ = z; if ( z > cMaxZ ) cMaxZ = z;

			}

			const ex = cMaxX - cMinX, ey = cMaxY - cMinY, ez = cMaxZ - cMinZ;
			// A leaf when small enough, or when all centroids coincide (no split can separate them).
			if ( end - start <= LEAF_SIZE || ! ( ex > 0 || ey > 0 || ez > 0 ) ) {

				rightOrStart[ node ] = start;
				counts[ node ] = end - start;
				return node;

			}

			const axis = ex >= ey && ex >= ez ? 0 : ( ey >= ez ? 1 : 2 );
			const middle = ( start + end ) >> 1;
			selectNth( this.order, centroids, axis, start, end - 1, middle );
			counts[ node ] = 0;
			build( start, middle );
			rightOrStart[ node ] = build( middle, end );
			return node;

		};

		if ( count > 0 ) build( 0, count );
		this.nodeBounds = nodeBounds.slice( 0, 6 * nodeCount );
		this.rightOrStart = rightOrStart.slice( 0, nodeCount );
		this.nodeTriangleCounts = counts.slice( 0, nodeCount );

	}

	/** Number of triangles. */
	get triangleCount(): number {

		return this.triangles.length / 9;

	}

	/**
	 * How many triangles the ray o + t · d, t > 0, crosses (both faces, every hit). For a closed
	 * surface, odd means the origin is inside. Allocation-free.
	 */
	countCrossings( ox: number, oy: number, oz: number, dx: number, dy: number, dz: number ): number {

		const right = this.rightOrStart, counts = this.nodeTriangleCounts, order = this.order, tri = this.triangles;
		// Reciprocal direction for the slab test; a zero component gives ±Infinity, handled in hitsBox.
		const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
		let crossings = 0;
		this.pushRoot();
		let leaf: number;
		while ( ( leaf = this.nextLeaf( RAY, ox, oy, oz, ix, iy, iz, Infinity ) ) >= 0 ) {

			for ( let i = right[ leaf ], end = i + counts[ leaf ]; i < end; i ++ ) {

				if ( intersectRayTriangle( tri, order[ i ], ox, oy, oz, dx, dy, dz ) > 0 ) crossings ++;

			}

		}

		return crossings;

	}

	/**
	 * Whether the open segment from a to b crosses any triangle: hits within 1e-6 of the segment's
	 * length from either end do not count (a probe or an object standing exactly on a surface still
	 * sees along it); a zero-length segment is never blocked. Stops at the first hit. Allocation-free.
	 */
	segmentBlocked( ax: number, ay: number, az: number, bx: number, by: number, bz: number ): boolean {

		const right = this.rightOrStart, counts = this.nodeTriangleCounts, order = this.order, tri = this.triangles;
		const triangleBounds = this.triangleBounds;
		const dx = bx - ax, dy = by - ay, dz = bz - az;
		if ( dx === 0 && dy === 0 && dz === 0 ) return false;
		const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
		this.pushRoot();
		let leaf: number;
		while ( ( leaf = this.nextLeaf( RAY, ax, ay, az, ix, iy, iz, 1 ) ) >= 0 ) {

			for ( let i = right[ leaf ], end = i + counts[ leaf ]; i < end; i ++ ) {

				const triangle = order[ i ];
				// The triangle's own box first: leaves mix large and small triangles.
				if ( ! hitsBox( triangleBounds, 6 * triangle, ax, ay, az, ix, iy, iz, 1 ) ) continue;
				// d = b − a, so the hit parameter is the fraction of the segment.
				const t = intersectRayTriangle( tri, triangle, ax, ay, az, dx, dy, dz );
				if ( t > END_EPSILON && t < 1 - END_EPSILON ) return true;

			}

		}

		return false;

	}

	/**
	 * The nearest hit of the ray o + t · d with 0 < t < `tMax` (both faces). Allocation-free.
	 * @param dx Ray direction x (and `dy`, `dz`); need not be unit length — t is in its units.
	 * @param tMax Farthest ray parameter that counts (default Infinity; 1 with d = b − a: a segment).
	 * @param target Receives the hit's `t` and `triangle` index (−1 for both when nothing is hit).
	 * @returns The hit's ray parameter t, or −1 when nothing is hit.
	 */
	raycastFirst(
		ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, tMax = Infinity, target?: RayHit
	): number {

		const right = this.rightOrStart, counts = this.nodeTriangleCounts, order = this.order, tri = this.triangles;
		const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
		let best = tMax, found = - 1;
		this.pushRoot();
		let leaf: number;
		while ( ( leaf = this.nextLeaf( RAY, ox, oy, oz, ix, iy, iz, best ) ) >= 0 ) {

			for ( let i = right[ leaf ], end = i + counts[ leaf ]; i < end; i ++ ) {

				const t = intersectRayTriangle( tri, order[ i ], ox, oy, oz, dx, dy, dz );
				if ( t > 0 && t < best ) {

					best = t;
					found = order[ i ];

				}

			}

		}

		const t = found < 0 ? - 1 : best;
		if ( target !== undefined ) {

			target.t = t;
			target.triangle = found;

		}

		return t;

	}

	/**
	 * Whether any triangle has a point within `radius` of (x, y, z) (closed ball). Stops at the first
	 * one found. Allocation-free.
	 */
	anyWithin( x: number, y: number, z: number, radius: number ): boolean {

		if ( ! ( radius >= 0 ) ) return false;
		const right = this.rightOrStart, counts = this.nodeTriangleCounts, order = this.order, tri = this.triangles;
		const r2 = radius * radius;
		this.pushRoot();
		let leaf: number;
		while ( ( leaf = this.nextLeaf( BALL, x, y, z, 0, 0, 0, r2 ) ) >= 0 ) {

			for ( let i = right[ leaf ], end = i + counts[ leaf ]; i < end; i ++ ) {

				const k = 9 * order[ i ];
				const d2 = closestPointOnTriangle(
					x, y, z, tri[ k ], tri[ k + 1 ], tri[ k + 2 ], tri[ k + 3 ], tri[ k + 4 ], tri[ k + 5 ],
					tri[ k + 6 ], tri[ k + 7 ], tri[ k + 8 ], _closest
				);
				if ( d2 <= r2 ) return true;

			}

		}

		return false;

	}

	/**
	 * Distance from (x, y, z) to the nearest triangle (Infinity when there are none). Nodes are
	 * skipped once they are farther than the best distance so far.
	 */
	nearestDistance( x: number, y: number, z: number ): number {

		assertNumber( 'TriangleBVH.nearestDistance', 'x', x );
		assertNumber( 'TriangleBVH.nearestDistance', 'y', y );
		assertNumber( 'TriangleBVH.nearestDistance', 'z', z );
		const right = this.rightOrStart, counts = this.nodeTriangleCounts, order = this.order, tri = this.triangles;
		let best = Infinity;
		this.pushRoot();
		let leaf: number;
		while ( ( leaf = this.nextLeaf( NEAREST, x, y, z, 0, 0, 0, best ) ) >= 0 ) {

			for ( let i = right[ leaf ], end = i + counts[ leaf ]; i < end; i ++ ) {

				const k = 9 * order[ i ];
				const d2 = closestPointOnTriangle(
					x, y, z, tri[ k ], tri[ k + 1 ], tri[ k + 2 ], tri[ k + 3 ], tri[ k + 4 ], tri[ k + 5 ],
					tri[ k + 6 ], tri[ k + 7 ], tri[ k + 8 ], _closest
				);
				if ( d2 < best ) best = d2;

			}

		}

		return Math.sqrt( best );

	}

	/** Starts a traversal: the stack holds the root (nothing when there are no triangles). */
	private pushRoot(): void {

		this.stack[ 0 ] = 0;
		this.top = this.nodeTriangleCounts.length > 0 ? 1 : 0;

	}

	/**
	 * The one traversal behind every query: pops nodes off the instance's stack (depth first, from
	 * {@link TriangleBVH.pushRoot}) until a leaf passes the test, pushing the children of every
	 * inner node that passes. RAY (o = x, y, z; reciprocal direction i): the box meets o + t · d for
	 * some t ∈ [0, limit]. BALL: the box is within the squared distance `limit` of (x, y, z);
	 * NEAREST: strictly within it, and the nearer child is visited first (it tightens `limit` sooner).
	 * @returns The leaf's node index, or −1 when the traversal is over.
	 */
	private nextLeaf( test: number, x: number, y: number, z: number, ix: number, iy: number, iz: number, limit: number ): number {

		const bounds = this.nodeBounds, right = this.rightOrStart, counts = this.nodeTriangleCounts, stack = this.stack;
		let top = this.top;
		while ( top > 0 ) {

			const node = stack[ -- top ];
			if ( test === RAY ) {

				if ( ! hitsBox( bounds, 6 * node, x, y, z, ix, iy, iz, limit ) ) continue;

			} else {

				const d2 = boxDistanceSquared( bounds, 6 * node, x, y, z );
				if ( test === NEAREST ? d2 >= limit : d2 > limit ) continue;

			}

			if ( counts[ node ] > 0 ) {

				this.top = top;
				return node;

			}

			stack[ top ++ ] = right[ node ]; stack[ top ++ ] = node + 1;
			if ( test === NEAREST ) nearerOnTop( bounds, stack, top, x, y, z );

		}

		this.top = 0;
		return - 1;

	}

}

/** Swaps the two children just pushed when the left one (on top) is the farther. */
function nearerOnTop( bounds: Float64Array, stack: Int32Array, top: number, x: number, y: number, z: number ): void {

	const left = stack[ top - 1 ], right = stack[ top - 2 ];
	if ( boxDistanceSquared( bounds, 6 * left, x, y, z ) > boxDistanceSquared( bounds, 6 * right, x, y, z ) ) {

		stack[ top - 1 ] = right; stack[ top - 2 ] = left;

	}

}

/**
 * Slab test of o + t · d, t ∈ [0, tMax] (a ray with tMax = Infinity, a segment with d = b − a and
 * tMax = 1), against the box at `bounds[b …]`, given the reciprocal direction i = 1 / d. With a
 * zero direction component the reciprocal is ±Infinity: (min − o) · ±Infinity is NaN only when o
 * lies exactly on that slab's plane, which the comparisons below treat as inside the slab, and
 * ±Infinity for both ends when o is outside it, which empties the interval.
 */
export function hitsBox(
	bounds: Float64Array, b: number, ox: number, oy: number, oz: number, ix: number, iy: number, iz: number, tMax: number
): boolean {

	let near = 0, far = tMax;
	let t0 = ( bounds[ b ] - ox ) * ix, t1 = ( bounds[ b + 3 ] - ox ) * ix;
	if ( t0 > t1 ) { const s = t0; t0 = t1; t1 = s; }
	if ( t0 > near ) near = t0;
	if ( t1 < far ) far = t1;
	t0 = ( bounds[ b + 1 ] - oy ) * iy; t1 = ( bounds[ b + 4 ] - oy ) * iy;
	if ( t0 > t1 ) { const s = t0; t0 = t1; t1 = s; }
	if ( t0 > near ) near = t0;
	if ( t1 < far ) far = t1;
	t0 = ( bounds[ b + 2 ] - oz ) * iz; t1 = ( bounds[ b + 5 ] - oz ) * iz;
	if ( t0 > t1 ) { const s = t0; t0 = t1; t1 = s; }
	if ( t0 > near ) near = t0;
	if ( t1 < far ) far = t1;
	// near = Infinity: the origin is outside a slab the ray runs parallel to.
	return near <= far && near < Infinity;

}

/** Squared distance from a point to the box at `bounds[b …]` (0 inside). */
function boxDistanceSquared( bounds: Float64Array, b: number, x: number, y: number, z: number ): number {

	let d = 0, e: number;
	e = bounds[ b ] - x; if ( e > 0 ) d += e * e;
	e = x - bounds[ b + 3 ]; if ( e > 0 ) d += e * e;
	e = bounds[ b + 1 ] - y; if ( e > 0 ) d += e * e;
	e = y - bounds[ b + 4 ]; if ( e > 0 ) d += e * e;
	e = bounds[ b + 2 ] - z; if ( e > 0 ) d += e * e;
	e = z - bounds[ b + 5 ]; if ( e > 0 ) d += e * e;
	return d;

}

/**
 * Quickselect (Hoare partition, middle pivot): reorders `order[left..right]` so that entry `nth`
 * holds the triangle whose centroid is nth along `axis`, smaller ones before it, larger after.
 */
function selectNth( order: Uint32Array, centroids: Float64Array, axis: number, left: number, right: number, nth: number ): void {

	while ( right > left ) {

		const pivot = centroids[ 3 * order[ ( left + right ) >> 1 ] + axis ];
		let i = left, j = right;
		while ( i <= j ) {

			while ( centroids[ 3 * order[ i ] + axis ] < pivot ) i ++;
			while ( centroids[ 3 * order[ j ] + axis ] > pivot ) j --;
			if ( i <= j ) {

				const s = order[ i ]; order[ i ] = order[ j ]; order[ j ] = s;
				i ++; j --;

			}

		}

		if ( nth <= j ) right = j;
		else if ( nth >= i ) left = i;
		else return;

	}

}
