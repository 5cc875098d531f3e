/**
 * Browser side of bench/capture.bench.ts: one 1280×720 WebGL2 canvas, the Basic room (red, green,
 * blue walls, white floor, ceiling and back wall, a point light and a glowing ceiling panel), and
 * the measurements as functions on `window.captureBench`, each called by the Node side through
 * puppeteer and returning raw timings (milliseconds, `performance.now()`), summarised in Node.
 *
 * Every timing ends in a GPU → CPU read-back that depends on the work timed, so it includes the
 * GPU work (here SwiftShader, on the CPU).
 */

import * as THREE from 'three';
import { LightProbeGenerator } from 'three/examples/jsm/lights/LightProbeGenerator.js';
import { LightProbeGridWebGL } from 'three/examples/jsm/lighting/LightProbeGridWebGL.js';
// Relative, so `npm run typecheck` sees src/ (not a stale dist/); the bench's Vite server
// redirects it to BENCH_OURS when that is set.
import { LightProbeVolume } from '../../src/index.js';
import { ProbeCapturer, SHProjector } from '../../src/capture.js';
import { FAR, NEAR, createBenchRoom } from './benchRoom.js';

const GRID = [ 4, 4, 4 ];

// ---------------------------------------------------------------------------------------------
// Renderer and the room (benchRoom.ts)

const { renderer, gl, scene, camera, size, unlitWalls, room, lamp, light } = createBenchRoom();

// The 4 × 4 × 4 probe grid: probe positions exactly those of LightProbeGridWebGL (cell centres),
// in its texture order (x fastest, then y, then z).
function makeGrid(): LightProbeGridWebGL {

	const grid = new LightProbeGridWebGL( size.x, size.y, size.z, GRID[ 0 ], GRID[ 1 ], GRID[ 2 ] );
	grid.position.copy( room.position );
	grid.updateBoundingBox();
	return grid;

}

const gridPositions = ( () => {

	const grid = makeGrid(), p = new THREE.Vector3(), out: number[] = [];
	for ( let iz = 0; iz < GRID[ 2 ]; iz ++ ) for ( let iy = 0; iy < GRID[ 1 ]; iy ++ ) for ( let ix = 0; ix < GRID[ 0 ]; ix ++ ) {

		grid.getProbePosition( ix, iy, iz, p );
		out.push( p.x, p.y, p.z );

	}

	grid.dispose();
	return new Float64Array( out );

} )();
const PROBES = gridPositions.length / 3;

const syncPixel = new Uint8Array( 4 );

/** Waits for everything drawn to the canvas (default framebuffer) so far: a 1-pixel read-back. */
function syncCanvas(): void {

	renderer.setRenderTarget( null );
	gl.readPixels( 0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, syncPixel );

}

// A 1-texel read of a render target that depends on a texture: waits for the texture's writers.
const fetchScene = new THREE.Scene();
const fetchCamera = new THREE.OrthographicCamera( - 1, 1, 1, - 1, 0, 1 );
const fetchQuad = new THREE.Mesh( new THREE.PlaneGeometry( 2, 2 ) );
fetchQuad.frustumCulled = false;
fetchScene.add( fetchQuad );
const fetch3D = new THREE.RawShaderMaterial( {
	glslVersion: THREE.GLSL3,
	uniforms: { atlas: { value: null }, slice: { value: 0 }, resolution: { value: new THREE.Vector2() } },
	vertexShader: 'in vec3 position; void main() { gl_Position = vec4( position.xy, 0.0, 1.0 ); }',
	fragmentShader: /* glsl */`
		precision highp float; precision highp int; precision highp sampler3D;
		uniform sampler3D atlas; uniform int slice; uniform vec2 resolution; out vec4 color;
		// Fragment x = probe index (x fastest, then y; z = slice): texel ( ix, iy, slice ).
		void main() {
			int p = int( gl_FragCoord.x );
			int nx = int( resolution.x );
			color = texelFetch( atlas, ivec3( p % nx, p / nx, slice ), 0 );
		}`,
	depthTest: false, depthWrite: false,
} );

/** Reads texels ( ix, iy, slice ) of a 3D texture, `count` = nx·ny of them, as RGBA floats. */
function read3D( texture: THREE.Texture, nx: number, ny: number, slice: number ): Float32Array {

	const target = new THREE.WebGLRenderTarget( nx * ny, 1, {
		type: THREE.FloatType, depthBuffer: false, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter,
	} );
	fetch3D.uniforms.atlas.value = texture;
	fetch3D.uniforms.slice.value = slice;
	fetch3D.uniforms.resolution.value.set( nx, ny );
	fetchQuad.material = fetch3D;
	renderer.setRenderTarget( target );
	renderer.render( fetchScene, fetchCamera );
	renderer.setRenderTarget( null );
	const out = new Float32Array( 4 * nx * ny );
	renderer.readRenderTargetPixels( target, 0, 0, nx * ny, 1, out );
	target.dispose();
	return out;

}

// ---------------------------------------------------------------------------------------------
// 1. SH projection of already rendered cube maps

const CUBE_TYPES = { half: THREE.HalfFloatType, float: THREE.FloatType } as const;
let cubes: { size: number, type: keyof typeof CUBE_TYPES, targets: THREE.WebGLCubeRenderTarget[] } | null = null;
const projector = new SHProjector( renderer );

/** Renders `count` cube maps of the room at probe positions spread through it (not timed). */
function prepareCubes( cubeSize: number, count: number, type: keyof typeof CUBE_TYPES = 'half' ): void {

	disposeCubes();
	const targets: THREE.WebGLCubeRenderTarget[] = [];
	for ( let i = 0; i < count; i ++ ) {

		const target = new THREE.WebGLCubeRenderTarget( cubeSize, {
			type: CUBE_TYPES[ type ], minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
		} );
		const cubeCamera = new THREE.CubeCamera( NEAR, FAR, target );
		// Grid probes 0, 9, 18, … (a diagonal through the room), so the maps differ.
		const p = ( i * 9 ) % PROBES;
		cubeCamera.position.set( gridPositions[ 3 * p ], gridPositions[ 3 * p + 1 ], gridPositions[ 3 * p + 2 ] );
		cubeCamera.updateMatrixWorld();
		renderer.autoClear = true;
		cubeCamera.update( renderer, scene );
		targets.push( target );

	}

	cubes = { size: cubeSize, type, targets };
	// Wait for the renders, so the projection timings start from finished cube maps.
	const pixel = type === 'half' ? new Uint16Array( 4 ) : new Float32Array( 4 );
	renderer.readRenderTargetPixels( targets[ targets.length - 1 ], 0, 0, 1, 1, pixel, 5 );

}

function disposeCubes(): void {

	if ( cubes ) for ( const target of cubes.targets ) target.dispose();
	cubes = null;

}

/**
 * Ours: one SHProjector batch of `probes` cube render targets (cycling through the prepared ones):
 * begin, add × probes, finish (reduction + the read-back of 27 floats per probe, which waits for
 * the GPU). Returns the batch time and the SH of the first prepared cube maps.
 */
function oursProjectBatch( probes: number, solidAngle: 'exact' | 'paper' = 'exact' ): { ms: number, sh: number[][] } {

	if ( ! cubes ) throw new Error( 'prepareCubes first' );
	const { size: cubeSize, targets } = cubes;
	const sh = new Float32Array( 27 * probes );
	const start = performance.now();
	projector.begin( 'cube', cubeSize, probes, { solidAngle } );
	// The render targets, as ProbeCapturer gives them: from 128² on their faces are copied to 2D
	// textures first (timed), which SwiftShader reads faster than a cube map.
	for ( let i = 0; i < probes; i ++ ) projector.add( targets[ i % targets.length ] );
	projector.finish( sh );
	const ms = performance.now() - start;
	const first: number[][] = [];
	for ( let i = 0; i < Math.min( probes, targets.length ); i ++ ) first.push( Array.from( sh.subarray( 27 * i, 27 * i + 27 ) ) );
	return { ms, sh: first };

}

/** The peer: three's LightProbeGenerator.fromCubeRenderTarget (async read-back of 6 faces, awaited, then its CPU loop). */
async function peerProjectOne( index: number ): Promise<{ ms: number, sh: number[] }> {

	if ( ! cubes ) throw new Error( 'prepareCubes first' );
	const target = cubes.targets[ index % cubes.targets.length ];
	const start = performance.now();
	const probe = await LightProbeGenerator.fromCubeRenderTarget( renderer, target );
	const ms = performance.now() - start;
	return { ms, sh: probe.sh.toArray() as number[] };

}

/**
 * Diagnostic, not a peer of its own: LightProbeGenerator's loop as in three r187 (same texel
 * directions, weights, half-float decode, colour conversion and basis), with synchronous
 * readRenderTargetPixels instead of readRenderTargetPixelsAsync, timing read-back and loop apart.
 * It shows how much of the peer's time is the async read-back's polling latency.
 */
function peerPortSyncOne( index: number ): { ms: number, readMs: number, sh: number[] } {

	if ( ! cubes ) throw new Error( 'prepareCubes first' );
	const target = cubes.targets[ index % cubes.targets.length ];
	const start = performance.now();
	const flip = renderer.coordinateSystem === THREE.WebGLCoordinateSystem ? - 1 : 1;
	const dataType = target.texture.type;
	const imageWidth = target.width;
	const texels = imageWidth * imageWidth * 4;
	const data = dataType === THREE.FloatType ? new Float32Array( texels ) : new Uint16Array( texels );
	const coord = new THREE.Vector3(), dir = new THREE.Vector3(), color = new THREE.Color();
	const shBasis = [ 0, 0, 0, 0, 0, 0, 0, 0, 0 ];
	const sh = new THREE.SphericalHarmonics3();
	const c = sh.coefficients;
	let totalWeight = 0, readMs = 0;

	for ( let faceIndex = 0; faceIndex < 6; faceIndex ++ ) {

		const readStart = performance.now();
		renderer.readRenderTargetPixels( target, 0, 0, imageWidth, imageWidth, data, faceIndex );
		readMs += performance.now() - readStart;
		const pixelSize = 2 / imageWidth;
		for ( let i = 0, il = data.length; i < il; i += 4 ) {

			if ( dataType === THREE.FloatType ) color.setRGB( data[ i ], data[ i + 1 ], data[ i + 2 ] );
			else color.setRGB(
				THREE.DataUtils.fromHalfFloat( data[ i ] ),
				THREE.DataUtils.fromHalfFloat( data[ i + 1 ] ),
				THREE.DataUtils.fromHalfFloat( data[ i + 2 ] ),
			);
			const pixelIndex = i / 4;
			const col = ( 1 - ( pixelIndex % imageWidth + 0.5 ) * pixelSize ) * flip;
			const row = 1 - ( Math.floor( pixelIndex / imageWidth ) + 0.5 ) * pixelSize;
			switch ( faceIndex ) {

				case 0: coord.set( - 1 * flip, row, col * flip ); break;
				case 1: coord.set( 1 * flip, row, - col * flip ); break;
				case 2: coord.set( col, 1, - row ); break;
				case 3: coord.set( col, - 1, row ); break;
				case 4: coord.set( col, row, 1 ); break;
				case 5: coord.set( - col, row, - 1 ); break;

			}

			const lengthSq = coord.lengthSq();
			const weight = 4 / ( Math.sqrt( lengthSq ) * lengthSq );
			totalWeight += weight;
			dir.copy( coord ).normalize();
			THREE.SphericalHarmonics3.getBasisAt( dir, shBasis );
			for ( let j = 0; j < 9; j ++ ) {

				c[ j ].x += shBasis[ j ] * color.r * weight;
				c[ j ].y += shBasis[ j ] * color.g * weight;
				c[ j ].z += shBasis[ j ] * color.b * weight;

			}

		}

	}

	const norm = 4 * Math.PI / totalWeight;
	for ( let j = 0; j < 9; j ++ ) c[ j ].multiplyScalar( norm );
	return { ms: performance.now() - start, readMs, sh: sh.toArray() as number[] };

}

// ---------------------------------------------------------------------------------------------
// 2. Whole bake of the 64 grid probes

let capturer: ProbeCapturer | null = null;
let bakeGrid: LightProbeGridWebGL | null = null;

/** Ours: ProbeCapturer.capture over the 64 grid positions (ends in its own read-back of the SH). */
async function bakeOurs( cubeSize: number ): Promise<{ ms: number, l00: number[] }> {

	if ( ! capturer || capturer.resolution !== cubeSize ) {

		capturer?.dispose();
		capturer = new ProbeCapturer( renderer, { resolution: cubeSize, near: NEAR, far: FAR } );

	}

	const sh = new Float32Array( 27 * PROBES );
	const start = performance.now();
	await capturer.capture( scene, gridPositions, sh );
	syncCanvas(); // capture() already read its SH back; this 1-pixel read costs ~nothing, kept for symmetry
	const ms = performance.now() - start;
	const l00: number[] = [];
	for ( let p = 0; p < PROBES; p ++ ) l00.push( sh[ 27 * p ], sh[ 27 * p + 1 ], sh[ 27 * p + 2 ] );
	return { ms, l00 };

}

let renderOnly: { target: THREE.WebGLCubeRenderTarget, camera: THREE.CubeCamera } | null = null;

/**
 * Diagnostic: only the 64 cube renders both bakes share (CubeCamera.update into one HalfFloat,
 * NearestFilter cube target, as ProbeCapturer does), then a 1-texel read of the last face.
 */
function renderCubesOnly( cubeSize: number ): { ms: number } {

	if ( ! renderOnly || renderOnly.target.width !== cubeSize ) {

		renderOnly?.target.dispose();
		const target = new THREE.WebGLCubeRenderTarget( cubeSize, {
			type: THREE.HalfFloatType, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
		} );
		renderOnly = { target, camera: new THREE.CubeCamera( NEAR, FAR, target ) };

	}

	const { target, camera: cubeCamera } = renderOnly;
	const pixel = new Uint16Array( 4 );
	const start = performance.now();
	scene.updateMatrixWorld();
	renderer.autoClear = true;
	for ( let p = 0; p < PROBES; p ++ ) {

		cubeCamera.position.set( gridPositions[ 3 * p ], gridPositions[ 3 * p + 1 ], gridPositions[ 3 * p + 2 ] );
		cubeCamera.updateMatrixWorld();
		cubeCamera.update( renderer, scene );

	}

	renderer.readRenderTargetPixels( target, 0, 0, 1, 1, pixel, 5 );
	return { ms: performance.now() - start };

}

/**
 * The peer: LightProbeGridWebGL.bake over its 4 × 4 × 4 probes, then a 1-texel read of a render
 * target drawn from its atlas (so the read waits for the whole bake). `count` < 64 bakes only the
 * first probes (used to warm up at 128² without paying a full bake).
 */
function bakePeer( cubeSize: number, count = PROBES ): { ms: number, l00: number[] } {

	if ( ! bakeGrid ) bakeGrid = makeGrid();
	const grid = bakeGrid;
	const start = performance.now();
	grid.bake( renderer, scene, { cubemapSize: cubeSize, near: NEAR, far: FAR, count } );
	const texture = grid.texture!;
	read3D( texture, 1, 1, 0 );
	const ms = performance.now() - start;
	// L00 of every probe: atlas sub-volume 0 holds ( c0.rgb, c1.r ), data slices 1 … nz.
	const l00: number[] = new Array( 3 * PROBES ).fill( 0 );
	for ( let iz = 0; iz < GRID[ 2 ]; iz ++ ) {

		const slice = read3D( texture, GRID[ 0 ], GRID[ 1 ], 1 + iz );
		for ( let i = 0; i < GRID[ 0 ] * GRID[ 1 ]; i ++ ) {

			const p = iz * GRID[ 0 ] * GRID[ 1 ] + i;
			l00[ 3 * p ] = slice[ 4 * i ]; l00[ 3 * p + 1 ] = slice[ 4 * i + 1 ]; l00[ 3 * p + 2 ] = slice[ 4 * i + 2 ];

		}

	}

	return { ms, l00 };

}

// ---------------------------------------------------------------------------------------------
// 3. Frame time with moving probe-lit spheres

const VARIANTS = [ 'none', 'global', 'grid', 'ours', 'oursGradients' ] as const;
type Variant = typeof VARIANTS[ number ];

/** One scene per variant, so frames of all variants can alternate with no state switching between them. */
let frameState: {
	scenes: Record<Variant, THREE.Scene>, spheres: Record<Variant, THREE.Mesh[]>,
	volume: LightProbeVolume, gradientVolume: LightProbeVolume, phases: Float32Array, step: number,
} | null = null;

/**
 * Builds the frame-time scenes, one per variant, each: the room with unlit walls (so only the
 * spheres pay for probe lighting, in every variant), the ceiling panel, a PointLight, and `count`
 * small spheres, each with its own MeshStandardMaterial. none: nothing more; global: a LightProbe
 * holding the volume's SH at the room's centre; grid: a LightProbeGridWebGL baked at `cubeSize`;
 * ours: the spheres added to a LightProbeVolume over the 64 grid positions captured at
 * `cubeSize` (each sphere's own material is patched in place, so no clones); oursGradients: the
 * same, in a second volume with the same SH made gradient probes (`setGradients`, random
 * gradients bounded so that across the room each SH float changes by at most its L00's size).
 */
async function setupFrames( count: number, cubeSize: number ): Promise<{ sphereTriangles: number, tetrahedra: number, programs: number }> {

	disposeCubes();
	const volume = new LightProbeVolume( { positions: gridPositions } );
	await volume.capture( renderer, scene, { resolution: cubeSize, near: NEAR, far: FAR } );
	const grid = makeGrid();
	grid.bake( renderer, scene, { cubemapSize: cubeSize, near: NEAR, far: FAR } );
	const gradientVolume = new LightProbeVolume( { positions: gridPositions, sh: volume.sh } );
	gradientVolume.setGradients( randomGradients( volume.sh, 12345 ) );
	const globalProbe = new THREE.LightProbe();
	globalProbe.sh.fromArray( volume.sample( [ room.position.x, room.position.y, room.position.z ] ) );

	const geometry = new THREE.SphereGeometry( 0.08, 16, 12 );
	const phases = new Float32Array( count * 6 );
	let seed = 12345;
	const random = () => ( seed = ( seed * 16807 ) % 2147483647 ) / 2147483647;
	for ( let i = 0; i < phases.length; i ++ ) phases[ i ] = random();
	const colors = Array.from( { length: count }, () => new THREE.Color().setHSL( random(), 0.3, 0.75 ) );

	const scenes = {} as Record<Variant, THREE.Scene>, spheres = {} as Record<Variant, THREE.Mesh[]>;
	for ( const variant of VARIANTS ) {

		const frameScene = new THREE.Scene();
		const walls = new THREE.Mesh( room.geometry, unlitWalls );
		walls.position.copy( room.position );
		const panel = lamp.clone();
		const pointLight = light.clone();
		frameScene.add( walls, panel, pointLight );
		if ( variant === 'global' ) frameScene.add( globalProbe );
		if ( variant === 'grid' ) frameScene.add( grid );
		spheres[ variant ] = colors.map( ( color ) => {

			const sphere = new THREE.Mesh( geometry, new THREE.MeshStandardMaterial( { color, roughness: 0.8, metalness: 0 } ) );
			frameScene.add( sphere );
			return sphere;

		} );
		scenes[ variant ] = frameScene;

	}

	frameState = { scenes, spheres, volume, gradientVolume, phases, step: 0 };
	for ( const variant of VARIANTS ) moveSpheres( variant, 0 );
	for ( const sphere of spheres.ours ) volume.add( sphere );
	for ( const sphere of spheres.oursGradients ) gradientVolume.add( sphere );
	for ( const variant of VARIANTS ) renderer.compile( scenes[ variant ], camera );

	const triangles = geometry.index ? geometry.index.count / 3 : 0;
	return { sphereTriangles: triangles, tetrahedra: volume.interpolator.cellCount, programs: renderer.info.programs?.length ?? 0 };

}

/**
 * 81 gradient floats per probe for `sh` (27 per probe): uniform in ±(|L00| of the probe's channel)
 * / (the room's largest side), so the gradient term stays within about one L00 across the room.
 */
function randomGradients( sh: Float32Array, seed: number ): Float32Array {

	const count = sh.length / 27, out = new Float32Array( 81 * count );
	const side = Math.max( size.x, size.y, size.z );
	for ( let p = 0; p < count; p ++ ) {

		for ( let i = 0; i < 81; i ++ ) {

			seed = ( seed * 16807 ) % 2147483647;
			const l00 = Math.abs( sh[ 27 * p + ( i % 27 ) % 3 ] );
			out[ 81 * p + i ] = ( 2 * seed / 2147483647 - 1 ) * l00 / side;

		}

	}

	return out;

}

/** Lissajous paths inside the probes' hull (x, z in ±1.4, y in 0.45 … 2.55), at animation step `step`; not timed. */
function moveSpheres( variant: Variant, step: number ): void {

	const { spheres, phases } = frameState!;
	const t = step * 0.02;
	const list = spheres[ variant ];
	for ( let i = 0; i < list.length; i ++ ) {

		const f = phases.subarray( 6 * i, 6 * i + 6 );
		list[ i ].position.set(
			1.4 * Math.sin( ( 0.5 + f[ 0 ] ) * t + 6.283 * f[ 1 ] ),
			1.5 + 1.05 * Math.sin( ( 0.5 + f[ 2 ] ) * t + 6.283 * f[ 3 ] ),
			1.4 * Math.sin( ( 0.5 + f[ 4 ] ) * t + 6.283 * f[ 5 ] ),
		);

	}

}

let lastUpdateMs = 0;

/** One frame of `variant` at the current step: [ volume.update() ] + render + 1-pixel read-back, timed. */
function frame( variant: Variant ): number {

	const state = frameState!;
	moveSpheres( variant, state.step );
	const start = performance.now();
	if ( variant === 'ours' || variant === 'oursGradients' ) {

		( variant === 'ours' ? state.volume : state.gradientVolume ).update();
		lastUpdateMs = performance.now() - start;

	}

	renderer.render( state.scenes[ variant ], camera );
	syncCanvas();
	return performance.now() - start;

}

/**
 * `warmUp` untimed animation steps, then `frames` timed ones; at each step every variant renders
 * one frame, in an order rotated by the step, so all variants see the same machine load. Moving the
 * spheres is not timed. Returns the frame times per variant, and ours' volume.update() part.
 */
function runFrames( warmUp: number, frames: number ): Record<Variant | 'oursUpdate' | 'gradientUpdate', number[]> {

	const state = frameState!;
	const times = {
		none: [], global: [], grid: [], ours: [], oursGradients: [], oursUpdate: [], gradientUpdate: [],
	} as Record<Variant | 'oursUpdate' | 'gradientUpdate', number[]>;
	for ( let f = 0; f < warmUp + frames; f ++ ) {

		const step = state.step ++;
		for ( let v = 0; v < VARIANTS.length; v ++ ) {

			const variant = VARIANTS[ ( v + step ) % VARIANTS.length ];
			const ms = frame( variant );
			if ( f < warmUp ) continue;
			times[ variant ].push( ms );
			if ( variant === 'ours' ) times.oursUpdate.push( lastUpdateMs );
			if ( variant === 'oursGradients' ) times.gradientUpdate.push( lastUpdateMs );

		}

	}

	return times;

}

/** Mean colour of a 64 × 36 downscale of one frame of `variant`: a sanity check that it lights the spheres. */
function frameStats( variant: Variant ): { mean: number[], drawCalls: number, triangles: number } {

	frame( variant );
	const { calls, triangles } = renderer.info.render;
	const canvas = document.createElement( 'canvas' );
	canvas.width = 64; canvas.height = 36;
	const context = canvas.getContext( '2d' )!;
	context.drawImage( renderer.domElement, 0, 0, 64, 36 );
	const data = context.getImageData( 0, 0, 64, 36 ).data;
	const mean = [ 0, 0, 0 ];
	for ( let i = 0; i < data.length; i += 4 ) for ( let c = 0; c < 3; c ++ ) mean[ c ] += data[ i + c ] / ( data.length / 4 );
	return { mean, drawCalls: calls, triangles };

}

// ---------------------------------------------------------------------------------------------

function info(): Record<string, unknown> {

	const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
	return {
		version: gl.getParameter( gl.VERSION ),
		vendor: debug ? gl.getParameter( debug.UNMASKED_VENDOR_WEBGL ) : gl.getParameter( gl.VENDOR ),
		renderer: debug ? gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) : gl.getParameter( gl.RENDERER ),
		colorBufferFloat: gl.getExtension( 'EXT_color_buffer_float' ) !== null,
		three: THREE.REVISION,
		canvas: [ renderer.domElement.width, renderer.domElement.height ],
		devicePixelRatio: window.devicePixelRatio,
		probes: PROBES,
	};

}

const api = {
	info, prepareCubes, disposeCubes, oursProjectBatch, peerProjectOne, peerPortSyncOne,
	bakeOurs, bakePeer, renderCubesOnly, setupFrames, runFrames, frameStats,
	/** For experiments from the console / puppeteer: the frame-time scenes. */
	frameState: () => frameState,
};
Object.assign( window, { captureBench: api } );
export type CaptureBenchApi = typeof api;

// A first frame, so the canvas is live before the measurements start.
renderer.render( scene, camera );
syncCanvas();
Object.assign( window, { captureBenchReady: true } );
