import {
	DataTexture, FloatType, GLSL3, Mesh, NearestFilter, OrthographicCamera, PlaneGeometry, RawShaderMaterial,
	RedFormat, RGBAFormat, Scene, WebGLRenderTarget,
	type CubeTexture, type Texture, type WebGLRenderer,
} from 'three';
import { fullscreenVert, shProjectCubeFrag, shProjectEquirectFrag, shReduceFrag } from '../shaders.generated.js';
import { cubeTexelSolidAngle, paperTexelSolidAngle } from '../sh/cubeTexelSolidAngle.js';
import type { CubeSolidAngleMode } from '../sh/projectCubeMapToSH.js';
import { SH_FLOATS, assertInteger } from '../validate.js';

// Rows of the projection target: probes per batch × tiles must fit a texture everywhere WebGL2 runs.
const MAX_ROWS = 4096;

/** The grid of partial sums per coefficient and probe for a source of `size` texels per axis. */
function tilesFor( size: number ): number {

	// About 8 texels per block and axis; at most 16 × 16 tiles, so a reduction takes ≤ 2 passes.
	let tiles = 1;
	while ( tiles < 16 && tiles * 2 * 8 <= size ) tiles *= 2;
	return tiles;

}

/**
 * GPU projection of cube maps and panoramas onto SH9 (paper 2.2), batched: each source is
 * integrated into its own row block of a float target (one fragment per coefficient and block of
 * texels, exact texel solid angles), the blocks are summed by a logarithmic reduction (4 × 4 or
 * 2 × 2 per pass), and a whole batch ends in one read-back of 27 floats per probe.
 *
 * ```js
 * const projector = new SHProjector( renderer );
 * projector.begin( 'cube', 64, probeCount );
 * for ( … ) { cubeCamera.update( renderer, scene ); projector.add( cubeTarget.texture ); }
 * projector.finish( volumeSH );
 * ```
 *
 * Results match {@link projectCubeMapToSH} on the read-back faces of the same cube map.
 */
export class SHProjector {

	/** The renderer whose context owns the targets. */
	readonly renderer: WebGLRenderer;

	private readonly scene = new Scene();
	private readonly camera = new OrthographicCamera();
	private readonly quad: Mesh;
	private readonly cubeMaterial: RawShaderMaterial;
	private readonly equirectMaterial: RawShaderMaterial;
	private readonly reduceMaterial: RawShaderMaterial;
	private readonly solidAngleTextures = new Map<string, DataTexture>();
	private targets: WebGLRenderTarget[] = [];
	private targetKey = '';

	private source: 'cube' | 'equirect' | null = null;
	private tiles = 1;
	private capacity = 0;
	private count = 0;
	private width = 0;
	private height = 0;
	private readBuffer = new Float32Array( 0 );

	/**
	 * @param renderer A WebGL2 renderer whose context can render to float targets (EXT_color_buffer_float).
	 */
	constructor( renderer: WebGLRenderer ) {

		this.renderer = renderer;
		const material = ( fragmentShader: string, uniforms: Record<string, { value: unknown }> ) => new RawShaderMaterial( {
			glslVersion: GLSL3, vertexShader: fullscreenVert, fragmentShader, uniforms, depthTest: false, depthWrite: false,
		} );
		this.cubeMaterial = material( shProjectCubeFrag, {
			cubeMap: { value: null }, solidAngles: { value: null }, size: { value: 0 }, tiles: { value: 1 }, block: { value: 1 }, rowOffset: { value: 0 },
		} );
		this.equirectMaterial = material( shProjectEquirectFrag, {
			panorama: { value: null }, size: { value: [ 0, 0 ] }, tiles: { value: 1 }, block: { value: [ 1, 1 ] }, rowOffset: { value: 0 },
		} );
		this.reduceMaterial = material( shReduceFrag, { source: { value: null }, factor: { value: 2 } } );
		this.quad = new Mesh( new PlaneGeometry( 2, 2 ), this.cubeMaterial );
		this.quad.frustumCulled = false;
		this.scene.add( this.quad );

	}

	/** Most sources one batch can hold for a source of this size (texels per axis). */
	static batchCapacity( size: number ): number {

		return Math.floor( MAX_ROWS / tilesFor( size ) );

	}

	/**
	 * Starts a batch of `count` sources of one kind and size.
	 * @param source `'cube'`: cube maps with `size` texels per face edge; `'equirect'`: panoramas `size` × `height`.
	 * @param size Cube face edge, or panorama width, in texels.
	 * @param count Sources in this batch, at most {@link SHProjector.batchCapacity}.
	 * @param options `height` of panoramas (default size / 2); `solidAngle` for cube maps (default 'exact').
	 */
	begin( source: 'cube' | 'equirect', size: number, count: number, options: { height?: number, solidAngle?: CubeSolidAngleMode } = {} ): void {

		assertInteger( 'SHProjector.begin', 'size', size, 1, 1 << 14 );
		const height = source === 'equirect' ? options.height ?? Math.max( 1, size >> 1 ) : size;
		assertInteger( 'SHProjector.begin', 'height', height, 1, 1 << 14 );
		const tiles = tilesFor( Math.min( size, height ) );
		const capacity = Math.floor( MAX_ROWS / tiles );
		assertInteger( 'SHProjector.begin', 'count', count, 1, capacity );

		this.source = source;
		this.tiles = tiles;
		this.count = 0;
		this.capacity = count;
		this.width = size;
		this.height = height;
		this.ensureTargets( tiles, count );

		if ( source === 'cube' ) {

			const u = this.cubeMaterial.uniforms;
			u.solidAngles.value = this.solidAngleTexture( size, options.solidAngle ?? 'exact' );
			u.size.value = size;
			u.tiles.value = tiles;
			u.block.value = Math.ceil( size / tiles );

		} else {

			const u = this.equirectMaterial.uniforms;
			u.size.value = [ size, height ];
			u.tiles.value = tiles;
			u.block.value = [ Math.ceil( size / tiles ), Math.ceil( height / tiles ) ];

		}

	}

	/**
	 * Projects the next source of the batch. A cube texture must be the texture of a
	 * `WebGLCubeRenderTarget` with `NearestFilter` (as {@link ProbeCapturer} makes it), so every
	 * texel-centre lookup returns that texel; a panorama is any 2D texture, sampled texel by texel.
	 */
	add( texture: CubeTexture | Texture ): void {

		if ( this.source === null ) throw new Error( 'SHProjector.add: call begin() first.' );
		if ( this.count >= this.capacity ) throw new Error( `SHProjector.add: the batch holds ${this.capacity} sources; call finish() first.` );

		const material = this.source === 'cube' ? this.cubeMaterial : this.equirectMaterial;
		material.uniforms[ this.source === 'cube' ? 'cubeMap' : 'panorama' ].value = texture;
		material.uniforms.rowOffset.value = this.count * this.tiles;
		this.quad.material = material;

		const target = this.targets[ 0 ];
		target.viewport.set( 0, this.count * this.tiles, 9 * this.tiles, this.tiles );
		this.draw( target );
		this.count ++;

	}

	/**
	 * Reduces the batch and reads it back: 27 floats per source into `target` from `offset`.
	 * @returns `target`.
	 */
	finish( target: Float32Array, offset = 0 ): Float32Array {

		if ( this.source === null ) throw new Error( 'SHProjector.finish: call begin() first.' );
		const count = this.count;
		if ( target.length < offset + SH_FLOATS * count ) {

			throw new RangeError( `SHProjector.finish: target must have room for ${SH_FLOATS * count} floats from offset ${offset}, got length ${target.length}.` );

		}

		// Logarithmic reduction: tiles × tiles partial sums → 1 per coefficient and probe.
		let tiles = this.tiles, level = 0;
		this.quad.material = this.reduceMaterial;
		while ( tiles > 1 ) {

			const factor = tiles % 4 === 0 ? 4 : 2;
			tiles /= factor;
			const source = this.targets[ level ], destination = this.targets[ level + 1 ];
			this.reduceMaterial.uniforms.source.value = source.texture;
			this.reduceMaterial.uniforms.factor.value = factor;
			destination.viewport.set( 0, 0, 9 * tiles, count * tiles );
			this.draw( destination );
			level ++;

		}

		const final = this.targets[ level ];
		const floats = 9 * 4 * count;
		if ( this.readBuffer.length < floats ) this.readBuffer = new Float32Array( floats );
		const buffer = this.readBuffer.subarray( 0, floats );
		this.renderer.readRenderTargetPixels( final, 0, 0, 9, count, buffer );

		for ( let p = 0; p < count; p ++ ) {

			for ( let k = 0; k < 9; k ++ ) {

				const from = 4 * ( 9 * p + k ), to = offset + SH_FLOATS * p + 3 * k;
				target[ to ] = buffer[ from ];
				target[ to + 1 ] = buffer[ from + 1 ];
				target[ to + 2 ] = buffer[ from + 2 ];

			}

		}

		this.source = null;
		this.count = 0;
		return target;

	}

	/** Renders the full-screen quad into `target`'s viewport without clearing the rest of it. */
	private draw( target: WebGLRenderTarget ): void {

		const renderer = this.renderer;
		const previousTarget = renderer.getRenderTarget();
		const previousAutoClear = renderer.autoClear;
		renderer.autoClear = false;
		renderer.setRenderTarget( target );
		renderer.render( this.scene, this.camera );
		renderer.setRenderTarget( previousTarget );
		renderer.autoClear = previousAutoClear;

	}

	/** Projection and reduction targets for `tiles` and `count`, reused while they are big enough. */
	private ensureTargets( tiles: number, count: number ): void {

		const rows = Math.min( MAX_ROWS / tiles, Math.max( count, 16 ) );
		const key = `${tiles}:${rows}`;
		const current = this.targets[ 0 ];
		if ( current && this.targetKey.startsWith( `${tiles}:` ) && current.height >= count * tiles ) return;

		this.disposeTargets();
		this.targetKey = key;
		for ( let t = tiles; ; ) {

			this.targets.push( new WebGLRenderTarget( 9 * t, rows * t, {
				type: FloatType, format: RGBAFormat, minFilter: NearestFilter, magFilter: NearestFilter,
				depthBuffer: false, stencilBuffer: false, generateMipmaps: false,
			} ) );
			if ( t === 1 ) break;
			t /= t % 4 === 0 ? 4 : 2;

		}

	}

	/** Texel solid angles of one face (the same on all six), as a float texture. */
	private solidAngleTexture( size: number, mode: CubeSolidAngleMode ): DataTexture {

		const key = `${size}:${mode}`;
		let texture = this.solidAngleTextures.get( key );
		if ( texture ) return texture;

		const data = new Float32Array( size * size );
		let total = 0;
		for ( let row = 0; row < size; row ++ ) {

			for ( let column = 0; column < size; column ++ ) {

				const omega = mode === 'exact' ? cubeTexelSolidAngle( column, row, size ) : paperTexelSolidAngle( column, row, size );
				data[ row * size + column ] = omega;
				total += 6 * omega;

			}

		}

		// The paper's weights are rescaled to sum to 4π (its step 4), like projectCubeMapToSH does.
		if ( mode === 'paper' ) for ( let i = 0; i < data.length; i ++ ) data[ i ] *= 4 * Math.PI / total;

		texture = new DataTexture( data, size, size, RedFormat, FloatType );
		texture.minFilter = texture.magFilter = NearestFilter;
		texture.needsUpdate = true;
		this.solidAngleTextures.set( key, texture );
		return texture;

	}

	private disposeTargets(): void {

		for ( const target of this.targets ) target.dispose();
		this.targets = [];
		this.targetKey = '';

	}

	/** Frees every GPU resource: targets, textures, materials, the quad's geometry. */
	dispose(): void {

		this.disposeTargets();
		for ( const texture of this.solidAngleTextures.values() ) texture.dispose();
		this.solidAngleTextures.clear();
		this.cubeMaterial.dispose();
		this.equirectMaterial.dispose();
		this.reduceMaterial.dispose();
		this.quad.geometry.dispose();

	}

}
