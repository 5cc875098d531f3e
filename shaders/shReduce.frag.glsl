// One step of the logarithmic reduction: each output texel is the sum of a factor × factor block
// of the input. Tiles of the projection pass are multiples of the factor, so sums never mix
// coefficients or probes.
precision highp float;
precision highp int;
precision highp sampler2D;

uniform sampler2D source;
uniform int factor;

out vec4 fragColor;

void main() {

	ivec2 origin = ivec2( gl_FragCoord.xy ) * factor;
	vec4 sum = vec4( 0.0 );
	for ( int j = 0; j < factor; j ++ ) {

		for ( int i = 0; i < factor; i ++ ) {

			sum += texelFetch( source, origin + ivec2( i, j ), 0 );

		}

	}

	fragColor = sum;

}
