// First pass of the GPU SH projection of an equirectangular panorama: like shProjectCube, one
// fragment per (half of the coefficients, block). Directions follow three.js's equirectUv
// (u = atan(z, x) / 2π + 0.5, v = asin(y) / π + 0.5 with v measured up the texture), so the SH
// describe the world that three shows when the texture is a scene background; each texel row has
// its exact solid angle.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D panorama;
uniform ivec2 size; // width, height
uniform int tiles;
uniform ivec2 block;
uniform int rowOffset;

#include <shBasis>
#include <shPack>

const float PI = 3.141592653589793;

void main() {

	ivec2 pixel = ivec2( gl_FragCoord.xy ) - ivec2( 0, rowOffset );
	int half_ = pixel.x / tiles;
	int x0 = ( pixel.x - half_ * tiles ) * block.x;
	int y0 = pixel.y * block.y;
	int x1 = min( x0 + block.x, size.x );
	int y1 = min( y0 + block.y, size.y );
	float columnAngle = 2.0 * PI / float( size.x );

	vec3 s0 = vec3( 0.0 ), s1 = vec3( 0.0 ), s2 = vec3( 0.0 ), s3 = vec3( 0.0 ), s4 = vec3( 0.0 );
	for ( int j = y0; j < y1; j ++ ) {

		float bottom = ( float( j ) / float( size.y ) - 0.5 ) * PI;
		float top = ( float( j + 1 ) / float( size.y ) - 0.5 ) * PI;
		float latitude = ( float( j ) + 0.5 ) / float( size.y ) * PI - 0.5 * PI;
		float solidAngle = columnAngle * ( sin( top ) - sin( bottom ) );
		float c = cos( latitude ), h = sin( latitude );
		for ( int i = x0; i < x1; i ++ ) {

			float longitude = ( ( float( i ) + 0.5 ) / float( size.x ) - 0.5 ) * 2.0 * PI;
			vec3 direction = vec3( c * cos( longitude ), h, c * sin( longitude ) );
			vec3 radiance = texelFetch( panorama, ivec2( i, j ), 0 ).rgb * solidAngle;
			accumulateHalf( half_, radiance, direction, s0, s1, s2, s3, s4 );

		}

	}

	writeSums( s0, s1, s2, s3, s4 );

}
