import { it } from 'vitest';
import * as THREE from 'three';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { SHProjector } from '../../src/capture/SHProjector.js';

it( 'scratch', async () => {
	const ctx = await createHeadlessRenderer( 64, 64 );
	const renderer = ctx.renderer!, gl = ctx.gl!;
	console.log( gl.getSupportedExtensions() );
	console.log( 'lose', gl.getExtension( 'WEBGL_lose_context' ) );
	console.log( [ 8, 16, 32, 64, 100, 128, 256, 1 ].map( ( s ) => [ s, SHProjector.batchCapacity( s ) ] ) );
	const target = new THREE.WebGLCubeRenderTarget( 8, { type: THREE.HalfFloatType } );
	const cc = new THREE.CubeCamera( 0.1, 10, target );
	const scene = new THREE.Scene(); scene.background = new THREE.Color( 0.5, 0.25, 1 );
	cc.update( renderer, scene );
	const buf = new Uint16Array( 8 * 8 * 4 );
	try { renderer.readRenderTargetPixels( target, 0, 0, 8, 8, buf, 0 ); console.log( 'half', Array.from( buf.slice( 0, 4 ) ).map( THREE.DataUtils.fromHalfFloat ), gl.getError() ); } catch ( e ) { console.log( 'half err', e ); }
	const fbuf = new Float32Array( 8 * 8 * 4 );
	renderer.readRenderTargetPixels( target, 0, 0, 8, 8, fbuf, 0 ); console.log( 'half as float', fbuf.slice( 0, 4 ), gl.getError() );
	const scene2 = new THREE.Scene();
	const box = new THREE.Mesh( new THREE.BoxGeometry( 100, 100, 100 ), new THREE.ShaderMaterial( { side: THREE.BackSide, vertexShader: `varying vec3 vRay; void main(){ vec4 w = modelMatrix * vec4( position, 1.0 ); vRay = w.xyz - cameraPosition; gl_Position = projectionMatrix * viewMatrix * w; }`, fragmentShader: `varying vec3 vRay; void main(){ gl_FragColor = vec4( 1.0 + cameraPosition.x, 1.0 + cameraPosition.y, 2.0, 1.0 ); }` } ) );
	scene2.add( box );
	const n = 2049; const pos = new Float32Array( 3 * n );
	for ( let i = 0; i < n; i ++ ) { pos[ 3 * i ] = ( i % 64 ) * 0.1; pos[ 3 * i + 1 ] = Math.floor( i / 64 ) * 0.1; }
	const cap = new ProbeCapturer( renderer, { resolution: 16, type: THREE.FloatType, far: 500 } );
	let t = performance.now();
	const sh = await cap.capture( scene2, pos, new Float32Array( 27 * n ) );
	console.log( 'time', performance.now() - t, sh[ 0 ], sh[ 1 ], sh[ 27 * 2048 ], sh[ 27 * 2048 + 1 ], 4 * Math.PI * 0.282095 );
	const cap2 = new ProbeCapturer( renderer, { resolution: 128, type: THREE.FloatType, far: 500 } );
	t = performance.now();
	await cap2.capture( scene2, pos.subarray( 0, 30 ), new Float32Array( 27 * 10 ) );
	console.log( 'time 10 @128', performance.now() - t );
	ctx.dispose();
} );
