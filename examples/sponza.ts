import * as THREE from 'three';
import { LightProbeVolume, captureBounces, type AddOptions } from 'three-capture-lighting';
import { createProbeInterpolator } from 'three-capture-lighting/math';
import { buildSponza, sponzaLayouts, sponzaPath, SPONZA_CHARACTER_HEIGHT } from '@scenes/sponza.js';
import { DynamicObjects } from './common/DynamicObjects.js';
import { zonesOf } from './common/layouts.js';
import { ProbeVolumeDemo } from './common/ProbeVolumeDemo.js';
import { Viewer } from './common/Viewer.js';

// The paper's Sponza (Table 4: 432 grid probes vs 85 placed with meaning): an open-sky atrium.
// The sun lights half of the courtyard; the fox walks from the sun patch into the shade and under
// the arcades, lit by the four probes of the tetrahedron around it.
//
// Large objects: the floors are one 35 × 11 m mesh. Lit as one object they get one colour, from the
// probes at their centre (in the courtyard air); per vertex or through a 3D SH texture over their
// bounds they follow the probes across the courtyard and under the arcades. "ambient" is the scene
// as built: a flat emissive stand-in for indirect light, which the probe modes replace.
// ?floor=ambient|object|vertex|texture selects one. The automatic layout: ?budget=N (default 86)
// and ?candidates=M (grid candidates, default 8 per probe).

const FLOOR_MODES = [ 'ambient', 'object', 'vertex', 'texture' ] as const;
type FloorMode = typeof FLOOR_MODES[ number ];

const viewer = new Viewer( { camera: { position: [ 4.3, 3.4, 1.0 ], target: [ - 4, 0.7, - 0.6 ] } } );
const { renderer, scene, settings } = viewer;

init().catch( ( error ) => viewer.showError( error ) );

async function init(): Promise<void> {

	// The static scene the probes capture: the atrium, the sun and the sky over the open roof.
	await buildSponza( viewer );

	// What the probes light: the fox walking from the sun into the arcades, and (in a probe mode of
	// "floor lighting") the floors.
	const objects = await DynamicObjects.load( viewer, { path: sponzaPath, height: SPONZA_CHARACTER_HEIGHT } );
	const floor = scene.getObjectByName( 'floors' ) as THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial> | undefined;
	let floorLighting: AddOptions | null = null;

	// The automatic layout's budget and candidate count (?budget=N&candidates=M; tests take small ones).
	const automaticBudget = Math.max( 4, Math.round( Number( viewer.query.params.get( 'budget' ) ?? 86 ) ) || 86 );
	const automaticCandidates = Math.max( 8, Math.round( Number( viewer.query.params.get( 'candidates' ) ?? 8 * automaticBudget ) ) || 8 * automaticBudget );
	const demo = new ProbeVolumeDemo( viewer, objects, {
		layouts: sponzaLayouts,
		// The probes of a layout, tetrahedralized (the 432-probe grid also trilinearly).
		createVolume: ( layout, sh ) => new LightProbeVolume( {
			positions: layout.positions, names: layout.names, roles: layout.roles, sh,
			interpolator: createProbeInterpolator( layout.positions, { outside: settings.outside } ),
			zones: settings.zones ? zonesOf( layout ) : undefined,
		} ),
		// The fox, added before the capture, which then hides it (no fox in its own probes); the
		// floors stay in the captures as built (hideInCaptures: false below).
		addObjects: ( volume ) => {

			for ( const object of objects.list ) volume.add( object );
			if ( floor && floorLighting ) volume.add( floor, floorLighting );

		},
		// A cube map at each probe, projected to SH9 on the GPU (far: the sky dome); bounces capture
		// again with the atrium lit by the probes.
		capture: async ( volume, { bounces, ...options } ) => {

			const captureOptions = { ...options, near: 0.05, far: 400 };
			if ( bounces > 0 ) await captureBounces( volume, renderer, scene, { ...captureOptions, bounces } );
			else await volume.capture( renderer, scene, captureOptions );

		},
		// "automatic layout (budget 86)": LightProbeVolume.fromScene picks 86 probes (the hand-made
		// layout's count; ?budget=N another) in the atrium's open space reachable from the fox's path,
		// placing candidates in the atrium's box (not the sky dome around it) and capturing its ~770
		// candidates (?candidates=N grid cells, default 8 per probe) at 16² at most, then the chosen
		// ones at the panel's resolution. "fit to dense captures" fits a hand-made or grid layout to a
		// grid of captures 2.5 m apart.
		automatic: {
			budget: automaticBudget, candidates: automaticCandidates, reachableFrom: [ - 9, 1.6, - 1.4 ], fitSpacing: 2.5,
			capture: { near: 0.05, far: 400 }, bounds: { min: [ - 17.4, - 0.9, - 7.8 ], max: [ 17.42, 15.66, 7.81 ] },
			candidateResolution: 16,
		},
	} );
	await demo.start();

	// The fox walks in and out of the sun: let it receive the sun's shadow and cast its own (it is
	// hidden in captures, so its shadow never reaches the probes).
	scene.traverse( ( object ) => { object.receiveShadow = true; } );
	objects.character?.object.traverse( ( object ) => { object.castShadow = true; } );

	if ( floor ) {

		// "floor lighting": the floors as built, or lit by the probes as one object, per vertex or per
		// pixel. Seen in the captures as built (probe light off), so the probes do not see themselves.
		const ambient = floor.material.emissive.clone();
		const floorMode = viewer.query.params.get( 'floor' ) ?? '';
		const params = { floor: ( FLOOR_MODES as readonly string[] ).includes( floorMode ) ? floorMode as FloorMode : 'ambient' };
		const applyFloorMode = () => {

			const mode = params.floor;
			floor.material.emissive.copy( mode === 'ambient' ? ambient : new THREE.Color( 0 ) );
			// 'sh' per vertex: the floor has a bump map, which per-vertex irradiance would ignore.
			floorLighting = mode === 'ambient' ? null : { mode, vertexOutput: 'sh', texelSize: 0.5, hideInCaptures: false };
			const volume = demo.activeVolume;
			volume.remove( floor );
			if ( floorLighting ) volume.add( floor, floorLighting );

		};

		applyFloorMode();
		demo.gui?.add( params, 'floor', FLOOR_MODES ).name( 'floor lighting' ).onChange( applyFloorMode );

	}

	const lit = floor ? [ ...objects.list, floor ] : objects.list;
	viewer.animate( ( time, delta ) => {

		objects.move( time, delta );
		demo.activeVolume.update();
		demo.showView( lit );

	} );

}
