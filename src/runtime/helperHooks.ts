import type { Material } from 'three';

/*
 * LightProbeVolumeHelper reaches WebGPU code only through this hook: the `three-capture-lighting/webgpu`
 * entry installs node-material counterparts of the helper's GLSL materials (src/webgpu/installHelper.ts),
 * so the main entry never loads three/webgpu or three/tsl.
 */

/** The helper's materials for a WebGPURenderer (node materials, TSL). */
export interface HelperMaterials {

	/**
	 * A material for `ProbeSphereMesh`: each instance a white diffuse sphere lit by its own SH — the
	 * 27 floats of three's SphericalHarmonics3 packed in the per-instance attributes probeSH0…6
	 * (vec4, the last float unused) — drawing max( E(n), 0 ) / π for the world normal n, tone mapped
	 * and converted to the output colour space as three's own materials are.
	 */
	createProbeSphereMaterial(): Material;

}

let installed: HelperMaterials | null = null;

/** Installs the WebGPU helper materials (the webgpu entry does, once); later helpers use them. */
export function installHelperMaterials( impl: HelperMaterials ): void {

	installed = impl;

}

/** The installed WebGPU helper materials, or null (the main entry alone: WebGLRenderer only). */
export function helperMaterials(): HelperMaterials | null {

	return installed;

}
