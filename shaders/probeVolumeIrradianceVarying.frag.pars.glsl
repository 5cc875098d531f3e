uniform float probeVolumeDirectScale;
varying vec3 vProbeVolumeIrradiance;
