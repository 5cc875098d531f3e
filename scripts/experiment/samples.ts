/**
 * Pure parts of the experiment's point sets: a seeded random generator, the open-space test (what
 * a probe's cube camera would see from a point), ground-truth samples spread through the open
 * space of a box, and the dense candidate set the automatic reduction starts from.
 */

import { candidatesFromVertices } from '../../src/index.js';
import { TriangleBVH, intersectRayTriangle } from '../../src/math.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/** An axis-aligned box, [x, y, z] each. */
export interface Box { min: ArrayLike<number>; max: ArrayLike<number> }

/** The library's seeded generator (mulberry32, numbers in [0, 1)): the same seed, the same points on every machine. */
export { mulberry32 };

/**
 * `count` unit directions spread evenly over the sphere (a Fibonacci lattice), turned so that
 * none runs along an axis or an axis plane, where modelled scenes put their edges.
 */
export function sphereDirections( count: number ): Float64Array {

	const out = new Float64Array( 3 * count ), golden = Math.PI * ( 3 - Math.sqrt( 5 ) );
	for ( let i = 0; i < count; i ++ ) {

		const y = 1 - 2 * ( i + 0.5 ) / count, r = Math.sqrt( 1 - y * y ), phi = golden * i + 0.41;
		// A fixed small rotation about x, then about z, off the axis planes.
		const x0 = r * Math.cos( phi ), z0 = r * Math.sin( phi );
		const c1 = Math.cos( 0.37 ), s1 = Math.sin( 0.37 ), c2 = Math.cos( 0.23 ), s2 = Math.sin( 0.23 );
		const y1 = y * c1 - z0 * s1, z1 = y * s1 + z0 * c1;
		out[ 3 * i ] = x0 * c2 - y1 * s2;
		out[ 3 * i + 1 ] = x0 * s2 + y1 * c2;
		out[ 3 * i + 2 ] = z1;

	}

	return out;

}

/** {@link OpenSpaceTest.classify}: a usable position. */
export const OPEN = 0;

/** {@link OpenSpaceTest.classify}: a surface is closer than `minDistance`. */
export const NEAR = 1;

/** {@link OpenSpaceTest.classify}: rays from here reach the undrawn side of surfaces: inside geometry. */
export const INSIDE = 2;

/** {@link OpenSpaceTest.classify}: too many rays from here leave the scene: outside a closed interior (above its roof). */
export const OUTSIDE = 3;

/** Options of {@link OpenSpaceTest}. */
export interface OpenSpaceOptions {

	/** Points with a triangle closer than this are {@link NEAR}. */
	minDistance: number;

	/** Rays cast per point (default 32). */
	rays?: number;

	/**
	 * A point is {@link INSIDE} when more than this fraction of its rays first hit a surface from
	 * its undrawn side (default 0.1).
	 */
	maxSeeThrough?: number;

	/**
	 * A point is {@link OUTSIDE} when more than this fraction of its rays hit nothing (default 1:
	 * never). For a closed interior (Sibenik), open air above the roof is not the scene's space.
	 */
	maxSky?: number;

}

/**
 * "Open space" as the capture sees it. Three.js culls the undrawn side of single-sided surfaces, so
 * a cube camera inside a wall, a column or a closed roof space sees through the surfaces around it
 * (their back faces) into the rest of the scene: such a capture is not the light at that place.
 * A point is {@link INSIDE} when more than `maxSeeThrough` of `rays` evenly spread rays first hit a
 * triangle from the side its material does not draw; it is {@link NEAR} when a triangle is within
 * `minDistance`; else {@link OPEN}. Rays that hit nothing (open sky) count as open.
 *
 * Ray parity (`classifyPoints`) cannot decide this here: the Basic room is one closed box seen from
 * inside, and Sponza's open roof and single-sided walls make crossings counts meaningless.
 */
export class OpenSpaceTest {

	readonly bvh: TriangleBVH;
	readonly sides: Int8Array;
	readonly directions: Float64Array;
	readonly minDistance: number;
	readonly maxSeeThrough: number;
	readonly maxSky: number;
	/** Per triangle: its geometric normal (not normalised), from the winding. */
	private readonly normals: Float64Array;
	private readonly stack = new Int32Array( 64 );

	/**
	 * @param triangles 9 floats per triangle, world space.
	 * @param sides Per triangle: 1 front side drawn, −1 back side drawn, 0 both.
	 */
	constructor( triangles: ArrayLike<number>, sides: ArrayLike<number>, options: OpenSpaceOptions ) {

		if ( sides.length * 9 !== triangles.length ) throw new RangeError( `OpenSpaceTest: ${sides.length} sides for ${triangles.length / 9} triangles.` );
		this.bvh = new TriangleBVH( triangles );
		this.sides = Int8Array.from( sides );
		this.directions = sphereDirections( options.rays ?? 32 );
		this.minDistance = options.minDistance;
		this.maxSeeThrough = options.maxSeeThrough ?? 0.1;
		this.maxSky = options.maxSky ?? 1;
		const t = this.bvh.triangles, count = this.sides.length;
		this.normals = new Float64Array( 3 * count );
		for ( let i = 0; i < count; i ++ ) {

			const k = 9 * i;
			const e1x = t[ k + 3 ] - t[ k ], e1y = t[ k + 4 ] - t[ k + 1 ], e1z = t[ k + 5 ] - t[ k + 2 ];
			const e2x = t[ k + 6 ] - t[ k ], e2y = t[ k + 7 ] - t[ k + 1 ], e2z = t[ k + 8 ] - t[ k + 2 ];
			this.normals[ 3 * i ] = e1y * e2z - e1z * e2y;
			this.normals[ 3 * i + 1 ] = e1z * e2x - e1x * e2z;
			this.normals[ 3 * i + 2 ] = e1x * e2y - e1y * e2x;

		}

	}

	/** {@link OPEN}, {@link NEAR}, {@link INSIDE} or {@link OUTSIDE}. */
	classify( x: number, y: number, z: number ): number {

		if ( this.minDistance > 0 && this.bvh.anyWithin( x, y, z, this.minDistance ) ) return NEAR;
		const { seeThrough, sky } = this.rays( x, y, z );
		if ( seeThrough > this.maxSeeThrough ) return INSIDE;
		return sky > this.maxSky ? OUTSIDE : OPEN;

	}

	/**
	 * Of the rays from (x, y, z): the fraction whose first hit is an undrawn side (`seeThrough`) and
	 * the fraction that hit nothing (`sky`).
	 */
	rays( x: number, y: number, z: number ): { seeThrough: number; sky: number } {

		const d = this.directions, rays = d.length / 3;
		let through = 0, sky = 0;
		for ( let r = 0; r < rays; r ++ ) {

			const dx = d[ 3 * r ], dy = d[ 3 * r + 1 ], dz = d[ 3 * r + 2 ];
			const hit = this.firstHit( x, y, z, dx, dy, dz );
			if ( hit < 0 ) { sky ++; continue; }
			const side = this.sides[ hit ];
			if ( side === 0 ) continue;
			const facing = this.normals[ 3 * hit ] * dx + this.normals[ 3 * hit + 1 ] * dy + this.normals[ 3 * hit + 2 ] * dz;
			// The ray meets the triangle's front (counter-clockwise) side when it runs against the normal.
			const front = facing < 0;
			if ( front !== ( side > 0 ) ) through ++;

		}

		return { seeThrough: through / rays, sky: sky / rays };

	}

	/** Index of the nearest triangle the ray o + t·d (t > 0) hits, or −1. */
	firstHit( ox: number, oy: number, oz: number, dx: number, dy: number, dz: number ): number {

		const bvh = this.bvh, bounds = bvh.nodeBounds, right = bvh.rightOrStart, counts = bvh.nodeTriangleCounts, order = bvh.order,
			stack = this.stack;
		if ( counts.length === 0 ) return - 1;
		const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
		let best = - 1, bestT = Infinity, top = 0;
		stack[ top ++ ] = 0;
		while ( top > 0 ) {

			const node = stack[ -- top ];
			if ( rayBoxEntry( bounds, 6 * node, ox, oy, oz, ix, iy, iz ) >= bestT ) continue;
			const count = counts[ node ];
			if ( count > 0 ) {

				for ( let i = right[ node ], end = i + count; i < end; i ++ ) {

					const t = intersectRayTriangle( bvh.triangles, order[ i ], ox, oy, oz, dx, dy, dz );
					if ( t > 0 && t < bestT ) { bestT = t; best = order[ i ]; }

				}

			} else {

				stack[ top ++ ] = right[ node ];
				stack[ top ++ ] = node + 1;

			}

		}

		return best;

	}

}

/** Where the ray enters the box (0 when it starts inside), or Infinity when it misses. */
function rayBoxEntry( bounds: Float64Array, b: number, ox: number, oy: number, oz: number, ix: number, iy: number, iz: number ): number {

	let near = 0, far = Infinity;
	for ( let a = 0; a < 3; a ++ ) {

		const o = a === 0 ? ox : a === 1 ? oy : oz, inv = a === 0 ? ix : a === 1 ? iy : iz;
		let t0 = ( bounds[ b + a ] - o ) * inv, t1 = ( bounds[ b + 3 + a ] - o ) * inv;
		// 0 · ∞ (origin on a slab plane of a ray parallel to it): inside that slab.
		if ( t0 !== t0 ) t0 = - Infinity;
		if ( t1 !== t1 ) t1 = Infinity;
		if ( t0 > t1 ) { const s = t0; t0 = t1; t1 = s; }
		if ( t0 > near ) near = t0;
		if ( t1 < far ) far = t1;

	}

	return near <= far ? near : Infinity;

}

/** Anything that sorts points into {@link OPEN}, {@link NEAR} and {@link INSIDE}. */
export interface PointClassifier { classify( x: number, y: number, z: number ): number }

/** Result of {@link sampleOpenSpace}. */
export interface OpenSpaceSamples {

	/** x, y, z per sample, in the order drawn. */
	positions: Float64Array;

	/** Points drawn in the box, rejected ones included. */
	drawn: number;

	/** Rejected as {@link NEAR} / {@link INSIDE} / {@link OUTSIDE}. */
	near: number;
	inside: number;
	outside: number;

}

/**
 * `count` points uniformly distributed over the open space inside `box`: uniform draws in the box
 * (from `mulberry32( seed )`), keeping those the classifier calls {@link OPEN}. The same inputs
 * give the same points.
 * @throws Error when fewer than `count` are found in `maxDraws` draws.
 */
export function sampleOpenSpace(
	classifier: PointClassifier, box: Box, count: number, seed: number, maxDraws = 200 * count
): OpenSpaceSamples {

	const random = mulberry32( seed );
	const positions = new Float64Array( 3 * count );
	let kept = 0, drawn = 0, near = 0, inside = 0, outside = 0;
	while ( kept < count ) {

		if ( drawn >= maxDraws ) throw new Error( `sampleOpenSpace: only ${kept} of ${count} points in open space after ${drawn} draws (${near} near a surface, ${inside} inside geometry, ${outside} outside the interior).` );
		drawn ++;
		const x = box.min[ 0 ] + random() * ( box.max[ 0 ] - box.min[ 0 ] );
		const y = box.min[ 1 ] + random() * ( box.max[ 1 ] - box.min[ 1 ] );
		const z = box.min[ 2 ] + random() * ( box.max[ 2 ] - box.min[ 2 ] );
		const c = classifier.classify( x, y, z );
		if ( c === NEAR ) { near ++; continue; }
		if ( c === INSIDE ) { inside ++; continue; }
		if ( c === OUTSIDE ) { outside ++; continue; }
		positions[ 3 * kept ] = x; positions[ 3 * kept + 1 ] = y; positions[ 3 * kept + 2 ] = z;
		kept ++;

	}

	return { positions, drawn, near, inside, outside };

}

/**
 * A regular grid over `box` with about `spacing` between points (at least 2 per axis, ends on the
 * box's faces), each point moved by up to ±`jitter`·spacing per axis (seeded) and clamped to the box.
 */
export function jitteredGrid( box: Box, spacing: number, jitter: number, seed: number ): Float64Array {

	const random = mulberry32( seed );
	const counts = [ 0, 1, 2 ].map( ( a ) => Math.max( 2, Math.round( ( box.max[ a ] - box.min[ a ] ) / spacing ) + 1 ) );
	const out = new Float64Array( 3 * counts[ 0 ] * counts[ 1 ] * counts[ 2 ] );
	let o = 0;
	for ( let k = 0; k < counts[ 2 ]; k ++ ) for ( let j = 0; j < counts[ 1 ]; j ++ ) for ( let i = 0; i < counts[ 0 ]; i ++ ) {

		const index = [ i, j, k ];
		for ( let a = 0; a < 3; a ++ ) {

			const step = ( box.max[ a ] - box.min[ a ] ) / ( counts[ a ] - 1 );
			const v = box.min[ a ] + index[ a ] * step + ( 2 * random() - 1 ) * jitter * step;
			out[ o ++ ] = Math.min( box.max[ a ], Math.max( box.min[ a ], v ) );

		}

	}

	return out;

}

/**
 * Candidates from the scene's vertices (paper 2.1) with the library's `candidatesFromVertices`,
 * each triangle corner moved `offset` along the normal of the side its material draws (both sides
 * for double-sided ones) — not the vertex normal attribute, which points out of a room drawn
 * from inside (`BackSide`) — then kept inside `box`.
 */
export function vertexCandidates(
	triangles: ArrayLike<number>, sides: ArrayLike<number>, box: Box, offset: number, minSpacing: number
): Float64Array {

	const positions: number[] = [], normals: number[] = [];
	for ( let t = 0; t < sides.length; t ++ ) {

		const k = 9 * t;
		const e1x = triangles[ k + 3 ] - triangles[ k ], e1y = triangles[ k + 4 ] - triangles[ k + 1 ],
			e1z = triangles[ k + 5 ] - triangles[ k + 2 ];
		const e2x = triangles[ k + 6 ] - triangles[ k ], e2y = triangles[ k + 7 ] - triangles[ k + 1 ],
			e2z = triangles[ k + 8 ] - triangles[ k + 2 ];
		const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
		if ( ! ( nx * nx + ny * ny + nz * nz > 0 ) ) continue;
		const signs = sides[ t ] === 0 ? [ 1, - 1 ] : [ sides[ t ] ];
		for ( const s of signs ) for ( let c = 0; c < 3; c ++ ) {

			const x = triangles[ k + 3 * c ], y = triangles[ k + 3 * c + 1 ], z = triangles[ k + 3 * c + 2 ];
			// Only corners that can land in the box (a loose test; the exact one follows).
			if ( x < box.min[ 0 ] - offset || x > box.max[ 0 ] + offset ||
				y < box.min[ 1 ] - offset || y > box.max[ 1 ] + offset ||
				z < box.min[ 2 ] - offset || z > box.max[ 2 ] + offset ) continue;
			positions.push( x, y, z );
			normals.push( s * nx, s * ny, s * nz );

		}

	}

	if ( positions.length === 0 ) return new Float64Array( 0 );
	const moved = candidatesFromVertices( positions, normals, { offset, minSpacing } );
	const out: number[] = [];
	for ( let i = 0; i < moved.length; i += 3 ) {

		if ( insideBox( box, moved[ i ], moved[ i + 1 ], moved[ i + 2 ] ) ) out.push( moved[ i ], moved[ i + 1 ], moved[ i + 2 ] );

	}

	return Float64Array.from( out );

}

/** Keeps the points the classifier calls {@link OPEN}; returns them and the per-class counts. */
export function keepOpen(
	classifier: PointClassifier, points: ArrayLike<number>
): { positions: Float64Array; near: number; inside: number; outside: number } {

	const out: number[] = [];
	let near = 0, inside = 0, outside = 0;
	for ( let i = 0; i < points.length; i += 3 ) {

		const c = classifier.classify( points[ i ], points[ i + 1 ], points[ i + 2 ] );
		if ( c === NEAR ) near ++;
		else if ( c === INSIDE ) inside ++;
		else if ( c === OUTSIDE ) outside ++;
		else out.push( points[ i ], points[ i + 1 ], points[ i + 2 ] );

	}

	return { positions: Float64Array.from( out ), near, inside, outside };

}

/** Greedy thinning in order: the indices of the points kept, dropping every point closer than `spacing` to one kept before it. */
export function thinIndices( points: ArrayLike<number>, spacing: number ): Uint32Array {

	const kept: number[] = [];
	const s2 = spacing * spacing;
	const cells = new Map<string, number[]>();
	const key = ( x: number, y: number, z: number ) => `${x},${y},${z}`;
	for ( let p = 0; 3 * p < points.length; p ++ ) {

		const x = points[ 3 * p ], y = points[ 3 * p + 1 ], z = points[ 3 * p + 2 ];
		const cx = Math.floor( x / spacing ), cy = Math.floor( y / spacing ), cz = Math.floor( z / spacing );
		let free = true;
		search: for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

			for ( const q of cells.get( key( cx + dx, cy + dy, cz + dz ) ) ?? [] ) {

				const ex = points[ 3 * q ] - x, ey = points[ 3 * q + 1 ] - y, ez = points[ 3 * q + 2 ] - z;
				if ( ex * ex + ey * ey + ez * ez < s2 ) { free = false; break search; }

			}

		}

		if ( ! free ) continue;
		const cell = key( cx, cy, cz );
		if ( ! cells.has( cell ) ) cells.set( cell, [] );
		cells.get( cell )!.push( p );
		kept.push( p );

	}

	return Uint32Array.from( kept );

}

export function insideBox( box: Box, x: number, y: number, z: number ): boolean {

	return x >= box.min[ 0 ] && x <= box.max[ 0 ] && y >= box.min[ 1 ] && y <= box.max[ 1 ] && z >= box.min[ 2 ] && z <= box.max[ 2 ];

}
