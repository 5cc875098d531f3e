// Per-pixel probe light from a 3D texture resampled from the tetrahedral field over an object's
// bounds (ProbeVolumeTexture). The texture uses three.js LightProbeGrid's atlas layout: 7 packed SH
// sub-volumes stacked along z, each with one padding slice at both ends so the hardware trilinear
// filter never blends two sub-volumes. Grid nodes sit at texel centres; probeVolumeGridMin / Max
// are the world positions of the first and last node.
#include <probeVolumeSHEval>
uniform highp sampler3D probeVolumeSH;
uniform vec3 probeVolumeGridMin;
uniform vec3 probeVolumeGridMax;
uniform vec3 probeVolumeGridResolution;
uniform float probeVolumeIntensity;

vec3 probeVolumeTextureIrradiance( const in vec3 worldPosition, const in vec3 worldNormal ) {

	vec3 res = probeVolumeGridResolution;
	vec3 uvw = ( ( worldPosition - probeVolumeGridMin ) / ( probeVolumeGridMax - probeVolumeGridMin ) * ( res - 1.0 ) + 0.5 ) / res;
	// Outside the bounds the light stays that of the nearest face, as outside the probes' hull.
	uvw = clamp( uvw, 0.5 / res, 1.0 - 0.5 / res );
	float padded = res.z + 2.0;
	float depth = 7.0 * padded;
	float z = uvw.z * res.z + 1.0;
	vec4 s0 = texture( probeVolumeSH, vec3( uvw.xy, z / depth ) );
	vec4 s1 = texture( probeVolumeSH, vec3( uvw.xy, ( z + padded ) / depth ) );
	vec4 s2 = texture( probeVolumeSH, vec3( uvw.xy, ( z + 2.0 * padded ) / depth ) );
	vec4 s3 = texture( probeVolumeSH, vec3( uvw.xy, ( z + 3.0 * padded ) / depth ) );
	vec4 s4 = texture( probeVolumeSH, vec3( uvw.xy, ( z + 4.0 * padded ) / depth ) );
	vec4 s5 = texture( probeVolumeSH, vec3( uvw.xy, ( z + 5.0 * padded ) / depth ) );
	vec4 s6 = texture( probeVolumeSH, vec3( uvw.xy, ( z + 6.0 * padded ) / depth ) );
	return probeVolumeIntensity * probeVolumeIrradianceFromPacked( s0, s1, s2, s3, s4, s5, s6, worldNormal );

}
