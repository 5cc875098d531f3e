/**
 * The page side of moving typed arrays to Node: a script page returns base64 text from
 * page.evaluate (far faster than JSON arrays of numbers); Node decodes it with browser.ts's
 * `fromBase64`.
 */

/** The bytes of a typed array as base64, in chunks small enough for `String.fromCharCode( ... )`. */
export function toBase64( array: Float32Array | Int8Array ): string {

	const bytes = new Uint8Array( array.buffer, array.byteOffset, array.byteLength );
	let text = '';
	for ( let i = 0; i < bytes.length; i += 0x8000 ) text += String.fromCharCode( ...bytes.subarray( i, i + 0x8000 ) );
	return btoa( text );

}
