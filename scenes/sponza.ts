import * as THREE from 'three';
import { GridInterpolator } from 'three-capture-lighting/math';
import arbitrary from './sponza.json';
import { addStaticSun, createSky, loadOBJScene, maxAnisotropy, type SceneHost } from './loadOBJScene.js';
import type { ProbeLayout } from './layout.js';

/**
 * The paper's Sponza (Dabrovic's atrium, Table 4: 432 grid probes vs 85 placed with meaning): an
 * open-sky courtyard with two floors of arcades round it. A high sun from the east lights the
 * courtyard's west half and its west facade; the sky (an emissive dome the probes capture) lights
 * the rest through the open roof.
 */
export async function buildSponza( app: SceneHost ): Promise<void> {

	const { object } = await loadOBJScene( {
		url: app.assets + 'sponza/',
		obj: 'sponza.obj',
		ambient: 0.3,
		bumpScale: 0.8,
		anisotropy: maxAnisotropy( app.renderer ),
		source: 'The Sponza page needs the Dabrovic Sponza (sponza.obj, sponza.mtl and its 16 textures, from McGuire\'s Computer Graphics Archive) in the folder sponza/ of the asset folder: ../shared/assets/ beside the repository, or the folder named by CAPTURE_LIGHTING_ASSETS, or pass ?assets=URL.',
		onProgress: ( text, fraction ) => app.overlay.progress( text, fraction ),
	} );
	app.scene.add( object );

	// The sun: its shadow shapes the courtyard's sunlit patch (a capture draws its shadow map once).
	addStaticSun( app, { direction: SPONZA_SUN, color: 0xfff1dc, intensity: 5, extent: 20 } );

	// The sky over the open roof, something the probes can capture: a dome of sky radiance.
	app.scene.add( createSky( { zenith: 0x4f86d9, horizon: 0xb8d2ee, ground: 0x5a5046, intensity: 1.2 } ) );

}

/** Direction towards the sun: from the east, high (57° above the horizon). */
export const SPONZA_SUN = new THREE.Vector3( 0.65, 1, 0.1 ).normalize();

/** The fox's height: Sponza is in metres. */
export const SPONZA_CHARACTER_HEIGHT = 1.0;

/**
 * The fox's loop on the ground floor (y = 0.09): east across the courtyard from its sunlit west half
 * into the shade, under an arch into the north arcade, back west along it, out under another arch
 * and through the west end arch, where the sun reaches into the arcade.
 */
export const sponzaPath = new THREE.CatmullRomCurve3( [
	[ - 9, - 1.4 ], [ - 3, - 1.6 ], [ 3, - 1.5 ], [ 7.5, - 0.6 ], [ 8.8, 1.6 ], [ 8.7, 3.6 ], [ 6.8, 5.3 ],
	[ 0, 5.5 ], [ - 6.8, 5.3 ], [ - 8.7, 3.6 ], [ - 9.6, 1.2 ], [ - 12.6, 0.2 ], [ - 11.2, - 1.2 ],
].map( ( [ x, z ] ) => new THREE.Vector3( x, 0.09, z ) ), true, 'centripetal' );

/** The paper's 12 × 6 × 6 grid (432 probes) over the interior, inset so that no probe is inside geometry. */
export const sponzaGrid = { min: [ - 15.6, 0.45, - 6.6 ], max: [ 15.6, 14.6, 6.6 ], counts: [ 12, 6, 6 ] };

/** Layouts: 85 probes placed with meaning, and the 12 × 6 × 6 grid. */
export const sponzaLayouts: ProbeLayout[] = [
	arbitrary as ProbeLayout,
	{ name: '12x6x6 grid (432 probes)', positions: Array.from( new GridInterpolator( sponzaGrid.min, sponzaGrid.max, sponzaGrid.counts ).positions ), grid: sponzaGrid },
];
