import type { BakedVolumeData } from '../io/index.js';

/**
 * Name of the glTF extension that carries baked light probe volumes (docs/format.md, "glTF"):
 * a vendor extension of this library (prefix CBL, Capture Based Lighting; not registered with Khronos).
 * At the root: `extensions.CBL_light_probe_volume = { volumes: [ { name, bufferView } ] }`, each
 * bufferView holding one file in the binary format, positions in the glTF scene's world space.
 */
export const GLTF_LIGHT_PROBE_VOLUME_EXTENSION = 'CBL_light_probe_volume';

/** One volume to write into, or read from, a glTF file. */
export interface GLTFLightProbeVolumeEntry<T = BakedVolumeData> {

	/** Name of the volume in the file ('' when none). */
	name: string;

	/** The volume. */
	data: T;

}
