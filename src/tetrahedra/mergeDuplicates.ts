import { boundsOf } from '../geometry/boundsOf.js';

const _bounds = new Float64Array( 6 );

// Below this squared radius, squared distances may underflow: compare distances (hypot) instead.
const SQUARES_UNDERFLOW = 2 ** - 1000;

// Finest merge cell, relative to the diagonal: cell indices stay exact integers (below 2^53)
// whatever the tolerance; a cell larger than the merge distance only costs comparisons.
const FINEST_CELL = 2 ** - 40;

// The search grid's cells are SEARCH_SCALE merge cells wide: a point's matches lie in the merge
// cells at most 1 apart (2 with rounding), which span one or two search cells per axis.
const SEARCH_SCALE = 8;

/**
 * Finds points that coincide within `tolerance × diagonal` of the set's bounding box. The first point
 * of each group is kept; a point within the tolerance of several kept points is merged into the one
 * a scan of the 27 hashed merge cells around it meets first (the order: docs/incremental-delaunay.md,
 * "Duplicates").
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

		// Every kept point within the merge distance (its merge cell is at most 2 away per axis).
		let match = - 1, matchRank = Infinity;
		const gx0 = Math.floor( ( cx - 2 ) / SEARCH_SCALE ), gx1 = Math.floor( ( cx + 2 ) / SEARCH_SCALE );
		const gy0 = Math.floor( ( cy - 2 ) / SEARCH_SCALE ), gy1 = Math.floor( ( cy + 2 ) / SEARCH_SCALE );
		const gz0 = Math.floor( ( cz - 2 ) / SEARCH_SCALE ), gz1 = Math.floor( ( cz + 2 ) / SEARCH_SCALE );
		for ( let gz = gz0; gz <= gz1; gz ++ ) for ( let gy = gy0; gy <= gy1; gy ++ ) for ( let gx = gx0; gx <= gx1; gx ++ ) {

			for ( let j = head[ hashCell( gx, gy, gz ) & mask ]; j !== - 1; j = next[ j ] ) {

				const ex = p[ 3 * j ] - x, ey = p[ 3 * j + 1 ] - y, ez = p[ 3 * j + 2 ] - z;
				if ( ! ( squares ? ex * ex + ey * ey + ez * ez <= radius2 : Math.hypot( ex, ey, ez ) <= radius ) ) continue;
				const rank = scanRank( p, j, cx, cy, cz, minX, minY, minZ, cell, mask );
				if ( rank < matchRank || ( rank === matchRank && j > match ) ) {

					match = j;
					matchRank = rank;

				}

			}

		}

		if ( match >= 0 ) {

			pairs.push( i, match );
			continue;

		}

		keep[ i ] = 1;
		const h = hashCell( Math.floor( cx / SEARCH_SCALE ), Math.floor( cy / SEARCH_SCALE ), Math.floor( cz / SEARCH_SCALE ) ) & mask;
		next[ i ] = head[ h ];
		head[ h ] = i;

	}

	const unique = new Uint32Array( n - pairs.length / 2 );
	for ( let i = 0, k = 0; i < n; i ++ ) if ( keep[ i ] ) unique[ k ++ ] = i;
	return { unique, duplicates: Uint32Array.from( pairs ), diagonal };

}

/**
 * Where the 27-cell scan around merge cell ( cx, cy, cz ) meets kept point j: the first of the 27
 * cells (z, then y, then x from −1 to +1) whose hash-table bucket is j's merge cell's, Infinity if
 * none is (the scan would not see j). Within one bucket the scan meets the later kept points first.
 */
function scanRank(
	p: Float64Array, j: number, cx: number, cy: number, cz: number, minX: number, minY: number, minZ: number, cell: number, mask: number,
): number {

	const jx = Math.floor( ( p[ 3 * j ] - minX ) / cell ), jy = Math.floor( ( p[ 3 * j + 1 ] - minY ) / cell );
	const jz = Math.floor( ( p[ 3 * j + 2 ] - minZ ) / cell );
	const bucket = hashCell( jx, jy, jz ) & mask;
	let o = 0;
	for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

		if ( ( hashCell( cx + dx, cy + dy, cz + dz ) & mask ) === bucket ) return o;
		o ++;

	}

	return Infinity;

}

function hashCell( x: number, y: number, z: number ): number {

	return ( Math.imul( x | 0, 73856093 ) ^ Math.imul( y | 0, 19349663 ) ^ Math.imul( z | 0, 83492791 ) ) >>> 0;

}

function nextPowerOfTwo( v: number ): number {

	let size = 16;
	while ( size < v ) size *= 2;
	return size;

}
