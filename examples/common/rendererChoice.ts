import * as THREE from 'three';
import type GUI from 'lil-gui';
import type { WebGPURenderer } from 'three/webgpu';

/**
 * `?renderer=`: `webgl` (default) — three's WebGLRenderer; `webgpu` — `new WebGPURenderer()`;
 * `webgl2` — `new WebGPURenderer( { forceWebGL: true } )`, WebGPURenderer on its WebGL2 backend.
 */
export type RendererName = 'webgl' | 'webgpu' | 'webgl2';

/** The panel's renderer list: its labels and the `?renderer=` each reloads with. */
export const RENDERER_OPTIONS: Record<string, RendererName> = {
	'WebGLRenderer': 'webgl',
	'WebGPURenderer (WebGPU)': 'webgpu',
	'WebGPURenderer (WebGL2)': 'webgl2',
};

/** A page's renderer: three's WebGLRenderer, or a WebGPURenderer on either of its backends. */
export type AnyRenderer = THREE.WebGLRenderer | WebGPURenderer;

/** What {@link chooseRenderer} found: which renderer to make, and how. */
export interface RendererChoice {

	/** What `?renderer=` asked for. */
	readonly requested: RendererName;
	/** What runs: `webgl2` when `webgpu` was asked for where the browser has no WebGPU. */
	readonly name: RendererName;
	/** `three/webgpu`, loaded for `webgpu` and `webgl2` (null for `webgl`). */
	readonly webgpu: typeof import( 'three/webgpu' ) | null;
	/** Why what runs is not what was asked for ('' when it is). */
	readonly notice: string;

}

/** Reads `?renderer=` (anything else than `webgpu` or `webgl2` is `webgl`). */
export function readRendererName( search: string ): RendererName {

	const name = new URLSearchParams( search ).get( 'renderer' );
	return name === 'webgpu' || name === 'webgl2' ? name : 'webgl';

}

/**
 * Reads `?renderer=` and loads what it needs: for a WebGPURenderer, `three/webgpu` and the library
 * from `three-capture-lighting/webgpu` (which installs its node-material shading, WebGPU capture and
 * helper materials, as a WebGPURenderer project imports it) — both loaded only then, so a WebGL page
 * never loads three's node system. WebGPU asked for where `navigator.gpu` is missing or gives no
 * adapter runs WebGPURenderer's WebGL2 backend instead, and `notice` says so.
 */
export async function chooseRenderer( search: string = location.search ): Promise<RendererChoice> {

	const requested = readRendererName( search );
	if ( requested === 'webgl' ) return { requested, name: requested, webgpu: null, notice: '' };
	const [ webgpu ] = await Promise.all( [ import( 'three/webgpu' ), import( 'three-capture-lighting/webgpu' ) ] );
	let name = requested, notice = '';
	if ( requested === 'webgpu' ) {

		const gpu = ( navigator as Navigator & { gpu?: { requestAdapter(): Promise<unknown> } } ).gpu;
		const adapter = gpu ? await gpu.requestAdapter().catch( () => null ) : null;
		if ( ! adapter ) {

			name = 'webgl2';
			notice = `WebGPU was asked for (?renderer=webgpu) but this browser has none (${gpu ? 'navigator.gpu gives no adapter' : 'navigator.gpu is missing'}): `
				+ 'running WebGPURenderer on its WebGL2 backend instead. Chromium enables WebGPU on Linux with --enable-unsafe-webgpu.';

		}

	}

	return { requested, name, webgpu, notice };

}

/**
 * The renderer `choice` names, with three's usual parameters; a WebGPURenderer still needs
 * `await renderer.init()` before it renders (see {@link initRenderer}).
 */
export function createRenderer(
	choice: RendererChoice, parameters: { antialias?: boolean; preserveDrawingBuffer?: boolean },
): AnyRenderer {

	if ( choice.webgpu === null ) return new THREE.WebGLRenderer( parameters );
	return new choice.webgpu.WebGPURenderer( { antialias: parameters.antialias, forceWebGL: choice.name === 'webgl2' } );

}

/** `await renderer.init()` for a WebGPURenderer (nothing for a WebGLRenderer). */
export async function initRenderer( renderer: AnyRenderer ): Promise<void> {

	if ( isWebGPURenderer( renderer ) ) await renderer.init();

}

/** Whether `renderer` is a WebGPURenderer (either backend). */
export function isWebGPURenderer( renderer: AnyRenderer ): renderer is WebGPURenderer {

	return ( renderer as { isWebGPURenderer?: boolean } ).isWebGPURenderer === true;

}

/** Which backend runs, for the page: 'WebGLRenderer', 'WebGPU' or 'WebGPURenderer (WebGL2 backend)'. */
export function backendLabel( renderer: AnyRenderer ): string {

	if ( ! isWebGPURenderer( renderer ) ) return 'WebGLRenderer';
	const backend = renderer.backend as { isWebGPUBackend?: boolean } | undefined;
	return backend?.isWebGPUBackend === true ? 'WebGPU' : 'WebGPURenderer (WebGL2 backend)';

}

/**
 * Calls `onLost` with a message when the renderer's context (WebGL) or device (WebGPU) is lost, and
 * with '' when a WebGL context is restored.
 */
export function watchRendererLoss( renderer: AnyRenderer, onLost: ( message: string ) => void ): void {

	if ( isWebGPURenderer( renderer ) ) {

		renderer.onDeviceLost = ( info: { message?: string } ) => onLost( `The WebGPU device was lost (${info?.message ?? 'no reason given'}); reload the page.` );
		return;

	}

	renderer.domElement.addEventListener( 'webglcontextlost', () => {

		onLost( 'The WebGL context was lost; the probe SH are kept. Waiting for the browser to restore it…' );

	} );
	renderer.domElement.addEventListener( 'webglcontextrestored', () => onLost( '' ) );

}

/** The panel's "renderer" list: choosing one reloads the page with `?renderer=` set to it. */
export function addRendererSwitch( gui: GUI, choice: RendererChoice ): void {

	gui.add( { renderer: choice.requested }, 'renderer', RENDERER_OPTIONS ).onChange( ( name: RendererName ) => {

		const url = new URL( location.href );
		url.searchParams.set( 'renderer', name );
		location.assign( url.toString() );

	} );

}

/**
 * For a page without a panel: ' — running: <label> · switch to: …' with a link per other renderer,
 * each reloading the page with `?renderer=` set to it.
 */
export function rendererLinks( label: string, choice: RendererChoice ): HTMLSpanElement {

	const span = document.createElement( 'span' );
	span.id = 'renderer';
	span.append( ` — running: ${label} · switch to: ` );
	const others = Object.entries( RENDERER_OPTIONS ).filter( ( [ , name ] ) => name !== choice.requested );
	others.forEach( ( [ text, name ], i ) => {

		const url = new URL( location.href );
		url.searchParams.set( 'renderer', name );
		const link = Object.assign( document.createElement( 'a' ), { href: url.toString(), textContent: text } );
		span.append( ...( i > 0 ? [ ', ' ] : [] ), link );

	} );
	return span;

}
