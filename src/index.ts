/**
 * three-capture-lighting — capture-based indirect lighting for three.js.
 *
 * Pure math and geometry (no three.js imports): SH9 projection and irradiance, the exact 3D
 * Delaunay tetrahedralization, and probe interpolation.
 */

export * from './sh/index.js';

export { tetrahedralize, DegenerateInputError } from './tetrahedra/tetrahedralize.js';
export type { Tetrahedralization, TetrahedralizeOptions, DegenerateReason } from './tetrahedra/tetrahedralize.js';

export type { ProbeInterpolator } from './interpolation/ProbeInterpolator.js';
export { TetrahedralMesh } from './interpolation/TetrahedralMesh.js';
export { GridInterpolator } from './interpolation/GridInterpolator.js';
export { PlanarMesh } from './interpolation/PlanarMesh.js';
export { createProbeInterpolator } from './interpolation/createProbeInterpolator.js';
export { blendSH } from './interpolation/blendSH.js';

export { SH_FLOATS } from './validate.js';

// three.js glue: GPU capture and projection, the probe volume, patched materials.
export { SHProjector } from './capture/SHProjector.js';
export { ProbeCapturer } from './capture/ProbeCapturer.js';
export type { ProbeCaptureSettings, ProbeCaptureOptions } from './capture/ProbeCapturer.js';
export { projectEquirectToSHGPU } from './capture/projectEquirectToSHGPU.js';
export { LightProbeVolume } from './runtime/LightProbeVolume.js';
export type { LightProbeVolumeParameters, LightProbeVolumeCaptureOptions, AddOptions, ProbeRole } from './runtime/LightProbeVolume.js';
export { patchMaterial, unpatchMaterial, getProbeVolumeUniforms } from './runtime/patchMaterial.js';
export type { PatchMaterialOptions, ProbeVolumeUniforms } from './runtime/patchMaterial.js';
