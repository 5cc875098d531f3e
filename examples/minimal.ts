import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LightProbeVolume, placeGrid } from 'three-capture-lighting';
import { createBasicRoom } from '@scenes/basic.js';
import { backendLabel, chooseRenderer, createRenderer, initRenderer, rendererLinks } from './common/rendererChoice.js';

// The README's example, whole: a level (the Basic room: red, green and blue walls, one warm lamp)
// and a character (a white ball walking a loop), both lit by light probes captured from the level.
// The lines between "README example" and "end" are the README's, verbatim (a test compares them).

// ?renderer=webgpu|webgl2: the same code on a WebGPURenderer, with the library imported from
// 'three-capture-lighting/webgpu' (see common/rendererChoice.ts). Typed as the WebGLRenderer the
// library's signatures name.
const choice = await chooseRenderer();
const renderer = createRenderer( choice, { antialias: true } ) as THREE.WebGLRenderer;
await initRenderer( renderer );
renderer.setPixelRatio( window.devicePixelRatio );
renderer.setSize( window.innerWidth, window.innerHeight );
document.body.appendChild( renderer.domElement );

const camera = new THREE.PerspectiveCamera( 50, window.innerWidth / window.innerHeight, 0.05, 50 );
camera.position.set( 0, 1.6, 3.9 );
const controls = new OrbitControls( camera, renderer.domElement );
controls.target.set( 0, 1, 0 );
controls.update();

const scene = new THREE.Scene();
const { room, lamp } = createBasicRoom();
scene.add( room );

const character = new THREE.Mesh( new THREE.SphereGeometry( 0.3, 48, 24 ), new THREE.MeshStandardMaterial( { roughness: 1 } ) );
character.position.set( 0, 0.3, 1.2 );
scene.add( character );

const status = document.getElementById( 'status' )!;
status.textContent = 'capturing…';
// Which backend draws, and links that reload with another (the page has no panel: its picture is the README's).
document.getElementById( 'info' )!.append( rendererLinks( backendLabel( renderer ), choice ) );
if ( choice.notice ) document.getElementById( 'info' )!.append( ` — ${choice.notice}` );

// README example
const volume = new LightProbeVolume( {
	positions: placeGrid( [ - 1.8, 0.2, - 1.8 ], [ 1.8, 2.8, 1.8 ], [ 4, 4, 4 ] ), // 64 probes in the room's air (min, max, counts)
} );
volume.add( character ); // what moves, first: captures hide it; each frame it blends the probes around it
volume.add( scene ); // the level: each other mesh lit per object, per vertex or per texel, as its size needs
await volume.capture( renderer, scene ); // a cube map per probe, projected to SH9 on the GPU

renderer.setAnimationLoop( ( time ) => {

	character.position.set( 1.2 * Math.sin( time / 2000 ), 0.3, 1.2 * Math.cos( time / 2000 ) );
	volume.update(); // each lit object blends the probes around it
	renderer.render( scene, camera );

} );
// end

status.textContent = `${volume.count} probes captured`;

window.addEventListener( 'resize', () => {

	camera.aspect = window.innerWidth / window.innerHeight;
	camera.updateProjectionMatrix();
	renderer.setSize( window.innerWidth, window.innerHeight );

} );

// For the browser test (test/browser/minimal.test.ts): the objects, once the capture is done.
Object.assign( window, { minimal: { renderer, scene, camera, volume, character, lamp } } );
