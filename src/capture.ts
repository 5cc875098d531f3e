/**
 * `three-capture-lighting/capture` — GPU capture pieces for tools that drive capture themselves
 * (`LightProbeVolume.capture()` uses them): `ProbeCapturer` renders a cube map per probe and
 * projects it to SH9, `SHProjector` projects cube render targets already rendered, and
 * `projectEquirectToSHGPU` projects a panorama texture. `prepareCaptureScene` makes the changes
 * to a scene that `capture-lighting bake` makes before capturing (shadows on, and the like), so a
 * page's capture gives the SH the CLI bakes. WebGLRenderer (WebGL2).
 */

export { ProbeCapturer } from './capture/ProbeCapturer.js';
export type { ProbeCaptureSettings, ProbeCaptureOptions } from './capture/ProbeCapturer.js';
export { SHProjector } from './capture/SHProjector.js';
export type { SHProjectorOptions } from './capture/SHProjector.js';
export { projectEquirectToSHGPU } from './capture/projectEquirectToSHGPU.js';
export { prepareCaptureScene } from './capture/prepareCaptureScene.js';
export type { CaptureScenePreparation, CaptureLightKind, PreparedCaptureScene } from './capture/prepareCaptureScene.js';
export { CAPTURE_SCENE_DEFAULTS } from './capture/captureSceneDefaults.js';
