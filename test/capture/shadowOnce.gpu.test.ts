/**
 * ProbeCapturer.capture draws the renderer's shadow maps once per call, not once per cube face
 * (headless-gl, WebGL2): the SH are those of a capture with `shadowMap.autoUpdate = false` set by
 * hand and those of the old per-face redraw, the shadow pass runs exactly once per call, and
 * `autoUpdate` / `needsUpdate` are as before the call afterwards — also when the capture throws.
 *
 * Scenes: a closed 4 × 3 × 4 room (walls receive shadows, cast none) with a 2 × 0.1 × 2 slab at
 * 1.6 m that casts a shadow on the floor below it, lit by a shadow-casting PointLight above the
 * slab, or by a DirectionalLight from above. Probes under the slab see its shadow on the floor.
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';

const ctx = await createHeadlessRenderer( 16, 16 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;
const RESOLUTION = 8;
/** Under the slab (in its shadow), beside it, and above it. */
const PROBES = [ 0, 0.6, 0, 0.4, 0.3, - 0.3, 1.5, 0.8, 1.4, - 1.2, 1.2, 0.9, 0.2, 2.4, - 0.2 ];

type LightKind = 'point' | 'directional';

interface ShadowRoom {

	scene: THREE.Scene;
	slab: THREE.Mesh;
	dispose(): void;

}

function createShadowRoom( kind: LightKind ): ShadowRoom {

	const scene = new THREE.Scene();
	const walls = new THREE.MeshStandardMaterial( { color: 0xcccccc, roughness: 1, side: THREE.BackSide } );
	const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 4 ), walls );
	room.position.y = 1.5;
	room.receiveShadow = true;
	const slabMaterial = new THREE.MeshStandardMaterial( { color: 0x886644, roughness: 1 } );
	const slab = new THREE.Mesh( new THREE.BoxGeometry( 2, 0.1, 2 ), slabMaterial );
	slab.position.y = 1.6;
	slab.castShadow = slab.receiveShadow = true;
	scene.add( room, slab );
	if ( kind === 'point' ) {

		const light = new THREE.PointLight( 0xffffff, 20, 0, 2 );
		light.position.set( 0, 2.6, 0 );
		light.castShadow = true;
		light.shadow.mapSize.set( 128, 128 );
		scene.add( light );

	} else {

		const light = new THREE.DirectionalLight( 0xffffff, 3 );
		light.position.set( 0.5, 2.9, 0.3 );
		light.castShadow = true;
		light.shadow.mapSize.set( 256, 256 );
		Object.assign( light.shadow.camera, { left: - 3, right: 3, top: 3, bottom: - 3, near: 0.05, far: 6 } );
		scene.add( light, light.target );

	}

	return {
		scene, slab,
		dispose() {

			room.geometry.dispose(); walls.dispose(); slab.geometry.dispose(); slabMaterial.dispose();
			scene.traverse( ( object ) => ( object as THREE.PointLight ).shadow?.dispose() );

		},
	};

}

/** Largest |a − b| over all 27 floats of every probe, relative to that probe's largest |L00| channel of `b`. */
function relativeDifference( a: Float32Array, b: Float32Array ): number {

	let worst = 0;
	for ( let p = 0; p < a.length / 27; p ++ ) {

		const scale = Math.max( Math.abs( b[ 27 * p ] ), Math.abs( b[ 27 * p + 1 ] ), Math.abs( b[ 27 * p + 2 ] ) );
		for ( let i = 0; i < 27; i ++ ) worst = Math.max( worst, Math.abs( a[ 27 * p + i ] - b[ 27 * p + i ] ) / scale );

	}

	return worst;

}

describe.skipIf( ! ctx.renderer )( `ProbeCapturer: shadow maps drawn once per capture (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;
	const count = PROBES.length / 3;
	renderer.shadowMap.enabled = true;

	// Counts the draws of the shadow pass: three draws shadow casters with renderBufferDirect, no
	// scene, and its depth (directional) or distance (point) material.
	let shadowDraws = 0;
	const renderBufferDirect = renderer.renderBufferDirect;
	renderer.renderBufferDirect = function ( camera, scene, geometry, material, object, group ) {

		const depth = material as THREE.Material & { isMeshDepthMaterial?: boolean, isMeshDistanceMaterial?: boolean };
		if ( scene === null && ( depth.isMeshDepthMaterial || depth.isMeshDistanceMaterial ) ) shadowDraws ++;
		renderBufferDirect.call( this, camera, scene, geometry, material, object, group );

	};

	afterAll( () => ctx.dispose() );

	/** The shadow-pass draws of one shadow map render: one plain frame that redraws the maps. */
	function drawsPerShadowRender( scene: THREE.Scene ): number {

		const camera = new THREE.PerspectiveCamera( 90, 1, 0.05, 20 );
		camera.position.set( 0, 1, 1.5 );
		const before = shadowDraws;
		const { autoUpdate, needsUpdate } = renderer.shadowMap;
		renderer.shadowMap.autoUpdate = true;
		renderer.render( scene, camera );
		renderer.shadowMap.autoUpdate = autoUpdate;
		renderer.shadowMap.needsUpdate = needsUpdate;
		return shadowDraws - before;

	}

	/** The capture path before this change: CubeCamera.update per probe with the renderer's settings, so each face redraws the maps. */
	function capturePerFace( capturer: ProbeCapturer, scene: THREE.Scene ): Float32Array {

		const { cubeCamera, projector } = capturer;
		const out = new Float32Array( 27 * count );
		scene.updateMatrixWorld();
		projector.begin( 'cube', RESOLUTION, count );
		for ( let i = 0; i < count; i ++ ) {

			cubeCamera.position.fromArray( PROBES, 3 * i );
			cubeCamera.updateMatrixWorld();
			cubeCamera.update( renderer, scene );
			projector.add( capturer.cubeRenderTarget.texture );

		}

		return projector.finish( out );

	}

	for ( const kind of [ 'point', 'directional' ] as const ) {

		describe( `${kind} light`, () => {

			it( 'the test scene has shadows that matter: casting off changes L00 of the probe under the slab by > 30 % (measured 56 % point, 61 % directional)', async () => {

				const { scene, slab, dispose } = createShadowRoom( kind );
				const capturer = new ProbeCapturer( renderer, { resolution: RESOLUTION } );
				const shadowed = await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
				slab.castShadow = false;
				const unshadowed = await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
				// Probe 0, under the slab: the floor it looks down on is lit only without the shadow.
				const under = Math.abs( unshadowed[ 0 ] - shadowed[ 0 ] ) / unshadowed[ 0 ];
				expect( under ).toBeGreaterThan( 0.3 );
				expect( shadowed.every( Number.isFinite ) && shadowed[ 0 ] > 0 ).toBe( true );
				capturer.dispose();
				dispose();

			} );

			it( 'the same SH as a capture with autoUpdate = false set by hand (bit for bit) and as the per-face redraw (< 1e-6 of L00)', async () => {

				const { scene, dispose } = createShadowRoom( kind );
				const capturer = new ProbeCapturer( renderer, { resolution: RESOLUTION } );
				renderer.shadowMap.autoUpdate = true;
				const ours = await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
				renderer.shadowMap.autoUpdate = false;
				renderer.shadowMap.needsUpdate = true;
				const byHand = await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
				renderer.shadowMap.autoUpdate = true;
				const before = shadowDraws;
				const perFace = capturePerFace( capturer, scene );
				// The per-face path really redrew the maps for every face: the counter sees shadow draws.
				expect( shadowDraws - before ).toBe( 6 * count * drawsPerShadowRender( scene ) );
				expect( Array.from( ours ) ).toEqual( Array.from( byHand ) );
				expect( relativeDifference( ours, perFace ) ).toBeLessThan( 1e-6 );
				capturer.dispose();
				dispose();

			} );

			it( 'the shadow pass runs once per capture call (also across yields to the page), not once per face', async () => {

				const { scene, dispose } = createShadowRoom( kind );
				const capturer = new ProbeCapturer( renderer, { resolution: RESOLUTION } );
				const perRender = drawsPerShadowRender( scene );
				expect( perRender ).toBeGreaterThan( 0 ); // the slab casts: one draw per face of the map
				renderer.shadowMap.autoUpdate = true;
				let before = shadowDraws;
				await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
				expect( shadowDraws - before ).toBe( perRender );
				// A second call (a role or bounce pass) draws them once more.
				before = shadowDraws;
				await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
				expect( shadowDraws - before ).toBe( perRender );
				// Yields after every probe (onProgress outlasts the 30 ms between yields): still once.
				let yields = 0;
				const slow = () => { const end = performance.now() + 35; while ( performance.now() < end ) { /* wait */ } };
				const onProgress = ( done: number ) => { slow(); if ( done < count ) setTimeout( () => yields ++, 0 ); };
				before = shadowDraws;
				await capturer.capture( scene, PROBES, new Float32Array( 27 * count ), { onProgress } );
				expect( yields ).toBe( count - 1 );
				expect( shadowDraws - before ).toBe( perRender );
				capturer.dispose();
				dispose();

			} );

		} );

	}

	it( 'autoUpdate and needsUpdate are restored for all four combinations; the SH are the same in each', async () => {

		const { scene, dispose } = createShadowRoom( 'point' );
		const capturer = new ProbeCapturer( renderer, { resolution: RESOLUTION } );
		const perRender = drawsPerShadowRender( scene );
		renderer.shadowMap.autoUpdate = true;
		const reference = await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
		for ( const autoUpdate of [ true, false ] ) for ( const needsUpdate of [ true, false ] ) {

			renderer.shadowMap.autoUpdate = autoUpdate;
			renderer.shadowMap.needsUpdate = needsUpdate;
			const before = shadowDraws;
			const sh = await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
			const after = { autoUpdate: renderer.shadowMap.autoUpdate, needsUpdate: renderer.shadowMap.needsUpdate };
			expect( after ).toEqual( { autoUpdate, needsUpdate } );
			expect( shadowDraws - before ).toBe( perRender );
			expect( Array.from( sh ) ).toEqual( Array.from( reference ) );

		}

		// Shadows off: nothing drawn, nothing changed.
		renderer.shadowMap.enabled = false;
		renderer.shadowMap.autoUpdate = true;
		renderer.shadowMap.needsUpdate = false;
		const before = shadowDraws;
		await capturer.capture( scene, PROBES, new Float32Array( 27 * count ) );
		expect( shadowDraws - before ).toBe( 0 );
		expect( [ renderer.shadowMap.autoUpdate, renderer.shadowMap.needsUpdate ] ).toEqual( [ true, false ] );
		renderer.shadowMap.enabled = true;
		capturer.dispose();
		dispose();

	} );

	it( 'a redraw asked for while the capture awaits (needsUpdate = true from the page) is drawn for the capture and still pending after it', async () => {

		const { scene, dispose } = createShadowRoom( 'point' );
		const capturer = new ProbeCapturer( renderer, { resolution: RESOLUTION } );
		const perRender = drawsPerShadowRender( scene );
		renderer.shadowMap.autoUpdate = false;
		renderer.shadowMap.needsUpdate = false;
		const slow = () => { const end = performance.now() + 35; while ( performance.now() < end ) { /* wait */ } };
		// After probe 2 the capture yields; this timer runs in that yield, as a page's handler would.
		const onProgress = ( done: number ) => {

			if ( done === 2 ) { slow(); setTimeout( () => { renderer.shadowMap.needsUpdate = true; }, 0 ); }

		};

		const before = shadowDraws;
		await capturer.capture( scene, PROBES, new Float32Array( 27 * count ), { onProgress } );
		expect( shadowDraws - before ).toBe( 2 * perRender );
		expect( [ renderer.shadowMap.autoUpdate, renderer.shadowMap.needsUpdate ] ).toEqual( [ false, true ] );
		renderer.shadowMap.autoUpdate = true;
		capturer.dispose();
		dispose();

	} );

	it( 'a capture that throws (a render fails, the context is lost) restores autoUpdate and needsUpdate; the capturer stays usable', async () => {

		const { scene, dispose } = createShadowRoom( 'directional' );
		const capturer = new ProbeCapturer( renderer, { resolution: RESOLUTION } );
		const target = new Float32Array( 27 * count );
		const render = renderer.render;
		const ownIsContextLost = Object.getOwnPropertyDescriptor( gl, 'isContextLost' );
		for ( const failure of [ 'render', 'context' ] as const ) for ( const autoUpdate of [ true, false ] ) for ( const needsUpdate of [ true, false ] ) {

			renderer.shadowMap.autoUpdate = autoUpdate;
			renderer.shadowMap.needsUpdate = needsUpdate;
			let calls = 0;
			if ( failure === 'render' ) {

				// The 9th render is past the first probe's six faces, so after the maps were drawn.
				renderer.render = function ( ...args ) {

					if ( ++ calls === 9 ) throw new Error( 'render failed (test)' );
					return render.apply( this, args );

				};

			} else {

				Object.defineProperty( gl, 'isContextLost', { configurable: true, value: () => ++ calls > 2 } );

			}

			try {

				await expect( capturer.capture( scene, PROBES, target ) ).rejects.toThrow( failure === 'render' ? /render failed \(test\)/ : /context was lost/ );

			} finally {

				renderer.render = render;
				if ( ownIsContextLost ) Object.defineProperty( gl, 'isContextLost', ownIsContextLost );
				else delete ( gl as unknown as { isContextLost?: unknown } ).isContextLost;

			}

			expect( calls ).toBeGreaterThan( 2 ); // it failed mid-capture, after the first probe
			expect( { failure, autoUpdate: renderer.shadowMap.autoUpdate, needsUpdate: renderer.shadowMap.needsUpdate } )
				.toEqual( { failure, autoUpdate, needsUpdate } );
			expect( Array.from( target ) ).toEqual( new Array( 27 * count ).fill( 0 ) );

		}

		renderer.shadowMap.autoUpdate = true;
		renderer.shadowMap.needsUpdate = false;
		await capturer.capture( scene, PROBES, target );
		expect( target[ 0 ] ).toBeGreaterThan( 0 );
		capturer.dispose();
		dispose();

	} );

} );
