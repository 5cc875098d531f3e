/**
 * Solid angle subtended by one texel of a cube-map face (identical on all six faces, so no face
 * argument). Two versions so the paper's approximation can be measured against the truth.
 */

import { assertInteger } from '../validate.js';

/**
 * Exact solid angle of texel (`column`, `row`) of a `size`×`size` cube face. The texel is the
 * rectangle [x0, x1]×[y0, y1] on the face plane at distance 1, and
 * Ω = f(x0,y0) − f(x0,y1) − f(x1,y0) + f(x1,y1) with f(x, y) = atan2(x·y, √(x² + y² + 1)),
 * the closed-form integral of the area element dx·dy / (x² + y² + 1)^{3/2}. Summed over the six
 * faces this is 4π up to rounding, at any size.
 * @param column 0..size−1.
 * @param row 0..size−1.
 * @param size Face edge length in texels.
 */
export function cubeTexelSolidAngle( column: number, row: number, size: number ): number {

	assertInteger( 'cubeTexelSolidAngle', 'size', size, 1 );
	assertInteger( 'cubeTexelSolidAngle', 'column', column, 0, size - 1 );
	assertInteger( 'cubeTexelSolidAngle', 'row', row, 0, size - 1 );

	const x0 = - 1 + column * 2 / size;
	const x1 = - 1 + ( column + 1 ) * 2 / size;
	const y0 = - 1 + row * 2 / size;
	const y1 = - 1 + ( row + 1 ) * 2 / size;
	return cornerIntegral( x0, y0 ) - cornerIntegral( x0, y1 ) - cornerIntegral( x1, y0 ) + cornerIntegral( x1, y1 );

}

/**
 * The paper's texel solid angle A(ω) ≈ (r·n) / |r|³ · dS with dS = (2/w)(2/h), r the vector from
 * the cube centre to the texel centre on the unit cube (so r·n = 1) and n the face normal. This is
 * the raw value, before the paper's "Step 4: normalisation" (which
 * `projectCubeMapToSH( …, { solidAngle: 'paper' } )` applies by rescaling all weights to sum to 4π);
 * the raw values sum to slightly more than 4π (README, "Texel solid angle, paper vs exact").
 * @param column 0..size−1.
 * @param row 0..size−1.
 * @param size Face edge length in texels.
 */
export function paperTexelSolidAngle( column: number, row: number, size: number ): number {

	assertInteger( 'paperTexelSolidAngle', 'size', size, 1 );
	assertInteger( 'paperTexelSolidAngle', 'column', column, 0, size - 1 );
	assertInteger( 'paperTexelSolidAngle', 'row', row, 0, size - 1 );

	const u = - 1 + ( column + 0.5 ) * 2 / size;
	const v = - 1 + ( row + 0.5 ) * 2 / size;
	const lengthSq = 1 + u * u + v * v;
	return ( 2 / size ) * ( 2 / size ) / ( lengthSq * Math.sqrt( lengthSq ) );

}

/**
 * Antiderivative of the cube-face area element; see {@link cubeTexelSolidAngle}.
 * @internal
 */
export function cornerIntegral( x: number, y: number ): number {

	return Math.atan2( x * y, Math.sqrt( x * x + y * y + 1 ) );

}
