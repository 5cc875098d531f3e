import type { Texture, WebGPURenderer } from 'three/webgpu';
import { WebGPUSHProjector } from './WebGPUSHProjector.js';
import { deviceLostError, isDeviceLost, watchDevice } from './deviceLoss.js';

/**
 * `projectEquirectToSHGPU` on a WebGPURenderer (initialised; the texture checked by the caller):
 * one panorama projected by {@link WebGPUSHProjector} and read back.
 * @returns `target`, with the 27 floats.
 */
export async function projectEquirectWebGPU( renderer: WebGPURenderer, texture: Texture, target: Float32Array ): Promise<Float32Array> {

	const where = 'projectEquirectToSHGPU';
	watchDevice( renderer );
	if ( isDeviceLost( renderer ) ) throw deviceLostError( where, renderer );
	const image = texture.image as { width: number; height: number };
	const projector = new WebGPUSHProjector( renderer );
	try {

		projector.begin( 'equirect', image.width, 1, { height: image.height } );
		projector.add( texture );
		const sh = new Float32Array( 27 );
		await projector.finish( sh );
		if ( isDeviceLost( renderer ) ) throw deviceLostError( where, renderer );
		target.set( sh );
		return target;

	} finally {

		projector.dispose();

	}

}
