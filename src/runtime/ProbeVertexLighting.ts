import { BackSide, BufferAttribute, InterleavedBuffer, InterleavedBufferAttribute, Matrix3, type BufferGeometry, type Material, type Mesh } from 'three';
import { irradianceAt } from '../sh/irradiance.js';
import { blendProbes } from './gradientBlend.js';
import { GradientTracker } from './gradientTracker.js';
import { assertProbeField, assertUsableProbeField, trackSH, type ProbeField } from './ProbeField.js';
import { assertOptions } from '../validate.js';
import type { ProbeVolumeUniforms } from './patchMaterial.js';
import { patchProbeMaterial } from './nodeMaterialHooks.js';
import { PROBE_LIT_MATERIALS, takesProbeLight } from './probeLitMaterials.js';

/** Options of {@link ProbeVertexLighting}. */
export interface ProbeVertexLightingOptions {

	/**
	 * What each vertex stores:
	 * - `'irradiance'` (default): E(n) for the vertex's world normal, one vec3 attribute
	 *   (`probeIrradiance`, 12 bytes a vertex), for −n when every lit material is `BackSide` (the
	 *   normal it shades with; `DoubleSide` takes n: use `'sh'` for walls seen from both sides).
	 *   Normal and bump maps do not change the probe light (it is fixed per vertex), and a normal
	 *   that changes within a triangle is only interpolated.
	 * - `'sh'`: the blended SH itself, 7 vec4 attributes (`probeSH0`…`probeSH6`, 112 bytes a vertex,
	 *   one interleaved buffer), evaluated per pixel with the shaded normal: normal maps respond.
	 *   Costs 7 of WebGL2's 16 guaranteed vertex attributes and 7 varyings.
	 *
	 * `'irradiance'` is the default because it fits any material (skinning, morphs, uv2, tangents
	 * can use most of the 16 attribute slots) and uploads 9× less; use `'sh'` for normal-mapped
	 * floors and walls.
	 */
	output?: 'irradiance' | 'sh';

	/** Probe light scale (`probeVolumeIntensity`). Default 1. */
	intensity?: number;

}

const MAX_WEIGHTS = 8;
const _indices = new Uint32Array( MAX_WEIGHTS );
const _weights = new Float64Array( MAX_WEIGHTS );
const _sh = new Float64Array( 27 );
const _normalMatrix = new Matrix3();

/** A plain float attribute's array, read directly; null for interleaved or normalized ones (read with getX()). */
function directArray( attribute: BufferAttribute | undefined ): ArrayLike<number> | null {

	if ( attribute === undefined ) return null;
	const interleaved = ( attribute as { isInterleavedBufferAttribute?: boolean } ).isInterleavedBufferAttribute === true;
	return ! interleaved && attribute.normalized !== true ? attribute.array : null;

}

/** Attribute names this class writes. */
const IRRADIANCE = 'probeIrradiance';
const SH_NAMES = [ 0, 1, 2, 3, 4, 5, 6 ].map( ( i ) => `probeSH${i}` );

/**
 * Probe light per vertex for a large mesh (a floor, a long wall): the tetrahedral field is sampled
 * at every vertex's world position — not once per object — so the light changes across the mesh
 * (gradient probes blended by the gradient formula at each vertex).
 * The mesh's materials that take probe light (Standard, Physical, Phong, Lambert, Toon) are
 * replaced by patched clones (restored by `dispose()`) that read vertex attributes written into
 * the mesh's geometry.
 *
 * The geometry must belong to this mesh alone (the light depends on world positions): share-nothing
 * with `mesh.geometry = mesh.geometry.clone()` first. Static or occasionally moved meshes only:
 * skinning and morph targets are not followed. Light varies linearly across each triangle, so a
 * coarsely tessellated floor shows the field only at its corners; use {@link ProbeTextureLighting}
 * for per-pixel light independent of tessellation.
 *
 * ```js
 * const lighting = new ProbeVertexLighting( floor, volume ); // volume: a LightProbeVolume
 * // each frame (recomputes only when the mesh moved or the probe SH changed):
 * lighting.update();
 * ```
 */
export class ProbeVertexLighting {

	/** The lit mesh. */
	readonly mesh: Mesh;

	/**
	 * The probes: a `LightProbeVolume` or any `{ interpolator, sh, gradients?, positions? }`. May be replaced (resampled
	 * on the next `update()`).
	 */
	field: ProbeField;

	/** What the vertices store, see {@link ProbeVertexLightingOptions.output}. */
	readonly output: 'irradiance' | 'sh';

	/** The uniforms shared by the patched clones (intensity, direct scale). */
	readonly uniforms: ProbeVolumeUniforms;

	/** The attribute (irradiance) or interleaved buffer (SH) written into the geometry. */
	readonly data: Float32Array;

	private readonly geometry: BufferGeometry;
	private readonly original: Material | Material[];
	private readonly clones: Material[] = [];
	private readonly attributes: ( BufferAttribute | InterleavedBufferAttribute )[] = [];
	private readonly buffer: BufferAttribute | InterleavedBuffer;
	private readonly matrix = new Float64Array( 16 ).fill( NaN );
	private lastField: ProbeField | null = null;
	private shCopy: Float32Array | null = null;
	private readonly gradientTracker = new GradientTracker();
	private positionVersion = - 1;
	private normalVersion = - 1;
	private disposed = false;

	/**
	 * @param mesh A `Mesh` (not skinned, not instanced) with a position attribute (and normals for `'irradiance'`).
	 * @param field The probes, e.g. a `LightProbeVolume`.
	 * @param options See {@link ProbeVertexLightingOptions}.
	 */
	constructor( mesh: Mesh, field: ProbeField, options: ProbeVertexLightingOptions = {} ) {

		const where = 'ProbeVertexLighting';
		const candidate = mesh as Mesh & { isSkinnedMesh?: boolean; isInstancedMesh?: boolean };
		if ( ! candidate || candidate.isMesh !== true ) throw new TypeError( `${where}: mesh must be a three.js Mesh.` );
		if ( candidate.isSkinnedMesh === true || candidate.isInstancedMesh === true ) throw new TypeError( `${where}: skinned and instanced meshes are not supported (their vertices move on the GPU); use LightProbeVolume.add().` );
		assertUsableProbeField( where, field );
		assertOptions( where, 'options', options );
		const output = options.output ?? 'irradiance';
		if ( output !== 'irradiance' && output !== 'sh' ) throw new RangeError( `${where}: options.output is "${String( output )}"; expected 'irradiance' or 'sh'.` );
		const intensity = options.intensity ?? 1;
		if ( typeof intensity !== 'number' || ! Number.isFinite( intensity ) ) throw new RangeError( `${where}: options.intensity must be a finite number, got ${String( intensity )}.` );

		const geometry = mesh.geometry;
		const position = geometry?.getAttribute( 'position' );
		if ( ! position || position.itemSize < 3 ) throw new RangeError( `${where}: mesh.geometry has no position attribute.` );
		if ( output === 'irradiance' && ! geometry.getAttribute( 'normal' ) ) throw new RangeError( `${where}: output 'irradiance' needs a normal attribute (geometry.computeVertexNormals()), or use output 'sh'.` );
		if ( geometry.getAttribute( IRRADIANCE ) || geometry.getAttribute( SH_NAMES[ 0 ] ) ) {

			throw new Error( `${where}: mesh.geometry already carries probe attributes — another ProbeVertexLighting lights a mesh sharing this geometry; give each mesh its own (mesh.geometry = mesh.geometry.clone()).` );

		}

		this.mesh = mesh;
		this.field = field;
		this.output = output;
		this.geometry = geometry;
		this.uniforms = {
			probeVolumeMatrices: { value: new Float32Array( 48 ) },
			probeVolumeIntensity: { value: intensity },
			probeVolumeDirectScale: { value: 1 },
		};

		const count = position.count;
		if ( output === 'irradiance' ) {

			this.data = new Float32Array( 3 * count );
			const attribute = new BufferAttribute( this.data, 3 );
			geometry.setAttribute( IRRADIANCE, attribute );
			this.attributes.push( attribute );
			this.buffer = attribute;

		} else {

			this.data = new Float32Array( 28 * count );
			const buffer = new InterleavedBuffer( this.data, 28 );
			SH_NAMES.forEach( ( name, i ) => {

				const attribute = new InterleavedBufferAttribute( buffer, 4, 4 * i );
				geometry.setAttribute( name, attribute );
				this.attributes.push( attribute );

			} );
			this.buffer = buffer;

		}

		this.original = mesh.material;
		const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
		const replaced = materials.map( ( material ) => {

			if ( ! takesProbeLight( material ) ) return material;
			// A clone: the original may be shared with meshes that have no probe attributes.
			const copy = material.clone();
			patchProbeMaterial( copy, { source: output === 'irradiance' ? 'vertexIrradiance' : 'vertexSH', perVertex: false, uniforms: this.uniforms } );
			this.clones.push( copy );
			return copy;

		} );
		if ( this.clones.length === 0 ) {

			this.removeAttributes();
			throw new TypeError( `${where}: mesh has no ${PROBE_LIT_MATERIALS} to light.` );

		}

		mesh.material = Array.isArray( mesh.material ) ? replaced : replaced[ 0 ];
		this.update();

	}

	/**
	 * Recomputes the vertex light when the mesh moved (its `matrixWorld` changed), its positions or
	 * normals changed (attribute `version`), the field was replaced or its SH or gradients changed.
	 * Call once per frame (or after moving the mesh); allocation-free when nothing changed.
	 * @returns Whether it recomputed.
	 */
	update(): boolean {

		if ( this.disposed ) throw new Error( 'ProbeVertexLighting.update: called after dispose().' );
		const mesh = this.mesh;
		mesh.updateWorldMatrix( true, false );
		const e = mesh.matrixWorld.elements, m = this.matrix;
		let changed = false;
		for ( let i = 0; i < 16; i ++ ) if ( e[ i ] !== m[ i ] ) { changed = true; m[ i ] = e[ i ]; }

		const geometry = this.geometry;
		const position = geometry.getAttribute( 'position' ) as BufferAttribute;
		const normal = geometry.getAttribute( 'normal' ) as BufferAttribute | undefined;
		if ( position.version !== this.positionVersion || ( normal?.version ?? - 1 ) !== this.normalVersion ) changed = true;
		if ( this.field !== this.lastField ) {

			assertProbeField( 'ProbeVertexLighting.update', this.field );
			this.lastField = this.field;
			changed = true;

		}

		const copy = trackSH( 'ProbeVertexLighting.update', this.field.sh, this.shCopy );
		if ( copy !== null ) { this.shCopy = copy; changed = true; }
		if ( this.gradientTracker.changed( 'ProbeVertexLighting.update', this.field.gradients, this.field.positions ) ) changed = true;
		if ( ! changed ) return false;
		this.compute();
		return true;

	}

	/** Recomputes every vertex now, whatever changed. */
	compute(): void {

		const geometry = this.geometry;
		const position = geometry.getAttribute( 'position' ) as BufferAttribute;
		if ( position.count * ( this.output === 'irradiance' ? 3 : 28 ) !== this.data.length ) {

			throw new Error( `ProbeVertexLighting.compute: the geometry's vertex count changed (${position.count}); create a new ProbeVertexLighting.` );

		}

		const normal = geometry.getAttribute( 'normal' ) as BufferAttribute | undefined;
		this.positionVersion = position.version;
		this.normalVersion = normal?.version ?? - 1;
		this.mesh.updateWorldMatrix( true, false );
		const e = this.mesh.matrixWorld.elements;
		const field = this.field, interpolator = field.interpolator, probeSH = field.sh, weightCount = interpolator.weightCount;
		const gradients = field.gradients, probePositions = field.positions;
		const out = this.data, count = position.count, irradiance = this.output === 'irradiance';
		// Direct reads when the attribute is a plain float array; getX() otherwise (interleaved, normalized).
		const positions = directArray( position ), ps = position.itemSize;
		const normals = directArray( normal ), ns = normal?.itemSize ?? 0;
		const n = irradiance ? _normalMatrix.getNormalMatrix( this.mesh.matrixWorld ).elements : null;
		// A BackSide material is shaded with the flipped normal (an inward-facing room): its E is for -n.
		let sign = - 1;
		for ( const material of this.clones ) if ( material.side !== BackSide ) sign = 1;
		let hint = - 1;
		for ( let i = 0; i < count; i ++ ) {

			const px = positions ? positions[ ps * i ] : position.getX( i );
			const py = positions ? positions[ ps * i + 1 ] : position.getY( i );
			const pz = positions ? positions[ ps * i + 2 ] : position.getZ( i );
			const wx = e[ 0 ] * px + e[ 4 ] * py + e[ 8 ] * pz + e[ 12 ];
			const wy = e[ 1 ] * px + e[ 5 ] * py + e[ 9 ] * pz + e[ 13 ];
			const wz = e[ 2 ] * px + e[ 6 ] * py + e[ 10 ] * pz + e[ 14 ];
			// Consecutive vertices are close: the previous vertex's cell is the walk's start.
			hint = interpolator.interpolate( wx, wy, wz, _indices, _weights, hint );
			blendProbes( _indices, _weights, weightCount, probeSH, gradients, probePositions, wx, wy, wz, _sh );
			if ( n !== null ) {

				// E(n) for the vertex's world normal.
				const nx0 = normals ? normals[ ns * i ] : normal!.getX( i );
				const ny0 = normals ? normals[ ns * i + 1 ] : normal!.getY( i );
				const nz0 = normals ? normals[ ns * i + 2 ] : normal!.getZ( i );
				let x = n[ 0 ] * nx0 + n[ 3 ] * ny0 + n[ 6 ] * nz0;
				let y = n[ 1 ] * nx0 + n[ 4 ] * ny0 + n[ 7 ] * nz0;
				let z = n[ 2 ] * nx0 + n[ 5 ] * ny0 + n[ 8 ] * nz0;
				const length = sign * Math.sqrt( x * x + y * y + z * z );
				if ( length !== 0 ) { x /= length; y /= length; z /= length; }
				irradianceAt( _sh, 0, x, y, z, out, 3 * i );

			} else {

				// The SH itself, 28 floats a vertex (7 vec4, the last float unused).
				const base = 28 * i;
				for ( let k = 0; k < 27; k ++ ) out[ base + k ] = _sh[ k ];

			}

		}

		this.buffer.needsUpdate = true;

	}

	/** Restores the mesh's materials, removes the attributes from its geometry and disposes the clones. */
	dispose(): void {

		if ( this.disposed ) return;
		this.disposed = true;
		this.mesh.material = this.original;
		for ( const material of this.clones ) material.dispose();
		this.removeAttributes();

	}

	private removeAttributes(): void {

		// three frees a geometry's GL buffers for the attributes it holds when disposed: dispose while
		// ours are still attached (the rest are uploaded again on the next render), then detach them.
		this.geometry.dispose();
		const names = this.output === 'irradiance' ? [ IRRADIANCE ] : SH_NAMES;
		for ( const name of names ) if ( this.geometry.getAttribute( name ) ) this.geometry.deleteAttribute( name );

	}

}
