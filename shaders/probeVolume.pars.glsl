// Irradiance from the probe volume, the paper's quadratic form E(n) = nᵀ M n with n = (x, y, z, 1)
// (Ramamoorthi & Hanrahan 2001): one 4x4 M per colour channel, set per object from the blended SH.
uniform mat4 probeVolumeMatrices[ 3 ];
uniform float probeVolumeIntensity;

vec3 probeVolumeIrradiance( const in vec3 worldNormal ) {

	// No guard against a NaN normal here, unlike probeVolumeIrradianceFromPacked: in this per-object
	// path, the one every character and prop takes, a select on the normal made the 500-sphere frame
	// benchmark 1.63× a global LightProbe instead of 1.10× in SwiftShader. A NaN normal (a zero
	// normal) gives a NaN probe term here exactly as it does with three's own LightProbe.
	vec4 n = vec4( worldNormal, 1.0 );
	return probeVolumeIntensity * vec3(
		dot( n, probeVolumeMatrices[ 0 ] * n ),
		dot( n, probeVolumeMatrices[ 1 ] * n ),
		dot( n, probeVolumeMatrices[ 2 ] * n )
	);

}
