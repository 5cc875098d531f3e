/**
 * `three-capture-lighting/format` — the baked light-probe-volume codec (no three.js): the
 * versioned little-endian binary form and its JSON mirror, both validated field by field on
 * load (layout and rules: docs/format.md). `LightProbeVolumeExporter` /
 * `LightProbeVolumeLoader` use it; import it directly for tools that read or write files without a
 * renderer.
 */

export {
	encodeBakedVolume, decodeBakedVolume, bakedVolumeToJSON, bakedVolumeFromJSON, validateBakedVolume,
	BAKED_VOLUME_JSON_FORMAT, BAKED_VOLUME_VERSION_MAJOR, BAKED_VOLUME_VERSION_MINOR,
	type BakedVolumeData, type BakedVolumeInput, type BakedVolumeJSON, type BakedZone, type BakedCapture, type BakedCaptureSettings,
	type BakedProbeRole, type EncodeBakedVolumeOptions, type BakedFit,
} from './io/index.js';
export { BakedVolumeError, type BakedVolumeErrorCode } from './io/BakedVolumeError.js';
