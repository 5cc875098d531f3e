/**
 * Texel → world direction for the faces of a cube render target rendered by three's `CubeCamera`
 * (WebGL coordinate system) and read back with
 * `renderer.readRenderTargetPixels( target, 0, 0, size, size, buffer, face )`. The mapping is the
 * OpenGL cube-map face table; note that the first readback row of a side face is the world's up
 * side. Derivation and table: docs/cube-faces.md.
 */

import { assertInteger, assertOutput } from '../validate.js';

/**
 * Per face (three.js order +X, −X, +Y, −Y, +Z, −Z) the 9 numbers
 * [ normal.xyz, uAxis.xyz, vAxis.xyz ]: the unnormalised texel direction is
 * `normal + u·uAxis + v·vAxis`, u from the column, v from the readback row (docs/cube-faces.md).
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
export function cubeFaceDirection<T extends { [ index: number ]: number; readonly length: number } = Float64Array>(
	face: number, column: number, row: number, size: number, out?: T,
): T {

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
