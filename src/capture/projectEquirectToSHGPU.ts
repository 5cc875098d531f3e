import type { Texture, WebGLRenderer } from 'three';
import { SHProjector } from './SHProjector.js';
import { SH_FLOATS, describeValue } from '../validate.js';
import { assertCaptureBackend, prepareRenderer } from './captureBackends.js';
import type { CaptureRenderer, WebGPURendererLike } from './captureSettings.js';

/**
 * GPU counterpart of {@link projectEquirectToSH}: projects an equirectangular panorama texture
 * (an `.hdr` through three's `HDRLoader`, or an LDR JPEG/PNG with `colorSpace = SRGBColorSpace`,
 * which the GPU decodes to linear) onto SH9, in the same world orientation three uses when the
 * texture is shown with `EquirectangularReflectionMapping`.
 *
 * With a `WebGPURenderer` (the library imported from `three-capture-lighting/webgpu`) the
 * projection runs on its GPU too and the result comes back asynchronously: the call returns a
 * promise (`await` works on both).
 *
 * @param renderer A WebGL2 renderer, or a WebGPURenderer (either backend).
 * @param texture The panorama; it must have its image loaded (width and height known).
 * @param target Receives the 27 floats; a new Float32Array(27) when omitted.
 * @returns `target` (with a WebGPURenderer, a promise of it).
 */
export function projectEquirectToSHGPU( renderer: WebGLRenderer, texture: Texture, target?: Float32Array ): Float32Array;
export function projectEquirectToSHGPU( renderer: WebGPURendererLike, texture: Texture, target?: Float32Array ): Promise<Float32Array>;
export function projectEquirectToSHGPU(
	renderer: CaptureRenderer, texture: Texture, target?: Float32Array,
): Float32Array | Promise<Float32Array>;
export function projectEquirectToSHGPU(
	renderer: CaptureRenderer, texture: Texture, target: Float32Array = new Float32Array( SH_FLOATS ),
): Float32Array | Promise<Float32Array> {

	const webgpu = assertCaptureBackend( 'projectEquirectToSHGPU', renderer );
	const kind = texture as { isTexture?: boolean; isCubeTexture?: boolean } | null;
	if ( kind?.isTexture !== true || kind.isCubeTexture === true ) {

		throw new TypeError( `projectEquirectToSHGPU: texture must be a three.js 2D Texture (an equirectangular panorama), got ${describeValue( texture )}.` );

	}

	if ( ! ( target instanceof Float32Array ) || target.length < SH_FLOATS ) {

		throw new RangeError( `projectEquirectToSHGPU: target must be a Float32Array with room for ${SH_FLOATS} floats, got ${target instanceof Float32Array ? `length ${target.length}` : typeof target}.` );

	}

	const image = texture?.image as { width?: number; height?: number } | undefined;
	const width = image?.width, height = image?.height;
	if ( ! width || ! height ) {

		throw new Error( 'projectEquirectToSHGPU: texture has no image size yet; wait for the loader to finish (e.g. await loader.loadAsync( url )).' );

	}

	if ( webgpu !== null ) {

		return prepareRenderer( renderer ).then( () => webgpu.projectEquirect( renderer as WebGPURendererLike, texture, target ) );

	}

	const projector = new SHProjector( renderer as WebGLRenderer );
	try {

		projector.begin( 'equirect', width, 1, { height } );
		projector.add( texture );
		return projector.finish( target );

	} finally {

		projector.dispose();

	}

}
