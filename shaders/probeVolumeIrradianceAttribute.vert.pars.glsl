uniform float probeVolumeIntensity;
attribute vec3 probeIrradiance;
varying vec3 vProbeVolumeIrradiance;
