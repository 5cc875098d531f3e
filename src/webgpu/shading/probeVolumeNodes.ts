import { Data3DTexture, FloatType, HalfFloatType, LinearFilter, Matrix4, RGBAFormat, Vector3, type Material } from 'three';
import {
	attribute, dot, modelNormalMatrix, normalLocal, normalWorld, positionWorld, texture3D, uniform, varying, vec3, vec4,
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

