/**
 * The GPU half of `capture-lighting bake`: loads the scene file (glTF/GLB with its
 * KHR_lights_punctual lights, or OBJ + MTL), adds the sky, sun and ambient light asked for, and
 * captures SH9 at every probe with the library's `ProbeCapturer`. Node (cli/capture.ts) opens this
 * page in headless Chromium and calls `window.bake.run`; progress goes back through the function
 * Node exposes as `PROGRESS_FUNCTION`. Textures are decoded here because Node loaders cannot.
 */

import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { HDRLoader } from 'three/addons/loaders/HDRLoader.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { SHProjector } from '../../src/capture/SHProjector.js';
import { loadOBJScene } from '../../scenes/loadOBJScene.js';
import { PROGRESS_FUNCTION, type BakePageApi, type BakeRequest, type BakeResult } from './protocol.js';

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
		const model = request.kind === 'gltf' ? await loadGLTF( request.sceneUrl ) : await loadOBJ( request.sceneUrl );
		scene.add( model );

		if ( request.sky && 'color' in request.sky ) {

			const [ r, g, b ] = request.sky.color;
			scene.background = new THREE.Color().setRGB( r, g, b, THREE.SRGBColorSpace );

		} else if ( request.sky ) {

			const texture = await new HDRLoader().loadAsync( request.sky.hdrUrl );
			texture.mapping = THREE.EquirectangularReflectionMapping;
			scene.background = texture;

		}

		if ( request.ambient > 0 ) scene.add( new THREE.AmbientLight( 0xffffff, request.ambient ) );

		scene.updateMatrixWorld( true );
		const bounds = new THREE.Box3();
		model.traverse( ( object ) => {

			if ( ( object as THREE.Mesh ).isMesh ) bounds.expandByObject( object );

		} );
		const sphere = bounds.isEmpty() ? new THREE.Sphere( new THREE.Vector3(), 1 ) : bounds.getBoundingSphere( new THREE.Sphere() );
		sphere.radius = Math.max( sphere.radius, 1e-3 );

		if ( request.sun ) {

			const sun = new THREE.DirectionalLight( 0xffffff, request.sun.intensity );
			sun.name = 'sun';
			sun.position.fromArray( request.sun.direction ).normalize().multiplyScalar( 2 * sphere.radius ).add( sphere.center );
			sun.target.position.copy( sphere.center );
			sun.castShadow = true;
			scene.add( sun, sun.target );

		}

		// Every light casts shadows and every mesh casts and receives them: a capture must not see
		// light through walls. The scene is static, so the shadow maps are drawn once.
		let lights = 0, meshes = 0, triangles = 0, nonFiniteVertices = 0, shadows = false;
		scene.updateMatrixWorld( true );
		scene.traverse( ( object ) => {

			const mesh = object as THREE.Mesh;
			if ( mesh.isMesh ) {

				meshes ++;
				mesh.castShadow = mesh.receiveShadow = true;
				const geometry = mesh.geometry;
				triangles += ( geometry.index ? geometry.index.count : geometry.getAttribute( 'position' )?.count ?? 0 ) / 3;
				const position = geometry.getAttribute( 'position' );
				if ( position ) {

					for ( let i = 0; i < position.count; i ++ ) {

						if ( ! Number.isFinite( position.getX( i ) + position.getY( i ) + position.getZ( i ) ) ) nonFiniteVertices ++;

					}

				}

			}

			const light = object as THREE.Light;
			if ( ! light.isLight || ( light as THREE.AmbientLight ).isAmbientLight ||
				( light as THREE.HemisphereLight ).isHemisphereLight ) return;
			lights ++;
			const caster = light as THREE.DirectionalLight | THREE.SpotLight | THREE.PointLight;
			if ( ! caster.shadow ) return;
			caster.castShadow = true;
			caster.shadow.mapSize.set( 2048, 2048 );
			caster.shadow.bias = - 0.0005;
			if ( ( caster as THREE.DirectionalLight ).isDirectionalLight ) fitShadowCamera( caster as THREE.DirectionalLight, sphere );
			shadows = true;

		} );
		renderer.shadowMap.enabled = shadows;
		renderer.shadowMap.autoUpdate = false;
		renderer.shadowMap.needsUpdate = true;
		const loadMs = performance.now() - loadStart;
		progress( 'loading', 1, 1 );
		const gl = renderer.getContext();
		const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
		const info = {
			renderer: debug ? String( gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) ) : String( gl.getParameter( gl.RENDERER ) ),
			meshes, triangles: Math.round( triangles ), lights, shadows, nonFiniteVertices,
		};
		// Nothing to capture (no geometry and no sky), or geometry no capture can render: the CLI
		// reports it as bad input. A sky alone is a valid bake (an outdoor probe set).
		if ( ( info.triangles === 0 && ! request.sky ) || nonFiniteVertices > 0 ) {

			renderer.dispose();
			return { sh: '', captureMs: 0, loadMs, info };

		}

		const count = request.positions.length / 3;
		const capturer = new ProbeCapturer( renderer, {
			resolution: request.resolution, near: request.near, far: request.far, type: THREE.HalfFloatType
		} );
		const target = new Float32Array( 27 * count );
		// ProbeCapturer reports probes as submitted; the GPU finishes them at the read-back that ends
		// each call. Capturing in chunks (at most ~100 read-backs, never more probes than one
		// projection batch) makes the bar follow the finished probes, not the submitted ones.
		const chunk = Math.max( 1, Math.min( SHProjector.batchCapacity( request.resolution ), Math.ceil( count / 100 ) ) );
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

async function loadGLTF( url: string ): Promise<THREE.Object3D> {

	const gltf = await new GLTFLoader().loadAsync( url, ( event ) => {

		if ( event.total > 0 ) progress( 'loading', event.loaded, event.total );

	} );
	return gltf.scene;

}

async function loadOBJ( url: string ): Promise<THREE.Object3D> {

	const slash = url.lastIndexOf( '/' ) + 1;
	const folder = url.slice( 0, slash ), file = url.slice( slash );
	const response = await fetch( url );
	if ( ! response.ok ) throw new Error( `cannot load ${decodeURIComponent( file )} (HTTP ${response.status})` );
	const text = await response.text();
	if ( /^mtllib\s+\S/m.test( text ) ) {

		// Colours, textures and emission of the MTL, as MeshStandardMaterials (the demo scenes' loader).
		const { object } = await loadOBJScene( { url: folder, obj: file, onProgress: ( _text, fraction ) => progress( 'loading', fraction, 1 ) } );
		return object;

	}

	// No material library: a light grey, rough default.
	const object = new OBJLoader().parse( text );
	const material = new THREE.MeshStandardMaterial( { color: 0xcccccc, roughness: 0.9, metalness: 0 } );
	object.traverse( ( child ) => {

		if ( ( child as THREE.Mesh ).isMesh ) ( child as THREE.Mesh ).material = material;

	} );
	return object;

}

/** Fits a directional light's orthographic shadow camera around the scene's bounding sphere. */
function fitShadowCamera( light: THREE.DirectionalLight, sphere: THREE.Sphere ): void {

	light.updateMatrixWorld( true );
	light.target.updateMatrixWorld( true );
	const camera = light.shadow.camera;
	camera.position.setFromMatrixPosition( light.matrixWorld );
	camera.lookAt( new THREE.Vector3().setFromMatrixPosition( light.target.matrixWorld ) );
	camera.updateMatrixWorld( true );
	const c = sphere.center.clone().applyMatrix4( camera.matrixWorldInverse );
	const r = sphere.radius;
	camera.left = c.x - r;
	camera.right = c.x + r;
	camera.bottom = c.y - r;
	camera.top = c.y + r;
	// The camera looks down −z; an orthographic near plane may lie behind it.
	camera.near = - c.z - r;
	camera.far = - c.z + r;
	camera.updateProjectionMatrix();

}

function toBase64( array: Float32Array ): string {

	const bytes = new Uint8Array( array.buffer, array.byteOffset, array.byteLength );
	let text = '';
	for ( let i = 0; i < bytes.length; i += 0x8000 ) text += String.fromCharCode( ...bytes.subarray( i, i + 0x8000 ) );
	return btoa( text );

}

( window as unknown as { bake: BakePageApi } ).bake = api;
( window as unknown as { bakeReady: boolean } ).bakeReady = true;
