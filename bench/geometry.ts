/**
 * Exact geometric checks shared by the benchmarks.
 */

import { orient3d } from 'robust-predicates';

/**
 * Sign of det[ p1 − p0, p2 − p0, p3 − p0 ] for points given by index into flat xyz, exactly
 * (robust-predicates' orient3d has the opposite sign): 1, −1 or 0 for a flat tetrahedron.
 */
export function orientation( points: ArrayLike<number>, i0: number, i1: number, i2: number, i3: number ): number {

	const a = 3 * i0, b = 3 * i1, c = 3 * i2, d = 3 * i3;
	const o = orient3d(
		points[ a ], points[ a + 1 ], points[ a + 2 ],
		points[ b ], points[ b + 1 ], points[ b + 2 ],
		points[ c ], points[ c + 1 ], points[ c + 2 ],
		points[ d ], points[ d + 1 ], points[ d + 2 ] );
	return o < 0 ? 1 : o > 0 ? - 1 : 0;

}

/** Signed volume of a tetrahedron, det[ p1 − p0, p2 − p0, p3 − p0 ] / 6, in floating point. */
export function signedVolume( points: ArrayLike<number>, i0: number, i1: number, i2: number, i3: number ): number {

	const a = 3 * i0, b = 3 * i1, c = 3 * i2, d = 3 * i3;
	const ux = points[ b ] - points[ a ], uy = points[ b + 1 ] - points[ a + 1 ], uz = points[ b + 2 ] - points[ a + 2 ];
	const vx = points[ c ] - points[ a ], vy = points[ c + 1 ] - points[ a + 1 ], vz = points[ c + 2 ] - points[ a + 2 ];
	const wx = points[ d ] - points[ a ], wy = points[ d + 1 ] - points[ a + 1 ], wz = points[ d + 2 ] - points[ a + 2 ];
	return ( ux * ( vy * wz - vz * wy ) - uy * ( vx * wz - vz * wx ) + uz * ( vx * wy - vy * wx ) ) / 6;

}
