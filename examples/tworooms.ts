import * as THREE from 'three';
import { DemoApp } from './common/DemoApp.js';
import { createTwoRooms } from '@scenes/twoRooms.js';

// Light through walls: a red room and a blue room share a wall, and one grid of 16 probes spans
// both, so tetrahedra straddle the wall. The fox walks a loop in the blue room that passes 0.3 m
// from the wall: with the probes blended as they are it turns purple there (red leaking through).
// "lighting zones" gives each room its own tetrahedralization (objects take the zone whose box
// holds them); "no light through walls" drops the probes an object cannot see. Either one stops it.

const rooms = createTwoRooms();
const box = ( b: THREE.Box3 ) => ( { min: b.min.toArray(), max: b.max.toArray() } );

const app = new DemoApp( {
	layouts: [ {
		name: '16 probes over both rooms', positions: rooms.positions,
		zones: rooms.zones.map( ( zone ) => ( { name: zone.name, probes: zone.probes, bounds: box( zone.bounds ) } ) ),
	} ],
	camera: { position: [ 0.5, 2.4, 6.2 ], target: [ 0.3, 1, 0 ] },
	path: new THREE.CatmullRomCurve3( [ [ 0.4, 0, 0 ], [ 1.5, 0, - 1.2 ], [ 3, 0, 0 ], [ 1.5, 0, 1.2 ] ].map( ( p ) => new THREE.Vector3( ...p ) ), true ),
	characterHeight: 0.6,
	loopSeconds: 16,
	capture: { near: 0.05, far: 20 },
	build: async ( app ) => { app.scene.add( ...rooms.scene.children.slice() ); },
} );

app.start();
