/**
 * Browser side of the "shadows" part of bench/capture.bench.ts: probe captures of scenes lit by a
 * shadow-casting light, with and without its shadows, as functions on `window.captureShadowsBench`
 * that puppeteer calls; each returns its raw time (ms, `performance.now()`) and the SH captured.
 *
 * Scenes: the Basic room of the demo (scenes/basic.ts; its lamp casting shadows, the walls casting
 * and receiving them) with its 4 × 4 × 4 grid of probes, and Sponza (scenes/sponza.ts: the sun's
 * 2048² shadow map, the sky dome and the ambient stand-in of the demo page) with its 85 probes.
 * Every capture ends in the read-back of the SH, so the times include the GPU work. The diagnostics
 * (`captureLoop`, `shadowMapRender`, `setMapSize`, `countGL`, `sceneStats`) serve the floor rows and
 * bench/captureShadowsDecompose.ts.
 */

import * as THREE from 'three';
import { GridInterpolator } from 'three-capture-lighting/math';
import { ProbeCapturer, SHProjector } from '../../src/capture.js';
import { basicGrid, createBasicRoom } from '../../scenes/basic.js';
import { buildSponza } from '../../scenes/sponza.js';
import sponzaLayout from '../../scenes/sponza.json';

const renderer = new THREE.WebGLRenderer( { antialias: false, powerPreference: 'high-performance' } );
renderer.setPixelRatio( 1 );
renderer.setSize( 1280, 720 );
document.body.appendChild( renderer.domElement );
const gl = renderer.getContext() as WebGL2RenderingContext;

/** A scene ready to capture: its probes and the lights whose shadows are switched. */
interface ShadowScene {

	scene: THREE.Scene;
	positions: Float64Array;
	casters: THREE.Light[];
	triangles: number;

}

// Counts the shadow pass's draws: three draws shadow casters with renderBufferDirect, no scene, and
// its depth (directional) or distance (point) material. Shows that a capture draws the maps once.
let shadowDraws = 0;
const renderBufferDirect = renderer.renderBufferDirect;
renderer.renderBufferDirect = function ( camera, scene, geometry, material, object, group ) {

	const depth = material as THREE.Material & { isMeshDepthMaterial?: boolean, isMeshDistanceMaterial?: boolean };
	if ( scene === null && ( depth.isMeshDepthMaterial || depth.isMeshDistanceMaterial ) ) shadowDraws ++;
	renderBufferDirect.call( this, camera, scene, geometry, material, object, group );

};

const scenes = new Map<string, ShadowScene>();
const capturers = new Map<number, ProbeCapturer>();

function capturerFor( resolution: number ): ProbeCapturer {

	let capturer = capturers.get( resolution );
	if ( ! capturer ) {

		capturer = new ProbeCapturer( renderer, { resolution } );
		capturers.set( resolution, capturer );

	}

	return capturer;

}

function describeScene( name: string, scene: THREE.Scene, positions: Float64Array ): ShadowScene {

	const casters: THREE.Light[] = [];
	let triangles = 0;
	scene.traverse( ( object ) => {

		if ( ( object as THREE.Light ).isLight && object.castShadow ) casters.push( object as THREE.Light );
		const mesh = object as THREE.Mesh;
		if ( mesh.isMesh ) triangles += ( mesh.geometry.index ? mesh.geometry.index.count : mesh.geometry.getAttribute( 'position' ).count ) / 3;

	} );
	const entry = { scene, positions, casters, triangles };
	scenes.set( name, entry );
	return entry;

}

/** The demo's Basic room, its lamp casting shadows (512² cube map, three's default size). */
function loadBasic(): { probes: number, shadowLights: number, triangles: number } {

	const scene = new THREE.Scene();
	const { room, lamp } = createBasicRoom();
	lamp.castShadow = true;
	room.traverse( ( object ) => {

		// The walls cast and receive; the bulb around the lamp must not cast (it would shut the light in).
		if ( ( object as THREE.Mesh ).isMesh && object.name === 'room' ) object.castShadow = object.receiveShadow = true;

	} );
	scene.add( room );
	const positions = new Float64Array( new GridInterpolator( basicGrid.min, basicGrid.max, basicGrid.counts ).positions );
	const entry = describeScene( 'basic', scene, positions );
	return { probes: positions.length / 3, shadowLights: entry.casters.length, triangles: entry.triangles };

}

/** The demo's Sponza (assets at `assets`, e.g. '/assets/'), or `{ error }` when its files are missing. */
async function loadSponza( assets: string ): Promise<{ probes: number, shadowLights: number, triangles: number } | { error: string }> {

	const scene = new THREE.Scene();
	try {

		await buildSponza( { scene, renderer, assets, overlay: { progress() {} } } );

	} catch ( error ) {

		return { error: ( error as Error ).message };

	}

	const positions = new Float64Array( sponzaLayout.positions );
	const entry = describeScene( 'sponza', scene, positions );
	return { probes: positions.length / 3, shadowLights: entry.casters.length, triangles: entry.triangles };

}

/** Switches the scene's shadows: `renderer.shadowMap.enabled` and `castShadow` of its lights. */
function setShadows( entry: ShadowScene, shadows: boolean ): void {

	renderer.shadowMap.enabled = shadows;
	renderer.shadowMap.autoUpdate = true; // three's default: what a page that does nothing special has
	for ( const light of entry.casters ) light.castShadow = shadows;

}

function sceneNamed( name: string ): ShadowScene {

	const entry = scenes.get( name );
	if ( ! entry ) throw new Error( `captureShadowsBench: scene ${name} is not loaded` );
	return entry;

}

/** `ProbeCapturer.capture` of the first `probes` probes (all by default), shadows on or off. */
async function captureOnce(
	name: string, resolution: number, shadows: boolean, probes = - 1,
): Promise<{ ms: number, sh: number[], shadowDraws: number }> {

	const entry = sceneNamed( name );
	const positions = probes < 0 ? entry.positions : entry.positions.subarray( 0, 3 * probes );
	setShadows( entry, shadows );
	const capturer = capturerFor( resolution );
	const sh = new Float32Array( 9 * positions.length );
	const draws = shadowDraws;
	const start = performance.now();
	await capturer.capture( entry.scene, positions, sh );
	return { ms: performance.now() - start, sh: Array.from( sh ), shadowDraws: shadowDraws - draws };

}

/**
 * Diagnostic: the capture as it was before ProbeCapturer froze the shadow maps — CubeCamera.update
 * per probe with three's default `autoUpdate = true`, so every face draws every shadow map again —
 * then the same GPU projection and read-back.
 */
function capturePerFace( name: string, resolution: number, probes = - 1 ): { ms: number, sh: number[], shadowDraws: number } {

	const entry = sceneNamed( name );
	const positions = probes < 0 ? entry.positions : entry.positions.subarray( 0, 3 * probes );
	setShadows( entry, true );
	const capturer = capturerFor( resolution );
	const draws = shadowDraws;
	const start = performance.now();
	entry.scene.updateMatrixWorld();
	const sh = captureWithCubeCamera( entry, positions, resolution, capturer );
	return { ms: performance.now() - start, sh: Array.from( sh ), shadowDraws: shadowDraws - draws };

}

/**
 * CubeCamera.update at each probe, then the GPU projection and read-back in batches: the capture
 * loop of the diagnostics, with whatever shadow-map settings the caller left on the renderer.
 */
function captureWithCubeCamera(
	entry: ShadowScene, positions: Float32Array | Float64Array, resolution: number, capturer: ProbeCapturer,
): Float32Array {

	const { cubeCamera, cubeRenderTarget, projector } = capturer;
	const count = positions.length / 3;
	const sh = new Float32Array( 27 * count );
	const batch = SHProjector.batchCapacity( resolution );
	for ( let first = 0; first < count; first += batch ) {

		const size = Math.min( batch, count - first );
		projector.begin( 'cube', resolution, size );
		for ( let i = first; i < first + size; i ++ ) {

			cubeCamera.position.fromArray( positions, 3 * i );
			cubeCamera.updateMatrixWorld();
			renderer.autoClear = true;
			cubeCamera.update( renderer, entry.scene );
			projector.add( cubeRenderTarget.texture );

		}

		projector.finish( sh, 27 * first );

	}

	return sh;

}

/**
 * The shadow pass's draws of one shadow map render of the scene: one small frame that redraws the
 * maps, waited for (a 1-pixel read-back), so it does not spill into the next timed capture.
 */
function drawsPerShadowRender( name: string ): number {

	const entry = sceneNamed( name );
	setShadows( entry, true );
	const camera = new THREE.PerspectiveCamera( 60, 16 / 9, 0.05, 1000 );
	camera.position.fromArray( entry.positions, 0 );
	const target = new THREE.WebGLRenderTarget( 64, 36 );
	const draws = shadowDraws;
	renderer.setRenderTarget( target );
	renderer.render( entry.scene, camera );
	renderer.setRenderTarget( null );
	renderer.readRenderTargetPixels( target, 0, 0, 1, 1, new Uint8Array( 4 ) );
	target.dispose();
	return shadowDraws - draws;

}

// Diagnostics of the "shadows" part (bench/captureShadowsDecompose.ts): where the extra time of a
// capture with shadows goes. Same loop as ProbeCapturer.capture (no yields), three variants.

/** A 1-pixel read of the canvas: returns once every GL command issued before it has run. */
function finishGL(): void {

	renderer.setRenderTarget( null );
	gl.readPixels( 0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array( 4 ) );

}

/**
 * Diagnostic capture of the first `probes` probes: `'none'` without shadows; `'once'` with the maps
 * drawn at the first face (what ProbeCapturer does); `'frozen'` with the maps drawn and waited for
 * before the timer starts and never redrawn, so the time is the faces' shading alone.
 */
function captureLoop(
	name: string, resolution: number, mode: 'none' | 'once' | 'frozen', probes = - 1,
): { ms: number, sh: number[], shadowDraws: number } {

	const entry = sceneNamed( name );
	const positions = probes < 0 ? entry.positions : entry.positions.subarray( 0, 3 * probes );
	setShadows( entry, mode !== 'none' );
	const capturer = capturerFor( resolution );
	entry.scene.updateMatrixWorld();
	if ( mode !== 'none' ) {

		renderer.shadowMap.autoUpdate = false;
		renderer.shadowMap.needsUpdate = true;
		if ( mode === 'frozen' ) {

			renderTiny( entry, capturer.cubeCamera.children[ 0 ] as THREE.Camera );
			finishGL();

		}

	}

	const draws = shadowDraws;
	const start = performance.now();
	const sh = captureWithCubeCamera( entry, positions, resolution, capturer );
	const ms = performance.now() - start;
	renderer.shadowMap.autoUpdate = true;
	return { ms, sh: Array.from( sh ), shadowDraws: shadowDraws - draws };

}

// three's shadow pass draws through renderer.renderBufferDirect, which needs a render under way:
// the maps are drawn by a render of the scene into one texel.
const tinyTarget = new THREE.WebGLRenderTarget( 1, 1 );

/** Renders the scene into one texel: draws the shadow maps when they need it, and little else. */
function renderTiny( entry: ShadowScene, camera: THREE.Camera ): void {

	renderer.setRenderTarget( tinyTarget );
	renderer.render( entry.scene, camera );
	renderer.setRenderTarget( null );

}

/**
 * Diagnostic: ms per render of the scene's shadow maps — `reps` one-texel renders that redraw the
 * maps minus as many that do not, each set waited for.
 */
function shadowMapRender( name: string, reps: number ): number {

	const entry = sceneNamed( name );
	setShadows( entry, true );
	renderer.shadowMap.autoUpdate = false;
	const camera = new THREE.PerspectiveCamera();
	camera.position.fromArray( entry.positions, 0 );
	entry.scene.updateMatrixWorld();
	const time = ( redraw: boolean ) => {

		finishGL();
		const start = performance.now();
		for ( let r = 0; r < reps; r ++ ) {

			renderer.shadowMap.needsUpdate = redraw;
			renderTiny( entry, camera );

		}

		finishGL();
		return performance.now() - start;

	};

	time( true ); // warm-up
	const ms = ( time( true ) - time( false ) ) / reps;
	renderer.shadowMap.autoUpdate = true;
	return ms;

}

/** Diagnostic: sets the shadow map size of the scene's casters (the maps are made again at the next render). */
function setMapSize( name: string, size: number ): number[] {

	const casters = sceneNamed( name ).casters as ( THREE.Light & { shadow: THREE.LightShadow } )[];
	for ( const light of casters ) {

		light.shadow.mapSize.set( size, size );
		light.shadow.map?.dispose();
		light.shadow.map = null;

	}

	return casters.map( ( light ) => light.shadow.mapSize.x );

}

/** Diagnostic: the WebGL calls (by name) of one {@link captureLoop}, counted by wrapping the context's methods. */
function countGL( name: string, resolution: number, mode: 'none' | 'once' | 'frozen', probes = - 1 ): Record<string, number> {

	const counts: Record<string, number> = {};
	const context = gl as unknown as Record<string, unknown>;
	const wrapped: string[] = [];
	for ( const key of Object.getOwnPropertyNames( WebGL2RenderingContext.prototype ) ) {

		const original = context[ key ];
		if ( typeof original !== 'function' || key === 'constructor' ) continue;
		context[ key ] = function ( this: unknown, ...args: unknown[] ) {

			counts[ key ] = ( counts[ key ] ?? 0 ) + 1;
			return ( original as ( ...a: unknown[] ) => unknown ).apply( gl, args );

		};

		wrapped.push( key );

	}

	try {

		captureLoop( name, resolution, mode, probes );

	} finally {

		for ( const key of wrapped ) delete context[ key ];

	}

	return counts;

}

/** Diagnostic: draws per render of one cube capture (6 faces) and the receivers/casters of the scene. */
function sceneStats( name: string ): Record<string, number> {

	const entry = sceneNamed( name );
	let meshes = 0, receivers = 0, casters = 0, vertices = 0;
	const materials = new Set<THREE.Material>();
	entry.scene.traverse( ( object ) => {

		const mesh = object as THREE.Mesh;
		if ( ! mesh.isMesh ) return;
		meshes ++;
		if ( mesh.receiveShadow ) receivers ++;
		if ( mesh.castShadow ) casters ++;
		vertices += mesh.geometry.getAttribute( 'position' ).count;
		for ( const material of Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ] ) materials.add( material );

	} );
	return { meshes, receivers, casters, vertices, materials: materials.size };

}

function info(): Record<string, unknown> {

	const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
	return {
		renderer: debug ? gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) : gl.getParameter( gl.RENDERER ),
		shadowMapType: renderer.shadowMap.type,
	};

}

const api = {
	info, loadBasic, loadSponza, captureOnce, capturePerFace, drawsPerShadowRender,
	captureLoop, shadowMapRender, setMapSize, countGL, sceneStats,
};
Object.assign( window, { captureShadowsBench: api } );
export type CaptureShadowsBenchApi = typeof api;

Object.assign( window, { captureShadowsBenchReady: true } );
