import { cellHash } from '../geometry/cellHash.js';

/**
 * The first `count` points of `points` (x, y, z each) thinned so that no two kept ones are closer
 * than `spacing` (> 0): greedy in index order — a point is kept unless an already kept one lies
 * within `spacing` — so every dropped point has a kept one within `spacing`, and the same input
 * gives the same output. A hashed grid of cells `spacing` wide (a chained hash table in typed
 * arrays: `head` per bucket, `next` per kept point) limits each test to the 27 neighbouring cells.
 * @returns Flat x, y, z per kept point, in index order.
 */
export function thinToSpacing( points: Float64Array, count: number, spacing: number ): Float64Array {

	let buckets = 1;
	while ( buckets < 2 * count ) buckets *= 2;
	const mask = buckets - 1;
	const head = new Int32Array( buckets ).fill( - 1 );
	const next = new Int32Array( count );
	const kept = new Float64Array( 3 * count );
	const spacingSquared = spacing * spacing, inverse = 1 / spacing;
	let keptCount = 0;

	for ( let i = 0; i < count; i ++ ) {

		const x = points[ 3 * i ], y = points[ 3 * i + 1 ], z = points[ 3 * i + 2 ];
		const cx = Math.floor( x * inverse ), cy = Math.floor( y * inverse ), cz = Math.floor( z * inverse );
		let free = true;
		search: for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

			for ( let k = head[ cellHash( cx + dx, cy + dy, cz + dz ) & mask ]; k !== - 1; k = next[ k ] ) {

				const ex = kept[ 3 * k ] - x, ey = kept[ 3 * k + 1 ] - y, ez = kept[ 3 * k + 2 ] - z;
				if ( ex * ex + ey * ey + ez * ez < spacingSquared ) {

					free = false;
					break search;

				}

			}

		}

		if ( ! free ) continue;
		const o = 3 * keptCount;
		kept[ o ] = x; kept[ o + 1 ] = y; kept[ o + 2 ] = z;
		const bucket = cellHash( cx, cy, cz ) & mask;
		next[ keptCount ] = head[ bucket ];
		head[ bucket ] = keptCount ++;

	}

	return kept.slice( 0, 3 * keptCount );

}
