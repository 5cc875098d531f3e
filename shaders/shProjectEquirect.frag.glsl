// First pass of the GPU SH projection of an equirectangular panorama: like shProjectCube, one
// fragment per block of texels, all nine coefficients. Directions follow three.js's equirectUv
// (u = atan(z, x) / 2π + 0.5, v = asin(y) / π + 0.5 with v measured up the texture), so the SH
// describe the world that three shows when the texture is a scene background; each texel row has
// its exact solid angle. Directions and solid angles come from a table computed in float64 on the
// CPU (createEquirectTableTexture), not from the GPU's sin / cos, which are too coarse.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D panorama;
// Row 0: ( cos φ, sin φ ) per column; row 1: ( sin lat, cos lat, solid angle ) per texel row.
uniform sampler2D directions;
uniform ivec2 size; // width, height
uniform ivec2 block;
uniform int rowOffset;

#include <shPack>

void main() {

	ivec2 tile = ivec2( gl_FragCoord.xy ) - ivec2( 0, rowOffset );
	int x0 = tile.x * block.x;
	int y0 = tile.y * block.y;
	int x1 = min( x0 + block.x, size.x );
	int y1 = min( y0 + block.y, size.y );

	vec3 s0 = vec3( 0.0 ), s1 = vec3( 0.0 ), s2 = vec3( 0.0 ), s3 = vec3( 0.0 ), s4 = vec3( 0.0 );
	vec3 s5 = vec3( 0.0 ), s6 = vec3( 0.0 ), s7 = vec3( 0.0 ), s8 = vec3( 0.0 );
	for ( int j = y0; j < y1; j ++ ) {

		vec3 row = texelFetch( directions, ivec2( j, 1 ), 0 ).xyz;
		float h = row.x, c = row.y, solidAngle = row.z;
		for ( int i = x0; i < x1; i ++ ) {

			vec2 column = texelFetch( directions, ivec2( i, 0 ), 0 ).xy;
			vec3 d = vec3( c * column.x, h, c * column.y );
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
