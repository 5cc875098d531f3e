/**
 * The capture and frame bench pages' shared set: one 1280×720 WebGL2 canvas and the Basic room —
 * red (−x), green (+x), blue (−z) walls, white floor, ceiling and back wall (BackSide, seen from
 * inside), a glowing ceiling panel and a PointLight under it.
 */

import * as THREE from 'three';

export const WIDTH = 1280, HEIGHT = 720;
export const ROOM_MIN = [ - 2, 0, - 2 ], ROOM_MAX = [ 2, 3, 2 ];
export const NEAR = 0.05, FAR = 20;

/** What {@link createBenchRoom} returns. */
export interface BenchRoom {

	renderer: THREE.WebGLRenderer;
	gl: WebGL2RenderingContext;
	scene: THREE.Scene;
	camera: THREE.PerspectiveCamera;
	/** The room's extent, ROOM_MAX − ROOM_MIN. */
	size: THREE.Vector3;
	/** The walls in MeshStandardMaterial, roughness 1 (what captures see). */
	litWalls: THREE.MeshStandardMaterial[];
	/** The same colours halved in MeshBasicMaterial: frame tests, so only the spheres pay for probe light in every variant. */
	unlitWalls: THREE.MeshBasicMaterial[];
	room: THREE.Mesh<THREE.BoxGeometry, THREE.Material[]>;
	lamp: THREE.Mesh;
	light: THREE.PointLight;

}

/** Creates the canvas (appended to the page), the scene with the lit room, the lamp and the light, and the camera. */
export function createBenchRoom(): BenchRoom {

	const renderer = new THREE.WebGLRenderer( { antialias: false, powerPreference: 'high-performance' } );
	renderer.setPixelRatio( 1 );
	renderer.setSize( WIDTH, HEIGHT );
	document.body.appendChild( renderer.domElement );
	const gl = renderer.getContext() as WebGL2RenderingContext;

	const scene = new THREE.Scene();
	const camera = new THREE.PerspectiveCamera( 75, WIDTH / HEIGHT, 0.05, 50 );
	camera.position.set( 0, 1.5, 1.9 );
	camera.lookAt( 0, 1.3, - 2 );

	const size = new THREE.Vector3().fromArray( ROOM_MAX ).sub( new THREE.Vector3().fromArray( ROOM_MIN ) );
	// BoxGeometry groups: +x, −x, +y, −y, +z, −z. Seen from inside (BackSide).
	const WALL_COLORS = [ 0x20c020, 0xc02020, 0xffffff, 0xffffff, 0xffffff, 0x2020c0 ];
	const litWalls = WALL_COLORS.map( ( color ) => new THREE.MeshStandardMaterial( {
		color, roughness: 1, metalness: 0, side: THREE.BackSide,
	} ) );
	const unlitWalls = WALL_COLORS.map( ( color ) => new THREE.MeshBasicMaterial( {
		color: new THREE.Color( color ).multiplyScalar( 0.5 ), side: THREE.BackSide,
	} ) );
	const room = new THREE.Mesh<THREE.BoxGeometry, THREE.Material[]>( new THREE.BoxGeometry( size.x, size.y, size.z ), litWalls );
	room.position.set( 0, ( ROOM_MIN[ 1 ] + ROOM_MAX[ 1 ] ) / 2, 0 );
	scene.add( room );

	const lamp = new THREE.Mesh( new THREE.PlaneGeometry( 1, 1 ), new THREE.MeshBasicMaterial( { color: 0xffffff } ) );
	lamp.rotation.x = Math.PI / 2; // faces down
	lamp.position.set( 0, ROOM_MAX[ 1 ] - 0.01, 0 );
	scene.add( lamp );

	const light = new THREE.PointLight( 0xffffff, 12, 0, 2 );
	light.position.set( 0, ROOM_MAX[ 1 ] - 0.3, 0 );
	scene.add( light );

	return { renderer, gl, scene, camera, size, litWalls, unlitWalls, room, lamp, light };

}
