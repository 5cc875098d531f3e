import { PROBE_ROLES, type ProbeRole } from '../roles.js';

/*
 * Constants of the baked light probe volume's binary format (docs/format.md): a versioned
 * little-endian file holding everything a LightProbeVolume needs to light a scene without capturing
 * or tetrahedralizing again. The reference reader and writer are decodeBakedVolume.ts and
 * encodeBakedVolume.ts; no three.js in src/io: it runs in plain Node, in workers and in build tools.
 */

/** Role codes of the ROLE section: the index in this list (= {@link PROBE_ROLES}). */
export const BAKED_ROLES: readonly ProbeRole[] = PROBE_ROLES;

/** Major version this code reads and writes. */
export const BAKED_VOLUME_VERSION_MAJOR = 1;

/**
 * Newest minor version this code writes: 1.1 added the optional GRAD and FITS sections. A file
 * without them is written as 1.0 ({@link bakedVolumeMinorVersion}), byte for byte what 1.0 wrote.
 */
export const BAKED_VOLUME_VERSION_MINOR = 1;

/** The 8 magic bytes at offset 0: 0xAB 'L' 'P' 'V' '\r' '\n' 0x1A '\n'. */
export const BAKED_VOLUME_MAGIC: readonly number[] = [ 0xAB, 0x4C, 0x50, 0x56, 0x0D, 0x0A, 0x1A, 0x0A ];

/** `format` tag of the JSON form. */
export const BAKED_VOLUME_JSON_FORMAT = 'three-capture-lighting/baked-light-probe-volume';

/** Bytes of the header, before the section table. */
export const HEADER_SIZE = 64;

/** Bytes of one section table entry: id, flags, offset, length (u32 each). */
export const ENTRY_SIZE = 16;

/** Header flag bit: the SH are stored as float16. */
export const FLAG_SH_FLOAT16 = 1;

/** Section flag bit: a reader that does not know the section must refuse the file. */
export const SECTION_REQUIRED = 1;

/** Four ASCII characters as a little-endian u32. */
function fourCC( s: string ): number {

	return ( s.charCodeAt( 0 ) | ( s.charCodeAt( 1 ) << 8 ) | ( s.charCodeAt( 2 ) << 16 ) | ( s.charCodeAt( 3 ) << 24 ) ) >>> 0;

}

/** Section ids: four ASCII characters read as a little-endian u32. */
export const BAKED_SECTION = {
	POSITIONS: fourCC( 'POS ' ),
	SH: fourCC( 'SH  ' ),
	TETRAHEDRA: fourCC( 'TETS' ),
	NEIGHBORS: fourCC( 'NBRS' ),
	ROLES: fourCC( 'ROLE' ),
	NAMES: fourCC( 'NAME' ),
	ZONES: fourCC( 'ZONE' ),
	BOUNDS: fourCC( 'BNDS' ),
	CAPTURE: fourCC( 'CAPT' ),
	METADATA: fourCC( 'META' ),
	GRADIENTS: fourCC( 'GRAD' ),
	FIT: fourCC( 'FITS' ),
} as const;

/** Floats per probe of the GRAD section: ∂(SH float k)/∂(axis a) at 27·a + k. */
export const GRADIENT_FLOATS = 81;

/** The minor version a writer gives a file: the lowest whose sections it holds (1 with gradients or a fit record, else 0). */
export function bakedVolumeMinorVersion( data: { gradients: unknown; fit: unknown } ): number {

	return data.gradients !== null || data.fit !== null ? 1 : 0;

}

/** The section ids this reader knows. */
export const KNOWN_SECTIONS = new Set<number>( Object.values( BAKED_SECTION ) );

/** A section id as its four characters in quotes, for messages ('?' for unprintable bytes). */
export function sectionName( id: number ): string {

	let s = '';
	for ( let k = 0; k < 4; k ++ ) {

		const c = ( id >>> ( 8 * k ) ) & 0xFF;
		s += c >= 0x20 && c < 0x7F ? String.fromCharCode( c ) : '?';

	}

	return `'${s}'`;

}

/**
 * `n` rounded up to a multiple of 8 (sections and zone fields are 8-aligned). Float arithmetic, not
 * `& ~7`: sizes computed from hostile counts exceed 32 bits.
 */
export const align8 = ( n: number ): number => Math.ceil( n / 8 ) * 8;

/** Whether this platform stores typed arrays little-endian (then sections are copied or viewed as they are). */
export const LITTLE_ENDIAN = new Uint8Array( new Uint16Array( [ 1 ] ).buffer )[ 0 ] === 1;
