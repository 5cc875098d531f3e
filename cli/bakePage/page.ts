/**
 * The GPU half of `capture-lighting bake`: loads the scene file with three's loaders
 * (loadScene.ts), adds the sky and the lights asked for (addLights.ts), prepares the scene with the
 * library's `prepareCaptureScene` — the only change made to it, the same a page makes before
 * `volume.capture()` — and captures SH9 at every probe with the library's `ProbeCapturer`. Node
 * (cli/capture.ts) opens this page in headless Chromium and calls `window.bake.run`; progress goes
 * back through the function Node exposes as `PROGRESS_FUNCTION`. Textures are decoded here because
 * Node loaders cannot.
 */

import * as THREE from 'three';
import { HDRLoader } from 'three/addons/loaders/HDRLoader.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { SHProjector } from '../../src/capture/SHProjector.js';
import { prepareCaptureScene } from '../../src/capture/prepareCaptureScene.js';
import { addBakeLights } from './addLights.js';
import { loadGLTF, loadOBJ } from './loadScene.js';
import { PROGRESS_FUNCTION, type BakePageApi, type BakeRequest, type BakeResult, type BakeSceneInfo } from './protocol.js';

type ProgressFunction = ( stage: string, done: number, total: number ) => void;

const progress: ProgressFunction = ( stage, done, total ) => {

	const report = ( window as unknown as Record<string, ProgressFunction | undefined> )[ PROGRESS_FUNCTION ];
	if ( report ) void Promise.resolve( report( stage, done, total ) ).catch( () => undefined );

};

const api: BakePageApi = {

	async run( request: BakeRequest ): Promise<BakeResult> {

		const renderer = new THREE.WebGLRenderer( { antialias: false } );
		renderer.setPixelRatio( 1 );
		renderer.setSize( 16, 16 );
		const scene = new THREE.Scene();

		const loadStart = performance.now();
		progress( 'loading', 0, 1 );
		const onLoadProgress = ( fraction: number ) => progress( 'loading', fraction, 1 );
		const model = request.kind === 'gltf' ? await loadGLTF( request.sceneUrl, onLoadProgress ) : await loadOBJ( request.sceneUrl, onLoadProgress );
		scene.add( model );

		if ( request.sky && 'color' in request.sky ) {

			const [ r, g, b ] = request.sky.color;
			scene.background = new THREE.Color().setRGB( r, g, b, THREE.SRGBColorSpace );

		} else if ( request.sky ) {

			const texture = await new HDRLoader().loadAsync( request.sky.hdrUrl );
			texture.mapping = THREE.EquirectangularReflectionMapping;
			scene.background = texture;

		}

		scene.updateMatrixWorld( true );
		const box = new THREE.Box3().setFromObject( model );
		const bounds = box.isEmpty() || ! Number.isFinite( box.min.x + box.max.x + box.min.y + box.max.y + box.min.z + box.max.z )
			? new THREE.Sphere( new THREE.Vector3(), 1 ) : box.getBoundingSphere( new THREE.Sphere() );
		bounds.radius = Math.max( bounds.radius, 1e-3 );
		const added = addBakeLights( scene, request.lights, request.ambient, bounds );

		// The one change made to the scene: what a page calls before volume.capture(). The capture
		// draws the shadow maps once per ProbeCapturer.capture call (the scene is static).
		const prepared = prepareCaptureScene( renderer, scene, request.prepare );
		const loadMs = performance.now() - loadStart;
		progress( 'loading', 1, 1 );
		const gl = renderer.getContext();
		const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
		const info: BakeSceneInfo = {
			renderer: debug ? String( gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) ) : String( gl.getParameter( gl.RENDERER ) ),
			meshes: prepared.meshes, triangles: prepared.triangles, nonFiniteVertices: prepared.nonFiniteVertices,
			lights: prepared.lights.map( ( { light, kind } ) => ( { kind, source: added.get( light ) ?? 'file' } ) ),
			emissiveMaterials: prepared.emissiveMaterials, unlitMaterials: prepared.unlitMaterials,
			shadowLights: prepared.shadowLights, shadowMeshes: prepared.shadowMeshes, doubleSidedMaterials: prepared.doubleSidedMaterials,
		};
		// Nothing to capture (no geometry and no sky), or geometry no capture can render: the CLI
		// reports it as bad input. A sky alone is a valid bake (an outdoor probe set).
		if ( ( info.triangles === 0 && ! request.sky ) || info.nonFiniteVertices > 0 ) {

			renderer.dispose();
			return { sh: '', captureMs: 0, loadMs, info };

		}

		const count = request.positions.length / 3;
		const capturer = new ProbeCapturer( renderer, {
			resolution: request.resolution, near: request.near, far: request.far, type: THREE.HalfFloatType,
		} );
		const target = new Float32Array( 27 * count );
		// ProbeCapturer reports probes as submitted; the GPU finishes them at the read-back that ends
		// each call. Capturing in chunks (at most ~20 calls, never more probes than one projection
		// batch) makes the bar follow the finished probes; each call draws the shadow maps once.
		const chunk = Math.max( 1, Math.min( SHProjector.batchCapacity( request.resolution ), Math.ceil( count / 20 ) ) );
		const captureStart = performance.now();
		try {

			progress( 'capturing', 0, count );
			for ( let start = 0; start < count; start += chunk ) {

				const end = Math.min( count, start + chunk );
				await capturer.capture( scene, request.positions.slice( 3 * start, 3 * end ), target, {}, 27 * start );
				progress( 'capturing', end, count );

			}

		} finally {

			capturer.dispose();

		}

		const captureMs = performance.now() - captureStart;
		renderer.dispose();
		return { sh: toBase64( target ), captureMs, loadMs, info };

	},

};

function toBase64( array: Float32Array ): string {

	const bytes = new Uint8Array( array.buffer, array.byteOffset, array.byteLength );
	let text = '';
	for ( let i = 0; i < bytes.length; i += 0x8000 ) text += String.fromCharCode( ...bytes.subarray( i, i + 0x8000 ) );
	return btoa( text );

}

( window as unknown as { bake: BakePageApi } ).bake = api;
( window as unknown as { bakeReady: boolean } ).bakeReady = true;
