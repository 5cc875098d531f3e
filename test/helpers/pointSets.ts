/** Deterministic point sets for tests and benchmarks. */
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/** The library's seeded PRNG (mulberry32), so every run sees the same points. */
export const seededRandom = mulberry32;

/** n uniform random points in [0, size)³. */
export function randomPoints( n: number, seed: number, size = 1 ): Float64Array {

	const random = seededRandom( seed );
	const points = new Float64Array( 3 * n );
	for ( let i = 0; i < points.length; i ++ ) points[ i ] = random() * size;
	return points;

}

/** A regular grid nx × ny × nz with coordinates `i * spacing` (0.1 is inexact in binary: near co-spherical). */
export function gridPoints( nx: number, ny: number, nz: number, spacing = 0.1 ): Float64Array {

	const points = new Float64Array( 3 * nx * ny * nz );
	let o = 0;
	for ( let k = 0; k < nz; k ++ ) for ( let j = 0; j < ny; j ++ ) for ( let i = 0; i < nx; i ++ ) {

		points[ o ++ ] = i * spacing; points[ o ++ ] = j * spacing; points[ o ++ ] = k * spacing;

	}

	return points;

}

/** Every integer point on the sphere x² + y² + z² = r²: exactly co-spherical in floating point. */
export function integerSpherePoints( r: number ): Float64Array {

	const out: number[] = [];
	for ( let x = - r; x <= r; x ++ ) for ( let y = - r; y <= r; y ++ ) for ( let z = - r; z <= r; z ++ ) {

		if ( x * x + y * y + z * z === r * r ) out.push( x, y, z );

	}

	return Float64Array.from( out );

}
