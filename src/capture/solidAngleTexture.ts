import { DataTexture, FloatType, NearestFilter, RGBAFormat, RedFormat } from 'three';
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

/**
 * The direction and weight tables of a `width` × `height` equirectangular panorama for the GPU
 * projections of both renderers, computed in float64 like `projectEquirectToSH`'s and stored as
 * float32: an RGBA float texture max( width, height ) × 2 whose row 0 holds each column's
 * ( cos φ, sin φ ) and row 1 each texel row's ( sin latitude, cos latitude, solid angle of one
 * texel ), rows counted up from the nadir as the texture's rows are. The shaders read them by
 * index instead of evaluating sin and cos themselves: a GPU's float32 sin / cos may be far less
 * accurate than float32 rounding (SwiftShader's visibly moved the quadratic coefficients).
 */
export function createEquirectTableTexture( width: number, height: number ): DataTexture {

	const length = Math.max( width, height );
	const data = new Float32Array( 4 * length * 2 );
	for ( let i = 0; i < width; i ++ ) {

		const longitude = 2 * Math.PI * ( ( i + 0.5 ) / width - 0.5 );
		data[ 4 * i ] = Math.cos( longitude );
		data[ 4 * i + 1 ] = Math.sin( longitude );

	}

	for ( let j = 0; j < height; j ++ ) {

		// Row j from the bottom is row height − 1 − j from the top, the CPU projection's index.
		const top = height - 1 - j;
		const latitudeTop = Math.PI / 2 - top * Math.PI / height;
		const latitudeBottom = Math.PI / 2 - ( top + 1 ) * Math.PI / height;
		const latitude = Math.PI / 2 - ( top + 0.5 ) * Math.PI / height;
		const k = 4 * ( length + j );
		data[ k ] = Math.sin( latitude );
		data[ k + 1 ] = Math.cos( latitude );
		data[ k + 2 ] = ( 2 * Math.PI / width ) * ( Math.sin( latitudeTop ) - Math.sin( latitudeBottom ) );

	}

	const texture = new DataTexture( data, length, 2, RGBAFormat, FloatType );
	texture.minFilter = texture.magFilter = NearestFilter;
	texture.needsUpdate = true;
	return texture;

}
