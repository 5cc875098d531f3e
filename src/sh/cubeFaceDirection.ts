/**
 * Texel → world direction for the faces of a cube render target rendered by three's `CubeCamera`
 * (WebGL coordinate system) and read back with
 * `renderer.readRenderTargetPixels( target, 0, 0, size, size, buffer, face )`.
 *
 * Derivation. Each CubeCamera face camera has fov −90°, so its projection matrix has
 * left = near, right = −near, top = −near, bottom = near: both NDC axes are mirrored,
 * x_ndc = −x_cam / depth and y_ndc = −y_cam / depth. The face cameras are oriented with
 * `up` / `lookAt` (+X: up +Y, look +X, so camera x = world +Z, camera y = world +Y; and so on).
 * readPixels returns rows bottom-up in window coordinates, i.e. buffer row j has
 * y_ndc = −1 + (j + ½)·2/size, and column i has x_ndc = −1 + (i + ½)·2/size. With
 * u = x_ndc and v = y_ndc, the direction of texel (i, j) of face f is
 * `normal_f + u·uAxis_f + v·vAxis_f`:
 *
 * | face | direction      |
 * |------|----------------|
 * | 0 +X | ( 1, −v, −u)   |
 * | 1 −X | (−1, −v,  u)   |
 * | 2 +Y | ( u,  1,  v)   |
 * | 3 −Y | ( u, −1, −v)   |
 * | 4 +Z | ( u, −v,  1)   |
 * | 5 −Z | (−u, −v, −1)   |
 *
 * This is exactly the OpenGL cube-map face table (s = (u+1)/2, t = (v+1)/2 with t = 0 in the
 * first row of memory): the negative fov exists so that the rendered faces are valid GL cube
 * maps. A consequence worth knowing: the FIRST row of the readback buffer of a side face is the
 * world's UP side (y > 0), although readPixels is "bottom-up". Verified on a real GL context in
 * test/sh/cubeFaceMapping.gpu.test.ts (agreement ≈ 1e-7 on every texel of every face).
 */

import { assertInteger, assertOutput } from '../validate.js';

/**
 * Per face (three.js order +X, −X, +Y, −Y, +Z, −Z) the 9 numbers
 * [ normal.xyz, uAxis.xyz, vAxis.xyz ]: the unnormalised texel direction is
 * `normal + u·uAxis + v·vAxis`, u from the column, v from the readback row (see module doc).
 */
export const CUBE_FACE_AXES: ReadonlyArray<readonly number[]> = Object.freeze( [
	Object.freeze( [ 1, 0, 0, 0, 0, - 1, 0, - 1, 0 ] ),
	Object.freeze( [ - 1, 0, 0, 0, 0, 1, 0, - 1, 0 ] ),
	Object.freeze( [ 0, 1, 0, 1, 0, 0, 0, 0, 1 ] ),
	Object.freeze( [ 0, - 1, 0, 1, 0, 0, 0, 0, - 1 ] ),
	Object.freeze( [ 0, 0, 1, 1, 0, 0, 0, - 1, 0 ] ),
	Object.freeze( [ 0, 0, - 1, - 1, 0, 0, 0, - 1, 0 ] ),
] );

/**
 * Unit world direction through the centre of texel (`column`, `row`) of cube face `face`, where
 * `row` counts rows in the order `readRenderTargetPixels` returns them (first row first).
 * @param face 0..5 in three.js order +X, −X, +Y, −Y, +Z, −Z.
 * @param column 0..size−1, left to right in the readback buffer.
 * @param row 0..size−1, first to last row of the readback buffer.
 * @param size Face edge length in texels.
 * @param out Receives x, y, z (length ≥ 3); a new Float64Array(3) when omitted.
 * @returns `out`.
 */
export function cubeFaceDirection<T extends { [ index: number ]: number; readonly length: number } = Float64Array>( face: number, column: number, row: number, size: number, out?: T ): T {

	assertInteger( 'cubeFaceDirection', 'size', size, 1 );
	assertInteger( 'cubeFaceDirection', 'face', face, 0, 5 );
	assertInteger( 'cubeFaceDirection', 'column', column, 0, size - 1 );
	assertInteger( 'cubeFaceDirection', 'row', row, 0, size - 1 );
	const target = ( out ?? new Float64Array( 3 ) ) as T;
	assertOutput( 'cubeFaceDirection', 'out', target, 3 );

	const u = - 1 + ( column + 0.5 ) * 2 / size;
	const v = - 1 + ( row + 0.5 ) * 2 / size;
	const a = CUBE_FACE_AXES[ face ];
	const x = a[ 0 ] + u * a[ 3 ] + v * a[ 6 ];
	const y = a[ 1 ] + u * a[ 4 ] + v * a[ 7 ];
	const z = a[ 2 ] + u * a[ 5 ] + v * a[ 8 ];
	const inverseLength = 1 / Math.sqrt( x * x + y * y + z * z );
	target[ 0 ] = x * inverseLength;
	target[ 1 ] = y * inverseLength;
	target[ 2 ] = z * inverseLength;
	return target;

}
