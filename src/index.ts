/**
 * three-capture-lighting — capture-based indirect lighting for three.js (WebGLRenderer).
 *
 * This entry holds what a game needs: {@link LightProbeVolume} (place, capture, bake, light
 * objects), the material patch for objects managed by hand, the placement tools, the glTF
 * plugins for baked volumes and the error classes. Specialised pieces are subpath entries:
 * - `three-capture-lighting/math` — SH projection and irradiance, the exact tetrahedralization,
 *   the interpolators and `blendSH`, geometry queries, `irradianceError` (no three.js);
 * - `three-capture-lighting/format` — the baked-volume codec (no three.js);
 * - `three-capture-lighting/capture` — `ProbeCapturer`, `SHProjector`, GPU panorama projection;
 * - `three-capture-lighting/lightProbeGrid` — feeding three's own `LightProbeGridWebGL` (r186+).
 */

export { LightProbeVolume } from './runtime/LightProbeVolume.js';
export type {
	AddOptions, AddProbeOptions, LightProbeVolumeBounceOptions, LightProbeVolumeCaptureOptions, LightProbeVolumeParameters,
	ProbeLighting, ProbeLightingChoice, ProbeOccluders, ProbePosition, ProbeRole, SampleOptions,
} from './runtime/LightProbeVolumeOptions.js';
export type { LightProbeVolumeFitOptions } from './runtime/fitVolume.js';
export type { FromSceneOptions, FromSceneProgress, FromSceneStage } from './runtime/volumeFromScene.js';
export type { CaptureProgressCallback, CaptureStage } from './runtime/captureProbes.js';
export { LightProbeVolumeLoader } from './runtime/LightProbeVolumeLoader.js';
export type { LightProbeVolumeData, BakedVolumeParameters } from './runtime/LightProbeVolumeLoader.js';
export { LightProbeVolumeExporter } from './runtime/LightProbeVolumeExporter.js';
export type {
	LightProbeVolumeExporterOptions, LightProbeVolumeBinaryOptions, LightProbeVolumeJSONOptions,
} from './runtime/LightProbeVolumeExporter.js';
export { captureBounces } from './runtime/captureBounces.js';
export type { CaptureBouncesOptions, CaptureBouncesResult, BouncePass } from './runtime/captureBounces.js';
export { VisibilityGuard } from './runtime/VisibilityGuard.js';
export type { VisibilityGuardOptions } from './runtime/VisibilityGuard.js';
export type { ProbeZoneDefinition, BoxLike } from './runtime/ProbeZones.js';

// Seeing the probes: spheres shaded by their SH, the cells, the cell an object is lit from.
export { LightProbeVolumeHelper } from './runtime/LightProbeVolumeHelper.js';
export type { HighlightTarget } from './runtime/ProbeCellHighlight.js';

// Objects managed by hand, and large objects lit per vertex or per texel (`add( object, { mode } )` uses these).
export { patchMaterial, unpatchMaterial, getProbeVolumeUniforms } from './runtime/patchMaterial.js';
export { isProbeLitMaterial } from './runtime/probeLitMaterials.js';
export type { PatchMaterialOptions, ProbeVolumeUniforms, ProbeVolumeSource } from './runtime/patchMaterial.js';
export { ProbeVertexLighting } from './runtime/ProbeVertexLighting.js';
export type { ProbeVertexLightingOptions } from './runtime/ProbeVertexLighting.js';
export { ProbeTextureLighting } from './runtime/ProbeTextureLighting.js';
export type { ProbeTextureLightingOptions } from './runtime/ProbeTextureLighting.js';
export { ProbeVolumeTexture } from './runtime/ProbeVolumeTexture.js';
export type { ProbeVolumeTextureOptions, BoundsLike } from './runtime/ProbeVolumeTexture.js';
export type { ProbeField } from './runtime/ProbeField.js';

// Probe placement: one call (placeProbes), or the steps it runs.
export { placeProbes } from './runtime/placeProbes.js';
export type { PlaceProbesOptions, PlaceProbesResult } from './runtime/placeProbes.js';
export type { PointList } from './placement/readPointList.js';
export { placeGrid } from './placement/placeGrid.js';
export { placeFromMeshes } from './placement/placeFromMeshes.js';
export type { PlaceFromMeshesOptions } from './placement/placeFromMeshes.js';
export { findProbeLocators } from './placement/findProbeLocators.js';
export type { ProbeLocators } from './placement/findProbeLocators.js';
export { candidatesFromVertices } from './placement/candidatesFromVertices.js';
export type { CandidatesFromVerticesOptions } from './placement/candidatesFromVertices.js';
export { reduceProbes } from './placement/reduceProbes.js';
export type { ReduceProbesOptions, ReduceProbesResult } from './placement/reduceProbes.js';
export { regionWeights } from './placement/regionOfInterest.js';
export type { RegionOfInterest, RegionBox } from './placement/regionOfInterest.js';
export { WalkableRegion } from './placement/walkableRegion.js';
export type { WalkableRegionOptions } from './placement/walkableRegion.js';

// Baked volumes inside glTF files.
export { GLTFLightProbeVolumeExporterPlugin } from './gltf/GLTFLightProbeVolumeExporterPlugin.js';
export { GLTFLightProbeVolumeLoaderPlugin } from './gltf/GLTFLightProbeVolumeLoaderPlugin.js';
export { GLTF_LIGHT_PROBE_VOLUME_EXTENSION } from './gltf/GLTFLightProbeVolumeExtension.js';
export type { GLTFLightProbeVolumeEntry } from './gltf/GLTFLightProbeVolumeExtension.js';

// Errors.
export { DegenerateInputError } from './tetrahedra/tetrahedralize.js';
export type { DegenerateReason } from './tetrahedra/tetrahedralize.js';
export { BakedVolumeError } from './io/BakedVolumeError.js';
export type { BakedFit } from './io/index.js';
export type { BakedVolumeErrorCode } from './io/BakedVolumeError.js';
