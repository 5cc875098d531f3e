// LightProbeVolumeHelper: a white Lambertian sphere lit by its probe alone shows the outgoing
// radiance E(n) / π for each world normal n, as three's LightProbeHelper draws a LightProbe; then
// three's tone mapping and output colour space, as its built-in materials apply them.
#include <probeVolumeSHEval>
varying vec4 vProbeSH0;
varying vec4 vProbeSH1;
varying vec4 vProbeSH2;
varying vec4 vProbeSH3;
varying vec4 vProbeSH4;
varying vec4 vProbeSH5;
varying vec4 vProbeSH6;
varying vec3 vWorldNormal;

void main() {

	vec3 irradiance = probeVolumeIrradianceFromPacked(
		vProbeSH0, vProbeSH1, vProbeSH2, vProbeSH3, vProbeSH4, vProbeSH5, vProbeSH6, normalize( vWorldNormal ) );
	// Negative irradiance (SH ringing) shows black rather than passing negative values to tone mapping.
	gl_FragColor = vec4( max( irradiance, vec3( 0.0 ) ) * 0.3183098861837907, 1.0 );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>

}
