import {
	Box3, DoubleSide, Sphere, Vector3,
	type BufferGeometry, type DirectionalLight, type Light, type LightShadow, type Material, type Mesh,
	type Object3D, type OrthographicCamera, type Side, type WebGLRenderer,
} from 'three';
import { assertRenderer, assertScene } from './captureSettings.js';
import { CAPTURE_SCENE_DEFAULTS } from './captureSceneDefaults.js';
import { assertInteger, assertNumber, assertOptionalBoolean, assertOptions } from '../validate.js';

/**
 * Options of {@link prepareCaptureScene}: what a bake changes in a scene before capturing it.
 * Every change can be switched off; the defaults are what `capture-lighting bake` does.
 */
export interface CaptureScenePreparation {

	/**
	 * Shadows on: every directional, point and spot light casts shadows, every mesh with a lit
	 * material casts and receives them, and the renderer draws shadow maps. A capture without
	 * them sees light through walls (glTF has no shadow flags). false changes nothing. Default true.
	 */
	shadows?: boolean;

	/** Shadow map edge in texels for every shadow-casting light (1..16384); null keeps each light's. Default 1024. */
	shadowMapSize?: number | null;

	/** `shadow.bias` of every shadow-casting light; null keeps each light's. Default −0.0005. */
	shadowBias?: number | null;

	/** Fits each directional light's orthographic shadow camera around the scene's lit meshes. Default true. */
	fitShadowCameras?: boolean;

	/**
	 * Lit materials render both faces into shadow maps (`shadowSide = DoubleSide`), so a single-sided
	 * wall facing the light still blocks it; lit faces then shadow themselves a little (acne, see
	 * `shadowBias`). Default false: three's rule, back faces only (closed meshes and rooms whose walls
	 * face inwards cast correct shadows).
	 */
	doubleSidedShadows?: boolean;

}

/** Kinds of lights {@link prepareCaptureScene} reports. */
export type CaptureLightKind = 'directional' | 'point' | 'spot' | 'rectArea' | 'hemisphere' | 'ambient' | 'probe';

/** What {@link prepareCaptureScene} found and changed; `restore()` undoes the changes. */
export interface PreparedCaptureScene {

	/** Visible meshes. */
	readonly meshes: number;

	/** Their triangles (instances counted). */
	readonly triangles: number;

	/** Vertex positions with a NaN or infinite coordinate (such geometry cannot be captured). */
	readonly nonFiniteVertices: number;

	/** The visible lights that give light (intensity > 0, colour not black), with their kind. */
	readonly lights: readonly { readonly light: Light; readonly kind: CaptureLightKind }[];

	/** Lit materials with an emissive colour (× intensity) above black. */
	readonly emissiveMaterials: number;

	/** Unlit materials (`MeshBasicMaterial` and the like) that are not black: they show in captures as light sources. */
	readonly unlitMaterials: number;

	/** Lights casting shadows after the preparation. */
	readonly shadowLights: number;

	/** Meshes whose `castShadow` / `receiveShadow` were turned on. */
	readonly shadowMeshes: number;

	/** Materials whose `shadowSide` was set to `DoubleSide`. */
	readonly doubleSidedMaterials: number;

	/**
	 * Puts back every property the preparation changed (light and mesh shadow flags, shadow map
	 * sizes, biases and cameras, materials' `shadowSide`, `renderer.shadowMap.enabled`) and asks the
	 * renderer to draw its shadow maps again. Calling it twice does nothing more.
	 */
	restore(): void;

}

type ShadowLight = Light & { shadow: LightShadow; castShadow: boolean };

const OPTION_KEYS = [ 'shadows', 'shadowMapSize', 'shadowBias', 'fitShadowCameras', 'doubleSidedShadows' ];
const MAX_SHADOW_MAP_SIZE = 16384;

// Reusable scratch for the bounds and the shadow-camera fit.
const meshBox = new Box3();
const lookTarget = new Vector3();
const sphereCentre = new Vector3();

/**
 * What a bake does to a scene before capturing it, in one call, so that a page capturing its own
 * scene (`volume.capture`) gets the SH `capture-lighting bake` writes: shadows on for every light and
 * lit mesh, shadow map size and bias, directional shadow cameras fitted to the scene, optionally both
 * faces in shadow maps. It also counts what it saw (meshes, triangles, lights by kind, emissive materials,
 * non-finite vertices). Meshes whose materials are all unlit (lamp bulbs, sky domes) are left as they
 * are, so they do not block the light they stand for. Call it once the scene is loaded and lit; call
 * `restore()` after the capture to give the game its own settings back.
 *
 * ```js
 * const prepared = prepareCaptureScene( renderer, scene );
 * await volume.capture( renderer, scene );
 * prepared.restore();
 * ```
 * @param options See {@link CaptureScenePreparation}; defaults as `capture-lighting bake`.
 * @throws {TypeError|RangeError} for a bad renderer, scene or option (nothing changed then).
 */
export function prepareCaptureScene(
	renderer: WebGLRenderer, scene: Object3D, options: CaptureScenePreparation = {},
): PreparedCaptureScene {

	const where = 'prepareCaptureScene';
	assertRenderer( where, renderer );
	assertScene( where, scene );
	const settings = checkPreparation( where, options );

	scene.updateMatrixWorld( true );
	const meshes: Mesh[] = [];
	const lights: { light: Light; kind: CaptureLightKind }[] = [];
	let meshCount = 0, triangles = 0, nonFiniteVertices = 0;
	const emissive = new Set<Material>(), unlit = new Set<Material>();
	scene.traverseVisible( ( object ) => {

		const mesh = object as Mesh;
		if ( mesh.isMesh ) {

			meshCount ++;
			const instanced = mesh as Mesh & { isInstancedMesh?: boolean; count?: number };
			const instances = instanced.isInstancedMesh ? instanced.count! : 1;
			triangles += instances * triangleCount( mesh.geometry );
			nonFiniteVertices += countNonFinite( mesh.geometry );
			let lit = false;
			for ( const material of materialsOf( mesh ) ) {

				if ( isLit( material ) ) {

					lit = true;
					if ( isEmissive( material ) ) emissive.add( material );

				} else if ( isVisibleUnlit( material ) ) {

					unlit.add( material );

				}

			}

			if ( lit ) meshes.push( mesh );

		}

		const light = object as Light;
		if ( light.isLight && givesLight( light ) ) lights.push( { light, kind: lightKind( light ) } );

	} );

	const restores: ( () => void )[] = [];
	let shadowLights = 0, shadowMeshes = 0, doubleSided = 0;
	const casters = lights.map( ( entry ) => entry.light ).filter( ( light ): light is ShadowLight => castsShadows( light ) );
	if ( settings.shadows && casters.length > 0 ) {

		const sphere = settings.fitShadowCameras ? litBounds( meshes, nonFiniteVertices ) : null;
		for ( const light of casters ) restores.push( prepareLight( light, settings, sphere ) );
		for ( const mesh of meshes ) restores.push( setFlags( mesh, true ) );
		if ( settings.doubleSidedShadows ) {

			const materials = new Set( meshes.flatMap( ( mesh ) => materialsOf( mesh ).filter( isLit ) ) );
			for ( const material of materials ) restores.push( setShadowSide( material, DoubleSide ) );
			doubleSided = materials.size;

		}

		const enabled = renderer.shadowMap.enabled;
		renderer.shadowMap.enabled = true;
		restores.push( () => { renderer.shadowMap.enabled = enabled; } );
		shadowLights = casters.length;
		shadowMeshes = meshes.length;

	} else {

		shadowLights = casters.filter( ( light ) => light.castShadow ).length;

	}

	let restored = false;
	return {
		meshes: meshCount, triangles, nonFiniteVertices, lights,
		emissiveMaterials: emissive.size, unlitMaterials: unlit.size,
		shadowLights, shadowMeshes, doubleSidedMaterials: doubleSided,
		restore() {

			if ( restored ) return;
			restored = true;
			for ( let i = restores.length - 1; i >= 0; i -- ) restores[ i ]();
			if ( restores.length > 0 ) renderer.shadowMap.needsUpdate = true;

		},
	};

}

/** The options with their defaults, checked. */
function checkPreparation( where: string, options: unknown ): Required<CaptureScenePreparation> {

	assertOptions( where, 'options', options );
	const o = ( options ?? {} ) as Record<string, unknown>;
	for ( const key of Object.keys( o ) ) {

		if ( ! OPTION_KEYS.includes( key ) ) throw new TypeError( `${where}: unknown option "${key}"; expected ${OPTION_KEYS.join( ', ' )}.` );

	}

	assertOptionalBoolean( where, 'options.shadows', o.shadows );
	assertOptionalBoolean( where, 'options.fitShadowCameras', o.fitShadowCameras );
	assertOptionalBoolean( where, 'options.doubleSidedShadows', o.doubleSidedShadows );
	const size = o.shadowMapSize === undefined ? CAPTURE_SCENE_DEFAULTS.shadowMapSize : o.shadowMapSize;
	if ( size !== null ) assertInteger( where, 'options.shadowMapSize', size, 1, MAX_SHADOW_MAP_SIZE );
	const bias = o.shadowBias === undefined ? CAPTURE_SCENE_DEFAULTS.shadowBias : o.shadowBias;
	if ( bias !== null ) assertNumber( where, 'options.shadowBias', bias );
	return {
		shadows: ( o.shadows ?? CAPTURE_SCENE_DEFAULTS.shadows ) as boolean,
		shadowMapSize: size as number | null,
		shadowBias: bias as number | null,
		fitShadowCameras: ( o.fitShadowCameras ?? CAPTURE_SCENE_DEFAULTS.fitShadowCameras ) as boolean,
		doubleSidedShadows: ( o.doubleSidedShadows ?? CAPTURE_SCENE_DEFAULTS.doubleSidedShadows ) as boolean,
	};

}

/** Turns one light's shadow on with the settings; returns how to undo it. */
function prepareLight( light: ShadowLight, settings: Required<CaptureScenePreparation>, sphere: Sphere | null ): () => void {

	const shadow = light.shadow;
	const castShadow = light.castShadow, bias = shadow.bias;
	const width = shadow.mapSize.x, height = shadow.mapSize.y;
	light.castShadow = true;
	if ( settings.shadowBias !== null ) shadow.bias = settings.shadowBias;
	if ( settings.shadowMapSize !== null ) setMapSize( shadow, settings.shadowMapSize, settings.shadowMapSize );
	let camera: number[] | null = null;
	const directional = ( light as DirectionalLight ).isDirectionalLight === true;
	if ( directional && sphere ) {

		const c = shadow.camera as OrthographicCamera;
		camera = [ c.left, c.right, c.top, c.bottom, c.near, c.far ];
		fitShadowCamera( light as DirectionalLight, sphere );

	}

	return () => {

		light.castShadow = castShadow;
		shadow.bias = bias;
		setMapSize( shadow, width, height );
		if ( camera ) {

			const c = shadow.camera as OrthographicCamera;
			[ c.left, c.right, c.top, c.bottom, c.near, c.far ] = camera;
			c.updateProjectionMatrix();

		}

	};

}

/** three keeps a shadow map at the size it was made with: a new size needs a new map. */
function setMapSize( shadow: LightShadow, width: number, height: number ): void {

	if ( shadow.mapSize.x === width && shadow.mapSize.y === height ) return;
	shadow.mapSize.set( width, height );
	if ( shadow.map ) {

		shadow.map.dispose();
		shadow.map = null;

	}

}

function setFlags( mesh: Mesh, on: boolean ): () => void {

	const cast = mesh.castShadow, receive = mesh.receiveShadow;
	mesh.castShadow = mesh.receiveShadow = on;
	return () => {

		mesh.castShadow = cast;
		mesh.receiveShadow = receive;

	};

}

function setShadowSide( material: Material, side: Side ): () => void {

	const previous = material.shadowSide;
	material.shadowSide = side;
	return () => { material.shadowSide = previous; };

}

/**
 * The bounding sphere of the lit meshes (what shadows fall on); a unit sphere at the origin
 * when there are none or their geometry is not finite.
 */
function litBounds( meshes: readonly Mesh[], nonFiniteVertices: number ): Sphere {

	const box = new Box3();
	if ( nonFiniteVertices === 0 ) {

		for ( const mesh of meshes ) {

			const instanced = mesh as Mesh & { isInstancedMesh?: boolean; boundingBox?: Box3 | null; computeBoundingBox?: () => void };
			if ( instanced.isInstancedMesh ) {

				if ( ! instanced.boundingBox ) instanced.computeBoundingBox!();
				meshBox.copy( instanced.boundingBox! );

			} else {

				if ( ! mesh.geometry.boundingBox ) mesh.geometry.computeBoundingBox();
				meshBox.copy( mesh.geometry.boundingBox! );

			}

			box.union( meshBox.applyMatrix4( mesh.matrixWorld ) );

		}

	}

	const sphere = box.isEmpty() ? new Sphere( new Vector3(), 1 ) : box.getBoundingSphere( new Sphere() );
	sphere.radius = Math.max( sphere.radius, 1e-3 );
	return sphere;

}

/** Fits a directional light's orthographic shadow camera around a sphere, in the frame three renders it from. */
function fitShadowCamera( light: DirectionalLight, sphere: Sphere ): void {

	light.updateMatrixWorld( true );
	light.target.updateMatrixWorld( true );
	const camera = light.shadow.camera;
	camera.position.setFromMatrixPosition( light.matrixWorld );
	camera.lookAt( lookTarget.setFromMatrixPosition( light.target.matrixWorld ) );
	camera.updateMatrixWorld( true );
	const c = sphereCentre.copy( sphere.center ).applyMatrix4( camera.matrixWorldInverse );
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

function materialsOf( mesh: Mesh ): Material[] {

	return Array.isArray( mesh.material ) ? mesh.material : mesh.material ? [ mesh.material ] : [];

}

/** Materials shaded by lights (and so by shadows). */
function isLit( material: Material ): boolean {

	const m = material as Material & Record<string, unknown>;
	return m.isMeshStandardMaterial === true || m.isMeshPhongMaterial === true || m.isMeshLambertMaterial === true
		|| m.isMeshToonMaterial === true || ( m.isShaderMaterial === true && m.lights === true );

}

function isEmissive( material: Material ): boolean {

	const m = material as Material & { emissive?: { r: number; g: number; b: number }; emissiveIntensity?: number };
	if ( ! m.emissive ) return false;
	return ( m.emissiveIntensity ?? 1 ) > 0 && m.emissive.r + m.emissive.g + m.emissive.b > 0;

}

/** An unlit material a camera sees as not black (a lamp's bulb, a sky dome). */
function isVisibleUnlit( material: Material ): boolean {

	const m = material as Material & { isMeshBasicMaterial?: boolean; color?: { r: number; g: number; b: number } };
	return m.isMeshBasicMaterial === true && m.visible && !! m.color && m.color.r + m.color.g + m.color.b > 0;

}

function givesLight( light: Light ): boolean {

	if ( ! ( light.intensity > 0 ) ) return false;
	const probe = light as Light & { isLightProbe?: boolean; sh?: { coefficients: { x: number; y: number; z: number }[] } };
	if ( probe.isLightProbe ) return probe.sh!.coefficients.some( ( c ) => c.x !== 0 || c.y !== 0 || c.z !== 0 );
	return light.color.r + light.color.g + light.color.b > 0;

}

function lightKind( light: Light ): CaptureLightKind {

	const l = light as Light & Record<string, unknown>;
	if ( l.isDirectionalLight ) return 'directional';
	if ( l.isSpotLight ) return 'spot';
	if ( l.isPointLight ) return 'point';
	if ( l.isRectAreaLight ) return 'rectArea';
	if ( l.isHemisphereLight ) return 'hemisphere';
	if ( l.isLightProbe ) return 'probe';
	return 'ambient';

}

function castsShadows( light: Light ): light is ShadowLight {

	const l = light as Light & Record<string, unknown>;
	return ( l.isDirectionalLight === true || l.isSpotLight === true || l.isPointLight === true ) && !! l.shadow;

}

function triangleCount( geometry: BufferGeometry ): number {

	const count = geometry.index ? geometry.index.count : geometry.getAttribute( 'position' )?.count ?? 0;
	return Math.floor( count / 3 );

}

function countNonFinite( geometry: BufferGeometry ): number {

	const position = geometry.getAttribute( 'position' );
	if ( ! position ) return 0;
	let bad = 0;
	for ( let i = 0; i < position.count; i ++ ) {

		if ( ! Number.isFinite( position.getX( i ) + position.getY( i ) + position.getZ( i ) ) ) bad ++;

	}

	return bad;

}
