import type { Material } from 'three';
import type { ProbeVolumeUniforms } from '../../runtime/patchMaterial.js';

/*
 * What node shading keeps per patched material. The node graph is shared by every material of a
 * variant (one pipeline); each draw's uniform values are looked up here from the material being
 * drawn, so only the values differ per object.
 */

/**
 * The node graphs: `'pixel'` / `'vertex'` (object mode, per pixel or per vertex), `'vertexIrradiance'`
 * and `'vertexSH'` (ProbeVertexLighting's attributes), `'texture'` and `'textureFloat'` (a half- or
 * float-texel ProbeVolumeTexture atlas: the sampler type differs).
 */
export type ProbeNodeVariant = 'pixel' | 'vertex' | 'vertexIrradiance' | 'vertexSH' | 'texture' | 'textureFloat';

/** The material methods node shading wraps, as own properties (three copies them when converting a built-in material). */
export const WRAPPED = [ 'setupLightingModel', 'setupMaterialLightings', 'customProgramCacheKey' ] as const;

/** One wrapped method's name. */
export type WrappedMethod = typeof WRAPPED[ number ];

/** A patched material's node-shading state. */
export interface ProbeMaterialRecord {

	variant: ProbeNodeVariant;
	uniforms: ProbeVolumeUniforms;
	/** The own properties the wrappers replaced (undefined: none, the prototype's method ran). */
	previous: Partial<Record<WrappedMethod, unknown>>;

}

/** Patched materials (the user's or clones; the built-in material itself, not three's node copy of it). */
export const probeMaterialRecords = new WeakMap<Material, ProbeMaterialRecord>();
