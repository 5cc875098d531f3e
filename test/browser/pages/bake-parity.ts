import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MTLLoader } from 'three/addons/loaders/MTLLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { LightProbeVolume } from 'three-capture-lighting';
import { prepareCaptureScene } from 'three-capture-lighting/capture';

// What a game's page writes to capture its own level as `capture-lighting bake` does: three's
// loaders as three's examples use them, the lamp added by hand, prepareCaptureScene, then
// LightProbeVolume.capture. test/browser/bakeParity.test.ts compares the SH with the CLI's file.
// Nothing here comes from the CLI's bake page.

/** One capture, as the test asks for it. */
interface ParityRequest {

	/** Folder URL (ending in '/') and file name of the scene. */
	folder: string;
	file: string;
	positions: number[];
	resolution: number;

	/** A point light added by hand (what --point adds), or null. */
	lamp: { position: number[]; intensity: number; color: number } | null;

	/** Whether to call prepareCaptureScene (false: the scene as loaded, for the control). */
	prepare: boolean;

}

async function load( folder: string, file: string ): Promise<THREE.Object3D> {

	if ( file.endsWith( '.glb' ) ) return ( await new GLTFLoader().setPath( folder ).loadAsync( file ) ).scene;
	const materials = await new MTLLoader().setPath( folder ).loadAsync( file.replace( /\.obj$/, '.mtl' ) );
	materials.preload();
	return new OBJLoader().setMaterials( materials ).setPath( folder ).loadAsync( file );

}

async function capture( request: ParityRequest ): Promise<number[]> {

	const renderer = new THREE.WebGLRenderer();
	const scene = new THREE.Scene();
	scene.add( await load( request.folder, request.file ) );
	if ( request.lamp ) {

		const lamp = new THREE.PointLight( request.lamp.color, request.lamp.intensity, 0, 2 );
		lamp.position.fromArray( request.lamp.position );
		scene.add( lamp );

	}

	const prepared = request.prepare ? prepareCaptureScene( renderer, scene ) : null;
	const volume = new LightProbeVolume( { positions: request.positions } );
	await volume.capture( renderer, scene, { resolution: request.resolution } );
	prepared?.restore();
	const sh = Array.from( volume.sh.subarray( 0, 27 * request.positions.length / 3 ) );
	volume.dispose();
	renderer.dispose();
	return sh;

}

( window as unknown as { parity: { capture: typeof capture } } ).parity = { capture };
( window as unknown as { parityReady: boolean } ).parityReady = true;
