// First pass of the GPU SH projection of an equirectangular panorama: like shProjectCube, one
// fragment per block of texels, all nine coefficients. Directions follow three.js's equirectUv
// (u = atan(z, x) / 2π + 0.5, v = asin(y) / π + 0.5 with v measured up the texture), so the SH
// describe the world that three shows when the texture is a scene background; each texel row has
// its exact solid angle.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D panorama;
uniform ivec2 size; // width, height
uniform ivec2 block;
uniform int rowOffset;

#include <shPack>

const float PI = 3.141592653589793;

void main() {

	ivec2 tile = ivec2( gl_FragCoord.xy ) - ivec2( 0, rowOffset );
	int x0 = tile.x * block.x;
	int y0 = tile.y * block.y;
	int x1 = min( x0 + block.x, size.x );
	int y1 = min( y0 + block.y, size.y );
	float columnAngle = 2.0 * PI / float( size.x );

	vec3 s0 = vec3( 0.0 ), s1 = vec3( 0.0 ), s2 = vec3( 0.0 ), s3 = vec3( 0.0 ), s4 = vec3( 0.0 );
	vec3 s5 = vec3( 0.0 ), s6 = vec3( 0.0 ), s7 = vec3( 0.0 ), s8 = vec3( 0.0 );
	for ( int j = y0; j < y1; j ++ ) {

		float bottom = ( float( j ) / float( size.y ) - 0.5 ) * PI;
		float top = ( float( j + 1 ) / float( size.y ) - 0.5 ) * PI;
		float latitude = ( float( j ) + 0.5 ) / float( size.y ) * PI - 0.5 * PI;
		float solidAngle = columnAngle * ( sin( top ) - sin( bottom ) );
		float c = cos( latitude ), h = sin( latitude );
		for ( int i = x0; i < x1; i ++ ) {

			float longitude = ( ( float( i ) + 0.5 ) / float( size.x ) - 0.5 ) * 2.0 * PI;
			vec3 d = vec3( c * cos( longitude ), h, c * sin( longitude ) );
			vec3 radiance = texelFetch( panorama, ivec2( i, j ), 0 ).rgb * solidAngle;
			// three.js SphericalHarmonics3 basis (getBasisAt), constants applied once at the end.
			s0 += radiance;
			s1 += radiance * d.y;
			s2 += radiance * d.z;
			s3 += radiance * d.x;
			s4 += radiance * ( d.x * d.y );
			s5 += radiance * ( d.y * d.z );
			s6 += radiance * ( 3.0 * d.z * d.z - 1.0 );
			s7 += radiance * ( d.x * d.z );
			s8 += radiance * ( d.x * d.x - d.y * d.y );

		}

	}

	writeSums( s0 * 0.282095, s1 * 0.488603, s2 * 0.488603, s3 * 0.488603, s4 * 1.092548,
		s5 * 1.092548, s6 * 0.315392, s7 * 1.092548, s8 * 0.546274 );

}
