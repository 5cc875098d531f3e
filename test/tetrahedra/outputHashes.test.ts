import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { DynamicTetrahedralization } from '../../src/tetrahedra/DynamicTetrahedralization.js';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { gridPoints, integerSpherePoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * Byte-for-byte stability of the output: the other tests check that a mesh is a valid Delaunay
 * tetrahedralization, which any order of its cells and any slot reuse would pass; these hashes pin
 * the exact arrays (cell order, vertex order in each cell, neighbour ids) so that a speed-up of the
 * builder cannot change what callers and baked files get. The hashes were computed from the code
 * of 83c1299, before the speed work of issue 16; the sets are those of bench/datasets.ts (same
 * seeds, same generators) plus a few degenerate ones. A hash changes if one byte of the output does.
 */

/** First 16 hex digits of the SHA-256 of tetrahedra, neighbors and duplicates, in that order. */
function digest( result: { tetrahedra: Uint32Array; neighbors: Int32Array; duplicates: Uint32Array } ): string {

	const hash = createHash( 'sha256' );
	for ( const array of [ result.tetrahedra, result.neighbors, result.duplicates ] ) {

		hash.update( new Uint8Array( array.buffer, array.byteOffset, array.byteLength ) );

	}

	return hash.digest( 'hex' ).slice( 0, 16 );

}

/** 2,000 random points, then 50 exact copies and 50 copies moved by 1e-12 (all 100 merged: the hash covers `duplicates`). */
function withDuplicates(): Float64Array {

	const base = randomPoints( 2000, 21 );
	const points = new Float64Array( base.length + 300 );
	points.set( base );
	for ( let i = 0; i < 100; i ++ ) {

		for ( let a = 0; a < 3; a ++ ) points[ base.length + 3 * i + a ] = base[ 3 * 19 * i + a ] + ( i < 50 ? 0 : 1e-12 );

	}

	return points;

}

/** Points on the faces of a cube, 7 per edge, plus its centre (many coplanar hull points). */
function cubeFaces(): Float64Array {

	const out: number[] = [];
	for ( let i = 0; i <= 6; i ++ ) for ( let j = 0; j <= 6; j ++ ) for ( let k = 0; k <= 6; k ++ ) {

		if ( i === 0 || i === 6 || j === 0 || j === 6 || k === 0 || k === 6 ) out.push( i / 6, j / 6, k / 6 );

	}

	out.push( 0.5, 0.5, 0.5 );
	return Float64Array.from( out );

}

describe( 'tetrahedralize: output bytes are pinned', () => {

	const cases: [ string, () => Float64Array, number, string ][] = [
		[ 'grid 12x6x6 (bench)', () => gridPoints( 12, 6, 6, 0.1 ), 1650, 'dab719535df311df' ],
		[ 'random 1k (bench)', () => randomPoints( 1000, 1 ), 6338, 'a27c5de5224c8861' ],
		[ 'random 10k (bench)', () => randomPoints( 10000, 2 ), 66557, '6964553ccccd7ebd' ],
		[ 'grid 40³ (bench)', () => gridPoints( 40, 40, 40, 0.1 ), 355914, '7a370e4ca8bb11a6' ],
		[ 'random 100k (bench)', () => randomPoints( 100000, 3 ), 672633, '765509ada0c3fe52' ],
		[ 'integer sphere of radius 9 (all co-spherical)', () => integerSpherePoints( 9 ), 383, '67a170a21a92641f' ],
		[ 'random 2,000 with 100 duplicates', withDuplicates, 12915, '834dbf8e2d54db69' ],
		[ 'cube faces and centre', cubeFaces, 558, 'bb3a41a820602ac3' ],
		[ 'random 3,000 scaled by 2^30 and offset by 1e9', () => randomPoints( 3000, 4 ).map( ( v ) => v * 2 ** 30 + 1e9 ), 19712, '37e76cedb68a8d39' ],
	];
	for ( const [ name, points, count, expected ] of cases ) {

		it( name, () => {

			const result = tetrahedralize( points() );
			expect( result.tetrahedra.length / 4 ).toBe( count );
			expect( digest( result ) ).toBe( expected );

		} );

	}

} );

describe( 'DynamicTetrahedralization: output bytes after edits are pinned', () => {

	it( '500 random points, then 100 inserts, 100 removals and 100 moves', () => {

		const random = seededRandom( 31 );
		const mesh = new DynamicTetrahedralization( randomPoints( 500, 30 ) );
		for ( let i = 0; i < 100; i ++ ) mesh.insert( random(), random(), random() );
		for ( let i = 0; i < 100; i ++ ) mesh.remove( 5 * i + 1 );
		for ( let i = 0; i < 100; i ++ ) mesh.move( 5 * i + 2, random(), random(), random() );
		expect( digest( mesh.toTetrahedralization() ) ).toBe( 'e9e35ff4bbec6286' );

	} );

} );
