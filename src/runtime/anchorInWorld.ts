import type { Object3D } from 'three';

/**
 * Writes the world position of `anchor` — a point in `object`'s local frame, where it samples the
 * probes — under `object.matrixWorld` (as it stands) into `out`, and returns `out`. Allocation-free.
 */
export function anchorInWorld( object: Object3D, anchor: ArrayLike<number>, out: Float64Array ): Float64Array {

	const e = object.matrixWorld.elements, a0 = anchor[ 0 ], a1 = anchor[ 1 ], a2 = anchor[ 2 ];
	out[ 0 ] = e[ 0 ] * a0 + e[ 4 ] * a1 + e[ 8 ] * a2 + e[ 12 ];
	out[ 1 ] = e[ 1 ] * a0 + e[ 5 ] * a1 + e[ 9 ] * a2 + e[ 13 ];
	out[ 2 ] = e[ 2 ] * a0 + e[ 6 ] * a1 + e[ 10 ] * a2 + e[ 14 ];
	return out;

}
