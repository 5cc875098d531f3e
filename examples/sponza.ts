import { DemoApp } from './common/DemoApp.js';
import { buildSponza, sponzaLayouts, sponzaPath, SPONZA_CHARACTER_HEIGHT } from '@scenes/sponza.js';

// The paper's Sponza (Table 4: 432 grid probes vs 85 placed with meaning): an open-sky atrium.
// The sun lights half of the courtyard; the fox walks from the sun patch into the shade and under
// the arcades, lit by the four probes of the tetrahedron around it.

const app = new DemoApp( {
	layouts: sponzaLayouts,
	camera: { position: [ 4.3, 3.4, 1.0 ], target: [ - 4, 0.7, - 0.6 ] },
	path: sponzaPath,
	characterHeight: SPONZA_CHARACTER_HEIGHT,
	capture: { near: 0.05, far: 400 },
	build: buildSponza,
} );

// The fox walks in and out of the sun: once it is loaded, let it receive the sun's shadow.
app.start().then( () => app.scene.traverse( ( object ) => { object.receiveShadow = true; } ) );
