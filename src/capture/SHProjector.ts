import {
	DataTexture, FloatType, FramebufferTexture, GLSL3, Mesh, NearestFilter, OrthographicCamera, PlaneGeometry, RawShaderMaterial,
	RGBAFormat, Scene, WebGLRenderTarget,
	type CubeTexture, type Texture, type WebGLCubeRenderTarget, type WebGLRenderer,
} from 'three';
import { fullscreenVert, shGatherFrag, shProjectCubeFrag, shProjectEquirectFrag, shReduceFrag } from '../shaders.generated.js';
import type { CubeSolidAngleMode } from '../sh/projectCubeMapToSH.js';
import { SH_FLOATS, assertInteger, assertOptionalBoolean, assertOptions, describeValue } from '../validate.js';
import { CAPTURE_SOLID_ANGLES, assertWebGLRenderer } from './captureSettings.js';
import { createEquirectTableTexture, createSolidAngleTexture } from './solidAngleTexture.js';

// Rows of the projection targets: probes per batch × tiles must fit a texture everywhere WebGL2 runs.
const MAX_ROWS = 4096;

// The 27 SH floats and one unused, as seven RGBA float planes (shaders/shPack.glsl).
const PLANES = 7;

// The gather pass sums up to this many tiles per axis itself; larger grids are reduced by 4 first.
const GATHER_TILES = 4;

// Cube maps one draw can project (shProjectCube's SOURCES), beside the solid-angle texture: well
// within the 16 texture units WebGL2 guarantees.
const MAX_CUBES_PER_DRAW = 8;

// Faces of cube render targets at least this large are copied to 2D textures and read with
// texelFetch: in SwiftShader a cube lookup costs about 1.4× a 2D texelFetch, which at 256² pays
// for six copies per probe and at 128² breaks even (docs/gpu-projection.md).
const COPY_MIN_SIZE = 128;

/** A cube map to project: a cube render target, or its texture. */
type CubeSource = CubeTexture | WebGLCubeRenderTarget;

function isCubeTarget( item: CubeSource ): item is WebGLCubeRenderTarget {

	return ( item as { isWebGLCubeRenderTarget?: boolean } ).isWebGLCubeRenderTarget === true;

}

/**
 * Tiles per axis of a probe's grid of partial sums over a domain of `texels` per axis (a cube face
 * quadrant; half a panorama's shorter side, so that a panorama of width `size` never needs more
 * tiles than a cube of `size`): blocks of at least 4 texels, at most 16 × 16 tiles (one reduction
 * pass, then the gather), and 2 × 2 where the domain allows, so a draw fills a whole fragment quad.
 */
function tilesFor( texels: number ): number {

	let tiles = 1;
	while ( tiles < 16 && tiles * 2 * 4 <= texels ) tiles *= 2;
	return tiles === 1 && texels >= 2 ? 2 : tiles;

}

/** The planes one draw writes: `count` of them from `first`. */
interface PlaneGroup {

	first: number;
	count: number;

}

const multipleTargetSupport = new WeakMap<WebGLRenderer, boolean>();

/** Options of {@link SHProjector}. */
export interface SHProjectorOptions {

	/**
	 * Write the seven planes of partial sums with multiple render targets, as many per draw as the
	 * renderer's draw buffers allow (default: when a quick self-test on this renderer shows they
	 * work), or one plane per draw (`false`). headless-gl, for one, accepts multiple targets but
	 * fills only the first.
	 */
	multipleTargets?: boolean;

	/**
	 * Most planes one draw writes with multiple render targets, 1..7 (default: the renderer's
	 * MAX_DRAW_BUFFERS, at most 7). Lower it for a driver that mishandles many attachments.
	 */
	drawBuffers?: number;

}

/**
 * GPU projection of cube maps and panoramas onto SH9 (paper 2.2), batched: each source is
 * integrated into its own row block of seven float planes (one fragment per block of texels, all
 * nine coefficients, exact texel solid angles), the blocks are summed by a 4 × 4 reduction and a
 * gather pass that lays every probe's 27 floats out in one small target, and a whole batch ends
 * in one read-back.
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

	/** Whether the planes are written with multiple render targets (several per draw) or one per draw. */
	readonly multipleTargets: boolean;

	/** Planes each draw writes: all seven in one draw where the renderer allows, 1 without multiple targets. */
	readonly drawBuffers: number;

	private readonly scene = new Scene();
	private readonly camera = new OrthographicCamera();
	private readonly quad: Mesh;
	// The planes each draw writes: one group of seven with enough draw buffers.
	private readonly groups: PlaneGroup[] = [];
	// One material per plane group; the materials of a pass share one uniforms object. The batch
	// variant projects up to MAX_CUBES_PER_DRAW cube maps per draw.
	private readonly cubeMaterials: RawShaderMaterial[];
	private readonly cubeBatchMaterials: RawShaderMaterial[];
	private readonly faceMaterials: RawShaderMaterial[];
	// Reads a whole draw's cube maps from one 2D face atlas (addAtlas).
	private readonly atlasMaterials: RawShaderMaterial[];
	// 2D copies of a large cube render target's faces (FramebufferTexture), made when first needed.
	private readonly faces: FramebufferTexture[] = [];
	private readonly equirectMaterials: RawShaderMaterial[];
	private readonly reduceMaterials: RawShaderMaterial[];
	private readonly gatherMaterial: RawShaderMaterial;
	private readonly solidAngleTextures = new Map<string, DataTexture>();
	// levels[ l ][ g ]: the render target holding plane group g at reduction level l.
	private levels: WebGLRenderTarget[][] = [];
	private levelTiles = 0;
	// Every probe's seven planes side by side (x = plane, y = probe): the batch's one read-back.
	private gatherTarget: WebGLRenderTarget | null = null;

	private source: 'cube' | 'equirect' | null = null;
	private size = 0;
	private tiles = 1;
	private capacity = 0;
	private count = 0;
	private readBuffer = new Float32Array( 0 );

	/**
	 * @param renderer A WebGL2 renderer whose context can render to float targets (EXT_color_buffer_float).
	 * @param options See {@link SHProjectorOptions}.
	 */
	constructor( renderer: WebGLRenderer, options: SHProjectorOptions = {} ) {

		assertWebGLRenderer( 'SHProjector', renderer );
		assertOptions( 'SHProjector', 'options', options );
		assertOptionalBoolean( 'SHProjector', 'options.multipleTargets', options.multipleTargets );
		if ( options.drawBuffers !== undefined ) assertInteger( 'SHProjector', 'options.drawBuffers', options.drawBuffers, 1, PLANES );
		this.renderer = renderer;
		this.multipleTargets = options.multipleTargets ?? SHProjector.supportsMultipleTargets( renderer );
		const perDraw = this.multipleTargets ? Math.min( options.drawBuffers ?? PLANES, drawBuffers( renderer ) ) : 1;
		this.drawBuffers = perDraw;
		for ( let first = 0; first < PLANES; first += perDraw ) this.groups.push( { first, count: Math.min( perDraw, PLANES - first ) } );

		type Uniforms = Record<string, { value: unknown }>;
		type Defines = Record<string, number>;
		const material = ( fragment: string, uniforms: Uniforms, group: PlaneGroup, defines: Defines = {} ) => new RawShaderMaterial( {
			fragmentShader: fragment,
			glslVersion: GLSL3, vertexShader: fullscreenVert, uniforms, depthTest: false, depthWrite: false,
			defines: { PLANE_FIRST: group.first, PLANE_COUNT: group.count, SOURCES: 1, ...defines },
		} );
		const cube: Uniforms = {
			solidAngles: { value: null }, size: { value: 0 }, block: { value: 1 }, rowOffset: { value: 0 }, tiles: { value: 1 },
		};
		for ( let i = 0; i < MAX_CUBES_PER_DRAW; i ++ ) cube[ `cubeMap${i}` ] = { value: null };
		for ( let face = 0; face < 6; face ++ ) cube[ `face${face}` ] = { value: null };
		cube.atlas = { value: null };
		const equirect: Uniforms = {
			panorama: { value: null }, directions: { value: null }, size: { value: [ 0, 0 ] }, block: { value: [ 1, 1 ] },
			rowOffset: { value: 0 },
		};
		const reduce: Uniforms = { factor: { value: 4 } };
		const gather: Uniforms = { factor: { value: 1 } };
		for ( let plane = 0; plane < PLANES; plane ++ ) {

			reduce[ `source${plane}` ] = { value: null };
			gather[ `plane${plane}` ] = { value: null };

		}

		this.cubeMaterials = this.groups.map( ( group ) => material( shProjectCubeFrag, cube, group ) );
		const batch = { SOURCES: MAX_CUBES_PER_DRAW };
		this.cubeBatchMaterials = this.groups.map( ( group ) => material( shProjectCubeFrag, cube, group, batch ) );
		this.faceMaterials = this.groups.map( ( group ) => material( shProjectCubeFrag, cube, group, { FACES: 1 } ) );
		this.atlasMaterials = this.groups.map( ( group ) => material( shProjectCubeFrag, cube, group, { ATLAS: 1 } ) );
		this.equirectMaterials = this.groups.map( ( group ) => material( shProjectEquirectFrag, equirect, group ) );
		this.reduceMaterials = this.groups.map( ( group ) => material( shReduceFrag, reduce, group ) );
		this.gatherMaterial = material( shGatherFrag, gather, { first: 0, count: 1 } );
		this.quad = new Mesh( new PlaneGeometry( 2, 2 ), this.gatherMaterial );
		this.quad.frustumCulled = false;
		this.scene.add( this.quad );

	}

	/** Most cube maps one {@link SHProjector.add} call projects in one draw. */
	static readonly maxCubesPerDraw: number = MAX_CUBES_PER_DRAW;

	/** Most sources one batch can hold for a source of this size (texels per axis). */
	static batchCapacity( size: number ): number {

		assertInteger( 'SHProjector.batchCapacity', 'size', size, 1, 1 << 14 );
		return Math.floor( MAX_ROWS / tilesFor( Math.ceil( size / 2 ) ) );

	}

	/**
	 * Whether multiple render targets really work on this renderer: renders constant outputs into
	 * as many float targets as the projection would use at once (up to seven) and reads the last
	 * one back. Cached per renderer.
	 */
	static supportsMultipleTargets( renderer: WebGLRenderer ): boolean {

		assertWebGLRenderer( 'SHProjector.supportsMultipleTargets', renderer );
		let supported = multipleTargetSupport.get( renderer );
		if ( supported !== undefined ) return supported;

		const count = Math.min( PLANES, drawBuffers( renderer ) );
		if ( count < 2 ) {

			multipleTargetSupport.set( renderer, false );
			return false;

		}

		const target = new WebGLRenderTarget( 1, 1, {
			type: FloatType, count, depthBuffer: false, minFilter: NearestFilter, magFilter: NearestFilter,
		} );
		let fragmentShader = 'precision highp float;\n';
		for ( let i = 0; i < count; i ++ ) fragmentShader += `layout( location = ${i} ) out vec4 out${i};\n`;
		fragmentShader += 'void main() {\n';
		for ( let i = 0; i < count; i ++ ) fragmentShader += `\tout${i} = vec4( ${i + 1}.0 );\n`;
		fragmentShader += '}\n';
		const material = new RawShaderMaterial( { glslVersion: GLSL3, vertexShader: fullscreenVert, fragmentShader } );
		const scene = new Scene();
		const quad = new Mesh( new PlaneGeometry( 2, 2 ), material );
		quad.frustumCulled = false;
		scene.add( quad );
		const previous = renderer.getRenderTarget();
		const pixel = new Float32Array( 4 );
		try {

			renderer.setRenderTarget( target );
			renderer.render( scene, new OrthographicCamera() );
			renderer.readRenderTargetPixels( target, 0, 0, 1, 1, pixel, undefined, count - 1 );
			// A GL error here means the draw was refused; drain the queue so it does not surface
			// later as someone else's error.
			const gl = renderer.getContext();
			let errors = 0;
			for ( let i = 0; i < 8 && gl.getError() !== gl.NO_ERROR; i ++ ) errors ++;
			supported = pixel[ 0 ] === count && errors === 0;

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
		const tiles = tilesFor( Math.ceil( Math.min( size, height ) / 2 ) );
		assertInteger( 'SHProjector.begin', 'count', count, 1, Math.floor( MAX_ROWS / tiles ) );

		this.source = source;
		this.size = size;
		this.tiles = tiles;
		this.count = 0;
		this.capacity = count;
		this.ensureTargets( tiles, count );

		if ( source === 'cube' ) {

			const u = this.cubeMaterials[ 0 ].uniforms;
			u.solidAngles.value = this.solidAngleTexture( size, solidAngle );
			u.size.value = size;
			u.tiles.value = tiles;
			u.block.value = Math.ceil( Math.ceil( size / 2 ) / tiles );

		} else {

			const u = this.equirectMaterials[ 0 ].uniforms;
			u.directions.value = this.equirectTable( size, height );
			u.size.value = [ size, height ];
			u.block.value = [ Math.ceil( size / tiles ), Math.ceil( height / tiles ) ];

		}

	}

	/**
	 * Projects the next source of the batch, or the next few cube maps (an array of up to
	 * {@link SHProjector.maxCubesPerDraw}, in order; small faces go in one draw, which saves a
	 * draw, a render pass and a texture barrier per probe). A cube source is a
	 * `WebGLCubeRenderTarget` with `NearestFilter` (as {@link ProbeCapturer} makes it), or its
	 * texture; give the target where you have it: faces of 128² and more are then copied to 2D
	 * textures, which software rasterisers read faster than a cube map. A panorama is any 2D
	 * texture, sampled texel by texel. The draws are issued at once: the sources may be rendered
	 * into again right after.
	 */
	add( source: CubeSource | Texture | readonly CubeSource[] ): void {

		if ( this.source === null ) throw new Error( 'SHProjector.add: call begin() first.' );
		const many = Array.isArray( source );
		const list = many ? source as readonly CubeSource[] : null;
		const count = list ? list.length : 1;
		if ( list && ( this.source !== 'cube' || count < 1 || count > MAX_CUBES_PER_DRAW ) ) {

			throw new RangeError( `SHProjector.add: an array must hold 1..${MAX_CUBES_PER_DRAW} cube render targets or textures for a 'cube' batch, `
				+ `got ${count} for a '${this.source}' batch.` );

		}

		if ( this.count + count > this.capacity ) {

			throw new Error( `SHProjector.add: the batch holds ${this.capacity} sources, ${this.count} added; call finish() first.` );

		}

		for ( let i = 0; i < count; i ++ ) this.checkSource( list ? list[ i ] : source, list ? `sources[ ${i} ]` : 'source' );

		if ( this.source === 'equirect' ) {

			this.equirectMaterials[ 0 ].uniforms.panorama.value = source;
			this.drawSources( this.equirectMaterials, 1 );
			return;

		}

		const items = list ?? [ source as CubeSource ];
		if ( this.size >= COPY_MIN_SIZE || this.groups.length > 1 ) {

			// Large faces: one source per draw, render targets through 2D copies of their faces.
			// Few draw buffers: several draws per source anyway, and one program of eight
			// projections per plane group is not worth compiling.
			for ( let i = 0; i < count; i ++ ) {

				const item = items[ i ];
				if ( this.size >= COPY_MIN_SIZE && isCubeTarget( item ) ) {

					this.copyFaces( item );
					this.drawSources( this.faceMaterials, 1 );

				} else {

					this.setCubes( items, i, 1 );
					this.drawSources( this.cubeMaterials, 1 );

				}

			}

			return;

		}

		this.setCubes( items, 0, count );
		this.drawSources( count > 1 ? this.cubeBatchMaterials : this.cubeMaterials, count );

	}

	/**
	 * Projects the next `count` cube maps of a `'cube'` batch from one 2D face atlas, in one draw
	 * (per plane group) whatever the count: cube map k's six faces lie side by side in row block k,
	 * face f in the size × size block from texel ( f·size, k·size ), each as a cube render target
	 * holds that face — what rendering the face's camera into that viewport of a 2D render target
	 * gives ({@link ProbeCapturer} renders its groups so). Read with `texelFetch`, so any filter
	 * works. The draws are issued at once: the atlas may be rendered into again right after.
	 * @param atlas A 2D texture at least 6·size wide and count·size high (a render target's texture).
	 * @param count Cube maps in the atlas, from its first row block.
	 */
	addAtlas( atlas: Texture, count: number ): void {

		const where = 'SHProjector.addAtlas';
		if ( this.source === null ) throw new Error( `${where}: call begin() first.` );
		if ( this.source !== 'cube' ) throw new RangeError( `${where}: an atlas holds cube map faces, for a 'cube' batch; this batch is '${this.source}'.` );
		assertInteger( where, 'count', count, 1 );
		if ( this.count + count > this.capacity ) {

			throw new Error( `${where}: the batch holds ${this.capacity} sources, ${this.count} added; call finish() first.` );

		}

		type Kind = { isTexture?: boolean, isCubeTexture?: boolean, isData3DTexture?: boolean, isDataArrayTexture?: boolean };
		const kind = atlas as ( Kind & { image?: { width?: number, height?: number } } ) | null;
		if ( kind?.isTexture !== true || kind.isCubeTexture === true || kind.isData3DTexture === true
			|| kind.isDataArrayTexture === true ) {

			throw new TypeError( `${where}: atlas must be a three.js 2D Texture, got ${describeValue( atlas )}.` );

		}

		const width = kind.image?.width ?? 0, height = kind.image?.height ?? 0;
		if ( width < 6 * this.size || height < count * this.size ) {

			throw new RangeError( `${where}: a ${width} × ${height} atlas cannot hold ${count} cube maps of ${this.size}² (it needs ${6 * this.size} × ${count * this.size}).` );

		}

		this.cubeMaterials[ 0 ].uniforms.atlas.value = atlas;
		this.drawSources( this.atlasMaterials, count );

	}

	/** Throws unless `item` is a source this batch takes. */
	private checkSource( item: unknown, name: string ): void {

		const kind = item as { isTexture?: boolean; isCubeTexture?: boolean; isWebGLCubeRenderTarget?: boolean; width?: number } | null;
		if ( this.source === 'cube' && kind?.isWebGLCubeRenderTarget === true ) {

			if ( kind.width !== this.size ) {

				throw new RangeError( `SHProjector.add: ${name} is a ${kind.width}² cube render target; this batch began with size ${this.size}.` );

			}

			return;

		}

		if ( kind?.isTexture !== true || ( kind.isCubeTexture === true ) !== ( this.source === 'cube' ) ) {

			throw new TypeError( `SHProjector.add: ${name} must be a three.js `
				+ `${this.source === 'cube' ? 'WebGLCubeRenderTarget or its CubeTexture' : '2D Texture'} for a '${this.source}' batch, got ${describeValue( item )}.` );

		}

	}

	/**
	 * Binds `count` cube maps of `items` from `first` to the sampler slots; unused slots hold null
	 * (three binds an empty cube map), not a stale texture.
	 */
	private setCubes( items: readonly CubeSource[], first: number, count: number ): void {

		const uniforms = this.cubeMaterials[ 0 ].uniforms;
		for ( let i = 0; i < MAX_CUBES_PER_DRAW; i ++ ) {

			const item = i < count ? items[ first + i ] : null;
			uniforms[ `cubeMap${i}` ].value = item === null ? null : isCubeTarget( item ) ? item.texture : item;

		}

	}

	/** Copies the six faces of `target` to the 2D face textures the FACES program reads (made or remade to its size and type). */
	private copyFaces( target: WebGLCubeRenderTarget ): void {

		const type = target.texture.type;
		if ( this.faces.length === 0 || this.faces[ 0 ].image.width !== target.width || this.faces[ 0 ].type !== type ) {

			this.disposeFaces();
			for ( let face = 0; face < 6; face ++ ) {

				const texture = new FramebufferTexture( target.width, target.width );
				texture.type = type;
				this.faces.push( texture );

			}

			const uniforms = this.faceMaterials[ 0 ].uniforms;
			this.faces.forEach( ( texture, face ) => { uniforms[ `face${face}` ].value = texture; } );

		}

		const renderer = this.renderer;
		const previous = renderer.getRenderTarget();
		const previousFace = renderer.getActiveCubeFace(), previousLevel = renderer.getActiveMipmapLevel();
		for ( let face = 0; face < 6; face ++ ) {

			renderer.setRenderTarget( target, face );
			renderer.copyFramebufferToTexture( this.faces[ face ] );

		}

		renderer.setRenderTarget( previous, previousFace, previousLevel );

	}

	private disposeFaces(): void {

		for ( const texture of this.faces ) texture.dispose();
		this.faces.length = 0;

	}

	/** Projects the next `count` sources, whose textures are bound, into their row blocks: one draw per plane group. */
	private drawSources( materials: RawShaderMaterial[], count: number ): void {

		materials[ 0 ].uniforms.rowOffset.value = this.count * this.tiles;
		for ( let g = 0; g < this.groups.length; g ++ ) {

			this.quad.material = materials[ g ];
			const target = this.levels[ 0 ][ g ];
			target.viewport.set( 0, this.count * this.tiles, this.tiles, count * this.tiles );
			this.draw( target );

		}

		this.count += count;

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

		// Grids of more than 4 × 4 tiles (8 or 16 per axis) are first summed 4 × 4 per texel.
		let tiles = this.tiles, level = 0;
		const reduce = this.reduceMaterials[ 0 ].uniforms;
		while ( tiles > GATHER_TILES ) {

			tiles /= 4;
			for ( let g = 0; g < this.groups.length; g ++ ) {

				const sources = this.levels[ level ][ g ], destination = this.levels[ level + 1 ][ g ];
				for ( let i = 0; i < this.groups[ g ].count; i ++ ) reduce[ `source${i}` ].value = sources.textures[ i ];
				destination.viewport.set( 0, 0, tiles, count * tiles );
				this.quad.material = this.reduceMaterials[ g ];
				this.draw( destination );

			}

			level ++;

		}

		// The gather sums the last tiles × tiles of every plane into texel ( plane, probe ).
		const gather = this.gatherMaterial.uniforms;
		this.groups.forEach( ( group, g ) => {

			for ( let i = 0; i < group.count; i ++ ) gather[ `plane${group.first + i}` ].value = this.levels[ level ][ g ].textures[ i ];

		} );

		gather.factor.value = tiles;
		const gatherTarget = this.gatherTarget!;
		gatherTarget.viewport.set( 0, 0, PLANES, count );
		this.quad.material = this.gatherMaterial;
		this.draw( gatherTarget );

		const floats = 4 * PLANES;
		if ( this.readBuffer.length < floats * count ) this.readBuffer = new Float32Array( floats * count );
		const buffer = this.readBuffer;
		this.renderer.readRenderTargetPixels( gatherTarget, 0, 0, PLANES, count, buffer );
		for ( let p = 0; p < count; p ++ ) target.set( buffer.subarray( floats * p, floats * p + SH_FLOATS ), offset + SH_FLOATS * p );

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

	/** Projection, reduction and gather targets for `tiles` and `count`, reused while they are big enough. */
	private ensureTargets( tiles: number, count: number ): void {

		const first = this.levels[ 0 ];
		if ( first && this.levelTiles === tiles && first[ 0 ].height >= count * tiles ) return;

		this.disposeTargets();
		this.levelTiles = tiles;
		const rows = Math.min( MAX_ROWS / tiles, Math.max( count, 16 ) );
		const create = ( width: number, height: number, planes: number ) => new WebGLRenderTarget( width, height, {
			type: FloatType, format: RGBAFormat, minFilter: NearestFilter, magFilter: NearestFilter,
			depthBuffer: false, stencilBuffer: false, generateMipmaps: false, count: planes,
		} );
		for ( let t = tiles; ; t /= 4 ) {

			this.levels.push( this.groups.map( ( group ) => create( t, rows * t, group.count ) ) );
			if ( t <= GATHER_TILES ) break;

		}

		this.gatherTarget = create( PLANES, rows, 1 );

	}

	/** The solid-angle texture of a face size and formula, made once per projector. */
	private solidAngleTexture( size: number, mode: CubeSolidAngleMode ): DataTexture {

		const key = `${size}:${mode}`;
		let texture = this.solidAngleTextures.get( key );
		if ( ! texture ) this.solidAngleTextures.set( key, texture = createSolidAngleTexture( size, mode ) );
		return texture;

	}

	/** The direction and solid-angle table of a panorama size, made once per projector (kept with the solid-angle textures). */
	private equirectTable( width: number, height: number ): DataTexture {

		const key = `equirect:${width}x${height}`;
		let texture = this.solidAngleTextures.get( key );
		if ( ! texture ) this.solidAngleTextures.set( key, texture = createEquirectTableTexture( width, height ) );
		return texture;

	}

	private disposeTargets(): void {

		for ( const level of this.levels ) for ( const target of level ) target.dispose();
		this.gatherTarget?.dispose();
		this.gatherTarget = null;
		this.levels = [];
		this.levelTiles = 0;

	}

	/** Frees every GPU resource: targets, textures, materials, the quad's geometry. */
	dispose(): void {

		this.disposeTargets();
		this.disposeFaces();
		for ( const texture of this.solidAngleTextures.values() ) texture.dispose();
		this.solidAngleTextures.clear();
		const materials = [
			...this.cubeMaterials, ...this.cubeBatchMaterials, ...this.faceMaterials, ...this.atlasMaterials, ...this.equirectMaterials,
			...this.reduceMaterials, this.gatherMaterial,
		];
		for ( const material of materials ) material.dispose();
		this.quad.geometry.dispose();

	}

}

/** The renderer's MAX_DRAW_BUFFERS: how many planes one draw can write. */
function drawBuffers( renderer: WebGLRenderer ): number {

	// A lost context answers null: then WebGL2's guaranteed minimum, right once it is restored.
	const gl = renderer.getContext() as WebGL2RenderingContext;
	const value = gl.getParameter( gl.MAX_DRAW_BUFFERS ) as number | null;
	return typeof value === 'number' && value >= 1 ? value : 4;

}
