// Last pass of the GPU SH projection: sums each probe's remaining factor × factor tiles of every
// plane and lays the seven planes side by side in one RGBA float target (x = plane, y = probe),
// so a single readPixels returns the whole batch: 28 floats per probe, the 27 SH floats in
// order and one unused. Works with one render target, so every renderer ends here.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D plane0;
uniform sampler2D plane1;
uniform sampler2D plane2;
uniform sampler2D plane3;
uniform sampler2D plane4;
uniform sampler2D plane5;
uniform sampler2D plane6;
uniform int factor;

layout( location = 0 ) out vec4 sum;

// Samplers can only be indexed by constants in GLSL ES 3.00, hence the chain.
vec4 fetchPlane( const in int plane, const in ivec2 p ) {

	if ( plane == 0 ) return texelFetch( plane0, p, 0 );
	if ( plane == 1 ) return texelFetch( plane1, p, 0 );
	if ( plane == 2 ) return texelFetch( plane2, p, 0 );
	if ( plane == 3 ) return texelFetch( plane3, p, 0 );
	if ( plane == 4 ) return texelFetch( plane4, p, 0 );
	if ( plane == 5 ) return texelFetch( plane5, p, 0 );
	return texelFetch( plane6, p, 0 );

}

void main() {

	ivec2 pixel = ivec2( gl_FragCoord.xy );
	vec4 total = vec4( 0.0 );
	for ( int j = 0; j < factor; j ++ ) {

		for ( int i = 0; i < factor; i ++ ) total += fetchPlane( pixel.x, ivec2( i, pixel.y * factor + j ) );

	}

	sum = total;

}
