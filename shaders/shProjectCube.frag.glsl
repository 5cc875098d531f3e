// First pass of the GPU SH projection of a cube map (paper 2.2): each fragment integrates half of
// the 9 SH coefficients (5 or 4) over one block of texels, on all six faces, as
// Σ L(ω)·Y_k(ω)·Ω(texel), reading each texel once. The output is a tiles × tiles grid per half,
// the two halves side by side, one row block per probe, in four float targets (shPack);
// shReduce.frag.glsl then sums each grid down to one texel.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform samplerCube cubeMap; // NEAREST filtering: every lookup below hits one texel centre exactly
uniform sampler2D solidAngles; // size × size texel solid angles, the same on every face
uniform int size;
uniform int tiles;
uniform int block;
uniform int rowOffset;

#include <shBasis>
#include <shPack>

// The direction through the centre of texel (s, t) of a face, s, t in (−1, 1): the inverse of the
// OpenGL ES 3.0 cube map face selection (section 3.8.10), so texture() lands on that very texel.
vec3 faceDirection( const in int face, const in float s, const in float t ) {

	if ( face == 0 ) return vec3( 1.0, - t, - s );
	if ( face == 1 ) return vec3( - 1.0, - t, s );
	if ( face == 2 ) return vec3( s, 1.0, t );
	if ( face == 3 ) return vec3( s, - 1.0, - t );
	if ( face == 4 ) return vec3( s, - t, 1.0 );
	return vec3( - s, - t, - 1.0 );

}

void main() {

	ivec2 pixel = ivec2( gl_FragCoord.xy ) - ivec2( 0, rowOffset );
	int half_ = pixel.x / tiles;
	int x0 = ( pixel.x - half_ * tiles ) * block;
	int y0 = pixel.y * block;
	int x1 = min( x0 + block, size );
	int y1 = min( y0 + block, size );
	float texel = 2.0 / float( size );

	vec3 s0 = vec3( 0.0 ), s1 = vec3( 0.0 ), s2 = vec3( 0.0 ), s3 = vec3( 0.0 ), s4 = vec3( 0.0 );
	for ( int face = 0; face < 6; face ++ ) {

		for ( int j = y0; j < y1; j ++ ) {

			float t = ( float( j ) + 0.5 ) * texel - 1.0;
			for ( int i = x0; i < x1; i ++ ) {

				float s = ( float( i ) + 0.5 ) * texel - 1.0;
				vec3 direction = faceDirection( face, s, t );
				vec3 radiance = texture( cubeMap, direction ).rgb * texelFetch( solidAngles, ivec2( i, j ), 0 ).r;
				accumulateHalf( half_, radiance, normalize( direction ), s0, s1, s2, s3, s4 );

			}

		}

	}

	writeSums( s0, s1, s2, s3, s4 );

}
