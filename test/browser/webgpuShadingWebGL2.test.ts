import { shadingSuite } from './webgpuShadingSuite.js';

// Node-material shading on WebGPURenderer's WebGL2 backend (`forceWebGL: true`); the WebGPU
// backend runs the same suite in webgpuShading.test.ts.
shadingSuite( 'webgl2' );
