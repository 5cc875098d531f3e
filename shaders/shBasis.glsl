// SH9 basis in three.js SphericalHarmonics3 order and constants (getBasisAt), accumulated in two
// halves: half 0 adds radiance × Y_0..Y_4 to s0..s4, half 1 adds Y_5..Y_8 to s0..s3. Plain
// variables rather than arrays: software rasterisers (SwiftShader) spill arrays to memory.
void accumulateHalf( const in int half_, const in vec3 radiance, const in vec3 d, inout vec3 s0, inout vec3 s1, inout vec3 s2, inout vec3 s3, inout vec3 s4 ) {

	if ( half_ == 0 ) {

		s0 += radiance * 0.282095;
		s1 += radiance * ( 0.488603 * d.y );
		s2 += radiance * ( 0.488603 * d.z );
		s3 += radiance * ( 0.488603 * d.x );
		s4 += radiance * ( 1.092548 * d.x * d.y );

	} else {

		s0 += radiance * ( 1.092548 * d.y * d.z );
		s1 += radiance * ( 0.315392 * ( 3.0 * d.z * d.z - 1.0 ) );
		s2 += radiance * ( 1.092548 * d.x * d.z );
		s3 += radiance * ( 0.546274 * ( d.x * d.x - d.y * d.y ) );

	}

}
