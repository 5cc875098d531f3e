#include <defaultnormal_vertex>
vProbeVolumeIrradiance = probeVolumeIntensity * probeIrradiance;
