/**
 * Shared fixtures for the SH tests: analytic SH truth and environments sampled at texel centres.
 */

import { cubeFaceDirection, evaluateSHBasis } from '../../src/sh/index.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/** three's truncated basis constants, per coefficient index. */
export const BASIS_CONSTANT = [ 0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548, 0.315392, 1.092548, 0.546274 ];

/**
 * ∫ p_k(ω)² dω over the sphere for the basis polynomials p_k = 1, y, z, x, xy, yz, 3z²−1, xz, x²−y²
 * (standard moments: ∫x² = 4π/3, ∫x²y² = 4π/15, ∫x⁴ = 4π/5).
 */
export const POLYNOMIAL_NORM = [
	4 * Math.PI, 4 * Math.PI / 3, 4 * Math.PI / 3, 4 * Math.PI / 3,
	4 * Math.PI / 15, 4 * Math.PI / 15, 16 * Math.PI / 5, 4 * Math.PI / 15, 16 * Math.PI / 15,
];

/**
 * Exact projection of Y_k (three's truncated Y_k) onto itself: c_k²·∫p_k². It is 1 ± 3e-6, not 1,
 * because three's 6-digit constants are not exactly 1/‖p_k‖. The different-k projections are
 * exactly 0 because the p_k are orthogonal regardless of the constants.
 */
export function selfProjection( k: number ): number {

	return BASIS_CONSTANT[ k ] * BASIS_CONSTANT[ k ] * POLYNOMIAL_NORM[ k ];

}

/** A fixed band-limited environment L(ω) = Σ a_k Y_k(ω); its exact coefficients are a_k·selfProjection(k). */
export const BAND_LIMITED = [ 1.0, 0.3, - 0.5, 0.4, 0.2, - 0.25, 0.35, 0.15, - 0.3 ];

const basis = new Float64Array( 9 );

/** Evaluates Σ a_k Y_k at a unit direction. */
export function evaluateBandLimited( a: ArrayLike<number>, x: number, y: number, z: number ): number {

	evaluateSHBasis( x, y, z, basis );
	let value = 0;
	for ( let k = 0; k < 9; k ++ ) value += a[ k ] * basis[ k ];
	return value;

}

/**
 * Six RGBA faces whose texel (i, j) holds `colour · radiance( direction of that texel )`, using the
 * library's own face mapping (the mapping itself is checked independently elsewhere).
 */
export function cubeFacesFrom(
	size: number, radiance: ( x: number, y: number, z: number ) => number, colour: readonly number[] = [ 1, 1, 1 ],
	faces?: Float32Array[]
): Float32Array[] {

	const result = faces ?? [];
	const d = new Float64Array( 3 );
	for ( let f = 0; f < 6; f ++ ) {

		const face = result[ f ] ?? ( result[ f ] = new Float32Array( size * size * 4 ) );
		for ( let j = 0; j < size; j ++ ) {

			for ( let i = 0; i < size; i ++ ) {

				cubeFaceDirection( f, i, j, size, d );
				const value = radiance( d[ 0 ], d[ 1 ], d[ 2 ] );
				const p = ( j * size + i ) * 4;
				face[ p ] = colour[ 0 ] * value;
				face[ p + 1 ] = colour[ 1 ] * value;
				face[ p + 2 ] = colour[ 2 ] * value;
				face[ p + 3 ] = 1;

			}

		}

	}

	return result;

}

/**
 * A top-down RGBA panorama of `radiance`, each pixel sampled at its centre with three's
 * `equirectUv` convention inverted: longitude φ = 2π(u − ½), latitude = π(v − ½), v = 1 on the top
 * row, dir = (cos lat cos φ, sin lat, cos lat sin φ).
 */
export function equirectFrom(
	width: number, height: number, radiance: ( x: number, y: number, z: number ) => number, colour: readonly number[] = [ 1, 1, 1 ],
	pixels?: Float32Array
): Float32Array {

	const result = pixels ?? new Float32Array( width * height * 4 );
	for ( let row = 0; row < height; row ++ ) {

		const latitude = Math.PI * ( 1 - ( row + 0.5 ) / height - 0.5 );
		for ( let i = 0; i < width; i ++ ) {

			const longitude = 2 * Math.PI * ( ( i + 0.5 ) / width - 0.5 );
			const value = radiance(
				Math.cos( latitude ) * Math.cos( longitude ), Math.sin( latitude ), Math.cos( latitude ) * Math.sin( longitude )
			);
			const p = ( row * width + i ) * 4;
			result[ p ] = colour[ 0 ] * value;
			result[ p + 1 ] = colour[ 1 ] * value;
			result[ p + 2 ] = colour[ 2 ] * value;
			result[ p + 3 ] = 1;

		}

	}

	return result;

}

/** Largest |sh[k·3 + channel] − expected[k]·scale| over the 9 coefficients. */
export function maxCoefficientError( sh: ArrayLike<number>, expected: ArrayLike<number>, channel = 0, scale = 1 ): number {

	let error = 0;
	for ( let k = 0; k < 9; k ++ ) error = Math.max( error, Math.abs( sh[ k * 3 + channel ] - expected[ k ] * scale ) );
	return error;

}

/** Small deterministic PRNG (the library's mulberry32) so failures are reproducible. */
export const random = mulberry32;

/** A uniformly distributed random unit vector. */
export function randomDirection( next: () => number ): [ number, number, number ] {

	const z = 2 * next() - 1;
	const phi = 2 * Math.PI * next();
	const r = Math.sqrt( 1 - z * z );
	return [ r * Math.cos( phi ), r * Math.sin( phi ), z ];

}
