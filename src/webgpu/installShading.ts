/** Installs node-material (TSL) shading for LightProbeVolume (issue 15; filled by the shading work). */
export {};
