// Per-vertex SH (ProbeVertexLighting, output 'sh'): the field's SH at each vertex in 7 packed vec4
// attributes, interpolated across triangles and evaluated per pixel with the shaded normal, so
// normal and bump maps still respond. Fragment-side declarations; the vertex side passes them on.
#include <probeVolumeSHEval>
uniform float probeVolumeIntensity;
varying vec4 vProbeSH0;
varying vec4 vProbeSH1;
varying vec4 vProbeSH2;
varying vec4 vProbeSH3;
varying vec4 vProbeSH4;
varying vec4 vProbeSH5;
varying vec4 vProbeSH6;

vec3 probeVolumeVertexSHIrradiance( const in vec3 worldNormal ) {

	return probeVolumeIntensity * probeVolumeIrradianceFromPacked( vProbeSH0, vProbeSH1, vProbeSH2, vProbeSH3, vProbeSH4, vProbeSH5, vProbeSH6, worldNormal );

}
