/** Installs WebGPURenderer capture for LightProbeVolume (issue 15; filled by the capture work). */
export {};
