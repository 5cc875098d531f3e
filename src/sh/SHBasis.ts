/**
 * The order-2 (9 coefficient) real spherical-harmonics basis exactly as three.js uses it in
 * `SphericalHarmonics3.getBasisAt`, and the cosine-lobe convolution constants of its
 * `getIrradianceAt`. The constants are three's 6-digit truncations on purpose: SH produced here
 * must be interchangeable with `new SphericalHarmonics3().fromArray( sh )`, and the shader code
 * three generates for `LightProbe` uses the same truncated values.
 *
 * Coefficient order (index k): 0 → Y00, 1 → Y1−1 (y), 2 → Y10 (z), 3 → Y11 (x), 4 → Y2−2 (xy),
 * 5 → Y2−1 (yz), 6 → Y20 (3z²−1), 7 → Y21 (xz), 8 → Y22 (x²−y²).
 */

import { assertInteger, assertNumber, assertOutput } from '../validate.js';

/** Y00 = 1 / (2√π), truncated as in three.js. */
export const SH_Y00 = 0.282095;

/** Band-1 constant √3 / (2√π); multiplies y, z and x (coefficients 1, 2, 3). */
export const SH_Y1 = 0.488603;

/** Band-2 constant √15 / (2√π); multiplies xy, yz and xz (coefficients 4, 5, 7). */
export const SH_Y2_PRODUCT = 1.092548;

/** Y20 constant √5 / (4√π); multiplies (3z² − 1) (coefficient 6). */
export const SH_Y20 = 0.315392;

/** Y22 constant √15 / (4√π); multiplies (x² − y²) (coefficient 8). */
export const SH_Y22 = 0.546274;

/**
 * Ramamoorthi & Hanrahan (2001) eq. 12 constant c1 = (π/4)·√15/(4√π) = 0.429043.
 * three's getIrradianceAt uses 2·c1 for xy, yz, xz and c1 for (x² − y²).
 */
export const IRRADIANCE_C1 = 0.429043;

/**
 * R&H constant c2 = (π/3)·√3/(2√π) = 0.511664; three uses 2·c2 = (2π/3)·√3/(2√π) for the three
 * band-1 terms.
 */
export const IRRADIANCE_C2 = 0.511664;

/** R&H constant c3 = (π/4)·3·√5/(4√π) = 0.743125; multiplies z² for coefficient 6. */
export const IRRADIANCE_C3 = 0.743125;

/** R&H constant c4 = π·1/(2√π) = 0.886227; multiplies coefficient 0. */
export const IRRADIANCE_C4 = 0.886227;

/** R&H constant c5 = (π/4)·√5/(4√π) = 0.247708; subtracted for coefficient 6. */
export const IRRADIANCE_C5 = 0.247708;

/**
 * Writes the 9 basis values at direction (x, y, z) into `out[ offset .. offset + 8 ]`, identical
 * to three's `SphericalHarmonics3.getBasisAt`. The direction is assumed to be unit length and is
 * not normalised, again like three.
 * @param x Direction x.
 * @param y Direction y.
 * @param z Direction z.
 * @param out Receives the 9 values; needs length ≥ offset + 9.
 * @param offset First index written (default 0).
 * @returns `out`.
 */
export function evaluateSHBasis<T extends { [ index: number ]: number; readonly length: number }>(
	x: number, y: number, z: number, out: T, offset = 0,
): T {

	assertNumber( 'evaluateSHBasis', 'x', x );
	assertNumber( 'evaluateSHBasis', 'y', y );
	assertNumber( 'evaluateSHBasis', 'z', z );
	assertInteger( 'evaluateSHBasis', 'offset', offset, 0 );
	assertOutput( 'evaluateSHBasis', 'out', out, offset + 9 );
	writeSHBasis( x, y, z, out, offset );
	return out;

}

/**
 * Unchecked core of {@link evaluateSHBasis} for the projection loops, which have already
 * validated their input and must not pay for per-texel checks.
 * @internal
 */
export function writeSHBasis( x: number, y: number, z: number, out: { [ index: number ]: number }, offset: number ): void {

	out[ offset ] = SH_Y00;
	out[ offset + 1 ] = SH_Y1 * y;
	out[ offset + 2 ] = SH_Y1 * z;
	out[ offset + 3 ] = SH_Y1 * x;
	out[ offset + 4 ] = SH_Y2_PRODUCT * x * y;
	out[ offset + 5 ] = SH_Y2_PRODUCT * y * z;
	out[ offset + 6 ] = SH_Y20 * ( 3 * z * z - 1 );
	out[ offset + 7 ] = SH_Y2_PRODUCT * x * z;
	out[ offset + 8 ] = SH_Y22 * ( x * x - y * y );

}
