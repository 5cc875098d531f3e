import { DataTexture, FloatType, NearestFilter, RedFormat } from 'three';
import { cubeTexelSolidAngle, paperTexelSolidAngle } from '../sh/cubeTexelSolidAngle.js';
import type { CubeSolidAngleMode } from '../sh/projectCubeMapToSH.js';

/**
 * Texel solid angles of one cube-face quadrant (the same on all six faces and on the four mirror
 * images of a texel), as a float texture, for the GPU projections of both renderers. On an odd
 * size the middle row and column are their own mirror images, read twice by the shader, so they
 * hold half their solid angle (the middle texel a quarter): halving is exact in floating point.
 */
export function createSolidAngleTexture( size: number, mode: CubeSolidAngleMode ): DataTexture {

	const solidAngle = mode === 'exact' ? cubeTexelSolidAngle : paperTexelSolidAngle;
	const quadrant = Math.ceil( size / 2 );
	const data = new Float32Array( quadrant * quadrant );
	let total = 0;
	for ( let row = 0; row < size; row ++ ) {

		for ( let column = 0; column < size; column ++ ) {

			const omega = solidAngle( column, row, size );
			total += 6 * omega;
			if ( row >= quadrant || column >= quadrant ) continue;
			const mirrors = ( 2 * column + 1 === size ? 2 : 1 ) * ( 2 * row + 1 === size ? 2 : 1 );
			data[ row * quadrant + column ] = omega / mirrors;

		}

	}

	// The paper's weights are rescaled to sum to 4π (its step 4), like projectCubeMapToSH does.
	if ( mode === 'paper' ) for ( let i = 0; i < data.length; i ++ ) data[ i ] *= 4 * Math.PI / total;

	const texture = new DataTexture( data, quadrant, quadrant, RedFormat, FloatType );
	texture.minFilter = texture.magFilter = NearestFilter;
	texture.needsUpdate = true;
	return texture;

}
