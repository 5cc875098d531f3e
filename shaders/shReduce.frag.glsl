// One step of the logarithmic reduction: each output texel is the sum of a factor × factor block
// of the input, for each of the four packed targets (or the one of SINGLE_TARGET). Tiles of the
// projection pass are multiples of the factor, so sums never mix halves or probes.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D source0;
uniform int factor;
layout( location = 0 ) out vec4 out0;

#ifndef SINGLE_TARGET

uniform sampler2D source1;
uniform sampler2D source2;
uniform sampler2D source3;
layout( location = 1 ) out vec4 out1;
layout( location = 2 ) out vec4 out2;
layout( location = 3 ) out vec4 out3;

#endif

void main() {

	ivec2 origin = ivec2( gl_FragCoord.xy ) * factor;
	vec4 s0 = vec4( 0.0 );
	#ifndef SINGLE_TARGET
	vec4 s1 = vec4( 0.0 ), s2 = vec4( 0.0 ), s3 = vec4( 0.0 );
	#endif
	for ( int j = 0; j < factor; j ++ ) {

		for ( int i = 0; i < factor; i ++ ) {

			ivec2 p = origin + ivec2( i, j );
			s0 += texelFetch( source0, p, 0 );
			#ifndef SINGLE_TARGET
			s1 += texelFetch( source1, p, 0 );
			s2 += texelFetch( source2, p, 0 );
			s3 += texelFetch( source3, p, 0 );
			#endif

		}

	}

	out0 = s0;
	#ifndef SINGLE_TARGET
	out1 = s1; out2 = s2; out3 = s3;
	#endif

}
