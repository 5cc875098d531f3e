/**
 * The bake page's loaders: three's own, used as a page uses them, so the bake sees the materials
 * a game that loads the same file sees. glTF/GLB: `GLTFLoader` (KHR_lights_punctual lights and
 * emissive materials included). OBJ: `MTLLoader` + `OBJLoader` (MeshPhongMaterials from the MTL);
 * without an mtllib line, `OBJLoader`'s own default material (vertex colours when the file has
 * them). Textures are waited for, and one that cannot be loaded is an error naming it.
 */

import { LoadingManager, type Object3D } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MTLLoader } from 'three/addons/loaders/MTLLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';

/** Progress of a load: the fraction done, 0..1. */
export type LoadProgress = ( fraction: number ) => void;

/** Loads a glTF/GLB file; the model is the loaded `gltf.scene`. */
export async function loadGLTF( url: string, onProgress: LoadProgress ): Promise<Object3D> {

	const textures = new TextureWait();
	const gltf = await new GLTFLoader( textures.manager ).loadAsync( url, ( event ) => {

		if ( event.total > 0 ) onProgress( event.loaded / event.total );

	} );
	await textures.done();
	return gltf.scene;

}

/** Loads an OBJ file and the MTL its mtllib line names (from the same folder). */
export async function loadOBJ( url: string, onProgress: LoadProgress ): Promise<Object3D> {

	const slash = url.lastIndexOf( '/' ) + 1;
	const folder = url.slice( 0, slash ), file = url.slice( slash );
	const response = await fetch( url );
	if ( ! response.ok ) throw new Error( `cannot load ${decodeURIComponent( file )} (HTTP ${response.status})` );
	const text = await response.text();
	onProgress( 0.5 );
	const loader = new OBJLoader();
	const textures = new TextureWait();
	const mtl = /^mtllib\s+(.+?)\s*$/m.exec( text )?.[ 1 ];
	if ( mtl ) {

		const materials = await new MTLLoader( textures.manager ).setPath( folder ).loadAsync( mtl );
		materials.preload();
		loader.setMaterials( materials );

	}

	const object = loader.parse( text );
	await textures.done();
	onProgress( 1 );
	return object;

}

/** Counts the textures a loader starts through its manager and waits for all of them. */
class TextureWait {

	readonly manager = new LoadingManager();
	private pending = 0;
	private readonly failed: string[] = [];
	private wake: ( () => void ) | null = null;

	constructor() {

		this.manager.itemStart = () => {

			this.pending ++;

		};

		this.manager.itemEnd = () => {

			this.pending --;
			if ( this.pending === 0 ) this.wake?.();

		};

		this.manager.itemError = ( url ) => {

			this.failed.push( decodeURIComponent( url.slice( url.lastIndexOf( '/' ) + 1 ) ) );

		};

	}

	/** Resolves once nothing is loading; throws naming the files that failed. */
	async done(): Promise<void> {

		if ( this.pending > 0 ) await new Promise<void>( ( resolve ) => { this.wake = resolve; } );
		if ( this.failed.length > 0 ) throw new Error( `cannot load ${this.failed.join( ', ' )} (named by the scene; not found next to it)` );

	}

}
