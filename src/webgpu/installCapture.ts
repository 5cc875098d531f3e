import type { Texture, WebGPURenderer } from 'three/webgpu';
import { installWebGPUCapture } from '../capture/captureBackends.js';
import { WebGPUProbeCapturer } from './capture/WebGPUProbeCapturer.js';
import { projectEquirectWebGPU } from './capture/projectEquirectWebGPU.js';

/*
 * Installs WebGPURenderer capture for LightProbeVolume (imported by the `three-capture-lighting/webgpu`
 * entry): `capture`, `recaptureDirty`, `fromScene`, `placeProbes`, the bounce passes and
 * `projectEquirectToSHGPU` then take a WebGPURenderer, on its WebGPU backend or its WebGL2 fallback.
 */
installWebGPUCapture( {
	createCapturer: ( renderer, settings ) => new WebGPUProbeCapturer( renderer as unknown as WebGPURenderer, settings ),
	projectEquirect: ( renderer, texture, target ) => projectEquirectWebGPU(
		renderer as unknown as WebGPURenderer, texture as unknown as Texture, target,
	),
} );
