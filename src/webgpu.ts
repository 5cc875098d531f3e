/**
 * `three-capture-lighting/webgpu` — the library for `WebGPURenderer` (`three/webgpu`): everything
 * the main entry exports, with node-material shading (TSL) and WebGPU capture installed, so the
 * same `LightProbeVolume` code runs on both renderers. Import it instead of the main entry in a
 * WebGPURenderer project, as three.js itself is imported from `three/webgpu` there; a WebGL-only
 * project keeps the main entry and never loads three's node system.
 */

import './webgpu/installShading.js';
import './webgpu/installCapture.js';
import './webgpu/installHelper.js';

export * from './index.js';
export { ProbeVolumeIrradiance } from './webgpu/lightmap/ProbeVolumeIrradiance.js';
export type { ProbeVolumeIrradianceOptions } from './webgpu/lightmap/ProbeVolumeIrradiance.js';
