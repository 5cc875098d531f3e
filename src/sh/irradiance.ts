/**
 * Reconstruction from SH9 (paper 2.5): radiance L(ω), irradiance E(n) and the Ramamoorthi &
 * Hanrahan quadratic form E(n) = nᵀ M n, all numerically equal to three.js `SphericalHarmonics3`.
 *
 * Every function reads the 27 floats of one probe starting at `shOffset`, so a probe inside a large
 * `Float32Array( 27 · N )` is used in place (pass `shOffset = 27 · probeIndex`) without a
 * `subarray` allocation.
 */

import { SH_FLOATS, assertArrayLike, assertInteger, assertOutput } from '../validate.js';
import {
	IRRADIANCE_C1, IRRADIANCE_C2, IRRADIANCE_C3, IRRADIANCE_C4, IRRADIANCE_C5,
	SH_Y00, SH_Y1, SH_Y2_PRODUCT, SH_Y20, SH_Y22,
} from './SHBasis.js';

/** A direction: `{ x, y, z }` (e.g. a three.js Vector3) or an array-like `[ x, y, z ]`. */
export type DirectionLike = { readonly x: number; readonly y: number; readonly z: number } | ArrayLike<number>;

/** Anything indexable that results can be written into (plain array or typed array). */
export type WritableArrayLike = { [ index: number ]: number; readonly length: number };

/** Floats written by {@link irradianceMatrices}: one 4×4 matrix per colour channel. */
export const IRRADIANCE_MATRICES_FLOATS = 48;

// Scratch for the direction so reading `{x,y,z}` or `[x,y,z]` costs no allocation.
const direction = new Float64Array( 3 );

/**
 * Irradiance E(n) = ∫ L(ω) max(0, n·ω) dω reconstructed from SH9 (cosine-lobe convolution,
 * Ramamoorthi & Hanrahan 2001); the same numbers as three's `SphericalHarmonics3.getIrradianceAt`.
 * Like three, `normal` is assumed to be unit length and is not normalised. Divide by π for the
 * outgoing radiance of a white Lambertian surface.
 * @param sh SH array (length a positive multiple of 27).
 * @param normal Surface normal, `{ x, y, z }` or `[ x, y, z ]`.
 * @param target Receives R, G, B in entries 0..2; a new Float32Array(3) when omitted.
 * @param shOffset Index of the probe's first float in `sh` (default 0).
 * @returns `target`.
 */
export function evaluateIrradiance<T extends WritableArrayLike = Float32Array>(
	sh: ArrayLike<number>, normal: DirectionLike, target?: T, shOffset = 0,
): T {

	const where = 'evaluateIrradiance';
	assertSHAt( where, sh, shOffset );
	readDirection( where, 'normal', normal );
	const out = ( target ?? new Float32Array( 3 ) ) as T;
	assertOutput( where, 'target', out, 3 );

	irradianceAt( sh, shOffset, direction[ 0 ], direction[ 1 ], direction[ 2 ], out, 0 );
	return out;

}

/**
 * {@link evaluateIrradiance} without argument checks, for loops over many points whose arrays were
 * validated once (per-vertex lighting): E(n) for the unit normal (x, y, z) of the probe at
 * `shOffset`, written to `out[ outOffset … outOffset + 2 ]`. Internal (not exported by the package).
 */
export function irradianceAt(
	sh: ArrayLike<number>, shOffset: number, x: number, y: number, z: number, out: WritableArrayLike, outOffset: number,
): void {

	const c0 = IRRADIANCE_C4;
	const c1 = 2 * IRRADIANCE_C2 * y;
	const c2 = 2 * IRRADIANCE_C2 * z;
	const c3 = 2 * IRRADIANCE_C2 * x;
	const c4 = 2 * IRRADIANCE_C1 * x * y;
	const c5 = 2 * IRRADIANCE_C1 * y * z;
	const c6 = IRRADIANCE_C3 * z * z - IRRADIANCE_C5;
	const c7 = 2 * IRRADIANCE_C1 * x * z;
	const c8 = IRRADIANCE_C1 * ( x * x - y * y );
	weightedSum( sh, shOffset, c0, c1, c2, c3, c4, c5, c6, c7, c8, out, outOffset );

}

/**
 * Radiance L(ω) reconstructed from SH9; the same numbers as three's `SphericalHarmonics3.getAt`.
 * @param sh SH array (length a positive multiple of 27).
 * @param dir Direction, `{ x, y, z }` or `[ x, y, z ]`, assumed unit length (not normalised).
 * @param target Receives R, G, B in entries 0..2; a new Float32Array(3) when omitted.
 * @param shOffset Index of the probe's first float in `sh` (default 0).
 * @returns `target`.
 */
export function evaluateRadiance<T extends WritableArrayLike = Float32Array>(
	sh: ArrayLike<number>, dir: DirectionLike, target?: T, shOffset = 0,
): T {

	const where = 'evaluateRadiance';
	assertSHAt( where, sh, shOffset );
	readDirection( where, 'dir', dir );
	const out = ( target ?? new Float32Array( 3 ) ) as T;
	assertOutput( where, 'target', out, 3 );

	const x = direction[ 0 ], y = direction[ 1 ], z = direction[ 2 ];
	weightedSum(
		sh, shOffset,
		SH_Y00, SH_Y1 * y, SH_Y1 * z, SH_Y1 * x,
		SH_Y2_PRODUCT * x * y, SH_Y2_PRODUCT * y * z, SH_Y20 * ( 3 * z * z - 1 ), SH_Y2_PRODUCT * x * z, SH_Y22 * ( x * x - y * y ),
		out,
	);
	return out;

}

/**
 * The paper's per-channel irradiance matrices (Ramamoorthi & Hanrahan 2001, eq. 12): with
 * n = (x, y, z, 1), E_c(n) = nᵀ M_c n equals {@link evaluateIrradiance} for channel c. Written for
 * three's basis order (L00, L1−1, L10, L11, L2−2, L2−1, L20, L21, L22 = indices 0..8):
 *
 *     M = | c1·L22   c1·L2−2  c1·L21   c2·L11        |
 *         | c1·L2−2  −c1·L22  c1·L2−1  c2·L1−1       |
 *         | c1·L21   c1·L2−1  c3·L20   c2·L10        |
 *         | c2·L11   c2·L1−1  c2·L10   c4·L00 − c5·L20 |
 *
 * (c1..c5 = {@link IRRADIANCE_C1}..{@link IRRADIANCE_C5}). Each M is symmetric, so its
 * column-major 16 floats (three.js `Matrix4.elements` order) are also its row-major ones.
 * Output: R's matrix, then G's, then B's — 48 floats from `outOffset`. Meant to be called per
 * object per frame: pass `out` (and offsets) to avoid any allocation.
 * @param sh SH array (length a positive multiple of 27), e.g. all probes in one Float32Array.
 * @param out Receives 48 floats at `outOffset`; a new Float32Array(48) when omitted.
 * @param outOffset First index written in `out` (default 0), e.g. 48·objectIndex.
 * @param shOffset Index of the probe's first float in `sh` (default 0), e.g. 27·probeIndex.
 * @returns `out`.
 */
export function irradianceMatrices<T extends WritableArrayLike = Float32Array>(
	sh: ArrayLike<number>, out?: T, outOffset = 0, shOffset = 0,
): T {

	const where = 'irradianceMatrices';
	assertSHAt( where, sh, shOffset );
	assertInteger( where, 'outOffset', outOffset, 0 );
	const target = ( out ?? new Float32Array( IRRADIANCE_MATRICES_FLOATS ) ) as T;
	assertOutput( where, 'out', target, outOffset + IRRADIANCE_MATRICES_FLOATS );

	for ( let channel = 0; channel < 3; channel ++ ) {

		const s = shOffset + channel;
		const L00 = sh[ s ], L1m1 = sh[ s + 3 ], L10 = sh[ s + 6 ], L11 = sh[ s + 9 ];
		const L2m2 = sh[ s + 12 ], L2m1 = sh[ s + 15 ], L20 = sh[ s + 18 ], L21 = sh[ s + 21 ], L22 = sh[ s + 24 ];
		const m = outOffset + channel * 16;

		target[ m ] = IRRADIANCE_C1 * L22;
		target[ m + 1 ] = IRRADIANCE_C1 * L2m2;
		target[ m + 2 ] = IRRADIANCE_C1 * L21;
		target[ m + 3 ] = IRRADIANCE_C2 * L11;

		target[ m + 4 ] = IRRADIANCE_C1 * L2m2;
		target[ m + 5 ] = - IRRADIANCE_C1 * L22;
		target[ m + 6 ] = IRRADIANCE_C1 * L2m1;
		target[ m + 7 ] = IRRADIANCE_C2 * L1m1;

		target[ m + 8 ] = IRRADIANCE_C1 * L21;
		target[ m + 9 ] = IRRADIANCE_C1 * L2m1;
		target[ m + 10 ] = IRRADIANCE_C3 * L20;
		target[ m + 11 ] = IRRADIANCE_C2 * L10;

		target[ m + 12 ] = IRRADIANCE_C2 * L11;
		target[ m + 13 ] = IRRADIANCE_C2 * L1m1;
		target[ m + 14 ] = IRRADIANCE_C2 * L10;
		target[ m + 15 ] = IRRADIANCE_C4 * L00 - IRRADIANCE_C5 * L20;

	}

	return target;

}

/**
 * Validates only what is read: `sh`'s length (a positive multiple of 27, so a truncated or padded
 * array is caught), the offset, and the 27 values at it — not all of a large probe array, since
 * these functions run per object per frame.
 */
function assertSHAt( where: string, sh: unknown, shOffset: unknown ): asserts sh is ArrayLike<number> {

	assertArrayLike( where, 'sh', sh );
	if ( sh.length === 0 || sh.length % SH_FLOATS !== 0 ) {

		throw new RangeError(
			`${where}: sh must have a length that is a positive multiple of 27 (9 RGB coefficients per probe), got ${sh.length}.`,
		);

	}

	assertInteger( where, 'shOffset', shOffset, 0, sh.length - SH_FLOATS );
	for ( let i = shOffset; i < shOffset + SH_FLOATS; i ++ ) {

		const v = sh[ i ];
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) {

			throw new RangeError( `${where}: sh[${i}] is ${String( v )}; all values must be finite numbers.` );

		}

	}

}

function readDirection( where: string, name: string, value: DirectionLike ): void {

	if ( value === null || typeof value !== 'object' ) {

		throw new TypeError( `${where}: ${name} must be { x, y, z } or [ x, y, z ], got ${value === null ? 'null' : typeof value}.` );

	}

	let x: unknown, y: unknown, z: unknown;
	if ( typeof ( value as ArrayLike<number> ).length === 'number' ) {

		const a = value as ArrayLike<number>;
		if ( a.length < 3 ) {

			throw new RangeError( `${where}: ${name} must have 3 components, got length ${a.length}.` );

		}

		x = a[ 0 ]; y = a[ 1 ]; z = a[ 2 ];

	} else {

		const v = value as { x: unknown; y: unknown; z: unknown };
		x = v.x; y = v.y; z = v.z;

	}

	// Checked before storing: the Float64Array scratch would silently coerce '1' or undefined.
	assertComponent( where, name, 'x', x );
	assertComponent( where, name, 'y', y );
	assertComponent( where, name, 'z', z );
	direction[ 0 ] = x as number;
	direction[ 1 ] = y as number;
	direction[ 2 ] = z as number;

}

function assertComponent( where: string, name: string, axis: string, value: unknown ): void {

	if ( typeof value !== 'number' || ! Number.isFinite( value ) ) {

		throw new RangeError( `${where}: ${name}.${axis} must be a finite number, got ${String( value )}.` );

	}

}

function weightedSum(
	sh: ArrayLike<number>, o: number,
	c0: number, c1: number, c2: number, c3: number, c4: number, c5: number, c6: number, c7: number, c8: number,
	out: WritableArrayLike, outOffset = 0,
): void {

	for ( let channel = 0; channel < 3; channel ++ ) {

		const s = o + channel;
		out[ outOffset + channel ] = c0 * sh[ s ] + c1 * sh[ s + 3 ] + c2 * sh[ s + 6 ] + c3 * sh[ s + 9 ]
			+ c4 * sh[ s + 12 ] + c5 * sh[ s + 15 ] + c6 * sh[ s + 18 ] + c7 * sh[ s + 21 ] + c8 * sh[ s + 24 ];

	}

}
