import * as THREE from 'three';
import { GridInterpolator } from 'three-capture-lighting/math';
import arbitrary from './basic.json';
import type { ProbeLayout } from './layout.js';

/**
 * The paper's Basic scene: a 4 × 3 × 4 room with a red (−x), a green (+x) and a blue (−z) wall,
 * grey floor, ceiling and front wall, lit by one warm lamp hanging in the middle. `segments`
 * subdivides each side of the box (tests of vertex-based placement want more than its corners).
 */
export function createBasicRoom( segments = 1 ): { room: THREE.Group; lamp: THREE.PointLight } {

	const wall = ( color: number ) => new THREE.MeshStandardMaterial( { color, roughness: 0.9, side: THREE.BackSide } );
	// BoxGeometry groups: +x, −x, +y, −y, +z, −z.
	// Grey floor and ceiling, so the coloured walls dominate the bounce light, as in the paper's figures.
	const box = new THREE.Mesh(
		new THREE.BoxGeometry( 4, 3, 4, segments, segments, segments ),
		[ wall( 0x30c030 ), wall( 0xd02020 ), wall( 0xaaaaaa ), wall( 0x888888 ), wall( 0xcccccc ), wall( 0x2040e0 ) ]
	);
	box.position.y = 1.5;
	box.name = 'room';
	const lamp = new THREE.PointLight( 0xfff2e0, 12, 0, 2 );
	lamp.position.set( 0.2, 2.1, 0.3 );
	const bulb = new THREE.Mesh( new THREE.SphereGeometry( 0.08 ), new THREE.MeshBasicMaterial( { color: 0xfff2e0 } ) );
	bulb.position.copy( lamp.position );
	const room = new THREE.Group();
	room.add( box, lamp, bulb );
	return { room, lamp };

}

/** The paper's 4x4x4 grid (64 probes) over the room, inset from the walls. */
export const basicGrid = { min: [ - 1.8, 0.2, - 1.8 ], max: [ 1.8, 2.8, 1.8 ], counts: [ 4, 4, 4 ] };

/** Layouts: 13 probes placed with meaning (sky above, bounce at the floor, bleed by each coloured wall), and the grid. */
export const basicLayouts: ProbeLayout[] = [
	arbitrary as ProbeLayout,
	{ name: '4x4x4 grid (64 probes)', positions: Array.from( new GridInterpolator( basicGrid.min, basicGrid.max, basicGrid.counts ).positions ), grid: basicGrid },
];
