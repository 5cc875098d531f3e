import { describe, expect, it } from 'vitest';
import { boundsOf } from '../../src/geometry/boundsOf.js';
import { mergeDuplicates } from '../../src/tetrahedra/mergeDuplicates.js';
import { seededRandom } from '../helpers/pointSets.js';

/*
 * mergeDuplicates decides which kept point a duplicate is merged into; that choice is part of the
 * output (`duplicates`, and which point the mesh keeps), so a faster search must make the same one.
 * The reference is the original search, kept here verbatim: a hash table of merge cells (as wide as
 * the merge distance), the 27 cells around each point scanned in z, y, x order, each bucket from the
 * last kept point back, the first point within the distance taken. The sets below put several kept
 * points within the merge distance of one point (clusters a little wider than it) and use few
 * points, so that the 16-bucket table makes cells collide: then the scan order alone decides.
 */

const SQUARES_UNDERFLOW = 2 ** - 1000;
const FINEST_CELL = 2 ** - 40;

function referenceHash( x: number, y: number, z: number ): number {

	return ( Math.imul( x | 0, 73856093 ) ^ Math.imul( y | 0, 19349663 ) ^ Math.imul( z | 0, 83492791 ) ) >>> 0;

}

/** The merge search of 83c1299 (before the speed work of issue 16). */
function referenceMerge( p: Float64Array, tolerance: number ): { unique: Uint32Array; duplicates: Uint32Array } {

	const n = p.length / 3;
	const bounds = boundsOf( p, n );
	const minX = bounds[ 0 ], minY = bounds[ 1 ], minZ = bounds[ 2 ];
	const diagonal = Math.hypot( bounds[ 3 ] - minX, bounds[ 4 ] - minY, bounds[ 5 ] - minZ );
	const radius = tolerance * diagonal, radius2 = radius * radius;
	let tableSize = 16;
	while ( tableSize < 2 * n ) tableSize *= 2;
	const mask = tableSize - 1;
	const head = new Int32Array( tableSize ).fill( - 1 ), next = new Int32Array( n ), keep = new Uint8Array( n );
	const pairs: number[] = [];
	const cell = Math.max( radius, diagonal * FINEST_CELL ) || 1;
	const squares = radius2 >= SQUARES_UNDERFLOW;
	for ( let i = 0; i < n; i ++ ) {

		const x = p[ 3 * i ], y = p[ 3 * i + 1 ], z = p[ 3 * i + 2 ];
		const cx = Math.floor( ( x - minX ) / cell ), cy = Math.floor( ( y - minY ) / cell ), cz = Math.floor( ( z - minZ ) / cell );
		let match = - 1;
		search: for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

			for ( let j = head[ referenceHash( cx + dx, cy + dy, cz + dz ) & mask ]; j !== - 1; j = next[ j ] ) {

				const ex = p[ 3 * j ] - x, ey = p[ 3 * j + 1 ] - y, ez = p[ 3 * j + 2 ] - z;
				if ( squares ? ex * ex + ey * ey + ez * ez <= radius2 : Math.hypot( ex, ey, ez ) <= radius ) { match = j; break search; }

			}

		}

		if ( match >= 0 ) {

			pairs.push( i, match );
			continue;

		}

		keep[ i ] = 1;
		const h = referenceHash( cx, cy, cz ) & mask;
		next[ i ] = head[ h ];
		head[ h ] = i;

	}

	const unique = new Uint32Array( n - pairs.length / 2 );
	for ( let i = 0, k = 0; i < n; i ++ ) if ( keep[ i ] ) unique[ k ++ ] = i;
	return { unique, duplicates: Uint32Array.from( pairs ) };

}

/** `clusters` clusters of `size` points each, spread over `spread` × the merge distance, in a unit box. */
function clusteredPoints( seed: number, clusters: number, size: number, tolerance: number, spread: number ): Float64Array {

	const random = seededRandom( seed );
	const points = new Float64Array( 3 * clusters * size );
	// The diagonal is about √3 (the corners pin the box), so the merge distance is about √3 · tolerance.
	const reach = spread * Math.sqrt( 3 ) * tolerance;
	for ( let c = 0; c < clusters; c ++ ) {

		const cx = random(), cy = random(), cz = random();
		for ( let k = 0; k < size; k ++ ) {

			const o = 3 * ( c * size + k );
			points[ o ] = cx + ( random() - 0.5 ) * reach;
			points[ o + 1 ] = cy + ( random() - 0.5 ) * reach;
			points[ o + 2 ] = cz + ( random() - 0.5 ) * reach;

		}

	}

	// Pin the bounding box to the unit cube.
	points.set( [ 0, 0, 0 ], 0 );
	points.set( [ 1, 1, 1 ], 3 );
	return points;

}

describe( 'mergeDuplicates: the same choices as the original 27-cell scan', () => {

	it( 'clusters a little wider than the merge distance: several kept points in reach, cells colliding in the table', () => {

		let merged = 0, cases = 0;
		for ( let seed = 1; seed <= 400; seed ++ ) {

			const tolerance = [ 0.002, 0.01, 0.05, 0.2 ][ seed % 4 ];
			const points = clusteredPoints( seed, 1 + ( seed % 5 ), 2 + ( seed % 9 ), tolerance, 1 + ( seed % 3 ) );
			const expected = referenceMerge( points, tolerance ), result = mergeDuplicates( points, tolerance );
			expect( Array.from( result.duplicates ), `seed ${seed}` ).toEqual( Array.from( expected.duplicates ) );
			expect( Array.from( result.unique ), `seed ${seed}` ).toEqual( Array.from( expected.unique ) );
			merged += expected.duplicates.length / 2;
			cases ++;

		}

		// The sets do merge points (the comparison is not between two empty lists).
		expect( merged ).toBeGreaterThan( cases );

	} );

	it( 'larger clustered sets, tolerance 0 with exact copies, and a merge distance whose squares underflow', () => {

		const sets: [ Float64Array, number ][] = [
			[ clusteredPoints( 7, 400, 6, 1e-9, 1.5 ), 1e-9 ],
			[ clusteredPoints( 8, 2000, 3, 1e-4, 2 ), 1e-4 ],
			[ clusteredPoints( 9, 300, 4, 1e-170, 1.8 ), 1e-170 ],
		];
		const copies = clusteredPoints( 10, 500, 1, 1e-9, 0 );
		const withCopies = new Float64Array( copies.length * 2 );
		withCopies.set( copies );
		withCopies.set( copies.subarray( 0, copies.length / 2 ), copies.length );
		withCopies.set( copies.subarray( 0, copies.length / 2 ), copies.length * 1.5 );
		sets.push( [ withCopies, 0 ] );
		for ( const [ points, tolerance ] of sets ) {

			const expected = referenceMerge( points, tolerance ), result = mergeDuplicates( points, tolerance );
			expect( expected.duplicates.length ).toBeGreaterThan( 0 );
			expect( Array.from( result.duplicates ) ).toEqual( Array.from( expected.duplicates ) );
			expect( Array.from( result.unique ) ).toEqual( Array.from( expected.unique ) );

		}

	} );

} );
