import type { Scene, Texture } from 'three';
import { ProbeCapturer, type ProbeCaptureOptions, type ProbeCaptureSettings } from './ProbeCapturer.js';
import { assertRenderer, isWebGPURenderer, type CaptureRenderer, type WebGPURendererLike } from './captureSettings.js';

/*
 * The one place the WebGL capture code reaches a WebGPURenderer's: a hook that
 * `three-capture-lighting/webgpu` installs (src/webgpu/installCapture.ts), so the main entry never
 * loads three/webgpu or three/tsl, and a factory that picks the capturer for a renderer.
 */

/** What captures probes for `LightProbeVolume`: `ProbeCapturer`'s shape, for either renderer. */
export interface ProbeCapturerLike {

	/** Cube face edge in texels. */
	readonly resolution: number;

	/**
	 * Captures the scene at each position (x, y, z per probe) and writes 27 SH floats per probe
	 * into `target` from `offset`, all at once when every probe is done (see `ProbeCapturer.capture`).
	 */
	capture(
		scene: Scene, positions: ArrayLike<number>, target: Float32Array, options?: ProbeCaptureOptions, offset?: number,
	): Promise<Float32Array>;

	/** Frees the capturer's GPU resources. */
	dispose(): void;

}

/** The WebGPURenderer capture that `three-capture-lighting/webgpu` installs. */
export interface WebGPUCapture {

	/** A capturer drawing with `renderer` (already initialised: `prepareRenderer` ran). */
	createCapturer( renderer: WebGPURendererLike, settings: ProbeCaptureSettings ): ProbeCapturerLike;

	/** `projectEquirectToSHGPU` on a WebGPURenderer (the renderer initialised). */
	projectEquirect( renderer: WebGPURendererLike, texture: Texture, target: Float32Array ): Promise<Float32Array>;

}

let installed: WebGPUCapture | null = null;

/** Installs the WebGPURenderer capture (called once by `three-capture-lighting/webgpu`; a second call replaces it). */
export function installWebGPUCapture( capture: WebGPUCapture ): void {

	installed = capture;

}

/** The installed WebGPURenderer capture, or null when `three-capture-lighting/webgpu` was not imported. */
export function webGPUCapture(): WebGPUCapture | null {

	return installed;

}

/**
 * Throws unless `renderer` can capture: a `WebGLRenderer`, or a `WebGPURenderer` with the WebGPU
 * capture installed (else the error says to import the library from 'three-capture-lighting/webgpu').
 * @returns The installed WebGPU capture for a WebGPURenderer, null for a WebGLRenderer.
 */
export function assertCaptureBackend( where: string, renderer: unknown ): WebGPUCapture | null {

	assertRenderer( where, renderer );
	if ( ! isWebGPURenderer( renderer ) ) return null;
	if ( installed === null ) {

		throw new Error( `${where}: renderer is a WebGPURenderer, and WebGPU capture is not installed; import the library from `
			+ '\'three-capture-lighting/webgpu\' (as three from \'three/webgpu\') to capture with a WebGPURenderer.' );

	}

	return installed;

}

/**
 * Awaits `renderer.init()` when the renderer has one and is not initialised yet (a WebGPURenderer
 * must be before it draws); does nothing for a WebGLRenderer or an initialised renderer.
 */
export async function prepareRenderer( renderer: CaptureRenderer ): Promise<void> {

	const candidate = renderer as { init?: () => Promise<unknown>; initialized?: boolean };
	if ( typeof candidate.init === 'function' && candidate.initialized !== true ) await candidate.init();

}

/**
 * The capturer for `renderer`: a `ProbeCapturer` for a `WebGLRenderer`, the installed WebGPU
 * capturer for a `WebGPURenderer` (its WebGPU backend or its WebGL2 fallback, `forceWebGL: true`).
 * A WebGPURenderer must be initialised first (`await prepareRenderer( renderer )`).
 * @throws {TypeError} for anything else; {Error} for a WebGPURenderer without `three-capture-lighting/webgpu` imported.
 */
export function createProbeCapturer( renderer: CaptureRenderer, settings: ProbeCaptureSettings = {} ): ProbeCapturerLike {

	const capture = assertCaptureBackend( 'createProbeCapturer', renderer );
	if ( capture !== null ) return capture.createCapturer( renderer as WebGPURendererLike, settings );
	return new ProbeCapturer( renderer as Exclude<CaptureRenderer, WebGPURendererLike>, settings );

}

