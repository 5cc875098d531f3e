#include <lights_fragment_begin>
#include <probeVolumeDirectScale>
#if defined( RE_IndirectDiffuse )
	irradiance += probeVolumeIrradiance( geometryNormal );
#endif
