// Five RGB sums packed into four RGBA outputs, 15 floats in order (coefficient-major, RGB):
// the reduction adds outputs component-wise, so the packing survives it unchanged. Where multiple
// render targets do not work (headless-gl), SINGLE_TARGET writes one of the four per draw.
#ifdef SINGLE_TARGET

uniform int outputIndex;
layout( location = 0 ) out vec4 out0;

void writeSums( const in vec3 s0, const in vec3 s1, const in vec3 s2, const in vec3 s3, const in vec3 s4 ) {

	if ( outputIndex == 0 ) out0 = vec4( s0, s1.r );
	else if ( outputIndex == 1 ) out0 = vec4( s1.gb, s2.rg );
	else if ( outputIndex == 2 ) out0 = vec4( s2.b, s3 );
	else out0 = vec4( s4, 0.0 );

}

#else

layout( location = 0 ) out vec4 out0;
layout( location = 1 ) out vec4 out1;
layout( location = 2 ) out vec4 out2;
layout( location = 3 ) out vec4 out3;

void writeSums( const in vec3 s0, const in vec3 s1, const in vec3 s2, const in vec3 s3, const in vec3 s4 ) {

	out0 = vec4( s0, s1.r );
	out1 = vec4( s1.gb, s2.rg );
	out2 = vec4( s2.b, s3 );
	out3 = vec4( s4, 0.0 );

}

#endif
