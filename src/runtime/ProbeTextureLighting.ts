import { Box3, Vector3, type Material, type Mesh, type Object3D } from 'three';
import { assertProbeField, assertUsableProbeField, type ProbeField } from './ProbeField.js';
import { ProbeVolumeTexture, checkVolumeTextureOptions, type ProbeVolumeTextureOptions } from './ProbeVolumeTexture.js';
import { assertOptions } from '../validate.js';
import type { ProbeVolumeUniforms } from './patchMaterial.js';
import { patchProbeMaterial } from './nodeMaterialHooks.js';
import { PROBE_LIT_MATERIALS, takesProbeLight } from './probeLitMaterials.js';

/** Options of {@link ProbeTextureLighting}: the texture's plus intensity and padding. */
export interface ProbeTextureLightingOptions extends ProbeVolumeTextureOptions {

	/** Probe light scale (`probeVolumeIntensity`). Default 1. */
	intensity?: number;

	/** World distance added around the object's bounding box. Default 0. */
	padding?: number;

}

const _box = new Box3();
const _padding = new Vector3();

/**
 * Per-pixel probe light for a large object (a floor, a long wall, a whole level chunk): a
 * {@link ProbeVolumeTexture} over the object's world bounding box, sampled at each fragment's world
 * position by patched clones of the object's materials that take probe light (Standard, Physical,
 * Phong, Lambert, Toon; restored by `dispose()`). Independent of tessellation, unlike
 * {@link ProbeVertexLighting}; responds to normal maps.
 *
 * ```js
 * const lighting = new ProbeTextureLighting( floor, volume, { texelSize: 0.5 } );
 * // each frame (resamples only when the object moved or the probe SH changed):
 * lighting.update();
 * ```
 */
export class ProbeTextureLighting {

	/** The lit object (a mesh or a group: all its meshes). */
	readonly object: Object3D;

	/** The resampled texture (texture, bounds and resolution). */
	readonly volumeTexture: ProbeVolumeTexture;

	/** The uniforms shared by the patched clones. */
	readonly uniforms: ProbeVolumeUniforms;

	private readonly padding: number;
	private readonly replaced: { mesh: Mesh; original: Material | Material[] }[] = [];
	private readonly clones: Material[] = [];
	private readonly matrix = new Float64Array( 16 );
	private disposed = false;
	private fieldChanged = false;

	/**
	 * @param object A mesh or group with materials that take probe light, in world position (its bounds are read now).
	 * @param field The probes, e.g. a `LightProbeVolume`.
	 * @param options See {@link ProbeTextureLightingOptions}.
	 */
	constructor( object: Object3D, field: ProbeField, options: ProbeTextureLightingOptions = {} ) {

		const where = 'ProbeTextureLighting';
		if ( ! object || ( object as { isObject3D?: boolean } ).isObject3D !== true ) throw new TypeError( `${where}: object must be a three.js Object3D.` );
		assertUsableProbeField( where, field );
		assertOptions( where, 'options', options );
		const intensity = options.intensity ?? 1;
		if ( typeof intensity !== 'number' || ! Number.isFinite( intensity ) ) throw new RangeError( `${where}: options.intensity must be a finite number, got ${String( intensity )}.` );
		const padding = options.padding ?? 0;
		if ( ! ( typeof padding === 'number' && Number.isFinite( padding ) && padding >= 0 ) ) throw new RangeError( `${where}: options.padding must be a finite number ≥ 0, got ${String( options.padding )}.` );
		checkVolumeTextureOptions( where, options );
		this.padding = padding;

		this.object = object;
		this.volumeTexture = new ProbeVolumeTexture( field, this.bounds(), options );
		const texture = this.volumeTexture;
		this.uniforms = {
			probeVolumeMatrices: { value: new Float32Array( 48 ) },
			probeVolumeIntensity: { value: intensity },
			probeVolumeDirectScale: { value: 1 },
			probeVolumeSH: { value: texture.texture },
			probeVolumeGridMin: { value: texture.min },
			probeVolumeGridMax: { value: texture.max },
			probeVolumeGridResolution: { value: texture.resolution },
		};
		this.matrix.set( object.matrixWorld.elements );

		object.traverse( ( child ) => {

			const mesh = child as Mesh;
			if ( mesh.isMesh !== true ) return;
			const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
			let changed = false;
			const replacement = materials.map( ( material ) => {

				if ( ! takesProbeLight( material ) ) return material;
				// A clone: the original may light other objects, outside this texture's box.
				const copy = material.clone();
				patchProbeMaterial( copy, { source: 'texture', perVertex: false, uniforms: this.uniforms } );
				this.clones.push( copy );
				changed = true;
				return copy;

			} );
			if ( ! changed ) return;
			this.replaced.push( { mesh, original: mesh.material } );
			mesh.material = Array.isArray( mesh.material ) ? replacement : replacement[ 0 ];

		} );

		if ( this.clones.length === 0 ) {

			this.volumeTexture.dispose();
			throw new TypeError( `${where}: object has no mesh with a ${PROBE_LIT_MATERIALS} to light.` );

		}

	}

	/** The probes the texture samples; assigning one resamples on the next `update()`. */
	get field(): ProbeField {

		return this.volumeTexture.field;

	}

	set field( field: ProbeField ) {

		assertProbeField( 'ProbeTextureLighting.field', field );
		this.volumeTexture.field = field;
		this.fieldChanged = true;

	}

	/**
	 * Resamples when the object moved (its `matrixWorld` changed: new bounds), the field was
	 * replaced or its SH changed. Call once per frame; allocation-free when nothing changed.
	 * @returns Whether it resampled.
	 */
	update(): boolean {

		if ( this.disposed ) throw new Error( 'ProbeTextureLighting.update: called after dispose().' );
		this.object.updateWorldMatrix( true, false );
		const e = this.object.matrixWorld.elements, m = this.matrix;
		let moved = false;
		for ( let i = 0; i < 16; i ++ ) if ( e[ i ] !== m[ i ] ) { moved = true; m[ i ] = e[ i ]; }
		if ( moved ) {

			this.volumeTexture.setBounds( this.bounds() );
			this.fieldChanged = false;
			return true;

		}

		const force = this.fieldChanged;
		this.fieldChanged = false;
		return this.volumeTexture.resample( force );

	}

	/** Restores the materials, disposes the clones and the texture. */
	dispose(): void {

		if ( this.disposed ) return;
		this.disposed = true;
		for ( const { mesh, original } of this.replaced ) mesh.material = original;
		for ( const material of this.clones ) material.dispose();
		this.volumeTexture.dispose();

	}

	private bounds(): Box3 {

		this.object.updateWorldMatrix( true, true );
		_box.setFromObject( this.object );
		if ( _box.isEmpty() ) throw new RangeError( 'ProbeTextureLighting: the object has empty bounds (no geometry).' );
		return _box.expandByVector( _padding.setScalar( this.padding ) );

	}

}
