import * as THREE from 'three';
import { LightProbeVolume } from 'three-capture-lighting';

// Lights a sphere from a captured volume, loses the WebGL context, checks what survives, restores
// it and renders again. The outcome is left in window.__result for test/browser/contextLoss.test.ts.

const renderer = new THREE.WebGLRenderer( { preserveDrawingBuffer: true } );
renderer.setSize( 64, 64 );
document.body.appendChild( renderer.domElement );
const gl = renderer.getContext();

const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera( 40, 1, 0.1, 100 );
camera.position.set( 0, 0, 4 );
const room = new THREE.Mesh( new THREE.BoxGeometry( 8, 8, 8 ), new THREE.MeshBasicMaterial( { color: 0xff4020, side: THREE.BackSide } ) );
scene.add( room );
const sphere = new THREE.Mesh( new THREE.SphereGeometry( 1, 32, 16 ), new THREE.MeshStandardMaterial( { roughness: 1 } ) );
scene.add( sphere );

function pixels(): Uint8Array {

	renderer.render( scene, camera );
	const out = new Uint8Array( 64 * 64 * 4 );
	gl.readPixels( 0, 0, 64, 64, gl.RGBA, gl.UNSIGNED_BYTE, out );
	return out;

}

async function run(): Promise<Record<string, unknown>> {

	const volume = new LightProbeVolume( { positions: [ - 1, - 1, - 1, 2, - 1, - 1, - 1, 2, - 1, - 1, - 1, 2, 1, 1, 1 ] } );
	await volume.capture( renderer, scene, { resolution: 16 } );
	volume.add( sphere );
	room.visible = false; // only the probe-lit sphere on black
	volume.update();
	const before = pixels();
	const shBefore = Array.from( volume.sh );

	const extension = gl.getExtension( 'WEBGL_lose_context' );
	if ( ! extension ) return { error: 'WEBGL_lose_context is not available' };
	const lost = new Promise( ( resolve ) => renderer.domElement.addEventListener( 'webglcontextlost', resolve, { once: true } ) );
	extension.loseContext();
	await lost;
	// Chromium allows restoreContext() only once the lost event has been fully dispatched (and
	// three.js has called preventDefault on it), i.e. from a later task.
	await new Promise( ( resolve ) => setTimeout( resolve, 0 ) );

	let captureError = '';
	room.visible = true;
	try {

		await volume.capture( renderer, scene, { resolution: 16 } );

	} catch ( error ) {

		captureError = ( error as Error ).message;

	}

	room.visible = false;
	const shDuringLoss = Array.from( volume.sh );

	const restored = new Promise( ( resolve ) => renderer.domElement.addEventListener( 'webglcontextrestored', resolve, { once: true } ) );
	extension.restoreContext();
	await restored;
	volume.update();
	const after = pixels();

	let maxDifference = 0, lit = 0;
	for ( let i = 0; i < before.length; i ++ ) {

		maxDifference = Math.max( maxDifference, Math.abs( before[ i ] - after[ i ] ) );
		if ( i % 4 === 0 && before[ i ] > 20 ) lit ++;

	}

	return {
		captureError,
		shKeptDuringLoss: shDuringLoss.every( ( v, i ) => v === shBefore[ i ] ),
		shNonZero: shBefore.some( ( v ) => v !== 0 ),
		litPixels: lit,
		maxDifference,
	};

}

run().then( ( result ) => Object.assign( window, { __result: result } ), ( error ) => Object.assign( window, { __result: { error: String( error?.stack ?? error ) } } ) );
