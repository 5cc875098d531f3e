import { irradianceAt } from '../sh/irradiance.js';

/**
 * The library's irradiance error measure (placement's `irradianceError`), rebuilt on src/sh so the
 * fit can judge held-out samples with it: the same 26 normals in the same order, the same
 * per-direction arithmetic, max over RGB, one global normaliser.
 */

/** Number of normals the measure uses. */
export const MEASURE_DIRECTIONS = 26;

/** Floats per point of an irradiance table: R, G, B at each of the 26 normals. */
export const IRRADIANCE_ROW = 3 * MEASURE_DIRECTIONS;

/**
 * The 26 normals of `irradianceError`: from the centre of a 3×3×3 block of cubes to each neighbour,
 * normalised, z slowest and x fastest (the order of placement's `IRRADIANCE_ERROR_NORMALS`).
 */
export const MEASURE_NORMALS: Float64Array = ( () => {

	const out: number[] = [];
	for ( let z = - 1; z <= 1; z ++ ) for ( let y = - 1; y <= 1; y ++ ) for ( let x = - 1; x <= 1; x ++ ) {

		if ( x === 0 && y === 0 && z === 0 ) continue;
		const length = Math.sqrt( x * x + y * y + z * z );
		out.push( x / length, y / length, z / length );

	}

	return Float64Array.from( out );

} )();

// basis[ 9k + b ]: the factor of coefficient b in the irradiance at normal k, taken from irradianceAt itself
// (a unit coefficient gives its factor exactly), so the rows below add the same products in the same order.
const basis: Float64Array = ( () => {

	const table = new Float64Array( 9 * MEASURE_DIRECTIONS );
	const unit = new Float64Array( 27 ), value = new Float64Array( 3 );
	for ( let k = 0; k < MEASURE_DIRECTIONS; k ++ ) {

		for ( let b = 0; b < 9; b ++ ) {

			unit.fill( 0 );
			unit[ 3 * b ] = 1;
			irradianceAt( unit, 0, MEASURE_NORMALS[ 3 * k ], MEASURE_NORMALS[ 3 * k + 1 ], MEASURE_NORMALS[ 3 * k + 2 ], value, 0 );
			table[ 9 * k + b ] = value[ 0 ];

		}

	}

	return table;

} )();

/**
 * Writes one SH's irradiance at the 26 normals (78 floats, `3k + channel`) to `out` at `outOffset`:
 * the numbers `evaluateIrradiance` gives.
 */
export function irradianceRow( sh: ArrayLike<number>, shOffset: number, out: Float64Array, outOffset: number ): void {

	for ( let k = 0; k < MEASURE_DIRECTIONS; k ++ ) {

		const t = 9 * k;
		const b0 = basis[ t ], b1 = basis[ t + 1 ], b2 = basis[ t + 2 ], b3 = basis[ t + 3 ], b4 = basis[ t + 4 ];
		const b5 = basis[ t + 5 ], b6 = basis[ t + 6 ], b7 = basis[ t + 7 ], b8 = basis[ t + 8 ];
		for ( let c = 0; c < 3; c ++ ) {

			const s = shOffset + c;
			out[ outOffset + 3 * k + c ] = b0 * sh[ s ] + b1 * sh[ s + 3 ] + b2 * sh[ s + 6 ] + b3 * sh[ s + 9 ]
				+ b4 * sh[ s + 12 ] + b5 * sh[ s + 15 ] + b6 * sh[ s + 18 ] + b7 * sh[ s + 21 ] + b8 * sh[ s + 24 ];

		}

	}

}

/** The irradiance table of `count` SH (27 floats each): {@link IRRADIANCE_ROW} floats per point. */
export function irradianceTable( sh: ArrayLike<number>, count: number ): Float64Array {

	const table = new Float64Array( IRRADIANCE_ROW * count );
	for ( let p = 0; p < count; p ++ ) irradianceRow( sh, 27 * p, table, IRRADIANCE_ROW * p );
	return table;

}

/**
 * The measure's normaliser Ē with sample weights: Σⱼ sⱼ · (mean of row j) / Σⱼ sⱼ — with all weights
 * 1 the mean of the whole table, as `irradianceError` takes it.
 */
export function weightedMeanIrradiance( table: Float64Array, weights: Float64Array ): number {

	let sum = 0, weightSum = 0;
	for ( let j = 0; j < weights.length; j ++ ) {

		let row = 0;
		for ( let i = IRRADIANCE_ROW * j, end = i + IRRADIANCE_ROW; i < end; i ++ ) row += table[ i ];
		sum += weights[ j ] * row / IRRADIANCE_ROW;
		weightSum += weights[ j ];

	}

	return sum / weightSum;

}

/**
 * One point's error, Σₖ maxᶜ |predicted − truth| · scale with scale = 1 / (K · Ē): placement's
 * `pointIrradianceError`.
 */
export function pointError(
	predicted: Float64Array, predictedOffset: number, truth: Float64Array, truthOffset: number, scale: number,
): number {

	let sum = 0;
	for ( let k = 0; k < IRRADIANCE_ROW; k += 3 ) {

		const a = predictedOffset + k, b = truthOffset + k;
		const r = Math.abs( predicted[ a ] - truth[ b ] ), g = Math.abs( predicted[ a + 1 ] - truth[ b + 1 ] );
		const bl = Math.abs( predicted[ a + 2 ] - truth[ b + 2 ] );
		sum += r > g ? ( r > bl ? r : bl ) : ( g > bl ? g : bl );

	}

	return sum * scale;

}
