import { cellHash } from './cellHash.js';
import { boundsOf } from './boundsOf.js';

/**
 * How close two triangle corners must be to count as one vertex, relative to the diagonal of the
 * triangles' bounding box: float32 geometry and per-mesh matrices put corners that a modeller
 * snapped together up to ~1e-7 of the scene's size apart (three's SphereGeometry seam, pieces of a
 * level placed by separate matrices), far below any gap meant to be there.
 */
export const WELD_TOLERANCE = 1e-6;

/**
 * One vertex id per triangle corner, equal for corners within `WELD_TOLERANCE` × the bounding
 * box's diagonal of each other: the topology of a triangle soup, as three's meshes give it
 * (BoxGeometry repeats its corners per face, SphereGeometry its seam, a level its shared walls in
 * separate meshes). Greedy in corner order — a corner takes the id of the first earlier one within
 * the tolerance — with a hashed grid of cells one tolerance wide, so each corner tests the corners
 * of its 27 neighbouring cells: O(n), deterministic.
 * @param triangles 9 floats (a, b, c) per triangle.
 * @returns `ids[ 3 · t + k ]`: the vertex id of corner k of triangle t, numbered from 0 in order of
 * first use; `count`: the number of ids.
 */
export function weldCorners( triangles: ArrayLike<number> ): { ids: Uint32Array; count: number } {

	const corners = Math.floor( triangles.length / 3 );
	const ids = new Uint32Array( corners );
	const box = boundsOf( triangles, corners );
	const diagonal = Math.hypot( box[ 3 ] - box[ 0 ], box[ 4 ] - box[ 1 ], box[ 5 ] - box[ 2 ] );
	const tolerance = WELD_TOLERANCE * diagonal;
	// All corners in one point (or none): one vertex.
	if ( ! ( tolerance > 0 ) ) return { ids, count: corners > 0 ? 1 : 0 };

	let buckets = 1;
	while ( buckets < 2 * corners ) buckets *= 2;
	const mask = buckets - 1;
	const head = new Int32Array( buckets ).fill( - 1 );
	// Per id: its first corner (the representative) and the next id in the same bucket.
	const representative = new Uint32Array( corners ), next = new Int32Array( corners );
	const inverse = 1 / tolerance, toleranceSquared = tolerance * tolerance;
	let count = 0;
	for ( let c = 0; c < corners; c ++ ) {

		const x = triangles[ 3 * c ], y = triangles[ 3 * c + 1 ], z = triangles[ 3 * c + 2 ];
		const cx = Math.floor( x * inverse ), cy = Math.floor( y * inverse ), cz = Math.floor( z * inverse );
		// The corner's own cell first: copies of one vertex (the usual case) are found in one lookup.
		let found = - 1;
		for ( let n = 0; n < 27 && found < 0; n ++ ) {

			const m = n === 0 ? 13 : n <= 13 ? n - 1 : n; // 13 is (0, 0, 0)
			const bucket = cellHash( cx + ( m % 3 ) - 1, cy + ( Math.floor( m / 3 ) % 3 ) - 1, cz + Math.floor( m / 9 ) - 1 ) & mask;
			for ( let id = head[ bucket ]; id !== - 1; id = next[ id ] ) {

				const r = 3 * representative[ id ];
				const ex = triangles[ r ] - x, ey = triangles[ r + 1 ] - y, ez = triangles[ r + 2 ] - z;
				if ( ex * ex + ey * ey + ez * ez <= toleranceSquared ) {

					found = id;
					break;

				}

			}

		}

		if ( found < 0 ) {

			found = count ++;
			representative[ found ] = c;
			const bucket = cellHash( cx, cy, cz ) & mask;
			next[ found ] = head[ bucket ];
			head[ bucket ] = found;

		}

		ids[ c ] = found;

	}

	return { ids, count };

}
