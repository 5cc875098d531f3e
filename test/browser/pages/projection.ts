import * as THREE from 'three';
import { projectCubeMapToSH, projectEquirectToSH } from 'three-capture-lighting/math';
import { SHProjector, projectEquirectToSHGPU } from 'three-capture-lighting/capture';

// The GPU projection in Chromium, with multiple render targets (what browsers use; headless-gl
// cannot) and with the four-draw fallback, against the CPU projection of the read-back faces.
// Results go to window.__result for test/browser/projection.test.ts.

const renderer = new THREE.WebGLRenderer();
const scene = new THREE.Scene();
// A room with a few coloured boxes: a radiance with sharp features in every direction.
const room = new THREE.Mesh( new THREE.BoxGeometry( 10, 8, 12 ), new THREE.MeshBasicMaterial( { color: 0x8090a0, side: THREE.BackSide } ) );
scene.add( room );
for ( const [ color, x, y, z ] of [ [ 0xff2000, 3, 0, - 2 ], [ 0x00ff40, - 2, 2, 1 ], [ 0x3040ff, 0, - 2, 3 ], [ 0xffffff, 1, 3, 0 ] ] ) {

	const box = new THREE.Mesh( new THREE.BoxGeometry( 1.5, 1, 2 ), new THREE.MeshBasicMaterial( { color } ) );
	box.position.set( x, y, z );
	scene.add( box );

}

function worstError( gpu: Float32Array, cpu: Float32Array ): number {

	let worst = 0;
	for ( let i = 0; i < 27; i ++ ) worst = Math.max( worst, Math.abs( gpu[ i ] - cpu[ i ] ) / Math.abs( cpu[ i % 3 ] ) );
	return worst;

}

const result: Record<string, unknown> = { supportsMultipleTargets: SHProjector.supportsMultipleTargets( renderer ) };
for ( const size of [ 8, 32, 100, 128 ] ) {

	const target = new THREE.WebGLCubeRenderTarget( size, { type: THREE.FloatType, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false } );
	const camera = new THREE.CubeCamera( 0.05, 100, target );
	camera.position.set( 0.3, - 0.2, 0.5 );
	camera.update( renderer, scene );
	const faces: Float32Array[] = [];
	for ( let f = 0; f < 6; f ++ ) {

		const face = new Float32Array( size * size * 4 );
		renderer.readRenderTargetPixels( target, 0, 0, size, size, face, f );
		faces.push( face );

	}

	const cpu = projectCubeMapToSH( faces, size );
	for ( const multipleTargets of [ true, false ] ) {

		const projector = new SHProjector( renderer, { multipleTargets } );
		projector.begin( 'cube', size, 3 );
		for ( let i = 0; i < 3; i ++ ) projector.add( target.texture );
		const gpu = projector.finish( new Float32Array( 81 ) );
		result[ `${size}:${multipleTargets ? 'mrt' : 'single'}` ] = Math.max( worstError( gpu.subarray( 0, 27 ), cpu ), worstError( gpu.subarray( 54, 81 ), cpu ) );
		projector.dispose();

	}

	target.dispose();

}

// Panoramas (random HDR texels over a ramp, so a flipped row or column order shows) against the
// CPU projection of the same texels, at power-of-two and odd sizes.
for ( const [ width, height ] of [ [ 64, 32 ], [ 100, 49 ], [ 256, 128 ] ] ) {

	const pixels = new Float32Array( width * height * 4 );
	let seed = 11;
	for ( let i = 0; i < pixels.length; i ++ ) {

		seed = ( seed * 16807 ) % 2147483647;
		const texel = i >> 2, row = Math.floor( texel / width ), column = texel % width;
		pixels[ i ] = seed / 2147483647 + 2 * row / height + column / width;

	}

	const panorama = new THREE.DataTexture( pixels, width, height, THREE.RGBAFormat, THREE.FloatType );
	panorama.minFilter = panorama.magFilter = THREE.NearestFilter;
	panorama.needsUpdate = true;
	const cpu = projectEquirectToSH( pixels, width, height, { rowOrder: 'bottom-up' } );
	result[ `panorama ${width}x${height}` ] = worstError( projectEquirectToSHGPU( renderer, panorama ), cpu );
	panorama.dispose();

}

result.glError = renderer.getContext().getError();
Object.assign( window, { __result: result } );
