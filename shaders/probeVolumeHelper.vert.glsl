// LightProbeVolumeHelper: one sphere per probe (an InstancedMesh); the probe's SH arrive as 7 packed
// vec4 per instance (the 27 floats of three's SphericalHarmonics3 plus one unused) and go on to the
// fragment stage unchanged, which evaluates them for the world normal of each pixel.
attribute vec4 probeSH0;
attribute vec4 probeSH1;
attribute vec4 probeSH2;
attribute vec4 probeSH3;
attribute vec4 probeSH4;
attribute vec4 probeSH5;
attribute vec4 probeSH6;
varying vec4 vProbeSH0;
varying vec4 vProbeSH1;
varying vec4 vProbeSH2;
varying vec4 vProbeSH3;
varying vec4 vProbeSH4;
varying vec4 vProbeSH5;
varying vec4 vProbeSH6;
varying vec3 vWorldNormal;

void main() {

	vProbeSH0 = probeSH0; vProbeSH1 = probeSH1; vProbeSH2 = probeSH2; vProbeSH3 = probeSH3;
	vProbeSH4 = probeSH4; vProbeSH5 = probeSH5; vProbeSH6 = probeSH6;
	// Instance matrices are a translation and a uniform scale: the sphere's normal turns only with the
	// helper's own matrix (kept free of shear: probe positions are world positions).
	vWorldNormal = mat3( modelMatrix ) * normal;
	gl_Position = projectionMatrix * modelViewMatrix * instanceMatrix * vec4( position, 1.0 );

}
