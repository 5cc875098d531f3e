#include <lights_fragment_begin>
#include <probeVolumeDirectScale>
#if defined( RE_IndirectDiffuse )
	irradiance += probeVolumeTextureIrradiance(
		( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz,
		normalize( ( vec4( geometryNormal, 0.0 ) * viewMatrix ).xyz ) );
#endif
