import {
	CubeCamera, FloatType, NearestFilter, WebGLCubeRenderTarget, WebGLRenderTarget,
	type Camera, type Layers, type Material, type Object3D, type Scene, type TextureDataType, type WebGLRenderer,
} from 'three';
import { SHProjector } from './SHProjector.js';
import { ShadowMapFreeze } from './ShadowMapFreeze.js';
import { captureClock, hideForCapture, nextTask, showAfterCapture } from './captureHiding.js';
import { assertScene, assertWebGLRenderer, checkCaptureCall, checkCaptureSettings } from './captureSettings.js';
import type { CubeSolidAngleMode } from '../sh/projectCubeMapToSH.js';
import { SH_FLOATS, SH_LIMIT, assertInteger, assertPoints, describeValue, firstBeyond } from '../validate.js';

/** Settings of {@link ProbeCapturer}. */
export interface ProbeCaptureSettings {

	/** Cube face edge in texels, 1..256 (paper: 8..256, experiments 128). Default 32. */
	resolution?: number;

	/** Near plane of the cube camera. Default 0.05. */
	near?: number;

	/** Far plane of the cube camera. Default 1000. */
	far?: number;

	/** Cube render target type: `HalfFloatType` (default) or `FloatType`. */
	type?: TextureDataType;

	/**
	 * Texel solid-angle formula of the projection: `'exact'` (default), `'paper'` (the paper's
	 * formula rescaled to sum to 4π) or `'paper-unnormalized'` (as printed, +1.5 % on L00).
	 */
	solidAngle?: CubeSolidAngleMode;

}

/** Per-call options of {@link ProbeCapturer.capture}. */
export interface ProbeCaptureOptions {

	/** Objects hidden while capturing (dynamic objects must not light themselves). */
	exclude?: Iterable<Object3D>;

	/** Objects for which this returns false are hidden while capturing. */
	filter?: ( object: Object3D ) => boolean;

	/** When given, the cube camera sees only these layers. */
	layers?: Layers;

	/** Called after each probe with the number of probes done and the total. */
	onProgress?: ( done: number, total: number ) => void;

}

// GPU memory the face atlas of a group may take (bytes): small faces get groups of many probes
// rendered into one atlas and projected in one draw, large ones, whose projection dwarfs the cost
// of a draw, one probe per group.
const GROUP_BYTES = 1 << 20;

// Most atlas rows: WebGL2 guarantees textures of 2048 texels per side (and 6 × 256 fits a row).
const ATLAS_MAX_SIZE = 2048;

/**
 * Renders cube maps of a scene at probe positions and projects them to SH9 on the GPU. The six
 * faces of a group of probes are rendered side by side into one 2D atlas (one framebuffer, where
 * a cube render target has one per face), each group projected in one draw, and projected in
 * batches, each ending in one small read-back (27 floats per probe).
 *
 * ```js
 * const capturer = new ProbeCapturer( renderer, { resolution: 64 } );
 * const sh = await capturer.capture( scene, positions, new Float32Array( 27 * count ) );
 * capturer.dispose();
 * ```
 */
export class ProbeCapturer {

	/** The renderer that draws the captures. */
	readonly renderer: WebGLRenderer;

	/** Cube face edge in texels. */
	readonly resolution: number;

	/**
	 * A cube render target of the capture's size and type, the one `cubeCamera` renders into: for
	 * a probe rendered by hand (`cubeCamera.update`, then `projector.add`). `capture()` renders
	 * each face with `cubeCamera`'s cameras into a 2D face atlas instead, texel for texel the same
	 * image, except in scenes whose pixels depend on their screen position (shadow maps, whose PCF
	 * noise uses gl_FragCoord, or dithered materials): those it renders here, one probe per draw.
	 */
	readonly cubeRenderTarget: WebGLCubeRenderTarget;

	/** The cube camera; its position is set to each probe in turn, and its six cameras render the faces. */
	readonly cubeCamera: CubeCamera;

	/** The GPU projection. */
	readonly projector: SHProjector;

	private readonly solidAngle: CubeSolidAngleMode;
	private readonly shadowMaps: ShadowMapFreeze;
	// A group's faces: probe k of the group in row block k, face f in column block f (made when first needed).
	private atlas: WebGLRenderTarget | null = null;
	private readonly groupSize: number;
	private readonly type: TextureDataType;
	private busy = false;

	/**
	 * @param renderer A WebGL2 renderer.
	 * @param settings See {@link ProbeCaptureSettings}.
	 */
	constructor( renderer: WebGLRenderer, settings: ProbeCaptureSettings = {} ) {

		assertWebGLRenderer( 'ProbeCapturer', renderer );
		const { resolution, near, far, type, solidAngle } = checkCaptureSettings( 'ProbeCapturer', '', settings );

		this.renderer = renderer;
		this.resolution = resolution;
		this.solidAngle = solidAngle;
		this.type = type;
		this.cubeRenderTarget = new WebGLCubeRenderTarget( resolution, {
			type, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false,
		} );
		const bytes = 6 * resolution * resolution * ( type === FloatType ? 16 : 8 );
		this.groupSize = Math.max( 1, Math.min( Math.floor( ATLAS_MAX_SIZE / resolution ), Math.floor( GROUP_BYTES / bytes ) ) );
		this.cubeCamera = new CubeCamera( near, far, this.cubeRenderTarget );
		this.projector = new SHProjector( renderer );
		this.shadowMaps = new ShadowMapFreeze( renderer );

	}

	/**
	 * Captures the scene at each position and writes 27 SH floats per probe into `target`. With
	 * `renderer.shadowMap.enabled`, the shadow maps are drawn once per call (at its first cube face)
	 * and reused for every face, and `shadowMap.autoUpdate` / `needsUpdate` are restored afterwards.
	 * @param positions Flat x, y, z per probe.
	 * @param target Receives 27 floats per probe, from `offset`.
	 * @returns `target`, once every probe is done.
	 * @throws {Error} when the WebGL context is lost during the capture, or a probe captures a value
	 * that is not finite or beyond ±1e30 (`target` then keeps what it had).
	 */
	async capture(
		scene: Scene, positions: ArrayLike<number>, target: Float32Array, options: ProbeCaptureOptions = {}, offset = 0,
	): Promise<Float32Array> {

		const where = 'ProbeCapturer.capture';
		assertScene( where, scene );
		const count = assertPoints( where, 'positions', positions, 1 );
		if ( ! ( target instanceof Float32Array ) ) throw new TypeError( `${where}: target must be a Float32Array, got ${describeValue( target )}.` );
		assertInteger( where, 'offset', offset, 0 );
		const { exclude } = checkCaptureCall( where, 'options.', options );
		options = { ...options, exclude };
		if ( target.length < offset + SH_FLOATS * count ) {

			throw new RangeError( `ProbeCapturer.capture: target must have room for ${SH_FLOATS * count} floats from offset ${offset}, got length ${target.length}.` );

		}

		// One render target and one projection batch serve every call: overlapping captures would
		// interleave their probes.
		if ( this.busy ) throw new Error( 'ProbeCapturer.capture: a capture is already running on this capturer; await it first (or use a second ProbeCapturer).' );
		const { renderer, cubeCamera, projector, shadowMaps } = this;
		const savedLayers = cubeCamera.children.map( ( camera ) => camera.layers.mask );
		if ( options.layers ) for ( const camera of cubeCamera.children ) camera.layers.mask = options.layers.mask;
		const autoClear = renderer.autoClear, xrEnabled = renderer.xr.enabled;
		const savedTarget = renderer.getRenderTarget();
		const savedFace = renderer.getActiveCubeFace(), savedLevel = renderer.getActiveMipmapLevel();
		// Results go to `target` only once complete, so a context loss mid-way leaves the caller's
		// SH as they were.
		const batch = SHProjector.batchCapacity( this.resolution );
		const result = new Float32Array( SH_FLOATS * count );
		let hidden: Object3D[] = [];
		let lastYield = captureClock();
		this.busy = true;

		try {

			shadowMaps.begin();
			hidden = hideForCapture( scene, options );

			scene.updateMatrixWorld();
			// three's PCF shadow filter and dithering vary with gl_FragCoord, which differs in the
			// atlas: such scenes keep the cube render target, one probe per draw, for the same SH.
			// Faces too large for two probes to share an atlas keep it too: the atlas saves draws
			// and read-backs only when it groups probes, and large faces project faster from the
			// cube target's 2D copies (SHProjector.add).
			const useAtlas = this.groupSize > 1 && ! dependsOnPixelPosition( renderer, scene );
			const group = useAtlas ? Math.min( this.groupSize, count ) : 1;
			const atlas = useAtlas ? this.ensureAtlas( group ) : null;

			for ( let start = 0; start < count; start += batch ) {

				const size = Math.min( batch, count - start );
				projector.begin( 'cube', this.resolution, size, { solidAngle: this.solidAngle } );
				for ( let i = start; i < start + size; i ++ ) {

					this.checkContext();
					// Probe i goes to row k of the atlas; the group is projected in one draw once full.
					const k = ( i - start ) % group;
					cubeCamera.position.set( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] );
					cubeCamera.updateMatrixWorld();
					if ( atlas ) {

						this.renderFaces( scene, atlas, k );
						if ( k === group - 1 || i === start + size - 1 ) projector.addAtlas( atlas.texture, k + 1 );

					} else {

						renderer.autoClear = true; // every face must start cleared
						cubeCamera.update( renderer, scene );
						// The target, not its texture: large faces are then read from 2D copies (SHProjector.add).
						projector.add( this.cubeRenderTarget );

					}

					options.onProgress?.( i + 1, count );

					// Give a page a frame now and then to paint its progress bar, with the hidden
					// objects shown again and its render target and settings back, so the frame it
					// draws looks normal.
					if ( i + 1 < count && captureClock() - lastYield > 30 ) {

						renderer.setRenderTarget( savedTarget, savedFace, savedLevel );
						renderer.autoClear = autoClear;
						renderer.xr.enabled = xrEnabled;
						showAfterCapture( hidden );
						shadowMaps.pause();
						await nextTask();
						shadowMaps.resume();
						hidden = hideForCapture( scene, options );
						lastYield = captureClock();

					}

				}

				this.checkContext();
				projector.finish( result, SH_FLOATS * start );

			}

		} finally {

			shadowMaps.end();
			renderer.setRenderTarget( savedTarget, savedFace, savedLevel );
			renderer.autoClear = autoClear;
			renderer.xr.enabled = xrEnabled;
			cubeCamera.children.forEach( ( camera, i ) => { camera.layers.mask = savedLayers[ i ]; } );
			showAfterCapture( hidden );
			this.busy = false;

		}

		this.checkContext();
		const bad = firstBeyond( result, SH_LIMIT );
		if ( bad >= 0 ) {

			throw new Error( `${where}: probe ${Math.floor( bad / SH_FLOATS )} captured ${result[ bad ]}, not a finite value within ±${SH_LIMIT.toPrecision( 3 )}; `
				+ 'check the scene for NaN, Infinity or huge emissive or light values.' );

		}

		target.set( result, offset );
		return target;

	}

	private checkContext(): void {

		if ( this.renderer.getContext().isContextLost() ) {

			throw new Error( 'ProbeCapturer.capture: the WebGL context was lost; the SH already held are kept. Capture again after "webglcontextrestored".' );

		}

	}

	/**
	 * Renders the six faces at `cubeCamera`'s position into row block `row` of the atlas, each
	 * face's camera into its own viewport with a scissor around it, so three's clear (and its
	 * background) touch only that face: the same image as `cubeCamera.update` renders into a cube
	 * render target's face, without a framebuffer switch per face.
	 */
	private renderFaces( scene: Scene, atlas: WebGLRenderTarget, row: number ): void {

		const { renderer, cubeCamera, resolution } = this;
		if ( cubeCamera.coordinateSystem !== renderer.coordinateSystem ) {

			cubeCamera.coordinateSystem = renderer.coordinateSystem;
			cubeCamera.updateCoordinateSystem();

		}

		renderer.autoClear = true; // every face must start cleared
		renderer.xr.enabled = false;
		for ( let face = 0; face < 6; face ++ ) {

			atlas.viewport.set( face * resolution, row * resolution, resolution, resolution );
			atlas.scissor.copy( atlas.viewport );
			// setRenderTarget takes the target's viewport and scissor.
			renderer.setRenderTarget( atlas );
			renderer.render( scene, cubeCamera.children[ face ] as Camera );

		}

	}

	/** The face atlas, with room for `rows` probes (made or remade larger when needed). */
	private ensureAtlas( rows: number ): WebGLRenderTarget {

		const size = this.resolution;
		if ( this.atlas && this.atlas.height >= rows * size ) return this.atlas;
		this.atlas?.dispose();
		this.atlas = new WebGLRenderTarget( 6 * size, rows * size, {
			type: this.type, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false, depthBuffer: true,
		} );
		this.atlas.scissorTest = true;
		return this.atlas;

	}

	/** Frees the cube render target, the face atlas and the projection's targets and materials. */
	dispose(): void {

		this.cubeRenderTarget.dispose();
		this.atlas?.dispose();
		this.atlas = null;
		this.projector.dispose();

	}

}

/** Whether the capture's pixels depend on where a face lies on the target: shadow maps (PCF noise) or a dithered material. */
function dependsOnPixelPosition( renderer: WebGLRenderer, scene: Scene ): boolean {

	if ( renderer.shadowMap.enabled ) return true;
	let dithered = false;
	scene.traverseVisible( ( object ) => {

		const material = ( object as { material?: Material | Material[] } ).material;
		if ( material ) for ( const m of Array.isArray( material ) ? material : [ material ] ) if ( m.dithering ) dithered = true;

	} );
	return dithered;

}
