/**
 * SH9 projection of an equirectangular panorama (paper 2.2.2: lighting captured from photos,
 * Street View or phone panoramas), in the orientation three.js gives such a panorama.
 */

import { SH_FLOATS, assertArrayLike, assertFinite, assertInteger, assertOutput } from '../validate.js';
import { writeSHBasis } from './SHBasis.js';
import { LRUCache } from './LRUCache.js';

/** Options for {@link projectEquirectToSH}. */
export interface EquirectProjectionOptions {

	/** Floats per pixel in `pixels`: 4 (RGBA, default) or 3 (RGB). */
	channels?: 3 | 4;

	/**
	 * `'top-down'` (default): the first row is the zenith (+Y), as images are stored and as three
	 * shows an image texture (flipY = true). `'bottom-up'`: the first row is the nadir (−Y), e.g.
	 * a `DataTexture` (flipY = false) whose data was not flipped, or a readPixels result.
	 */
	rowOrder?: 'top-down' | 'bottom-up';

	/** Receives the 27 floats at `targetOffset`; a new Float32Array(27) when omitted. */
	target?: Float32Array;

	/** First index written in `target` (default 0). */
	targetOffset?: number;

}

/** Separable per-row / per-column tables for one panorama size (top-down row order). */
interface EquirectTable {

	/** sin(latitude) of each row centre: the direction's y. */
	readonly rowY: Float64Array;

	/** cos(latitude) of each row centre. */
	readonly rowCos: Float64Array;

	/** Exact solid angle of one pixel of each row. */
	readonly rowSolidAngle: Float64Array;

	/** cos(longitude) of each column centre. */
	readonly columnCos: Float64Array;

	/** sin(longitude) of each column centre. */
	readonly columnSin: Float64Array;

}

const tableCache = new LRUCache<string, EquirectTable>( 4 );
const accumulator = new Float64Array( SH_FLOATS );
const basis = new Float64Array( 9 );

/**
 * Projects an equirectangular panorama onto SH9 in three.js `SphericalHarmonics3` layout.
 *
 * Orientation matches three's `equirectUv` (used for `EquirectangularReflectionMapping`, e.g. as
 * `scene.background`): texture u = atan2(dir.z, dir.x)/(2π) + ½, v = asin(dir.y)/π + ½, v = 1 at
 * the top row. So column i's centre has longitude φ = 2π·((i + ½)/W − ½) with
 * dir = (cos lat·cos φ, sin lat, cos lat·sin φ): the left edge looks along −X, the centre
 * column along +X, a quarter of the way along −Z. The SH then describes the same world three
 * shows.
 *
 * Each pixel is weighted by its exact solid angle Ω_row = (2π/W)(sin lat_top − sin lat_bottom)
 * (the weights sum to exactly 4π) and the basis is evaluated at the pixel centre. Values are used
 * as linear radiance.
 * @param pixels width·height·channels finite numbers, row after row.
 * @param width Pixels per row.
 * @param height Number of rows.
 * @param options See {@link EquirectProjectionOptions}.
 * @returns The 27 SH floats (coefficient-major, RGB interleaved), in `options.target` if given.
 */
export function projectEquirectToSH(
	pixels: ArrayLike<number>, width: number, height: number, options: EquirectProjectionOptions = {},
): Float32Array {

	const where = 'projectEquirectToSH';
	assertInteger( where, 'width', width, 1 );
	assertInteger( where, 'height', height, 1 );
	const channels = options.channels ?? 4;
	if ( channels !== 3 && channels !== 4 ) {

		throw new RangeError( `${where}: options.channels must be 3 or 4, got ${String( channels )}.` );

	}

	const rowOrder = options.rowOrder ?? 'top-down';
	if ( rowOrder !== 'top-down' && rowOrder !== 'bottom-up' ) {

		throw new RangeError( `${where}: options.rowOrder must be 'top-down' or 'bottom-up', got ${String( rowOrder )}.` );

	}

	assertArrayLike( where, 'pixels', pixels );
	if ( pixels.length !== width * height * channels ) {

		throw new RangeError(
			`${where}: pixels must have length width·height·${channels} = ${width * height * channels} for ${width}×${height}, got ${pixels.length}.`,
		);

	}

	assertFinite( where, 'pixels', pixels );
	const targetOffset = options.targetOffset ?? 0;
	assertInteger( where, 'options.targetOffset', targetOffset, 0 );
	const target = options.target ?? new Float32Array( SH_FLOATS );
	assertOutput( where, 'options.target', target, targetOffset + SH_FLOATS );

	const table = tableCache.getOrCreate( `${width}x${height}`, () => buildTable( width, height ) );
	const { rowY, rowCos, rowSolidAngle, columnCos, columnSin } = table;
	const sum = accumulator;
	sum.fill( 0 );

	for ( let row = 0; row < height; row ++ ) {

		const latitudeRow = rowOrder === 'top-down' ? row : height - 1 - row;
		const y = rowY[ latitudeRow ];
		const cosLatitude = rowCos[ latitudeRow ];
		const omega = rowSolidAngle[ latitudeRow ];
		let p = row * width * channels;
		for ( let column = 0; column < width; column ++, p += channels ) {

			writeSHBasis( cosLatitude * columnCos[ column ], y, cosLatitude * columnSin[ column ], basis, 0 );
			const r = pixels[ p ] * omega, g = pixels[ p + 1 ] * omega, b = pixels[ p + 2 ] * omega;
			for ( let k = 0, c = 0; k < 9; k ++, c += 3 ) {

				const value = basis[ k ];
				sum[ c ] += value * r;
				sum[ c + 1 ] += value * g;
				sum[ c + 2 ] += value * b;

			}

		}

	}

	for ( let k = 0; k < SH_FLOATS; k ++ ) target[ targetOffset + k ] = sum[ k ];
	return target;

}

function buildTable( width: number, height: number ): EquirectTable {

	const rowY = new Float64Array( height );
	const rowCos = new Float64Array( height );
	const rowSolidAngle = new Float64Array( height );
	for ( let j = 0; j < height; j ++ ) {

		const latitudeTop = Math.PI / 2 - j * Math.PI / height;
		const latitudeBottom = Math.PI / 2 - ( j + 1 ) * Math.PI / height;
		const latitude = Math.PI / 2 - ( j + 0.5 ) * Math.PI / height;
		rowY[ j ] = Math.sin( latitude );
		rowCos[ j ] = Math.cos( latitude );
		rowSolidAngle[ j ] = ( 2 * Math.PI / width ) * ( Math.sin( latitudeTop ) - Math.sin( latitudeBottom ) );

	}

	const columnCos = new Float64Array( width );
	const columnSin = new Float64Array( width );
	for ( let i = 0; i < width; i ++ ) {

		const longitude = 2 * Math.PI * ( ( i + 0.5 ) / width - 0.5 );
		columnCos[ i ] = Math.cos( longitude );
		columnSin[ i ] = Math.sin( longitude );

	}

	return { rowY, rowCos, rowSolidAngle, columnCos, columnSin };

}
