/**
 * Browser side of bench/webgpuFrames.bench.ts and bench/webgpuBake.bench.ts: the Basic room on a
 * WebGPURenderer (?backend=webgpu | webgl2), the library used through `three-capture-lighting/webgpu`
 * as a user would. Frames: 500 moving spheres, one scene per variant (no probe, one global
 * LightProbe, three's LightProbeGrid, ours), each step renders every variant in a rotated order.
 * Bake: ours (`LightProbeVolume.capture`) vs `LightProbeGrid.bake` over the same 4 × 4 × 4 probes.
 * Every timing ends in a GPU sync (a 1-texel read-back; a 1-pixel readPixels on WebGL2).
 */

import * as THREE from 'three';
import { WebGPURenderer } from 'three/webgpu';
import { LightProbeGrid } from 'three/examples/jsm/lighting/LightProbeGrid.js';
import { LightProbeVolume } from '../../src/webgpu.js';
import { FAR, HEIGHT, NEAR, ROOM_MAX, ROOM_MIN, WIDTH } from './benchRoom.js';

const backend = new URLSearchParams( location.search ).get( 'backend' ) === 'webgl2' ? 'webgl2' : 'webgpu';
const renderer = new WebGPURenderer( { antialias: false, forceWebGL: backend === 'webgl2' } );
renderer.setPixelRatio( 1 );
renderer.setSize( WIDTH, HEIGHT );
document.body.appendChild( renderer.domElement );

const size = new THREE.Vector3().fromArray( ROOM_MAX ).sub( new THREE.Vector3().fromArray( ROOM_MIN ) );
const centre = new THREE.Vector3().fromArray( ROOM_MIN ).addScaledVector( size, 0.5 );
const camera = new THREE.PerspectiveCamera( 75, WIDTH / HEIGHT, 0.05, 50 );
camera.position.set( 0, 1.5, 1.9 );
camera.lookAt( 0, 1.3, - 2 );

const WALL_COLORS = [ 0x20c020, 0xc02020, 0xffffff, 0xffffff, 0xffffff, 0x2020c0 ];
const litWalls = WALL_COLORS.map( ( color ) => new THREE.MeshStandardMaterial( {
	color, roughness: 1, metalness: 0, side: THREE.BackSide,
} ) );
const unlitWalls = WALL_COLORS.map( ( color ) => new THREE.MeshBasicMaterial( {
	color: new THREE.Color( color ).multiplyScalar( 0.5 ), side: THREE.BackSide,
} ) );
const roomGeometry = new THREE.BoxGeometry( size.x, size.y, size.z );

/** The room (lit walls for captures, unlit for frames so only the spheres pay for probe light), lamp and light. */
function room( lit: boolean ): THREE.Scene {

	const scene = new THREE.Scene();
	const walls = new THREE.Mesh( roomGeometry, lit ? litWalls : unlitWalls );
	walls.position.copy( centre );
	const lamp = new THREE.Mesh( new THREE.PlaneGeometry( 1, 1 ), new THREE.MeshBasicMaterial( { color: 0xffffff } ) );
	lamp.rotation.x = Math.PI / 2;
	lamp.position.set( 0, ROOM_MAX[ 1 ] - 0.01, 0 );
	const light = new THREE.PointLight( 0xffffff, 12, 0, 2 );
	light.position.set( 0, ROOM_MAX[ 1 ] - 0.3, 0 );
	return scene.add( walls, lamp, light );

}

const captureScene = room( true );

/** LightProbeGrid's 4 × 4 × 4 probes over the room; its cell centres are ours' positions too. */
function makeGrid(): LightProbeGrid {

	const grid = new LightProbeGrid( size.x, size.y, size.z, 4, 4, 4 );
	grid.position.copy( centre );
	return grid;

}

const positions: number[] = [];
{

	const grid = makeGrid();
	grid.updateMatrixWorld();
	const p = new THREE.Vector3();
	for ( let iy = 0; iy < 4; iy ++ ) for ( let iz = 0; iz < 4; iz ++ ) for ( let ix = 0; ix < 4; ix ++ ) {

		positions.push( ...grid.getProbePosition( ix, iy, iz, p ).toArray() );

	}


}

const pixel = new Uint8Array( 4 );
const syncTarget = new THREE.RenderTarget( 1, 1 );

/**
 * Waits for the GPU work submitted so far: on WebGPU a read-back of a 1-texel target (its buffer
 * map waits for every earlier submission; queue.onSubmittedWorkDone fails on SwiftShader's adapter
 * here), on WebGL2 a 1-pixel readPixels of the canvas.
 */
async function sync(): Promise<void> {

	const gpu = renderer.backend as unknown as { isWebGPUBackend?: boolean, gl?: WebGL2RenderingContext };
	if ( gpu.isWebGPUBackend ) await renderer.readRenderTargetPixelsAsync( syncTarget, 0, 0, 1, 1 );
	else gpu.gl!.readPixels( 0, 0, 1, 1, gpu.gl!.RGBA, gpu.gl!.UNSIGNED_BYTE, pixel );

}

// Frames

const SPHERES = 500;
const sphereGeometry = new THREE.SphereGeometry( 0.08, 16, 12 );
interface Variant { name: string, scene: THREE.Scene, spheres: THREE.Mesh[], volume: LightProbeVolume | null }
let variants: Variant[] = [];
let step = 0;

function place( spheres: THREE.Mesh[], t: number ): void {

	for ( let i = 0; i < spheres.length; i ++ ) {

		const a = i * 0.37 + t;
		spheres[ i ].position.set(
			centre.x + 0.4 * size.x * Math.sin( 1.1 * a + i ),
			centre.y + 0.4 * size.y * Math.sin( 1.7 * a + 2 * i ),
			centre.z + 0.4 * size.z * Math.sin( 0.7 * a + 3 * i ),
		);

	}

}

/** Builds the four variants' scenes; ours and the grid are captured / baked at `cubeSize`. */
async function setupFrames( cubeSize: number ): Promise<string[]> {

	const volume = new LightProbeVolume( { positions } );
	await volume.capture( renderer, captureScene, { resolution: cubeSize, near: NEAR, far: FAR } );
	const grid = makeGrid();
	grid.bake( renderer, captureScene, { cubemapSize: cubeSize, near: NEAR, far: FAR } );
	const global = new THREE.LightProbe();
	global.sh.fromArray( Array.from( volume.sample( centre ) ) );
	variants = [ 'none', 'global', 'grid', 'ours' ].map( ( name ) => {

		const scene = room( false );
		const spheres: THREE.Mesh[] = [];
		for ( let i = 0; i < SPHERES; i ++ ) {

			spheres.push( new THREE.Mesh( sphereGeometry, new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 0.8 } ) ) );

		}

		scene.add( ...spheres );
		if ( name === 'global' ) scene.add( global );
		if ( name === 'grid' ) scene.add( grid );
		if ( name === 'ours' ) for ( const sphere of spheres ) volume.add( sphere );
		place( spheres, 0 );
		return { name, scene, spheres, volume: name === 'ours' ? volume : null };

	} );
	return variants.map( ( v ) => v.name );

}

/** One animation step: every variant renders once, order rotated per step; ms per variant (in `names` order). */
async function frameStep(): Promise<number[]> {

	step ++;
	const ms = new Array<number>( variants.length );
	for ( let k = 0; k < variants.length; k ++ ) {

		const index = ( k + step ) % variants.length, v = variants[ index ];
		place( v.spheres, step * 0.05 ); // moving the spheres is not timed
		await sync();
		const start = performance.now();
		v.volume?.update();
		renderer.render( v.scene, camera );
		await sync();
		ms[ index ] = performance.now() - start;

	}

	return ms;

}

// Bake

let bakeVolume: LightProbeVolume | null = null;
let bakeGrid: LightProbeGrid | null = null;

async function bakeOurs( cubeSize: number ): Promise<number> {

	bakeVolume ??= new LightProbeVolume( { positions } );
	await sync();
	const start = performance.now();
	await bakeVolume.capture( renderer, captureScene, { resolution: cubeSize, near: NEAR, far: FAR } );
	return performance.now() - start;

}

async function bakePeer( cubeSize: number ): Promise<number> {

	bakeGrid ??= makeGrid();
	await sync();
	const start = performance.now();
	bakeGrid.bake( renderer, captureScene, { cubemapSize: cubeSize, near: NEAR, far: FAR } );
	await sync();
	return performance.now() - start;

}

async function info(): Promise<Record<string, unknown>> {

	const isWebGPUBackend = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend === true;
	return { backend, isWebGPUBackend, three: THREE.REVISION, canvas: [ WIDTH, HEIGHT ] };

}

const api = { info, setupFrames, frameStep, bakeOurs, bakePeer };
/** What the bench files call through page.evaluate. */
export type WebGPUBenchApi = typeof api;
renderer.init().then( () => {

	renderer.setRenderTarget( syncTarget );
	renderer.clear();
	renderer.setRenderTarget( null );

	Object.assign( window, { webgpuBench: api, webgpuBenchReady: true } );

}, ( error: Error ) => {

	Object.assign( window, { webgpuBenchError: String( error.message ?? error ) } );

} );
