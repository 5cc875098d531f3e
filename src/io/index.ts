/*
 * The baked-volume codec (no three.js): binary and JSON forms of a baked light probe volume.
 * The glTF plugins, which need three.js, are in GLTFLightProbeVolumeExtension.ts.
 */
export {
	encodeBakedVolume, decodeBakedVolume, bakedVolumeToJSON, bakedVolumeFromJSON, validateBakedVolume,
	BAKED_ROLES, BAKED_SECTION, BAKED_VOLUME_MAGIC, BAKED_VOLUME_JSON_FORMAT, BAKED_VOLUME_VERSION_MAJOR, BAKED_VOLUME_VERSION_MINOR,
	type BakedVolumeData, type BakedVolumeInput, type BakedVolumeJSON, type BakedZone, type BakedCapture, type BakedCaptureSettings,
	type BakedProbeRole, type EncodeBakedVolumeOptions,
} from './BakedVolume.js';
export { BakedVolumeError, type BakedVolumeErrorCode } from './BakedVolumeError.js';
export { crc32 } from './crc32.js';
export { toFloat16Bits, fromFloat16Bits, FLOAT16_MAX } from './float16.js';
