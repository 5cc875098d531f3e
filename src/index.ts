/**
 * three-capture-lighting — capture-based indirect lighting for three.js.
 *
 * Pure math and geometry (no three.js imports): SH9 projection and irradiance, the exact 3D
 * Delaunay tetrahedralization, and probe interpolation.
 */

export * from './sh/index.js';

export { tetrahedralize, DegenerateInputError } from './tetrahedra/tetrahedralize.js';
export type { Tetrahedralization, TetrahedralizeOptions, DegenerateReason } from './tetrahedra/tetrahedralize.js';
export { DynamicTetrahedralization } from './tetrahedra/DynamicTetrahedralization.js';
export type { TetrahedralEdit } from './tetrahedra/DynamicTetrahedralization.js';

export type { ProbeInterpolator } from './interpolation/ProbeInterpolator.js';
export { TetrahedralMesh } from './interpolation/TetrahedralMesh.js';
export type { OutsideMode, TetrahedralMeshOptions, FromTetrahedralizationOptions, FromDynamicOptions } from './interpolation/TetrahedralMesh.js';
export { OuterCells } from './interpolation/OuterCells.js';
export { GridInterpolator } from './interpolation/GridInterpolator.js';
export { PlanarMesh } from './interpolation/PlanarMesh.js';
export { createProbeInterpolator } from './interpolation/createProbeInterpolator.js';
export { blendSH } from './interpolation/blendSH.js';

export { SH_FLOATS } from './validate.js';

// Probe placement and automatic reduction (pure).
export { placeGrid } from './placement/placeGrid.js';
export { candidatesFromVertices } from './placement/candidatesFromVertices.js';
export type { CandidatesFromVerticesOptions } from './placement/candidatesFromVertices.js';
export { intersectRayTriangle } from './geometry/intersectRayTriangle.js';
export { TriangleBVH } from './geometry/TriangleBVH.js';
export { classifyPoints, OPEN_SPACE, INSIDE_GEOMETRY, NEAR_SURFACE, PARITY_RAY_DIRECTIONS } from './placement/classifyPoints.js';
export type { ClassifyPointsOptions } from './placement/classifyPoints.js';
export { irradianceError, IRRADIANCE_ERROR_NORMALS } from './placement/irradianceError.js';
export type { IrradianceErrorSummary, IrradianceErrorResult } from './placement/irradianceError.js';
export { reduceProbes } from './placement/reduceProbes.js';
export type { ReduceProbesOptions, ReduceProbesResult } from './placement/reduceProbes.js';

// three.js glue: GPU capture and projection, the probe volume, patched materials.
export { SHProjector } from './capture/SHProjector.js';
export { ProbeCapturer } from './capture/ProbeCapturer.js';
export type { ProbeCaptureSettings, ProbeCaptureOptions } from './capture/ProbeCapturer.js';
export { projectEquirectToSHGPU } from './capture/projectEquirectToSHGPU.js';
export { captureBounces } from './capture/captureBounces.js';
export type { CaptureBouncesOptions, CaptureBouncesResult, BouncePass } from './capture/captureBounces.js';
export { LightProbeVolume } from './runtime/LightProbeVolume.js';
export type { LightProbeVolumeParameters, LightProbeVolumeCaptureOptions, AddOptions, ProbeRole, ProbeOccluders, SampleOptions, AddProbeOptions } from './runtime/LightProbeVolume.js';
export { VisibilityGuard } from './runtime/VisibilityGuard.js';
export type { VisibilityGuardOptions } from './runtime/VisibilityGuard.js';
export { ProbeZones } from './runtime/ProbeZones.js';
export type { ProbeZoneDefinition, ProbeZone, BoxLike } from './runtime/ProbeZones.js';
export { patchMaterial, unpatchMaterial, getProbeVolumeUniforms } from './runtime/patchMaterial.js';
export type { PatchMaterialOptions, ProbeVolumeUniforms, ProbeVolumeSource } from './runtime/patchMaterial.js';
// Large objects. `toLightProbeGrid` (three's LightProbeGridWebGL, r186+) is the separate entry
// 'three-capture-lighting/lightProbeGrid', so this index loads with older three releases too.
export type { ProbeField } from './runtime/ProbeField.js';
export { ProbeVertexLighting } from './runtime/ProbeVertexLighting.js';
export type { ProbeVertexLightingOptions } from './runtime/ProbeVertexLighting.js';
export { ProbeVolumeTexture } from './runtime/ProbeVolumeTexture.js';
export type { ProbeVolumeTextureOptions, BoundsLike } from './runtime/ProbeVolumeTexture.js';
export { ProbeTextureLighting } from './runtime/ProbeTextureLighting.js';
export type { ProbeTextureLightingOptions } from './runtime/ProbeTextureLighting.js';
export { placeFromMeshes } from './placement/placeFromMeshes.js';
export type { PlaceFromMeshesOptions } from './placement/placeFromMeshes.js';
export { gatherWorldGeometry } from './geometry/gatherWorldGeometry.js';
export type { WorldGeometry } from './geometry/gatherWorldGeometry.js';
export { findProbeLocators } from './placement/findProbeLocators.js';
export type { ProbeLocators } from './placement/findProbeLocators.js';

// Baked volumes: the file format (pure codec) and its glTF extension.
export * from './io/index.js';
export { GLTFLightProbeVolumeExporterPlugin, GLTFLightProbeVolumeLoaderPlugin, GLTF_LIGHT_PROBE_VOLUME_EXTENSION } from './io/GLTFLightProbeVolumeExtension.js';
export type { GLTFLightProbeVolumeEntry } from './io/GLTFLightProbeVolumeExtension.js';
