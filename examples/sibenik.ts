import { DemoApp } from './common/DemoApp.js';
import { buildSibenik, sibenikLayouts, sibenikPath, SIBENIK_CHARACTER_HEIGHT } from '@scenes/sibenik.js';

// The paper's Sibenik (Table 4: 432 grid probes vs 39 placed with meaning): a closed cathedral lit
// through its windows. 39 probes — bounce probes on the floors, probes under the arches and at the
// windows, one by the stained-glass rose window, one in the sky — light the fox as it walks up the
// nave and back down the aisle through patches of sun.

const app = new DemoApp( {
	layouts: sibenikLayouts,
	camera: { position: [ - 14.5, - 12.9, - 0.8 ], target: [ - 6, - 14.4, 2.2 ] },
	path: sibenikPath,
	characterHeight: SIBENIK_CHARACTER_HEIGHT,
	capture: { near: 0.05, far: 400 },
	build: buildSibenik,
} );

// The fox walks through patches of sun: once it is loaded, let it receive the sun's shadow.
app.start().then( () => app.scene.traverse( ( object ) => { object.receiveShadow = true; } ) );
