import { hitsBox, type RayHit, type TriangleBVH } from './TriangleBVH.js';
import { intersectRayTriangle } from './intersectRayTriangle.js';

// Traversal stack (the BVH's depth is about log2(n / 4); 64 covers any array that fits in memory).
const _stack = new Int32Array( 64 );

/**
 * One ray o + t · d (t > 0) through every triangle of `bvh`: writes the nearest hit into `first`
 * (−1, −1 when nothing is hit) and returns the winding number of the origin with respect to the
 * oriented shells it crossed — Σ orientation[ tri ] · sign( d · n ) over the hits, n the winding
 * normal: +1 for each shell surface the ray leaves an enclosed solid through, −1 for each it
 * enters one through. A ray from inside k overlapping solids returns k (it ends outside them all);
 * triangles with orientation 0 only count for `first`. Allocation-free.
 * @param orientation Per triangle of `bvh`: +1 / −1 (see `findClosedShells`), 0 for none.
 */
export function windingAlongRay(
	bvh: TriangleBVH, orientation: Int8Array, ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, first: RayHit,
): number {

	const bounds = bvh.nodeBounds, right = bvh.rightOrStart, counts = bvh.nodeTriangleCounts, order = bvh.order, tri = bvh.triangles;
	const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
	let winding = 0, nearest = Infinity, nearestTriangle = - 1, top = 0;
	if ( counts.length > 0 ) _stack[ top ++ ] = 0;
	while ( top > 0 ) {

		const node = _stack[ -- top ];
		if ( ! hitsBox( bounds, 6 * node, ox, oy, oz, ix, iy, iz, Infinity ) ) continue;
		if ( counts[ node ] === 0 ) {

			_stack[ top ++ ] = right[ node ];
			_stack[ top ++ ] = node + 1;
			continue;

		}

		for ( let i = right[ node ], end = i + counts[ node ]; i < end; i ++ ) {

			const triangle = order[ i ];
			const t = intersectRayTriangle( tri, triangle, ox, oy, oz, dx, dy, dz );
			if ( t <= 0 ) continue;
			if ( t < nearest ) {

				nearest = t;
				nearestTriangle = triangle;

			}

			const sign = orientation[ triangle ];
			if ( sign !== 0 ) winding += facing( tri, triangle, dx, dy, dz ) > 0 ? sign : - sign;

		}

	}

	first.t = nearestTriangle < 0 ? - 1 : nearest;
	first.triangle = nearestTriangle;
	return winding;

}

/** d · n for triangle `triangle`'s winding normal n = (b − a) × (c − a): > 0 when the ray meets its back. */
export function facing( tri: ArrayLike<number>, triangle: number, dx: number, dy: number, dz: number ): number {

	const k = 9 * triangle;
	const e1x = tri[ k + 3 ] - tri[ k ], e1y = tri[ k + 4 ] - tri[ k + 1 ], e1z = tri[ k + 5 ] - tri[ k + 2 ];
	const e2x = tri[ k + 6 ] - tri[ k ], e2y = tri[ k + 7 ] - tri[ k + 1 ], e2z = tri[ k + 8 ] - tri[ k + 2 ];
	return dx * ( e1y * e2z - e1z * e2y ) + dy * ( e1z * e2x - e1x * e2z ) + dz * ( e1x * e2y - e1y * e2x );

}
