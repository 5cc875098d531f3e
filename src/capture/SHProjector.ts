import {
	DataTexture, FloatType, GLSL3, Mesh, NearestFilter, OrthographicCamera, PlaneGeometry, RawShaderMaterial,
	RedFormat, RGBAFormat, Scene, WebGLRenderTarget,
	type CubeTexture, type Texture, type WebGLRenderer,
} from 'three';
import { fullscreenVert, shProjectCubeFrag, shProjectEquirectFrag, shReduceFrag } from '../shaders.generated.js';
import { cubeTexelSolidAngle, paperTexelSolidAngle } from '../sh/cubeTexelSolidAngle.js';
import type { CubeSolidAngleMode } from '../sh/projectCubeMapToSH.js';
import { SH_FLOATS, assertInteger, assertOptionalBoolean, assertOptions, describeValue } from '../validate.js';
import { CAPTURE_SOLID_ANGLES, assertRenderer } from './captureSettings.js';

// Rows of the projection target: probes per batch × tiles must fit a texture everywhere WebGL2 runs.
const MAX_ROWS = 4096;

// The 9 coefficients are projected in two halves (0..4 and 5..8) of up to 15 floats, each packed
// into four RGBA float planes: a fragment reads each texel of its block once for five
// coefficients, instead of once per coefficient.
const HALVES = 2;
const PLANES = 4;

/** The grid of partial sums per half and probe for a source of `size` texels per axis. */
function tilesFor( size: number ): number {

	// About 8 texels per block and axis; at most 16 × 16 tiles, so a reduction takes ≤ 2 passes.
	let tiles = 1;
	while ( tiles < 16 && tiles * 2 * 8 <= size ) tiles *= 2;
	return tiles;

}

const multipleTargetSupport = new WeakMap<WebGLRenderer, boolean>();

/** Options of {@link SHProjector}. */
export interface SHProjectorOptions {

	/**
	 * Write the four planes in one draw with multiple render targets (default: when a quick
	 * self-test on this renderer shows they work), or in four draws (`false`). headless-gl, for one,
	 * accepts multiple targets but fills only the first.
	 */
	multipleTargets?: boolean;

}

/**
 * GPU projection of cube maps and panoramas onto SH9 (paper 2.2), batched: each source is
 * integrated into its own row block of four float planes (one fragment per half of the
 * coefficients and block of texels, exact texel solid angles), the blocks are summed by a
 * logarithmic reduction (4 × 4 or 2 × 2 per pass), and a whole batch ends in one small read-back
 * per plane: 27 floats per probe in all.
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

	/** Whether the planes are written in one draw (multiple render targets) or four. */
	readonly multipleTargets: boolean;

	private readonly scene = new Scene();
	private readonly camera = new OrthographicCamera();
	private readonly quad: Mesh;
	private readonly cubeMaterial: RawShaderMaterial;
	private readonly equirectMaterial: RawShaderMaterial;
	private readonly reduceMaterial: RawShaderMaterial;
	private readonly solidAngleTextures = new Map<string, DataTexture>();
	// levels[ l ][ p ]: the render target holding plane p at reduction level l (with multiple
	// targets, one render target serves all four planes of a level).
	private levels: WebGLRenderTarget[][] = [];
	private levelTiles = 0;

	private source: 'cube' | 'equirect' | null = null;
	private tiles = 1;
	private capacity = 0;
	private count = 0;
	private readBuffer = new Float32Array( 0 );

	/**
	 * @param renderer A WebGL2 renderer whose context can render to float targets (EXT_color_buffer_float).
	 * @param options See {@link SHProjectorOptions}.
	 */
	constructor( renderer: WebGLRenderer, options: SHProjectorOptions = {} ) {

		assertRenderer( 'SHProjector', renderer );
		assertOptions( 'SHProjector', 'options', options );
		assertOptionalBoolean( 'SHProjector', 'options.multipleTargets', options.multipleTargets );
		this.renderer = renderer;
		this.multipleTargets = options.multipleTargets ?? SHProjector.supportsMultipleTargets( renderer );
		const defines: Record<string, number> = this.multipleTargets ? {} : { SINGLE_TARGET: 1 };
		const material = ( fragmentShader: string, uniforms: Record<string, { value: unknown }> ) => new RawShaderMaterial( {
			glslVersion: GLSL3, vertexShader: fullscreenVert, fragmentShader, uniforms, defines, depthTest: false, depthWrite: false,
		} );
		this.cubeMaterial = material( shProjectCubeFrag, {
			cubeMap: { value: null }, solidAngles: { value: null }, size: { value: 0 }, tiles: { value: 1 }, block: { value: 1 },
			rowOffset: { value: 0 }, outputIndex: { value: 0 },
		} );
		this.equirectMaterial = material( shProjectEquirectFrag, {
			panorama: { value: null }, size: { value: [ 0, 0 ] }, tiles: { value: 1 }, block: { value: [ 1, 1 ] },
			rowOffset: { value: 0 }, outputIndex: { value: 0 },
		} );
		this.reduceMaterial = material( shReduceFrag, {
			source0: { value: null }, source1: { value: null }, source2: { value: null }, source3: { value: null }, factor: { value: 2 },
		} );
		this.quad = new Mesh( new PlaneGeometry( 2, 2 ), this.cubeMaterial );
		this.quad.frustumCulled = false;
		this.scene.add( this.quad );

	}

	/** Most sources one batch can hold for a source of this size (texels per axis). */
	static batchCapacity( size: number ): number {

		assertInteger( 'SHProjector.batchCapacity', 'size', size, 1, 1 << 14 );
		return Math.floor( MAX_ROWS / tilesFor( size ) );

	}

	/**
	 * Whether multiple render targets really work on this renderer: renders two constant outputs
	 * into a tiny two-target float render target and reads the second back. Cached per renderer.
	 */
	static supportsMultipleTargets( renderer: WebGLRenderer ): boolean {

		assertRenderer( 'SHProjector.supportsMultipleTargets', renderer );
		let supported = multipleTargetSupport.get( renderer );
		if ( supported !== undefined ) return supported;

		const target = new WebGLRenderTarget( 1, 1, {
			type: FloatType, count: 2, depthBuffer: false, minFilter: NearestFilter, magFilter: NearestFilter,
		} );
		const material = new RawShaderMaterial( {
			glslVersion: GLSL3, vertexShader: fullscreenVert,
			fragmentShader: 'precision highp float;\nlayout( location = 0 ) out vec4 a;\nlayout( location = 1 ) out vec4 b;\nvoid main() { a = vec4( 1.0 ); b = vec4( 2.0 ); }',
		} );
		const scene = new Scene();
		const quad = new Mesh( new PlaneGeometry( 2, 2 ), material );
		quad.frustumCulled = false;
		scene.add( quad );
		const previous = renderer.getRenderTarget();
		const pixel = new Float32Array( 4 );
		try {

			renderer.setRenderTarget( target );
			renderer.render( scene, new OrthographicCamera() );
			renderer.readRenderTargetPixels( target, 0, 0, 1, 1, pixel, undefined, 1 );
			// A GL error here means the draw was refused; drain the queue so it does not surface
			// later as someone else's error.
			const gl = renderer.getContext();
			let errors = 0;
			for ( let i = 0; i < 8 && gl.getError() !== gl.NO_ERROR; i ++ ) errors ++;
			supported = pixel[ 0 ] === 2 && errors === 0;

		} catch {

			supported = false;

		} finally {

			renderer.setRenderTarget( previous );
			target.dispose();
			material.dispose();
			quad.geometry.dispose();

		}

		multipleTargetSupport.set( renderer, supported );
		return supported;

	}

	/**
	 * Starts a batch of `count` sources of one kind and size.
	 * @param source `'cube'`: cube maps with `size` texels per face edge; `'equirect'`: panoramas `size` × `height`.
	 * @param size Cube face edge, or panorama width, in texels.
	 * @param count Sources in this batch, at most {@link SHProjector.batchCapacity}.
	 * @param options `height` of panoramas (default size / 2); `solidAngle` for cube maps (default 'exact').
	 */
	begin( source: 'cube' | 'equirect', size: number, count: number, options: { height?: number, solidAngle?: CubeSolidAngleMode } = {} ): void {

		const where = 'SHProjector.begin';
		if ( source !== 'cube' && source !== 'equirect' ) throw new RangeError( `${where}: source is ${describeValue( source )}; expected 'cube' or 'equirect'.` );
		assertOptions( where, 'options', options );
		const solidAngle = options.solidAngle ?? 'exact';
		if ( ! CAPTURE_SOLID_ANGLES.includes( solidAngle ) ) {

			throw new RangeError( `${where}: options.solidAngle is ${describeValue( solidAngle )}; expected ${CAPTURE_SOLID_ANGLES.map( ( m ) => `'${m}'` ).join( ', ' )}.` );

		}

		assertInteger( 'SHProjector.begin', 'size', size, 1, 1 << 14 );
		const height = source === 'equirect' ? options.height ?? Math.max( 1, size >> 1 ) : size;
		assertInteger( 'SHProjector.begin', 'height', height, 1, 1 << 14 );
		const tiles = tilesFor( Math.min( size, height ) );
		assertInteger( 'SHProjector.begin', 'count', count, 1, Math.floor( MAX_ROWS / tiles ) );

		this.source = source;
		this.tiles = tiles;
		this.count = 0;
		this.capacity = count;
		this.ensureTargets( tiles, count );

		if ( source === 'cube' ) {

			const u = this.cubeMaterial.uniforms;
			u.solidAngles.value = this.solidAngleTexture( size, solidAngle );
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
		const kind = texture as { isTexture?: boolean; isCubeTexture?: boolean } | null;
		if ( kind?.isTexture !== true || ( kind.isCubeTexture === true ) !== ( this.source === 'cube' ) ) {

			throw new TypeError( `SHProjector.add: texture must be a three.js ${this.source === 'cube' ? 'CubeTexture (a WebGLCubeRenderTarget\'s)' : '2D Texture'} `
				+ `for a '${this.source}' batch, got ${describeValue( texture )}.` );

		}

		const material = this.source === 'cube' ? this.cubeMaterial : this.equirectMaterial;
		material.uniforms[ this.source === 'cube' ? 'cubeMap' : 'panorama' ].value = texture;
		material.uniforms.rowOffset.value = this.count * this.tiles;
		this.quad.material = material;

		const draws = this.multipleTargets ? 1 : PLANES;
		for ( let plane = 0; plane < draws; plane ++ ) {

			material.uniforms.outputIndex.value = plane;
			const target = this.levels[ 0 ][ plane ];
			target.viewport.set( 0, this.count * this.tiles, HALVES * this.tiles, this.tiles );
			this.draw( target );

		}

		this.count ++;

	}

	/**
	 * Reduces the batch and reads it back: 27 floats per source into `target` from `offset`.
	 * @returns `target`.
	 */
	finish( target: Float32Array, offset = 0 ): Float32Array {

		if ( this.source === null ) throw new Error( 'SHProjector.finish: call begin() first.' );
		if ( ! ( target instanceof Float32Array ) ) throw new TypeError( `SHProjector.finish: target must be a Float32Array, got ${describeValue( target )}.` );
		assertInteger( 'SHProjector.finish', 'offset', offset, 0 );
		const count = this.count;
		if ( target.length < offset + SH_FLOATS * count ) {

			throw new RangeError( `SHProjector.finish: target must have room for ${SH_FLOATS * count} floats from offset ${offset}, got length ${target.length}.` );

		}

		// Logarithmic reduction: tiles × tiles partial sums → 1 per half and probe.
		let tiles = this.tiles, level = 0;
		this.quad.material = this.reduceMaterial;
		const uniforms = this.reduceMaterial.uniforms;
		while ( tiles > 1 ) {

			const factor = tiles % 4 === 0 ? 4 : 2;
			tiles /= factor;
			uniforms.factor.value = factor;
			const sources = this.levels[ level ], destinations = this.levels[ level + 1 ];
			if ( this.multipleTargets ) {

				for ( let plane = 0; plane < PLANES; plane ++ ) uniforms[ `source${plane}` ].value = sources[ 0 ].textures[ plane ];
				destinations[ 0 ].viewport.set( 0, 0, HALVES * tiles, count * tiles );
				this.draw( destinations[ 0 ] );

			} else {

				for ( let plane = 0; plane < PLANES; plane ++ ) {

					uniforms.source0.value = sources[ plane ].texture;
					destinations[ plane ].viewport.set( 0, 0, HALVES * tiles, count * tiles );
					this.draw( destinations[ plane ] );

				}

			}

			level ++;

		}

		// Texel (half, probe) of plane p holds floats 4p..4p+3 of that half's 16; coefficient k of
		// the half, channel c, is float 3k + c.
		const final = this.levels[ level ];
		const floats = HALVES * 4 * count;
		if ( this.readBuffer.length < PLANES * floats ) this.readBuffer = new Float32Array( PLANES * floats );
		for ( let plane = 0; plane < PLANES; plane ++ ) {

			const buffer = this.readBuffer.subarray( plane * floats, ( plane + 1 ) * floats );
			if ( this.multipleTargets ) this.renderer.readRenderTargetPixels( final[ 0 ], 0, 0, HALVES, count, buffer, undefined, plane );
			else this.renderer.readRenderTargetPixels( final[ plane ], 0, 0, HALVES, count, buffer );

		}

		const buffer = this.readBuffer;
		for ( let p = 0; p < count; p ++ ) {

			for ( let half = 0; half < HALVES; half ++ ) {

				const texel = 4 * ( HALVES * p + half );
				const first = 5 * half, coefficients = half === 0 ? 5 : 4;
				for ( let f = 0; f < 3 * coefficients; f ++ ) {

					target[ offset + SH_FLOATS * p + 3 * first + f ] = buffer[ ( f >> 2 ) * floats + texel + ( f & 3 ) ];

				}

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

		const first = this.levels[ 0 ];
		if ( first && this.levelTiles === tiles && first[ 0 ].height >= count * tiles ) return;

		this.disposeTargets();
		this.levelTiles = tiles;
		const rows = Math.min( MAX_ROWS / tiles, Math.max( count, 16 ) );
		const create = ( t: number ) => new WebGLRenderTarget( HALVES * t, rows * t, {
			type: FloatType, format: RGBAFormat, minFilter: NearestFilter, magFilter: NearestFilter,
			depthBuffer: false, stencilBuffer: false, generateMipmaps: false, count: this.multipleTargets ? PLANES : 1,
		} );
		for ( let t = tiles; ; ) {

			if ( this.multipleTargets ) {

				const target = create( t );
				this.levels.push( [ target, target, target, target ] );

			} else {

				this.levels.push( [ create( t ), create( t ), create( t ), create( t ) ] );

			}

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

		for ( const level of this.levels ) for ( const target of new Set( level ) ) target.dispose();
		this.levels = [];
		this.levelTiles = 0;

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
