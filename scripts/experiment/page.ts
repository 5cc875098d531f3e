/**
 * Browser side of the experiment (scripts/experiment/run.ts): builds one of the paper's scenes
 * with its own scene module — the same static geometry, materials, textures, lights, shadows and
 * sky as the demo pages — and captures SH9 at any list of positions with one `ProbeCapturer`.
 * The Node side calls the functions on `window.experiment` through puppeteer; bulk arrays travel
 * as base64 strings of typed arrays.
 */

import * as THREE from 'three';
import { placeFromMeshes } from '../../src/index.js';
import { ProbeCapturer } from '../../src/capture.js';
import type { ProbeLayout } from '../../scenes/layout.js';
import type { SceneHost } from '../../scenes/loadOBJScene.js';
import { toBase64 } from './pageData.js';

/** A probe grid over a box, as the scene modules define the paper's grid. */
export interface GridBox { min: number[]; max: number[]; counts: number[] }

/** What `load` returns. */
export interface LoadedScene {

	/** The hand-made layout of the scene module (the paper's "arbitrary" probes). */
	hand: ProbeLayout;

	/** The paper's grid over the interior, as the scene module defines it. */
	grid: GridBox;

	/** Triangles the cube camera sees, but the sky dome: 9 floats each (Float32, base64). */
	triangles: string;

	/**
	 * Per triangle (Int8, base64): 1 when only its front side (counter-clockwise) is drawn,
	 * −1 when only its back side, 0 when both.
	 */
	sides: string;

	/** Renderer and scene facts for the report. */
	info: Record<string, string | number | boolean>;

}

/** Capture settings, the same for every layout of a run. */
export interface CaptureRequest { resolution: number; near: number; far: number }

/** The functions the Node side calls. */
export interface ExperimentApi {

	load( scene: string, assets: string ): Promise<LoadedScene>;
	vertexCandidates( options: { offset: number; minSpacing: number; bounds: { min: number[]; max: number[] } } ): string;
	capture( positions: number[], settings: CaptureRequest, label: string ): Promise<{ sh: string; ms: number }>;

}

const renderer = new THREE.WebGLRenderer( { antialias: false } );
renderer.setPixelRatio( 1 );
renderer.setSize( 64, 64 );
document.body.appendChild( renderer.domElement );
const scene = new THREE.Scene();
const capturers = new Map<string, ProbeCapturer>();

const api: ExperimentApi = {

	async load( name, assets ) {

		const host: SceneHost = { scene, renderer, assets, overlay: { progress() {} } };
		let hand: ProbeLayout, grid: GridBox;
		if ( name === 'basic' ) {

			const { createBasicRoom, basicLayouts, basicGrid } = await import( '../../scenes/basic.js' );
			scene.add( createBasicRoom().room );
			hand = basicLayouts.find( ( layout ) => ! layout.grid )!;
			grid = basicGrid;

		} else if ( name === 'sponza' ) {

			const { buildSponza, sponzaLayouts, sponzaGrid } = await import( '../../scenes/sponza.js' );
			await buildSponza( host );
			hand = sponzaLayouts.find( ( layout ) => ! layout.grid )!;
			grid = sponzaGrid;

		} else if ( name === 'sibenik' ) {

			const { buildSibenik, sibenikLayouts, sibenikGrid } = await import( '../../scenes/sibenik.js' );
			await buildSibenik( host );
			hand = sibenikLayouts.find( ( layout ) => ! layout.grid )!;
			grid = sibenikGrid;

		} else {

			throw new Error( `unknown scene "${name}"` );

		}

		const { triangles, sides } = gatherVisibleTriangles( scene );
		const gl = renderer.getContext();
		const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
		let lights = 0, meshes = 0, textures = 0;
		scene.traverse( ( object ) => {

			if ( ( object as THREE.Light ).isLight ) lights ++;
			const mesh = object as THREE.Mesh;
			if ( mesh.isMesh ) {

				meshes ++;
				const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
				for ( const material of materials ) if ( ( material as THREE.MeshStandardMaterial ).map ) textures ++;

			}

		} );

		return {
			hand: { name: hand.name, positions: Array.from( hand.positions ) },
			grid: { min: Array.from( grid.min ), max: Array.from( grid.max ), counts: Array.from( grid.counts ) },
			triangles: toBase64( triangles ),
			sides: toBase64( sides ),
			info: {
				renderer: debug ? String( gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) ) : String( gl.getParameter( gl.RENDERER ) ),
				three: THREE.REVISION,
				triangles: sides.length,
				meshes,
				lights,
				texturedMaterialSlots: textures,
				shadows: renderer.shadowMap.enabled,
			},
		};

	},

	vertexCandidates( { offset, minSpacing, bounds } ) {

		// Inside/outside is decided on the Node side (by what the capture would see), so only the
		// vertex offset, the spacing and the box are applied here.
		const box = new THREE.Box3( new THREE.Vector3().fromArray( bounds.min ), new THREE.Vector3().fromArray( bounds.max ) );
		// The sky dome's vertices lie far outside the box, so the whole scene can be passed.
		const points = placeFromMeshes( scene, { offset, minSpacing, rejectInside: false, minDistance: 0, bounds: box } );
		return toBase64( Float32Array.from( points ) );

	},

	async capture( positions, settings, label ) {

		const key = `${settings.resolution}|${settings.near}|${settings.far}`;
		let capturer = capturers.get( key );
		if ( ! capturer ) {

			// The library's defaults (HalfFloat targets: linear HDR, no clipping; exact solid
			// angles); the same settings for every layout and the ground truth.
			capturer = new ProbeCapturer( renderer, {
				resolution: settings.resolution, near: settings.near, far: settings.far, type: THREE.HalfFloatType,
			} );
			capturers.set( key, capturer );
			// Warm-up, not timed: shader compilation and the shadow maps' one-off render.
			await capturer.capture( scene, positions.slice( 0, 3 ), new Float32Array( 27 ) );

		}

		const count = positions.length / 3;
		const target = new Float32Array( 27 * count );
		let reported = 0;
		const start = performance.now();
		await capturer.capture( scene, positions, target, {
			onProgress( done, total ) {

				// Probes submitted (the GPU may still be drawing them).
				if ( done === total || done - reported >= Math.max( 50, total / 10 ) ) {

					reported = done;
					console.log( `[experiment] ${label}: ${done} / ${total} probes submitted` );

				}

			},
		} );
		const ms = performance.now() - start;
		return { sh: toBase64( target ), ms };

	},

};

/** Every triangle of every visible mesh but the sky dome, in world space, with the side(s) its material draws. */
function gatherVisibleTriangles( root: THREE.Object3D ): { triangles: Float32Array; sides: Int8Array } {

	root.updateMatrixWorld( true );
	const triangles: number[] = [], sides: number[] = [];
	const v = new THREE.Vector3();
	root.traverseVisible( ( object ) => {

		const mesh = object as THREE.Mesh;
		// The sky dome is 200 m away: a ray that reaches it left the scene.
		if ( ! mesh.isMesh || mesh.name === 'sky' ) return;
		const geometry = mesh.geometry;
		const position = geometry.getAttribute( 'position' );
		if ( ! position ) return;
		const index = geometry.index;
		const total = index ? index.count : position.count;
		const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
		const groups = geometry.groups.length > 0 ? geometry.groups : [ { start: 0, count: total, materialIndex: 0 } ];
		const mirrored = mesh.matrixWorld.determinant() < 0;
		for ( const group of groups ) {

			const material = materials[ group.materialIndex ?? 0 ];
			if ( ! material || ! material.visible ) continue;
			let side = material.side === THREE.DoubleSide ? 0 : material.side === THREE.BackSide ? - 1 : 1;
			if ( mirrored ) side = - side;
			const end = Math.min( total, group.start + group.count );
			for ( let i = group.start; i + 2 < end; i += 3 ) {

				for ( let corner = 0; corner < 3; corner ++ ) {

					v.fromBufferAttribute( position, index ? index.getX( i + corner ) : i + corner ).applyMatrix4( mesh.matrixWorld );
					triangles.push( v.x, v.y, v.z );

				}

				sides.push( side );

			}

		}

	} );

	return { triangles: Float32Array.from( triangles ), sides: Int8Array.from( sides ) };

}

( window as unknown as { experiment: ExperimentApi } ).experiment = api;
( window as unknown as { experimentReady: boolean } ).experimentReady = true;
