import { intersectRayTriangle } from '../geometry/intersectRayTriangle.js';

// Hits this close to a lattice point (in lattice steps) do not block its edges: the same end
// tolerance as `TriangleBVH.segmentBlocked`, so the fill sees what the segment tests saw.
const END_EPSILON = 1e-6;

/** A lattice of points: point (i, j, k) at `origin + ( i, j, k ) · spacing`, `counts` points per axis. */
export interface Lattice {

	/** The position of point (0, 0, 0). */
	origin: ArrayLike<number>;

	/** The distance between neighbouring points, per axis (> 0 on every axis with more than one point). */
	spacing: ArrayLike<number>;

	/** Points per axis (≥ 1). */
	counts: ArrayLike<number>;

}

/**
 * Which edges between 6-neighbouring lattice points a triangle crosses — the answers of
 * `TriangleBVH.segmentBlocked` for every edge at once, found from the triangles' side: each
 * triangle is intersected with the lattice lines its bounding box spans (per axis, the lines along
 * that axis), and the edge holding the hit is marked. That costs about the lines each triangle
 * covers instead of a tree traversal per edge: the flood fill of `ReachableSpace` over 64³ points
 * tests up to 1.5 M edges, where a level's triangles cover a few lines each.
 * @returns Per axis a (x, y, z), per lattice point p (x fastest): 1 when the edge from p to its
 * neighbour one step along +a is blocked (the last point of a line has no such edge: 0).
 */
export function blockedLatticeEdges( triangles: ArrayLike<number>, lattice: Lattice ): [ Uint8Array, Uint8Array, Uint8Array ] {

	const { origin, spacing, counts } = lattice;
	const total = counts[ 0 ] * counts[ 1 ] * counts[ 2 ];
	const blocked: [ Uint8Array, Uint8Array, Uint8Array ] = [ new Uint8Array( total ), new Uint8Array( total ), new Uint8Array( total ) ];
	const stride = [ 1, counts[ 0 ], counts[ 0 ] * counts[ 1 ] ];
	const triangleCount = triangles.length / 9;
	for ( let a = 0; a < 3; a ++ ) {

		const n = counts[ a ];
		if ( n < 2 ) continue;
		// The lines along axis a are indexed by the other two axes b and c.
		const b = ( a + 1 ) % 3, c = ( a + 2 ) % 3;
		const out = blocked[ a ];
		const step = spacing[ a ], dx = a === 0 ? step : 0, dy = a === 1 ? step : 0, dz = a === 2 ? step : 0;
		const o = [ 0, 0, 0 ];
		o[ a ] = origin[ a ];
		for ( let t = 0; t < triangleCount; t ++ ) {

			const k = 9 * t;
			// The lines through the triangle's box, one more on each side against rounding (the exact test decides).
			const jFirst = firstLine( triangles, k, b, origin[ b ], spacing[ b ], counts[ b ] );
			const jLast = lastLine( triangles, k, b, origin[ b ], spacing[ b ], counts[ b ] );
			const kFirst = firstLine( triangles, k, c, origin[ c ], spacing[ c ], counts[ c ] );
			const kLast = lastLine( triangles, k, c, origin[ c ], spacing[ c ], counts[ c ] );
			for ( let j = jFirst; j <= jLast; j ++ ) {

				o[ b ] = origin[ b ] + j * spacing[ b ];
				for ( let l = kFirst; l <= kLast; l ++ ) {

					o[ c ] = origin[ c ] + l * spacing[ c ];
					// From the line's first point one lattice step at a time: the hit's t is in lattice steps.
					const hit = intersectRayTriangle( triangles, t, o[ 0 ], o[ 1 ], o[ 2 ], dx, dy, dz );
					if ( hit < 0 || hit >= n - 1 ) continue;
					const i = Math.floor( hit ), f = hit - i;
					if ( f <= END_EPSILON || f >= 1 - END_EPSILON ) continue;
					out[ i * stride[ a ] + j * stride[ b ] + l * stride[ c ] ] = 1;

				}

			}

		}

	}

	return blocked;

}

/** The first line index (along axis `b`) at or above the triangle's least coordinate, less one, clamped. */
function firstLine( triangles: ArrayLike<number>, k: number, b: number, origin: number, spacing: number, count: number ): number {

	if ( count < 2 ) return 0;
	const min = Math.min( triangles[ k + b ], triangles[ k + 3 + b ], triangles[ k + 6 + b ] );
	return Math.max( 0, Math.ceil( ( min - origin ) / spacing ) - 1 );

}

/** The last line index (along axis `b`) at or below the triangle's greatest coordinate, plus one, clamped. */
function lastLine( triangles: ArrayLike<number>, k: number, b: number, origin: number, spacing: number, count: number ): number {

	if ( count < 2 ) return 0;
	const max = Math.max( triangles[ k + b ], triangles[ k + 3 + b ], triangles[ k + 6 + b ] );
	return Math.min( count - 1, Math.floor( ( max - origin ) / spacing ) + 1 );

}
