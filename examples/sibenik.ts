import { LightProbeVolume, captureBounces } from 'three-capture-lighting';
import { createProbeInterpolator } from 'three-capture-lighting/math';
import { buildSibenik, sibenikLayouts, sibenikPath, SIBENIK_CHARACTER_HEIGHT } from '@scenes/sibenik.js';
import { DynamicObjects } from './common/DynamicObjects.js';
import { zonesOf } from './common/layouts.js';
import { ProbeVolumeDemo } from './common/ProbeVolumeDemo.js';
import { Viewer } from './common/Viewer.js';

// The paper's Sibenik (Table 4: 432 grid probes vs 39 placed with meaning): a closed cathedral lit
// through its windows. 39 probes — bounce probes on the floors, probes under the arches and at the
// windows, one by the stained-glass rose window, one in the sky — light the fox as it walks up the
// nave and back down the aisle through patches of sun.

const viewer = new Viewer( { camera: { position: [ - 14.5, - 12.9, - 0.8 ], target: [ - 6, - 14.4, 2.2 ] } } );
const { renderer, scene, settings } = viewer;

init().catch( ( error ) => viewer.showError( error ) );

async function init(): Promise<void> {

	// The static scene the probes capture: the cathedral, its sun, sky and lamps.
	await buildSibenik( viewer );

	// What the probes light: the fox walking up the nave and down the aisle.
	const objects = await DynamicObjects.load( viewer, { path: sibenikPath, height: SIBENIK_CHARACTER_HEIGHT } );

	const demo = new ProbeVolumeDemo( viewer, objects, {
		layouts: sibenikLayouts,
		// The probes of a layout, tetrahedralized (the 432-probe grid also trilinearly).
		createVolume: ( layout, sh ) => new LightProbeVolume( {
			positions: layout.positions, names: layout.names, roles: layout.roles, sh,
			interpolator: createProbeInterpolator( layout.positions, { outside: settings.outside } ),
			zones: settings.zones ? zonesOf( layout ) : undefined,
		} ),
		// The fox, added before the capture, which then hides it (no fox in its own probes).
		addObjects: ( volume ) => {

			for ( const object of objects.list ) volume.add( object );

		},
		// A cube map at each probe, projected to SH9 on the GPU (far: the sky dome); bounces capture
		// again with the stone lit by the probes.
		capture: async ( volume, { bounces, ...options } ) => {

			const captureOptions = { ...options, near: 0.05, far: 400 };
			if ( bounces > 0 ) await captureBounces( volume, renderer, scene, { ...captureOptions, bounces } );
			else await volume.capture( renderer, scene, captureOptions );

		},
	} );
	await demo.start();

	// The fox walks through patches of sun: once it is loaded, let it receive the sun's shadow and
	// cast its own (it is hidden in captures, so its shadow never reaches the probes).
	scene.traverse( ( object ) => { object.receiveShadow = true; } );
	objects.character?.object.traverse( ( object ) => { object.castShadow = true; } );

	viewer.animate( ( time, delta ) => {

		objects.move( time, delta );
		demo.activeVolume.update();
		demo.showView( objects.list );

	} );

}
