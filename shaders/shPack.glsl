// Nine RGB sums packed into seven RGBA planes, the 27 floats in order (coefficient-major, RGB) and
// one unused: the reduction adds planes component-wise, so the packing survives it unchanged. A
// draw writes PLANE_COUNT planes from PLANE_FIRST: all seven where the renderer has the draw
// buffers, fewer per draw where it has not, one per draw where multiple targets do not work
// (headless-gl).
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

// Plane `plane` of the packing; called with constants only, so it folds to one swizzle.
vec4 packedPlane( const in int plane, const in vec3 s0, const in vec3 s1, const in vec3 s2, const in vec3 s3, const in vec3 s4,
	const in vec3 s5, const in vec3 s6, const in vec3 s7, const in vec3 s8 ) {

	if ( plane == 0 ) return vec4( s0, s1.r );
	if ( plane == 1 ) return vec4( s1.gb, s2.rg );
	if ( plane == 2 ) return vec4( s2.b, s3 );
	if ( plane == 3 ) return vec4( s4, s5.r );
	if ( plane == 4 ) return vec4( s5.gb, s6.rg );
	if ( plane == 5 ) return vec4( s6.b, s7 );
	return vec4( s8, 0.0 );

}

void writeSums( const in vec3 s0, const in vec3 s1, const in vec3 s2, const in vec3 s3, const in vec3 s4,
	const in vec3 s5, const in vec3 s6, const in vec3 s7, const in vec3 s8 ) {

	out0 = packedPlane( PLANE_FIRST, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#if PLANE_COUNT > 1
	out1 = packedPlane( PLANE_FIRST + 1, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#endif
	#if PLANE_COUNT > 2
	out2 = packedPlane( PLANE_FIRST + 2, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#endif
	#if PLANE_COUNT > 3
	out3 = packedPlane( PLANE_FIRST + 3, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#endif
	#if PLANE_COUNT > 4
	out4 = packedPlane( PLANE_FIRST + 4, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#endif
	#if PLANE_COUNT > 5
	out5 = packedPlane( PLANE_FIRST + 5, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#endif
	#if PLANE_COUNT > 6
	out6 = packedPlane( PLANE_FIRST + 6, s0, s1, s2, s3, s4, s5, s6, s7, s8 );
	#endif

}
