/**
 * Closest point of triangle abc to p (Ericson, "Real-Time Collision Detection", 5.1.5), by Voronoi
 * region, so the result is continuous in p and exact on edges and vertices.
 * @param out Receives the point (out[0..2]) and its barycentric weights for a, b, c (out[3..5]).
 * @returns The squared distance from p to the triangle.
 */
export function closestPointOnTriangle(
	px: number, py: number, pz: number,
	ax: number, ay: number, az: number,
	bx: number, by: number, bz: number,
	cx: number, cy: number, cz: number,
	out: Float64Array
): number {

	const abx = bx - ax, aby = by - ay, abz = bz - az;
	const acx = cx - ax, acy = cy - ay, acz = cz - az;
	const apx = px - ax, apy = py - ay, apz = pz - az;
	let u: number, v: number, w: number;

	const d1 = abx * apx + aby * apy + abz * apz;
	const d2 = acx * apx + acy * apy + acz * apz;
	if ( d1 <= 0 && d2 <= 0 ) {

		u = 1; v = 0; w = 0;

	} else {

		const bpx = px - bx, bpy = py - by, bpz = pz - bz;
		const d3 = abx * bpx + aby * bpy + abz * bpz;
		const d4 = acx * bpx + acy * bpy + acz * bpz;
		const cpx = px - cx, cpy = py - cy, cpz = pz - cz;
		const d5 = abx * cpx + aby * cpy + abz * cpz;
		const d6 = acx * cpx + acy * cpy + acz * cpz;
		const vc = d1 * d4 - d3 * d2;
		const vb = d5 * d2 - d1 * d6;
		const va = d3 * d6 - d5 * d4;

		if ( d3 >= 0 && d4 <= d3 ) {

			u = 0; v = 1; w = 0;

		} else if ( vc <= 0 && d1 >= 0 && d3 <= 0 ) {

			v = d1 / ( d1 - d3 ); u = 1 - v; w = 0;

		} else if ( d6 >= 0 && d5 <= d6 ) {

			u = 0; v = 0; w = 1;

		} else if ( vb <= 0 && d2 >= 0 && d6 <= 0 ) {

			w = d2 / ( d2 - d6 ); u = 1 - w; v = 0;

		} else if ( va <= 0 && ( d4 - d3 ) >= 0 && ( d5 - d6 ) >= 0 ) {

			w = ( d4 - d3 ) / ( ( d4 - d3 ) + ( d5 - d6 ) ); v = 1 - w; u = 0;

		} else {

			const denom = 1 / ( va + vb + vc );
			v = vb * denom; w = vc * denom; u = 1 - v - w;

		}

	}

	const qx = u * ax + v * bx + w * cx, qy = u * ay + v * by + w * cy, qz = u * az + v * bz + w * cz;
	out[ 0 ] = qx; out[ 1 ] = qy; out[ 2 ] = qz;
	out[ 3 ] = u; out[ 4 ] = v; out[ 5 ] = w;
	const dx = px - qx, dy = py - qy, dz = pz - qz;
	return dx * dx + dy * dy + dz * dz;

}
