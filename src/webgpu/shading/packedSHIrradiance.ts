import { clamp, vec3 } from 'three/tsl';

/*
 * The TSL evaluation of SH9 packed as three's LightProbeGrid packs it, and of a ProbeVolumeTexture
 * atlas, shared by the shading variants (probeVolumeNodes.ts) and the light-map source
 * (../lightmap/ProbeVolumeIrradiance.ts), so both read the same light.
 */

// TSL's typings model each node class; the graph below is built from untyped chains.
type TSLNode = any;

/**
 * E(n) from SH9 packed in 7 vec4 (three's LightProbeGrid atlas packing), with the constants of
 * `SphericalHarmonics3.getIrradianceAt` (shaders/probeVolumeSHEval.glsl; not clamped at zero).
 * @param s The seven packed texels.
 * @param normal A unit world normal node.
 */
export function irradianceFromPacked( s: TSLNode[], normal: TSLNode ): TSLNode {

	const [ s0, s1, s2, s3, s4, s5, s6 ] = s;
	const x = normal.x, y = normal.y, z = normal.z;
	let e = s0.xyz.mul( 0.886227 );
	e = e.add( vec3( s0.w, s1.xy ).mul( y.mul( 2 * 0.511664 ) ) );
	e = e.add( vec3( s1.zw, s2.x ).mul( z.mul( 2 * 0.511664 ) ) );
	e = e.add( s2.yzw.mul( x.mul( 2 * 0.511664 ) ) );
	e = e.add( s3.xyz.mul( x.mul( y ).mul( 2 * 0.429043 ) ) );
	e = e.add( vec3( s3.w, s4.xy ).mul( y.mul( z ).mul( 2 * 0.429043 ) ) );
	e = e.add( vec3( s4.zw, s5.x ).mul( z.mul( z ).mul( 0.743125 ).sub( 0.247708 ) ) );
	e = e.add( s5.yzw.mul( x.mul( z ).mul( 2 * 0.429043 ) ) );
	e = e.add( s6.xyz.mul( x.mul( x ).sub( y.mul( y ) ).mul( 0.429043 ) ) );
	return e;

}

/**
 * E(n) at a world position from a ProbeVolumeTexture atlas (shaders/probeVolumeTexture.pars.glsl):
 * 7 packed sub-volumes along z with a padding slice at both ends, grid nodes at texel centres.
 * Outside the grid the light stays that of the nearest face, as outside the probes' hull.
 * @param atlas A `texture3D` node of the atlas.
 * @param gridMin World position of the first grid node (vec3 node).
 * @param gridMax World position of the last grid node (vec3 node).
 * @param res Grid nodes per axis (vec3 node).
 * @param position World position (vec3 node).
 * @param normal Unit world normal (vec3 node).
 */
export function atlasIrradiance(
	atlas: TSLNode, gridMin: TSLNode, gridMax: TSLNode, res: TSLNode, position: TSLNode, normal: TSLNode,
): TSLNode {

	let uvw: TSLNode = position.sub( gridMin ).div( gridMax.sub( gridMin ) ).mul( res.sub( 1 ) ).add( 0.5 ).div( res );
	uvw = clamp( uvw, vec3( 0.5 ).div( res ), vec3( 1 ).sub( vec3( 0.5 ).div( res ) ) );
	const padded = res.z.add( 2 );
	const depth = padded.mul( 7 );
	const z = uvw.z.mul( res.z ).add( 1 );
	const slices: TSLNode[] = [];
	for ( let i = 0; i < 7; i ++ ) slices.push( atlas.sample( vec3( uvw.xy, z.add( padded.mul( i ) ).div( depth ) ) ) );
	return irradianceFromPacked( slices, normal );

}
