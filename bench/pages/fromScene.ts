/**
 * Browser side of bench/fromScene.bench.ts: `LightProbeVolume.fromScene` on the demo's Basic room
 * and Sponza, beside a capture of the same candidates alone, as functions on
 * `window.fromSceneBench` that puppeteer calls; each returns raw times (ms, `performance.now()`).
 *
 * fromScene's stages are timed from its `onProgress` (each stage from its first report to the next
 * stage's); the candidates stage is split further by timing its parts alone on the same level
 * (gathering the triangles, the BVH, the inside test's closed shells, the reachability flood, the
 * whole `placeCandidates`). The candidates to capture alone are `placeCandidates`' with fromScene's
 * settings (the same function and arguments, so the same points; the Node side checks the count).
 */

import * as THREE from 'three';
import { LightProbeVolume, type FromSceneOptions, type FromSceneProgress } from '../../src/index.js';
import { TriangleBVH } from '../../src/geometry/TriangleBVH.js';
import { INSIDE_RAY_DIRECTIONS } from '../../src/placement/classifyPoints.js';
import { InsideTest } from '../../src/placement/InsideTest.js';
import { ReachableSpace } from '../../src/placement/ReachableSpace.js';
import { placeCandidates } from '../../src/runtime/probeCandidates.js';
import { gatherStaticGeometry } from '../../src/runtime/staticGeometry.js';
import { createBasicRoom } from '../../scenes/basic.js';
import { buildSponza } from '../../scenes/sponza.js';

const renderer = new THREE.WebGLRenderer( { antialias: false, powerPreference: 'high-performance' } );
renderer.setPixelRatio( 1 );
renderer.setSize( 1280, 720 );
document.body.appendChild( renderer.domElement );

/** A level and the fromScene settings of its demo page. */
interface Level {

	scene: THREE.Scene;
	budget: number;
	reachableFrom: number[];
	capture: { near: number; far: number };
	/** The box to place candidates in (Sponza: the atrium, not its sky dome). */
	bounds?: THREE.Box3;

}

const levels = new Map<string, Level>();

/** The demo's Basic room (budget 12, seed in the middle of the room, as examples/basic.ts). */
function loadBasic(): { triangles: number } {

	const scene = new THREE.Scene();
	scene.add( createBasicRoom().room );
	levels.set( 'basic', { scene, budget: 12, reachableFrom: [ 0, 1.6, 0 ], capture: { near: 0.02, far: 20 } } );
	return { triangles: gatherStaticGeometry( scene ).triangles.length / 9 };

}

/** The demo's Sponza (assets at `assets`, e.g. '/assets/'; budget 86, seed on the fox's path at eye height), or `{ error }`. */
async function loadSponza( assets: string ): Promise<{ triangles: number } | { error: string }> {

	const scene = new THREE.Scene();
	try {

		await buildSponza( { scene, renderer, assets, overlay: { progress() {} } } );

	} catch ( error ) {

		return { error: ( error as Error ).message };

	}

	// The atrium's box: the sky dome around it (radius 200) would spread the candidates over the sky.
	const bounds = new THREE.Box3();
	scene.traverse( ( object ) => {

		if ( ( object as THREE.Mesh ).isMesh && object.name !== 'sky' ) bounds.expandByObject( object );

	} );
	levels.set( 'sponza', { scene, budget: 86, reachableFrom: [ - 9, 1.6, - 1.4 ], capture: { near: 0.05, far: 400 }, bounds } );
	return { triangles: gatherStaticGeometry( scene ).triangles.length / 9 };

}

function level( name: string ): Level {

	const entry = levels.get( name );
	if ( ! entry ) throw new Error( `fromSceneBench: level ${name} is not loaded` );
	return entry;

}

/** The settings of one run: the level's, with the resolution and the fit switch. */
function optionsOf( entry: Level, resolution: number, fit: boolean, onProgress?: ( p: FromSceneProgress ) => void ): FromSceneOptions {

	const { budget, reachableFrom, bounds, capture } = entry;
	return { budget, reachableFrom, bounds, resolution, fit, capture, onProgress };

}

/**
 * A small fromScene and capture on the level (4 probes of about 64 grid candidates, 0.3 clear of surfaces), untimed: it
 * compiles the level's shaders and draws its shadow maps once, so the timed runs do not pay for that.
 */
async function warmUp( name: string, resolution: number ): Promise<void> {

	const entry = level( name );
	const options = { ...optionsOf( entry, resolution, true ), budget: 4, candidates: 64, clearance: 0.3 };
	const volume = await LightProbeVolume.fromScene( renderer, entry.scene, options );
	volume.dispose();

}

/** One fromScene run: total time and per stage (from the first report of a stage to the next stage's first). */
async function fromScene( name: string, resolution: number, fit: boolean ): Promise<{
	ms: number; stages: Record<string, number>; probes: number; candidates: number;
}> {

	const entry = level( name );
	const starts: [ string, number ][] = [];
	const onProgress = ( { stage }: FromSceneProgress ) => {

		if ( starts.length === 0 || starts[ starts.length - 1 ][ 0 ] !== stage ) starts.push( [ stage, performance.now() ] );

	};

	const start = performance.now();
	const volume = await LightProbeVolume.fromScene( renderer, entry.scene, optionsOf( entry, resolution, fit, onProgress ) );
	const end = performance.now();
	const stages: Record<string, number> = {};
	starts.forEach( ( [ stage, at ], i ) => {

		stages[ stage ] = ( i + 1 < starts.length ? starts[ i + 1 ][ 1 ] : end ) - at;

	} );
	stages.setup = starts.length ? starts[ 0 ][ 1 ] - start : 0;
	const candidates = Number( /of (\d+) candidates/.exec( volume.metadata )?.[ 1 ] ?? NaN );
	const probes = volume.positions.length / 3;
	volume.dispose();
	return { ms: end - start, stages, probes, candidates };

}

/** The candidates fromScene places on this level (the same function and settings). */
function candidatesOf( entry: Level ): Float64Array {

	const geometry = gatherStaticGeometry( entry.scene );
	return placeCandidates( 'fromSceneBench', geometry, settingsOf( entry ) ).positions;

}

/** fromScene's settings of `placeCandidates` for the level. */
function settingsOf( entry: Level ) {

	return { reachableFrom: Float64Array.from( entry.reachableFrom ), bounds: entry.bounds, candidates: Math.max( 256, 8 * entry.budget ) };

}

const candidateCache = new Map<string, Float64Array>();

/** The capture of fromScene's candidates alone (a volume over them, captured with the same options). */
async function captureCandidates( name: string, resolution: number ): Promise<{ ms: number; candidates: number }> {

	const entry = level( name );
	let positions = candidateCache.get( name );
	if ( ! positions ) candidateCache.set( name, positions = candidatesOf( entry ) );
	const start = performance.now();
	const volume = new LightProbeVolume( { positions } );
	await volume.capture( renderer, entry.scene, { ...entry.capture, resolution } );
	const ms = performance.now() - start;
	volume.dispose();
	return { ms, candidates: positions.length / 3 };

}

/** The parts of the candidates stage, each timed alone on the level (ms). */
function placementParts( name: string ): Record<string, number> {

	const entry = level( name );
	const seeds = Float64Array.from( entry.reachableFrom );
	let t = performance.now();
	const geometry = gatherStaticGeometry( entry.scene );
	const gather = performance.now() - t;
	t = performance.now();
	const bvh = new TriangleBVH( geometry.triangles );
	const tree = performance.now() - t;
	t = performance.now();
	new InsideTest( bvh, geometry.sides, INSIDE_RAY_DIRECTIONS ).treatAsRooms( seeds );
	const shells = performance.now() - t;
	t = performance.now();
	const box = placeCandidates( 'fromSceneBench', geometry, settingsOf( entry ) ).box;
	t = performance.now();
	// The flood's box as placeCandidates gives it: the candidates' box grown to hold the seeds.
	for ( let a = 0; a < 3; a ++ ) {

		box[ a ] = Math.min( box[ a ], seeds[ a ] );
		box[ 3 + a ] = Math.max( box[ 3 + a ], seeds[ a ] );

	}

	new ReachableSpace( bvh, seeds, { bounds: box } );
	const flood = performance.now() - t;
	t = performance.now();
	placeCandidates( 'fromSceneBench', geometry, settingsOf( entry ) );
	const place = performance.now() - t;
	return { gather, bvh: tree, shells, flood, placeCandidates: place };

}

function info(): { renderer: string; three: string } {

	const gl = renderer.getContext();
	const debug = gl.getExtension( 'WEBGL_debug_renderer_info' );
	const name = debug ? gl.getParameter( debug.UNMASKED_RENDERER_WEBGL ) : gl.getParameter( gl.RENDERER );
	return { renderer: String( name ), three: THREE.REVISION };

}

const api = { loadBasic, loadSponza, warmUp, fromScene, captureCandidates, placementParts, info };
Object.assign( window, { fromSceneBench: api, fromSceneBenchReady: true } );
export type FromSceneBenchApi = typeof api;
