import { FloatType, type Material } from 'three';
import type { NodeMaterialShading, ProbeMaterialPatch } from '../../runtime/nodeMaterialHooks.js';
import { isLitNodeMaterial, isNodeMaterial } from '../../runtime/nodeMaterialHooks.js';
import type { ProbeVolumeUniforms } from '../../runtime/patchMaterial.js';
import { probeLightingNode } from './ProbeVolumeLightingNode.js';
import { WRAPPED, probeMaterialRecords, type ProbeMaterialRecord, type ProbeNodeVariant, type WrappedMethod } from './probeMaterialRecords.js';
import { directScale, probeIrradianceNode } from './probeVolumeNodes.js';

/** The own property holding the variant's node (see `patch`). */
const REFRESH = 'probeVolumeNode';


/*
 * Node-material shading (docs/webgpu.md): a patched material gets three own methods that wrap its
 * class's — setupMaterialLightings adds the shared probe lighting node of its variant,
 * setupLightingModel scales the direct light before the indirect term, customProgramCacheKey
 * (node materials only) names the variant. A built-in material keeps them as own enumerable
 * properties, which three's NodeLibrary.fromMaterial copies onto the node material it draws with.
 * The wrappers look the variant up from `builder.material` (the material being drawn: the built-in
 * one, not three's copy), so they hold no state and have the same source text for every material:
 * materials of one type and variant get one cache key, one node graph and one pipeline.
 */

interface Builder {

	material: Material;

}

interface LightingModelLike {

	indirect( builder: any ): void;
	/** PhysicalLightingModel's clear-coat and sheen direct terms (with clearcoat / sheen on). */
	clearcoatSpecularDirect?: any;
	sheenSpecularDirect?: any;

}

type Method = ( this: any, ...args: any[] ) => any;

/** The method a wrapper stands in for: the own property it replaced, else the class's. */
function original( material: any, record: ProbeMaterialRecord | undefined, name: WrappedMethod ): Method {

	const previous = record?.previous[ name ] as Method | undefined;
	if ( previous !== undefined ) return previous;
	return Object.getPrototypeOf( material )[ name ] as Method;

}

/** Adds the probe lighting node of the drawn material's variant to its own lightings. */
function setupMaterialLightings( this: any, builder: Builder ): unknown[] {

	const record = probeMaterialRecords.get( builder.material );
	const lightings = original( this, record, 'setupMaterialLightings' ).call( this, builder ) as unknown[];
	if ( record !== undefined ) lightings.push( probeLightingNode( record.variant ) );
	return lightings;

}

/**
 * Wraps the lighting model so that the direct light (all direct lights have been added when the
 * model's `indirect` runs) is scaled by `probeVolumeDirectScale`, as reflectedLight's direct terms
 * are in the WebGL patch, and the clear-coat and sheen direct terms too; 0 shows the probe light alone.
 */
function setupLightingModel( this: any, builder: Builder ): LightingModelLike | null {

	const record = probeMaterialRecords.get( builder.material );
	const model = original( this, record, 'setupLightingModel' ).call( this, builder ) as LightingModelLike | null;
	if ( record === undefined || model === null || model === undefined ) return model;
	const indirect = model.indirect;
	model.indirect = function ( this: LightingModelLike, nodeBuilder: any ) {

		const reflected = nodeBuilder.context.reflectedLight;
		reflected.directDiffuse.mulAssign( directScale );
		reflected.directSpecular.mulAssign( directScale );
		// Clear coat and sheen keep their direct light apart (added in the model's finish).
		this.clearcoatSpecularDirect?.mulAssign( directScale );
		this.sheenSpecularDirect?.mulAssign( directScale );
		indirect.call( this, nodeBuilder );

	};

	return model;

}

/** A node material's key with the variant appended (a built-in material's key comes from patchMaterial). */
function customProgramCacheKey( this: any ): string {

	const record = probeMaterialRecords.get( this );
	const key = original( this, record, 'customProgramCacheKey' ).call( this ) as string;
	return record !== undefined ? `${key}|three-capture-lighting:1:${record.variant}` : key;

}

const WRAPPERS: Record<WrappedMethod, Method> = { setupLightingModel, setupMaterialLightings, customProgramCacheKey };

/** The node graph for a patch. */
function variantOf( patch: ProbeMaterialPatch ): ProbeNodeVariant {

	switch ( patch.source ) {

		case 'uniform': return patch.perVertex ? 'vertex' : 'pixel';
		case 'texture': return patch.uniforms.probeVolumeSH?.value?.type === FloatType ? 'textureFloat' : 'texture';
		default: return patch.source;

	}

}

/** The {@link NodeMaterialShading} that `three-capture-lighting/webgpu` installs. */
export class NodeProbeShading implements NodeMaterialShading {

	/** Node materials of the lit types: Standard, Physical, Phong, Lambert, Toon. */
	lights( material: Material ): boolean {

		return isLitNodeMaterial( material );

	}

	/** Wraps the material's methods (see the file comment); the material recompiles on its next draw. */
	patch( material: Material, patch: ProbeMaterialPatch ): void {

		if ( probeMaterialRecords.has( material ) ) return;
		const target = material as unknown as Record<string, unknown>;
		const previous: ProbeMaterialRecord[ 'previous' ] = {};
		const names = WRAPPED.filter( ( name ) => name !== 'customProgramCacheKey' || isNodeMaterial( material ) );
		for ( const name of names ) {

			if ( Object.prototype.hasOwnProperty.call( target, name ) ) previous[ name ] = target[ name ];
			target[ name ] = WRAPPERS[ name ];

		}

		const variant = variantOf( patch );
		probeMaterialRecords.set( material, { variant, uniforms: patch.uniforms, previous } );
		// A node among the material's own properties makes three's observer refresh its draws every
		// frame (else unchanged materials and matrices skip the per-object uniform updates).
		target[ REFRESH ] = probeIrradianceNode( variant );
		material.needsUpdate = true;

	}

	/** Restores the material's own properties; it recompiles without probe light on its next draw. */
	unpatch( material: Material ): void {

		const record = probeMaterialRecords.get( material );
		if ( record === undefined ) return;
		const target = material as unknown as Record<string, unknown>;
		for ( const name of WRAPPED ) {

			if ( target[ name ] !== WRAPPERS[ name ] ) continue;
			if ( record.previous[ name ] !== undefined ) target[ name ] = record.previous[ name ];
			else delete target[ name ];

		}

		if ( target[ REFRESH ] === probeIrradianceNode( record.variant ) ) delete target[ REFRESH ];
		probeMaterialRecords.delete( material );
		material.needsUpdate = true;

	}

	/** The uniforms of a material it patched, or null. */
	uniformsOf( material: Material ): ProbeVolumeUniforms | null {

		return probeMaterialRecords.get( material )?.uniforms ?? null;

	}

}
