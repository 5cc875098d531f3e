import type { Material, WebGLProgramParametersWithUniforms, WebGLRenderer } from 'three';
import { probeVolumePars } from '../shaders.generated.js';

/** The uniforms a patched material reads; write them yourself, or let a `LightProbeVolume` do it. */
export interface ProbeVolumeUniforms {

	/** The three 4x4 irradiance matrices (R, G, B), column-major: `irradianceMatrices( sh, value )`. */
	probeVolumeMatrices: { value: Float32Array };

	/** Scale of the probe light on this material (the paper's blend into the diffuse term). Default 1. */
	probeVolumeIntensity: { value: number };

	/**
	 * Scale of direct (punctual) light on this material. Default 1; 0 shows the probe light alone —
	 * the paper's "indirect only" view, handy when placing probes.
	 */
	probeVolumeDirectScale: { value: number };

}

/** Options of {@link patchMaterial}. */
export interface PatchMaterialOptions {

	/** Evaluate irradiance per vertex instead of per pixel (cheaper; the paper offers both). Default false. */
	perVertex?: boolean;

	/** Initial `probeVolumeIntensity`. Default 1. */
	intensity?: number;

	/** Share these uniforms instead of making new ones (all meshes of one lit object share them). */
	uniforms?: ProbeVolumeUniforms;

}

const PATCHED = Symbol( 'three-capture-lighting.patched' );

interface PatchedMaterial extends Material {

	[ PATCHED ]?: { uniforms: ProbeVolumeUniforms; onBeforeCompile: Material[ 'onBeforeCompile' ]; customProgramCacheKey: Material[ 'customProgramCacheKey' ]; perVertex: boolean };

}

/**
 * Makes a `MeshStandardMaterial` or `MeshPhysicalMaterial` lit by probe SH: the paper's
 * E(n) = nᵀMn, with one 4x4 M per colour channel in uniforms, is added to three's indirect
 * diffuse irradiance (where a `LightProbe`'s term goes). All patched materials with the same
 * options share one shader program; only uniforms differ per object. A user `onBeforeCompile`
 * set before patching still runs.
 *
 * @returns The uniforms: fill `probeVolumeMatrices.value` with `irradianceMatrices( sh )`.
 */
export function patchMaterial( material: Material, options: PatchMaterialOptions = {} ): ProbeVolumeUniforms {

	const target = material as PatchedMaterial & { isMeshStandardMaterial?: boolean };
	if ( ! target || target.isMeshStandardMaterial !== true ) {

		throw new TypeError( `patchMaterial: material must be a MeshStandardMaterial or MeshPhysicalMaterial, got ${( material as { type?: string } )?.type ?? typeof material}.` );

	}

	const existing = target[ PATCHED ];
	if ( existing ) return existing.uniforms;

	const perVertex = options.perVertex === true;
	const uniforms: ProbeVolumeUniforms = options.uniforms ?? {
		probeVolumeMatrices: { value: new Float32Array( 48 ) },
		probeVolumeIntensity: { value: options.intensity ?? 1 },
		probeVolumeDirectScale: { value: 1 },
	};
	const previous = { onBeforeCompile: target.onBeforeCompile, customProgramCacheKey: target.customProgramCacheKey };
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

	target.onBeforeCompile = function ( shader: WebGLProgramParametersWithUniforms, renderer: WebGLRenderer ) {

		previous.onBeforeCompile.call( this, shader, renderer );
		shader.uniforms.probeVolumeMatrices = uniforms.probeVolumeMatrices;
		shader.uniforms.probeVolumeIntensity = uniforms.probeVolumeIntensity;
		shader.uniforms.probeVolumeDirectScale = uniforms.probeVolumeDirectScale;
		injectProbeVolume( shader, perVertex );

	};

	target.customProgramCacheKey = () => `${previousKey()}|three-capture-lighting:1:${perVertex ? 'vertex' : 'pixel'}`;
	target[ PATCHED ] = { uniforms, perVertex, ...previous };
	// Release the compiled program: three keeps uniforms per material and program key, so a
	// material patched again (new uniforms, same key) must be compiled afresh to pick them up.
	target.dispose();
	return uniforms;

}

/** The uniforms of a patched material, or null when it is not patched. */
export function getProbeVolumeUniforms( material: Material ): ProbeVolumeUniforms | null {

	return ( material as PatchedMaterial )[ PATCHED ]?.uniforms ?? null;

}

/** Undoes {@link patchMaterial}: the material compiles as before on its next use. */
export function unpatchMaterial( material: Material ): void {

	const target = material as PatchedMaterial;
	const patch = target[ PATCHED ];
	if ( ! patch ) return;
	target.onBeforeCompile = patch.onBeforeCompile;
	target.customProgramCacheKey = patch.customProgramCacheKey;
	delete target[ PATCHED ];
	target.dispose();

}

// Indirect diffuse irradiance is accumulated in `irradiance` by lights_fragment_begin; the probe
// term joins it there, before lights_fragment_end hands it to RE_IndirectDiffuse — the same place
// and space (world normal, no π) as three's LightProbe term.
const FRAGMENT_PIXEL = /* glsl */`
#include <lights_fragment_begin>
reflectedLight.directDiffuse *= probeVolumeDirectScale;
reflectedLight.directSpecular *= probeVolumeDirectScale;
#if defined( RE_IndirectDiffuse )
	irradiance += probeVolumeIrradiance( normalize( ( vec4( geometryNormal, 0.0 ) * viewMatrix ).xyz ) );
#endif
`;

const FRAGMENT_VERTEX = /* glsl */`
#include <lights_fragment_begin>
reflectedLight.directDiffuse *= probeVolumeDirectScale;
reflectedLight.directSpecular *= probeVolumeDirectScale;
#if defined( RE_IndirectDiffuse )
	irradiance += vProbeVolumeIrradiance;
#endif
`;

const VERTEX_VERTEX = /* glsl */`
#include <defaultnormal_vertex>
vProbeVolumeIrradiance = probeVolumeIrradiance( normalize( ( vec4( transformedNormal, 0.0 ) * viewMatrix ).xyz ) );
`;

function injectProbeVolume( shader: WebGLProgramParametersWithUniforms, perVertex: boolean ): void {

	const requireChunk = ( source: string, chunk: string, stage: string ) => {

		if ( ! source.includes( chunk ) ) throw new Error( `patchMaterial: the ${stage} shader has no ${chunk}; this three.js version or material is not supported.` );

	};

	requireChunk( shader.fragmentShader, '#include <lights_fragment_begin>', 'fragment' );
	if ( perVertex ) {

		requireChunk( shader.vertexShader, '#include <defaultnormal_vertex>', 'vertex' );
		shader.vertexShader = shader.vertexShader
			.replace( 'void main() {', `${probeVolumePars}\nvarying vec3 vProbeVolumeIrradiance;\nvoid main() {` )
			.replace( '#include <defaultnormal_vertex>', VERTEX_VERTEX );
		shader.fragmentShader = shader.fragmentShader
			.replace( 'void main() {', 'uniform float probeVolumeDirectScale;\nvarying vec3 vProbeVolumeIrradiance;\nvoid main() {' )
			.replace( '#include <lights_fragment_begin>', FRAGMENT_VERTEX );

	} else {

		shader.fragmentShader = shader.fragmentShader
			.replace( 'void main() {', `${probeVolumePars}\nuniform float probeVolumeDirectScale;\nvoid main() {` )
			.replace( '#include <lights_fragment_begin>', FRAGMENT_PIXEL );

	}

}
