/**
 * The points (x, y, z each) whose class in `classes` (one per point, e.g. from `classifyPoints`)
 * is `keep`, in order.
 */
export function keepClass( points: ArrayLike<number>, classes: Uint8Array, keep: number ): Float64Array {

	let kept = 0;
	const out = new Float64Array( 3 * classes.length );
	for ( let i = 0; i < classes.length; i ++ ) {

		if ( classes[ i ] !== keep ) continue;
		out[ 3 * kept ] = points[ 3 * i ]; out[ 3 * kept + 1 ] = points[ 3 * i + 1 ]; out[ 3 * kept + 2 ] = points[ 3 * i + 2 ];
		kept ++;

	}

	return out.slice( 0, 3 * kept );

}
