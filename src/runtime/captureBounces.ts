import { Layers, type BufferGeometry, type Material, type Mesh, type Object3D, type Scene } from 'three';
import type { CaptureRenderer } from '../capture/captureSettings.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { SH_FLOATS, assertInteger } from '../validate.js';
import { CAPTURE_ACCESS, applyCapturedProbes, captureProbes, type CaptureAccess, type CapturedProbes } from './captureProbes.js';
import { checkCaptureOptions } from './checkCaptureOptions.js';
import type { LightProbeVolume } from './LightProbeVolume.js';
import type { LightProbeVolumeCaptureOptions } from './LightProbeVolumeOptions.js';
import type { ProbeField } from './ProbeField.js';
import { ProbeVertexLighting } from './ProbeVertexLighting.js';
import { probeUniformsOf } from './nodeMaterialHooks.js';
import { PROBE_LIT_MATERIALS, meshMaterials, takesProbeLight } from './probeLitMaterials.js';

/**
 * Options of {@link captureBounces}: the capture options of `LightProbeVolume.capture`, whose
 * bounce options (`staticMeshes`, `hideInBounces`, `output`, `onPass`) apply, with `bounces` required.
 */
export type CaptureBouncesOptions = LightProbeVolumeCaptureOptions & {

	/** Bounces of diffuse interreflection to add, 0..16: `bounces + 1` captures in all. */
	bounces: number;

};

/** Statistics of one pass of {@link captureBounces}. */
export interface BouncePass {

	/** 0: direct light only; k: direct + k bounces. */
	pass: number;

	/** Mean L00 coefficient (r, g, b) over the captured probes (mean radiance = L00 × 0.282095). */
	meanL00: [ number, number, number ];

	/** Milliseconds of the capture. */
	captureMs: number;

	/** Milliseconds spent sampling the probe field at the static meshes' vertices before the capture (0 in pass 0). */
	lightingMs: number;

}

/** What {@link captureBounces} returns. */
export interface CaptureBouncesResult {

	/** One entry per pass, pass 0 first; the volume's SH are the last pass's. */
	passes: BouncePass[];

	/** The static meshes that were lit during the bounce passes. */
	staticMeshes: Mesh[];

	/** Their vertices (sampled once per bounce pass). */
	vertices: number;

	/** Milliseconds in all. */
	totalMs: number;

}

const MAX_BOUNCES = 16;

/**
 * Captures a volume's probes with bounced light: pass 0 is the ordinary capture (the light the
 * scene's lights and emissive surfaces give directly); each further pass lights the static meshes
 * with the previous pass's probes — sampled at every vertex through {@link ProbeVertexLighting},
 * from a frozen copy of that pass's SH — and captures every probe again, so pass k holds direct
 * light plus k bounces of diffuse interreflection, as far as per-vertex sampling of the probe
 * field resolves it (light varies linearly across each triangle; the field is the volume's
 * interpolator alone: zones and the visibility guard are not applied to the vertices). Each bounce
 * multiplies the added light by roughly the scene's mean albedo, so 2–3 bounces usually get
 * within a few per cent of the converged value.
 *
 * The passes work on a staged copy of the SH: the volume receives the last pass (SH, dirty set,
 * capture settings) only when every pass succeeded, so a capture that throws — a lost context, a
 * throwing callback — leaves the volume exactly as it was. The static meshes keep their own look
 * (colour, maps, emission): their materials are replaced by patched clones that add the probe
 * light to three's indirect diffuse term; geometries are cloned for the bounce passes, so no user
 * geometry is touched. Everything is restored when it returns, also when it throws.
 *
 * Stand-ins for indirect light the scene already has (an `AmbientLight` or `HemisphereLight` fill,
 * a faint emissive glow on every surface) would be counted twice: turn them off, or pass them in
 * `hideInBounces` so the bounces replace them from pass 1 on.
 *
 * `volume.capture( renderer, scene, { bounces: 2, … } )` does the same and returns the volume;
 * this function also returns the statistics of each pass.
 *
 * ```js
 * scene.remove( fill ); // the hemisphere light that stood in for bounced light
 * const { passes } = await captureBounces( volume, renderer, scene, { bounces: 2, resolution: 32 } );
 * ```
 *
 * @param volume The probes; its `sh` receive the last pass.
 * @param renderer A WebGL2 renderer, or a WebGPURenderer (with `three-capture-lighting/webgpu` imported).
 * @param scene The scene to capture.
 * @param options See {@link CaptureBouncesOptions}.
 */
export function captureBounces(
	volume: LightProbeVolume, renderer: CaptureRenderer, scene: Scene, options: CaptureBouncesOptions,
): Promise<CaptureBouncesResult> {

	return captureWithBounces( 'captureBounces', volume, renderer, scene, options );

}

/**
 * `LightProbeVolume.capture` and `recaptureDirty`, with errors naming `where`: one capture, or
 * {@link captureWithBounces} when `options.bounces` is given. All or nothing: the volume changes
 * only when everything was captured.
 */
export async function captureVolume(
	where: string, volume: LightProbeVolume, renderer: CaptureRenderer, scene: Scene, options: LightProbeVolumeCaptureOptions,
): Promise<void> {

	if ( options?.bounces !== undefined ) {

		await captureWithBounces( where, volume, renderer, scene, { ...options, bounces: options.bounces } );
		return;

	}

	const access = accessOf( where, volume );
	const { indices, exclude } = checkCaptureOptions( where, volume, renderer, scene, options );
	const fitting = await loadFitting( volume, access, options.fit );
	const plan = fitting?.planFit( where, volume, access, options, scene, hiddenObjects( access, exclude ) ) ?? null;
	if ( indices.length === 0 && plan?.mode !== 'refit' ) return;
	const points = plan?.points ?? null;
	const captured = indices.length > 0 || points !== null
		? await captureProbes( volume, access.lit, indices, renderer, scene, { ...options, exclude }, null, points )
		: null;
	if ( fitting !== null ) fitting.commitWithFit( plan!, volume, access, captured );
	else if ( captured !== null ) access.commit( captured );

}

/** {@link captureBounces} with errors naming `where`. */
export async function captureWithBounces(
	where: string, volume: LightProbeVolume, renderer: CaptureRenderer, scene: Scene, options: CaptureBouncesOptions,
): Promise<CaptureBouncesResult> {

	const access = accessOf( where, volume );
	if ( ! options || typeof options !== 'object' ) throw new TypeError( `${where}: options must be an object with at least { bounces }.` );
	const { bounces, staticMeshes, hideInBounces, output = 'irradiance', onPass, ...capture } = options;
	assertInteger( where, 'options.bounces', bounces, 0, MAX_BOUNCES );
	if ( output !== 'irradiance' && output !== 'sh' ) {

		throw new RangeError( `${where}: options.output is "${String( output )}"; expected 'irradiance' or 'sh'.` );

	}

	if ( onPass !== undefined && typeof onPass !== 'function' ) throw new TypeError( `${where}: options.onPass must be a function.` );
	const given = staticMeshes !== undefined ? checkMeshes( where, staticMeshes ) : null;
	if ( hideInBounces !== undefined && ( hideInBounces === null || typeof hideInBounces[ Symbol.iterator ] !== 'function' ) ) {

		throw new TypeError( `${where}: options.hideInBounces must be an iterable (e.g. an array) of three.js Object3Ds.` );

	}

	const hidden = hideInBounces !== undefined ? [ ...hideInBounces ] : [];
	hidden.forEach( ( object, i ) => {

		if ( ( object as { isObject3D?: boolean } )?.isObject3D !== true ) {

			throw new TypeError( `${where}: options.hideInBounces[${i}] is not a three.js Object3D.` );

		}

	} );

	// `exclude` is consumed twice (default mesh selection and every capture): an array, read once.
	const { indices, exclude } = checkCaptureOptions( where, volume, renderer, scene, capture );
	const checked = { ...capture, exclude };
	const fitting = await loadFitting( volume, access, capture.fit );
	const plan = fitting?.planFit( where, volume, access, capture, scene, hiddenObjects( access, exclude ) ) ?? null;
	const points = plan?.points ?? null;
	// Nothing to capture (recaptureDirty with no dirty probe) and nothing to refit: no pass at all.
	if ( indices.length === 0 && points === null && plan?.mode !== 'refit' ) {

		return { passes: [], staticMeshes: [], vertices: 0, totalMs: 0 };

	}

	const meshes = given ?? findStaticMeshes( volume, scene, checked );
	// Scenery the volume lights itself (add( scene ), large objects) takes the bounce through its own lighting.
	const bounced = bounces > 0 && ( meshes.length > 0 || access.lit.some( ( entry ) => ! entry.hidden ) );
	// The fit points are captured once, in the last pass, with the light the probes get there.
	const lastPass = bounced ? bounces : 0;
	const start = now();
	const passes: BouncePass[] = [];
	// The SH as the passes make them; the volume gets the last pass once every pass is done.
	const staged = new Float32Array( volume.sh );
	let last: CapturedProbes | null = null;
	const captureAndMeasure = async ( pass: number, lightingMs: number, scenery: ProbeField | null = null ) => {

		const captureStart = now();
		last = await captureProbes( volume, access.lit, indices, renderer, scene, checked, scenery, pass === lastPass ? points : null );
		applyCapturedProbes( last, staged );
		passes.push( { pass, meanL00: meanL00( staged, capture.indices ), captureMs: now() - captureStart, lightingMs } );
		onPass?.( pass, staged );

	};

	await captureAndMeasure( 0, 0 );
	const vertices = meshes.reduce( ( sum, mesh ) => sum + ( mesh.geometry.getAttribute( 'position' )?.count ?? 0 ), 0 );
	if ( bounced ) await bouncePasses( meshes, hidden, volume.interpolator, staged, output, bounces, captureAndMeasure );
	if ( fitting !== null ) fitting.commitWithFit( plan!, volume, access, last );
	else access.commit( last! );
	return { passes, staticMeshes: meshes, vertices, totalMs: now() - start };

}

/**
 * Passes 1..bounces: the static meshes lit per vertex by the previous pass's SH (frozen, so the
 * light on the walls does not change while role groups of probes are captured), the stand-ins
 * hidden; everything restored afterwards, also when a pass throws.
 */
async function bouncePasses(
	meshes: Mesh[], hidden: Object3D[], interpolator: ProbeInterpolator, staged: Float32Array, output: 'irradiance' | 'sh',
	bounces: number, captureAndMeasure: ( pass: number, lightingMs: number, scenery: ProbeField ) => Promise<void>,
): Promise<void> {

	const field = { interpolator, sh: new Float32Array( staged ) };
	const lightings: ProbeVertexLighting[] = [];
	const swapped: { mesh: Mesh; geometry: BufferGeometry; material: Material | Material[] }[] = [];
	const visibility = hidden.map( ( object ) => object.visible );
	try {

		let lightingStart = now();
		for ( const mesh of meshes ) {

			// A geometry of the pass's own: vertex light depends on world positions, and the user's
			// geometry (maybe shared by other meshes) must come back untouched.
			const geometry = mesh.geometry, copy = geometry.clone();
			swapped.push( { mesh, geometry, material: mesh.material } );
			mesh.geometry = copy;
			if ( output === 'irradiance' && ! copy.getAttribute( 'normal' ) ) copy.computeVertexNormals();
			lightings.push( new ProbeVertexLighting( mesh, field, { output } ) );

		}

		for ( const object of hidden ) object.visible = false;
		for ( let pass = 1; pass <= bounces; pass ++ ) {

			if ( pass > 1 ) {

				lightingStart = now();
				field.sh.set( staged );
				for ( const lighting of lightings ) lighting.update();

			}

			await captureAndMeasure( pass, now() - lightingStart, field );

		}

	} finally {

		for ( const lighting of lightings ) lighting.dispose();
		for ( const { mesh, geometry, material } of swapped ) {

			mesh.geometry.dispose();
			mesh.geometry = geometry;
			mesh.material = material;

		}

		hidden.forEach( ( object, i ) => { object.visible = visibility[ i ]; } );

	}

}

/**
 * The fitting module when this capture fits or refits — `options.fit` given, or the volume fitted
 * before (it refits, or becomes plain) — else null. Loaded on demand, so a game that never fits
 * does not ship it (it brings the placement tools for `fit.spacing`).
 */
async function loadFitting( volume: LightProbeVolume, access: CaptureAccess, fit: unknown ): Promise<typeof import( './fitVolume.js' ) | null> {

	if ( fit === undefined && access.fit === null && volume.fitSettings === null ) return null;
	return import( './fitVolume.js' );

}

/** What a capture hides: the volume's dynamic objects and `exclude`. */
function hiddenObjects( access: CaptureAccess, exclude: readonly Object3D[] | undefined ): Object3D[] {

	return [ ...access.lit.filter( ( entry ) => entry.hidden ).map( ( entry ) => entry.object ), ...( exclude ?? [] ) ];

}

/** The volume's {@link CaptureAccess}; a TypeError when it is not a `LightProbeVolume`. */
function accessOf( where: string, volume: LightProbeVolume ): CaptureAccess {

	if ( typeof volume?.[ CAPTURE_ACCESS ] !== 'function' ) throw new TypeError( `${where}: volume must be a LightProbeVolume.` );
	return volume[ CAPTURE_ACCESS ]();

}

/** Mean L00 (r, g, b) over the given probes, or all. */
function meanL00( sh: Float32Array, indices?: ArrayLike<number> ): [ number, number, number ] {

	const count = indices !== undefined ? indices.length : sh.length / SH_FLOATS;
	const sum: [ number, number, number ] = [ 0, 0, 0 ];
	for ( let k = 0; k < count; k ++ ) {

		const base = SH_FLOATS * ( indices !== undefined ? indices[ k ] : k );
		for ( let c = 0; c < 3; c ++ ) sum[ c ] += sh[ base + c ];

	}

	return count > 0 ? [ sum[ 0 ] / count, sum[ 1 ] / count, sum[ 2 ] / count ] : sum;

}

function isLightable( mesh: Mesh ): boolean {

	const candidate = mesh as Mesh & { isSkinnedMesh?: boolean; isInstancedMesh?: boolean };
	if ( candidate.isMesh !== true || candidate.isSkinnedMesh === true || candidate.isInstancedMesh === true ) return false;
	const position = mesh.geometry?.getAttribute( 'position' );
	return position !== undefined && position.itemSize >= 3;

}

/**
 * The materials of a mesh that a bounce pass lights (see `takesProbeLight`): the built-in lit
 * materials, and with `three-capture-lighting/webgpu` imported the lit node materials too — left
 * out, node-material scenery would reflect no bounce light and the passes would add less, unnoticed.
 */
function probeLitMaterials( mesh: Mesh ): Material[] {

	return meshMaterials( mesh ).filter( takesProbeLight );

}

function checkMeshes( where: string, meshes: readonly Mesh[] ): Mesh[] {

	if ( ! Array.isArray( meshes ) ) throw new TypeError( `${where}: options.staticMeshes must be an array of meshes.` );
	const unique = [ ...new Set( meshes ) ];
	unique.forEach( ( mesh, i ) => {

		if ( ! mesh || ( mesh as { isMesh?: boolean } ).isMesh !== true ) {

			throw new TypeError( `${where}: options.staticMeshes[${i}] is not a three.js Mesh.` );

		}

		const name = mesh.name ? ` ("${mesh.name}")` : '';
		if ( ! isLightable( mesh ) ) {

			throw new TypeError( `${where}: options.staticMeshes[${i}]${name} is skinned, instanced or has no position attribute; `
				+ 'bounce light is sampled at static vertices.' );

		}

		const materials = probeLitMaterials( mesh );
		if ( materials.length === 0 ) {

			throw new TypeError( `${where}: options.staticMeshes[${i}]${name} has no ${PROBE_LIT_MATERIALS} to light.` );

		}

		if ( materials.some( ( material ) => probeUniformsOf( material ) !== null ) ) {

			throw new Error( `${where}: options.staticMeshes[${i}]${name} already has a probe-lit (patched) material; `
				+ 'it would receive probe light twice.' );

		}

	} );

	return unique;

}

/** The default static meshes: what the capture draws and a bounce can light (see CaptureBouncesOptions.staticMeshes). */
function findStaticMeshes( volume: LightProbeVolume, scene: Scene, capture: LightProbeVolumeCaptureOptions ): Mesh[] {

	const excluded = new Set<Object3D>( capture.exclude as Object3D[] | undefined ?? [] );
	const seen = [ capture.layers ?? new Layers() ];
	for ( const settings of Object.values( capture.roles ?? {} ) ) if ( settings?.layers ) seen.push( settings.layers );
	const meshes: Mesh[] = [];
	scene.traverseVisible( ( object ) => {

		const mesh = object as Mesh;
		if ( ! isLightable( mesh ) ) return;
		if ( ! seen.some( ( layers ) => mesh.layers.test( layers ) ) ) return;
		const materials = probeLitMaterials( mesh );
		if ( materials.length === 0 || materials.some( ( material ) => probeUniformsOf( material ) !== null ) ) return;
		for ( let node: Object3D | null = mesh; node !== null; node = node.parent ) {

			if ( excluded.has( node ) || volume.getUniforms( node ) !== null ) return;
			if ( capture.filter && node !== scene && ! capture.filter( node ) ) return;

		}

		meshes.push( mesh );

	} );

	return meshes;

}

function now(): number {

	return typeof performance !== 'undefined' ? performance.now() : Date.now();

}
