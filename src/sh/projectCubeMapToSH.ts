/**
 * CPU reference projection of a captured cube map onto three.js-compatible SH9 (paper 2.2, steps
 * 1–4). The GPU path elsewhere in the library must agree with this one.
 */

import { SH_FLOATS, assertArrayLike, assertFinite, assertInteger, assertOutput } from '../validate.js';
import { writeSHBasis } from './SHBasis.js';
import { CUBE_FACE_AXES } from './cubeFaceDirection.js';
import { cornerIntegral } from './cubeTexelSolidAngle.js';
import { LRUCache } from './LRUCache.js';

/**
 * How each texel's solid angle is computed.
 * - `'exact'` (default): exact area-element integral of the texel; weights sum to 4π.
 * - `'paper'`: the paper's A(ω) = (r·n)/|r|³·(2/w)(2/h), then its step 4 normalisation, done as in
 *   three's `LightProbeGenerator` and the usual cube-map SH code: all weights rescaled so their
 *   sum is 4π (the paper names the step but gives no formula).
 * - `'paper-unnormalized'`: the paper's A(ω) without that rescaling (sum slightly above 4π).
 *
 * With texel-centre samples (a GPU capture) `'paper'` is the more accurate of the three; how much:
 * README, "Texel solid angle, paper vs exact" (test/sh/solidAngleComparison.test.ts).
 */
export type CubeSolidAngleMode = 'exact' | 'paper' | 'paper-unnormalized';

/** Options for {@link projectCubeMapToSH}. */
export interface CubeMapProjectionOptions {

	/** Texel solid-angle formula; default `'exact'`. */
	solidAngle?: CubeSolidAngleMode;

	/** Floats per texel in `faces`: 4 (RGBA, what readRenderTargetPixels returns; default) or 3. */
	channels?: 3 | 4;

	/** Receives the 27 floats at `targetOffset`; a new Float32Array(27) when omitted. */
	target?: Float32Array;

	/** First index written in `target` (default 0), e.g. 27·probeIndex. */
	targetOffset?: number;

}

/**
 * Precomputed SH basis × texel solid angle for one face size and solid-angle mode:
 * `weights[ ( ( face · size + row ) · size + column ) · 9 + k ]` is Y_k(ω_texel)·Ω_texel.
 */
export interface CubeProjectionTable {

	/** Face edge length in texels. */
	readonly size: number;

	/** Solid-angle mode the weights were built with. */
	readonly solidAngle: CubeSolidAngleMode;

	/** 6·size²·9 weights, laid out as documented on the interface. */
	readonly weights: Float32Array;

	/** Sum of the 6·size² texel solid angles actually used (4π for 'exact' and 'paper'). */
	readonly totalSolidAngle: number;

}

const CUBE_SOLID_ANGLE_MODES: readonly CubeSolidAngleMode[] = [ 'exact', 'paper', 'paper-unnormalized' ];

// Four tables at 256² are ~57 MB; enough for a capture size plus a comparison size or two.
const tableCache = new LRUCache<string, CubeProjectionTable>( 4 );

// Float64 accumulation: at 256² a face sum has 393 216 terms, too many for float32.
const accumulator = new Float64Array( SH_FLOATS );

/**
 * Projects six cube faces onto SH9 in three.js `SphericalHarmonics3` layout:
 * L_k = Σ_texels L(ω)·Y_k(ω)·Ω_texel.
 *
 * `faces[ i ]` (i = 0..5 in three's order +X, −X, +Y, −Y, +Z, −Z) is exactly what
 * `renderer.readRenderTargetPixels( cubeRenderTarget, 0, 0, size, size, buffer, i )` returns for a
 * float RGBA `WebGLCubeRenderTarget` rendered by `CubeCamera` with a `WebGLRenderer`; the texel
 * directions are those of {@link cubeFaceDirection}. Values are used as linear radiance: decode
 * half floats, bytes or sRGB before calling. The projection tables are cached per size and mode,
 * so repeated captures at one size only pay the multiply-adds.
 * @param faces Six arrays of size·size·channels finite numbers.
 * @param size Face edge length in texels.
 * @param options See {@link CubeMapProjectionOptions}.
 * @returns The 27 SH floats (coefficient-major, RGB interleaved), in `options.target` if given.
 */
export function projectCubeMapToSH(
	faces: ArrayLike<ArrayLike<number>>, size: number, options: CubeMapProjectionOptions = {},
): Float32Array {

	const where = 'projectCubeMapToSH';
	assertInteger( where, 'size', size, 1 );
	const channels = options.channels ?? 4;
	if ( channels !== 3 && channels !== 4 ) {

		throw new RangeError( `${where}: options.channels must be 3 or 4, got ${String( channels )}.` );

	}

	const mode = checkMode( where, options.solidAngle );
	assertArrayLike( where, 'faces', faces );
	if ( faces.length !== 6 ) {

		throw new RangeError( `${where}: faces must hold 6 cube faces (+X, −X, +Y, −Y, +Z, −Z), got ${faces.length}.` );

	}

	const texelCount = size * size;
	for ( let f = 0; f < 6; f ++ ) {

		const face = faces[ f ];
		assertArrayLike( where, `faces[${f}]`, face );
		if ( face.length !== texelCount * channels ) {

			throw new RangeError(
				`${where}: faces[${f}] must have length size·size·${channels} = ${texelCount * channels} for size ${size}, got ${face.length}.`,
			);

		}

		assertFinite( where, `faces[${f}]`, face );

	}

	const targetOffset = options.targetOffset ?? 0;
	assertInteger( where, 'options.targetOffset', targetOffset, 0 );
	const target = options.target ?? new Float32Array( SH_FLOATS );
	assertOutput( where, 'options.target', target, targetOffset + SH_FLOATS );

	const weights = getCubeProjectionTable( size, mode ).weights;
	const sum = accumulator;
	sum.fill( 0 );

	for ( let f = 0; f < 6; f ++ ) {

		const face = faces[ f ];
		let w = f * texelCount * 9;
		for ( let t = 0, p = 0; t < texelCount; t ++, p += channels ) {

			const r = face[ p ], g = face[ p + 1 ], b = face[ p + 2 ];
			for ( let k = 0; k < 27; k += 3, w ++ ) {

				const weight = weights[ w ];
				sum[ k ] += weight * r;
				sum[ k + 1 ] += weight * g;
				sum[ k + 2 ] += weight * b;

			}

		}

	}

	for ( let k = 0; k < SH_FLOATS; k ++ ) target[ targetOffset + k ] = sum[ k ];
	return target;

}

/**
 * The cached basis × solid-angle table {@link projectCubeMapToSH} uses for `size` and `solidAngle`,
 * built on first use. Exposed for GPU-side code that wants identical weights, and so tests can
 * check the caching.
 * @param size Face edge length in texels.
 * @param solidAngle Solid-angle mode (default `'exact'`).
 */
export function getCubeProjectionTable( size: number, solidAngle: CubeSolidAngleMode = 'exact' ): CubeProjectionTable {

	assertInteger( 'getCubeProjectionTable', 'size', size, 1 );
	const mode = checkMode( 'getCubeProjectionTable', solidAngle );
	return tableCache.getOrCreate( `${mode}:${size}`, () => buildTable( size, mode ) );

}

/**
 * Empties the projection-table cache (frees its memory; tables are rebuilt on demand).
 */
export function clearCubeProjectionCache(): void {

	tableCache.clear();

}

function checkMode( where: string, mode: unknown ): CubeSolidAngleMode {

	if ( mode === undefined ) return 'exact';
	if ( ! CUBE_SOLID_ANGLE_MODES.includes( mode as CubeSolidAngleMode ) ) {

		throw new RangeError(
			`${where}: solidAngle must be one of ${CUBE_SOLID_ANGLE_MODES.map( ( m ) => `'${m}'` ).join( ', ' )}, got ${String( mode )}.`,
		);

	}

	return mode as CubeSolidAngleMode;

}

function buildTable( size: number, mode: CubeSolidAngleMode ): CubeProjectionTable {

	const texelCount = size * size;

	// One face's solid angles serve all six: the faces are congruent and every face maps the same
	// (u, v) grid, only the axes differ.
	const solidAngles = new Float64Array( texelCount );
	const step = 2 / size;
	if ( mode === 'exact' ) {

		const corners = new Float64Array( ( size + 1 ) * ( size + 1 ) );
		for ( let j = 0; j <= size; j ++ ) {

			for ( let i = 0; i <= size; i ++ ) corners[ j * ( size + 1 ) + i ] = cornerIntegral( - 1 + i * step, - 1 + j * step );

		}

		for ( let j = 0; j < size; j ++ ) {

			for ( let i = 0; i < size; i ++ ) {

				const c = j * ( size + 1 ) + i;
				solidAngles[ j * size + i ] = corners[ c ] - corners[ c + size + 1 ] - corners[ c + 1 ] + corners[ c + size + 2 ];

			}

		}

	} else {

		for ( let j = 0; j < size; j ++ ) {

			const v = - 1 + ( j + 0.5 ) * step;
			for ( let i = 0; i < size; i ++ ) {

				const u = - 1 + ( i + 0.5 ) * step;
				const lengthSq = 1 + u * u + v * v;
				solidAngles[ j * size + i ] = step * step / ( lengthSq * Math.sqrt( lengthSq ) );

			}

		}

	}

	let faceSum = 0;
	for ( let t = 0; t < texelCount; t ++ ) faceSum += solidAngles[ t ];
	const scale = mode === 'paper' ? 4 * Math.PI / ( 6 * faceSum ) : 1;

	const weights = new Float32Array( 6 * texelCount * 9 );
	const basis = new Float64Array( 9 );
	for ( let f = 0; f < 6; f ++ ) {

		const a = CUBE_FACE_AXES[ f ];
		for ( let j = 0; j < size; j ++ ) {

			const v = - 1 + ( j + 0.5 ) * step;
			for ( let i = 0; i < size; i ++ ) {

				const u = - 1 + ( i + 0.5 ) * step;
				const x = a[ 0 ] + u * a[ 3 ] + v * a[ 6 ];
				const y = a[ 1 ] + u * a[ 4 ] + v * a[ 7 ];
				const z = a[ 2 ] + u * a[ 5 ] + v * a[ 8 ];
				const inverseLength = 1 / Math.sqrt( x * x + y * y + z * z );
				writeSHBasis( x * inverseLength, y * inverseLength, z * inverseLength, basis, 0 );
				const omega = solidAngles[ j * size + i ] * scale;
				const w = ( ( f * size + j ) * size + i ) * 9;
				for ( let k = 0; k < 9; k ++ ) weights[ w + k ] = basis[ k ] * omega;

			}

		}

	}

	return { size, solidAngle: mode, weights, totalSolidAngle: 6 * faceSum * scale };

}
