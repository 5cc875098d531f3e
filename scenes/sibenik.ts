import * as THREE from 'three';
import { GridInterpolator } from 'three-capture-lighting/math';
import arbitrary from './sibenik.json';
import { addStaticSun, createSky, loadOBJScene, maxAnisotropy, type SceneHost } from './loadOBJScene.js';
import type { ProbeLayout } from './layout.js';

/** Stained glass of the rose window: MTL name → glow (linear RGB). */
const GLASS: Record<string, [ number, number, number ]> = {
	staklo_crveno: [ 1.0, 0.12, 0.05 ],
	staklo_zeleno: [ 0.15, 0.8, 0.25 ],
	staklo_plavo: [ 0.15, 0.3, 1.0 ],
	staklo_zuto: [ 1.0, 0.75, 0.15 ],
};

/**
 * The paper's Sibenik (Dabrovic's cathedral, Table 4: 432 grid probes vs 39 placed with meaning): a
 * closed interior lit through its windows. The sun falls through the north windows onto the aisle
 * floors, the sky shows through every window (an emissive dome the probes capture), the rose
 * window's stained glass glows, and two warm lamps light the crossing and the altar.
 */
export async function buildSibenik( app: SceneHost ): Promise<void> {

	const { object } = await loadOBJScene( {
		url: app.assets + 'sibenik/',
		obj: 'sibenik.obj',
		ambient: 0.12,
		bumpScale: 0.8,
		anisotropy: maxAnisotropy( app.renderer ),
		source: 'The Sibenik page needs the Dabrovic Sibenik cathedral (sibenik.obj, untitled.mtl and its 5 textures, from McGuire\'s Computer Graphics Archive) in the folder sibenik/ of the asset folder: ../shared/assets/ beside the repository, or the folder named by CAPTURE_LIGHTING_ASSETS, or pass ?assets=URL.',
		onProgress: ( text, fraction ) => app.overlay.progress( text, fraction ),
		onMaterial( material ) {

			const glow = GLASS[ material.name ];
			if ( ! glow ) return;
			material.color.setRGB( 0, 0, 0 );
			material.emissive.setRGB( ...glow ).multiplyScalar( 3 );
			material.emissiveMap = null;
			material.transparent = false;
			material.opacity = 1;

		},
	} );
	app.scene.add( object );

	// The sun through the windows (a capture draws its shadow map once).
	addStaticSun( app, { direction: SIBENIK_SUN, color: 0xfff0d8, intensity: 6, extent: 24, mapSize: 4096 } );

	// Warm lamps over the crossing and the altar, with a visible bulb each.
	for ( const [ x, y, z, intensity ] of [ [ 6.8, - 8.5, 0, 60 ], [ 15.5, - 10, 0, 40 ] ] ) {

		const lamp = new THREE.PointLight( 0xffb45a, intensity, 0, 2 );
		lamp.position.set( x, y, z );
		const bulb = new THREE.Mesh(
			new THREE.SphereGeometry( 0.12, 12, 6 ),
			new THREE.MeshBasicMaterial( { color: new THREE.Color( 0xffb45a ).multiplyScalar( 4 ) } )
		);
		bulb.position.copy( lamp.position );
		app.scene.add( lamp, bulb );

	}

	app.scene.add( createSky( { zenith: 0x4f86d9, horizon: 0xc4dcf2, ground: 0x6a6052, intensity: 1.5 } ) );

}

/** Direction towards the sun: from the north (−z), 55° high. */
export const SIBENIK_SUN = new THREE.Vector3( 0, 1.43, - 1 ).normalize();

/** The fox's height: Sibenik is in metres. */
export const SIBENIK_CHARACTER_HEIGHT = 1.0;

/**
 * The fox's loop: east up the nave (floor y = −15.3), through an arch into the south aisle (floor
 * −15.15) across the patches of sun from the north windows, and back through another arch near
 * the rose window.
 */
export const sibenikPath = new THREE.CatmullRomCurve3( [
	[ - 16, - 15.3, 1.0 ], [ - 10, - 15.3, 1.4 ], [ - 4.5, - 15.3, 1.6 ], [ - 2.3, - 15.3, 2.8 ], [ - 2.4, - 15.15, 4.9 ],
	[ - 4.6, - 15.15, 5.2 ], [ - 10.25, - 15.15, 5.2 ], [ - 13.4, - 15.15, 4.9 ], [ - 13.9, - 15.3, 3.1 ], [ - 15.4, - 15.3, 1.3 ],
].map( ( p ) => new THREE.Vector3( ...p ) ), true, 'centripetal' );

/**
 * The paper's 12 × 6 × 6 grid (432 probes) over the interior. A regular grid cannot step around the
 * raised crossing and apse floors or the aisles' roof spaces: `checkLayouts.ts` lists the grid
 * probes that end up inside geometry.
 */
export const sibenikGrid = { min: [ - 18.8, - 14.85, - 5.4 ], max: [ 17.8, 15.5, 5.4 ], counts: [ 12, 6, 6 ] };

/** Layouts: 39 probes placed with meaning, and the 12 × 6 × 6 grid. */
export const sibenikLayouts: ProbeLayout[] = [
	arbitrary as ProbeLayout,
	{ name: '12x6x6 grid (432 probes)', positions: Array.from( new GridInterpolator( sibenikGrid.min, sibenikGrid.max, sibenikGrid.counts ).positions ), grid: sibenikGrid },
];
