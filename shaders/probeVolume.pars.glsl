// Irradiance from the probe volume, the paper's quadratic form E(n) = nᵀ M n with n = (x, y, z, 1)
// (Ramamoorthi & Hanrahan 2001): one 4x4 M per colour channel, set per object from the blended SH.
uniform mat4 probeVolumeMatrices[ 3 ];
uniform float probeVolumeIntensity;

vec3 probeVolumeIrradiance( const in vec3 worldNormal ) {

	// A NaN or infinite normal (normalize of a zero vector: a zero normal, a bump map on a
	// degenerate triangle) would make the whole probe term NaN; such a point gets the
	// direction-free part of E instead.
	vec4 n = vec4( abs( dot( worldNormal, worldNormal ) - 1.0 ) < 0.5 ? worldNormal : vec3( 0.0 ), 1.0 );
	return probeVolumeIntensity * vec3(
		dot( n, probeVolumeMatrices[ 0 ] * n ),
		dot( n, probeVolumeMatrices[ 1 ] * n ),
		dot( n, probeVolumeMatrices[ 2 ] * n )
	);

}
