import * as THREE from 'three';
import GUI from 'lil-gui';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LightMapper } from 'three/addons/lighting/LightMapper.js';
import { unwrapUVs } from 'three/addons/utils/unwrapUVs.js';
import type { WebGPURenderer } from 'three/webgpu';
import { LightProbeVolume, placeGrid, ProbeVolumeIrradiance } from 'three-capture-lighting/webgpu';
import { createBasicRoom } from '@scenes/basic.js';
import { backendLabel, chooseRenderer, createRenderer, initRenderer, rendererLinks, watchRendererLoss } from './common/rendererChoice.js';

// One source of light for both kinds of objects: the room's walls get a light map baked from the
// probe volume by three's LightMapper, the moving ball is lit by the same volume with volume.add().
// Toggle "scenery" to light the walls per object from the probes instead: the light stays the same.

// LightMapper is WebGPURenderer-only: this page defaults to ?renderer=webgpu.
const info = document.getElementById( 'info' )!, status = document.getElementById( 'status' )!;
const choice = await chooseRenderer( /renderer=/.test( location.search ) ? location.search : '?renderer=webgpu' );
if ( choice.webgpu === null ) {

	status.textContent = 'three\'s LightMapper runs only on WebGPURenderer: open this page with ?renderer=webgpu or ?renderer=webgl2.';
	throw new Error( 'lightmapper: WebGPURenderer only' );

}

const renderer = createRenderer( choice, { antialias: true } ) as THREE.WebGLRenderer;
await initRenderer( renderer );
renderer.setPixelRatio( window.devicePixelRatio );
renderer.setSize( window.innerWidth, window.innerHeight );
document.body.appendChild( renderer.domElement );
// A lost device (or context) would otherwise leave a frozen picture with no word why.
watchRendererLoss( renderer, ( message ) => { if ( message ) status.textContent = message; } );
info.append( rendererLinks( backendLabel( renderer ), choice ) );
if ( choice.notice ) info.append( ` — ${choice.notice}` );

const camera = new THREE.PerspectiveCamera( 50, window.innerWidth / window.innerHeight, 0.05, 50 );
camera.position.set( 0, 1.6, 3.9 );
const controls = new OrbitControls( camera, renderer.domElement );
controls.target.set( 0, 1, 0 );
controls.update();

const scene = new THREE.Scene();
const { room } = createBasicRoom();
scene.add( room );
const walls = room.getObjectByName( 'room' ) as THREE.Mesh;
const wallMaterials = walls.material as THREE.MeshStandardMaterial[];

const character = new THREE.Mesh( new THREE.SphereGeometry( 0.3, 48, 24 ), new THREE.MeshStandardMaterial( { roughness: 1 } ) );
character.position.set( 0, 0.3, 1.2 );
scene.add( character );

// The volume, captured from the room before any light map is on it.
status.textContent = 'capturing…';
const volume = new LightProbeVolume( { positions: placeGrid( [ - 1.8, 0.2, - 1.8 ], [ 1.8, 2.8, 1.8 ], [ 4, 4, 4 ] ) } );
volume.add( character );
await volume.capture( renderer, scene );

// The bake: light map UVs, the volume's irradiance as LightMapper's source (indirect light only:
// the lamp stays a runtime light, as for probe-lit objects).
unwrapUVs( walls, { resolution: 256 } );
const source = new ProbeVolumeIrradiance( renderer, volume, { bounds: new THREE.Box3().setFromObject( walls ) } );
const lightMapper = new LightMapper( renderer as unknown as WebGPURenderer, 256, source.irradiance );
lightMapper.addObjects( [ walls ] );

const params = { scenery: 'light map', samples: 16 };

function bake(): void {

	lightMapper.reset();
	lightMapper.update( params.samples );
	status.textContent = `${volume.count} probes captured, light map baked (${lightMapper.samples} samples)`;

}

function setScenery( mode: string ): void {

	const baked = mode === 'light map';
	if ( baked ) volume.remove( walls );
	for ( const material of wallMaterials ) {

		material.lightMap = baked ? lightMapper.texture : null;
		material.needsUpdate = true;

	}

	if ( ! baked ) volume.add( walls, { mode: 'texture' } );

}

bake();
setScenery( params.scenery );

const gui = new GUI();
gui.add( params, 'scenery', [ 'light map', 'probe-lit per object' ] ).onChange( setScenery );
gui.add( params, 'samples', 1, 256, 1 ).onFinishChange( bake );

// ?present=0 (tests): frames go to a render target, never to the canvas — headless Chromium on
// SwiftShader loses a WebGPU device soon after its first canvas present (as the demo pages' flag).
const offscreen = new URLSearchParams( location.search ).get( 'present' ) === '0' ? new THREE.RenderTarget( 320, 180, { type: THREE.HalfFloatType } ) as THREE.WebGLRenderTarget : null;

renderer.setAnimationLoop( ( time ) => {

	character.position.set( 1.2 * Math.sin( time / 2000 ), 0.3, 1.2 * Math.cos( time / 2000 ) );
	volume.update();
	renderer.setRenderTarget( offscreen );
	renderer.render( scene, camera );
	renderer.setRenderTarget( null );

} );

window.addEventListener( 'resize', () => {

	camera.aspect = window.innerWidth / window.innerHeight;
	camera.updateProjectionMatrix();
	renderer.setSize( window.innerWidth, window.innerHeight );

} );

// For the browser test (test/browser/webgpuLightMap.test.ts).
Object.assign( window, { lightmapper: { THREE, renderer, scene, camera, volume, walls, character, source, lightMapper, setScenery } } );
