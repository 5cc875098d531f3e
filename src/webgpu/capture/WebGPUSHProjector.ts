import {
	CubeTexture, DataTexture, FloatType, NearestFilter, NodeMaterial, NoBlending, QuadMesh, RGBAFormat, RenderTarget,
	Texture, type WebGPURenderer,
} from 'three/webgpu';
import { Fn, cubeTexture, instanceIndex, instancedArray, int, ivec2, screenCoordinate, select, texture, uniform, vec2, vec3, vec4 } from 'three/tsl';
import type { CubeSolidAngleMode } from '../../sh/projectCubeMapToSH.js';
import { SH_FLOATS, assertInteger, describeValue } from '../../validate.js';
import { CAPTURE_SOLID_ANGLES } from '../../capture/captureSettings.js';
import { createEquirectTableTexture, createSolidAngleTexture } from '../../capture/solidAngleTexture.js';
import { cubeTileSums, equirectTileSums, faceTileSums, loop, packPlanes, type TSLNode } from './shProjectionNodes.js';

// Rows of the fragment path's partial sums (probes × tiles), as the WebGL projector.
const MAX_ROWS = 4096;

// The 27 SH floats and one unused, as seven RGBA planes (shProjectionNodes.packPlanes).
const PLANES = 7;

// Batches are a multiple of this, so the compute path's gather (7 invocations per probe) fills whole workgroups.
const WORKGROUP = 64;

/** Tiles per axis of a probe's partial sums (SHProjector's tilesFor): blocks of ≥ 4 texels, at most 16 × 16. */
function tilesFor( texels: number ): number {

	let tiles = 1;
	while ( tiles < 16 && tiles * 2 * 4 <= texels ) tiles *= 2;
	return tiles === 1 && texels >= 2 ? 2 : tiles;

}

/** The kernels (compute) or materials (fragment) of one source kind and tile count, built on first use. */
interface Passes {

	project: TSLNode;
	gather: TSLNode;

}

/**
 * The GPU SH projection of `WebGPURenderer` captures: the counterpart of `SHProjector` (same
 * tiles, texel solid angles and packing, so the same sums to rounding), batched the same way —
 * `begin`, one `add` per cube map or panorama (its sums are computed at once, so the source may be
 * rendered into again right after), `finish` with one small read-back of 27 floats per source.
 * On the WebGPU backend each source is one compute dispatch (an invocation per tile writing its
 * seven planes to a storage buffer) and the batch ends with a gather dispatch and
 * `getArrayBufferAsync`; on the WebGL2 backend (`forceWebGL`), where compute runs through
 * transform feedback with at most four outputs, each source is one fragment pass into a float
 * target (a fragment per tile and plane) and the batch ends with a gather pass and
 * `readRenderTargetPixelsAsync`.
 */
export class WebGPUSHProjector {

	/** The renderer. */
	readonly renderer: WebGPURenderer;

	/** Whether the projection runs as compute kernels (the WebGPU backend) or fragment passes (WebGL2). */
	readonly compute: boolean;

	private readonly cube = cubeTexture( new CubeTexture(), vec3( 0, 0, 1 ) );
	private readonly panorama = texture( new Texture(), vec2( 0.5, 0.5 ) );
	private readonly faces = [ 0, 1, 2, 3, 4, 5 ].map( () => texture( new Texture() ) );
	private readonly solidAngles = texture();
	private readonly directions = texture();
	private readonly size = uniform( 1, 'int' );
	private readonly height = uniform( 1, 'int' );
	private readonly block = uniform( 1, 'int' );
	private readonly blockY = uniform( 1, 'int' );
	private readonly slot = uniform( 0, 'int' );
	private readonly solidAngleTextures = new Map<string, DataTexture>();
	private readonly passes = new Map<string, Passes>();
	private readonly quad = new QuadMesh( new NodeMaterial() );
	// Compute path: the partial sums (probe, tile, plane) and the gathered planes (probe, plane).
	private partials: TSLNode = null;
	private gathered: TSLNode = null;
	// Fragment path: the same, as float render targets (x: plane and tile, y: probe and tile).
	private partialTarget: RenderTarget | null = null;
	private gatherTarget: RenderTarget | null = null;
	private bufferTiles = 0;
	private bufferCapacity = 0;

	private source: 'cube' | 'equirect' | null = null;
	private tiles = 1;
	private capacity = 0;
	private count = 0;
	private current: Passes | null = null;

	/** @param renderer An initialised `WebGPURenderer` (either backend). */
	constructor( renderer: WebGPURenderer ) {

		this.renderer = renderer;
		this.compute = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend === true;

	}

	/** Most sources one batch can hold for a source of this size (texels per axis). */
	static batchCapacity( size: number ): number {

		return Math.floor( MAX_ROWS / tilesFor( Math.ceil( size / 2 ) ) );

	}

	/**
	 * Starts a batch of `count` sources of one kind and size (as `SHProjector.begin`).
	 * @param options `height` of panoramas (default size / 2); `solidAngle` of cube maps (default 'exact').
	 */
	begin( source: 'cube' | 'equirect', size: number, count: number, options: { height?: number, solidAngle?: CubeSolidAngleMode } = {} ): void {

		const where = 'WebGPUSHProjector.begin';
		const solidAngle = options.solidAngle ?? 'exact';
		if ( ! CAPTURE_SOLID_ANGLES.includes( solidAngle ) ) throw new RangeError( `${where}: options.solidAngle is ${describeValue( solidAngle )}.` );
		assertInteger( where, 'size', size, 1, 1 << 14 );
		const height = source === 'equirect' ? options.height ?? Math.max( 1, size >> 1 ) : size;
		assertInteger( where, 'height', height, 1, 1 << 14 );
		const tiles = tilesFor( Math.ceil( Math.min( size, height ) / 2 ) );
		assertInteger( where, 'count', count, 1, Math.floor( MAX_ROWS / tiles ) );

		this.source = source;
		this.tiles = tiles;
		this.count = 0;
		this.capacity = count;
		this.ensureBuffers( tiles, count );
		this.current = this.passesFor( source, tiles );
		this.size.value = size;
		this.height.value = height;
		if ( source === 'cube' ) {

			this.solidAngles.value = this.solidAngleTexture( size, solidAngle );
			this.block.value = Math.ceil( Math.ceil( size / 2 ) / tiles );

		} else {

			this.directions.value = this.equirectTable( size, height );
			this.block.value = Math.ceil( size / tiles );
			this.blockY.value = Math.ceil( height / tiles );

		}

	}

	/** Projects the next source of the batch: a cube render target's texture (NearestFilter) or a 2D panorama texture. */
	add( source: Texture ): void {

		if ( this.source === null || this.current === null ) throw new Error( 'WebGPUSHProjector.add: call begin() first.' );
		if ( this.count >= this.capacity ) throw new Error( `WebGPUSHProjector.add: the batch holds ${this.capacity} sources; call finish() first.` );
		if ( this.source === 'cube' ) this.cube.value = source;
		else this.panorama.value = source;
		this.slot.value = this.count;
		if ( this.compute ) {

			this.renderer.compute( this.current.project );

		} else {

			const target = this.partialTarget!;
			target.viewport.set( 0, this.count * this.tiles, PLANES * this.tiles, this.tiles );
			this.draw( target, this.current.project );

		}

		this.count ++;

	}

	/**
	 * Projects the next cube map of a `'cube'` batch given as six 2D face textures (+X, −X, +Y, −Y,
	 * +Z, −Z, NearestFilter) laid out as WebGL's cube faces (docs/cube-faces.md), read by texel
	 * index: what WebGPUCubeFaces renders on the WebGPU backend. Compute path only.
	 */
	addFaces( faces: readonly Texture[] ): void {

		const where = 'WebGPUSHProjector.addFaces';
		if ( this.source !== 'cube' ) throw new Error( `${where}: call begin( 'cube', … ) first.` );
		if ( ! this.compute ) throw new Error( `${where}: needs the WebGPU backend (compute); on WebGL2 give add() a cube texture.` );
		if ( faces.length !== 6 ) throw new RangeError( `${where}: faces must hold 6 textures, got ${faces.length}.` );
		if ( this.count >= this.capacity ) throw new Error( `${where}: the batch holds ${this.capacity} sources; call finish() first.` );
		faces.forEach( ( face, f ) => { this.faces[ f ].value = face; } );
		this.slot.value = this.count;
		this.renderer.compute( this.passesFor( 'faces', this.tiles ).project );
		this.count ++;

	}

	/**
	 * Sums the batch and reads it back: 27 floats per source into `target` from `offset`.
	 * @returns `target`, once the read-back is done.
	 */
	async finish( target: Float32Array, offset = 0 ): Promise<Float32Array> {

		if ( this.source === null || this.current === null ) throw new Error( 'WebGPUSHProjector.finish: call begin() first.' );
		const count = this.count;
		if ( target.length < offset + SH_FLOATS * count ) {

			throw new RangeError( `WebGPUSHProjector.finish: target must have room for ${SH_FLOATS * count} floats from offset ${offset}, got length ${target.length}.` );

		}

		const passes = this.current;
		this.source = null;
		this.current = null;
		this.count = 0;
		let planes: Float32Array;
		let flipped = false;
		if ( this.compute ) {

			this.renderer.compute( passes.gather );
			const bytes = await this.renderer.getArrayBufferAsync( this.gathered.value, null, 0, 16 * PLANES * count ) as ArrayBuffer;
			planes = new Float32Array( bytes );

		} else {

			const gatherTarget = this.gatherTarget!;
			gatherTarget.viewport.set( 0, 0, PLANES, count );
			this.draw( gatherTarget, passes.gather );
			// The WebGL2 backend draws rows from the top (viewport, screenCoordinate) but reads them
			// with readPixels from the bottom: probe p is row count − 1 − p of the last `count` rows.
			flipped = true;
			const y = gatherTarget.height - count;
			planes = await this.renderer.readRenderTargetPixelsAsync( gatherTarget, 0, y, PLANES, count ) as Float32Array;

		}

		const floats = 4 * PLANES;
		for ( let p = 0; p < count; p ++ ) {

			const row = flipped ? count - 1 - p : p;
			target.set( planes.subarray( floats * row, floats * row + SH_FLOATS ), offset + SH_FLOATS * p );

		}

		return target;

	}

	/** Renders the full-screen quad with `material` into `target`'s viewport, leaving the rest of it. */
	private draw( target: RenderTarget, material: NodeMaterial ): void {

		const renderer = this.renderer;
		const previousTarget = renderer.getRenderTarget();
		const previousAutoClear = renderer.autoClear;
		renderer.autoClear = false;
		renderer.setRenderTarget( target );
		this.quad.material = material;
		this.quad.render( renderer );
		renderer.setRenderTarget( previousTarget );
		renderer.autoClear = previousAutoClear;

	}

	/** The partial-sum and gather storage (compute) or targets (fragment) for `tiles` and `count`, reused while big enough. */
	private ensureBuffers( tiles: number, count: number ): void {

		if ( this.bufferTiles === tiles && this.bufferCapacity >= count ) return;
		this.disposeBuffers();
		const capacity = Math.ceil( Math.max( count, 16 ) / WORKGROUP ) * WORKGROUP;
		this.bufferTiles = tiles;
		this.bufferCapacity = capacity;
		if ( this.compute ) {

			this.partials = instancedArray( capacity * tiles * tiles * PLANES, 'vec4' );
			this.gathered = instancedArray( capacity * PLANES, 'vec4' );

		} else {

			const options = {
				type: FloatType, format: RGBAFormat, minFilter: NearestFilter, magFilter: NearestFilter,
				depthBuffer: false, generateMipmaps: false,
			};
			this.partialTarget = new RenderTarget( PLANES * tiles, Math.min( MAX_ROWS, capacity * tiles ), options );
			this.gatherTarget = new RenderTarget( PLANES, capacity, options );

		}

	}

	/** The project and gather passes of `source` at `tiles` (the buffers they address are the current ones). */
	private passesFor( source: 'cube' | 'faces' | 'equirect', tiles: number ): Passes {

		const key = `${source}:${tiles}:${this.bufferCapacity}`;
		let passes = this.passes.get( key );
		if ( passes ) return passes;

		const tileSums = ( tileX: TSLNode, tileY: TSLNode ) => {

			if ( source === 'cube' ) return cubeTileSums( this.cube, this.solidAngles, this.size, this.block, tileX, tileY );
			if ( source === 'faces' ) return faceTileSums( this.faces, this.solidAngles, this.size, this.block, tileX, tileY );
			const size = { x: this.size, y: this.height }, block = { x: this.block, y: this.blockY };
			return equirectTileSums( this.panorama, this.directions, size, block, tileX, tileY );

		};

		const perProbe = tiles * tiles;
		if ( this.compute ) {

			const partials = this.partials, gathered = this.gathered;
			const project = Fn( () => {

				const index = int( instanceIndex ).toVar();
				const planes = packPlanes( tileSums( index.mod( tiles ), index.div( tiles ) ) );
				const base = this.slot.mul( perProbe ).add( index ).mul( PLANES ).toVar();
				planes.forEach( ( plane, k ) => partials.element( base.add( k ) ).assign( plane ) );

			} )().compute( perProbe, [ Math.min( WORKGROUP, perProbe ) ] );
			const gather = Fn( () => {

				const index = int( instanceIndex ).toVar();
				const probe = index.div( PLANES ), plane = index.mod( PLANES );
				const sum = vec4( 0 ).toVar();
				loop( perProbe, ( { i }: TSLNode ) => {

					sum.addAssign( partials.element( probe.mul( perProbe ).add( i ).mul( PLANES ).add( plane ) ) );

				} );
				gathered.element( index ).assign( sum );

			} )().compute( this.bufferCapacity * PLANES, [ WORKGROUP ] );
			passes = { project, gather };

		} else {

			const project = new NodeMaterial();
			project.fragmentNode = Fn( () => {

				const x = int( screenCoordinate.x ).toVar();
				const plane = x.div( tiles ).toVar();
				const tileY = int( screenCoordinate.y ).sub( this.slot.mul( tiles ) );
				const planes = packPlanes( tileSums( x.mod( tiles ), tileY ) );
				let out = planes[ PLANES - 1 ];
				for ( let k = PLANES - 2; k >= 0; k -- ) out = select( plane.equal( k ), planes[ k ], out );
				return out;

			} )();
			const partial = texture( this.partialTarget!.texture );
			const gather = new NodeMaterial();
			gather.fragmentNode = Fn( () => {

				const plane = int( screenCoordinate.x ).toVar(), probe = int( screenCoordinate.y ).toVar();
				const sum = vec4( 0 ).toVar();
				loop( tiles, tiles, ( { i, j }: TSLNode ) => {

					sum.addAssign( partial.load( ivec2( plane.mul( tiles ).add( j ), probe.mul( tiles ).add( i ) ) ) );

				} );
				return sum;

			} )();
			for ( const material of [ project, gather ] ) {

				material.depthTest = material.depthWrite = false;
				material.blending = NoBlending;
				material.toneMapped = false;

			}

			passes = { project, gather };

		}

		this.passes.set( key, passes );
		return passes;

	}

	/** The solid-angle texture of a face size and formula (as `SHProjector`'s), made once per projector. */
	private solidAngleTexture( size: number, mode: CubeSolidAngleMode ): DataTexture {

		const key = `${size}:${mode}`;
		let texture = this.solidAngleTextures.get( key );
		if ( ! texture ) this.solidAngleTextures.set( key, texture = createSolidAngleTexture( size, mode ) );
		return texture;

	}

	/** The direction and solid-angle table of a panorama size (as `SHProjector`'s), made once per projector. */
	private equirectTable( width: number, height: number ): DataTexture {

		const key = `equirect:${width}x${height}`;
		let texture = this.solidAngleTextures.get( key );
		if ( ! texture ) this.solidAngleTextures.set( key, texture = createEquirectTableTexture( width, height ) );
		return texture;

	}

	private disposeBuffers(): void {

		// Passes address the buffers they were built with: they go with them.
		this.disposePasses();
		this.partialTarget?.dispose();
		this.gatherTarget?.dispose();
		this.partialTarget = this.gatherTarget = null;
		for ( const node of [ this.partials, this.gathered ] ) node?.value?.dispose?.();
		this.partials = this.gathered = null;
		this.bufferTiles = this.bufferCapacity = 0;

	}

	private disposePasses(): void {

		for ( const { project, gather } of this.passes.values() ) {

			for ( const pass of [ project, gather ] ) pass.dispose?.();

		}

		this.passes.clear();

	}

	/** Frees every GPU resource: storage buffers or targets, solid-angle textures, kernels, materials. */
	dispose(): void {

		this.disposeBuffers();
		for ( const texture of this.solidAngleTextures.values() ) texture.dispose();
		this.solidAngleTextures.clear();
		this.quad.geometry.dispose();

	}

}
