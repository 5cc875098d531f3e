import {
	BackSide, DoubleSide, FrontSide, Matrix4, NearestFilter, Object3D, RenderTarget,
	type Material, type Scene, type Side, type Sprite, type TextureDataType, type WebGPURenderer,
} from 'three/webgpu';
import { MirroredProjectionCamera } from './MirroredProjectionCamera.js';

// WebGL's CubeCamera face cameras (three's WebGLCoordinateSystem branch): fov −90°, these ups and
// looks, in face order +X, −X, +Y, −Y, +Z, −Z (docs/cube-faces.md).
const FACES: readonly ( readonly [ number, number, number, number, number, number ] )[] = [
	[ 0, 1, 0, 1, 0, 0 ], [ 0, 1, 0, - 1, 0, 0 ], [ 0, 0, - 1, 0, 1, 0 ],
	[ 0, 0, 1, 0, - 1, 0 ], [ 0, 1, 0, 0, 0, 1 ], [ 0, 1, 0, 0, 0, - 1 ],
];

type Determinant = () => number;
const determinant = Matrix4.prototype.determinant as Determinant;
const determinantAffine = ( Matrix4.prototype as unknown as { determinantAffine?: Determinant } ).determinantAffine;

// Shared by every instance (two captures of one scene may interleave at their yields): whether a face
// camera's draw is running, and how many prepared captures use each matrix given the flip.
let flipping = false;
const users = new Map<Matrix4, number>();

function mirrored( original: Determinant ): Determinant {

	return function ( this: Matrix4 ) {

		const value = original.call( this );
		return flipping ? - value : value;

	};

}

/**
 * The six faces of a probe rendered on WebGPURenderer's WebGPU backend exactly as WebGLRenderer's
 * CubeCamera lays them out in memory: six 2D render targets (face f, texel ( column, row ) with
 * row 0 first, as `readRenderTargetPixels` returns WebGL's face f), drawn by six cameras with
 * WebGL's orientation and a y-negated projection ({@link MirroredProjectionCamera}). three's own
 * WebGPU CubeCamera stores each face mirrored in x instead, which rasterises edges that pass through
 * a texel centre differently (the tie rules see the other side); here every texel is covered as on
 * WebGL. The projection reads the faces by texel index (WebGPUSHProjector.addFaces).
 *
 * The negated y reverses the winding of every triangle on screen, so inside the face cameras' draws
 * the world matrix of every mesh in the scene reports a negated determinant: three then draws it
 * with the opposite front face (and its own pipelines, kept apart from ordinary draws), as it does a
 * mirrored mesh, so culling and `frontFacing` are those of WebGL. Draws three nests in a face's draw
 * (shadow maps, reflectors) and every draw outside the capture see the true determinant.
 */
export class WebGPUCubeFaces {

	/** Face edge in texels. */
	readonly size: number;

	/** The six face targets, +X, −X, +Y, −Y, +Z, −Z (NearestFilter, no mipmaps). */
	readonly targets: readonly RenderTarget[];

	/** The six face cameras, children of {@link WebGPUCubeFaces.rig}. */
	readonly cameras: readonly MirroredProjectionCamera[];

	/** The cameras' parent: its position is the probe's. */
	readonly rig = new Object3D();

	// The matrices this instance prepared; the sprites' materials and their sides while swapped.
	private readonly flipped = new Set<Matrix4>();
	private readonly spriteMaterials = new Set<Material>();
	private readonly spriteSides = new Map<Material, Side>();

	/**
	 * @param size Face edge in texels.
	 * @param near Near plane of the cameras.
	 * @param far Far plane of the cameras.
	 * @param type Texel type of the targets.
	 */
	constructor( size: number, near: number, far: number, type: TextureDataType ) {

		this.size = size;
		this.targets = FACES.map( () => new RenderTarget( size, size, {
			type, minFilter: NearestFilter, magFilter: NearestFilter, generateMipmaps: false, depthBuffer: true,
		} ) );
		this.cameras = FACES.map( ( [ ux, uy, uz, lx, ly, lz ] ) => {

			const camera = new MirroredProjectionCamera( - 90, 1, near, far );
			camera.up.set( ux, uy, uz );
			camera.lookAt( lx, ly, lz );
			this.rig.add( camera );
			return camera;

		} );
		this.rig.updateMatrixWorld( true );

	}

	/**
	 * Gives every mesh of `scene` the flipping determinant (again after the scene may have changed,
	 * e.g. after a yield: meshes already prepared are skipped). Undo with {@link WebGPUCubeFaces.release}.
	 */
	prepare( scene: Scene ): void {

		scene.traverse( ( object ) => {

			if ( ( object as Sprite ).isSprite === true ) this.spriteMaterials.add( ( object as Sprite ).material );
			const matrix = ( object as { isMesh?: boolean } ).isMesh === true ? object.matrixWorld : null;
			if ( matrix === null || this.flipped.has( matrix ) ) return;
			this.flipped.add( matrix );
			const count = users.get( matrix ) ?? 0;
			users.set( matrix, count + 1 );
			if ( count > 0 ) return;
			const own = matrix as unknown as Record<string, Determinant>;
			own.determinant = mirrored( determinant );
			if ( determinantAffine ) own.determinantAffine = mirrored( determinantAffine );

		} );

	}

	/** Gives the meshes {@link WebGPUCubeFaces.prepare} changed their own determinant back (once no other capture uses them). */
	release(): void {

		for ( const matrix of this.flipped ) {

			const count = ( users.get( matrix ) ?? 1 ) - 1;
			if ( count > 0 ) {

				users.set( matrix, count );
				continue;

			}

			users.delete( matrix );
			const own = matrix as unknown as Record<string, unknown>;
			delete own.determinant;
			delete own.determinantAffine;

		}

		this.flipped.clear();
		this.spriteMaterials.clear();

	}

	/**
	 * Sprites are not meshes (three never flips their front face): inside the face cameras' draws
	 * their single-sided materials are drawn from the other side (`on`), and given back after.
	 */
	private swapSprites( on: boolean ): void {

		if ( on ) {

			for ( const material of this.spriteMaterials ) {

				if ( material.side === DoubleSide ) continue;
				this.spriteSides.set( material, material.side );
				material.side = material.side === FrontSide ? BackSide : FrontSide;

			}

		} else {

			for ( const [ material, side ] of this.spriteSides ) material.side = side;
			this.spriteSides.clear();

		}

	}

	/**
	 * Draws the six faces of `scene` seen from the rig's position (set it and update its matrices
	 * first), each into its target, cleared first (`renderer.autoClear` is set for the draws and
	 * restored). Call {@link WebGPUCubeFaces.prepare} once before. The meshes' determinants are
	 * flipped only inside draws with the face cameras: a draw three nests in one (a shadow map, a
	 * reflector) keeps its own winding.
	 */
	render( renderer: WebGPURenderer, scene: Scene ): void {

		const previous = renderer.getRenderTarget();
		const autoClear = renderer.autoClear;
		const xr = renderer.xr.enabled;
		const own = Object.prototype.hasOwnProperty.call( renderer, 'render' );
		const render = renderer.render;
		const cameras: readonly unknown[] = this.cameras;
		const faces = this;
		renderer.render = function ( this: WebGPURenderer, ...args: Parameters<WebGPURenderer[ 'render' ]> ) {

			const outer = flipping, inner = cameras.includes( args[ 1 ] );
			flipping = inner;
			if ( inner !== outer ) faces.swapSprites( inner );
			try {

				return render.apply( this, args );

			} finally {

				flipping = outer;
				if ( inner !== outer ) faces.swapSprites( outer );

			}

		};

		renderer.autoClear = true;
		renderer.xr.enabled = false;
		try {

			for ( let face = 0; face < 6; face ++ ) {

				renderer.setRenderTarget( this.targets[ face ] );
				renderer.render( scene, this.cameras[ face ] );

			}

		} finally {

			if ( own ) renderer.render = render;
			else delete ( renderer as Partial<WebGPURenderer> ).render;
			renderer.xr.enabled = xr;
			renderer.autoClear = autoClear;
			renderer.setRenderTarget( previous );

		}

	}

	/** Frees the six targets (and gives back the meshes' determinants). */
	dispose(): void {

		this.release();
		for ( const target of this.targets ) target.dispose();

	}

}
