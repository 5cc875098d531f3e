import * as THREE from 'three';
import { DemoApp } from './common/DemoApp.js';
import { buildSponza, sponzaLayouts, sponzaPath, SPONZA_CHARACTER_HEIGHT } from '@scenes/sponza.js';

// The paper's Sponza (Table 4: 432 grid probes vs 85 placed with meaning): an open-sky atrium.
// The sun lights half of the courtyard; the fox walks from the sun patch into the shade and under
// the arcades, lit by the four probes of the tetrahedron around it.
//
// Large objects: the floors are one 35 × 11 m mesh. Lit as one object they get one colour, from the
// probes at their centre (in the courtyard air); per vertex or through a 3D SH texture over their
// bounds they follow the probes across the courtyard and under the arcades. "ambient" is the scene
// as built: a flat emissive stand-in for indirect light, which the probe modes replace.
// ?floor=ambient|object|vertex|texture selects one.

const app = new DemoApp( {
	layouts: sponzaLayouts,
	camera: { position: [ 4.3, 3.4, 1.0 ], target: [ - 4, 0.7, - 0.6 ] },
	path: sponzaPath,
	characterHeight: SPONZA_CHARACTER_HEIGHT,
	capture: { near: 0.05, far: 400 },
	build: buildSponza,
} );

const FLOOR_MODES = [ 'ambient', 'object', 'vertex', 'texture' ] as const;

app.start().then( () => {

	// The fox walks in and out of the sun: let it receive the sun's shadow.
	app.scene.traverse( ( object ) => { object.receiveShadow = true; } );

	const floor = app.scene.getObjectByName( 'floors' ) as THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial> | undefined;
	if ( ! floor ) return;
	const ambient = floor.material.emissive.clone();
	const params = { floor: ( FLOOR_MODES as readonly string[] ).includes( app.query.get( 'floor' ) ?? '' ) ? app.query.get( 'floor' )! : 'ambient' };
	const apply = () => {

		const mode = params.floor as typeof FLOOR_MODES[ number ];
		floor.material.emissive.copy( mode === 'ambient' ? ambient : new THREE.Color( 0 ) );
		// 'sh' per vertex: the floor has a bump map, which per-vertex irradiance would ignore.
		app.setScenery( floor, mode === 'ambient' ? null : { mode, vertexOutput: 'sh', texelSize: 0.5, hideInCaptures: false } );

	};

	apply();
	app.gui?.add( params, 'floor', FLOOR_MODES ).name( 'floor lighting' ).onChange( apply );

} );
