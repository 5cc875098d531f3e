import {
	InstancedBufferAttribute, InstancedInterleavedBuffer, InstancedMesh, InterleavedBufferAttribute, Matrix4, ShaderMaterial,
	SphereGeometry, type Material,
} from 'three';
import { probeVolumeHelperFrag, probeVolumeHelperVert } from '../shaders.generated.js';
import { SH_FLOATS } from '../validate.js';
import { isCubeFace } from './cubeCameraHiding.js';
import { helperMaterials } from './helperHooks.js';

/** Floats per instance in the SH buffer: 27 SH plus one unused, as 7 vec4 attributes. */
const PACKED = 28;

const _matrix = new Matrix4();

/** What {@link ProbeSphereMesh.setProbes} reads of a volume. */
export interface ProbeSphereSource {

	/** Probe positions, x, y, z per probe id. */
	readonly positions: ArrayLike<number>;

	/** 27 SH floats per probe id. */
	readonly sh: ArrayLike<number>;

	/** Number of probe ids. */
	readonly count: number;

	/** Whether probe id `index` is in use. */
	isProbeActive( index: number ): boolean;

}

/**
 * The probe spheres of a `LightProbeVolumeHelper`: one instance per probe id (instance i is probe
 * i, so a raycast's `instanceId` is the probe id; removed probes are scaled to nothing), each
 * shaded by its own SH from per-instance attributes. Not drawn by cube cameras, so captures do not
 * see it.
 *
 * The material is a `ShaderMaterial` (GLSL, for WebGLRenderer), or — once the library is imported
 * from `three-capture-lighting/webgpu` — its node-material counterpart for WebGPURenderer (either
 * backend); chosen when the mesh is made.
 */
export class ProbeSphereMesh extends InstancedMesh<SphereGeometry, Material> {

	/** Instances the buffers hold; they grow by doubling when probes are added. */
	private capacity = 0;
	private shBuffer: InstancedInterleavedBuffer;
	private hiddenCount = - 1;

	/**
	 * A unit sphere with the SH shader (the node material when the webgpu entry installed it); no
	 * instances until {@link ProbeSphereMesh.setProbes}.
	 */
	constructor() {

		super( new SphereGeometry( 1, 16, 12 ), createSphereMaterial(), 0 ); // a unit sphere, scaled per instance
		this.name = 'probes';
		this.shBuffer = this.attachSHBuffer( 0 );
		// Cube cameras (the volume's captures, reflection probes) skip the spheres: rendering them
		// would put the helper's own colours into the probes it shows.
		this.onBeforeRender = ( renderer, _scene, camera, _geometry, material ) => {

			checkRenderer( renderer, material );
			if ( ! isCubeFace( camera ) ) return;
			this.hiddenCount = this.count;
			this.count = 0;

		};

		this.onAfterRender = () => {

			if ( this.hiddenCount < 0 ) return;
			this.count = this.hiddenCount;
			this.hiddenCount = - 1;

		};

	}

	/**
	 * One instance per probe id of `source`: a sphere of radius `size` at the probe (none for an
	 * inactive id) with the probe's SH. Grows the buffers when there are more ids than before.
	 */
	setProbes( source: ProbeSphereSource, size: number ): void {

		const count = source.count, positions = source.positions, sh = source.sh;
		if ( count > this.capacity ) this.grow( Math.max( count, 2 * this.capacity ) );
		const packed = this.shBuffer.array as Float32Array;
		for ( let i = 0; i < count; i ++ ) {

			const scale = source.isProbeActive( i ) ? size : 0;
			_matrix.makeScale( scale, scale, scale ).setPosition( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] );
			this.setMatrixAt( i, _matrix );
			for ( let k = 0; k < SH_FLOATS; k ++ ) packed[ PACKED * i + k ] = sh[ SH_FLOATS * i + k ];

		}

		this.count = count;
		this.instanceMatrix.needsUpdate = true;
		this.shBuffer.needsUpdate = true;
		this.computeBoundingSphere();

	}

	/** Frees the geometry, the material and the instance buffers. */
	override dispose(): this {

		super.dispose();
		this.geometry.dispose();
		this.material.dispose();
		return this;

	}

	/** New instance buffers for `capacity` instances; the old ones are freed (three cannot resize a buffer). */
	private grow( capacity: number ): void {

		// The 'dispose' event frees the old instance matrix buffer on the GPU; geometry.dispose() the SH buffer.
		super.dispose();
		this.instanceMatrix = new InstancedBufferAttribute( new Float32Array( 16 * capacity ), 16 );
		this.geometry.dispose();
		this.geometry = new SphereGeometry( 1, 16, 12 );
		this.shBuffer = this.attachSHBuffer( capacity );
		this.capacity = capacity;

	}

	/** Puts a fresh SH buffer for `capacity` instances on the geometry, as attributes probeSH0…6. */
	private attachSHBuffer( capacity: number ): InstancedInterleavedBuffer {

		const buffer = new InstancedInterleavedBuffer( new Float32Array( PACKED * capacity ), PACKED );
		for ( let k = 0; k < 7; k ++ ) this.geometry.setAttribute( `probeSH${k}`, new InterleavedBufferAttribute( buffer, 4, 4 * k ) );
		return buffer;

	}

}

/** The GLSL material, or the node material the webgpu entry installed. */
function createSphereMaterial(): Material {

	const hooks = helperMaterials();
	if ( hooks !== null ) return hooks.createProbeSphereMaterial();
	const material = new ShaderMaterial( { vertexShader: probeVolumeHelperVert, fragmentShader: probeVolumeHelperFrag } );
	material.name = 'LightProbeVolumeHelper';
	return material;

}

/**
 * A named error, before the renderer fails on its own, when the material does not suit the renderer:
 * the GLSL material on a WebGPURenderer (the webgpu entry was not imported before the helper was
 * made), or the node material on a WebGLRenderer.
 */
function checkRenderer( renderer: unknown, material: Material ): void {

	const webgpu = ( renderer as { isWebGPURenderer?: boolean } ).isWebGPURenderer === true;
	const node = ( material as { isNodeMaterial?: boolean } ).isNodeMaterial === true;
	if ( webgpu === node ) return;
	throw new Error( webgpu
		? 'LightProbeVolumeHelper: drawn by a WebGPURenderer, but made with the WebGL material; import the library from \'three-capture-lighting/webgpu\' before making the helper.'
		: 'LightProbeVolumeHelper: drawn by a WebGLRenderer, but made with the WebGPURenderer\'s node material (the library was imported from \'three-capture-lighting/webgpu\'); draw it with a WebGPURenderer.' );

}
