import { Box3, Matrix4, Vector3, type Material, type Mesh, type Object3D, type SkinnedMesh } from 'three';
import { blendSH } from '../interpolation/blendSH.js';
import { irradianceMatrices } from '../sh/irradiance.js';
import { SH_FLOATS } from '../validate.js';
import type { AddOptions } from './LightProbeVolumeOptions.js';
import { ProbeTextureLighting } from './ProbeTextureLighting.js';
import { ProbeVertexLighting } from './ProbeVertexLighting.js';
import { MAX_WEIGHTS, type ProbeWeighting, type VisibilityCache } from './ProbeWeighting.js';
import type { ProbeField } from './ProbeField.js';
import type { ProbeZones } from './ProbeZones.js';
import { getProbeVolumeUniforms, patchMaterial, unpatchMaterial, type ProbeVolumeUniforms } from './patchMaterial.js';

/*
 * The objects a `LightProbeVolume` lights: registration in its three modes (object, vertex,
 * texture), the rule that decides whether a material is patched in place or cloned, removal, and
 * the per-frame update of an object-mode entry.
 */

/** One object registered with `LightProbeVolume.add`. */
export interface LitObject extends VisibilityCache {

	object: Object3D;
	hint: number;
	sh: Float32Array;
	uniforms: ProbeVolumeUniforms;
	/** Meshes whose material was replaced by a patched clone, with the original to restore. */
	replaced: { mesh: Mesh; original: Material | Material[] }[];
	/** Materials patched in place (the user's, owned by this object alone). */
	patched: Material[];
	/** Patched clones made for this object (ours, disposed on remove). */
	clones: Material[];
	/** The point, in the object's local frame, where the probes are sampled. */
	anchor: Float64Array;
	/** The zone given to add(), or −1 for automatic assignment by bounds. */
	fixedZone: number;
	/** The zone used last update (−1: the whole volume); a change resets `hint`. */
	zone: number;
	/** Large-object modes: the per-vertex lightings (one per mesh) or the 3D-texture lighting. */
	large: ( ProbeVertexLighting | ProbeTextureLighting )[] | null;
	/** Hidden during `capture()`. */
	hidden: boolean;

}

let _warnedInstancing = false;

/**
 * Builds the entry that lights `object` in the mode of `options`: the large-object lightings, or
 * the object's `MeshStandardMaterial`s patched — in place when only this object uses them, else as
 * clones (uniforms live on the material). The caller pushes it into `lit` (the other entries,
 * whose patched materials this one must not take over); an object-mode entry then needs one
 * {@link updateLitObject}.
 * @param field The probe field of the large-object modes.
 */
export function createLitObject(
	object: Object3D, options: AddOptions, fixedZone: number, field: () => ProbeField, lit: readonly LitObject[],
): LitObject {

	const entry: LitObject = {
		object, hint: - 1, sh: new Float32Array( SH_FLOATS ),
		uniforms: {
			probeVolumeMatrices: { value: new Float32Array( 48 ) },
			probeVolumeIntensity: { value: options.intensity ?? 1 },
			probeVolumeDirectScale: { value: 1 },
		},
		replaced: [], patched: [], clones: [], anchor: localBoundsCentre( object, options.anchor ),
		fixedZone, zone: - 1, guardPosition: new Float64Array( 3 ), guardIndices: new Uint32Array( MAX_WEIGHTS ),
		guardTested: 0, guardBlocked: 0, guardValid: false, guardFallback: - 2, large: null, hidden: true,
	};

	const mode = options.mode ?? 'object';
	entry.hidden = options.hideInCaptures ?? mode === 'object';
	if ( mode === 'vertex' || mode === 'texture' ) {

		entry.large = createLargeLightings( object, options, mode, field );
		entry.uniforms = entry.large[ 0 ]?.uniforms ?? entry.uniforms;
		return entry;

	}

	if ( mode !== 'object' ) {

		throw new RangeError( `LightProbeVolume.add: options.mode must be 'object', 'vertex' or 'texture', got ${String( mode )}.` );

	}

	patchObjectMaterials( entry, options.perVertex, lit );
	return entry;

}

/** Stops lighting an entry's object: its materials are restored, clones and large-object lightings disposed. */
export function disposeLitObject( entry: LitObject ): void {

	for ( const lighting of entry.large ?? [] ) lighting.dispose();
	for ( const { mesh, original } of entry.replaced ) mesh.material = original;
	for ( const material of entry.patched ) unpatchMaterial( material );
	for ( const material of entry.clones ) material.dispose();

}

/**
 * One frame of an entry: large objects resample when they moved or the SH changed; an object-mode
 * entry is weighed at its anchor (in its zone, walking from last frame's cell, through the guard)
 * and its irradiance matrices written. Allocation-free.
 */
export function updateLitObject( entry: LitObject, weighting: ProbeWeighting, zones: ProbeZones | null, sh: Float32Array ): void {

	if ( entry.large !== null ) {

		// Resample only when the object moved or the probes' SH changed (checked inside).
		for ( let i = 0; i < entry.large.length; i ++ ) entry.large[ i ].update();
		return;

	}

	const object = entry.object;
	object.updateWorldMatrix( true, false );
	const e = object.matrixWorld.elements, a = entry.anchor;
	const x = e[ 0 ] * a[ 0 ] + e[ 4 ] * a[ 1 ] + e[ 8 ] * a[ 2 ] + e[ 12 ];
	const y = e[ 1 ] * a[ 0 ] + e[ 5 ] * a[ 1 ] + e[ 9 ] * a[ 2 ] + e[ 13 ];
	const z = e[ 2 ] * a[ 0 ] + e[ 6 ] * a[ 1 ] + e[ 10 ] * a[ 2 ] + e[ 14 ];
	let zone = entry.fixedZone;
	if ( zone < 0 && zones !== null ) zone = zones.zoneAt( x, y, z );
	if ( zone !== entry.zone ) {

		// Cell indices belong to one interpolator: a hint from another zone's would be wrong.
		entry.zone = zone;
		entry.hint = - 1;

	}

	entry.hint = weighting.weigh( x, y, z, zone, entry.hint, entry );
	blendSH( weighting.indices, weighting.weights, sh, entry.sh, weighting.count );
	irradianceMatrices( entry.sh, entry.uniforms.probeVolumeMatrices.value );

}

/** The vertex- or texture-mode lightings of an object; none is left behind when one throws. */
function createLargeLightings(
	object: Object3D, options: AddOptions, mode: 'vertex' | 'texture', field: () => ProbeField,
): ( ProbeVertexLighting | ProbeTextureLighting )[] {

	const large: ( ProbeVertexLighting | ProbeTextureLighting )[] = [];
	try {

		if ( mode === 'texture' ) {

			const { intensity, texelSize, maxResolution } = options;
			large.push( new ProbeTextureLighting( object, field(), { intensity, texelSize, maxResolution } ) );

		} else {

			object.traverse( ( child ) => {

				const mesh = child as Mesh;
				if ( mesh.isMesh !== true ) return;
				large.push( new ProbeVertexLighting( mesh, field(), { intensity: options.intensity, output: options.vertexOutput } ) );

			} );

		}

	} catch ( error ) {

		for ( const lighting of large ) lighting.dispose();
		throw error;

	}

	return large;

}

/**
 * Patches the `MeshStandardMaterial`s of an object-mode entry. Uniforms live on the material: one
 * patched for another entry (or by the user) gets a clone of its own, which replaces it on the mesh.
 */
function patchObjectMaterials( entry: LitObject, perVertex: boolean | undefined, lit: readonly LitObject[] ): void {

	const owned = new Set<Material>();
	for ( const other of lit ) for ( const material of other.patched ) owned.add( material );

	entry.object.traverse( ( child ) => {

		const mesh = child as Mesh & { isInstancedMesh?: boolean };
		if ( ( mesh as { isMesh?: boolean } ).isMesh !== true ) return;
		if ( mesh.isInstancedMesh === true && ! _warnedInstancing ) {

			_warnedInstancing = true;
			console.warn(
				'LightProbeVolume.add: InstancedMesh is lit as one object, with the probes around its own origin; '
				+ 'per-instance probe lighting is not supported yet.',
			);

		}

		const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
		let replacement: Material[] | null = null;
		materials.forEach( ( material, i ) => {

			if ( ( material as { isMeshStandardMaterial?: boolean } ).isMeshStandardMaterial !== true ) return;
			if ( owned.has( material ) || ( getProbeVolumeUniforms( material ) !== null && ! entry.patched.includes( material ) ) ) {

				const copy = material.clone();
				patchMaterial( copy, { perVertex, uniforms: entry.uniforms } );
				replacement ??= materials.slice();
				replacement[ i ] = copy;
				entry.clones.push( copy );
				return;

			}

			if ( ! entry.patched.includes( material ) ) {

				patchMaterial( material, { perVertex, uniforms: entry.uniforms } );
				entry.patched.push( material );

			}

		} );

		if ( replacement ) {

			entry.replaced.push( { mesh, original: mesh.material } );
			mesh.material = Array.isArray( mesh.material ) ? replacement : replacement[ 0 ];

		}

	} );

}

/** The centre of an object's bounding box in its own frame (or the given anchor). */
function localBoundsCentre( object: Object3D, anchor?: { x: number; y: number; z: number } ): Float64Array {

	if ( anchor ) return Float64Array.of( anchor.x, anchor.y, anchor.z );
	object.updateWorldMatrix( true, true );
	// A skinned mesh's bounds follow its bones, whose matrices stay zero until the first render.
	object.traverse( ( child ) => ( child as SkinnedMesh ).skeleton?.update() );
	const box = new Box3().setFromObject( object );
	if ( box.isEmpty() ) return new Float64Array( 3 );
	const centre = box.getCenter( new Vector3() ).applyMatrix4( new Matrix4().copy( object.matrixWorld ).invert() );
	return Float64Array.of( centre.x, centre.y, centre.z );

}
