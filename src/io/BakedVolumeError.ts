/** What is wrong with a baked light probe volume; one value per failure class (see docs/format.md). */
export type BakedVolumeErrorCode =
	| 'truncated' // the buffer is shorter than the header or than the length it declares
	| 'bad-magic' // not a baked light probe volume at all
	| 'version' // a major version this reader does not know, or an unknown required section
	| 'checksum' // CRC-32 mismatch: the bytes were corrupted
	| 'header' // header fields out of their allowed values (header size, reserved flags)
	| 'section' // section table: offsets out of the file, misaligned, overlapping, duplicated, missing
	| 'count' // a count that disagrees with the section lengths or the data
	| 'range' // an index out of range (tetrahedron vertex, neighbour, zone probe, role)
	| 'nan' // NaN or ±Infinity in positions, SH, bounds or capture settings
	| 'orientation' // a tetrahedron that is not positively oriented (flat or inverted)
	| 'neighbors' // neighbour links that are not symmetric or do not share a face
	| 'utf8' // a string that is not valid UTF-8
	| 'json' // malformed JSON (the JSON form, or the capture settings section)
	| 'float16-overflow' // an SH value too large for float16 (encoder only)
	| 'argument'; // a wrong argument type given to an encoder or to the glTF plugins

/**
 * The one error class of the baked-volume codec: every rejection of a file, a JSON object or a
 * volume to encode throws this, with a {@link BakedVolumeError.code} naming the failure class and a
 * message naming the function, the field and, where there is one, the index.
 */
export class BakedVolumeError extends Error {

	/** The failure class. */
	readonly code: BakedVolumeErrorCode;

	/**
	 * @param code The failure class.
	 * @param message Names the function, the field and the problem.
	 */
	constructor( code: BakedVolumeErrorCode, message: string ) {

		super( message );
		this.name = 'BakedVolumeError';
		this.code = code;

	}

}
