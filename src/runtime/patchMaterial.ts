import { Vector3, type Camera, type Data3DTexture, type Material, type WebGLProgramParametersWithUniforms, type WebGLRenderer } from 'three';
import {
	probeVolumeIrradianceAttributeVert, probeVolumeIrradianceAttributeVertPars, probeVolumeIrradianceVaryingFragPars,
	probeVolumeLightsFrag, probeVolumeLightsTextureFrag, probeVolumeLightsVaryingFrag, probeVolumeLightsVertexSHFrag,
	probeVolumeNormalVert, probeVolumePars, probeVolumeSHAttributesVert, probeVolumeSHAttributesVertPars,
	probeVolumeTexturePars, probeVolumeVertexSHPars,
} from '../shaders.generated.js';
import { assertNumber, assertOptionalBoolean, assertOptions, describeValue } from '../validate.js';
import { PROBE_LIT_MATERIALS, isProbeLitMaterial } from './probeLitMaterials.js';
import { VIEW_IRRADIANCE_FLOATS, viewIrradiance } from './viewIrradiance.js';

/** The uniforms a patched material reads; write them yourself, or let a `LightProbeVolume` do it. */
export interface ProbeVolumeUniforms {

	/**
	 * The three 4x4 irradiance matrices (R, G, B), column-major, for world-space normals:
	 * `irradianceMatrices( sh, value )`. Read at every draw, when the material turns them into
	 * coefficients for the camera's view space (source `'uniform'`).
	 */
	probeVolumeMatrices: { value: Float32Array };

	/** Scale of the probe light on this material (the paper's blend into the diffuse term). Default 1. */
	probeVolumeIntensity: { value: number };

	/**
	 * Scale of direct (punctual) light on this material. Default 1; 0 shows the probe light alone —
	 * the paper's "indirect only" view, handy when placing probes.
	 */
	probeVolumeDirectScale: { value: number };

	/** Mode `'texture'`: the SH atlas of a {@link ProbeVolumeTexture} (three's LightProbeGrid layout). */
	probeVolumeSH?: { value: Data3DTexture | null };

	/** Mode `'texture'`: world position of the texture's first grid node. */
	probeVolumeGridMin?: { value: Vector3 };

	/** Mode `'texture'`: world position of the texture's last grid node. */
	probeVolumeGridMax?: { value: Vector3 };

	/** Mode `'texture'`: grid nodes per axis (each ≥ 2). */
	probeVolumeGridResolution?: { value: Vector3 };

}

/**
 * Where a patched material's probe light comes from:
 * - `'uniform'`: one SH per object, as 3 irradiance matrices (`LightProbeVolume`'s object mode).
 * - `'vertexIrradiance'`: a `probeIrradiance` vec3 attribute per vertex (`ProbeVertexLighting`).
 * - `'vertexSH'`: 7 vec4 attributes `probeSH0`…`probeSH6` per vertex, evaluated per pixel.
 * - `'texture'`: a 3D SH texture over the object's bounds, sampled per pixel (`ProbeTextureLighting`).
 */
export type ProbeVolumeSource = 'uniform' | 'vertexIrradiance' | 'vertexSH' | 'texture';

const SOURCES: readonly ProbeVolumeSource[] = [ 'uniform', 'vertexIrradiance', 'vertexSH', 'texture' ];

/** Options of {@link patchMaterial}. */
export interface PatchMaterialOptions {

	/** Evaluate irradiance per vertex instead of per pixel (cheaper; the paper offers both). Default false. Source `'uniform'` only. */
	perVertex?: boolean;

	/** Where the probe light comes from. Default `'uniform'`. */
	source?: ProbeVolumeSource;

	/** Initial `probeVolumeIntensity`. Default 1. */
	intensity?: number;

	/** Share these uniforms instead of making new ones (all meshes of one lit object share them). */
	uniforms?: ProbeVolumeUniforms;

}

const PATCHED = Symbol( 'three-capture-lighting.patched' );

interface PatchedMaterial extends Material {

	[ PATCHED ]?: {
		uniforms: ProbeVolumeUniforms; variant: string; onBeforeCompile: Material[ 'onBeforeCompile' ];
		customProgramCacheKey: Material[ 'customProgramCacheKey' ]; onBeforeRender: Material[ 'onBeforeRender' ];
	};

}

/**
 * Makes a `MeshStandardMaterial`, `MeshPhysicalMaterial`, `MeshPhongMaterial`,
 * `MeshLambertMaterial` or `MeshToonMaterial` lit by probe SH: the paper's E(n) = nᵀMn, with one
 * 4x4 M per colour channel in uniforms, is added to three's indirect diffuse irradiance (where a
 * `LightProbe`'s term goes; the material's own diffuse response shades it). All patched
 * materials of one type with the same options share one shader program; only uniforms differ.
 * A user `onBeforeCompile` or `onBeforeRender` set before patching still runs. With source
 * `'uniform'` the material's `onBeforeRender` turns the matrices into view-space coefficients at
 * every draw: a hook set on it after patching must call the one it replaces. `options.source`
 * swaps the per-object matrices for per-vertex attributes or a 3D SH texture (large objects: see
 * `ProbeVertexLighting`, `ProbeTextureLighting`).
 *
 * @returns The uniforms: fill `probeVolumeMatrices.value` with `irradianceMatrices( sh )`.
 */
export function patchMaterial( material: Material, options: PatchMaterialOptions = {} ): ProbeVolumeUniforms {

	if ( ! isProbeLitMaterial( material ) ) {

		throw new TypeError( `patchMaterial: material must be a ${PROBE_LIT_MATERIALS}, got ${( material as { type?: string } )?.type ?? typeof material}.` );

	}

	const target = material as PatchedMaterial;
	assertOptions( 'patchMaterial', 'options', options );
	assertOptionalBoolean( 'patchMaterial', 'options.perVertex', options.perVertex );
	if ( options.intensity !== undefined ) assertNumber( 'patchMaterial', 'options.intensity', options.intensity );
	if ( options.uniforms !== undefined ) checkUniforms( options.uniforms );
	const existing = target[ PATCHED ];
	if ( existing ) return existing.uniforms;

	const source = options.source ?? 'uniform';
	if ( ! SOURCES.includes( source ) ) throw new RangeError( `patchMaterial: options.source is "${String( source )}"; expected one of ${SOURCES.join( ', ' )}.` );
	const perVertex = options.perVertex === true;
	if ( perVertex && source !== 'uniform' ) throw new RangeError( `patchMaterial: options.perVertex applies to source 'uniform' only, got source '${source}'.` );
	const variant = source === 'uniform' ? ( perVertex ? 'vertex' : 'pixel' ) : source;
	const uniforms: ProbeVolumeUniforms = options.uniforms ?? {
		probeVolumeMatrices: { value: new Float32Array( 48 ) },
		probeVolumeIntensity: { value: options.intensity ?? 1 },
		probeVolumeDirectScale: { value: 1 },
	};
	if ( source === 'texture' && options.uniforms === undefined ) {

		uniforms.probeVolumeSH = { value: null };
		uniforms.probeVolumeGridMin = { value: new Vector3() };
		uniforms.probeVolumeGridMax = { value: new Vector3( 1, 1, 1 ) };
		uniforms.probeVolumeGridResolution = { value: new Vector3( 2, 2, 2 ) };

	}

	if ( source === 'texture' && ( ! uniforms.probeVolumeSH || ! uniforms.probeVolumeGridMin || ! uniforms.probeVolumeGridMax || ! uniforms.probeVolumeGridResolution ) ) {

		throw new TypeError( 'patchMaterial: source \'texture\' needs options.uniforms with probeVolumeSH, probeVolumeGridMin, probeVolumeGridMax and probeVolumeGridResolution.' );

	}

	const previous = {
		onBeforeCompile: target.onBeforeCompile, customProgramCacheKey: target.customProgramCacheKey, onBeforeRender: target.onBeforeRender,
	};
	// three's default key is onBeforeCompile.toString(): evaluate it with the user's hook in place,
	// or every patched material would share the wrapper's text and one program.
	const previousKey = () => {

		const wrapper = target.onBeforeCompile;
		target.onBeforeCompile = previous.onBeforeCompile;
		try {

			return previous.customProgramCacheKey.call( target );

		} finally {

			target.onBeforeCompile = wrapper;

		}

	};

	// The object mode's coefficients depend on the camera: made for each draw, just before three
	// uploads the material's uniforms (it re-uploads them whenever the material or camera changes).
	const view = { value: new Float32Array( VIEW_IRRADIANCE_FLOATS ) };
	if ( source === 'uniform' ) {

		target.onBeforeRender = function ( renderer, scene, camera: Camera, geometry, object, group ) {

			previous.onBeforeRender.call( this, renderer, scene, camera, geometry, object, group );
			const { probeVolumeMatrices, probeVolumeIntensity } = uniforms;
			viewIrradiance( probeVolumeMatrices.value, probeVolumeIntensity.value, camera.matrixWorldInverse.elements, view.value );

		};

	}

	target.onBeforeCompile = function ( shader: WebGLProgramParametersWithUniforms, renderer: WebGLRenderer ) {

		previous.onBeforeCompile.call( this, shader, renderer );
		shader.uniforms.probeVolumeMatrices = uniforms.probeVolumeMatrices;
		shader.uniforms.probeVolumeIntensity = uniforms.probeVolumeIntensity;
		shader.uniforms.probeVolumeDirectScale = uniforms.probeVolumeDirectScale;
		if ( source === 'texture' ) {

			shader.uniforms.probeVolumeSH = uniforms.probeVolumeSH!;
			shader.uniforms.probeVolumeGridMin = uniforms.probeVolumeGridMin!;
			shader.uniforms.probeVolumeGridMax = uniforms.probeVolumeGridMax!;
			shader.uniforms.probeVolumeGridResolution = uniforms.probeVolumeGridResolution!;

		}

		if ( source === 'uniform' ) shader.uniforms.probeVolumeViewIrradiance = view;
		injectProbeVolume( shader, variant );

	};

	target.customProgramCacheKey = () => `${previousKey()}|three-capture-lighting:1:${variant}`;
	target[ PATCHED ] = { uniforms, variant, ...previous };
	// Release the compiled program: three keeps uniforms per material and program key, so a
	// material patched again (new uniforms, same key) must be compiled afresh to pick them up.
	target.dispose();
	return uniforms;

}

/** `options.uniforms` of {@link patchMaterial}: the three common uniforms, each `{ value }` of the right type. */
function checkUniforms( uniforms: unknown ): void {

	const u = uniforms as Partial<Record<keyof ProbeVolumeUniforms, { value?: unknown }>> | null;
	const matrices = u?.probeVolumeMatrices?.value;
	if ( ! ( matrices instanceof Float32Array && matrices.length >= 48 )
		|| typeof u?.probeVolumeIntensity?.value !== 'number' || typeof u?.probeVolumeDirectScale?.value !== 'number' ) {

		throw new TypeError( 'patchMaterial: options.uniforms must be ProbeVolumeUniforms: { probeVolumeMatrices: { value: Float32Array( 48 ) }, '
			+ 'probeVolumeIntensity: { value: number }, probeVolumeDirectScale: { value: number } } (as patchMaterial returns them).' );

	}

}

/** Checks a material argument: any three.js `Material`. */
function assertMaterial( where: string, material: unknown ): void {

	if ( ( material as { isMaterial?: boolean } | null )?.isMaterial !== true ) {

		throw new TypeError( `${where}: material must be a three.js Material, got ${describeValue( material )}.` );

	}

}

/** The uniforms of a patched material, or null when it is not patched. */
export function getProbeVolumeUniforms( material: Material ): ProbeVolumeUniforms | null {

	assertMaterial( 'getProbeVolumeUniforms', material );
	return ( material as PatchedMaterial )[ PATCHED ]?.uniforms ?? null;

}

/** Undoes {@link patchMaterial}: the material compiles as before on its next use. */
export function unpatchMaterial( material: Material ): void {

	assertMaterial( 'unpatchMaterial', material );
	const target = material as PatchedMaterial;
	const patch = target[ PATCHED ];
	if ( ! patch ) return;
	target.onBeforeCompile = patch.onBeforeCompile;
	target.customProgramCacheKey = patch.customProgramCacheKey;
	target.onBeforeRender = patch.onBeforeRender;
	delete target[ PATCHED ];
	target.dispose();

}

// Indirect diffuse irradiance is accumulated in `irradiance` by lights_fragment_begin (in the
// Standard, Phong, Lambert and Toon shaders alike); the probe term joins it there
// (shaders/probeVolumeLights*.frag.glsl), before lights_fragment_end hands it to
// RE_IndirectDiffuse — the same place and units (no π) as three's LightProbe term; the object mode
// evaluates it for the view-space normal, the other sources for the world normal.
// The direct scale multiplies reflectedLight's direct terms, which all four declare. The texture
// variant takes the world position from the view-space one, as three's own light-probe-grid path
// does: no extra varying.

const MAIN = 'void main() {';
const LIGHTS = '#include <lights_fragment_begin>';
const NORMAL = '#include <defaultnormal_vertex>';
const DIRECT_SCALE = 'uniform float probeVolumeDirectScale;\n';

/**
 * What a variant adds to each stage: declarations before `void main() {`, and a chunk (from
 * shaders/, starting with three's include it replaces; put on lines of its own) in place of
 * lights_fragment_begin and, when the vertex stage takes part, defaultnormal_vertex.
 */
interface ProbeVolumeInjection {

	vertexPars?: string;
	vertex?: string;
	fragmentPars: string;
	fragment: string;

}

const INJECTIONS: Record<string, ProbeVolumeInjection> = {
	pixel: { fragmentPars: `${probeVolumePars}\n${DIRECT_SCALE}`, fragment: probeVolumeLightsFrag },
	vertex: {
		vertexPars: `${probeVolumePars}\nvarying vec3 vProbeVolumeIrradiance;\n`, vertex: probeVolumeNormalVert,
		fragmentPars: probeVolumeIrradianceVaryingFragPars, fragment: probeVolumeLightsVaryingFrag,
	},
	vertexIrradiance: {
		vertexPars: probeVolumeIrradianceAttributeVertPars, vertex: probeVolumeIrradianceAttributeVert,
		fragmentPars: probeVolumeIrradianceVaryingFragPars, fragment: probeVolumeLightsVaryingFrag,
	},
	vertexSH: {
		vertexPars: probeVolumeSHAttributesVertPars, vertex: probeVolumeSHAttributesVert,
		fragmentPars: `${probeVolumeVertexSHPars}\n${DIRECT_SCALE}`, fragment: probeVolumeLightsVertexSHFrag,
	},
	texture: { fragmentPars: `${probeVolumeTexturePars}\n${DIRECT_SCALE}`, fragment: probeVolumeLightsTextureFrag },
};

function injectProbeVolume( shader: WebGLProgramParametersWithUniforms, variant: string ): void {

	const requireChunk = ( source: string, chunk: string, stage: string ) => {

		if ( ! source.includes( chunk ) ) {

			throw new Error( `patchMaterial: the ${stage} shader has no ${chunk}; this three.js version or material is not supported.` );

		}

	};

	const injection = INJECTIONS[ variant ];
	requireChunk( shader.fragmentShader, LIGHTS, 'fragment' );
	if ( injection.vertex !== undefined ) {

		requireChunk( shader.vertexShader, NORMAL, 'vertex' );
		shader.vertexShader = shader.vertexShader
			.replace( MAIN, `${injection.vertexPars}${MAIN}` )
			.replace( NORMAL, `\n${injection.vertex}` );

	}

	shader.fragmentShader = shader.fragmentShader
		.replace( MAIN, `${injection.fragmentPars}${MAIN}` )
		.replace( LIGHTS, `\n${injection.fragment}` );

}
