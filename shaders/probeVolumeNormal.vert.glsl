#include <defaultnormal_vertex>
vProbeVolumeIrradiance = probeVolumeIrradiance( normalize( transformedNormal ) );
