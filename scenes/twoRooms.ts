import * as THREE from 'three';

/**
 * Two rooms sharing a wall — the classic light-leak setup. Room A (x < 0) is lit red, room B
 * (x > 0) blue; a probe grid spans both, so the Delaunay cells between the two probe layers
 * nearest the wall straddle it and, without zones or the visibility guard, blend red light into
 * room B (and blue into A).
 *
 * - Outer shell: x ∈ [−4.1, 4.1], y ∈ [0, 3], z ∈ [−2, 2], white matte, seen from inside.
 * - Shared wall: a closed box x ∈ [−0.1, 0.1], full height and depth, white matte.
 * - Each room: an emissive ceiling panel (pure red in A, pure blue in B) and a lamp of the same
 *   colour, a spot light high up against the shared wall that shines away from it, over the
 *   room's floor, ceiling and walls. Every ray of its cone heads away from the wall (the cone's
 *   axis is more than its angle away from the wall's plane), so no light of one room reaches the
 *   other room's surfaces, with or without shadows: all red in room B comes through the probes.
 * - Probes: x ∈ {−3.4, −1, 1, 3.4} × y ∈ {0.5, 2.5} × z ∈ {−1.5, 1.5}, 16 in all, index
 *   `4 · ix + 2 · iy + iz`; probes 0–7 are in room A, 8–15 in room B.
 */
export interface TwoRooms {

	/** Everything: shell, wall, panels, lamps and their bulbs. */
	scene: THREE.Scene;

	/** The static meshes (shell, wall, panels): the occluders for the visibility guard. */
	statics: THREE.Group;

	/** Probe positions, x, y, z per probe (16). */
	positions: number[];

	/** Probe indices per room. */
	probesA: number[];
	probesB: number[];

	/** Inner bounds of each room (the air between floor, ceiling and walls). */
	boundsA: THREE.Box3;
	boundsB: THREE.Box3;

	/** x of the wall's faces: room A's side at −halfThickness, room B's at +halfThickness. */
	wallHalfThickness: number;

	/** Zone definitions for `LightProbeVolume` (`zones`): one per room, assigned by bounds. */
	zones: { name: string; probes: number[]; bounds: THREE.Box3 }[];

	/** Frees geometries and materials. */
	dispose(): void;

}

/** Candela of each room's lamp: bright enough to show the walls under filmic tone mapping at exposure 1. */
const LAMP_INTENSITY = 40;
/** Cone half-angle of each lamp (83°, under 90°: no ray towards the wall) and its height. */
const LAMP_ANGLE = 1.45, LAMP_HEIGHT = 2.2;

/** Builds the two-room scene (see {@link TwoRooms}). */
export function createTwoRooms(): TwoRooms {

	const HALF = 0.1, LENGTH = 4.1, HEIGHT = 3, DEPTH = 4;
	const white = ( side: THREE.Side ) => new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1, side } );
	const shell = new THREE.Mesh( new THREE.BoxGeometry( 2 * LENGTH, HEIGHT, DEPTH ), white( THREE.BackSide ) );
	shell.position.y = HEIGHT / 2;
	shell.name = 'shell';
	const wall = new THREE.Mesh( new THREE.BoxGeometry( 2 * HALF, HEIGHT, DEPTH ), white( THREE.FrontSide ) );
	wall.position.y = HEIGHT / 2;
	wall.name = 'shared wall';

	const statics = new THREE.Group();
	statics.add( shell, wall );
	const scene = new THREE.Scene();
	scene.add( statics );

	const centreA = - ( LENGTH + HALF ) / 2, centreB = ( LENGTH + HALF ) / 2;
	for ( const [ side, color, name ] of [ [ - 1, 0xff0000, 'A' ], [ 1, 0x0060ff, 'B' ] ] as const ) {

		const panel = new THREE.Mesh(
			new THREE.PlaneGeometry( 1.6, 1.6 ),
			new THREE.MeshStandardMaterial( { color: 0x000000, emissive: color, emissiveIntensity: 2 } )
		);
		panel.rotation.x = Math.PI / 2; // facing down
		panel.position.set( side < 0 ? centreA : centreB, HEIGHT - 0.02, 0 );
		panel.name = `panel ${name}`;
		statics.add( panel );
		// The lamp: a sconce on the shared wall, 0.05 m in front of it, shining straight away from
		// it with a cone 83° wide: every ray heads away from the wall, and the room is lit up to it.
		const lamp = new THREE.SpotLight( color, LAMP_INTENSITY, 0, LAMP_ANGLE, 0.5, 2 );
		lamp.position.set( side * ( HALF + 0.05 ), LAMP_HEIGHT, 0 );
		lamp.target.position.set( side * LENGTH, LAMP_HEIGHT, 0 );
		lamp.name = `lamp ${name}`;
		// Its bulb, so the bright patch it throws on the ceiling has a visible source.
		const bulb = new THREE.Mesh( new THREE.SphereGeometry( 0.05, 12, 6 ), new THREE.MeshBasicMaterial( { color } ) );
		bulb.position.copy( lamp.position );
		bulb.name = `bulb ${name}`;
		scene.add( lamp, lamp.target, bulb );

	}

	const positions: number[] = [];
	for ( const x of [ - 3.4, - 1, 1, 3.4 ] ) for ( const y of [ 0.5, 2.5 ] ) for ( const z of [ - 1.5, 1.5 ] ) positions.push( x, y, z );
	const probesA = [ 0, 1, 2, 3, 4, 5, 6, 7 ], probesB = [ 8, 9, 10, 11, 12, 13, 14, 15 ];
	const boundsA = new THREE.Box3( new THREE.Vector3( - LENGTH, 0, - DEPTH / 2 ), new THREE.Vector3( - HALF, HEIGHT, DEPTH / 2 ) );
	const boundsB = new THREE.Box3( new THREE.Vector3( HALF, 0, - DEPTH / 2 ), new THREE.Vector3( LENGTH, HEIGHT, DEPTH / 2 ) );
	scene.updateMatrixWorld( true );

	return {
		scene, statics, positions, probesA, probesB, boundsA, boundsB, wallHalfThickness: HALF,
		zones: [ { name: 'A', probes: probesA, bounds: boundsA }, { name: 'B', probes: probesB, bounds: boundsB } ],
		dispose() {

			scene.traverse( ( object ) => {

				const mesh = object as THREE.Mesh;
				if ( mesh.isMesh !== true ) return;
				mesh.geometry.dispose();
				for ( const material of Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ] ) material.dispose();

			} );

		},
	};

}
