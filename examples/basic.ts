import * as THREE from 'three';
import { DemoApp } from './common/DemoApp.js';
import { basicLayouts, createBasicRoom } from '@scenes/basic.js';

// The paper's Basic scene (Table 4: 64 grid probes vs 13 placed with meaning): a room with red,
// green and blue walls; the fox walks a loop lit by the probes around it.

const app = new DemoApp( {
	layouts: basicLayouts,
	camera: { position: [ 0, 1.6, 3.9 ], target: [ 0, 1.0, 0 ] },
	path: new THREE.CatmullRomCurve3( [ [ 1.2, 0, 0 ], [ 0, 0, - 1.3 ], [ - 1.2, 0, 0 ], [ 0, 0, 1.2 ] ].map( ( p ) => new THREE.Vector3( ...p ) ), true ),
	characterHeight: 0.5,
	capture: { near: 0.02, far: 20 },
	async build( app ) {

		app.scene.add( createBasicRoom().room );

	},
} );

app.start();
