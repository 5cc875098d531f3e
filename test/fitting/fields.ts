import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/*
 * Layouts and fields for the fitting tests, with their truth known in closed form.
 */

/** A 4×4×4 lattice over [−2, 2]³, interior probes jittered by ±0.2 (corners stay: the hull is the cube). */
export function jitteredLattice( seed = 1 ): Float64Array {

	const random = mulberry32( seed );
	const out: number[] = [];
	for ( let k = 0; k < 4; k ++ ) for ( let j = 0; j < 4; j ++ ) for ( let i = 0; i < 4; i ++ ) {

		const onHull = i === 0 || i === 3 || j === 0 || j === 3 || k === 0 || k === 3;
		const jitter = (): number => ( onHull ? 0 : 0.4 * ( random() - 0.5 ) );
		out.push( - 2 + 4 * i / 3 + jitter(), - 2 + 4 * j / 3 + jitter(), - 2 + 4 * k / 3 + jitter() );

	}

	return Float64Array.from( out );

}

/** `count` points uniform in the box [min, max]³. */
export function randomPoints( count: number, min: number, max: number, seed: number ): Float64Array {

	const random = mulberry32( seed );
	return Float64Array.from( { length: 3 * count }, () => min + ( max - min ) * random() );

}

/** SH field value at a point: 27 floats written at `out[ offset ]`. */
export type Field = ( x: number, y: number, z: number, out: Float64Array, offset: number ) => void;

/** A field linear in position: L00 bright enough that irradiance stays positive in the box ±3. */
export const linearField: Field = ( x, y, z, out, offset ) => {

	for ( let k = 0; k < 27; k ++ ) {

		const base = k < 3 ? 4 + 0.5 * k : 0.05 * ( ( k % 5 ) - 2 );
		out[ offset + k ] = base + 0.1 * x * ( ( k % 3 ) + 1 ) - 0.07 * y + 0.02 * z * ( ( k % 4 ) - 1.5 );

	}

};

/**
 * A point light's SH9 seen from (x, y, z) plus a constant ambient: the light at `light`, intensity
 * falling as 1/r² (smoothed by 0.25 so it stays finite): radiance from one direction projected to SH,
 * the L1 band toward the light, a faint L2 band. Not linear: a layout cannot represent it exactly.
 */
export function pointLightField( light: readonly number[] = [ 0.6, 1.2, - 0.4 ] ): Field {

	const Y00 = 0.282095, Y1 = 0.488603, Y2 = 1.092548, Y20 = 0.315392, Y22 = 0.546274;
	return ( x, y, z, out, offset ) => {

		const dx = light[ 0 ] - x, dy = light[ 1 ] - y, dz = light[ 2 ] - z;
		const r2 = dx * dx + dy * dy + dz * dz + 0.25, r = Math.sqrt( r2 );
		const e = 2 / r2, ux = dx / r, uy = dy / r, uz = dz / r;
		const basis = [
			Y00, Y1 * uy, Y1 * uz, Y1 * ux, Y2 * ux * uy, Y2 * uy * uz,
			Y20 * ( 3 * uz * uz - 1 ), Y2 * ux * uz, Y22 * ( ux * ux - uy * uy ),
		];
		const colour = [ 1, 0.85, 0.6 ];
		for ( let b = 0; b < 9; b ++ ) for ( let c = 0; c < 3; c ++ ) {

			// The L2 band halved: a capture's band-limited, slightly softened lobe.
			out[ offset + 3 * b + c ] = e * colour[ c ] * basis[ b ] * ( b >= 4 ? 0.5 : 1 ) + ( b === 0 ? 0.6 : 0 );

		}

	};

}

/** The field at every point: 27 floats per point. */
export function sample( field: Field, points: ArrayLike<number> ): Float64Array {

	const count = points.length / 3;
	const out = new Float64Array( 27 * count );
	for ( let j = 0; j < count; j ++ ) field( points[ 3 * j ], points[ 3 * j + 1 ], points[ 3 * j + 2 ], out, 27 * j );
	return out;

}

/** The largest |a − b| over two arrays of equal length. */
export function maxDifference( a: ArrayLike<number>, b: ArrayLike<number> ): number {

	let max = 0;
	for ( let i = 0; i < a.length; i ++ ) max = Math.max( max, Math.abs( a[ i ] - b[ i ] ) );
	return max;

}

/** `values` with seeded uniform noise of ± `amplitude` added. */
export function perturbed( values: ArrayLike<number>, amplitude: number, seed: number ): Float64Array {

	const random = mulberry32( seed );
	return Float64Array.from( values, ( v ) => v + amplitude * ( 2 * random() - 1 ) );

}
