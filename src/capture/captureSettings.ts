import { FloatType, HalfFloatType, type Layers, type Object3D, type Scene, type TextureDataType, type WebGLRenderer } from 'three';
import type { CubeSolidAngleMode } from '../sh/projectCubeMapToSH.js';
import { assertInteger, assertNumber, assertOptionalFunction, assertOptions, describeValue } from '../validate.js';

/*
 * The checks of capture settings and per-call capture options, shared by `ProbeCapturer` and
 * `LightProbeVolume.capture` (which checks every role's settings before it captures anything).
 */

/** Settings of a probe capture (see `ProbeCaptureSettings`), with the defaults filled in. */
export interface ResolvedCaptureSettings {

	resolution: number;
	near: number;
	far: number;
	type: TextureDataType;
	solidAngle: CubeSolidAngleMode;

}

/** The texel solid-angle formulas a capture may use. */
export const CAPTURE_SOLID_ANGLES: readonly CubeSolidAngleMode[] = [ 'exact', 'paper', 'paper-unnormalized' ];

/** The largest cube face edge a capture renders. */
export const MAX_CAPTURE_RESOLUTION = 256;

/**
 * Capture settings `{ resolution?, near?, far?, type?, solidAngle? }` checked, with defaults.
 * @param prefix Put before each member's name in messages, e.g. `'options.'`, `'options.roles.sky.'`.
 * @throws TypeError / RangeError starting with `where`.
 */
export function checkCaptureSettings( where: string, prefix: string, settings: unknown ): ResolvedCaptureSettings {

	assertOptions( where, prefix ? prefix.slice( 0, - 1 ) : 'settings', settings );
	const s = ( settings ?? {} ) as Record<string, unknown>;
	const { resolution = 32, near = 0.05, far = 1000, type = HalfFloatType, solidAngle = 'exact' } = s;
	assertInteger( where, `${prefix}resolution`, resolution, 1, MAX_CAPTURE_RESOLUTION );
	assertNumber( where, `${prefix}near`, near );
	assertNumber( where, `${prefix}far`, far );
	if ( ! ( near > 0 && far > near ) ) {

		throw new RangeError( `${where}: need 0 < ${prefix}near < ${prefix}far, got near ${near}, far ${far}.` );

	}

	if ( type !== HalfFloatType && type !== FloatType ) {

		throw new RangeError( `${where}: ${prefix}type must be HalfFloatType or FloatType (the capture holds linear HDR radiance), `
			+ `got ${describeValue( type )}.` );

	}

	if ( ! ( CAPTURE_SOLID_ANGLES as readonly unknown[] ).includes( solidAngle ) ) {

		throw new RangeError( `${where}: ${prefix}solidAngle is ${describeValue( solidAngle )}; expected ${CAPTURE_SOLID_ANGLES.map( ( m ) => `'${m}'` ).join( ', ' )}.` );

	}

	return { resolution, near, far, type, solidAngle: solidAngle as CubeSolidAngleMode };

}

/**
 * Per-call capture options `{ exclude?, filter?, layers?, onProgress? }` checked: `exclude` an
 * iterable of `Object3D`s (read once, returned as an array), `layers` a three.js `Layers`.
 * @param prefix As {@link checkCaptureSettings}.
 */
export function checkCaptureCall( where: string, prefix: string, options: unknown ): { exclude: Object3D[] | undefined } {

	assertOptions( where, prefix ? prefix.slice( 0, - 1 ) : 'options', options );
	const o = ( options ?? {} ) as Record<string, unknown>;
	assertOptionalFunction( where, `${prefix}filter`, o.filter );
	assertOptionalFunction( where, `${prefix}onProgress`, o.onProgress );
	checkLayers( where, `${prefix}layers`, o.layers );
	let exclude: Object3D[] | undefined;
	if ( o.exclude !== undefined ) {

		const iterable = o.exclude as Iterable<unknown> | null;
		if ( iterable === null || typeof iterable !== 'object' || typeof iterable[ Symbol.iterator ] !== 'function' ) {

			throw new TypeError( `${where}: ${prefix}exclude must be an iterable (e.g. an array) of three.js Object3Ds, got ${describeValue( o.exclude )}.` );

		}

		exclude = [ ...iterable ] as Object3D[];
		exclude.forEach( ( object, i ) => {

			if ( ( object as { isObject3D?: boolean } | null )?.isObject3D !== true ) {

				throw new TypeError( `${where}: ${prefix}exclude[${i}] is ${describeValue( object )}, not a three.js Object3D.` );

			}

		} );

	}

	return { exclude };

}

/** An optional three.js `Layers` (an object with an integer `mask`). */
export function checkLayers( where: string, name: string, layers: unknown ): asserts layers is Layers | undefined {

	if ( layers === undefined ) return;
	const mask = ( layers as { mask?: unknown } | null )?.mask;
	if ( typeof mask !== 'number' || ! Number.isInteger( mask ) ) {

		throw new TypeError( `${where}: ${name} must be a three.js Layers, got ${describeValue( layers )}.` );

	}

}

/**
 * A `WebGPURenderer` (`three/webgpu`), as the capture code sees it: a structural type, so the
 * WebGL core never loads three's node system. Its capture is installed by
 * `three-capture-lighting/webgpu` (src/capture/captureBackends.ts).
 */
export interface WebGPURendererLike {

	readonly isWebGPURenderer: true;

}

/** A renderer that captures probes: a `WebGLRenderer` (WebGL2), or a `WebGPURenderer` (either backend). */
export type CaptureRenderer = WebGLRenderer | WebGPURendererLike;

/** Whether `renderer` is a three.js `WebGPURenderer` (its WebGPU backend or its WebGL2 fallback). */
export function isWebGPURenderer( renderer: unknown ): renderer is WebGPURendererLike {

	return ( renderer as { isWebGPURenderer?: unknown } | null )?.isWebGPURenderer === true;

}

/**
 * A renderer to capture with: a three.js `WebGLRenderer` or `WebGPURenderer`. (A WebGPURenderer
 * also needs `three-capture-lighting/webgpu` imported; `createProbeCapturer` says so.)
 */
export function assertRenderer( where: string, renderer: unknown ): asserts renderer is CaptureRenderer {

	const candidate = renderer as { isWebGLRenderer?: boolean; getContext?: unknown } | null;
	if ( isWebGPURenderer( renderer ) || ( candidate?.isWebGLRenderer === true && typeof candidate.getContext === 'function' ) ) return;
	throw new TypeError( `${where}: renderer must be a three.js WebGLRenderer or WebGPURenderer, got ${describeValue( renderer )}.` );

}

/** A three.js `WebGLRenderer` (its context is read during the capture): what `ProbeCapturer` and `SHProjector` draw with. */
export function assertWebGLRenderer( where: string, renderer: unknown ): asserts renderer is WebGLRenderer {

	const candidate = renderer as { isWebGLRenderer?: boolean; getContext?: unknown } | null;
	if ( isWebGPURenderer( renderer ) ) {

		throw new TypeError( `${where}: renderer is a WebGPURenderer; this class draws with a WebGLRenderer only. `
			+ 'Capture through LightProbeVolume.capture or createProbeCapturer (with the library imported from \'three-capture-lighting/webgpu\').' );

	}

	if ( candidate?.isWebGLRenderer !== true || typeof candidate.getContext !== 'function' ) {

		throw new TypeError( `${where}: renderer must be a three.js WebGLRenderer, got ${describeValue( renderer )}.` );

	}

}

/** A three.js scene (any `Object3D`) to capture. */
export function assertScene( where: string, scene: unknown ): asserts scene is Scene {

	if ( ( scene as { isObject3D?: boolean } | null )?.isObject3D !== true ) {

		throw new TypeError( `${where}: scene must be a three.js Scene (or Object3D), got ${describeValue( scene )}.` );

	}

}
