import { Data3DTexture, FloatType, HalfFloatType, LinearFilter, Matrix4, RGBAFormat, Vector3, Vector4, type Material } from 'three';
import {
	attribute, modelNormalMatrix, normalLocal, normalWorld, positionWorld, texture3D, uniform, varying,
} from 'three/tsl';
import { atlasIrradiance, irradianceFromPacked } from './packedSHIrradiance.js';
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

/*
 * The blended SH's irradiance per draw, as nine RGB coefficients of E(n) = Σ cᵢ·bᵢ(n) with
 * bᵢ = x², y², xy, yz, xz, x, y, z, 1 — the record's matrices M_c (E_c = nᵀM_c n, symmetric)
 * expanded, z² folded into x², y² and the constant (x² + y² + z² = 1 for a unit normal): 5
 * products and 9 vec3 multiply-adds per pixel instead of three 4 × 4 matrix products and dots
 * (fewer than three's LightProbe node, which scales its 9 coefficients per pixel). Slot i's RGB
 * is column i % 4 of uniform ⌊i / 4⌋ (two matrices and a vector), its w unused.
 */

/** Coefficient `slot` (0–8, the order above) of channel `c` from the record's 48 matrix floats. */
function coefficient( m: Float32Array, c: number, slot: number ): number {

	const o = 16 * c, zz = m[ o + 10 ];
	switch ( slot ) {

		case 0: return m[ o ] - zz;
		case 1: return m[ o + 5 ] - zz;
		case 2: return 2 * m[ o + 1 ];
		case 3: return 2 * m[ o + 6 ];
		case 4: return 2 * m[ o + 2 ];
		case 5: return 2 * m[ o + 3 ];
		case 6: return 2 * m[ o + 7 ];
		case 7: return 2 * m[ o + 11 ];
		default: return m[ o + 15 ] + zz;

	}

}

/** Writes slots first … first + count − 1 as RGB0 columns of `target` (zero light without a record). */
function packCoefficients( record: ProbeMaterialRecord | null, first: number, count: number, target: number[] ): undefined {

	for ( let k = 0; k < count; k ++ ) for ( let c = 0; c < 4; c ++ ) {

		target[ 4 * k + c ] = record === null || c === 3 ? 0 : coefficient( record.uniforms.probeVolumeMatrices.value, c, first + k );

	}

	return undefined;

}

const coefficients0 = perDraw( new Matrix4(), ( record, m ) => packCoefficients( record, 0, 4, m.elements ) );
const coefficients1 = perDraw( new Matrix4(), ( record, m ) => packCoefficients( record, 4, 4, m.elements ) );
const lastSlot = [ 0, 0, 0, 0 ];
const coefficients2 = perDraw( new Vector4(), ( record, v ) => {

	packCoefficients( record, 8, 1, lastSlot );
	v.fromArray( lastSlot );
	return undefined;

} );
const intensity = perDraw( 1, ( record ) => record?.uniforms.probeVolumeIntensity.value ?? 0 );

/** Scale of direct light (`probeVolumeDirectScale`), read by the lighting-model wrapper. */
export const directScale = perDraw( 1, ( record ) => record?.uniforms.probeVolumeDirectScale.value ?? 1 );

/** E(n) per channel for a unit world normal (the record's nᵀMn, expanded as above). */
function irradianceFromCoefficients( normal: TSLNode ): TSLNode {

	const n = normal.toVar();
	const x = n.x, y = n.y, z = n.z;
	const c = ( uniform: TSLNode, column: number ) => uniform.element( column ).xyz;
	return c( coefficients0, 0 ).mul( x.mul( x ) )
		.add( c( coefficients0, 1 ).mul( y.mul( y ) ) )
		.add( c( coefficients0, 2 ).mul( x.mul( y ) ) )
		.add( c( coefficients0, 3 ).mul( y.mul( z ) ) )
		.add( c( coefficients1, 0 ).mul( x.mul( z ) ) )
		.add( c( coefficients1, 1 ).mul( x ) )
		.add( c( coefficients1, 2 ).mul( y ) )
		.add( c( coefficients1, 3 ).mul( z ) )
		.add( coefficients2.xyz );

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

	return atlasIrradiance( atlas, gridMin, gridMax, res, positionWorld, normalWorld ).mul( intensity );

}

/** Builds the irradiance node of a variant (world-space probe light added to the indirect diffuse irradiance). */
function buildIrradiance( variant: ProbeNodeVariant ): TSLNode {

	switch ( variant ) {

		case 'pixel':
			return irradianceFromCoefficients( normalWorld ).mul( intensity );
		case 'vertex':
			// The world normal at the vertex (three's LightProbe would use the pixel's), interpolated.
			return varying( irradianceFromCoefficients( ( modelNormalMatrix as TSLNode ).mul( normalLocal ).normalize() ).mul( intensity ), 'vProbeVolumeIrradiance' );
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

