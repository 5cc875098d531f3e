/** Shared scene builders and analytic shapes for the placement tests. */
import type { BufferGeometry } from 'three';

/** The triangles of a three.js geometry, 9 floats each, in its local space. */
export function trianglesOf( geometry: BufferGeometry ): Float64Array {

	const flat = geometry.index ? geometry.toNonIndexed() : geometry;
	return Float64Array.from( flat.getAttribute( 'position' ).array );

}

/** Signed distance to a sphere (negative inside). */
export function sphereDistance( x: number, y: number, z: number, cx: number, cy: number, cz: number, radius: number ): number {

	return Math.hypot( x - cx, y - cy, z - cz ) - radius;

}

/**
 * Signed distance to a torus whose axis is `axis` ('y' or 'z'), centred at c (negative inside).
 * three's TorusGeometry lies in the xy plane (axis z).
 */
export function torusDistance( x: number, y: number, z: number, cx: number, cy: number, cz: number, radius: number, tube: number, axis: 'y' | 'z' = 'z' ): number {

	const dx = x - cx, dy = y - cy, dz = z - cz;
	const ring = axis === 'z' ? Math.hypot( dx, dy ) : Math.hypot( dx, dz );
	const along = axis === 'z' ? dz : dy;
	return Math.hypot( ring - radius, along ) - tube;

}

/** Signed distance to an axis-aligned box given by centre and half sizes (negative inside). */
export function boxDistance(
	x: number, y: number, z: number, cx: number, cy: number, cz: number, hx: number, hy: number, hz: number
): number {

	const qx = Math.abs( x - cx ) - hx, qy = Math.abs( y - cy ) - hy, qz = Math.abs( z - cz ) - hz;
	const outside = Math.hypot( Math.max( qx, 0 ), Math.max( qy, 0 ), Math.max( qz, 0 ) );
	return outside + Math.min( Math.max( qx, qy, qz ), 0 );

}
