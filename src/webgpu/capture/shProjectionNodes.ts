import { Loop, float, inverseSqrt, ivec2, min, vec2, vec3, vec4 } from 'three/tsl';

/*
 * The TSL bodies of the WebGPU SH projection: the sums of one tile of a cube map or a panorama,
 * all nine coefficients, as the WebGL fragment shaders shProjectCube / shProjectEquirect compute
 * them (the same texel solid angles, the same 24-texel symmetry of the cube faces; the algorithm is
 * in docs/gpu-projection.md). Called inside a TSL `Fn`, by the compute kernels of the WebGPU
 * backend and by the fragment passes of the WebGL2 backend (WebGPUSHProjector).
 */

/** A TSL node (three's node types are too loose to be worth spelling out here). */
export type TSLNode = any;

/** TSL's `Loop`, with its parameters untyped (its typings refuse named loop variables and uniform bounds). */
export const loop = Loop as unknown as ( ...params: unknown[] ) => TSLNode;

/** three.js SphericalHarmonics3 basis constants (getBasisAt), applied once per tile. */
const BASIS = [ 0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548, 0.315392, 1.092548, 0.546274 ];

/** The parity sums E, P, Q, R of four mirror images' radiances (shProjectCube's paritySums). */
function paritySums( pp: TSLNode, pm: TSLNode, mp: TSLNode, mm: TSLNode ): TSLNode[] {

	const sPlus = pp.add( pm ), sMinus = mp.add( mm ), tPlus = pp.sub( pm ), tMinus = mp.sub( mm );
	return [ sPlus.add( sMinus ).toVar(), sPlus.sub( sMinus ).toVar(), tPlus.add( tMinus ).toVar(), tPlus.sub( tMinus ).toVar() ];

}

/**
 * The nine RGB sums (basis constants applied) of the tile ( `tileX`, `tileY` ) of a cube map's
 * face quadrant: blocks of `block` × `block` positions, each read on the six faces at its four
 * mirror images. `cube` is a `cubeTexture` node (NearestFilter; three's TSL maps the world
 * direction to the stored texel on both backends, so the sums are in world orientation like the
 * WebGL path's), `solidAngles` a `texture` node of the quadrant's solid angles.
 */
export function cubeTileSums(
	cube: TSLNode, solidAngles: TSLNode, size: TSLNode, block: TSLNode, tileX: TSLNode, tileY: TSLNode,
): TSLNode[] {

	const read = ( x: TSLNode, y: TSLNode, z: TSLNode ) => cube.sample( vec3( x, y, z ) ).level( 0 ).rgb;
	return tileSums( size, block, tileX, tileY, solidAngles, ( face, s, t ) => {

		// The directions through the texel centres (±s, ±t) of each face, as shProjectCube's faceSums.
		const ns = s.negate(), nt = t.negate();
		switch ( face ) {

			case 0: return paritySums( read( 1, nt, ns ), read( 1, t, ns ), read( 1, nt, s ), read( 1, t, s ) );
			case 1: return paritySums( read( - 1, nt, s ), read( - 1, t, s ), read( - 1, nt, ns ), read( - 1, t, ns ) );
			case 2: return paritySums( read( s, 1, t ), read( s, 1, nt ), read( ns, 1, t ), read( ns, 1, nt ) );
			case 3: return paritySums( read( s, - 1, nt ), read( s, - 1, t ), read( ns, - 1, nt ), read( ns, - 1, t ) );
			case 4: return paritySums( read( s, nt, 1 ), read( s, t, 1 ), read( ns, nt, 1 ), read( ns, t, 1 ) );
			default: return paritySums( read( ns, nt, - 1 ), read( ns, t, - 1 ), read( s, nt, - 1 ), read( s, t, - 1 ) );

		}

	} );

}

/**
 * The walk of {@link cubeTileSums} over a tile of quadrant positions, with the parity sums E, P, Q, R
 * of face `face` at position ( s, t ) — quadrant texel ( column `j`, row `i` ) — given by `faceSums`.
 */
function tileSums(
	size: TSLNode, block: TSLNode, tileX: TSLNode, tileY: TSLNode, solidAngles: TSLNode,
	faceSums: ( face: number, s: TSLNode, t: TSLNode, i: TSLNode, j: TSLNode ) => TSLNode[],
): TSLNode[] {

	const quadrant = size.add( 1 ).div( 2 ).toVar();
	const x0 = tileX.mul( block ).toVar(), y0 = tileY.mul( block ).toVar();
	const x1 = min( x0.add( block ), quadrant ).toVar(), y1 = min( y0.add( block ), quadrant ).toVar();
	const texel = float( 2 ).div( float( size ) ).toVar();
	const c = BASIS.map( () => vec3( 0 ).toVar() );

	loop( { start: y0, end: y1, type: 'int', condition: '<' }, { start: x0, end: x1, type: 'int', condition: '<' }, ( { i, j }: TSLNode ) => {

		// i: quadrant row, j: column; quadrant texel ( j, i ) is face texel ( j, i ), at ( −s, −t ).
		const t = float( 1 ).sub( float( i ).add( 0.5 ).mul( texel ) ).toVar();
		const s = float( 1 ).sub( float( j ).add( 0.5 ).mul( texel ) ).toVar();
		const w = solidAngles.load( ivec2( j, i ) ).r.toVar();
		const A = inverseSqrt( s.mul( s ).add( t.mul( t ) ).add( 1 ) ).toVar();
		const S = s.mul( A ).toVar(), T = t.mul( A ).toVar();
		const [ E0, P0, Q0, R0 ] = faceSums( 0, s, t, i, j );
		const [ E1, P1, Q1, R1 ] = faceSums( 1, s, t, i, j );
		const [ E2, P2, Q2, R2 ] = faceSums( 2, s, t, i, j );
		const [ E3, P3, Q3, R3 ] = faceSums( 3, s, t, i, j );
		const [ E4, P4, Q4, R4 ] = faceSums( 4, s, t, i, j );
		const [ E5, P5, Q5, R5 ] = faceSums( 5, s, t, i, j );
		const AS = A.mul( S ), AT = A.mul( T ), ST = S.mul( T );
		const xFaces = E0.add( E1 ).toVar(), yFaces = E2.add( E3 ).toVar(), zFaces = E4.add( E5 ).toVar();
		c[ 0 ].addAssign( xFaces.add( yFaces ).add( zFaces ).mul( w ) );
		c[ 1 ].addAssign( E2.sub( E3 ).mul( A ).sub( Q0.add( Q1 ).add( Q4 ).add( Q5 ).mul( T ) ).mul( w ) );
		c[ 2 ].addAssign( E4.sub( E5 ).mul( A ).add( P1.sub( P0 ).mul( S ) ).add( Q2.sub( Q3 ).mul( T ) ).mul( w ) );
		c[ 3 ].addAssign( E0.sub( E1 ).mul( A ).add( P2.add( P3 ).add( P4 ).sub( P5 ).mul( S ) ).mul( w ) );
		c[ 4 ].addAssign( Q1.sub( Q0 ).mul( AT ).add( P2.sub( P3 ).mul( AS ) ).add( R5.sub( R4 ).mul( ST ) ).mul( w ) );
		c[ 5 ].addAssign( R0.sub( R1 ).mul( ST ).add( Q2.add( Q3 ).sub( Q4 ).add( Q5 ).mul( AT ) ).mul( w ) );
		c[ 6 ].addAssign( xFaces.mul( S.mul( S ).mul( 3 ).sub( 1 ) ).add( yFaces.mul( T.mul( T ).mul( 3 ).sub( 1 ) ) )
			.add( zFaces.mul( A.mul( A ).mul( 3 ).sub( 1 ) ) ).mul( w ) );
		c[ 7 ].addAssign( P4.add( P5 ).sub( P0 ).sub( P1 ).mul( AS ).add( R2.sub( R3 ).mul( ST ) ).mul( w ) );
		c[ 8 ].addAssign( xFaces.mul( A.mul( A ).sub( T.mul( T ) ) ).add( yFaces.mul( S.mul( S ).sub( A.mul( A ) ) ) )
			.add( zFaces.mul( S.mul( S ).sub( T.mul( T ) ) ) ).mul( w ) );

	} );

	return c.map( ( sum, k ) => sum.mul( BASIS[ k ] ) );

}

/**
 * The same sums as {@link cubeTileSums} from six 2D face textures read by texel index, laid out as
 * WebGL's cube faces (docs/cube-faces.md: face f, texel ( column, row ) at u = −1 + ( column + ½ )·2 / size,
 * v = −1 + ( row + ½ )·2 / size, row 0 first), as shProjectCube's FACES variant reads them.
 * `faces` holds six `texture` nodes, +X, −X, +Y, −Y, +Z, −Z.
 */
export function faceTileSums(
	faces: readonly TSLNode[], solidAngles: TSLNode, size: TSLNode, block: TSLNode, tileX: TSLNode, tileY: TSLNode,
): TSLNode[] {

	return tileSums( size, block, tileX, tileY, solidAngles, ( face, s, t, i, j ) => {

		// Quadrant texel ( j, i ) is at ( −s, −t ); its mirror images are column size − 1 − j and row size − 1 − i.
		const last = size.sub( 1 );
		const low = ivec2( j, i ), high = ivec2( last.sub( j ), last.sub( i ) );
		const read = ( at: TSLNode ) => faces[ face ].load( at ).rgb;
		return paritySums( read( high ), read( ivec2( high.x, low.y ) ), read( ivec2( low.x, high.y ) ), read( low ) );

	} );

}

/**
 * The nine RGB sums of tile ( `tileX`, `tileY` ) of an equirectangular panorama `size` ( width,
 * height, an ivec2 node ) in blocks `block` (ivec2): three's equirectUv directions, exact row
 * solid angles, as shProjectEquirect. `panorama` is a `texture` node, read at texel centres;
 * `directions` a `texture` node of the panorama's direction table (createEquirectTableTexture:
 * float64 sin / cos on the CPU, which the GPU's float32 ones are too coarse to replace).
 */
export function equirectTileSums(
	panorama: TSLNode, directions: TSLNode, size: TSLNode, block: TSLNode, tileX: TSLNode, tileY: TSLNode,
): TSLNode[] {

	const x0 = tileX.mul( block.x ).toVar(), y0 = tileY.mul( block.y ).toVar();
	const x1 = min( x0.add( block.x ), size.x ).toVar(), y1 = min( y0.add( block.y ), size.y ).toVar();
	const width = float( size.x ).toVar(), height = float( size.y ).toVar();
	const c = BASIS.map( () => vec3( 0 ).toVar() );

	loop( { start: y0, end: y1, type: 'int', condition: '<' }, ( { i }: TSLNode ) => {

		const v = float( i ).add( 0.5 ).div( height ).toVar();
		const row = directions.load( ivec2( i, 1 ) ).toVar();
		const h = row.x, ring = row.y, solidAngle = row.z;

		loop( { start: x0, end: x1, type: 'int', condition: '<', name: 'column' }, ( { column }: TSLNode ) => {

			const u = float( column ).add( 0.5 ).div( width ).toVar();
			const longitude = directions.load( ivec2( column, 0 ) ).toVar();
			const d = vec3( ring.mul( longitude.x ), h, ring.mul( longitude.y ) ).toVar();
			const radiance = panorama.sample( vec2( u, v ) ).level( 0 ).rgb.mul( solidAngle ).toVar();
			c[ 0 ].addAssign( radiance );
			c[ 1 ].addAssign( radiance.mul( d.y ) );
			c[ 2 ].addAssign( radiance.mul( d.z ) );
			c[ 3 ].addAssign( radiance.mul( d.x ) );
			c[ 4 ].addAssign( radiance.mul( d.x.mul( d.y ) ) );
			c[ 5 ].addAssign( radiance.mul( d.y.mul( d.z ) ) );
			c[ 6 ].addAssign( radiance.mul( d.z.mul( d.z ).mul( 3 ).sub( 1 ) ) );
			c[ 7 ].addAssign( radiance.mul( d.x.mul( d.z ) ) );
			c[ 8 ].addAssign( radiance.mul( d.x.mul( d.x ).sub( d.y.mul( d.y ) ) ) );

		} );

	} );

	return c.map( ( sum, k ) => sum.mul( BASIS[ k ] ) );

}

/** The seven RGBA planes of nine RGB sums: the 27 floats in order (coefficient-major, RGB) and one unused (shPack). */
export function packPlanes( c: TSLNode[] ): TSLNode[] {

	return [
		vec4( c[ 0 ], c[ 1 ].x ), vec4( c[ 1 ].y, c[ 1 ].z, c[ 2 ].x, c[ 2 ].y ), vec4( c[ 2 ].z, c[ 3 ] ),
		vec4( c[ 4 ], c[ 5 ].x ), vec4( c[ 5 ].y, c[ 5 ].z, c[ 6 ].x, c[ 6 ].y ), vec4( c[ 6 ].z, c[ 7 ] ), vec4( c[ 8 ], 0 ),
	];

}
