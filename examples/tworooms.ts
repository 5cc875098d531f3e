import * as THREE from 'three';
import { LightProbeVolume, captureBounces } from 'three-capture-lighting';
import { createProbeInterpolator } from 'three-capture-lighting/math';
import { createTwoRooms } from '@scenes/twoRooms.js';
import { DynamicObjects } from './common/DynamicObjects.js';
import { zonesOf } from './common/layouts.js';
import { ProbeVolumeDemo } from './common/ProbeVolumeDemo.js';
import type { DemoSettings } from './common/queryParameters.js';
import { Viewer } from './common/Viewer.js';

// Light through walls: a red room and a blue room share a wall, and one grid of 16 probes spans
// both, so tetrahedra straddle the wall. A white ball hangs in the blue room by the wall, and the
// fox walks a loop there that passes 0.3 m from it: with the probes blended as they are, both
// turn purple by the wall (red leaking through). "lighting zones" gives each room its own
// tetrahedralization (objects take the zone whose box holds them); "no light through walls" drops
// the probes an object cannot see. Either one stops it: the ball and the fox stay blue.

/** The white ball: in the blue room, by the wall, where the cells across the wall weigh the red room's probes most. */
const LEAK_BALL = [ 0.45, 1.4, 0.3 ];

const viewer = new Viewer( { camera: { position: [ 0.5, 2.4, 6.2 ], target: [ 0.3, 1, 0 ] } } );
const { renderer, scene, settings } = viewer;

init().catch( ( error ) => viewer.showError( error ) );

async function init(): Promise<void> {

	// The static scene the probes capture: the two rooms, their ceiling panels and spots.
	const rooms = createTwoRooms();
	scene.add( ...rooms.scene.children.slice() );

	// What the probes light: the fox walking a loop in the blue room, close to the wall.
	const loop = [ [ 0.4, 0, 0 ], [ 1.5, 0, - 1.2 ], [ 3, 0, 0 ], [ 1.5, 0, 1.2 ] ];
	const path = new THREE.CatmullRomCurve3( loop.map( ( p ) => new THREE.Vector3( ...p ) ), true );
	const objects = await DynamicObjects.load( viewer, { path, height: 0.6, loopSeconds: 16, ball: LEAK_BALL } );

	// One layout over both rooms, with a zone per room ("lighting zones" in the panel, ?zones=1).
	const box = ( b: THREE.Box3 ) => ( { min: b.min.toArray(), max: b.max.toArray() } );
	const zones = rooms.zones.map( ( zone ) => ( { name: zone.name, probes: zone.probes, bounds: box( zone.bounds ) } ) );

	const demo = new ProbeVolumeDemo( viewer, objects, {
		layouts: [ { name: '16 probes over both rooms', positions: rooms.positions, zones } ],
		createVolume: ( layout, sh ) => new LightProbeVolume( {
			positions: layout.positions, names: layout.names, roles: layout.roles, sh,
			interpolator: createProbeInterpolator( layout.positions, { outside: settings.outside } ),
			// Each zone its own tetrahedralization: no cell spans the wall.
			zones: settings.zones ? zonesOf( layout ) : undefined,
		} ),
		// The fox and the ball, added before the capture: the capture hides them (no fox in the probes).
		addObjects: ( volume ) => {

			for ( const object of objects.list ) volume.add( object );

		},
		capture: async ( volume, { bounces, ...options } ) => {

			const captureOptions = { ...options, near: 0.05, far: 20 };
			if ( bounces > 0 ) await captureBounces( volume, renderer, scene, { ...captureOptions, bounces } );
			else await volume.capture( renderer, scene, captureOptions );

		},
	} );
	await demo.start();

	// The legend says which fix is on; rewritten when a toggle changes it.
	let shownFix: string | null = null;
	viewer.animate( ( time, delta ) => {

		objects.move( time, delta );
		demo.activeVolume.update(); // with the guard on, also drops the probes behind the wall
		demo.showView( objects.list );
		const fix = fixName( settings );
		if ( fix !== shownFix ) showFix( viewer.overlay, shownFix = fix );

	} );

}

/** Which fix is on, as the legend names it ('' for none). */
function fixName( { zones, guard }: DemoSettings ): string {

	return zones && guard ? 'lighting zones + no light through walls' : zones ? 'lighting zones' : guard ? 'no light through walls' : '';

}

/** The legend: which fix is on and what the ball and the fox show. */
function showFix( overlay: Viewer[ 'overlay' ], fix: string ): void {

	overlay.legend( fix === '' ? [
		{ text: 'no fix on: red leaks through the wall', swatch: '#c040ff' },
		{ text: 'the ball and the fox by it turn purple' },
	] : [
		{ text: `fix on: ${fix}`, swatch: '#4060ff' },
		{ text: 'no red in the blue room: ball and fox blue' },
	] );

}
