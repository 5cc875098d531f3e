// A PlaneGeometry( 2, 2 ) already spans clip space: no camera, no matrices.
precision highp float;

in vec3 position;

void main() {

	gl_Position = vec4( position.xy, 0.0, 1.0 );

}
