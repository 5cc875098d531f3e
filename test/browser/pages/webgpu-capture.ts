import * as THREE from 'three';
import { MeshBasicNodeMaterial, RenderTarget, WebGPURenderer } from 'three/webgpu';
import { positionWorld, vec3 } from 'three/tsl';
import { projectCubeMapToSH, projectEquirectToSH } from 'three-capture-lighting/math';
import { projectEquirectToSHGPU } from 'three-capture-lighting/capture';
// The webgpu entry (its capture hook installed); the main entry's modules are the same ones.
import { LightProbeVolume } from '../../../src/webgpu.js';
import { WebGPUProbeCapturer } from '../../../src/webgpu/capture/WebGPUProbeCapturer.js';

// WebGPURenderer capture on one backend (?backend=webgpu | webgl2), for test/browser/webgpuCapture.test.ts:
// an analytic environment, the same room captured by WebGLRenderer, a panorama against the CPU
// projection, create → capture → dispose cycles, and a lost device or context. Results go to window.__result.

const backend = new URLSearchParams( location.search ).get( 'backend' ) === 'webgl2' ? 'webgl2' : 'webgpu';
const result: Record<string, unknown> = { backend };
const SIZE = 16;

/** Largest |a − b| over the 27 floats of each probe, relative to that probe's L00 of the channel. */
function worstError( a: Float32Array, b: Float32Array ): number {

	let worst = 0;
	for ( let i = 0; i < a.length; i ++ ) {

		const l00 = Math.abs( b[ 27 * Math.floor( i / 27 ) + ( i % 3 ) ] );
		worst = Math.max( worst, Math.abs( a[ i ] - b[ i ] ) / l00 );

	}

	return worst;

}

/** A room of unlit coloured boxes: the same radiance on both renderers, sharp features everywhere. */
function room(): THREE.Scene {

	const scene = new THREE.Scene();
	const walls = new THREE.MeshBasicMaterial( { color: 0x8090a0, side: THREE.BackSide } );
	scene.add( new THREE.Mesh( new THREE.BoxGeometry( 10, 8, 12 ), walls ) );
	const boxes = [ [ 0xff2000, 3, 0, - 2 ], [ 0x00ff40, - 2, 2, 1 ], [ 0x3040ff, 0, - 2, 3 ], [ 0xffffff, 1, 3, 0 ] ];
	for ( const [ color, x, y, z ] of boxes ) {

		const box = new THREE.Mesh( new THREE.BoxGeometry( 1.5, 1, 2 ), new THREE.MeshBasicMaterial( { color } ) );
		box.position.set( x, y, z );
		scene.add( box );

	}

	// A sprite (not a mesh: its front face is not flipped by three, WebGPUCubeFaces swaps its side instead).
	const sprite = new THREE.Sprite( new THREE.SpriteMaterial( { color: 0xffc000 } ) );
	sprite.position.set( - 1.5, - 1, - 2.5 );
	sprite.scale.set( 1.5, 1, 1 );
	scene.add( sprite );
	return scene;

}

const PROBES = [ 0.3, - 0.2, 0.5, - 2, 1, - 1, 2.5, - 1.5, 2 ];

async function run(): Promise<void> {

	const adapter = backend === 'webgpu' ? await ( navigator as unknown as { gpu?: { requestAdapter(): Promise<unknown> } } ).gpu?.requestAdapter() : null;
	result.adapter = backend === 'webgl2' || adapter != null;
	const renderer = new WebGPURenderer( { forceWebGL: backend === 'webgl2' } );
	renderer.setSize( 32, 32 );
	document.body.appendChild( renderer.domElement );
	await renderer.init();
	result.isWebGPUBackend = ( renderer.backend as { isWebGPUBackend?: boolean } ).isWebGPUBackend === true;

	// Analytic: a sphere painted with L(d) = ( 0.5 + 0.3 d.y, 0.4 − 0.2 d.x, 0.6 + 0.5 d.x d.z ) around the probe,
	// whose SH are known: L00 = c·0.282095·4π, L1 = b·0.488603·4π/3, L2(xz) = h·1.092548·4π/15, the rest 0.
	const painted = new THREE.Scene();
	const paint = new MeshBasicNodeMaterial( { side: THREE.BackSide } );
	const d = positionWorld.normalize();
	paint.colorNode = vec3( d.y.mul( 0.3 ).add( 0.5 ), d.x.mul( - 0.2 ).add( 0.4 ), d.x.mul( d.z ).mul( 0.5 ).add( 0.6 ) );
	painted.add( new THREE.Mesh( new THREE.SphereGeometry( 5, 64, 32 ), paint ) );
	const expected = new Float32Array( 27 );
	const l0 = 0.282095 * 4 * Math.PI, l1 = 0.488603 * 4 * Math.PI / 3, l2 = 1.092548 * 4 * Math.PI / 15;
	expected.set( [ 0.5 * l0, 0.4 * l0, 0.6 * l0 ] );
	expected[ 3 ] = 0.3 * l1; // coefficient 1 (y), red
	expected[ 9 + 1 ] = - 0.2 * l1; // coefficient 3 (x), green
	expected[ 21 + 2 ] = 0.5 * l2; // coefficient 7 (xz), blue
	const analytic = new LightProbeVolume( { positions: [ 0, 0, 0, 0.01, 0, 0, 0, 0.01, 0, 0, 0, 0.01 ] } );
	let progress = 0;
	await analytic.capture( renderer, painted, { resolution: SIZE, onProgress: () => { progress ++; } } );
	result.analyticError = worstError( analytic.sh.slice( 0, 27 ), expected );
	result.progressCalls = progress;
	analytic.dispose();

	// The same room captured by WebGLRenderer (ProbeCapturer) and this renderer.
	const gl = new THREE.WebGLRenderer();
	const volumeGL = new LightProbeVolume( { positions: PROBES.concat( [ 0, 0, 0 ] ) } );
	await volumeGL.capture( gl, room(), { resolution: SIZE } );
	const volumeGPU = new LightProbeVolume( { positions: PROBES.concat( [ 0, 0, 0 ] ) } );
	await volumeGPU.capture( renderer, room(), { resolution: SIZE } );
	result.webglError = worstError( volumeGPU.sh, volumeGL.sh );
	const probeSH = ( sh: Float32Array, p: number ) => sh.slice( 27 * p, 27 * p + 27 );
	result.webglPerProbe = [ 0, 1, 2, 3 ].map( ( p ) => worstError( probeSH( volumeGPU.sh, p ), probeSH( volumeGL.sh, p ) ) );

	// The faces texel by texel against WebGLRenderer's CubeCamera faces at each probe (float RGBA, face f
	// row 0 first as readRenderTargetPixels returns them), and the projection alone: this renderer's SH of
	// a probe against the CPU projection of its read-back faces.
	const capturer = new WebGPUProbeCapturer( renderer, { resolution: SIZE } );
	const glTarget = new THREE.WebGLCubeRenderTarget( SIZE, {
		type: THREE.HalfFloatType, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
	} );
	const glCamera = new THREE.CubeCamera( 0.05, 1000, glTarget );
	const glRoom = room();
	const readFaces = async ( from = capturer, size = SIZE ): Promise<Float32Array[]> => {

		const faces: Float32Array[] = [];
		for ( let face = 0; face < 6; face ++ ) {

			// WebGPU backend: six 2D targets laid out as WebGL's faces; WebGL2 backend: three's cube target, the
			// same layout there.
			const half = ( from.faces
				? await renderer.readRenderTargetPixelsAsync( from.faces.targets[ face ], 0, 0, size, size )
				: await renderer.readRenderTargetPixelsAsync( from.cubeRenderTarget!, 0, 0, size, size, 0, face ) ) as Uint16Array;
			faces.push( Float32Array.from( half, ( h ) => THREE.DataUtils.fromHalfFloat( h ) ) );

		}

		return faces;

	};

	const faceDiffs: number[] = [];
	const shOne = new Float32Array( 27 );
	for ( let p = 0; p < 4; p ++ ) {

		await capturer.capture( room(), PROBES.concat( [ 0, 0, 0 ] ).slice( 3 * p, 3 * p + 3 ), shOne );
		const faces = await readFaces();
		if ( p === 0 ) result.projectionError = worstError( shOne, projectCubeMapToSH( faces, SIZE ) );
		glCamera.position.fromArray( PROBES.concat( [ 0, 0, 0 ] ), 3 * p );
		glCamera.updateMatrixWorld();
		glCamera.update( gl, glRoom );
		let differing = 0;
		for ( let face = 0; face < 6; face ++ ) {

			const half = new Uint16Array( 4 * SIZE * SIZE );
			gl.readRenderTargetPixels( glTarget, 0, 0, SIZE, SIZE, half, face );
			for ( let t = 0; t < SIZE * SIZE; t ++ ) {

				let off = 0;
				for ( let c = 0; c < 3; c ++ ) {

					off = Math.max( off, Math.abs( THREE.DataUtils.fromHalfFloat( half[ 4 * t + c ] ) - faces[ face ][ 4 * t + c ] ) );

				}

				if ( off > 1e-3 ) differing ++;

			}

		}

		faceDiffs.push( differing );

	}

	result.faceDiffs = faceDiffs;
	// The projection alone at an odd size too (its middle row and column are their own mirror images).
	const odd = new WebGPUProbeCapturer( renderer, { resolution: 15 } );
	await odd.capture( room(), PROBES.slice( 3, 6 ), shOne );
	result.projectionErrorOdd = worstError( shOne, projectCubeMapToSH( await readFaces( odd, 15 ), 15 ) );
	odd.dispose();
	glTarget.dispose();
	capturer.dispose();
	result.webglL00 = volumeGL.sh[ 0 ];
	gl.dispose();
	// Panoramas (random HDR texels), against the CPU projection of the same texels, at a power-of-two
	// and an odd size.
	result.panoramaError = 0;
	for ( const [ width, height ] of [ [ 64, 32 ], [ 100, 49 ] ] ) {

		const pixels = new Float32Array( width * height * 4 );
		let seed = 7;
		// Random texels over a ramp up the panorama and along it, so a flipped row or column order shows.
		for ( let i = 0; i < pixels.length; i ++ ) {

			seed = ( seed * 16807 ) % 2147483647;
			const texel = i >> 2, row = Math.floor( texel / width ), column = texel % width;
			pixels[ i ] = seed / 2147483647 + 2 * row / height + column / width;

		}

		const panorama = new THREE.DataTexture( pixels, width, height, THREE.RGBAFormat, THREE.FloatType );
		panorama.minFilter = panorama.magFilter = THREE.NearestFilter;
		panorama.needsUpdate = true;
		const cpu = projectEquirectToSH( pixels, width, height, { rowOrder: 'bottom-up' } );
		const gpu = await projectEquirectToSHGPU( renderer, panorama );
		result.panoramaError = Math.max( result.panoramaError as number, worstError( gpu, cpu ) );
		panorama.dispose();

	}

	// Create → capture → dispose: what the renderer holds after a cycle is what it held before.
	const memory = () => {

		const m = renderer.info.memory as unknown as Record<string, number>;
		return { textures: m.textures, renderTargets: m.renderTargets, storageAttributes: m.storageAttributes, attributes: m.attributes };

	};

	const scene = room();
	const cycle = async () => {

		const volume = new LightProbeVolume( { positions: PROBES } );
		await volume.capture( renderer, scene, { resolution: 8 } );
		volume.dispose();

	};

	// A view of the room drawn before and after the captures: the faces' mirrored front faces (WebGPU
	// backend) must not leak into ordinary draws of the same meshes and materials.
	const view = new RenderTarget( 32, 32 );
	const viewCamera = new THREE.PerspectiveCamera( 70, 1, 0.05, 100 );
	viewCamera.position.set( 0.5, 0.2, 0.3 );
	viewCamera.lookAt( 3, 0, - 2 );
	const drawView = async () => {

		renderer.setRenderTarget( view );
		renderer.render( scene, viewCamera );
		renderer.setRenderTarget( null );
		return await renderer.readRenderTargetPixelsAsync( view, 0, 0, 32, 32 ) as Uint8Array;

	};

	const viewBefore = await drawView();
	await cycle(); // the scene's own geometries and textures come to the GPU once
	const before = memory();
	for ( let i = 0; i < 3; i ++ ) await cycle();
	result.memoryBefore = before;
	result.memoryAfter = memory();
	const viewAfter = await drawView();
	view.dispose();
	result.viewUnchanged = viewBefore.length === 4 * 32 * 32 && viewBefore.every( ( value, i ) => value === viewAfter[ i ] );
	// Red, green and grey in the view: the box and the (back-sided) walls were drawn.
	result.viewColours = [ ...new Set( Array.from( { length: 32 * 32 }, ( _, i ) => viewBefore.slice( 4 * i, 4 * i + 3 ).join() ) ) ];
	let ownDeterminants = 0;
	scene.traverse( ( object ) => { if ( Object.prototype.hasOwnProperty.call( object.matrixWorld, 'determinant' ) ) ownDeterminants ++; } );
	result.ownDeterminants = ownDeterminants;

	// A shadow-casting light: its map is drawn inside the first face's draw, from the light's camera. The
	// mirrored front face of the WebGPU backend's face cameras must not reach that nested draw.
	const lit = room();
	const sun = new THREE.DirectionalLight( 0xffffff, 2 );
	sun.position.set( 2, 3, 1 );
	sun.castShadow = true;
	lit.add( sun );
	const caster = lit.children[ 1 ] as THREE.Mesh;
	caster.castShadow = true;
	const walls = lit.children[ 0 ] as THREE.Mesh;
	walls.material = new THREE.MeshStandardMaterial( { color: 0x8090a0, side: THREE.BackSide } );
	walls.receiveShadow = true;
	const draws = { face: 0, faceFlipped: 0, other: 0, otherFlipped: 0 };
	const shadowCapturer = new WebGPUProbeCapturer( renderer, { resolution: 8 } );
	const faceCameras: unknown[] = shadowCapturer.faces ? [ ...shadowCapturer.faces.cameras ] : [ ...shadowCapturer.cubeCamera!.children ];
	caster.onBeforeRender = ( _renderer, _scene, camera ) => {

		const face = faceCameras.includes( camera ), flipped = caster.matrixWorld.determinantAffine() < 0;
		if ( face ) { draws.face ++; if ( flipped ) draws.faceFlipped ++; } else { draws.other ++; if ( flipped ) draws.otherFlipped ++; }

	};

	renderer.shadowMap.enabled = true;
	await shadowCapturer.capture( lit, [ 0, 0, 0 ], new Float32Array( 27 ) );
	renderer.shadowMap.enabled = false;
	caster.onBeforeRender = () => {};
	shadowCapturer.dispose();
	result.shadowDraws = draws;

	// A double-sided lit plane seen from its back, lit from that side: `frontFacing` (hence the normal) must be
	// WebGL's in the face cameras' draws, or the plane goes dark. Against WebGLRenderer (other shader code:
	// close, not equal).
	const backLit = new THREE.Scene();
	const plane = new THREE.Mesh( new THREE.PlaneGeometry( 6, 6 ), new THREE.MeshLambertMaterial( { color: 0xffffff, side: THREE.DoubleSide } ) );
	plane.position.set( 0, 0, - 1 );
	plane.rotation.y = Math.PI; // its front faces −Z: the probe at the origin, and the light from +Z, see its back
	backLit.add( plane );
	const lamp = new THREE.DirectionalLight( 0xffffff, 1 );
	lamp.position.set( 0, 0, 1 );
	backLit.add( lamp );
	const backGL = new LightProbeVolume( { positions: [ 0, 0, 0 ] } );
	const glAgain = new THREE.WebGLRenderer();
	await backGL.capture( glAgain, backLit, { resolution: 8 } );
	glAgain.dispose();
	const backGPU = new LightProbeVolume( { positions: [ 0, 0, 0 ] } );
	await backGPU.capture( renderer, backLit, { resolution: 8 } );
	result.backLitL00 = [ backGPU.sh[ 0 ], backGL.sh[ 0 ] ];
	backGL.dispose();
	backGPU.dispose();

	// A lost device or context in the middle of a capture: the named error, the SH kept.
	const kept = new LightProbeVolume( { positions: PROBES } );
	await kept.capture( renderer, scene, { resolution: 8 } );
	const held = kept.sh.slice();
	const lose = () => {

		if ( backend === 'webgpu' ) ( renderer.backend as unknown as { device: { destroy(): void } } ).device.destroy();
		else ( renderer.backend as unknown as { gl: WebGL2RenderingContext } ).gl.getExtension( 'WEBGL_lose_context' )!.loseContext();

	};

	try {

		await kept.capture( renderer, scene, { resolution: 8, onProgress: ( done ) => { if ( done === 1 ) lose(); } } );
		result.lossError = 'no error';

	} catch ( error ) {

		result.lossError = ( error as Error ).message;

	}

	result.shKept = kept.sh.every( ( value, i ) => value === held[ i ] );
	try {

		await kept.capture( renderer, scene, { resolution: 8 } );
		result.lostError = 'no error';

	} catch ( error ) {

		result.lostError = ( error as Error ).message;

	}

}

run().then( () => {

	( window as unknown as { __result: unknown } ).__result = result;

}, ( error: Error ) => {

	result.error = `${error.message}\n${error.stack}`;
	( window as unknown as { __result: unknown } ).__result = result;

} );
