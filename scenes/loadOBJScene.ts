import * as THREE from 'three';
import { MTLLoader } from 'three/addons/loaders/MTLLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';

/** What a scene's `build` needs from the demo (a `Viewer` is one). */
export interface SceneHost {

	scene: THREE.Scene;
	/** A WebGLRenderer or a WebGPURenderer: what a scene sets is their common shadow-map switch. */
	renderer: { shadowMap: { enabled: boolean; type: THREE.ShadowMapType } };
	/** Base URL of the asset folder, ending in '/'. */
	assets: string;
	overlay: { progress( text: string, fraction: number ): void };

}

/** Options of {@link loadOBJScene}. */
export interface OBJSceneOptions {

	/** Folder URL of the OBJ, its MTL and textures, ending in '/' (e.g. `app.assets + 'sponza/'`). */
	url: string;

	/** OBJ file name in that folder. */
	obj: string;

	/** MTL file name; default: the OBJ's `mtllib` line. */
	mtl?: string;

	/** Roughness of every converted material. Default 0.9. */
	roughness?: number;

	/** Scale of the MTL bump (height) maps. Default 1. */
	bumpScale?: number;

	/**
	 * A faint emission equal to `ambient` × the diffuse colour (and texture) of every surface: the
	 * stand-in for the static scene's baked lighting, so shade is not black. Probes capture it like
	 * any other light. Default 0.
	 */
	ambient?: number;

	/** Texture anisotropy (e.g. `renderer.capabilities.getMaxAnisotropy()`). Default 1. */
	anisotropy?: number;

	/** One sentence saying where to get the files; appended to the error when one is missing. */
	source?: string;

	/** Progress: what is loading and the fraction done, 0..1. */
	onProgress?: ( text: string, fraction: number ) => void;

	/** Last word on each converted material (e.g. make stained glass glow). */
	onMaterial?: ( material: THREE.MeshStandardMaterial, info: Record<string, unknown> ) => void;

}

/** What {@link loadOBJScene} returns. */
export interface OBJScene {

	/** The model: meshes with `MeshStandardMaterial`s, casting and receiving shadows. */
	object: THREE.Group;

	/** The converted materials by MTL name. */
	materials: Map<string, THREE.MeshStandardMaterial>;

}

/**
 * Loads an OBJ + MTL scene (Sponza, Sibenik) from a folder URL with its textures, and converts the
 * MTL's Phong materials to `MeshStandardMaterial` (colour, diffuse map in sRGB, bump map, emission,
 * opacity; roughness ~0.9) so the model is lit like the rest of three.js's physically based scene.
 *
 * Texture names are looked up as written, then with the extension's case swapped (.JPG / .jpg),
 * because servers on Linux are case-sensitive. A missing OBJ, MTL or texture throws an Error naming
 * the file and its URL.
 */
export async function loadOBJScene( options: OBJSceneOptions ): Promise<OBJScene> {

	const { url, roughness = 0.9, bumpScale = 1, ambient = 0, anisotropy = 1, onProgress = () => {} } = options;
	const missing = ( file: string, why: string ) => new Error( `Missing asset ${file} (${why}).${options.source ? ' ' + options.source : ''}` );

	// 1. The OBJ text (most of the download): 0 … 0.6.
	const objText = await fetchText( url + options.obj, ( fraction ) => onProgress( `loading ${options.obj}…`, 0.6 * fraction ), missing );

	// 2. The MTL, named by the OBJ's mtllib line unless given.
	const mtlName = options.mtl ?? /^mtllib\s+(.+?)\s*$/m.exec( objText )?.[ 1 ];
	if ( ! mtlName ) throw new Error( `loadOBJScene: ${options.obj} names no material library (mtllib) and options.mtl is not set.` );
	const mtlText = await fetchText( url + mtlName, () => {}, missing );
	const creator = new MTLLoader().parse( mtlText, url );
	const infos = creator.materialsInfo as Record<string, Record<string, unknown>>;

	// 3. The textures, each file once: 0.6 … 0.9.
	const files = new Set<string>();
	const textureFile = ( value: unknown ) => typeof value === 'string' && value !== '' ? creator.getTextureParams( value, {} ).url : '';
	for ( const info of Object.values( infos ) ) {

		for ( const key of [ 'map_kd', 'map_bump', 'bump' ] ) if ( textureFile( info[ key ] ) ) files.add( textureFile( info[ key ] ) );

	}

	const images = new Map<string, HTMLImageElement | ImageBitmap>();
	let done = 0;
	await Promise.all( [ ...files ].map( async ( file ) => {

		images.set( file, await loadImage( url, file, missing ) );
		onProgress( `loading textures… ${++ done} / ${files.size}`, 0.6 + 0.3 * done / files.size );

	} ) );

	const textures = new Map<string, THREE.Texture>();
	const texture = ( file: string, colorSpace: THREE.ColorSpace ) => {

		const key = `${file}|${colorSpace}`;
		let map = textures.get( key );
		if ( ! map ) {

			map = new THREE.Texture( images.get( file ) as HTMLImageElement );
			map.name = file;
			map.colorSpace = colorSpace;
			map.wrapS = map.wrapT = THREE.RepeatWrapping;
			map.anisotropy = anisotropy;
			map.needsUpdate = true;
			textures.set( key, map );

		}

		return map;

	};

	// 4. Phong (MTL) → MeshStandardMaterial.
	const materials = new Map<string, THREE.MeshStandardMaterial>();
	for ( const [ name, info ] of Object.entries( infos ) ) {

		const material = new THREE.MeshStandardMaterial( { name, roughness, metalness: 0 } );
		const kd = info.kd as number[] | undefined;
		if ( kd ) material.color.setRGB( kd[ 0 ], kd[ 1 ], kd[ 2 ], THREE.SRGBColorSpace );
		const ke = info.ke as number[] | undefined;
		if ( ke ) material.emissive.setRGB( ke[ 0 ], ke[ 1 ], ke[ 2 ], THREE.SRGBColorSpace );
		const map = textureFile( info.map_kd );
		if ( map ) material.map = texture( map, THREE.SRGBColorSpace );
		const bump = textureFile( info.map_bump ) || textureFile( info.bump );
		if ( bump ) {

			material.bumpMap = texture( bump, THREE.NoColorSpace );
			material.bumpScale = bumpScale;

		}

		const opacity = info.d !== undefined ? parseFloat( info.d as string ) : 1;
		if ( opacity < 1 ) { material.opacity = opacity; material.transparent = true; }
		if ( ambient > 0 && material.emissive.getHex() === 0 ) {

			material.emissive.copy( material.color ).multiplyScalar( ambient );
			material.emissiveMap = material.map;
			// Marked so that a multi-bounce capture can switch the stand-in off: bounces replace it.
			material.userData.ambientStandIn = true;

		}

		// Single-sided walls and roofs must still block the sun: render both sides into shadow maps.
		material.shadowSide = THREE.DoubleSide;
		options.onMaterial?.( material, info );
		materials.set( name, material );

	}

	// 5. The geometry: 0.9 … 1.
	onProgress( `parsing ${options.obj}…`, 0.9 );
	await new Promise( ( resolve ) => setTimeout( resolve, 0 ) ); // let the progress bar paint
	const object = new OBJLoader().parse( objText );
	object.name = options.obj;
	object.traverse( ( child ) => {

		const mesh = child as THREE.Mesh;
		if ( ! mesh.isMesh ) return;
		const swap = ( placeholder: THREE.Material ) => {

			const material = materials.get( placeholder.name );
			if ( ! material ) throw new Error( `loadOBJScene: ${options.obj} uses material "${placeholder.name}", which ${mtlName} does not define.` );
			placeholder.dispose();
			return material;

		};

		mesh.material = Array.isArray( mesh.material ) ? mesh.material.map( swap ) : swap( mesh.material );
		mesh.castShadow = mesh.receiveShadow = true;

	} );
	onProgress( '', 1 );
	return { object, materials };

}

/** Fetches a text file with download progress; a 404 (or an HTML fallback page) is a missing file. */
async function fetchText(
	url: string, onProgress: ( fraction: number ) => void, missing: ( file: string, why: string ) => Error
): Promise<string> {

	let response: Response;
	try {

		response = await fetch( url );

	} catch ( error ) {

		throw missing( url, `fetch failed: ${( error as Error ).message}` );

	}

	if ( ! response.ok ) throw missing( url, `HTTP ${response.status}` );
	const total = Number( response.headers.get( 'Content-Length' ) ?? 0 );
	let text: string;
	if ( response.body && total > 0 ) {

		const reader = response.body.getReader();
		const chunks: Uint8Array[] = [];
		let loaded = 0;
		for ( ;; ) {

			const { done, value } = await reader.read();
			if ( done ) break;
			chunks.push( value );
			loaded += value.length;
			onProgress( Math.min( 1, loaded / total ) );

		}

		text = await new Blob( chunks as BlobPart[] ).text();

	} else {

		text = await response.text();

	}

	// A dev server without the asset folder may answer with its index page instead of a 404.
	if ( /^\s*<(!doctype|html)/i.test( text ) ) throw missing( url, 'the server answered with an HTML page' );
	onProgress( 1 );
	return text;

}

/** Loads an image by its name in the MTL, trying the other case of its extension when that fails. */
async function loadImage( base: string, file: string, missing: ( file: string, why: string ) => Error ): Promise<HTMLImageElement> {

	const extension = /\.[^.]+$/.exec( file )?.[ 0 ] ?? '';
	const stem = file.slice( 0, file.length - extension.length );
	const candidates = [ ...new Set( [ file, stem + extension.toLowerCase(), stem + extension.toUpperCase() ] ) ];
	const loader = new THREE.ImageLoader();
	for ( const candidate of candidates ) {

		try {

			return await loader.loadAsync( base + candidate );

		} catch {

			// try the next spelling

		}

	}

	throw missing( base + file, candidates.length > 1 ? `tried ${candidates.join( ', ' )}` : 'not found' );

}

/** Options of {@link createSky}: colours as hex (sRGB), radiance scale. */
export interface SkyOptions { zenith: number; horizon: number; ground: number; intensity: number; radius?: number }

/**
 * A sky the probes can capture: a big unlit dome of sky radiance (zenith → horizon gradient, dark
 * ground below), since three's HemisphereLight lights objects but is never seen by a cube camera.
 */
export function createSky( { zenith, horizon, ground, intensity, radius = 200 }: SkyOptions ): THREE.Mesh {

	const geometry = new THREE.SphereGeometry( radius, 48, 24 );
	const normals = geometry.getAttribute( 'normal' );
	const colors = new Float32Array( 3 * normals.count );
	const top = new THREE.Color( zenith ), middle = new THREE.Color( horizon ), bottom = new THREE.Color( ground ),
		color = new THREE.Color();
	for ( let i = 0; i < normals.count; i ++ ) {

		const y = normals.getY( i );
		if ( y >= 0 ) color.lerpColors( middle, top, Math.pow( y, 0.6 ) ); else color.lerpColors( middle, bottom, Math.min( 1, - y * 8 ) );
		color.multiplyScalar( intensity ).toArray( colors, 3 * i );

	}

	geometry.setAttribute( 'color', new THREE.BufferAttribute( colors, 3 ) );
	const sky = new THREE.Mesh(
		geometry,
		new THREE.MeshBasicMaterial( { vertexColors: true, side: THREE.BackSide, depthWrite: false, fog: false } )
	);
	sky.name = 'sky';
	sky.renderOrder = - 1;
	return sky;

}

/** Options of {@link addStaticSun}. */
export interface StaticSunOptions {

	/** Direction towards the sun (normalized). */
	direction: THREE.Vector3;
	color: number;
	intensity: number;
	/** Half-size of the square shadow frustum, in scene units; it must cover the model. */
	extent: number;
	/** Shadow map size in texels. Default 2048. */
	mapSize?: number;

}

/**
 * A shadow-casting sun over the model. The shadow map keeps three.js's defaults: redrawn every
 * frame, so the moving character casts a shadow too; probe captures draw it once per capture
 * (`ProbeCapturer` does, and restores the renderer's settings after).
 */
export function addStaticSun(
	app: SceneHost, { direction, color, intensity, extent, mapSize = 2048 }: StaticSunOptions
): THREE.DirectionalLight {

	const sun = new THREE.DirectionalLight( color, intensity );
	sun.position.copy( direction ).multiplyScalar( 2 * extent );
	sun.castShadow = true;
	sun.shadow.mapSize.set( mapSize, mapSize );
	Object.assign( sun.shadow.camera, {
		left: - extent, right: extent, top: extent, bottom: - extent, near: 0.1 * extent, far: 4 * extent
	} );
	sun.shadow.bias = - 0.0005;
	sun.shadow.normalBias = 0.03;
	app.scene.add( sun, sun.target );

	app.renderer.shadowMap.enabled = true;
	// r187's PCF filter is the soft one (a rotated disc of samples, `shadow.radius` wide); PCFSoftShadowMap was removed.
	app.renderer.shadowMap.type = THREE.PCFShadowMap;
	return sun;

}

/**
 * The renderer's highest texture anisotropy: `capabilities.getMaxAnisotropy()` on a
 * WebGLRenderer, `getMaxAnisotropy()` on a WebGPURenderer (which has no `capabilities`).
 */
export function maxAnisotropy( renderer: unknown ): number {

	const r = renderer as { capabilities?: { getMaxAnisotropy(): number }; getMaxAnisotropy?(): number };
	return r.capabilities?.getMaxAnisotropy() ?? r.getMaxAnisotropy?.() ?? 1;

}
