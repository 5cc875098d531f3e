/**
 * `volume.add( scene )` on a real GL context (headless-gl, WebGL2): what a capture hides, what it
 * re-blends afterwards, and that walls out of the direct light are lit by the probes.
 *
 * The room: a white floor lit by a directional light from above and behind the back wall, so
 * the back wall (facing +z) and the left wall (facing +x) get no direct light (N·L ≤ 0) and, with
 * no ambient light, render black unless probe light reaches them — the "pitch-black shadows" of
 * a level where only add( character ) was called. The probes see the lit floor, so after
 * add( scene ) and a capture the walls must be lit, and exactly as add( wall, { mode } ) by hand
 * lights them: the same SH (the capture sees the same scene) sampled the same way.
 *
 * Needs an X display: `xvfb-run -a npx vitest run test/runtime/addScene.gpu.test.ts`.
 */

import * as path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import {
	OUTPUT_DIR, averageColor, compareImages, disposeMesh, projectToImage, renderToImage, writePNG, type Image8,
} from '../helpers/gpuScenes.js';

const SIZE = 64;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** Probes every 2 m inside the room (spacing 2). */
function roomProbes(): number[] {

	const positions: number[] = [];
	for ( const x of [ - 3, - 1, 1, 3 ] ) for ( const y of [ 0.5, 2.5 ] ) for ( const z of [ - 3, - 1, 1, 3 ] ) positions.push( x, y, z );
	return positions;

}

/** A skinned cylinder with its bone under a group (a character as GLTFLoader gives one). */
function character(): { root: THREE.Group; mesh: THREE.SkinnedMesh } {

	const geometry = new THREE.CylinderGeometry( 0.3, 0.3, 1.6, 16, 4 );
	const count = geometry.getAttribute( 'position' ).count;
	const weights = new Float32Array( 4 * count );
	for ( let i = 0; i < count; i ++ ) weights[ 4 * i ] = 1;
	geometry.setAttribute( 'skinIndex', new THREE.Uint16BufferAttribute( new Uint16Array( 4 * count ), 4 ) );
	geometry.setAttribute( 'skinWeight', new THREE.Float32BufferAttribute( weights, 4 ) );
	const bone = new THREE.Bone();
	const mesh = new THREE.SkinnedMesh( geometry, new THREE.MeshStandardMaterial( { color: 0xff0000 } ) );
	const root = new THREE.Group();
	root.add( bone, mesh );
	mesh.bind( new THREE.Skeleton( [ bone ] ) );
	root.position.set( 1, 0.8, 0 );
	return { root, mesh };

}

/** The room: floor, a finely tessellated back wall, a coarse left wall, a prop, a lamp, a character and a marked cart. */
function room() {

	const scene = new THREE.Scene();
	const white = () => new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1, metalness: 0 } );
	const floor = new THREE.Mesh( new THREE.PlaneGeometry( 8, 8 ).rotateX( - Math.PI / 2 ), white() );
	const backWall = new THREE.Mesh( new THREE.PlaneGeometry( 8, 3, 32, 12 ), white() ); // 0.35 m triangles: per vertex
	backWall.position.set( 0, 1.5, - 4 );
	const leftWall = new THREE.Mesh( new THREE.PlaneGeometry( 8, 3 ), white() ); // two triangles: a 3D texture
	leftWall.rotation.y = Math.PI / 2;
	leftWall.position.set( - 4, 1.5, 0 );
	const prop = new THREE.Mesh( new THREE.BoxGeometry( 0.6, 0.6, 0.6 ), new THREE.MeshStandardMaterial( { color: 0x20ff20 } ) );
	prop.position.set( - 1, 0.3, 1 );
	const lamp = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshBasicMaterial( { color: 0xffffff } ) );
	lamp.position.set( 0, 2.8, 0 );
	const cart = new THREE.Mesh( new THREE.BoxGeometry( 0.8, 0.5, 0.5 ), new THREE.MeshStandardMaterial( { color: 0x0000ff } ) );
	cart.position.set( 2, 0.25, 2 );
	cart.userData.probeLighting = 'dynamic'; // a moving object the rule cannot see (not skinned)
	const hero = character();
	const light = new THREE.DirectionalLight( 0xffffff, 3 );
	light.position.set( 0, 10, - 6 ); // from above and behind the back wall: N·L < 0 on both walls
	scene.add( floor, backWall, leftWall, prop, lamp, cart, hero.root, light, light.target );
	scene.updateMatrixWorld( true );
	return {
		scene, floor, backWall, leftWall, prop, lamp, cart, hero,
		dispose() {

			for ( const mesh of [ floor, backWall, leftWall, prop, lamp, cart, hero.mesh ] ) disposeMesh( mesh );

		},
	};

}

/** Rows first..last of an image. */
function rows( image: Image8, first: number, last: number ): Image8 {

	const row = 4 * image.width;
	return { width: image.width, height: last - first + 1, data: image.data.slice( first * row, ( last + 1 ) * row ) };

}

function cameraAt( position: THREE.Vector3Like, target: THREE.Vector3Like ): THREE.PerspectiveCamera {

	const camera = new THREE.PerspectiveCamera( 60, 1, 0.1, 50 );
	camera.position.set( position.x, position.y, position.z );
	camera.lookAt( target.x, target.y, target.z );
	camera.updateMatrixWorld();
	return camera;

}

describe.skipIf( ! ctx.renderer )( `volume.add( scene ) on a real GL context (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;
	const CAPTURE = { resolution: 16 };

	afterAll( () => ctx.dispose() );

	it( 'capture hides exactly the dynamic objects (the rig, the cart marked \'dynamic\'), draws the scenery, and shows them again', async () => {

		const r = room();
		const volume = new LightProbeVolume( { positions: roomProbes() } );
		volume.add( r.scene );
		expect( volume.getLighting( r.hero.mesh ) ).toBe( 'dynamic' );
		expect( volume.getLighting( r.cart ) ).toBe( 'dynamic' );
		const watched = [ r.floor, r.backWall, r.leftWall, r.prop, r.lamp, r.cart, r.hero.mesh ];
		const drawn = new Map<THREE.Object3D, number>( watched.map( ( mesh ) => [ mesh, 0 ] ) );
		for ( const mesh of watched ) mesh.onBeforeRender = () => drawn.set( mesh, drawn.get( mesh )! + 1 );
		await volume.capture( renderer, r.scene, CAPTURE );
		const counts = watched.map( ( mesh ) => drawn.get( mesh ) );
		// 32 probes × 6 faces each, for what is in view of a face (the floor is below every probe).
		expect( drawn.get( r.floor ), `draw counts ${counts}` ).toBeGreaterThanOrEqual( 32 );
		for ( const mesh of [ r.backWall, r.leftWall, r.prop, r.lamp ] ) expect( drawn.get( mesh ), `draw counts ${counts}` ).toBeGreaterThan( 0 );
		expect( drawn.get( r.cart ), `draw counts ${counts}` ).toBe( 0 );
		expect( drawn.get( r.hero.mesh ), `draw counts ${counts}` ).toBe( 0 );
		expect( r.cart.visible && r.hero.root.visible && r.hero.mesh.visible ).toBe( true );
		// A normal render draws them all: the counters can see the hidden ones.
		drawn.forEach( ( _, mesh ) => drawn.set( mesh, 0 ) );
		renderToImage( renderer, gl, r.scene, cameraAt( { x: 0, y: 2, z: 6 }, { x: 0, y: 1, z: 0 } ) );
		expect( drawn.get( r.cart ) ).toBe( 1 );
		expect( drawn.get( r.hero.mesh ) ).toBe( 1 );
		volume.dispose();
		r.dispose();

	} );

	it( 'static props are blended again after a capture, once, and not on the frames after it', async () => {

		const r = room();
		const volume = new LightProbeVolume( { positions: roomProbes() } );
		volume.add( r.scene );
		const before = Float32Array.from( volume.getUniforms( r.prop )!.probeVolumeMatrices.value );
		expect( before.every( ( v ) => v === 0 ) ).toBe( true ); // black probes before the capture
		await volume.capture( renderer, r.scene, CAPTURE );
		const interpolator = volume.interpolator;
		const original = interpolator.interpolate.bind( interpolator );
		let calls = 0;
		interpolator.interpolate = ( ...args ) => { calls ++; return original( ...args ); };
		volume.update();
		const afterCapture = calls;
		calls = 0;
		volume.update();
		volume.update();
		// The first update after the capture: the prop, the dynamic rig and cart, and the large meshes' resampling.
		expect( afterCapture ).toBeGreaterThan( 3 );
		expect( calls ).toBe( 4 ); // two frames × (rig + cart): the prop and the walls are not redone
		const after = volume.getUniforms( r.prop )!.probeVolumeMatrices.value;
		expect( after.some( ( v ) => v > 0 ) ).toBe( true ); // the captured light reached the prop
		volume.dispose();
		r.dispose();

	} );

	it( 'walls out of the direct light: black without probes, lit after add( scene ) + capture, equal to add( wall, { mode } ) by hand', async () => {

		const back = cameraAt( { x: 0, y: 1.5, z: 0 }, { x: 0, y: 1.5, z: - 4 } );
		const left = cameraAt( { x: 0, y: 1.5, z: 0 }, { x: - 4, y: 1.5, z: 0 } );
		const wallPixels = ( scene: THREE.Scene ) => [ back, left ].map( ( camera ) => renderToImage( renderer, gl, scene, camera ) );

		// Without probe light the walls are black (what the issue calls pitch-black shadows).
		const bare = room();
		const dark = wallPixels( bare.scene );
		bare.dispose();

		const auto = room();
		const volume = new LightProbeVolume( { positions: roomProbes() } );
		volume.add( auto.scene );
		expect( volume.getLighting( auto.backWall ) ).toBe( 'vertex' );
		expect( volume.getLighting( auto.leftWall ) ).toBe( 'texture' );
		await volume.capture( renderer, auto.scene, CAPTURE );
		volume.update();
		const lit = wallPixels( auto.scene );

		// By hand: the same room, the character and cart added, the two walls in the modes chosen.
		const hand = room();
		const byHand = new LightProbeVolume( { positions: roomProbes() } );
		byHand.add( hand.hero.root ).add( hand.cart );
		byHand.add( hand.backWall, { mode: 'vertex' } ).add( hand.leftWall, { mode: 'texture' } );
		await byHand.capture( renderer, hand.scene, CAPTURE );
		byHand.update();
		const reference = wallPixels( hand.scene );

		let worstSH = 0;
		for ( let i = 0; i < volume.sh.length; i ++ ) worstSH = Math.max( worstSH, Math.abs( volume.sh[ i ] - byHand.sh[ i ] ) );
		const centre = ( camera: THREE.Camera, point: THREE.Vector3 ) => projectToImage( point, camera, SIZE, SIZE );
		const [ bx, by ] = centre( back, new THREE.Vector3( 0, 1.5, - 4 ) );
		const [ lx, ly ] = centre( left, new THREE.Vector3( - 4, 1.5, 0 ) );
		const show = ( c: number[] ) => c.map( Math.round ).join( ', ' );
		const message = `back wall: dark ${show( averageColor( dark[ 0 ], bx, by, 4 ) )}, lit ${show( averageColor( lit[ 0 ], bx, by, 4 ) )}; `
			+ `left wall: dark ${show( averageColor( dark[ 1 ], lx, ly, 4 ) )}, lit ${show( averageColor( lit[ 1 ], lx, ly, 4 ) )}`;
		writePNG( path.join( OUTPUT_DIR, 'addScene-back-lit.png' ), lit[ 0 ] );
		writePNG( path.join( OUTPUT_DIR, 'addScene-left-lit.png' ), lit[ 1 ] );
		for ( const [ image, x, y ] of [ [ dark[ 0 ], bx, by ], [ dark[ 1 ], lx, ly ] ] as const ) {

			expect( Math.max( ...averageColor( image, x, y, 4 ) ), message ).toBeLessThan( 1 );

		}

		for ( const [ image, x, y ] of [ [ lit[ 0 ], bx, by ], [ lit[ 1 ], lx, ly ] ] as const ) {

			expect( Math.min( ...averageColor( image, x, y, 4 ) ), message ).toBeGreaterThan( 20 );

		}

		// Per-vertex and per-texel light follow the field down the wall (brighter near the lit floor):
		// measured 125..153 on both walls (llvmpipe); one blend per wall would give one colour.
		for ( const image of lit ) {

			const wall = rows( image, 13, 50 ).data.filter( ( _, i ) => i % 4 === 1 );
			expect( Math.max( ...wall ) - Math.min( ...wall ), message ).toBeGreaterThan( 10 );

		}

		expect( worstSH, 'the two captures saw the same scene' ).toBeLessThan( 1e-6 );
		// Only the walls: rows 13..50 (the floor, lit by the probes in one room and not in the other, is below row 52).
		expect( compareImages( rows( lit[ 0 ], 13, 50 ), rows( reference[ 0 ], 13, 50 ) ).max, message ).toBeLessThanOrEqual( 1 );
		expect( compareImages( rows( lit[ 1 ], 13, 50 ), rows( reference[ 1 ], 13, 50 ) ).max, message ).toBeLessThanOrEqual( 1 );
		volume.dispose();
		byHand.dispose();
		auto.dispose();
		hand.dispose();

	} );

} );
