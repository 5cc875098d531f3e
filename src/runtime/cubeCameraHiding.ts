import type { BufferGeometry, Camera, LineSegments, Material } from 'three';

/*
 * LightProbeVolumeHelper's parts stay out of cube-camera renders — the volume's captures (and
 * reflection probes) — so that adding the helper to the scene before a capture needs no `exclude`.
 * They are skipped in their own onBeforeRender, which runs for every camera just before the draw.
 */

/** Whether `camera` renders a face of a `CubeCamera` (the capture's six cameras are its children). */
export function isCubeFace( camera: Camera ): boolean {

	return camera.parent !== null && camera.parent.type === 'CubeCamera';

}

/** Makes `lines` draw nothing for cube cameras: an empty draw range for that draw, restored after it. */
export function hideLinesFromCubeCameras( lines: LineSegments<BufferGeometry, Material> ): void {

	let hiddenCount = - 1;
	lines.onBeforeRender = ( _renderer, _scene, camera, geometry ) => {

		if ( ! isCubeFace( camera ) ) return;
		hiddenCount = geometry.drawRange.count;
		geometry.drawRange.count = 0;

	};

	lines.onAfterRender = ( _renderer, _scene, _camera, geometry ) => {

		if ( hiddenCount < 0 ) return;
		geometry.drawRange.count = hiddenCount;
		hiddenCount = - 1;

	};

}
