/**
 * Scene and read-back helpers for the GPU tests of test/capture and test/runtime: environments of
 * known radiance painted in world directions, cube-face and framebuffer read-back, PNG output.
 */

import * as fs from 'node:fs';
import * as path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import * as THREE from 'three';
import { BASIS_CONSTANT, POLYNOMIAL_NORM } from '../sh/helpers.js';

/** The repository root (this file is test/helpers/gpuScenes.ts). */
export const REPO_ROOT = path.resolve( path.dirname( fileURLToPath( import.meta.url ) ), '../..' );

/** Where failing image tests write their actual and diff images (gitignored). */
export const OUTPUT_DIR = path.join( REPO_ROOT, 'test/output' );

/**
 * GLSL of `vec3 name( vec3 d )` = Σ_k c_k Y_k(d) with three's basis constants (the same ones as
 * SphericalHarmonics3.getBasisAt and shaders/shBasis.glsl); `coefficients[ k ]` is [ r, g, b ].
 */
export function shRadianceGLSL( name: string, coefficients: ReadonlyArray<readonly number[]> ): string {

	const c = ( k: number ) => `vec3( ${coefficients[ k ].map( ( v ) => v.toFixed( 8 ) ).join( ', ' )} )`;
	const b = BASIS_CONSTANT.map( ( v ) => v.toFixed( 6 ) );
	return /* glsl */`
		vec3 ${name}( vec3 d ) {
			return ${c( 0 )} * ${b[ 0 ]}
				+ ${c( 1 )} * ( ${b[ 1 ]} * d.y ) + ${c( 2 )} * ( ${b[ 2 ]} * d.z ) + ${c( 3 )} * ( ${b[ 3 ]} * d.x )
				+ ${c( 4 )} * ( ${b[ 4 ]} * d.x * d.y ) + ${c( 5 )} * ( ${b[ 5 ]} * d.y * d.z )
				+ ${c( 6 )} * ( ${b[ 6 ]} * ( 3.0 * d.z * d.z - 1.0 ) )
				+ ${c( 7 )} * ( ${b[ 7 ]} * d.x * d.z ) + ${c( 8 )} * ( ${b[ 8 ]} * ( d.x * d.x - d.y * d.y ) );
		}
	`;

}

/**
 * The exact SH9 (27 floats, three's layout) of Σ_k c_k Y_k: coefficient k is c_k·∫Y_k², which is
 * c_k·(1 ± 3e-6) because three's 6-digit constants are not exactly 1/‖p_k‖ (see test/sh/helpers).
 */
export function analyticSH( coefficients: ReadonlyArray<readonly number[]> ): Float32Array {

	const sh = new Float32Array( 27 );
	for ( let k = 0; k < 9; k ++ ) {

		const self = BASIS_CONSTANT[ k ] * BASIS_CONSTANT[ k ] * POLYNOMIAL_NORM[ k ];
		for ( let c = 0; c < 3; c ++ ) sh[ 3 * k + c ] = coefficients[ k ][ c ] * self;

	}

	return sh;

}

/**
 * A big inward-facing box whose fragment shader paints radiance as a function of the world
 * direction from the camera: `body` is GLSL that reads `vec3 d` (the unit world ray) and
 * `vec3 probe` (the camera position: for a CubeCamera, the probe) and writes `gl_FragColor`.
 * The ray is interpolated per fragment on flat faces, which is exact (see
 * test/sh/cubeFaceMapping.gpu.test.ts), so the cube map holds f(ω) at every texel centre.
 */
export function directionEnvironment( body: string, declarations = '', size = 50 ): THREE.Mesh<THREE.BoxGeometry, THREE.ShaderMaterial> {

	const material = new THREE.ShaderMaterial( {
		side: THREE.BackSide,
		depthWrite: false,
		vertexShader: /* glsl */`
			varying vec3 vRay;
			void main() {
				vec4 world = modelMatrix * vec4( position, 1.0 );
				vRay = world.xyz - cameraPosition;
				gl_Position = projectionMatrix * viewMatrix * world;
			}
		`,
		fragmentShader: /* glsl */`
			varying vec3 vRay;
			${declarations}
			void main() {
				vec3 d = normalize( vRay );
				vec3 probe = cameraPosition;
				${body}
			}
		`,
	} );
	// Off-centre and not cubic, so nothing depends on where the walls happen to be.
	const box = new THREE.Mesh( new THREE.BoxGeometry( size, size * 1.3, size * 1.7 ), material );
	box.position.set( 0.1 * size, - 0.05 * size, 0.07 * size );
	box.frustumCulled = false;
	return box;

}

/** Frees a mesh's geometry and material(s). */
export function disposeMesh( mesh: THREE.Mesh ): void {

	mesh.geometry.dispose();
	for ( const material of Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ] ) material.dispose();

}

/**
 * The six faces (+X, −X, +Y, −Y, +Z, −Z) of a cube render target as RGBA Float32Arrays, in the
 * order projectCubeMapToSH takes. Half-float targets are read as Uint16 and decoded: reading
 * them into a Float32Array silently returns garbage in headless-gl (it does not check the
 * buffer type against the read type).
 */
export function readCubeFaces( renderer: THREE.WebGLRenderer, target: THREE.WebGLCubeRenderTarget ): Float32Array[] {

	const size = target.width;
	const faces: Float32Array[] = [];
	for ( let f = 0; f < 6; f ++ ) {

		const face = new Float32Array( size * size * 4 );
		if ( target.texture.type === THREE.HalfFloatType ) {

			const half = new Uint16Array( size * size * 4 );
			renderer.readRenderTargetPixels( target, 0, 0, size, size, half, f );
			for ( let i = 0; i < half.length; i ++ ) face[ i ] = THREE.DataUtils.fromHalfFloat( half[ i ] );

		} else {

			renderer.readRenderTargetPixels( target, 0, 0, size, size, face, f );

		}

		faces.push( face );

	}

	return faces;

}

/** An RGBA8 image, rows top-down (as PNG stores them). */
export interface Image8 {

	width: number;
	height: number;
	data: Uint8Array;

}

/**
 * Renders `scene` to the default framebuffer (so `renderer.outputColorSpace`, sRGB by default, is
 * applied as on a page) and reads it back, top row first.
 */
export function renderToImage(
	renderer: THREE.WebGLRenderer, gl: WebGL2RenderingContext, scene: THREE.Scene, camera: THREE.Camera
): Image8 {

	const size = renderer.getDrawingBufferSize( new THREE.Vector2() );
	const width = size.x, height = size.y;
	renderer.setRenderTarget( null );
	renderer.render( scene, camera );
	const bottomUp = new Uint8Array( width * height * 4 );
	gl.readPixels( 0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, bottomUp );
	const data = new Uint8Array( bottomUp.length );
	const row = width * 4;
	for ( let y = 0; y < height; y ++ ) data.set( bottomUp.subarray( y * row, ( y + 1 ) * row ), ( height - 1 - y ) * row );
	return { width, height, data };

}

/** Largest per-channel difference (0..255, RGB only) and how many pixels differ by more than `threshold`. */
export function compareImages( a: Image8, b: Image8, threshold = 0 ): { max: number; count: number; at: [ number, number ] } {

	if ( a.width !== b.width || a.height !== b.height ) throw new Error( `compareImages: sizes differ (${a.width}×${a.height} vs ${b.width}×${b.height}).` );
	let max = 0, count = 0, at: [ number, number ] = [ - 1, - 1 ];
	for ( let p = 0; p < a.width * a.height; p ++ ) {

		let pixel = 0;
		for ( let c = 0; c < 3; c ++ ) pixel = Math.max( pixel, Math.abs( a.data[ 4 * p + c ] - b.data[ 4 * p + c ] ) );
		if ( pixel > threshold ) count ++;
		if ( pixel > max ) { max = pixel; at = [ p % a.width, Math.floor( p / a.width ) ]; }

	}

	return { max, count, at };

}

/** |a − b| per channel, amplified ×`gain`, opaque: for a diff image. */
export function diffImage( a: Image8, b: Image8, gain = 8 ): Image8 {

	const data = new Uint8Array( a.data.length );
	for ( let i = 0; i < data.length; i ++ ) {

		data[ i ] = ( i & 3 ) === 3 ? 255 : Math.min( 255, gain * Math.abs( a.data[ i ] - b.data[ i ] ) );

	}

	return { width: a.width, height: a.height, data };

}

/** Average RGB (0..255) over a square of pixels centred at (x, y), top-down coordinates. */
export function averageColor( image: Image8, x: number, y: number, radius: number ): [ number, number, number ] {

	const sum = [ 0, 0, 0 ];
	let n = 0;
	for ( let j = Math.round( y - radius ); j <= Math.round( y + radius ); j ++ ) {

		for ( let i = Math.round( x - radius ); i <= Math.round( x + radius ); i ++ ) {

			const p = 4 * ( j * image.width + i );
			for ( let c = 0; c < 3; c ++ ) sum[ c ] += image.data[ p + c ];
			n ++;

		}

	}

	return [ sum[ 0 ] / n, sum[ 1 ] / n, sum[ 2 ] / n ];

}

/** Where a world point lands in an image rendered with `camera` (pixels, top-down). */
export function projectToImage( point: THREE.Vector3, camera: THREE.Camera, width: number, height: number ): [ number, number ] {

	const ndc = point.clone().project( camera );
	return [ ( ndc.x + 1 ) / 2 * width, ( 1 - ndc.y ) / 2 * height ];

}

export function writePNG( file: string, image: Image8 ): void {

	const png = new PNG( { width: image.width, height: image.height } );
	png.data = Buffer.from( image.data.buffer, image.data.byteOffset, image.data.byteLength );
	fs.mkdirSync( path.dirname( file ), { recursive: true } );
	fs.writeFileSync( file, PNG.sync.write( png ) );

}

export function readPNG( file: string ): Image8 {

	const png = PNG.sync.read( fs.readFileSync( file ) );
	return { width: png.width, height: png.height, data: new Uint8Array( png.data.buffer, png.data.byteOffset, png.data.byteLength ) };

}

/**
 * The folder of real assets (panoramas, scenes): `$CAPTURE_LIGHTING_ASSETS`, else
 * `../shared/assets` next to the repository; null when neither exists.
 */
export function assetsDirectory(): string | null {

	const candidates = [ process.env.CAPTURE_LIGHTING_ASSETS, path.resolve( REPO_ROOT, '../shared/assets' ) ];
	for ( const candidate of candidates ) if ( candidate && fs.existsSync( candidate ) ) return candidate;
	return null;

}

/** sRGB transfer function, decode (IEC 61966-2-1), as the GPU applies to SRGB8_ALPHA8 textures. */
export function srgbToLinear( c: number ): number {

	return c <= 0.04045 ? c / 12.92 : Math.pow( ( c + 0.055 ) / 1.055, 2.4 );

}
