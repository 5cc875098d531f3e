import { installNodeMaterialShading } from '../runtime/nodeMaterialHooks.js';
import { NodeProbeShading } from './shading/NodeProbeShading.js';

/**
 * Installs node-material (TSL) shading for LightProbeVolume: `volume.add()` then lights
 * MeshStandardNodeMaterial, MeshPhysicalNodeMaterial (and Phong, Lambert, Toon node materials),
 * and built-in materials drawn by WebGPURenderer, in every mode (docs/webgpu.md).
 */
installNodeMaterialShading( new NodeProbeShading() );
