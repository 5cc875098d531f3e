// Irradiance E(n) from SH9 packed in 7 vec4 — the 27 floats of three.js SphericalHarmonics3 in
// order plus one unused (the packing of three's LightProbeGrid atlas) — with the same constants as
// SphericalHarmonics3.getIrradianceAt, so it equals the object mode's nᵀMn. Not clamped at zero,
// like the object mode: ringing shows instead of being hidden differently per mode.
vec3 probeVolumeIrradianceFromPacked( const in vec4 s0, const in vec4 s1, const in vec4 s2, const in vec4 s3, const in vec4 s4, const in vec4 s5, const in vec4 s6, const in vec3 n ) {

	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	// A NaN or infinite normal gets the direction-free part of E (see probeVolumeIrradiance).
	vec3 m = abs( dot( n, n ) - 1.0 ) < 0.5 ? n : vec3( 0.0 );
	float x = m.x, y = m.y, z = m.z;
	vec3 result = c0 * 0.886227;
	result += c1 * ( 2.0 * 0.511664 * y );
	result += c2 * ( 2.0 * 0.511664 * z );
	result += c3 * ( 2.0 * 0.511664 * x );
	result += c4 * ( 2.0 * 0.429043 * x * y );
	result += c5 * ( 2.0 * 0.429043 * y * z );
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * ( 2.0 * 0.429043 * x * z );
	result += c8 * ( 0.429043 * ( x * x - y * y ) );
	return result;

}
