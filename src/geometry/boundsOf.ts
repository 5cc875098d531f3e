/**
 * Axis-aligned bounds of a flat xyz array (pure: no three.js).
 *
 * Writes `[ minX, minY, minZ, maxX, maxY, maxZ ]` into `target` (a new `Float64Array(6)` by
 * default) over the first `count` points; with no points the bounds are empty (min = +∞, max = −∞).
 */
export function boundsOf(
	positions: ArrayLike<number>, count = Math.floor( positions.length / 3 ), target: Float64Array | number[] = new Float64Array( 6 ),
): Float64Array | number[] {

	let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
	for ( let i = 0; i < count; i ++ ) {

		const x = positions[ 3 * i ], y = positions[ 3 * i + 1 ], z = positions[ 3 * i + 2 ];
		if ( x < minX ) minX = x;
		if ( x > maxX ) maxX = x;
		if ( y < minY ) minY = y;
		if ( y > maxY ) maxY = y;
		if ( z < minZ ) minZ = z;
		if ( z > maxZ ) maxZ = z;

	}

	target[ 0 ] = minX; target[ 1 ] = minY; target[ 2 ] = minZ;
	target[ 3 ] = maxX; target[ 4 ] = maxY; target[ 5 ] = maxZ;
	return target;

}
