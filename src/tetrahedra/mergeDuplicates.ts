import { boundsOf } from '../geometry/boundsOf.js';

const _bounds = new Float64Array( 6 );

// Below this squared radius, squared distances may underflow: compare distances (hypot) instead.
const SQUARES_UNDERFLOW = 2 ** - 1000;

// Finest hashed cell, relative to the diagonal: cell indices stay exact integers (below 2^53)
// whatever the tolerance; a cell larger than the merge distance only costs comparisons.
const FINEST_CELL = 2 ** - 40;

/**
 * Finds points that coincide within `tolerance × diagonal` of the set's bounding box, with a
 * hashed uniform grid whose cell is the merge distance (so only the 27 surrounding cells can hold
 * a match). The first point of each group is kept.
 *
 * @param p Flat x, y, z coordinates, normalised (`normalizePoints`: squares neither over- nor underflow).
 * @param tolerance Merge distance as a fraction of the bounding-box diagonal.
 * @returns The kept point indices in input order, the merged pairs (merged, kept) flat, and the diagonal.
 */
export function mergeDuplicates( p: Float64Array, tolerance: number ): { unique: Uint32Array; duplicates: Uint32Array; diagonal: number } {

	const n = p.length / 3;
	const bounds = boundsOf( p, n, _bounds );
	const minX = bounds[ 0 ], minY = bounds[ 1 ], minZ = bounds[ 2 ], maxX = bounds[ 3 ], maxY = bounds[ 4 ], maxZ = bounds[ 5 ];
	const diagonal = Math.hypot( maxX - minX, maxY - minY, maxZ - minZ );
	const radius = tolerance * diagonal;
	const radius2 = radius * radius;

	const tableSize = nextPowerOfTwo( 2 * n );
	const mask = tableSize - 1;
	const head = new Int32Array( tableSize ).fill( - 1 );
	const next = new Int32Array( n );
	const keep = new Uint8Array( n );
	const pairs: number[] = [];
	const cell = Math.max( radius, diagonal * FINEST_CELL ) || 1;
	const squares = radius2 >= SQUARES_UNDERFLOW;

	for ( let i = 0; i < n; i ++ ) {

		const x = p[ 3 * i ], y = p[ 3 * i + 1 ], z = p[ 3 * i + 2 ];
		const cx = Math.floor( ( x - minX ) / cell ), cy = Math.floor( ( y - minY ) / cell ), cz = Math.floor( ( z - minZ ) / cell );

		let match = - 1;
		search: for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

			for ( let j = head[ hashCell( cx + dx, cy + dy, cz + dz ) & mask ]; j !== - 1; j = next[ j ] ) {

				const ex = p[ 3 * j ] - x, ey = p[ 3 * j + 1 ] - y, ez = p[ 3 * j + 2 ] - z;
				if ( squares ? ex * ex + ey * ey + ez * ez <= radius2 : Math.hypot( ex, ey, ez ) <= radius ) { match = j; break search; }

			}

		}

		if ( match >= 0 ) {

			pairs.push( i, match );
			continue;

		}

		keep[ i ] = 1;
		const h = hashCell( cx, cy, cz ) & mask;
		next[ i ] = head[ h ];
		head[ h ] = i;

	}

	const unique = new Uint32Array( n - pairs.length / 2 );
	for ( let i = 0, k = 0; i < n; i ++ ) if ( keep[ i ] ) unique[ k ++ ] = i;
	return { unique, duplicates: Uint32Array.from( pairs ), diagonal };

}

function hashCell( x: number, y: number, z: number ): number {

	return ( Math.imul( x | 0, 73856093 ) ^ Math.imul( y | 0, 19349663 ) ^ Math.imul( z | 0, 83492791 ) ) >>> 0;

}

function nextPowerOfTwo( v: number ): number {

	let size = 16;
	while ( size < v ) size *= 2;
	return size;

}
