import type { Material } from 'three';
import { getProbeVolumeUniforms, patchMaterial, unpatchMaterial, type ProbeVolumeSource, type ProbeVolumeUniforms } from './patchMaterial.js';

/*
 * The one door from the WebGL core to node-material (TSL) shading. The core never imports
 * three/webgpu or three/tsl: `three-capture-lighting/webgpu` installs an implementation here, and
 * every place that patches a material for probe light goes through {@link patchProbeMaterial}.
 * With it installed, a built-in material gets both patches (WebGL's onBeforeCompile and the node
 * hooks three copies when WebGPURenderer converts it), so one material is lit on either renderer.
 */

/** How a material is patched: where its probe light comes from and the uniforms it reads. */
export interface ProbeMaterialPatch {

	/** Where the probe light comes from (see `ProbeVolumeSource`). */
	source: ProbeVolumeSource;

	/** Source `'uniform'`: evaluate the irradiance per vertex instead of per pixel. */
	perVertex: boolean;

	/** The uniforms the material reads; written by the volume (or a large-object lighting). */
	uniforms: ProbeVolumeUniforms;

}

/** Node-material shading, installed by `three-capture-lighting/webgpu`. */
export interface NodeMaterialShading {

	/** Whether `material` is a node material this shading lights (Standard, Physical, Phong, Lambert, Toon). */
	lights( material: Material ): boolean;

	/**
	 * Adds probe light to a node material, or the node hooks to a built-in material (which three's
	 * WebGPURenderer copies onto the node material it converts it to). Idempotent.
	 */
	patch( material: Material, patch: ProbeMaterialPatch ): void;

	/** Undoes {@link NodeMaterialShading.patch}; no-op for a material it did not patch. */
	unpatch( material: Material ): void;

	/** The uniforms of a material it patched, or null. */
	uniformsOf( material: Material ): ProbeVolumeUniforms | null;

}

let installed: NodeMaterialShading | null = null;

/** Installs node-material shading (called once by `three-capture-lighting/webgpu`); a later call replaces it. */
export function installNodeMaterialShading( impl: NodeMaterialShading ): void {

	installed = impl;

}

/** The installed node-material shading, or null when the library was imported from the main entry. */
export function nodeMaterialShading(): NodeMaterialShading | null {

	return installed;

}

/** Whether a material is a three.js node material (`isNodeMaterial`). */
export function isNodeMaterial( material: unknown ): boolean {

	return ( material as { isNodeMaterial?: boolean } | null | undefined )?.isNodeMaterial === true;

}

/** Whether a node material is of a lit type the shading can reach (Standard, Physical, Phong, Lambert, Toon). */
export function isLitNodeMaterial( material: unknown ): boolean {

	const m = material as Record<string, unknown> | null | undefined;
	if ( ! m || m.isNodeMaterial !== true ) return false;
	return m.isMeshStandardNodeMaterial === true || m.isMeshPhongNodeMaterial === true || m.isMeshLambertNodeMaterial === true
		|| m.isMeshToonNodeMaterial === true;

}

/**
 * Patches a material for probe light on whichever renderer draws it: a built-in one with
 * `patchMaterial` (and the node hooks too when installed), a node material with the installed
 * node shading. The caller has checked `takesProbeLight`.
 */
export function patchProbeMaterial( material: Material, patch: ProbeMaterialPatch ): void {

	if ( isNodeMaterial( material ) ) {

		installed!.patch( material, patch );
		return;

	}

	const perVertex = patch.source === 'uniform' ? patch.perVertex : undefined;
	patchMaterial( material, { source: patch.source, perVertex, uniforms: patch.uniforms } );
	try {

		installed?.patch( material, patch );

	} catch ( error ) {

		unpatchMaterial( material );
		throw error;

	}

}

/** Undoes {@link patchProbeMaterial}. */
export function unpatchProbeMaterial( material: Material ): void {

	installed?.unpatch( material );
	if ( ! isNodeMaterial( material ) ) unpatchMaterial( material );

}

/** The probe uniforms of a material patched by either path, or null. */
export function probeUniformsOf( material: Material ): ProbeVolumeUniforms | null {

	if ( isNodeMaterial( material ) ) return installed?.uniformsOf( material ) ?? null;
	return getProbeVolumeUniforms( material );

}

/**
 * The message for `add()` of an object whose lit-looking materials are all node materials while
 * node shading is not installed (the library imported from the main entry).
 */
export function nodeMaterialsNeedWebGPUEntry( where: string, name: string, types: readonly string[] ): string {

	return `${where}: ${name} uses node materials (${types.join( ', ' )}); import the library from 'three-capture-lighting/webgpu' to light them.`;

}
