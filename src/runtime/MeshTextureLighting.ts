import { Box3, type Material, type Mesh } from 'three';
import type { ProbeField } from './ProbeField.js';
import { ProbeVolumeTexture } from './ProbeVolumeTexture.js';
import { meshWorldBox } from './chooseLighting.js';
import type { ProbeVolumeUniforms } from './patchMaterial.js';
import { patchProbeMaterial } from './nodeMaterialHooks.js';
import { takesProbeLight } from './probeLitMaterials.js';

/** Options of {@link MeshTextureLighting}. */
export interface MeshTextureLightingOptions {

	/** Probe light scale (`probeVolumeIntensity`). Default 1. */
	intensity?: number;

	/** World size of a texel. Default: the longest side / 31. */
	texelSize?: number;

	/** Largest texel count per axis. Default 64. */
	maxResolution?: number;

}

const _box = new Box3();

/**
 * Per-pixel probe light for one mesh of a level (`add( scene )`'s `'texture'` choice): a
 * {@link ProbeVolumeTexture} over the mesh's own world bounds, read by patched clones of its
 * materials that take probe light. Unlike `ProbeTextureLighting`, which lights an object with
 * everything below it, the mesh's children are left alone — they are lit (or not) on their own.
 * The same texture and shading as `ProbeTextureLighting` on a mesh without children.
 */
export class MeshTextureLighting {

	/** The lit mesh. */
	readonly mesh: Mesh;

	/** The resampled texture. */
	readonly volumeTexture: ProbeVolumeTexture;

	/** The uniforms shared by the patched clones. */
	readonly uniforms: ProbeVolumeUniforms;

	private readonly original: Material | Material[];
	private readonly clones: Material[] = [];
	private readonly matrix = new Float64Array( 16 );
	private disposed = false;
	private fieldChanged = false;

	/**
	 * @param mesh A mesh with a material that takes probe light and a position attribute, in world position.
	 * @param field The probes (checked by the caller).
	 * @param options See {@link MeshTextureLightingOptions} (checked by the caller).
	 */
	constructor( mesh: Mesh, field: ProbeField, options: MeshTextureLightingOptions = {} ) {

		this.mesh = mesh;
		const { texelSize, maxResolution } = options;
		this.volumeTexture = new ProbeVolumeTexture( field, this.bounds(), { texelSize, maxResolution } );
		const texture = this.volumeTexture;
		this.uniforms = {
			probeVolumeMatrices: { value: new Float32Array( 48 ) },
			probeVolumeIntensity: { value: options.intensity ?? 1 },
			probeVolumeDirectScale: { value: 1 },
			probeVolumeSH: { value: texture.texture },
			probeVolumeGridMin: { value: texture.min },
			probeVolumeGridMax: { value: texture.max },
			probeVolumeGridResolution: { value: texture.resolution },
		};
		this.matrix.set( mesh.matrixWorld.elements );
		this.original = mesh.material;
		const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
		const replacement = materials.map( ( material ) => {

			if ( ! takesProbeLight( material ) ) return material;
			// A clone: the original may light other meshes, outside this texture's box.
			const copy = material.clone();
			patchProbeMaterial( copy, { source: 'texture', perVertex: false, uniforms: this.uniforms } );
			this.clones.push( copy );
			return copy;

		} );
		mesh.material = Array.isArray( mesh.material ) ? replacement : replacement[ 0 ];

	}

	/** The probes the texture samples; assigning one resamples on the next `update()`. */
	get field(): ProbeField {

		return this.volumeTexture.field;

	}

	set field( field: ProbeField ) {

		this.volumeTexture.field = field;
		this.fieldChanged = true;

	}

	/**
	 * Resamples when the mesh moved (new bounds), the field was replaced or its SH or gradients changed.
	 * Allocation-free when nothing changed.
	 * @returns Whether it resampled.
	 */
	update(): boolean {

		if ( this.disposed ) throw new Error( 'MeshTextureLighting.update: called after dispose().' );
		this.mesh.updateWorldMatrix( true, false );
		const e = this.mesh.matrixWorld.elements, m = this.matrix;
		let moved = false;
		for ( let i = 0; i < 16; i ++ ) if ( e[ i ] !== m[ i ] ) { moved = true; m[ i ] = e[ i ]; }
		const force = this.fieldChanged;
		this.fieldChanged = false;
		if ( moved ) {

			this.volumeTexture.setBounds( this.bounds() );
			return true;

		}

		return this.volumeTexture.resample( force );

	}

	/** Restores the mesh's materials, disposes the clones and the texture. */
	dispose(): void {

		if ( this.disposed ) return;
		this.disposed = true;
		this.mesh.material = this.original;
		for ( const material of this.clones ) material.dispose();
		this.volumeTexture.dispose();

	}

	private bounds(): Box3 {

		meshWorldBox( this.mesh, _box );
		if ( _box.isEmpty() ) throw new RangeError( 'MeshTextureLighting: the mesh has empty bounds (no geometry).' );
		return _box;

	}

}
