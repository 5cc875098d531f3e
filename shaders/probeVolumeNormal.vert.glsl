#include <defaultnormal_vertex>
vProbeVolumeIrradiance = probeVolumeIrradiance( normalize( ( vec4( transformedNormal, 0.0 ) * viewMatrix ).xyz ) );
