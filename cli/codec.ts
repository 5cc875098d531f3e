import {
	BAKED_VOLUME_MAGIC, bakedVolumeFromJSON, bakedVolumeToJSON, decodeBakedVolume, encodeBakedVolume,
	type BakedVolumeData, type BakedVolumeInput,
} from '../src/io/index.js';

/**
 * What `bake` writes: the codec's input, where null tetrahedra and neighbours (a planar or collinear
 * layout, see `tetrahedralizeLayout`) mean a volume stored without them.
 */
export type VolumeData = Omit<BakedVolumeInput, 'tetrahedra' | 'neighbors'> & {
	tetrahedra?: BakedVolumeInput[ 'tetrahedra' ] | null;
	neighbors?: BakedVolumeInput[ 'neighbors' ] | null;
};

/** A decoded volume file. */
export interface ReadVolume {

	data: BakedVolumeData;
	format: 'bin' | 'json';
	/** SH storage: the binary header's flag, or 'json' (exact decimal numbers). */
	precision: 'float16' | 'float32' | 'json';

}

/**
 * Encodes a volume in the binary or the JSON form of the baked-volume codec (src/io); without
 * tetrahedra when they are null or absent.
 * @throws {BakedVolumeError} from the codec (invalid data, float16 overflow).
 */
export function encodeVolume( data: VolumeData, format: 'bin' | 'json', precision: 'float16' | 'float32' ): Uint8Array {

	const { tetrahedra, neighbors, ...rest } = data;
	const input: BakedVolumeInput = rest;
	if ( tetrahedra != null ) input.tetrahedra = tetrahedra;
	if ( neighbors != null ) input.neighbors = neighbors;
	if ( format === 'json' ) return new TextEncoder().encode( JSON.stringify( bakedVolumeToJSON( input ) ) + '\n' );
	return new Uint8Array( encodeBakedVolume( input, { precision } ) );

}

/**
 * Decodes and validates a volume file's bytes: binary when they start with the format's magic
 * bytes, JSON when they start with "{" (after white space), else binary, whose reader names the problem.
 * @throws {BakedVolumeError} from the codec.
 */
export function readVolume( bytes: Uint8Array ): ReadVolume {

	let first = 0;
	while ( first < bytes.length && (
		bytes[ first ] === 0x20 || bytes[ first ] === 0x0A || bytes[ first ] === 0x0D || bytes[ first ] === 0x09 ||
		bytes[ first ] === 0xEF || bytes[ first ] === 0xBB || bytes[ first ] === 0xBF
	) ) first ++;
	const binary = bytes.length >= 8 && BAKED_VOLUME_MAGIC.every( ( byte, i ) => bytes[ i ] === byte );
	if ( ! binary && bytes[ first ] === 0x7B ) {

		return { data: bakedVolumeFromJSON( new TextDecoder().decode( bytes ) ), format: 'json', precision: 'json' };

	}

	const data = decodeBakedVolume( bytes );
	// Header flags (docs/format.md): bit 0 of the u32 at byte 24 = SH stored as float16.
	const flags = new DataView( bytes.buffer, bytes.byteOffset, bytes.byteLength ).getUint32( 24, true );
	return { data, format: 'bin', precision: ( flags & 1 ) ? 'float16' : 'float32' };

}
