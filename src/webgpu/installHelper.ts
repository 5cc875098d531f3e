/**
 * Installs the node-material (TSL) counterparts of LightProbeVolumeHelper's GLSL materials, so the
 * helper draws on a WebGPURenderer (issue 15). Imported by the `three-capture-lighting/webgpu` entry.
 */

import { installHelperMaterials } from '../runtime/helperHooks.js';
import { createProbeSphereNodeMaterial } from './helper/probeSphereNodeMaterial.js';

installHelperMaterials( { createProbeSphereMaterial: createProbeSphereNodeMaterial } );

export {};
