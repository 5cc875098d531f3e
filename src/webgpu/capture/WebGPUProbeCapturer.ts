import { CubeCamera, CubeRenderTarget, NearestFilter, type Object3D, type Scene, type TextureDataType, type WebGPURenderer } from 'three/webgpu';
import type { ProbeCaptureOptions, ProbeCaptureSettings } from '../../capture/ProbeCapturer.js';
import type { ProbeCapturerLike } from '../../capture/captureBackends.js';
import { captureClock, hideForCapture, nextTask, showAfterCapture } from '../../capture/captureHiding.js';
import { assertScene, checkCaptureCall, checkCaptureSettings } from '../../capture/captureSettings.js';
import type { CubeSolidAngleMode } from '../../sh/projectCubeMapToSH.js';
import { SH_FLOATS, SH_LIMIT, assertInteger, assertPoints, describeValue, firstBeyond } from '../../validate.js';
import { WebGPUSHProjector } from './WebGPUSHProjector.js';
import { WebGPUShadowFreeze } from './WebGPUShadowFreeze.js';
import { WebGPUCubeFaces } from './WebGPUCubeFaces.js';
import { deviceLostError, isDeviceLost, watchDevice } from './deviceLoss.js';

/**
 * `ProbeCapturer` for `WebGPURenderer` (`three/webgpu`, either backend): renders the six faces at
 * each probe (HalfFloat by default, NearestFilter), projects them to SH9 on the GPU
 * ({@link WebGPUSHProjector}) and reads each batch back once. On the WebGPU backend the faces are
 * six 2D targets laid out texel for texel as WebGLRenderer's cube faces ({@link WebGPUCubeFaces}),
 * projected by compute kernels reading them by index; on the WebGL2 backend three's `CubeCamera`
 * renders a `CubeRenderTarget`, projected by fragment passes. The same
 * settings, options, batching, progress, hiding and shadow rules as `ProbeCapturer`; a lost
 * device or context throws a named error and leaves `target` as it was.
 *
 * ```js
 * await renderer.init();
 * const capturer = new WebGPUProbeCapturer( renderer, { resolution: 32 } );
 * const sh = await capturer.capture( scene, positions, new Float32Array( 27 * count ) );
 * capturer.dispose();
 * ```
 */
export class WebGPUProbeCapturer implements ProbeCapturerLike {

	/** The renderer that draws the captures (initialised). */
	readonly renderer: WebGPURenderer;

	/** Cube face edge in texels. */
	readonly resolution: number;

	/** WebGL2 backend: the cube render target every probe is rendered into (null on the WebGPU backend). */
	readonly cubeRenderTarget: CubeRenderTarget | null = null;

	/** WebGL2 backend: the cube camera, set to each probe in turn (null on the WebGPU backend). */
	readonly cubeCamera: CubeCamera | null = null;

	/** WebGPU backend: the six face targets and cameras, set to each probe in turn (null on WebGL2). */
	readonly faces: WebGPUCubeFaces | null = null;

	/** The GPU projection. */
	readonly projector: WebGPUSHProjector;

	private readonly solidAngle: CubeSolidAngleMode;
	private readonly shadowMaps = new WebGPUShadowFreeze();
	private busy = false;

	/**
	 * @param renderer An initialised WebGPURenderer (`await renderer.init()`).
	 * @param settings As `ProbeCapturer`'s: resolution, near, far, type, solidAngle.
	 */
	constructor( renderer: WebGPURenderer, settings: ProbeCaptureSettings = {} ) {

		if ( ( renderer as { isWebGPURenderer?: boolean } | null )?.isWebGPURenderer !== true ) {

			throw new TypeError( `WebGPUProbeCapturer: renderer must be a three.js WebGPURenderer, got ${describeValue( renderer )}.` );

		}

		const { resolution, near, far, type, solidAngle } = checkCaptureSettings( 'WebGPUProbeCapturer', '', settings );
		this.renderer = renderer;
		this.resolution = resolution;
		this.solidAngle = solidAngle;
		this.projector = new WebGPUSHProjector( renderer );
		if ( this.projector.compute ) {

			this.faces = new WebGPUCubeFaces( resolution, near, far, type as TextureDataType );

		} else {

			this.cubeRenderTarget = new CubeRenderTarget( resolution, {
				type: type as TextureDataType, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false,
			} );
			this.cubeCamera = new CubeCamera( near, far, this.cubeRenderTarget );

		}

		watchDevice( renderer );

	}

	/**
	 * Captures the scene at each position and writes 27 SH floats per probe into `target` (as
	 * `ProbeCapturer.capture`). With `renderer.shadowMap.enabled`, every shadow-casting light's map
	 * is drawn once per call and reused for every face (its `shadow.autoUpdate` / `needsUpdate`
	 * restored afterwards).
	 * @throws {Error} when the device or context is lost during the capture, or a probe captures a
	 * value that is not finite or beyond ±1e30 (`target` then keeps what it had).
	 */
	async capture(
		scene: Scene, positions: ArrayLike<number>, target: Float32Array, options: ProbeCaptureOptions = {}, offset = 0,
	): Promise<Float32Array> {

		const where = 'WebGPUProbeCapturer.capture';
		assertScene( where, scene );
		const count = assertPoints( where, 'positions', positions, 1 );
		if ( ! ( target instanceof Float32Array ) ) throw new TypeError( `${where}: target must be a Float32Array, got ${describeValue( target )}.` );
		assertInteger( where, 'offset', offset, 0 );
		const { exclude } = checkCaptureCall( where, 'options.', options );
		options = { ...options, exclude };
		if ( target.length < offset + SH_FLOATS * count ) {

			throw new RangeError( `${where}: target must have room for ${SH_FLOATS * count} floats from offset ${offset}, got length ${target.length}.` );

		}

		if ( this.busy ) throw new Error( `${where}: a capture is already running on this capturer; await it first (or use a second capturer).` );
		const { renderer, cubeCamera, faces, projector, shadowMaps } = this;
		this.checkDevice( where );
		const cameras = faces ? faces.cameras : cubeCamera!.children;
		const savedLayers = cameras.map( ( camera ) => camera.layers.mask );
		if ( options.layers ) for ( const camera of cameras ) camera.layers.mask = options.layers.mask;
		const autoClear = renderer.autoClear;
		const batch = WebGPUSHProjector.batchCapacity( this.resolution );
		const result = new Float32Array( SH_FLOATS * count );
		let hidden: Object3D[] = [];
		let lastYield = captureClock();
		this.busy = true;

		try {

			shadowMaps.begin( scene, renderer.shadowMap.enabled );
			hidden = hideForCapture( scene, options );
			scene.updateMatrixWorld();
			faces?.prepare( scene );
			for ( let start = 0; start < count; start += batch ) {

				const size = Math.min( batch, count - start );
				projector.begin( 'cube', this.resolution, size, { solidAngle: this.solidAngle } );
				for ( let i = start; i < start + size; i ++ ) {

					this.checkDevice( where );
					this.renderFaces( scene, positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] );
					options.onProgress?.( i + 1, count );

					// A frame for the page now and then (its progress bar), with the hidden objects shown.
					if ( i + 1 < count && captureClock() - lastYield > 30 ) {

						renderer.autoClear = autoClear;
						showAfterCapture( hidden );
						shadowMaps.pause();
						await nextTask();
						shadowMaps.resume();
						hidden = hideForCapture( scene, options );
						faces?.prepare( scene ); // meshes added meanwhile
						lastYield = captureClock();

					}

				}

				this.checkDevice( where );
				await projector.finish( result, SH_FLOATS * start );

			}

		} catch ( error ) {

			// A read-back on a lost device fails (or the loss shows only now): the named error, with the cause.
			await nextTask();
			if ( isDeviceLost( renderer ) ) throw deviceLostError( where, renderer, error );
			throw error;

		} finally {

			shadowMaps.end();
			faces?.release();
			renderer.autoClear = autoClear;
			cameras.forEach( ( camera, i ) => { camera.layers.mask = savedLayers[ i ]; } );
			showAfterCapture( hidden );
			this.busy = false;

		}

		this.checkDevice( where );
		const bad = firstBeyond( result, SH_LIMIT );
		if ( bad >= 0 ) {

			throw new Error( `${where}: probe ${Math.floor( bad / SH_FLOATS )} captured ${result[ bad ]}, not a finite value within ±${SH_LIMIT.toPrecision( 3 )}; `
				+ 'check the scene for NaN, Infinity or huge emissive or light values.' );

		}

		target.set( result, offset );
		return target;

	}

	/** Renders the six faces at ( x, y, z ) and hands them to the projector's batch. */
	private renderFaces( scene: Scene, x: number, y: number, z: number ): void {

		const { renderer, faces, cubeCamera, projector } = this;
		if ( faces ) {

			faces.rig.position.set( x, y, z );
			faces.rig.updateMatrixWorld( true );
			faces.render( renderer, scene );
			projector.addFaces( faces.targets.map( ( target ) => target.texture ) );

		} else {

			cubeCamera!.position.set( x, y, z );
			cubeCamera!.updateMatrixWorld();
			renderer.autoClear = true; // every face must start cleared
			cubeCamera!.update( renderer, scene );
			projector.add( this.cubeRenderTarget!.texture );

		}

	}

	private checkDevice( where: string ): void {

		if ( isDeviceLost( this.renderer ) ) throw deviceLostError( where, this.renderer );

	}

	/** Frees the face targets (or cube render target) and the projection's buffers, textures and kernels. */
	dispose(): void {

		this.cubeRenderTarget?.dispose();
		this.faces?.dispose();
		this.projector.dispose();

	}

}
