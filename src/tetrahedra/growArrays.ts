/** A copy of `array` resized to `length` (truncated or zero-padded). */
export function growInt32( array: Int32Array, length: number ): Int32Array<ArrayBuffer> {

	const grown = new Int32Array( length );
	grown.set( array.subarray( 0, Math.min( array.length, length ) ) );
	return grown;

}

/** A copy of `array` resized to `length` (truncated or zero-padded). */
export function growUint32( array: Uint32Array, length: number ): Uint32Array<ArrayBuffer> {

	const grown = new Uint32Array( length );
	grown.set( array.subarray( 0, Math.min( array.length, length ) ) );
	return grown;

}
