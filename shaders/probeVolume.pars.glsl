// Irradiance from the probe volume for one object: the paper's quadratic form E(n) = nᵀ M n
// (Ramamoorthi & Hanrahan 2001), rewritten per draw for the unit view-space normal v = (x, y, z)
// that three's shaders already hold (viewIrradiance.ts): nine RGB coefficients of 1, x, y, z, x²,
// y², xy, xz, yz, scaled by the intensity. No transform back to world space, no normalisation.
uniform vec3 probeVolumeViewIrradiance[ 9 ];

vec3 probeVolumeIrradiance( const in vec3 viewNormal ) {

	// No guard against a NaN normal (unlike probeVolumeIrradianceFromPacked): a select on the normal
	// in this path, the one every character and prop takes, made the 500-sphere frame bench ~1.5×
	// slower in SwiftShader. A NaN (zero) normal gives a NaN probe term, as with three's LightProbe.
	float x = viewNormal.x, y = viewNormal.y, z = viewNormal.z;
	vec3 e = probeVolumeViewIrradiance[ 0 ];
	e += probeVolumeViewIrradiance[ 1 ] * x;
	e += probeVolumeViewIrradiance[ 2 ] * y;
	e += probeVolumeViewIrradiance[ 3 ] * z;
	e += probeVolumeViewIrradiance[ 4 ] * ( x * x );
	e += probeVolumeViewIrradiance[ 5 ] * ( y * y );
	e += probeVolumeViewIrradiance[ 6 ] * ( x * y );
	e += probeVolumeViewIrradiance[ 7 ] * ( x * z );
	e += probeVolumeViewIrradiance[ 8 ] * ( y * z );
	return e;

}
