// One step of the logarithmic reduction: each output texel is the sum of a factor × factor block
// of the input, for each of the PLANE_COUNT planes this draw writes (shPack). Tiles of the
// projection pass are multiples of the factor, so sums never mix probes.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D source0;
uniform sampler2D source1;
uniform sampler2D source2;
uniform sampler2D source3;
uniform sampler2D source4;
uniform sampler2D source5;
uniform sampler2D source6;
uniform int factor;

layout( location = 0 ) out vec4 out0;
#if PLANE_COUNT > 1
layout( location = 1 ) out vec4 out1;
#endif
#if PLANE_COUNT > 2
layout( location = 2 ) out vec4 out2;
#endif
#if PLANE_COUNT > 3
layout( location = 3 ) out vec4 out3;
#endif
#if PLANE_COUNT > 4
layout( location = 4 ) out vec4 out4;
#endif
#if PLANE_COUNT > 5
layout( location = 5 ) out vec4 out5;
#endif
#if PLANE_COUNT > 6
layout( location = 6 ) out vec4 out6;
#endif

void main() {

	ivec2 origin = ivec2( gl_FragCoord.xy ) * factor;
	vec4 s0 = vec4( 0.0 ), s1 = vec4( 0.0 ), s2 = vec4( 0.0 ), s3 = vec4( 0.0 ), s4 = vec4( 0.0 ), s5 = vec4( 0.0 ), s6 = vec4( 0.0 );
	for ( int j = 0; j < factor; j ++ ) {

		for ( int i = 0; i < factor; i ++ ) {

			ivec2 p = origin + ivec2( i, j );
			s0 += texelFetch( source0, p, 0 );
			#if PLANE_COUNT > 1
			s1 += texelFetch( source1, p, 0 );
			#endif
			#if PLANE_COUNT > 2
			s2 += texelFetch( source2, p, 0 );
			#endif
			#if PLANE_COUNT > 3
			s3 += texelFetch( source3, p, 0 );
			#endif
			#if PLANE_COUNT > 4
			s4 += texelFetch( source4, p, 0 );
			#endif
			#if PLANE_COUNT > 5
			s5 += texelFetch( source5, p, 0 );
			#endif
			#if PLANE_COUNT > 6
			s6 += texelFetch( source6, p, 0 );
			#endif

		}

	}

	out0 = s0;
	#if PLANE_COUNT > 1
	out1 = s1;
	#endif
	#if PLANE_COUNT > 2
	out2 = s2;
	#endif
	#if PLANE_COUNT > 3
	out3 = s3;
	#endif
	#if PLANE_COUNT > 4
	out4 = s4;
	#endif
	#if PLANE_COUNT > 5
	out5 = s5;
	#endif
	#if PLANE_COUNT > 6
	out6 = s6;
	#endif

}
