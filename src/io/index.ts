/*
 * The baked-volume codec (no three.js): binary and JSON forms of a baked light probe volume.
 * The glTF plugins, which need three.js, are in src/gltf/.
 */
export { encodeBakedVolume } from './encodeBakedVolume.js';
export { decodeBakedVolume } from './decodeBakedVolume.js';
export { bakedVolumeToJSON, bakedVolumeFromJSON } from './bakedVolumeJSON.js';
export { validateBakedVolume } from './validateBakedVolume.js';
export {
	BAKED_ROLES, BAKED_SECTION, BAKED_VOLUME_MAGIC, BAKED_VOLUME_JSON_FORMAT, BAKED_VOLUME_VERSION_MAJOR, BAKED_VOLUME_VERSION_MINOR,
} from './bakedVolumeFormat.js';
export type {
	BakedVolumeData, BakedVolumeInput, BakedVolumeJSON, BakedZone, BakedCapture, BakedCaptureSettings,
	BakedProbeRole, BakedFit, EncodeBakedVolumeOptions,
} from './bakedVolumeTypes.js';
export { BakedVolumeError, type BakedVolumeErrorCode } from './BakedVolumeError.js';
export { crc32 } from './crc32.js';
export { toFloat16Bits, fromFloat16Bits, FLOAT16_MAX } from './float16.js';
