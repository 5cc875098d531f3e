import { LightProbeGridWebGL } from 'three/examples/jsm/lighting/LightProbeGridWebGL.js';
import type { ProbeVolumeTexture } from './ProbeVolumeTexture.js';

/**
 * A three.js `LightProbeGridWebGL` that shows a {@link ProbeVolumeTexture} — the tetrahedral field
 * resampled on a grid — through three's built-in per-pixel light-probe-grid path, with no bake:
 * add it to the scene and every lit material whose fragments fall inside its box is shaded from it
 * by `WebGLRenderer` itself (no patched materials).
 *
 * This works because the texture is written in three's atlas layout (7 packed SH sub-volumes along
 * z, padded) with the same SH convention, and the grid's cells are placed so that its probes (cell
 * centres) are the texture's nodes: the box is the nodes' box grown by half a node spacing.
 *
 * Differences from {@link ProbeTextureLighting} (the library's own path over the same texture):
 * three samples half a node spacing along the normal (against self-occlusion in baked grids) and
 * clamps irradiance at zero; it lights *every* lit object inside the box (it is a scene light,
 * not per object — a character walking on the floor gets it on top of its own probe light, so
 * keep the box tight or the character's material unpatched); `probeVolumeIntensity` and the
 * direct-light scale do not apply. Do not call the grid's `bake()` (it would replace the texture).
 * The grid does not own the texture: dispose the `ProbeVolumeTexture` yourself; after it is
 * resampled over new bounds (`setBounds`), call this again or update the grid's box.
 *
 * @param volumeTexture The resampled texture.
 * @param target A grid to configure instead of a new one.
 * @returns The configured grid; add it to the scene.
 */
export function toLightProbeGrid(
	volumeTexture: ProbeVolumeTexture, target: LightProbeGridWebGL = new LightProbeGridWebGL(),
): LightProbeGridWebGL {

	if ( ! volumeTexture || ! ( volumeTexture as { texture?: { isData3DTexture?: boolean } } ).texture?.isData3DTexture ) {

		throw new TypeError( 'toLightProbeGrid: volumeTexture must be a ProbeVolumeTexture.' );

	}

	if ( ( target as { isLightProbeGrid?: boolean } )?.isLightProbeGrid !== true ) throw new TypeError( 'toLightProbeGrid: target must be a LightProbeGridWebGL.' );
	const { min, max, resolution } = volumeTexture;
	const spacing = [
		( max.x - min.x ) / ( resolution.x - 1 ), ( max.y - min.y ) / ( resolution.y - 1 ), ( max.z - min.z ) / ( resolution.z - 1 ),
	];
	target.width = max.x - min.x + spacing[ 0 ];
	target.height = max.y - min.y + spacing[ 1 ];
	target.depth = max.z - min.z + spacing[ 2 ];
	target.resolution.copy( resolution );
	target.position.set( ( min.x + max.x ) / 2, ( min.y + max.y ) / 2, ( min.z + max.z ) / 2 );
	target.updateBoundingBox();
	target.updateMatrixWorld();
	target.texture = volumeTexture.texture;
	return target;

}
