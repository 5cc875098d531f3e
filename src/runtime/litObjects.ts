import { Box3, Matrix4, Vector3, type Material, type Mesh, type Object3D, type SkinnedMesh } from 'three';
import { irradianceMatrices } from '../sh/irradiance.js';
import { SH_FLOATS, SH_LIMIT, assertInteger, assertNumber, assertOptionalBoolean, describeValue, firstBeyond } from '../validate.js';
import { anchorInWorld } from './anchorInWorld.js';
import { describeObject, meshWorldBox } from './chooseLighting.js';
import { blendProbes } from './gradientBlend.js';
import type { AddOptions, ProbeLighting } from './LightProbeVolumeOptions.js';
import { MeshTextureLighting } from './MeshTextureLighting.js';
import { ProbeTextureLighting } from './ProbeTextureLighting.js';
import { ProbeVertexLighting } from './ProbeVertexLighting.js';
import { MAX_WEIGHTS, type ProbeWeighting, type VisibilityCache } from './ProbeWeighting.js';
import type { ProbeField } from './ProbeField.js';
import type { ProbeZones } from './ProbeZones.js';
import type { ProbeVolumeUniforms } from './patchMaterial.js';
import { isLitNodeMaterial, nodeMaterialShading, nodeMaterialsNeedWebGPUEntry, patchProbeMaterial, probeUniformsOf, unpatchProbeMaterial } from './nodeMaterialHooks.js';
import { PROBE_LIT_MATERIALS, hasProbeLitMaterial, meshMaterials, takesProbeLight } from './probeLitMaterials.js';

/*
 * The objects a `LightProbeVolume` lights: registration in its three modes (object, vertex,
 * texture), the rule that decides whether a material is patched in place or cloned, removal, and
 * the per-frame update of an entry (static entries only when they moved or the probes changed).
 */

/** A large-object lighting of an entry: per vertex (one per mesh) or from a 3D SH texture. */
export type LargeLighting = ProbeVertexLighting | ProbeTextureLighting | MeshTextureLighting;

/** How an entry was registered: by `add( object )` itself, or as one object of `add( scene )`. */
export interface EntryScope {

	/** The root passed to `add( scene )` (mode `'auto'`) that registered it; null for `add( object )`. */
	root: Object3D | null;

	/** Whether the entry lights everything below its object (else the object alone: a mesh of a level). */
	subtree: boolean;

	/** Blended (or resampled) only when the object moved or the probes changed, not every frame. */
	static: boolean;

}

/** The scope of `add( object )`: the object with everything below it, updated every frame. */
export const EXPLICIT_SCOPE: EntryScope = { root: null, subtree: true, static: false };

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
	large: LargeLighting[] | null;
	/** Hidden during `capture()`. */
	hidden: boolean;
	/** What `LightProbeVolume.getLighting` reports for the object. */
	lighting: ProbeLighting;
	/** The `add( scene )` root that registered it, or null. */
	root: Object3D | null;
	/** Whether it lights the object's descendants too. */
	subtree: boolean;
	/** Updated only when {@link LitObject.matrix} or {@link LitObject.version} changed. */
	static: boolean;
	/** Static entries: the object's world matrix at the last update (NaN before the first). */
	matrix: Float64Array;
	/** Static entries: the volume's lighting version at the last update. */
	version: number;
	/** The options it was registered with (to register it again). */
	options: AddOptions;

}

let _warnedInstancing = false;
const _world = new Float64Array( 3 );

// Local copies: read in update()'s per-object loop (an imported binding can cost a getter call each time).
const BLEND_FLOATS = SH_FLOATS;
const BLEND_SQUARES = 28 * SH_LIMIT * SH_LIMIT;

/**
 * Builds the entry that lights `object` in the mode of `options`: the large-object lightings, or
 * the object's materials that take probe light (see `takesProbeLight`) patched — in place when
 * only this object uses them, else as clones (uniforms live on the material). The caller pushes
 * it into `lit` (the other entries, whose patched materials this one must not take over); an
 * object-mode entry then needs one {@link updateLitObject}.
 * @param field The probe field of the large-object modes.
 * @throws TypeError, for `add( object )` itself, when no mesh of the object takes probe light.
 */
export function createLitObject(
	object: Object3D, options: AddOptions, fixedZone: number, field: () => ProbeField, lit: readonly LitObject[],
	scope: EntryScope = EXPLICIT_SCOPE,
): LitObject {

	checkAddOptions( options );
	if ( scope.root === null ) assertProbeLitObject( object );
	const mode = options.mode ?? 'object';
	const hidden = options.hideInCaptures ?? mode === 'object';
	const entry: LitObject = {
		object, hint: - 1, sh: new Float32Array( SH_FLOATS ),
		uniforms: {
			probeVolumeMatrices: { value: new Float32Array( 48 ) },
			probeVolumeIntensity: { value: options.intensity ?? 1 },
			probeVolumeDirectScale: { value: 1 },
		},
		replaced: [], patched: [], clones: [], anchor: localBoundsCentre( object, options.anchor, scope.subtree ),
		fixedZone, zone: - 1, guardPosition: new Float64Array( 3 ), guardIndices: new Uint32Array( MAX_WEIGHTS ),
		guardTested: 0, guardBlocked: 0, guardValid: false, guardFallback: - 2, large: null, hidden,
		lighting: mode === 'object' ? ( hidden ? 'dynamic' : 'object' ) : mode as 'vertex' | 'texture',
		root: scope.root, subtree: scope.subtree, static: scope.static, matrix: new Float64Array( 16 ).fill( NaN ), version: - 1,
		options,
	};

	if ( mode === 'vertex' || mode === 'texture' ) {

		entry.large = createLargeLightings( object, options, mode, field, scope.subtree );
		entry.uniforms = entry.large[ 0 ]?.uniforms ?? entry.uniforms;
		return entry;

	}

	patchObjectMaterials( entry, options.perVertex, lit );
	return entry;

}

/** Stops lighting an entry's object: its materials are restored, clones and large-object lightings disposed. */
export function disposeLitObject( entry: LitObject ): void {

	for ( const lighting of entry.large ?? [] ) lighting.dispose();
	for ( const { mesh, original } of entry.replaced ) mesh.material = original;
	for ( const material of entry.patched ) unpatchProbeMaterial( material );
	for ( const material of entry.clones ) material.dispose();

}

/**
 * One frame of an entry: large objects resample when they moved or the SH changed; an object-mode
 * entry is weighed at its anchor (in its zone, walking from last frame's cell, through the guard),
 * blended there (by the gradient formula at the anchor for gradient probes) and its irradiance
 * matrices written — zeros (no probe light) when the blend is not finite or far beyond ±SH_LIMIT
 * (SH written into the volume's `sh` directly). Allocation-free.
 * @param gradients The volume's gradients (81 per probe, checked by the caller), or null.
 * @param positions The volume's probe positions.
 * @returns false when the blend was refused (see {@link reportBadBlend}), else true.
 */
export function updateLitObject(
	entry: LitObject, weighting: ProbeWeighting, zones: ProbeZones | null, sh: Float32Array, gradients: Float32Array | null,
	positions: Float64Array, version: number,
): boolean {

	if ( entry.static && ! staticEntryChanged( entry, version ) ) return true;
	if ( entry.large !== null ) {

		// Resample only when the object moved or the probes' SH changed (checked inside).
		for ( let i = 0; i < entry.large.length; i ++ ) entry.large[ i ].update();
		return true;

	}

	entry.object.updateWorldMatrix( true, false );
	const world = anchorInWorld( entry.object, entry.anchor, _world );
	const x = world[ 0 ], y = world[ 1 ], z = world[ 2 ];
	let zone = entry.fixedZone;
	if ( zone < 0 && zones !== null ) zone = zones.zoneAt( x, y, z );
	if ( zone !== entry.zone ) {

		// Cell indices belong to one interpolator: a hint from another zone's would be wrong.
		entry.zone = zone;
		entry.hint = - 1;

	}

	entry.hint = weighting.weigh( x, y, z, zone, entry.hint, entry );
	const blend = blendProbes( weighting.indices, weighting.weights, weighting.count, sh, gradients, positions, x, y, z, entry.sh );
	// Σ v² ≤ 28 · SH_LIMIT² holds for every blend of valid probes (each |v| ≤ SH_LIMIT, weights summing to 1)
	// and bounds each |v| by 5.3 · SH_LIMIT, which keeps the matrices and the shader's nᵀMn finite in
	// float32; NaN and ±Infinity fail it. Three running sums: no branch, no dependency chain of 27.
	let r = 0, g = 0, b = 0;
	for ( let i = 0; i < BLEND_FLOATS; i += 3 ) {

		const vr = blend[ i ], vg = blend[ i + 1 ], vb = blend[ i + 2 ];
		r += vr * vr; g += vg * vg; b += vb * vb;

	}

	const m = entry.uniforms.probeVolumeMatrices.value;
	if ( ! ( r + g + b <= BLEND_SQUARES ) ) {

		m.fill( 0 );
		return false;

	}

	irradianceMatrices( blend, m );
	return true;

}

/**
 * Whether a static entry must be updated: its object moved (world matrix) or the volume's lighting
 * version changed since its last update; records both. Allocation-free.
 */
function staticEntryChanged( entry: LitObject, version: number ): boolean {

	const object = entry.object;
	object.updateWorldMatrix( true, false );
	const e = object.matrixWorld.elements, m = entry.matrix;
	let changed = entry.version !== version;
	entry.version = version;
	for ( let i = 0; i < 16; i ++ ) if ( e[ i ] !== m[ i ] ) { changed = true; m[ i ] = e[ i ]; }
	return changed;

}

/**
 * Throws the RangeError for an entry whose blend {@link updateLitObject} refused: names the object
 * and the first probe whose SH (written into the volume's `sh` directly) is not finite or beyond
 * ±1e30, or whose gradient is not finite, or the object's position when the probes are fine.
 */
export function reportBadBlend( where: string, entry: LitObject, sh: Float32Array, gradients: Float32Array | null ): never {

	const name = describeObject( entry.object );
	const i = firstBeyond( sh, SH_LIMIT ), j = gradients !== null ? firstBeyond( gradients, Infinity ) : - 1;
	let cause = gradients !== null
		? 'its position is not finite, or so far from the probes that their gradients take the blend beyond the SH limit'
		: 'its position is not finite';
	if ( j >= 0 ) cause = `probe ${Math.floor( j / 81 )} holds gradients[${j}] = ${gradients![ j ]}; probe gradients must be finite`;
	if ( i >= 0 ) {

		cause = `probe ${Math.floor( i / SH_FLOATS )} holds sh[${i}] = ${sh[ i ]}; probe SH must be finite and within ±${SH_LIMIT.toPrecision( 3 )}`;

	}

	throw new RangeError( `${where}: the blend for object ${name} is not finite (${cause}); its probe light is off (zero matrices).` );

}

/**
 * `add( object )` of something whose materials all take no probe light (a lamp's
 * `MeshBasicMaterial`, a `ShaderMaterial`) is a mistake, not a no-op: an Error says so before
 * anything is patched. An object that draws nothing (no material at all) has nothing to light.
 */
function assertProbeLitObject( object: Object3D ): void {

	const types = new Set<string>(), nodes = new Set<string>();
	let found = false;
	object.traverse( ( node ) => {

		if ( found || ( node as Mesh ).isMesh !== true ) return;
		found = hasProbeLitMaterial( node as Mesh );
		for ( const material of meshMaterials( node as Mesh ) ) {

			types.add( material.type );
			if ( isLitNodeMaterial( material ) ) nodes.add( material.type );

		}

	} );
	if ( found || types.size === 0 ) return;
	// Lit node materials are lit by the WebGPU entry's shading: without it, say where to get it.
	if ( nodeMaterialShading() === null && nodes.size > 0 ) {

		throw new TypeError( nodeMaterialsNeedWebGPUEntry( 'LightProbeVolume.add', describeObject( object ), [ ...nodes ] ) );

	}

	throw new TypeError( `LightProbeVolume.add: ${describeObject( object )} has only ${[ ...types ].join( ', ' )}; probe light `
		+ `needs a mesh with a ${PROBE_LIT_MATERIALS} (the others are unlit or shade themselves).` );

}

/** Checks an argument is a three.js `Object3D`. */
export function assertObject3D( where: string, object: unknown ): asserts object is Object3D {

	if ( ( object as { isObject3D?: boolean } | null )?.isObject3D !== true ) {

		throw new TypeError( `${where}: object must be a three.js Object3D, got ${describeValue( object )}.` );

	}

}

/** The options of `LightProbeVolume.add` in modes 'object', 'vertex' and 'texture', checked before anything is patched. */
export function checkAddOptions( options: AddOptions ): void {

	const where = 'LightProbeVolume.add';
	assertOptionalBoolean( where, 'options.perVertex', options.perVertex );
	assertOptionalBoolean( where, 'options.hideInCaptures', options.hideInCaptures );
	if ( options.intensity !== undefined ) assertNumber( where, 'options.intensity', options.intensity );
	if ( options.anchor !== undefined ) {

		const a = options.anchor as { x?: unknown; y?: unknown; z?: unknown } | null;
		if ( ! a || typeof a !== 'object' || ! [ a.x, a.y, a.z ].every( ( v ) => typeof v === 'number' && Number.isFinite( v ) ) ) {

			throw new TypeError( `${where}: options.anchor must be { x, y, z } of finite numbers (e.g. a Vector3), got ${describeValue( options.anchor )}.` );

		}

	}

	const mode = options.mode ?? 'object';
	if ( mode !== 'object' && mode !== 'vertex' && mode !== 'texture' ) {

		throw new RangeError( `${where}: options.mode must be 'object', 'vertex', 'texture' or 'auto', got ${describeValue( mode )}.` );

	}

	const output = options.vertexOutput;
	if ( output !== undefined && output !== 'irradiance' && output !== 'sh' ) {

		throw new RangeError( `${where}: options.vertexOutput must be 'irradiance' or 'sh', got ${describeValue( output )}.` );

	}

	if ( options.texelSize !== undefined ) {

		assertNumber( where, 'options.texelSize', options.texelSize );
		if ( ! ( options.texelSize > 0 ) ) throw new RangeError( `${where}: options.texelSize must be > 0, got ${options.texelSize}.` );

	}

	if ( options.maxResolution !== undefined ) assertInteger( where, 'options.maxResolution', options.maxResolution, 2, 256 );

}

/**
 * The vertex- or texture-mode lightings of an object (of the object alone, a mesh, when `subtree`
 * is false); none is left behind when one throws.
 */
function createLargeLightings(
	object: Object3D, options: AddOptions, mode: 'vertex' | 'texture', field: () => ProbeField, subtree: boolean,
): LargeLighting[] {

	const large: LargeLighting[] = [];
	try {

		const { intensity, texelSize, maxResolution } = options;
		if ( mode === 'texture' && subtree ) {

			large.push( new ProbeTextureLighting( object, field(), { intensity, texelSize, maxResolution } ) );

		} else if ( mode === 'texture' ) {

			large.push( new MeshTextureLighting( object as Mesh, field(), { intensity, texelSize, maxResolution } ) );

		} else {

			const visit = ( child: Object3D ) => {

				const mesh = child as Mesh;
				// Below a group, meshes that take no probe light (a lamp's bulb) are left as they are.
				if ( mesh.isMesh !== true || ( subtree && ! hasProbeLitMaterial( mesh ) ) ) return;
				large.push( new ProbeVertexLighting( mesh, field(), { intensity, output: options.vertexOutput } ) );

			};

			if ( subtree ) object.traverse( visit );
			else visit( object );

		}

	} catch ( error ) {

		for ( const lighting of large ) lighting.dispose();
		throw error;

	}

	return large;

}

/**
 * Patches the materials of an object-mode entry that take probe light. Uniforms live on the material:
 * one patched for another entry (or by the user) gets a clone of its own, which replaces it on the mesh.
 */
function patchObjectMaterials( entry: LitObject, perVertex: boolean | undefined, lit: readonly LitObject[] ): void {

	const owned = new Set<Material>();
	for ( const other of lit ) for ( const material of other.patched ) owned.add( material );

	const visit = ( child: Object3D ) => {

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

			// A null or undefined slot is drawn by nothing (three skips it): nothing to patch.
			if ( ! takesProbeLight( material ) ) return;
			if ( owned.has( material ) || ( probeUniformsOf( material ) !== null && ! entry.patched.includes( material ) ) ) {

				const copy = material.clone();
				patchProbeMaterial( copy, { source: 'uniform', perVertex: perVertex === true, uniforms: entry.uniforms } );
				replacement ??= materials.slice();
				replacement[ i ] = copy;
				entry.clones.push( copy );
				return;

			}

			if ( ! entry.patched.includes( material ) ) {

				patchProbeMaterial( material, { source: 'uniform', perVertex: perVertex === true, uniforms: entry.uniforms } );
				entry.patched.push( material );

			}

		} );

		if ( replacement ) {

			entry.replaced.push( { mesh, original: mesh.material } );
			mesh.material = Array.isArray( mesh.material ) ? replacement : replacement[ 0 ];

		}

	};

	if ( entry.subtree ) entry.object.traverse( visit );
	else visit( entry.object );

}

/** The centre of an object's bounding box (of the object alone when not `subtree`) in its own frame, or the given anchor. */
export function localBoundsCentre(
	object: Object3D, anchor: { x: number; y: number; z: number } | undefined, subtree: boolean,
): Float64Array {

	if ( anchor ) return Float64Array.of( anchor.x, anchor.y, anchor.z );
	object.updateWorldMatrix( true, true );
	// A skinned mesh's bounds follow its bones, whose matrices stay zero until the first render.
	object.traverse( ( child ) => ( child as SkinnedMesh ).skeleton?.update() );
	const box = subtree ? new Box3().setFromObject( object ) : meshWorldBox( object as Mesh, new Box3() );
	if ( box.isEmpty() ) return new Float64Array( 3 );
	const centre = box.getCenter( new Vector3() ).applyMatrix4( new Matrix4().copy( object.matrixWorld ).invert() );
	return Float64Array.of( centre.x, centre.y, centre.z );

}
