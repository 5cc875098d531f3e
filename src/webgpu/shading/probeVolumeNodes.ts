import { Data3DTexture, FloatType, HalfFloatType, LinearFilter, Matrix4, RGBAFormat, Vector3, type Material } from 'three';
import {
	attribute, clamp, dot, modelNormalMatrix, normalLocal, normalWorld, positionWorld, texture3D, uniform, varying, vec3, vec4,
} from 'three/tsl';
import { probeMaterialRecords, type ProbeMaterialRecord, type ProbeNodeVariant } from './probeMaterialRecords.js';

/*
 * The TSL side of the probe light: one node graph per variant, built once and shared by every
 * patched material, so materials of one type share a pipeline. Its uniforms sit in three's object
 * group (a buffer per draw) and are filled at each draw by onObjectUpdate from the record of the
 * material drawn (probeMaterialRecords): the blended SH's irradiance matrices, intensity, direct
 * scale and, for the texture variants, the atlas and its grid. The formulas are the WebGL shaders'
 * (shaders/probeVolume*.glsl), evaluated for three's world normal as its LightProbe node does.
 */

// TSL's typings model each node class; the graph below is built from untyped chains.
type TSLNode = any;

interface DrawFrame {

	material: Material | null;

}

/** The record of the material being drawn, or null (a material unpatched since its pipeline was made). */
function recordOf( frame: DrawFrame ): ProbeMaterialRecord | null {

	return frame.material !== null ? probeMaterialRecords.get( frame.material ) ?? null : null;

}

/**
 * A uniform in three's object group, set at each draw from the drawn material's record: `update`
 * returns the new value, or changes `value` in place and returns undefined.
 */
function perDraw<T>( value: T, update: ( record: ProbeMaterialRecord | null, value: T ) => T | undefined ): TSLNode {

	const node: TSLNode = uniform( value as any );
	return node.onObjectUpdate( ( frame: DrawFrame, self: { value: T } ) => update( recordOf( frame ), self.value ) );

}

/**
 * The per-draw uniforms shared by all variants: three irradiance matrices (R, G, B, for world
 * normals), intensity and direct scale. A draw of a material without a record keeps zero light.
 */
const matrixR = perDraw( new Matrix4(), ( record, m ) => copyMatrix( record, 0, m ) );
const matrixG = perDraw( new Matrix4(), ( record, m ) => copyMatrix( record, 16, m ) );
const matrixB = perDraw( new Matrix4(), ( record, m ) => copyMatrix( record, 32, m ) );
const intensity = perDraw( 1, ( record ) => record?.uniforms.probeVolumeIntensity.value ?? 0 );

/** Scale of direct light (`probeVolumeDirectScale`), read by the lighting-model wrapper. */
export const directScale = perDraw( 1, ( record ) => record?.uniforms.probeVolumeDirectScale.value ?? 1 );

function copyMatrix( record: ProbeMaterialRecord | null, offset: number, target: Matrix4 ): undefined {

	if ( record === null ) target.elements.fill( 0 );
	else target.fromArray( record.uniforms.probeVolumeMatrices.value, offset );
	return undefined;

}

/** E(n) = nᵀMn per channel for a unit world normal, with n = ( normal, 1 ). */
function irradianceFromMatrices( normal: TSLNode ): TSLNode {

	const n = vec4( normal, 1 );
	return vec3( dot( n, matrixR.mul( n ) ), dot( n, matrixG.mul( n ) ), dot( n, matrixB.mul( n ) ) );

}

/**
 * E(n) from SH9 packed in 7 vec4 (three's LightProbeGrid atlas packing), with the constants of
 * `SphericalHarmonics3.getIrradianceAt` (shaders/probeVolumeSHEval.glsl; not clamped at zero).
 */
function irradianceFromPacked( s: TSLNode[], normal: TSLNode ): TSLNode {

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

/** An empty atlas of the given texel type: the value the texture node is built with. */
function placeholderAtlas( type: typeof HalfFloatType | typeof FloatType ): Data3DTexture {

	const texture = new Data3DTexture( type === FloatType ? new Float32Array( 4 * 21 ) : new Uint16Array( 4 * 21 ), 1, 1, 21 );
	texture.format = RGBAFormat;
	texture.type = type;
	texture.minFilter = texture.magFilter = LinearFilter;
	texture.needsUpdate = true;
	return texture;

}

/**
 * Per-pixel light from a ProbeVolumeTexture atlas (shaders/probeVolumeTexture.pars.glsl): 7 packed
 * sub-volumes along z with a padding slice at both ends; grid nodes at texel centres. The atlas
 * node's texture is set per draw with the grid uniforms.
 */
function textureIrradiance( type: typeof HalfFloatType | typeof FloatType ): TSLNode {

	const atlas: TSLNode = texture3D( placeholderAtlas( type ) );
	const gridMin = perDraw( new Vector3(), ( record, v ) => {

		const u = record?.uniforms;
		if ( u?.probeVolumeGridMin && u.probeVolumeSH?.value ) {

			v.copy( u.probeVolumeGridMin.value );
			// The atlas binding is per draw too: set with the grid it belongs to.
			atlas.value = u.probeVolumeSH.value;

		}

		return undefined;

	} );
	const gridMax = perDraw( new Vector3( 1, 1, 1 ), ( record, v ) => {

		if ( record?.uniforms.probeVolumeGridMax ) v.copy( record.uniforms.probeVolumeGridMax.value );
		return undefined;

	} );
	const res = perDraw( new Vector3( 2, 2, 2 ), ( record, v ) => {

		if ( record?.uniforms.probeVolumeGridResolution ) v.copy( record.uniforms.probeVolumeGridResolution.value );
		return undefined;

	} );

	let uvw: TSLNode = positionWorld.sub( gridMin ).div( gridMax.sub( gridMin ) ).mul( res.sub( 1 ) ).add( 0.5 ).div( res );
	// Outside the bounds the light stays that of the nearest face, as outside the probes' hull.
	uvw = clamp( uvw, vec3( 0.5 ).div( res ), vec3( 1 ).sub( vec3( 0.5 ).div( res ) ) );
	const padded = res.z.add( 2 );
	const depth = padded.mul( 7 );
	const z = uvw.z.mul( res.z ).add( 1 );
	const slices: TSLNode[] = [];
	for ( let i = 0; i < 7; i ++ ) slices.push( atlas.sample( vec3( uvw.xy, z.add( padded.mul( i ) ).div( depth ) ) ) );
	return irradianceFromPacked( slices, normalWorld ).mul( intensity );

}

/** Builds the irradiance node of a variant (world-space probe light added to the indirect diffuse irradiance). */
function buildIrradiance( variant: ProbeNodeVariant ): TSLNode {

	switch ( variant ) {

		case 'pixel':
			return irradianceFromMatrices( normalWorld ).mul( intensity );
		case 'vertex':
			// The world normal at the vertex (three's LightProbe would use the pixel's), interpolated.
			return varying( irradianceFromMatrices( ( modelNormalMatrix as TSLNode ).mul( normalLocal ).normalize() ).mul( intensity ), 'vProbeVolumeIrradiance' );
		case 'vertexIrradiance':
			return ( attribute( 'probeIrradiance', 'vec3' ) as TSLNode ).mul( intensity );
		case 'vertexSH': {

			const packed = [ 0, 1, 2, 3, 4, 5, 6 ].map( ( i ) => attribute( `probeSH${i}`, 'vec4' ) );
			return irradianceFromPacked( packed, normalWorld ).mul( intensity );

		}

		case 'texture':
			return textureIrradiance( HalfFloatType );
		case 'textureFloat':
			return textureIrradiance( FloatType );

	}

}

const irradianceNodes = new Map<ProbeNodeVariant, TSLNode>();

/** The shared irradiance node of a variant (built on first use). */
export function probeIrradianceNode( variant: ProbeNodeVariant ): TSLNode {

	let node = irradianceNodes.get( variant );
	if ( node === undefined ) {

		node = buildIrradiance( variant );
		irradianceNodes.set( variant, node );

	}

	return node;

}

