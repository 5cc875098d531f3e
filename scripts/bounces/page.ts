/**
 * Browser side of the bounce measurement (scripts/bounces/run.ts): builds the Sibenik scene with
 * its own scene module (the demo page's geometry, materials, sun, lamps, stained glass and sky),
 * and captures its hand-made probe layout with `captureBounces`. The Node side calls the functions
 * on `window.bounces` through puppeteer; SH travel as base64 strings of Float32Arrays.
 *
 * The scene's stand-in for indirect light is `loadOBJScene`'s `ambient: 0.12`: every surface
 * without an emission of its own glows with 0.12 × its diffuse colour (and texture). It is not a
 * light (the scene has no AmbientLight or HemisphereLight — `load` reports the lights), so it is
 * switched off here by setting those materials' emissive to black; the stained glass keeps its glow.
 */

import * as THREE from 'three';
import { LightProbeVolume } from '../../src/index.js';
import { captureBounces } from '../../src/runtime/captureBounces.js';
import type { SceneHost } from '../../scenes/loadOBJScene.js';
import { toBase64 } from '../experiment/pageData.js';

/** What `load` returns. */
export interface LoadedBounceScene {

	/** The hand-made layout. */
	layout: { name: string; positions: number[]; names: string[] };

	/** Materials whose emission is the 0.12 × diffuse stand-in, and those that glow for real. */
	standInMaterials: string[];
	glowingMaterials: string[];

	/** Lights of the scene, by type. */
	lights: Record<string, number>;

	info: Record<string, string | number | boolean>;

}

/** One run's request. */
export interface BounceRequest { resolution: number; near: number; far: number; bounces: number; standIn: boolean; output: 'irradiance' | 'sh' }

/** One run's answer. */
export interface BounceAnswer {

	/** Per pass: 27 floats per probe, base64. */
	sh: string[];
	passes: { pass: number; meanL00: number[]; captureMs: number; lightingMs: number }[];
	staticMeshes: number;
	vertices: number;
	totalMs: number;
	warmUpMs: number;

}

export interface BounceApi {

	load( assets: string ): Promise<LoadedBounceScene>;
	run( request: BounceRequest ): Promise<BounceAnswer>;

}

const renderer = new THREE.WebGLRenderer( { antialias: false } );
renderer.setPixelRatio( 1 );
renderer.setSize( 64, 64 );
document.body.appendChild( renderer.domElement );
const scene = new THREE.Scene();
/** Stand-in materials and their emissive colour. */
const standIn = new Map<THREE.MeshStandardMaterial, THREE.Color>();
let layout: LoadedBounceScene[ 'layout' ] | null = null;

const api: BounceApi = {

	async load( assets ) {

		const host: SceneHost = { scene, renderer, assets, overlay: { progress() {} } };
		const { buildSibenik, sibenikLayouts } = await import( '../../scenes/sibenik.js' );
		await buildSibenik( host );
		const hand = sibenikLayouts.find( ( candidate ) => ! candidate.grid )!;
		layout = { name: hand.name, positions: Array.from( hand.positions ), names: Array.from( hand.names ?? [] ) };

		const lights: Record<string, number> = {};
		const glowing = new Set<string>();
		let meshes = 0, vertices = 0, triangles = 0;
		const expected = new THREE.Color();
		scene.traverse( ( object ) => {

			if ( ( object as THREE.Light ).isLight ) lights[ object.type ] = ( lights[ object.type ] ?? 0 ) + 1;
			const mesh = object as THREE.Mesh;
			if ( ! mesh.isMesh || mesh.name === 'sky' ) return;
			meshes ++;
			const position = mesh.geometry.getAttribute( 'position' );
			vertices += position.count;
			triangles += ( mesh.geometry.index?.count ?? position.count ) / 3;
			for ( const material of Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ] ) {

				const standard = material as THREE.MeshStandardMaterial;
				if ( standard.isMeshStandardMaterial !== true || standard.emissive.getHex() === 0 ) continue;
				// loadOBJScene's stand-in: emissive = 0.12 × colour, with the colour's map.
				expected.copy( standard.color ).multiplyScalar( 0.12 );
				const emissive = standard.emissive;
				const distance = Math.abs( expected.r - emissive.r ) + Math.abs( expected.g - emissive.g )
					+ Math.abs( expected.b - emissive.b );
				const isStandIn = standard.emissiveMap === standard.map && distance < 1e-5;
				if ( isStandIn ) standIn.set( standard, standard.emissive.clone() );
				else glowing.add( standard.name );

			}

		} );

		const gl = renderer.getContext();
		const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
		return {
			layout,
			standInMaterials: [ ...standIn.keys() ].map( ( material ) => material.name ).sort(),
			glowingMaterials: [ ...glowing ].sort(),
			lights,
			info: {
				renderer: debug ? String( gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) ) : String( gl.getParameter( gl.RENDERER ) ),
				three: THREE.REVISION, meshes, vertices, triangles, shadows: renderer.shadowMap.enabled,
			},
		};

	},

	async run( request ) {

		if ( ! layout ) throw new Error( 'load() first' );
		for ( const [ material, emissive ] of standIn ) material.emissive.copy( request.standIn ? emissive : new THREE.Color( 0 ) );
		const volume = new LightProbeVolume( { positions: layout.positions, names: layout.names } );
		const capture = { resolution: request.resolution, near: request.near, far: request.far };
		// Warm-up, not counted: shader compilation and the sun's one-off shadow map.
		const warmUpStart = performance.now();
		await volume.capture( renderer, scene, { ...capture, indices: [ 0 ] } );
		const warmUpMs = performance.now() - warmUpStart;
		const sh: string[] = [];
		const result = await captureBounces( volume, renderer, scene, {
			...capture, bounces: request.bounces, output: request.output,
			onPass( pass, passSH ) {

				sh.push( toBase64( passSH ) );
				console.log( `[bounces] pass ${pass} captured` );

			},
		} );
		volume.dispose();
		return {
			sh,
			passes: result.passes.map( ( pass ) => ( { ...pass, meanL00: [ ...pass.meanL00 ] } ) ),
			staticMeshes: result.staticMeshes.length,
			vertices: result.vertices,
			totalMs: result.totalMs,
			warmUpMs,
		};

	},

};

( window as unknown as { bounces: BounceApi } ).bounces = api;
( window as unknown as { bouncesReady: boolean } ).bouncesReady = true;
