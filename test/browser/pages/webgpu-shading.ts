import * as THREE from 'three/webgpu';
import { WebGLRenderer, WebGLRenderTarget } from 'three';
// The webgpu subpath by file: cli/libraryAliases.ts does not alias it yet.
import { LightProbeVolume } from '../../../src/webgpu.js';

// Node-material shading on WebGPURenderer (both backends), checked against three's own LightProbe
// and against WebGLRenderer drawing the same volume: test/browser/webgpuShading.test.ts calls
// window.shading.* and asserts on the numbers. Images are 64² linear RGBA8 render targets, read
// back top row first on every renderer.

const SIZE = 64;

/** A sky-like SH with variation in all bands and channels (the WebGL tests' SKY). */
const SKY = [
	1.5, 1.35, 1.2, 0.45, 0.52, 0.75, 0.3, 0.1, - 0.15, - 0.38, 0.15, 0.3, 0.15, - 0.08, 0.08,
	0.08, 0.15, - 0.08, - 0.15, 0.08, 0.15, 0.12, - 0.09, 0.06, 0.18, 0.0, - 0.12,
];

/** A probe layout around everything drawn: a large irregular double tetrahedron. */
const WIDE = [ - 10, - 8, - 9, 11, - 9, - 8, 0, 12, - 10, 1, - 1, 12, - 2, 10, 9 ];

type Backend = 'webgpu' | 'webgl2' | 'webgl';
type AnyRenderer = THREE.WebGPURenderer | WebGLRenderer;

interface Diff {

	/** Largest channel difference (0–255). */
	max: number;
	/** Pixels with a channel beyond the tolerance. */
	count: number;
	/** Pixels covered (not black) in the first image. */
	covered: number;

}

function repeat( sh: readonly number[], count: number ): Float32Array {

	const out = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) out.set( sh, 27 * i );
	return out;

}

function lightProbe( sh: readonly number[] ): THREE.LightProbe {

	return new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( sh as number[] ) );

}

function camera( x: number, y: number, z: number ): THREE.PerspectiveCamera {

	const result = new THREE.PerspectiveCamera( 45, 1, 0.05, 100 );
	result.position.set( x, y, z );
	result.lookAt( 0, 0, 0 );
	result.updateMatrixWorld();
	return result;

}

const renderers = new Map<Backend, RendererEntry>();

/** A renderer of the backend (made once), its render target, and whether its read-back is bottom row first. */
async function rendererFor( backend: Backend ): Promise<RendererEntry> {

	let entry = renderers.get( backend );
	if ( entry !== undefined ) return entry;
	let renderer: AnyRenderer, target: THREE.RenderTarget | WebGLRenderTarget;
	if ( backend === 'webgl' ) {

		renderer = new WebGLRenderer();
		target = new WebGLRenderTarget( SIZE, SIZE );

	} else {

		renderer = new THREE.WebGPURenderer( { forceWebGL: backend === 'webgl2' } );
		await renderer.init();
		target = new THREE.RenderTarget( SIZE, SIZE );

	}

	renderer.setSize( SIZE, SIZE, false );
	entry = { renderer, target, flip: false };
	renderers.set( backend, entry );
	// Orientation: a white plane over the upper half of the view.
	const plane = new THREE.Mesh( new THREE.PlaneGeometry( 2, 1 ), new THREE.MeshBasicMaterial( { color: 0xffffff } ) );
	plane.position.y = 0.5;
	const ortho = new THREE.OrthographicCamera( - 1, 1, 1, - 1, 0.1, 10 );
	ortho.position.z = 1;
	const image = await renderRaw( entry, new THREE.Scene().add( plane ), ortho );
	entry.flip = image[ 0 ] === 0;
	return entry;

}

interface RendererEntry {

	renderer: AnyRenderer;
	target: THREE.RenderTarget | WebGLRenderTarget;
	/** Whether the read-back comes bottom row first. */
	flip: boolean;

}

async function renderRaw( entry: RendererEntry, scene: THREE.Scene, view: THREE.Camera ): Promise<Uint8Array> {

	const { renderer, target } = entry;
	if ( renderer instanceof WebGLRenderer ) {

		renderer.setRenderTarget( target as WebGLRenderTarget );
		renderer.setClearColor( 0x000000, 1 );
		renderer.clear();
		renderer.render( scene, view );
		const out = new Uint8Array( 4 * SIZE * SIZE );
		renderer.readRenderTargetPixels( target as WebGLRenderTarget, 0, 0, SIZE, SIZE, out );
		renderer.setRenderTarget( null );
		return out;

	}

	renderer.setRenderTarget( target as THREE.RenderTarget );
	renderer.setClearColor( 0x000000, 1 );
	renderer.render( scene, view );
	const pixels = await renderer.readRenderTargetPixelsAsync( target as THREE.RenderTarget, 0, 0, SIZE, SIZE );
	renderer.setRenderTarget( null );
	return new Uint8Array( pixels.buffer, pixels.byteOffset, 4 * SIZE * SIZE ).slice();

}

/** Renders to RGBA8, top row first. */
async function render( backend: Backend, scene: THREE.Scene, view: THREE.Camera ): Promise<Uint8Array> {

	const entry = await rendererFor( backend );
	const image = await renderRaw( entry, scene, view );
	if ( ! entry.flip ) return image;
	const out = new Uint8Array( image.length ), row = 4 * SIZE;
	for ( let y = 0; y < SIZE; y ++ ) out.set( image.subarray( y * row, ( y + 1 ) * row ), ( SIZE - 1 - y ) * row );
	return out;

}

function diff( a: Uint8Array, b: Uint8Array, tolerance: number ): Diff {

	let max = 0, count = 0, covered = 0;
	for ( let p = 0; p < a.length; p += 4 ) {

		let worst = 0;
		for ( let c = 0; c < 3; c ++ ) worst = Math.max( worst, Math.abs( a[ p + c ] - b[ p + c ] ) );
		max = Math.max( max, worst );
		if ( worst > tolerance ) count ++;
		if ( a[ p ] + a[ p + 1 ] + a[ p + 2 ] > 0 ) covered ++;

	}

	return { max, count, covered };

}

type MaterialKind = 'standard' | 'physical' | 'plain';

/** The materials of the spheres: node materials, or plain built-in ones (three converts them). */
function makeMaterials( kind: MaterialKind | 'mixed' ): THREE.Material[] {

	const standard = { color: 0xd0c8b0, roughness: 0.8, metalness: 0 };
	const physical = { color: 0xa0c0e0, roughness: 0.6, metalness: 0, clearcoat: 0.3 };
	switch ( kind ) {

		case 'standard': return [ new THREE.MeshStandardNodeMaterial( standard ), new THREE.MeshStandardNodeMaterial( { ...standard, color: 0x80d080 } ) ];
		case 'physical': return [ new THREE.MeshPhysicalNodeMaterial( physical ), new THREE.MeshPhysicalNodeMaterial( { ...physical, clearcoat: 0 } ) ];
		case 'plain': return [ new THREE.MeshStandardMaterial( standard ), new THREE.MeshPhysicalMaterial( physical ) ];
		default: return [ new THREE.MeshStandardNodeMaterial( standard ), new THREE.MeshPhysicalNodeMaterial( physical ) ];

	}

}

/** Two spheres side by side, each with its own geometry (vertex mode writes attributes into it). */
function spheres( materials: THREE.Material[], segments: number ): THREE.Mesh[] {

	return materials.map( ( material, i ) => {

		const mesh = new THREE.Mesh( new THREE.SphereGeometry( 0.45, segments, segments / 2 ), material );
		mesh.position.set( ( i - ( materials.length - 1 ) / 2 ) * 1.0, 0, 0 );
		return mesh;

	} );

}

type Mode = 'object' | 'perVertex' | 'vertex' | 'vertexSH' | 'texture';

function addOptions( mode: Mode ): Record<string, unknown> {

	switch ( mode ) {

		case 'object': return {};
		case 'perVertex': return { perVertex: true };
		case 'vertex': return { mode: 'vertex' };
		case 'vertexSH': return { mode: 'vertex', vertexOutput: 'sh' };
		case 'texture': return { mode: 'texture' };

	}

}

function disposeScene( scene: THREE.Scene ): void {

	scene.traverse( ( node ) => {

		const mesh = node as THREE.Mesh;
		if ( mesh.isMesh !== true ) return;
		mesh.geometry.dispose();
		for ( const material of Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ] ) material.dispose();

	} );

}

/**
 * Spheres lit by a volume whose probes all hold SKY against the same spheres with a LightProbe
 * holding SKY; also the unlit picture (nothing but black) to show the light is really there.
 */
async function versusLightProbe( backend: Backend, mode: Mode, kind: MaterialKind | 'mixed' ) {

	const segments = mode === 'object' || mode === 'texture' || mode === 'vertexSH' ? 48 : 128;
	const lit = spheres( makeMaterials( kind ), segments );
	const volume = new LightProbeVolume( { positions: WIDE, sh: repeat( SKY, 5 ) } );
	const volumeScene = new THREE.Scene().add( ...lit );
	for ( const mesh of lit ) volume.add( mesh, addOptions( mode ) );
	volume.update();
	const referenceScene = new THREE.Scene().add( ...spheres( makeMaterials( kind ), segments ), lightProbe( SKY ) );
	const view = camera( 0.3, 0.8, 3 );
	const actual = await render( backend, volumeScene, view );
	const expected = await render( backend, referenceScene, view );
	const lighting = lit.map( ( mesh ) => volume.getLighting( mesh ) );
	volume.dispose();
	const unlit = await render( backend, volumeScene, view );
	disposeScene( volumeScene );
	disposeScene( referenceScene );
	return { ...diff( actual, expected, 2 ), unlitCovered: diff( unlit, unlit, 0 ).covered, lighting };

}

/** The bipyramid of the WebGL tests: two probes 0.6 apart on x, a ring around them; the origin is halfway. */
const PAIR = [ - 0.3, 0, 0, 0.3, 0, 0, 0, 1, 0, 0, - 0.5, 0.866, 0, - 0.5, - 0.866 ];
const RED = SKY.map( ( v, i ) => i % 3 === 0 ? v * 1.6 : v * 0.4 );
const BLUE = SKY.map( ( v, i ) => i % 3 === 2 ? v * 1.4 : v * 0.3 ).map( ( v, i ) => i >= 3 && i < 12 ? - v : v );
const GREEN = SKY.map( ( v, i ) => i % 3 === 1 ? v * 5 : 0 );

/** An object halfway between two probes against a LightProbe holding their average (and against RED alone). */
async function halfway( backend: Backend ) {

	const average = RED.map( ( v, i ) => ( v + BLUE[ i ] ) / 2 );
	const volume = new LightProbeVolume( { positions: PAIR, sh: [ ...RED, ...BLUE, ...GREEN, ...GREEN, ...GREEN ] } );
	const [ mesh ] = spheres( [ new THREE.MeshStandardNodeMaterial( { roughness: 0.7 } ) ], 64 );
	const volumeScene = new THREE.Scene().add( mesh );
	volume.add( mesh );
	volume.update();
	const view = camera( 0.4, 0.6, 1.8 );
	const actual = await render( backend, volumeScene, view );
	const reference = ( sh: number[] ) => {

		const material = new THREE.MeshStandardNodeMaterial( { roughness: 0.7 } );
		return new THREE.Scene().add( ...spheres( [ material ], 64 ), lightProbe( sh ) );

	};

	const expectedScene = reference( average ), redScene = reference( RED );
	const expected = await render( backend, expectedScene, view );
	const red = await render( backend, redScene, view );
	volume.dispose();
	[ volumeScene, expectedScene, redScene ].forEach( disposeScene );
	return { ...diff( actual, expected, 2 ), versusRed: diff( actual, red, 2 ).max };

}

/**
 * The same volume and scene drawn by WebGLRenderer (built-in materials, the onBeforeCompile patch)
 * and by WebGPURenderer (node materials, or the same built-in materials); a control pair lit by a
 * LightProbe shows how far the two renderers differ by themselves.
 */
async function versusWebGL( backend: Backend, mode: Mode, kind: 'node' | 'plain' ) {

	const segments = mode === 'object' || mode === 'texture' || mode === 'vertexSH' ? 48 : 96;
	const volume = new LightProbeVolume( { positions: PAIR, sh: [ ...RED, ...BLUE, ...GREEN, ...GREEN, ...GREEN ] } );
	const glMeshes = spheres( makeMaterials( 'plain' ), segments );
	const gpuMeshes = spheres( kind === 'plain' ? makeMaterials( 'plain' ) : makeMaterials( 'mixed' ), segments );
	for ( const mesh of [ ...glMeshes, ...gpuMeshes ] ) mesh.scale.setScalar( 0.6 );
	const glScene = new THREE.Scene().add( ...glMeshes ), gpuScene = new THREE.Scene().add( ...gpuMeshes );
	for ( const mesh of [ ...glMeshes, ...gpuMeshes ] ) volume.add( mesh, addOptions( mode ) );
	volume.update();
	const view = camera( 0.2, 0.5, 2.2 );
	const gl = await render( 'webgl', glScene, view );
	const gpu = await render( backend, gpuScene, view );
	volume.dispose();
	const probeGL = new THREE.Scene().add( ...spheres( makeMaterials( 'plain' ), segments ), lightProbe( SKY ) );
	const probeGPU = new THREE.Scene().add( ...spheres( kind === 'plain' ? makeMaterials( 'plain' ) : makeMaterials( 'mixed' ), segments ), lightProbe( SKY ) );
	const control = diff( await render( backend, probeGPU, view ), await render( 'webgl', probeGL, view ), 2 );
	[ glScene, gpuScene, probeGL, probeGPU ].forEach( disposeScene );
	return { ...diff( gpu, gl, 2 ), control };

}

/**
 * The render pipelines a WebGPURenderer holds (r187 exposes programs in `info.memory`; the pipeline
 * cache, keyed by shader and state, is internal): keys, so that pipelines released in between
 * (a disposed material's) do not hide new ones.
 */
function pipelineKeys( renderer: THREE.WebGPURenderer ): Set<unknown> {

	return new Set( ( renderer as unknown as { _pipelines: { caches: Map<unknown, unknown> } } )._pipelines.caches.keys() );

}

/** 10 spheres sharing one material: pipelines before and after the volume lights them (each gets its own clone). */
async function sharing( backend: Backend, kind: 'node' | 'plain' ) {

	const { renderer } = await rendererFor( backend );
	const material = kind === 'node' ? new THREE.MeshStandardNodeMaterial( { roughness: 0.9 } ) : new THREE.MeshStandardMaterial( { roughness: 0.9 } );
	const geometry = new THREE.SphereGeometry( 0.1, 16, 8 );
	const meshes: THREE.Mesh[] = [];
	for ( let i = 0; i < 10; i ++ ) {

		const mesh = new THREE.Mesh( geometry, material );
		mesh.position.set( ( i % 5 ) * 0.25 - 0.5, i < 5 ? 0.15 : - 0.15, 0 );
		meshes.push( mesh );

	}

	const scene = new THREE.Scene().add( ...meshes, new THREE.DirectionalLight( 0xffffff, 1 ) );
	const view = camera( 0, 0, 2 );
	await render( backend, scene, view );
	const before = pipelineKeys( renderer as THREE.WebGPURenderer );
	const volume = new LightProbeVolume( { positions: WIDE, sh: repeat( SKY, 5 ) } );
	for ( const mesh of meshes ) volume.add( mesh );
	volume.update();
	const lit = await render( backend, scene, view );
	const after = pipelineKeys( renderer as THREE.WebGPURenderer );
	const added = [ ...after ].filter( ( key ) => ! before.has( key ) ).length;
	const materials = new Set( meshes.map( ( mesh ) => mesh.material ) ).size;
	volume.dispose();
	const restored = meshes.every( ( mesh ) => mesh.material === material );
	disposeScene( scene );
	return { added, materials, restored, litCovered: diff( lit, lit, 0 ).covered };

}

/**
 * The views: direct scale 0 (a directional light too) equals the LightProbe alone; intensity ½
 * equals a LightProbe with SKY / 2; the full picture equals LightProbe + directional light.
 */
async function views( backend: Backend, kind: 'node' | 'plain' ) {

	const make = () => spheres( kind === 'node' ? makeMaterials( 'mixed' ) : makeMaterials( 'plain' ), 48 );
	const sun = () => {

		const light = new THREE.DirectionalLight( 0xffffff, 1.5 );
		light.position.set( 1, 2, 1.5 );
		return light;

	};

	const lit = make();
	const volume = new LightProbeVolume( { positions: WIDE, sh: repeat( SKY, 5 ) } );
	const scene = new THREE.Scene().add( ...lit, sun() );
	for ( const mesh of lit ) volume.add( mesh );
	volume.update();
	const view = camera( 0.3, 0.8, 3 );
	const full = await render( backend, scene, view );
	for ( const mesh of lit ) volume.getUniforms( mesh )!.probeVolumeDirectScale.value = 0;
	const indirect = await render( backend, scene, view );
	for ( const mesh of lit ) {

		volume.getUniforms( mesh )!.probeVolumeDirectScale.value = 1;
		volume.getUniforms( mesh )!.probeVolumeIntensity.value = 0.5;

	}

	const half = await render( backend, scene, view );
	volume.dispose();
	const probeAndSun = new THREE.Scene().add( ...make(), lightProbe( SKY ), sun() );
	const probeOnly = new THREE.Scene().add( ...make(), lightProbe( SKY ) );
	const halfProbeAndSun = new THREE.Scene().add( ...make(), lightProbe( SKY.map( ( v ) => v / 2 ) ), sun() );
	const result = {
		full: diff( full, await render( backend, probeAndSun, view ), 2 ),
		indirect: diff( indirect, await render( backend, probeOnly, view ), 2 ),
		half: diff( half, await render( backend, halfProbeAndSun, view ), 2 ),
		fullVersusIndirect: diff( full, indirect, 2 ).max,
	};
	[ scene, probeAndSun, probeOnly, halfProbeAndSun ].forEach( disposeScene );
	return result;

}

/**
 * add / remove / dispose cycles: after each removal the material has exactly its own properties of
 * before and draws as it did unlit; lit again it matches the first lit picture.
 */
async function cycles( backend: Backend, kind: 'node' | 'plain' ) {

	const parameters = { roughness: 0.8 };
	const material = kind === 'node' ? new THREE.MeshStandardNodeMaterial( parameters ) : new THREE.MeshStandardMaterial( parameters );
	const [ mesh ] = spheres( [ material ], 48 );
	const scene = new THREE.Scene().add( mesh, new THREE.AmbientLight( 0x404040, 1 ) );
	const view = camera( 0, 0.5, 1.8 );
	const unlit = await render( backend, scene, view );
	// After a first draw: three adds its own (event listeners).
	const keys = new Set( Object.keys( material ) );
	// Own properties the material did not have, other than the class's own value put back (unpatchMaterial does that).
	const proto = Object.getPrototypeOf( material ) as Record<string, unknown>;
	const own = material as unknown as Record<string, unknown>;
	const extra = () => Object.keys( material ).filter( ( key ) => ! keys.has( key ) && own[ key ] !== proto[ key ] );
	let firstLit: Uint8Array | null = null;
	const report: { extraKeys: string; litMax: number; unlitMax: number; keysRestored: boolean; sameMaterial: boolean }[] = [];
	for ( let cycle = 0; cycle < 3; cycle ++ ) {

		const volume = new LightProbeVolume( { positions: WIDE, sh: repeat( SKY, 5 ) } );
		volume.add( mesh, cycle === 1 ? { mode: 'texture' } : {} );
		volume.update();
		const lit = await render( backend, scene, view );
		firstLit ??= lit;
		if ( cycle === 2 ) volume.dispose();
		else volume.remove( mesh );
		const after = await render( backend, scene, view );
		report.push( {
			extraKeys: extra().join( ',' ), litMax: diff( lit, firstLit, 2 ).max, unlitMax: diff( after, unlit, 0 ).max,
			keysRestored: extra().length === 0, sameMaterial: mesh.material === material,
		} );
		if ( cycle !== 2 ) volume.dispose();

	}

	const litVersusUnlit = diff( firstLit!, unlit, 2 ).max;
	disposeScene( scene );
	return { report, litVersusUnlit };

}

async function hasWebGPU(): Promise<boolean> {

	const gpu = ( navigator as unknown as { gpu?: { requestAdapter(): Promise<unknown> } } ).gpu;
	return gpu !== undefined && ( await gpu.requestAdapter() ) !== null;

}

Object.assign( window, { shading: { hasWebGPU, versusLightProbe, halfway, versusWebGL, sharing, views, cycles }, shadingReady: true } );
