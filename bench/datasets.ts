/**
 * Deterministic point sets for the benchmarks: the same seeds give the same points on every
 * machine, so figures from different runs compare. Points are flat xyz in a Float64Array.
 */

import { readFileSync, writeFileSync } from 'node:fs';
import { mulberry32 } from '../src/tetrahedra/spatialOrder.js';

export interface Dataset {
	/** Short name used in tables, e.g. `'random 10k'`. */
	name: string;
	/** Flat x, y, z per point. */
	points: Float64Array;
	/** For grids: the number of points along x, y, z; absent for random sets. */
	grid?: [ number, number, number ];
}

/** mulberry32: the library's small seeded PRNG, floats in [0, 1). */
export { mulberry32 };

/** `count` points uniformly random in the unit cube. */
export function randomPoints( name: string, count: number, seed: number ): Dataset {

	const random = mulberry32( seed );
	const points = new Float64Array( count * 3 );
	for ( let i = 0; i < points.length; i ++ ) points[ i ] = random();
	return { name, points };

}

/**
 * A regular grid of nx × ny × nz points, coordinates computed as `i * spacing` — inexact floats
 * (3 * 0.1 = 0.30000000000000004), so the cells are only nearly cubes and nearly co-spherical:
 * the hard case for a Delaunay tetrahedralization.
 */
export function gridPoints( name: string, nx: number, ny: number, nz: number, spacing = 0.1 ): Dataset {

	const points = new Float64Array( nx * ny * nz * 3 );
	let p = 0;
	for ( let k = 0; k < nz; k ++ ) {

		for ( let j = 0; j < ny; j ++ ) {

			for ( let i = 0; i < nx; i ++ ) {

				points[ p ++ ] = i * spacing;
				points[ p ++ ] = j * spacing;
				points[ p ++ ] = k * spacing;

			}

		}

	}

	return { name, points, grid: [ nx, ny, nz ] };

}

/** Every benchmark point set, smallest first (peers that time out skip the larger ones). */
export function allDatasets(): Dataset[] {

	return [
		gridPoints( 'grid 12x6x6', 12, 6, 6 ),
		randomPoints( 'random 1k', 1000, 1 ),
		randomPoints( 'random 10k', 10000, 2 ),
		gridPoints( 'grid 40³', 40, 40, 40 ),
		randomPoints( 'random 100k', 100000, 3 ),
	];

}

export function pointCount( dataset: Dataset ): number {

	return dataset.points.length / 3;

}

/** Volume of the axis-aligned box around the points (for a grid: the volume its tetrahedra must fill). */
export function boxVolume( points: ArrayLike<number> ): number {

	const min = [ Infinity, Infinity, Infinity ];
	const max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < points.length; i ++ ) {

		const axis = i % 3;
		min[ axis ] = Math.min( min[ axis ], points[ i ] );
		max[ axis ] = Math.max( max[ axis ], points[ i ] );

	}

	return ( max[ 0 ] - min[ 0 ] ) * ( max[ 1 ] - min[ 1 ] ) * ( max[ 2 ] - min[ 2 ] );

}

/** Writes the points as little-endian float64 xyz, the format the CGAL and peer processes read. */
export function writePointsFile( path: string, points: Float64Array ): void {

	const bytes = new Uint8Array( points.length * 8 );
	const view = new DataView( bytes.buffer );
	for ( let i = 0; i < points.length; i ++ ) view.setFloat64( i * 8, points[ i ], true );
	writeFileSync( path, bytes );

}

/** Reads a file written by `writePointsFile`. */
export function readPointsFile( path: string ): Float64Array {

	const bytes = readFileSync( path );
	const view = new DataView( bytes.buffer, bytes.byteOffset, bytes.byteLength );
	const points = new Float64Array( bytes.byteLength / 8 );
	for ( let i = 0; i < points.length; i ++ ) points[ i ] = view.getFloat64( i * 8, true );
	return points;

}
