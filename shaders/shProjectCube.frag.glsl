// First pass of the GPU SH projection of a cube map (paper 2.2): Σ L(ω)·Y_k(ω)·Ω(texel) over every
// texel, all nine coefficients in one fragment. Texels come in groups of 24 that share a solid
// angle and, up to signs and a permutation, a direction: the four mirror images (±s, ±t) of one
// position on each of the six faces. A fragment walks one block of a face quadrant; per position
// it reads Ω once, normalises once, and combines each face's four radiances by their parity in s
// and t (E even, P odd in s, Q odd in t, R odd in both), since each Y_k is even or odd in each, so
// 24 texels cost nine multiply-adds instead of 24 × 9 (docs/gpu-projection.md derives the terms).
// The output is a tiles × tiles grid per probe, one row block per probe, in seven float planes
// (shPack); shReduce and shGather sum each grid to one texel. With SOURCES > 1 one draw projects up
// to that many cube maps, one row block each, which saves a render pass and a texture barrier per
// probe where the faces are small. With FACES the six faces come as 2D textures (copies of a cube
// render target's faces), read by texelFetch, which software rasterisers (SwiftShader) do faster
// than cube lookups: worth the copy where the faces are large. With ATLAS the faces of a whole draw
// come in one 2D texture, cube map k's face f in the size² block at texel ( f·size, k·size ), as
// ProbeCapturer renders them: one sampler for any number of cube maps per draw.
precision highp float;
precision highp int;
precision highp sampler2D;

// NEAREST filtering: every lookup below hits one texel centre exactly.
uniform samplerCube cubeMap0;
#if SOURCES > 1
uniform samplerCube cubeMap1;
uniform samplerCube cubeMap2;
uniform samplerCube cubeMap3;
uniform samplerCube cubeMap4;
uniform samplerCube cubeMap5;
uniform samplerCube cubeMap6;
uniform samplerCube cubeMap7;
#endif
#if SOURCES > 1 || defined( ATLAS )
uniform int tiles;
#endif
#ifdef ATLAS
uniform sampler2D atlas;
#endif
#ifdef FACES
uniform sampler2D face0;
uniform sampler2D face1;
uniform sampler2D face2;
uniform sampler2D face3;
uniform sampler2D face4;
uniform sampler2D face5;
#endif
// ceil(size / 2)² texel solid angles of one face quadrant, the same on every face and mirror image;
// halved on an odd size's middle row and column, whose mirror images are the texel itself.
uniform sampler2D solidAngles;
uniform int size;
uniform int block;
uniform int rowOffset;

#include <shPack>

// The four mirror images' radiances combined by parity: E even, P odd in s, Q odd in t, R odd in both.
void paritySums( const in vec3 pp, const in vec3 pm, const in vec3 mp, const in vec3 mm, out vec3 E, out vec3 P, out vec3 Q, out vec3 R ) {

	vec3 sPlus = pp + pm, sMinus = mp + mm, tOddPlus = pp - pm, tOddMinus = mp - mm;
	E = sPlus + sMinus;
	P = sPlus - sMinus;
	Q = tOddPlus + tOddMinus;
	R = tOddPlus - tOddMinus;

}

// The parity sums of face texels ( high.x, high.y ) at ( s, t ), ( high.x, low.y ) at ( s, −t ),
// ( low.x, high.y ) at ( −s, t ) and ( low.x, low.y ) at ( −s, −t ) of a face copied to a 2D texture.
void faceTexelSums( sampler2D face, const in ivec2 low, const in ivec2 high, out vec3 E, out vec3 P, out vec3 Q, out vec3 R ) {

	paritySums( texelFetch( face, high, 0 ).rgb, texelFetch( face, ivec2( high.x, low.y ), 0 ).rgb,
		texelFetch( face, ivec2( low.x, high.y ), 0 ).rgb, texelFetch( face, low, 0 ).rgb, E, P, Q, R );

}

// The directions through the texel centres (±s, ±t) of one face, s, t ≥ 0: the inverse of the
// OpenGL ES 3.0 cube map face selection (section 3.8.10), so texture() lands on those very texels
// (face 0: +X at (1, −t, −s), 1: −X at (−1, −t, s), 2: +Y at (s, 1, t), 3: −Y at (s, −1, −t),
// 4: +Z at (s, −t, 1), 5: −Z at (−s, −t, −1)). Returns their parity sums.
void faceSums( samplerCube cubeMap, const in int face, const in float s, const in float t, out vec3 E, out vec3 P, out vec3 Q, out vec3 R ) {

	vec3 pp, pm, mp, mm; // radiance at ( s, t ), ( s, −t ), ( −s, t ), ( −s, −t )
	if ( face == 0 ) {

		pp = texture( cubeMap, vec3( 1.0, - t, - s ) ).rgb; pm = texture( cubeMap, vec3( 1.0, t, - s ) ).rgb;
		mp = texture( cubeMap, vec3( 1.0, - t, s ) ).rgb; mm = texture( cubeMap, vec3( 1.0, t, s ) ).rgb;

	} else if ( face == 1 ) {

		pp = texture( cubeMap, vec3( - 1.0, - t, s ) ).rgb; pm = texture( cubeMap, vec3( - 1.0, t, s ) ).rgb;
		mp = texture( cubeMap, vec3( - 1.0, - t, - s ) ).rgb; mm = texture( cubeMap, vec3( - 1.0, t, - s ) ).rgb;

	} else if ( face == 2 ) {

		pp = texture( cubeMap, vec3( s, 1.0, t ) ).rgb; pm = texture( cubeMap, vec3( s, 1.0, - t ) ).rgb;
		mp = texture( cubeMap, vec3( - s, 1.0, t ) ).rgb; mm = texture( cubeMap, vec3( - s, 1.0, - t ) ).rgb;

	} else if ( face == 3 ) {

		pp = texture( cubeMap, vec3( s, - 1.0, - t ) ).rgb; pm = texture( cubeMap, vec3( s, - 1.0, t ) ).rgb;
		mp = texture( cubeMap, vec3( - s, - 1.0, - t ) ).rgb; mm = texture( cubeMap, vec3( - s, - 1.0, t ) ).rgb;

	} else if ( face == 4 ) {

		pp = texture( cubeMap, vec3( s, - t, 1.0 ) ).rgb; pm = texture( cubeMap, vec3( s, t, 1.0 ) ).rgb;
		mp = texture( cubeMap, vec3( - s, - t, 1.0 ) ).rgb; mm = texture( cubeMap, vec3( - s, t, 1.0 ) ).rgb;

	} else {

		pp = texture( cubeMap, vec3( - s, - t, - 1.0 ) ).rgb; pm = texture( cubeMap, vec3( - s, t, - 1.0 ) ).rgb;
		mp = texture( cubeMap, vec3( s, - t, - 1.0 ) ).rgb; mm = texture( cubeMap, vec3( s, t, - 1.0 ) ).rgb;

	}

	paritySums( pp, pm, mp, mm, E, P, Q, R );

}

// Integrates the tile's block of positions of `cubeMap` (of face0..5 with FACES, of the atlas's row
// block `source` with ATLAS) and writes the sums.
#ifdef ATLAS
void project( const in ivec2 tile, const in int source ) {

	ivec2 origin = ivec2( 0, source * size ), next = ivec2( size, 0 );
#else
void project( samplerCube cubeMap, const in ivec2 tile ) {
#endif

	int quadrant = ( size + 1 ) / 2;
	int x0 = tile.x * block;
	int y0 = tile.y * block;
	int x1 = min( x0 + block, quadrant );
	int y1 = min( y0 + block, quadrant );
	float texel = 2.0 / float( size );

	vec3 c0 = vec3( 0.0 ), c1 = vec3( 0.0 ), c2 = vec3( 0.0 ), c3 = vec3( 0.0 ), c4 = vec3( 0.0 );
	vec3 c5 = vec3( 0.0 ), c6 = vec3( 0.0 ), c7 = vec3( 0.0 ), c8 = vec3( 0.0 );
	for ( int j = y0; j < y1; j ++ ) {

		// Quadrant texel ( i, j ) is face texel ( i, j ), at ( −s, −t ); its mirror images are
		// columns size − 1 − i and rows size − 1 − j.
		float t = 1.0 - ( float( j ) + 0.5 ) * texel;
		for ( int i = x0; i < x1; i ++ ) {

			float s = 1.0 - ( float( i ) + 0.5 ) * texel;
			float w = texelFetch( solidAngles, ivec2( i, j ), 0 ).r;
			// The unit direction of ( s, t ) on face 0 is ( A, −T, −S ) (up to signs and order on the others).
			float A = inversesqrt( 1.0 + s * s + t * t ), S = s * A, T = t * A;
			vec3 E0, P0, Q0, R0, E1, P1, Q1, R1, E2, P2, Q2, R2, E3, P3, Q3, R3, E4, P4, Q4, R4, E5, P5, Q5, R5;
			#ifdef FACES
			ivec2 low = ivec2( i, j ), high = ivec2( size - 1 - i, size - 1 - j );
			faceTexelSums( face0, low, high, E0, P0, Q0, R0 );
			faceTexelSums( face1, low, high, E1, P1, Q1, R1 );
			faceTexelSums( face2, low, high, E2, P2, Q2, R2 );
			faceTexelSums( face3, low, high, E3, P3, Q3, R3 );
			faceTexelSums( face4, low, high, E4, P4, Q4, R4 );
			faceTexelSums( face5, low, high, E5, P5, Q5, R5 );
			#elif defined( ATLAS )
			ivec2 low = origin + ivec2( i, j ), high = origin + ivec2( size - 1 - i, size - 1 - j );
			faceTexelSums( atlas, low, high, E0, P0, Q0, R0 );
			faceTexelSums( atlas, low + next, high + next, E1, P1, Q1, R1 );
			faceTexelSums( atlas, low + 2 * next, high + 2 * next, E2, P2, Q2, R2 );
			faceTexelSums( atlas, low + 3 * next, high + 3 * next, E3, P3, Q3, R3 );
			faceTexelSums( atlas, low + 4 * next, high + 4 * next, E4, P4, Q4, R4 );
			faceTexelSums( atlas, low + 5 * next, high + 5 * next, E5, P5, Q5, R5 );
			#else
			faceSums( cubeMap, 0, s, t, E0, P0, Q0, R0 );
			faceSums( cubeMap, 1, s, t, E1, P1, Q1, R1 );
			faceSums( cubeMap, 2, s, t, E2, P2, Q2, R2 );
			faceSums( cubeMap, 3, s, t, E3, P3, Q3, R3 );
			faceSums( cubeMap, 4, s, t, E4, P4, Q4, R4 );
			faceSums( cubeMap, 5, s, t, E5, P5, Q5, R5 );
			#endif
			float AS = A * S, AT = A * T, ST = S * T;
			vec3 xFaces = E0 + E1, yFaces = E2 + E3, zFaces = E4 + E5;
			// Y_k without its constant (applied once at the end), summed over the 24 texels.
			c0 += w * ( xFaces + yFaces + zFaces );
			c1 += w * ( A * ( E2 - E3 ) - T * ( Q0 + Q1 + Q4 + Q5 ) );
			c2 += w * ( A * ( E4 - E5 ) + S * ( P1 - P0 ) + T * ( Q2 - Q3 ) );
			c3 += w * ( A * ( E0 - E1 ) + S * ( P2 + P3 + P4 - P5 ) );
			c4 += w * ( AT * ( Q1 - Q0 ) + AS * ( P2 - P3 ) + ST * ( R5 - R4 ) );
			c5 += w * ( ST * ( R0 - R1 ) + AT * ( Q2 + Q3 - Q4 + Q5 ) );
			c6 += w * ( ( 3.0 * S * S - 1.0 ) * xFaces + ( 3.0 * T * T - 1.0 ) * yFaces + ( 3.0 * A * A - 1.0 ) * zFaces );
			c7 += w * ( AS * ( P4 + P5 - P0 - P1 ) + ST * ( R2 - R3 ) );
			c8 += w * ( ( A * A - T * T ) * xFaces + ( S * S - A * A ) * yFaces + ( S * S - T * T ) * zFaces );

		}

	}

	// three.js SphericalHarmonics3 basis constants (getBasisAt).
	writeSums( c0 * 0.282095, c1 * 0.488603, c2 * 0.488603, c3 * 0.488603, c4 * 1.092548,
		c5 * 1.092548, c6 * 0.315392, c7 * 1.092548, c8 * 0.546274 );

}

void main() {

	ivec2 tile = ivec2( gl_FragCoord.xy ) - ivec2( 0, rowOffset );
	#ifdef ATLAS
	// Row block `source` of this draw's rows reads row block `source` of the atlas.
	int source = tile.y / tiles;
	project( ivec2( tile.x, tile.y - source * tiles ), source );
	#else
	#if SOURCES > 1
	// Samplers can only be indexed by constants in GLSL ES 3.00, hence the chain. tiles is even
	// (but for 1² and 2² faces), so a 2 × 2 fragment quad never spans two sources.
	int source = tile.y / tiles;
	tile.y -= source * tiles;
	if ( source == 1 ) { project( cubeMap1, tile ); return; }
	if ( source == 2 ) { project( cubeMap2, tile ); return; }
	if ( source == 3 ) { project( cubeMap3, tile ); return; }
	if ( source == 4 ) { project( cubeMap4, tile ); return; }
	if ( source == 5 ) { project( cubeMap5, tile ); return; }
	if ( source == 6 ) { project( cubeMap6, tile ); return; }
	if ( source == 7 ) { project( cubeMap7, tile ); return; }
	#endif
	project( cubeMap0, tile );
	#endif

}
