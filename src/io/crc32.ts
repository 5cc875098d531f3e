/*
 * CRC-32 (IEEE 802.3, the one of zlib, PNG and gzip: reflected polynomial 0xEDB88320, initial value
 * and final XOR 0xFFFFFFFF), slicing-by-8 so a 30 MB volume is checked in tens of milliseconds.
 */

let tables: Uint32Array | null = null;

function buildTables(): Uint32Array {

	const t = new Uint32Array( 8 * 256 );
	for ( let n = 0; n < 256; n ++ ) {

		let c = n;
		for ( let k = 0; k < 8; k ++ ) c = c & 1 ? 0xEDB88320 ^ ( c >>> 1 ) : c >>> 1;
		t[ n ] = c >>> 0;

	}

	for ( let n = 0; n < 256; n ++ ) {

		let c = t[ n ];
		for ( let k = 1; k < 8; k ++ ) {

			c = t[ c & 0xFF ] ^ ( c >>> 8 );
			t[ 256 * k + n ] = c >>> 0;

		}

	}

	return t;

}

/**
 * CRC-32 of `bytes[ start, end )`, as zlib's `crc32()` computes it.
 * @returns An unsigned 32-bit value.
 */
export function crc32( bytes: Uint8Array, start = 0, end = bytes?.length ): number {

	if ( ! ( bytes instanceof Uint8Array ) ) throw new TypeError( 'crc32: bytes must be a Uint8Array.' );
	if ( ! Number.isInteger( start ) || ! Number.isInteger( end ) || start < 0 || end < start || end > bytes.length ) {

		throw new RangeError( `crc32: need integers 0 ≤ start ≤ end ≤ bytes.length (${bytes.length}), got start ${start}, end ${end}.` );

	}

	const t = tables ?? ( tables = buildTables() );
	let c = 0xFFFFFFFF;
	let i = start;
	for ( const stop = end - 7; i < stop; i += 8 ) {

		const lo = c ^ ( bytes[ i ] | ( bytes[ i + 1 ] << 8 ) | ( bytes[ i + 2 ] << 16 ) | ( bytes[ i + 3 ] << 24 ) );
		c = t[ 1792 + ( lo & 0xFF ) ] ^ t[ 1536 + ( ( lo >>> 8 ) & 0xFF ) ]
			^ t[ 1280 + ( ( lo >>> 16 ) & 0xFF ) ] ^ t[ 1024 + ( lo >>> 24 ) ]
			^ t[ 768 + bytes[ i + 4 ] ] ^ t[ 512 + bytes[ i + 5 ] ] ^ t[ 256 + bytes[ i + 6 ] ] ^ t[ bytes[ i + 7 ] ];

	}

	for ( ; i < end; i ++ ) c = t[ ( c ^ bytes[ i ] ) & 0xFF ] ^ ( c >>> 8 );
	return ( c ^ 0xFFFFFFFF ) >>> 0;

}
