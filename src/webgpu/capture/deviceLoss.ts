import type { WebGPURenderer } from 'three/webgpu';

/*
 * Whether a WebGPURenderer can still draw. three marks a lost device (`GPUDevice.lost`) or WebGL
 * context only when the loss is not a `destroy()` call, and not at all when the page replaced its
 * `onDeviceLost`; so the capture watches the device itself, and asks the WebGL2 backend's context.
 */

const lost = new WeakSet<object>();
const watched = new WeakSet<object>();

interface BackendLike {

	isWebGPUBackend?: boolean;
	device?: { lost?: Promise<unknown> } | null;
	gl?: { isContextLost(): boolean } | null;

}

/** Starts watching `renderer`'s GPU device for loss (once per renderer; the renderer initialised). */
export function watchDevice( renderer: WebGPURenderer ): void {

	const backend = renderer.backend as unknown as BackendLike;
	const device = backend.device;
	if ( watched.has( renderer ) || ! device?.lost ) return;
	watched.add( renderer );
	device.lost.then( () => { lost.add( renderer ); } );

}

/** Whether `renderer`'s device (WebGPU backend) or context (WebGL2 backend) is lost. */
export function isDeviceLost( renderer: WebGPURenderer ): boolean {

	if ( lost.has( renderer ) || ( renderer as unknown as { _isDeviceLost?: boolean } )._isDeviceLost === true ) return true;
	const gl = ( renderer.backend as unknown as BackendLike ).gl;
	return gl ? gl.isContextLost() : false;

}

/** The named error of a capture on a lost device or context (the same wording as the WebGL capture's). */
export function deviceLostError( where: string, renderer: WebGPURenderer, cause?: unknown ): Error {

	const webgpu = ( renderer.backend as unknown as BackendLike ).isWebGPUBackend === true;
	const message = webgpu
		? `${where}: the WebGPU device was lost (the context was lost); the SH already held are kept. A lost device does not come back: `
			+ 'create the WebGPURenderer again (await renderer.init()) and capture again.'
		: `${where}: the WebGL context was lost; the SH already held are kept. Capture again after "webglcontextrestored".`;
	return new Error( message, cause === undefined ? undefined : { cause } );

}
