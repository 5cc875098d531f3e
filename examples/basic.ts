import * as THREE from 'three';
import { LightProbeVolume, captureBounces } from 'three-capture-lighting';
import { createProbeInterpolator } from 'three-capture-lighting/math';
import { basicLayouts, createBasicRoom } from '@scenes/basic.js';
import { DynamicObjects } from './common/DynamicObjects.js';
import { zonesOf } from './common/layouts.js';
import { ProbeVolumeDemo } from './common/ProbeVolumeDemo.js';
import { Viewer } from './common/Viewer.js';

// The paper's Basic scene (Table 4: 64 grid probes vs 13 placed with meaning): a room with red,
// green and blue walls; the fox walks a loop lit by the probes around it.

const viewer = new Viewer( { camera: { position: [ 0, 1.6, 3.9 ], target: [ 0, 1.0, 0 ] } } );
const { renderer, scene, settings } = viewer;

init().catch( ( error ) => viewer.showError( error ) );

async function init(): Promise<void> {

	// The static scene the probes capture: the room and its lamp.
	scene.add( createBasicRoom().room );

	// What the probes light: the fox walking its loop (with ?spheres=N and ?ball=x,y,z, more).
	const loop = [ [ 1.2, 0, 0 ], [ 0, 0, - 1.3 ], [ - 1.2, 0, 0 ], [ 0, 0, 1.2 ] ];
	const path = new THREE.CatmullRomCurve3( loop.map( ( p ) => new THREE.Vector3( ...p ) ), true );
	const objects = await DynamicObjects.load( viewer, { path, height: 0.5 } );

	const demo = new ProbeVolumeDemo( viewer, objects, {
		layouts: basicLayouts,
		// The probes of a layout (sky, bounce, bleed roles), tetrahedralized.
		createVolume: ( layout, sh ) => new LightProbeVolume( {
			positions: layout.positions, names: layout.names, roles: layout.roles, sh,
			interpolator: createProbeInterpolator( layout.positions, { outside: settings.outside } ),
			zones: settings.zones ? zonesOf( layout ) : undefined,
		} ),
		// Each object is lit by the 4 probes of the tetrahedron around it. Added before the capture,
		// which then hides them: the fox is never captured into its own probes.
		addObjects: ( volume ) => {

			for ( const object of objects.list ) volume.add( object );

		},
		// A cube map at each probe, projected to SH9 on the GPU; bounces capture again with the
		// room lit by the probes.
		capture: async ( volume, { bounces, ...options } ) => {

			const captureOptions = { ...options, near: 0.02, far: 20 };
			if ( bounces > 0 ) await captureBounces( volume, renderer, scene, { ...captureOptions, bounces } );
			else await volume.capture( renderer, scene, captureOptions );

		},
		// "automatic layout (budget 12)": LightProbeVolume.fromScene picks 12 probes in the room's open
		// space reachable from the middle of the room; "fit to dense captures" fits the probes to a
		// grid of captures 0.4 m apart (or, for the automatic layout, to all its candidates).
		automatic: { budget: 12, reachableFrom: [ 0, 1.6, 0 ], fitSpacing: 0.4, capture: { near: 0.02, far: 20 } },
	} );
	await demo.start();

	viewer.animate( ( time, delta ) => {

		objects.move( time, delta );
		demo.activeVolume.update(); // locate each object, blend its probes, set its irradiance matrices
		demo.showView( objects.list );

	} );

}
