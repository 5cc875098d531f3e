#include <lights_fragment_begin>
#include <probeVolumeDirectScale>
#if defined( RE_IndirectDiffuse )
	irradiance += probeVolumeIrradiance( normalize( ( vec4( geometryNormal, 0.0 ) * viewMatrix ).xyz ) );
#endif
