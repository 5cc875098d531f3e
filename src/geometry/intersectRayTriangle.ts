// Below this |det| the ray is treated as parallel to the triangle's plane. Relative to the edge
// lengths (det is a product of three of them), so it does not depend on the scene's units.
const PARALLEL_EPSILON = 1e-12;

/**
 * Möller–Trumbore ray–triangle intersection ("Fast, minimum storage ray/triangle intersection",
 * 1997) on one triangle of a flat array: 9 floats per triangle (a, b, c), starting at `9 · triangle`.
 *
 * Both faces count (parity counting needs every crossing, whatever the winding). Hits on an edge
 * or vertex count for every triangle sharing it (the barycentric test is inclusive), so a ray
 * through a shared edge can report two crossings where there is one: callers that count
 * crossings use several ray directions and a majority vote.
 * @param triangles 9 floats per triangle.
 * @param triangle Triangle index.
 * @param ox Ray origin x (and `oy`, `oz`).
 * @param dx Ray direction x (and `dy`, `dz`); need not be unit length — `t` is in its units.
 * @returns The ray parameter t > 0 of the hit (point = o + t · d), or −1 when there is none.
 */
export function intersectRayTriangle(
	triangles: ArrayLike<number>, triangle: number,
	ox: number, oy: number, oz: number,
	dx: number, dy: number, dz: number
): number {

	const k = 9 * triangle;
	const ax = triangles[ k ], ay = triangles[ k + 1 ], az = triangles[ k + 2 ];
	const e1x = triangles[ k + 3 ] - ax, e1y = triangles[ k + 4 ] - ay, e1z = triangles[ k + 5 ] - az;
	const e2x = triangles[ k + 6 ] - ax, e2y = triangles[ k + 7 ] - ay, e2z = triangles[ k + 8 ] - az;

	// p = d × e2; det = e1 · p is the (scaled) cosine between the ray and the triangle's plane.
	const px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
	const det = e1x * px + e1y * py + e1z * pz;
	const scale = ( Math.abs( e1x ) + Math.abs( e1y ) + Math.abs( e1z ) ) * ( Math.abs( e2x ) + Math.abs( e2y ) + Math.abs( e2z ) )
		* ( Math.abs( dx ) + Math.abs( dy ) + Math.abs( dz ) );
	if ( ! ( Math.abs( det ) > PARALLEL_EPSILON * scale ) ) return - 1;
	const inverse = 1 / det;

	const sx = ox - ax, sy = oy - ay, sz = oz - az;
	const u = ( sx * px + sy * py + sz * pz ) * inverse;
	if ( u < 0 || u > 1 ) return - 1;

	const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
	const v = ( dx * qx + dy * qy + dz * qz ) * inverse;
	if ( v < 0 || u + v > 1 ) return - 1;

	const t = ( e2x * qx + e2y * qy + e2z * qz ) * inverse;
	return t > 0 ? t : - 1;

}
