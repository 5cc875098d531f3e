import { irradianceAt } from '../sh/irradiance.js';

/**
 * The library's irradiance error measure (placement's `irradianceError`), rebuilt on src/sh so the
 * fit can judge held-out samples with it: the same 26 normals, the same factors (from
 * `irradianceAt`), max over RGB, mean over normals, one global normaliser.
 */

/** Number of normals the measure uses. */
export const MEASURE_DIRECTIONS = 26;

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

// The mean over the 26 normals of each coefficient's factor (odd band: 0, the normals pair up).
const meanFactor = Float64Array.from( { length: 9 }, ( _, b ) => {

	let sum = 0;
	for ( let k = 0; k < MEASURE_DIRECTIONS; k ++ ) sum += basis[ 9 * k + b ];
	return sum / MEASURE_DIRECTIONS;

} );

/**
 * The error of one point whose predicted SH differs from the truth by `delta` (27 floats at
 * `offset`): Σₖ maxᶜ |E_c(delta, nₖ)| · scale — placement's `pointIrradianceError` of the two
 * irradiance rows, since irradiance is linear in the SH. The normals come in opposite pairs
 * (k and 25 − k), so each pair shares its even bands and flips its odd band: half the products.
 * @param scale 1 / (K · Ē).
 */
export function differenceError( delta: ArrayLike<number>, offset: number, scale: number ): number {

	let sum = 0;
	for ( let k = 0; k < MEASURE_DIRECTIONS / 2; k ++ ) {

		const t = 9 * k;
		const b0 = basis[ t ], b1 = basis[ t + 1 ], b2 = basis[ t + 2 ], b3 = basis[ t + 3 ], b4 = basis[ t + 4 ];
		const b5 = basis[ t + 5 ], b6 = basis[ t + 6 ], b7 = basis[ t + 7 ], b8 = basis[ t + 8 ];
		let plus = 0, minus = 0;
		for ( let c = 0; c < 3; c ++ ) {

			const s = offset + c;
			const even = b0 * delta[ s ] + b4 * delta[ s + 12 ] + b5 * delta[ s + 15 ] + b6 * delta[ s + 18 ]
				+ b7 * delta[ s + 21 ] + b8 * delta[ s + 24 ];
			const odd = b1 * delta[ s + 3 ] + b2 * delta[ s + 6 ] + b3 * delta[ s + 9 ];
			const p = Math.abs( even + odd ), m = Math.abs( even - odd );
			if ( p > plus ) plus = p;
			if ( m > minus ) minus = m;

		}

		sum += plus + minus;

	}

	return sum * scale;

}

/**
 * The measure's normaliser Ē with sample weights: Σⱼ sⱼ · Ēⱼ / Σⱼ sⱼ, Ēⱼ the mean of sample j's
 * irradiance over the 26 normals and 3 channels — with all weights 1 the mean `irradianceError`
 * takes. Ēⱼ is linear in the SH: the normals' mean factor per coefficient.
 * @param sh 27 floats per sample.
 */
export function weightedMeanIrradiance( sh: ArrayLike<number>, weights: Float64Array ): number {

	let sum = 0, weightSum = 0;
	for ( let j = 0; j < weights.length; j ++ ) {

		let mean = 0;
		for ( let b = 0, o = 27 * j; b < 9; b ++, o += 3 ) mean += meanFactor[ b ] * ( sh[ o ] + sh[ o + 1 ] + sh[ o + 2 ] );
		sum += weights[ j ] * mean / 3;
		weightSum += weights[ j ];

	}

	return sum / weightSum;

}
