import { shadingSuite } from './webgpuShadingSuite.js';

// Node-material shading on WebGPURenderer's WebGPU backend (SwiftShader's adapter); the WebGL2
// backend runs the same suite in webgpuShadingWebGL2.test.ts.
shadingSuite( 'webgpu' );
