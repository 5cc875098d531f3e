/**
 * GPU capture on a real GL context (headless-gl, WebGL2): ProbeCapturer / LightProbeVolume.capture
 * (cube camera + SHProjector) and projectEquirectToSHGPU, checked against analytic SH and against
 * the CPU reference projections of the very same texels.
 *
 * Error metric throughout: the largest |GPU − expected| over the 9 coefficients of a channel,
 * divided by that channel's expected L00.
 *
 * Needs an X display for headless-gl: `node scripts/test.mjs test/capture` runs it under xvfb-run.
 */

import * as fs from 'node:fs';
import * as path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { HDRLoader } from 'three/examples/jsm/loaders/HDRLoader.js';
import { LightProbeGenerator } from 'three/examples/jsm/lights/LightProbeGenerator.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { SHProjector } from '../../src/capture/SHProjector.js';
import { projectEquirectToSHGPU } from '../../src/capture/projectEquirectToSHGPU.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { projectCubeMapToSH, projectEquirectToSH, type CubeSolidAngleMode } from '../../src/sh/index.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { analyticSH, assetsDirectory, directionEnvironment, disposeMesh, readCubeFaces, shRadianceGLSL, srgbToLinear } from '../helpers/gpuScenes.js';
import { equirectFrom, evaluateBandLimited, random } from '../sh/helpers.js';

const ctx = await createHeadlessRenderer( 64, 64 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/**
 * f(ω) = Σ c_k Y_k(ω), a different band-limited function per channel. L00 dominates so f > 0
 * everywhere (f ≥ c_0·Y00 − Σ_{k>0} |c_k|·max|Y_k| > 0.1), like real radiance.
 */
const C: number[][] = [
	[ 4.0, 3.0, 2.5 ],
	[ 0.3, - 0.4, 0.1 ],
	[ - 0.5, 0.2, 0.3 ],
	[ 0.4, 0.1, - 0.2 ],
	[ 0.2, - 0.3, 0.15 ],
	[ - 0.25, 0.2, 0.1 ],
	[ 0.35, - 0.1, 0.2 ],
	[ 0.15, 0.25, - 0.15 ],
	[ - 0.3, 0.2, 0.1 ],
];
const TRUTH = analyticSH( C );
const ENVIRONMENT_GLSL = shRadianceGLSL( 'environment', C );

/** The same f plus a sharp feature: a disc of radius ≈ 18° around DISC_AXIS, 20× brighter than f's mean. */
const DISC_AXIS = new THREE.Vector3( 0.6, 0.5, - 0.62 ).normalize();
const SHARP_BODY = /* glsl */`
	float disc = step( 0.95, dot( d, vec3( ${DISC_AXIS.toArray().map( ( v ) => v.toFixed( 8 ) ).join( ', ' )} ) ) );
	gl_FragColor = vec4( environment( d ) + disc * vec3( 20.0, 12.0, 6.0 ), 1.0 );
`;

/** Largest |a_k − b_k| over the 9 coefficients of `channel`, relative to b's L00 of that channel. */
function relativeError( a: ArrayLike<number>, b: ArrayLike<number>, channel: number, offsetA = 0, offsetB = 0 ): number {

	let error = 0;
	for ( let k = 0; k < 9; k ++ ) error = Math.max( error, Math.abs( a[ offsetA + 3 * k + channel ] - b[ offsetB + 3 * k + channel ] ) );
	return error / Math.abs( b[ offsetB + channel ] );

}

function worstRelativeError( a: ArrayLike<number>, b: ArrayLike<number>, offsetA = 0, offsetB = 0 ): number {

	return Math.max( ...[ 0, 1, 2 ].map( ( c ) => relativeError( a, b, c, offsetA, offsetB ) ) );

}

describe.skipIf( ! ctx.renderer )( `GPU probe capture (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;

	afterAll( () => ctx.dispose() );

	describe( 'end to end against analytic SH', () => {

		for ( const [ name, type ] of [ [ 'FloatType', THREE.FloatType ], [ 'HalfFloatType', THREE.HalfFloatType ] ] as const ) {

			it( `ProbeCapturer at 64², ${name}: a shader painting Σ c_k Y_k(ω) in world directions captures to c_k·∫Y_k² (< 1e-3·L00 per channel)`, async () => {

				// Why the expected value is right: the environment is exactly Σ c_k Y_k with three's
				// basis constants, whose projection onto Y_j is c_j·∫Y_j² (the p_k are orthogonal).
				// What is left: the quadrature error at texel centres (≈ 4e-5·L00 at 64², see
				// solidAngleComparison) and, for half floats, rounding to 11 bits (≤ 5e-4 per texel,
				// mostly cancelling). A mirrored axis, a swapped face, a wrong basis constant or a
				// wrong solid angle moves some coefficient by ≥ 0.05·L00.
				const scene = new THREE.Scene();
				const environment = directionEnvironment( 'gl_FragColor = vec4( environment( d ), 1.0 );', ENVIRONMENT_GLSL );
				scene.add( environment );
				const capturer = new ProbeCapturer( renderer, { resolution: 64, type, far: 500 } );
				const sh = await capturer.capture( scene, [ 1, 2, - 0.5 ], new Float32Array( 27 ) );
				capturer.dispose();
				disposeMesh( environment );

				expect( gl.getError() ).toBe( gl.NO_ERROR );
				for ( let c = 0; c < 3; c ++ ) expect( relativeError( sh, TRUTH, c ) ).toBeLessThan( 1e-3 );
				// Not vacuous: every channel has sizeable non-constant coefficients.
				expect( Math.abs( sh[ 3 * 1 + 1 ] ) ).toBeGreaterThan( 0.3 );

			} );

		}

		it( 'LightProbeVolume.capture at 64² (FloatType) gives every probe the same analytic SH, in volume.sh', async () => {

			// The environment depends on direction only, so every probe — wherever it is — sees the
			// same f and must get the same c_k·∫Y_k².
			const scene = new THREE.Scene();
			const environment = directionEnvironment( 'gl_FragColor = vec4( environment( d ), 1.0 );', ENVIRONMENT_GLSL );
			scene.add( environment );
			const volume = new LightProbeVolume( { positions: [ 0, 0, 0, 3, 0, 0, 0, 3, 0, 0, 0, 3, - 2, - 1, 4 ] } );
			const returned = await volume.capture( renderer, scene, { resolution: 64, type: THREE.FloatType, far: 500 } );
			disposeMesh( environment );

			expect( returned ).toBe( volume );
			for ( let p = 0; p < volume.count; p ++ ) expect( worstRelativeError( volume.sh, TRUTH, 27 * p ) ).toBeLessThan( 1e-3 );

		} );

	} );

	describe( 'GPU projection equals the CPU projection of the same read-back cube map', () => {

		const cases: [ number, CubeSolidAngleMode, THREE.TextureDataType ][] = [
			[ 1, 'exact', THREE.FloatType ], [ 8, 'exact', THREE.FloatType ], [ 32, 'exact', THREE.FloatType ],
			[ 100, 'exact', THREE.FloatType ], [ 128, 'exact', THREE.FloatType ], [ 37, 'exact', THREE.FloatType ],
			[ 8, 'paper', THREE.FloatType ], [ 32, 'paper', THREE.FloatType ], [ 100, 'paper', THREE.FloatType ],
			[ 32, 'exact', THREE.HalfFloatType ],
			// From 128² on the faces are copied to 2D textures first (SHProjector.add of a render target).
			[ 128, 'exact', THREE.HalfFloatType ], [ 131, 'exact', THREE.FloatType ], [ 256, 'paper', THREE.HalfFloatType ],
		];

		for ( const [ size, solidAngle, type ] of cases ) {

			it( `${size}², solidAngle '${solidAngle}', ${type === THREE.FloatType ? 'float' : 'half float'}: environment with a bright disc, GPU vs projectCubeMapToSH( faces ) < 1e-5·L00`, async () => {

				// Why: the GPU and the CPU integrate the very same texels with the same weights
				// (texel-centre directions, the same solid-angle formula), so only float32 summation
				// order separates them (≈ 1e-7). A sharp disc makes any texel-mapping, mirror-image or
				// block / tile-boundary error visible (a 37² or 100² face leaves a partial last tile;
				// 1² and 37² have a middle row and column that are their own mirror images), which a
				// smooth environment would average away.
				const scene = new THREE.Scene();
				const environment = directionEnvironment( SHARP_BODY, ENVIRONMENT_GLSL );
				scene.add( environment );
				const capturer = new ProbeCapturer( renderer, { resolution: size, type, far: 500, solidAngle } );
				const gpu = await capturer.capture( scene, [ - 0.3, 0.7, 1.1 ], new Float32Array( 27 ) );
				// Up to 64² the capture renders into a 2D face atlas, larger faces into the cube render
				// target; three's own cube render at the same position is the reference, so this also
				// checks that the atlas faces are those texels.
				capturer.cubeCamera.update( renderer, scene );
				const faces = readCubeFaces( renderer, capturer.cubeRenderTarget );
				capturer.dispose();
				disposeMesh( environment );

				const cpu = projectCubeMapToSH( faces, size, { solidAngle } );
				expect( worstRelativeError( gpu, cpu ) ).toBeLessThan( 1e-5 );
				// The disc is really in the capture: its direction dominates the band-1 red term.
				if ( size >= 8 ) expect( cpu[ 3 * 3 ] * DISC_AXIS.x ).toBeGreaterThan( 0 );

			} );

		}

	} );

	it( 'solidAngle \'paper\' equals three\'s LightProbeGenerator.fromCubeRenderTarget on the same half-float cube maps (< 1e-5·L00) at 8², 37², 64²', async () => {

		// Why: LightProbeGenerator weights each texel by 4/|r|³ and rescales the sum to 4π — the
		// paper's rule with its normalisation — with its own texel → direction table and its own
		// half-float decode, on the CPU; the GPU projection with 'paper' weights reads the same half
		// texels, so only float32 summation separates them. The bright disc makes a texel landing on
		// a wrong mirror image or face show. headless-gl cannot bind PIXEL_PACK_BUFFER, so three's
		// async read-back is routed through the synchronous one (as in test/sh/cubeFaceMapping).
		const asyncReadback = renderer.readRenderTargetPixelsAsync;
		renderer.readRenderTargetPixelsAsync = ( (
			rt: THREE.WebGLRenderTarget, x: number, y: number, w: number, h: number, buffer: THREE.TypedArray, face?: number,
		) => {

			renderer.readRenderTargetPixels( rt, x, y, w, h, buffer, face );
			return Promise.resolve( buffer );

		} ) as typeof renderer.readRenderTargetPixelsAsync;
		const scene = new THREE.Scene();
		const environment = directionEnvironment( SHARP_BODY, ENVIRONMENT_GLSL );
		scene.add( environment );
		try {

			for ( const size of [ 8, 37, 64 ] ) {

				const capturer = new ProbeCapturer( renderer, { resolution: size, far: 500, solidAngle: 'paper' } );
				const gpu = await capturer.capture( scene, [ 0.4, - 0.2, 0.3 ], new Float32Array( 27 ) );
				capturer.cubeCamera.update( renderer, scene ); // three's cube render at the capture's position
				const theirs = ( await LightProbeGenerator.fromCubeRenderTarget( renderer, capturer.cubeRenderTarget ) ).sh.toArray();
				capturer.dispose();
				expect( worstRelativeError( gpu, theirs ), `${size}²` ).toBeLessThan( 1e-5 );
				expect( Math.abs( theirs[ 3 * 3 ] ), `${size}²: the disc's band-1 term is there` ).toBeGreaterThan( 0.05 * theirs[ 0 ] );

			}

		} finally {

			renderer.readRenderTargetPixelsAsync = asyncReadback;
			disposeMesh( environment );

		}

	} );

	it( 'batching: 2049 probes at 16² (batch capacity 2048) each get their own SH, in order', async () => {

		// The radiance seen by a probe is (1 + p.x, 1 + p.y, 2) in every direction (the shader
		// reads the cube camera's position), so probe i must get L00 = 4π·Y00·(1 + x_i, 1 + y_i, 2)
		// — exact up to float32 rounding because the exact texel solid angles sum to 4π — and
		// nothing in the other coefficients. Probes 0..2047 fill the first batch, 2048 the second:
		// an offset or ordering mistake between batches gives a probe its neighbour's (x, y).
		const size = 16;
		const capacity = SHProjector.batchCapacity( size );
		const count = capacity + 1;
		const positions = new Float32Array( 3 * count );
		for ( let i = 0; i < count; i ++ ) {

			positions[ 3 * i ] = ( i % 64 ) * 0.1;
			positions[ 3 * i + 1 ] = Math.floor( i / 64 ) * 0.1;
			positions[ 3 * i + 2 ] = - 1;

		}

		const scene = new THREE.Scene();
		const environment = directionEnvironment( 'gl_FragColor = vec4( 1.0 + probe.x, 1.0 + probe.y, 2.0, 1.0 );', '', 200 );
		scene.add( environment );
		const capturer = new ProbeCapturer( renderer, { resolution: size, type: THREE.FloatType, far: 1000 } );
		const target = new Float32Array( 27 * ( count + 1 ) ).fill( - 7 );
		await capturer.capture( scene, positions, target, {}, 27 ); // also: the offset argument
		capturer.dispose();
		disposeMesh( environment );

		expect( capacity ).toBe( 2048 );
		for ( let i = 0; i < 27; i ++ ) expect( target[ i ] ).toBe( - 7 ); // before the offset: untouched
		const unit = 4 * Math.PI * 0.282095;
		let worst = 0, worstProbe = - 1;
		for ( let i = 0; i < count; i ++ ) {

			const o = 27 * ( i + 1 );
			const expected = [ 1 + positions[ 3 * i ], 1 + positions[ 3 * i + 1 ], 2 ].map( ( v ) => v * unit );
			for ( let c = 0; c < 3; c ++ ) {

				const error = Math.abs( target[ o + c ] - expected[ c ] ) / expected[ c ];
				if ( error > worst ) { worst = error; worstProbe = i; }

			}

			for ( let k = 3; k < 27; k ++ ) {

				const error = Math.abs( target[ o + k ] ) / expected[ 0 ];
				if ( error > worst ) { worst = error; worstProbe = i; }

			}

		}

		expect( worst, `worst probe ${worstProbe}` ).toBeLessThan( 1e-5 );

	} );

	it( 'SHProjector used directly: batches of different sizes and counts on one projector keep probes apart, added one by one and in arrays of up to 8 textures or render targets', () => {

		// begin/add/finish four times on one projector (targets reused or rebuilt in between), each
		// source a cube map of constant colour (i + 1, 2(i + 1), 0.5): L00 = 4π·Y00·colour. The
		// sources go in as single textures and as arrays of 1..8 textures or render targets (one
		// draw each where the faces are small), in chunks whose
		// sizes do not divide the batch, so a wrong row offset or sampler slot gives a probe its
		// neighbour's colour.
		const projector = new SHProjector( renderer );
		const unit = 4 * Math.PI * 0.282095;
		const scene = new THREE.Scene();
		const results: Float32Array[] = [];
		const chunks = [ 1, 3, 8, 0, 2, 5, 8, 7 ]; // 0: one single texture, not an array
		for ( const [ size, count ] of [ [ 64, 5 ], [ 16, 40 ], [ 7, 23 ], [ 129, 6 ] ] ) {

			projector.begin( 'cube', size, count );
			const cubes: THREE.WebGLCubeRenderTarget[] = [];
			for ( let i = 0; i < count; i ++ ) {

				// A background colour is drawn in linear working space into a float target, so
				// every texel holds exactly this colour.
				const cube = new THREE.WebGLCubeRenderTarget( size, { type: THREE.FloatType, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false } );
				scene.background = new THREE.Color( i + 1, 2 * ( i + 1 ), 0.5 );
				new THREE.CubeCamera( 0.1, 10, cube ).update( renderer, scene );
				cubes.push( cube );

			}

			for ( let i = 0, c = 0; i < count; c ++ ) {

				const chunk = Math.min( chunks[ c % chunks.length ], count - i );
				// Odd chunks as render targets (from 128² on their faces are copied to 2D textures).
				if ( chunk === 0 ) projector.add( cubes[ i ++ ].texture );
				else if ( c % 2 === 1 ) { projector.add( cubes.slice( i, i + chunk ) ); i += chunk; }
				else { projector.add( cubes.slice( i, i + chunk ).map( ( cube ) => cube.texture ) ); i += chunk; }

			}

			results.push( projector.finish( new Float32Array( 27 * count ) ) );
			for ( const cube of cubes ) cube.dispose();

		}

		projector.dispose();
		for ( const sh of results ) {

			for ( let i = 0; i < sh.length / 27; i ++ ) {

				const expected = [ i + 1, 2 * ( i + 1 ), 0.5 ];
				for ( let c = 0; c < 3; c ++ ) expect( Math.abs( sh[ 27 * i + c ] / unit / expected[ c ] - 1 ) ).toBeLessThan( 1e-5 );
				for ( let k = 3; k < 27; k ++ ) expect( Math.abs( sh[ 27 * i + k ] ) ).toBeLessThan( 1e-6 * unit * expected[ 1 ] );

			}

		}

	} );

	describe( 'what the capture sees: exclude, filter, layers, registered objects; progress', () => {

		/** A grey room of constant radiance 0.25 and a red emissive ball 1.2 units from the probes. */
		function makeScene() {

			const scene = new THREE.Scene();
			const environment = directionEnvironment( 'gl_FragColor = vec4( 0.25, 0.25, 0.25, 1.0 );' );
			const ball = new THREE.Mesh( new THREE.SphereGeometry( 0.6, 32, 16 ), new THREE.MeshStandardMaterial( { color: 0x000000, emissive: 0xff0000 } ) );
			ball.position.set( 1.2, 0.4, 0.4 );
			scene.add( environment, ball );
			return {
				scene, environment, ball,
				dispose() { disposeMesh( environment ); disposeMesh( ball ); },
			};

		}

		const positions = [ 0, 0, 0, 0.3, 0, 0, 0, 0.3, 0, 0, 0, 0.3 ];
		const settings = { resolution: 32, type: THREE.FloatType, far: 500 };

		it( 'an object registered with volume.add is not seen by volume.capture, and is visible again afterwards', async () => {

			// Reference "without": the same capture with the ball taken out of the scene. "With":
			// the ball seen (red L00 well above the grey room's 4π·Y00·0.25 = 0.886).
			const { scene, ball, dispose } = makeScene();
			const volume = new LightProbeVolume( { positions } );
			await volume.capture( renderer, scene, settings );
			const seen = volume.sh.slice();

			volume.add( ball );
			await volume.capture( renderer, scene, settings );
			const excluded = volume.sh.slice();
			expect( ball.visible ).toBe( true );

			scene.remove( ball );
			await volume.capture( renderer, scene, settings );
			const without = volume.sh.slice();
			scene.add( ball );

			volume.remove( ball );
			await volume.capture( renderer, scene, settings );
			const seenAgain = volume.sh.slice();
			volume.dispose();
			dispose();

			expect( seen[ 0 ] - without[ 0 ] ).toBeGreaterThan( 0.05 * without[ 0 ] ); // the ball matters
			for ( let i = 0; i < seen.length; i ++ ) {

				expect( excluded[ i ] ).toBeCloseTo( without[ i ], 6 );
				expect( seenAgain[ i ] ).toBeCloseTo( seen[ i ], 6 );

			}

		} );

		it( 'ProbeCapturer: exclude, filter and layers each hide the ball; hidden objects are shown again, hidden-before stays hidden; camera layers restored', async () => {

			const { scene, environment, ball, dispose } = makeScene();
			const capturer = new ProbeCapturer( renderer, settings );
			const capture = async ( options = {} ) => ( await capturer.capture( scene, positions, new Float32Array( 27 * 4 ), options ) ).slice();

			const seen = await capture();
			ball.visible = false;
			const reference = await capture(); // the ball hidden by the user
			ball.visible = true;

			const byExclude = await capture( { exclude: [ ball ] } );
			expect( ball.visible ).toBe( true );
			const byFilter = await capture( { filter: ( object: THREE.Object3D ) => object !== ball } );
			expect( ball.visible ).toBe( true );

			// Layers: the ball on layer 1 only; the cube camera restricted to layer 0 must miss it,
			// restricted to layer 1 must see only it (the room is on layer 0).
			const masksBefore = capturer.cubeCamera.children.map( ( camera ) => camera.layers.mask );
			ball.layers.set( 1 );
			const layer0 = new THREE.Layers();
			const byLayers = await capture( { layers: layer0 } );
			const layer1 = new THREE.Layers();
			layer1.set( 1 );
			const onlyBall = await capture( { layers: layer1 } );
			expect( capturer.cubeCamera.children.map( ( camera ) => camera.layers.mask ) ).toEqual( masksBefore );
			ball.layers.set( 0 );

			// An object the user had hidden stays hidden after a capture that excludes it.
			ball.visible = false;
			await capture( { exclude: [ ball ], filter: () => true } );
			expect( ball.visible ).toBe( false );
			ball.visible = true;
			expect( environment.visible ).toBe( true );

			capturer.dispose();
			dispose();

			expect( seen[ 0 ] - reference[ 0 ] ).toBeGreaterThan( 0.05 * reference[ 0 ] );
			for ( let i = 0; i < reference.length; i ++ ) {

				expect( byExclude[ i ] ).toBeCloseTo( reference[ i ], 6 );
				expect( byFilter[ i ] ).toBeCloseTo( reference[ i ], 6 );
				expect( byLayers[ i ] ).toBeCloseTo( reference[ i ], 6 );

			}

			// Only the ball: red light from the ball, and no grey room in green or blue.
			expect( onlyBall[ 0 ] ).toBeGreaterThan( 0.05 );
			expect( Math.abs( onlyBall[ 1 ] ) ).toBeLessThan( 1e-6 );
			expect( Math.abs( onlyBall[ 2 ] ) ).toBeLessThan( 1e-6 );

		} );

		it( 'exclusion survives the capture\'s yields: 300 probes (long enough to yield to the event loop) never see the excluded ball, and the ball is visible during a yield', async () => {

			// ProbeCapturer.capture shows hidden objects and awaits a task every ~30 ms (so a page
			// can paint a progress bar), then hides them again. Each probe's SH must equal the
			// capture of the scene without the ball; a timer queued before the capture runs in
			// the first yield (some probes done, not all) and sees the ball shown.
			const { scene, ball, dispose } = makeScene();
			const many: number[] = [];
			for ( let i = 0; i < 300; i ++ ) many.push( 0.3 * Math.cos( i ), 0.01 * i - 1.5, 0.3 * Math.sin( i ) - 0.5 );
			const capturer = new ProbeCapturer( renderer, { resolution: 32, type: THREE.FloatType, far: 500 } );
			let visibleInYield: boolean | null = null, done = 0, doneAtYield = - 1;
			setTimeout( () => { visibleInYield = ball.visible; doneAtYield = done; }, 0 );
			const excluded = await capturer.capture( scene, many, new Float32Array( 27 * 300 ), { exclude: [ ball ], onProgress: ( n ) => { done = n; } } );
			scene.remove( ball );
			const reference = await capturer.capture( scene, many, new Float32Array( 27 * 300 ) );
			capturer.dispose();
			dispose();

			expect( doneAtYield ).toBeGreaterThan( 0 );
			expect( doneAtYield ).toBeLessThan( 300 );
			expect( visibleInYield ).toBe( true );
			for ( let i = 0; i < excluded.length; i ++ ) expect( excluded[ i ] ).toBeCloseTo( reference[ i ], 6 );

		} );

		it( 'the capture ignores renderer.toneMapping, toneMappingExposure and outputColorSpace (they apply to the screen only)', async () => {

			// Probes must hold linear scene radiance; a tone-mapped or sRGB-encoded capture would
			// change L00 by tens of percent.
			const scene = new THREE.Scene();
			const environment = directionEnvironment( 'gl_FragColor = vec4( environment( d ), 1.0 );', ENVIRONMENT_GLSL );
			scene.add( environment );
			const capturer = new ProbeCapturer( renderer, { resolution: 32, type: THREE.FloatType, far: 500 } );
			const plain = ( await capturer.capture( scene, [ 0, 0, 0 ], new Float32Array( 27 ) ) ).slice();
			renderer.toneMapping = THREE.ACESFilmicToneMapping;
			renderer.toneMappingExposure = 0.5;
			renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
			const styled = await capturer.capture( scene, [ 0, 0, 0 ], new Float32Array( 27 ) );
			renderer.toneMapping = THREE.NoToneMapping;
			renderer.toneMappingExposure = 1;
			renderer.outputColorSpace = THREE.SRGBColorSpace;
			capturer.dispose();
			disposeMesh( environment );

			for ( let i = 0; i < 27; i ++ ) expect( styled[ i ] ).toBeCloseTo( plain[ i ], 6 );
			expect( worstRelativeError( plain, TRUTH ) ).toBeLessThan( 1e-3 );

		} );

		it( 'onProgress is called once per probe with (done, total), ending at (n, n), for ProbeCapturer and volume.capture', async () => {

			const { scene, dispose } = makeScene();
			const calls: [ number, number ][] = [];
			const capturer = new ProbeCapturer( renderer, { resolution: 8 } );
			await capturer.capture( scene, positions, new Float32Array( 27 * 4 ), { onProgress: ( done, total ) => calls.push( [ done, total ] ) } );
			capturer.dispose();
			expect( calls ).toEqual( [ [ 1, 4 ], [ 2, 4 ], [ 3, 4 ], [ 4, 4 ] ] );

			const volumeCalls: [ number, number ][] = [];
			const volume = new LightProbeVolume( { positions: [ ...positions, 1, 1, 1 ] } );
			await volume.capture( renderer, scene, { resolution: 8, onProgress: ( done, total ) => volumeCalls.push( [ done, total ] ) } );
			dispose();
			expect( volumeCalls ).toEqual( [ [ 1, 5 ], [ 2, 5 ], [ 3, 5 ], [ 4, 5 ], [ 5, 5 ] ] );

		} );

		it( 'a capture leaves the renderer as it found it: render target, autoClear, clear colour', async () => {

			const { scene, dispose } = makeScene();
			const own = new THREE.WebGLRenderTarget( 4, 4 );
			renderer.setRenderTarget( own );
			renderer.autoClear = false;
			renderer.setClearColor( 0x336699, 0.5 );
			const capturer = new ProbeCapturer( renderer, { resolution: 8 } );
			await capturer.capture( scene, positions, new Float32Array( 27 * 4 ) );
			capturer.dispose();

			expect( renderer.getRenderTarget() ).toBe( own );
			expect( renderer.autoClear ).toBe( false );
			expect( renderer.getClearColor( new THREE.Color() ).getHex() ).toBe( 0x336699 );
			expect( renderer.getClearAlpha() ).toBe( 0.5 );
			renderer.setRenderTarget( null );
			renderer.autoClear = true;
			renderer.setClearColor( 0x000000, 0 );
			own.dispose();
			dispose();

		} );

	} );

	describe( 'projectEquirectToSHGPU', () => {

		/** A sharp-featured panorama, top row = up: band-limited base plus a bright rectangle (the "sun"). */
		function hdrPanorama( width: number, height: number ): Float32Array {

			const base = [ 1.0, 0.3, - 0.5, 0.4, 0.2, - 0.25, 0.35, 0.15, - 0.3 ];
			const pixels = equirectFrom( width, height, ( x, y, z ) => 2 + evaluateBandLimited( base, x, y, z ), [ 1, 0.7, 0.4 ] );
			const next = random( 7 );
			for ( let p = 0; p < width * height; p ++ ) for ( let c = 0; c < 3; c ++ ) pixels[ 4 * p + c ] *= 0.9 + 0.2 * next();
			// A 50×-bright patch off the axes, a few pixels across.
			for ( let row = Math.floor( height * 0.2 ); row < Math.floor( height * 0.27 ); row ++ ) {

				for ( let column = Math.floor( width * 0.61 ); column < Math.floor( width * 0.66 ); column ++ ) {

					const p = 4 * ( row * width + column );
					pixels[ p ] = 100; pixels[ p + 1 ] = 80; pixels[ p + 2 ] = 40;

				}

			}

			return pixels;

		}

		function flipRows<T extends Float32Array | Uint16Array | Uint8Array>( pixels: T, width: number, height: number ): T {

			const flipped = pixels.slice() as T;
			const row = 4 * width;
			for ( let y = 0; y < height; y ++ ) flipped.set( pixels.subarray( y * row, ( y + 1 ) * row ), ( height - 1 - y ) * row );
			return flipped;

		}

		for ( const [ width, height ] of [ [ 256, 128 ], [ 100, 50 ], [ 64, 48 ] ] ) {

			it( `float RGBA DataTexture ${width}×${height} with flipY = true (as HDRLoader leaves it, top row first) equals projectEquirectToSH( top-down rows ) < 1e-4·L00`, () => {

				// three's HDRLoader hands the file's rows top row first and sets flipY = true, so
				// the upload flips them and texel row 0 is the bottom (nadir) — what the shader
				// assumes; projectEquirectToSH reads its first row as the top. Both then weight the
				// same pixels with the same exact row solid angles: only float32 summation differs.
				// A latitude mirror would flip the sign of the band-1 y term (≈ 0.1·L00 here).
				const topDown = hdrPanorama( width, height );
				const texture = new THREE.DataTexture( topDown, width, height, THREE.RGBAFormat, THREE.FloatType );
				texture.flipY = true;
				texture.minFilter = texture.magFilter = THREE.LinearFilter;
				texture.generateMipmaps = false;
				texture.colorSpace = THREE.LinearSRGBColorSpace;
				texture.needsUpdate = true;
				const gpu = projectEquirectToSHGPU( renderer, texture );

				// The same data with flipY = false is bottom-up for the GPU: uploaded unflipped.
				const bottomUp = flipRows( topDown, width, height );
				const plain = new THREE.DataTexture( bottomUp, width, height, THREE.RGBAFormat, THREE.FloatType );
				plain.needsUpdate = true;
				const gpuPlain = projectEquirectToSHGPU( renderer, plain, new Float32Array( 27 ) );
				texture.dispose();
				plain.dispose();

				const cpu = projectEquirectToSH( topDown, width, height );
				expect( worstRelativeError( gpu, cpu ) ).toBeLessThan( 1e-4 );
				expect( worstRelativeError( gpuPlain, cpu ) ).toBeLessThan( 1e-4 );
				expect( Math.abs( cpu[ 3 ] ) ).toBeGreaterThan( 0.05 * cpu[ 0 ] ); // band-1 y is not small
				expect( gl.getError() ).toBe( gl.NO_ERROR );

			} );

		}

		/**
		 * What this GPU returns for each sRGB byte: a 256×1 SRGB8_ALPHA8 texture drawn texel for
		 * texel (MeshBasicMaterial, nearest filtering) into a 256×1 float target, read back.
		 */
		function measureSRGBDecode(): Float32Array {

			const bytes = new Uint8Array( 256 * 4 );
			for ( let v = 0; v < 256; v ++ ) bytes.fill( v, 4 * v, 4 * v + 3 ), bytes[ 4 * v + 3 ] = 255;
			const texture = new THREE.DataTexture( bytes, 256, 1 );
			texture.colorSpace = THREE.SRGBColorSpace;
			texture.needsUpdate = true;
			const target = new THREE.WebGLRenderTarget( 256, 1, { type: THREE.FloatType, depthBuffer: false } );
			const quad = new THREE.Mesh( new THREE.PlaneGeometry( 2, 2 ), new THREE.MeshBasicMaterial( { map: texture } ) );
			quad.position.z = - 1; // in front of the default OrthographicCamera's near plane
			const scene = new THREE.Scene();
			scene.add( quad );
			renderer.setRenderTarget( target );
			renderer.render( scene, new THREE.OrthographicCamera() );
			renderer.setRenderTarget( null );
			const pixels = new Float32Array( 256 * 4 );
			renderer.readRenderTargetPixels( target, 0, 0, 256, 1, pixels );
			disposeMesh( quad );
			texture.dispose();
			target.dispose();
			return Float32Array.from( { length: 256 }, ( _, v ) => pixels[ 4 * v ] );

		}

		it( 'LDR UnsignedByte DataTexture with colorSpace = SRGBColorSpace: the GPU decodes sRGB; the SH equal the CPU projection of the decoded values (< 1e-4·L00 with this GPU\'s decode, < 1e-2 with the exact sRGB curve)', () => {

			// An SRGB8_ALPHA8 texture returns linear values to the shader, so the SH must be those
			// of decode( byte ). Mesa llvmpipe (headless-gl under Xvfb) decodes sRGB with an
			// approximation (up to 2.5 % off near black, 0.7 % at mid grey), so the exact curve
			// only agrees to ≈ 4e-3·L00 here; with the decode measured on this very GPU the
			// projection itself must agree to float precision. The undecoded bytes / 255 would be
			// off by ≫ 1e-2 (checked too, so the test can fail).
			const width = 128, height = 64;
			const next = random( 11 );
			const bottomUp = new Uint8Array( width * height * 4 );
			for ( let row = 0; row < height; row ++ ) {

				for ( let column = 0; column < width; column ++ ) {

					const p = 4 * ( row * width + column );
					const sky = row / height; // brighter towards the top (row height − 1 is the zenith here)
					bottomUp[ p ] = Math.round( 255 * Math.min( 1, 0.2 + 0.5 * sky + 0.2 * next() ) );
					bottomUp[ p + 1 ] = Math.round( 255 * Math.min( 1, 0.1 + 0.6 * sky * ( column / width ) + 0.1 * next() ) );
					bottomUp[ p + 2 ] = Math.round( 255 * Math.min( 1, 0.3 + 0.7 * sky * sky ) );
					bottomUp[ p + 3 ] = 255;

				}

			}

			const texture = new THREE.DataTexture( bottomUp, width, height, THREE.RGBAFormat, THREE.UnsignedByteType );
			texture.colorSpace = THREE.SRGBColorSpace;
			texture.needsUpdate = true;
			const gpu = projectEquirectToSHGPU( renderer, texture );
			texture.dispose();

			const table = measureSRGBDecode();
			const exact = new Float32Array( bottomUp.length );
			const measured = new Float32Array( bottomUp.length );
			const raw = new Float32Array( bottomUp.length );
			for ( let i = 0; i < bottomUp.length; i ++ ) {

				raw[ i ] = bottomUp[ i ] / 255;
				exact[ i ] = srgbToLinear( raw[ i ] );
				measured[ i ] = table[ bottomUp[ i ] ];

			}

			const options = { rowOrder: 'bottom-up' } as const;
			const cpuExact = projectEquirectToSH( exact, width, height, options );
			expect( worstRelativeError( gpu, projectEquirectToSH( measured, width, height, options ) ) ).toBeLessThan( 1e-4 );
			expect( worstRelativeError( gpu, cpuExact ) ).toBeLessThan( 1e-2 );
			expect( worstRelativeError( projectEquirectToSH( raw, width, height, options ), cpuExact ) ).toBeGreaterThan( 5e-2 );
			// The decode this GPU applies is sRGB (not identity, not gamma 2.2 off by more than 3 %).
			for ( let v = 16; v < 256; v ++ ) expect( Math.abs( table[ v ] / srgbToLinear( v / 255 ) - 1 ), `byte ${v}` ).toBeLessThan( 0.03 );

		} );

		it( 'headless-gl limitation: a HalfFloat RGBA DataTexture with flipY = true fails to upload (INVALID_OPERATION, texture stays black) — the real-HDR test below pre-flips half-float rows instead', () => {

			// node_modules/gl/src/native/webgl.cc, WebGLRenderingContext::unpackPixels: any type
			// other than UNSIGNED_BYTE/FLOAT gets pixelSize = 2 regardless of format, so the
			// flipped copy of an RGBA HALF_FLOAT image is a quarter of its size and the robust
			// texSubImage2D rejects it. Browsers flip correctly. When this test fails, headless-gl
			// has been fixed: drop the workaround in the HDR test.
			const data = new Uint16Array( 8 * 4 * 4 ).fill( THREE.DataUtils.toHalfFloat( 1 ) );
			const texture = new THREE.DataTexture( data, 8, 4, THREE.RGBAFormat, THREE.HalfFloatType );
			texture.flipY = true;
			texture.needsUpdate = true;
			gl.getError();
			const sh = projectEquirectToSHGPU( renderer, texture );
			expect( gl.getError() ).toBe( gl.INVALID_OPERATION );
			expect( sh[ 0 ] ).toBe( 0 );
			texture.flipY = false;
			texture.needsUpdate = true;
			expect( projectEquirectToSHGPU( renderer, texture )[ 0 ] ).toBeCloseTo( 4 * Math.PI * 0.282095, 5 );
			texture.dispose();

		} );

		const assets = assetsDirectory();
		const panoramaDirectory = assets ? path.join( assets, 'panoramas' ) : null;
		const hdrFiles = panoramaDirectory && fs.existsSync( panoramaDirectory ) ? fs.readdirSync( panoramaDirectory ).filter( ( f ) => f.endsWith( '.hdr' ) ).sort() : [];
		const how = 'put potsdamer_platz_1k.hdr and venice_sunset_1k.hdr (Poly Haven) in ../shared/assets/panoramas/ or set CAPTURE_LIGHTING_ASSETS to a folder with panoramas/*.hdr';

		it.skipIf( hdrFiles.length === 0 )( `real HDR panoramas through three's HDRLoader (float and half float): GPU equals CPU < 1e-4·L00${hdrFiles.length === 0 ? ` — SKIPPED: no panoramas found; ${how}` : ` (${hdrFiles.join( ', ' )})`}`, () => {

			// HDRLoader.createDataTexture is exactly what HDRLoader.load does with the file (Node's
			// fetch cannot read file: URLs): data rows top row first, flipY = true. The CPU gets
			// the same values (half floats decoded) with the default top-down row order, so only
			// float32 summation order separates the two. A latitude flip would negate the band-1
			// y coefficients (≈ 0.9·L00 for these outdoor panoramas: bright sky above).
			for ( const file of hdrFiles ) {

				const buffer = fs.readFileSync( path.join( panoramaDirectory as string, file ) );
				const arrayBuffer = buffer.buffer.slice( buffer.byteOffset, buffer.byteOffset + buffer.byteLength ) as ArrayBuffer;
				for ( const type of [ THREE.FloatType, THREE.HalfFloatType ] ) {

					const texture = new HDRLoader().setDataType( type ).createDataTexture( arrayBuffer );
					expect( texture.flipY ).toBe( true );
					const { data, width, height } = texture.image as { data: Uint16Array | Float32Array; width: number; height: number };
					const pixels = type === THREE.HalfFloatType ? Float32Array.from( data as Uint16Array, ( h ) => THREE.DataUtils.fromHalfFloat( h ) ) : data as Float32Array;
					if ( type === THREE.HalfFloatType ) {

						// headless-gl cannot flip half floats on upload (see the limitation test
						// above): hand it the rows already flipped, which is what the flip does.
						texture.image.data = flipRows( data as Uint16Array, width, height );
						texture.flipY = false;

					}

					const gpu = projectEquirectToSHGPU( renderer, texture );
					texture.dispose();
					const cpu = projectEquirectToSH( pixels, width, height );
					const label = `${file}, ${type === THREE.HalfFloatType ? 'half' : 'float'}`;
					expect( worstRelativeError( gpu, cpu ), label ).toBeLessThan( 1e-4 );
					expect( cpu[ 3 ], label ).toBeGreaterThan( 0.2 * cpu[ 0 ] ); // more light from above

				}

			}

		} );

	} );

	describe( 'bad input throws an Error naming the function and the argument', () => {

		it( 'ProbeCapturer settings: resolution 0, 300, 1.5; near ≥ far; non-finite near/far; a non-float type', () => {

			for ( const resolution of [ 0, 300, 1.5, Number.NaN ] ) {

				expect( () => new ProbeCapturer( renderer, { resolution } ), `resolution ${resolution}` ).toThrow( /ProbeCapturer.*resolution/ );

			}

			expect( () => new ProbeCapturer( renderer, { near: 10, far: 1 } ) ).toThrow( /ProbeCapturer.*near.*far/ );
			expect( () => new ProbeCapturer( renderer, { near: 1, far: 1 } ) ).toThrow( /ProbeCapturer.*near.*far/ );
			expect( () => new ProbeCapturer( renderer, { near: 0, far: 1 } ) ).toThrow( /ProbeCapturer.*near/ );
			expect( () => new ProbeCapturer( renderer, { near: Number.NaN } ) ).toThrow( /ProbeCapturer.*near/ );
			expect( () => new ProbeCapturer( renderer, { far: Infinity } ) ).toThrow( /ProbeCapturer.*far/ );
			expect( () => new ProbeCapturer( renderer, { type: THREE.UnsignedByteType } ) ).toThrow( /ProbeCapturer.*type/ );

		} );

		it( 'ProbeCapturer.capture: NaN positions, a length not a multiple of 3, a too-small target — and the target is left untouched', async () => {

			const scene = new THREE.Scene();
			const capturer = new ProbeCapturer( renderer, { resolution: 8 } );
			const target = new Float32Array( 54 ).fill( 3 );
			await expect( capturer.capture( scene, [ 0, 0, 0, 1, Number.NaN, 1 ], target ) ).rejects.toThrow( /ProbeCapturer\.capture.*positions\[4\]/ );
			await expect( capturer.capture( scene, [ 0, 0, 0, 1 ], target ) ).rejects.toThrow( /ProbeCapturer\.capture.*positions/ );
			await expect( capturer.capture( scene, [ 0, 0, 0, 1, 1, 1, 2, 2, 2 ], target ) ).rejects.toThrow( /ProbeCapturer\.capture.*target/ );
			await expect( capturer.capture( scene, [ 0, 0, 0 ], target, {}, 30 ) ).rejects.toThrow( /ProbeCapturer\.capture.*target/ );
			capturer.dispose();
			expect( target.every( ( v ) => v === 3 ) ).toBe( true );

		} );

		it( 'LightProbeVolume: NaN positions; volume.capture with resolution 300 or near ≥ far', async () => {

			expect( () => new LightProbeVolume( { positions: [ 0, 0, 0, 1, 0, 0, 0, Number.NaN, 0, 0, 0, 1 ] } ) ).toThrow( /LightProbeVolume.*positions\[7\]/ );
			const volume = new LightProbeVolume( { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] } );
			const scene = new THREE.Scene();
			await expect( volume.capture( renderer, scene, { resolution: 300 } ) ).rejects.toThrow( /resolution/ );
			await expect( volume.capture( renderer, scene, { near: 2, far: 1 } ) ).rejects.toThrow( /near.*far/ );

		} );

		it( 'SHProjector: count above the batch capacity, add() before begin(), add() past the batch, a too-small finish() target', () => {

			const projector = new SHProjector( renderer );
			expect( () => projector.begin( 'cube', 16, SHProjector.batchCapacity( 16 ) + 1 ) ).toThrow( /SHProjector\.begin.*count/ );
			expect( () => projector.begin( 'cube', 0, 1 ) ).toThrow( /SHProjector\.begin.*size/ );
			expect( () => projector.add( new THREE.CubeTexture() ) ).toThrow( /SHProjector\.add.*begin/ );
			const cube = new THREE.WebGLCubeRenderTarget( 4, { type: THREE.FloatType, minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter } );
			projector.begin( 'cube', 4, 1 );
			projector.add( cube.texture );
			expect( () => projector.add( cube.texture ) ).toThrow( /SHProjector\.add.*1 source/ );
			expect( () => projector.finish( new Float32Array( 26 ) ) ).toThrow( /SHProjector\.finish.*target/ );
			cube.dispose();
			projector.dispose();

		} );

		it( 'projectEquirectToSHGPU: a texture with no image yet; a too-small target names projectEquirectToSHGPU and target', () => {

			expect( () => projectEquirectToSHGPU( renderer, new THREE.Texture() ) ).toThrow( /projectEquirectToSHGPU.*image/ );
			const texture = new THREE.DataTexture( new Float32Array( 8 * 4 * 4 ), 8, 4, THREE.RGBAFormat, THREE.FloatType );
			texture.needsUpdate = true;
			// README "Errors": messages name the function called, the argument and the problem.
			// FAILS as of writing: the check happens only in SHProjector.finish, after the GPU
			// work, and its message names SHProjector.finish instead (src/capture/projectEquirectToSHGPU.ts).
			expect( () => projectEquirectToSHGPU( renderer, texture, new Float32Array( 20 ) ) ).toThrow( /^projectEquirectToSHGPU: .*target/ );
			texture.dispose();

		} );

	} );

} );
