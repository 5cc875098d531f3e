// SH9 basis in three.js SphericalHarmonics3 order and constants (getBasisAt), in two halves:
// half 0 gives coefficients 0..4, half 1 gives 5..8 (and a 0), so one fragment can accumulate a
// half for every texel it reads.
void shBasisHalf( const in int half_, const in vec3 d, out float y[ 5 ] ) {

	if ( half_ == 0 ) {

		y[ 0 ] = 0.282095;
		y[ 1 ] = 0.488603 * d.y;
		y[ 2 ] = 0.488603 * d.z;
		y[ 3 ] = 0.488603 * d.x;
		y[ 4 ] = 1.092548 * d.x * d.y;

	} else {

		y[ 0 ] = 1.092548 * d.y * d.z;
		y[ 1 ] = 0.315392 * ( 3.0 * d.z * d.z - 1.0 );
		y[ 2 ] = 1.092548 * d.x * d.z;
		y[ 3 ] = 0.546274 * ( d.x * d.x - d.y * d.y );
		y[ 4 ] = 0.0;

	}

}
