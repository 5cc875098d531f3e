/**
 * `LightProbeVolume.fromScene` end to end on a real GL context (headless-gl, WebGL2), in the Basic
 * room (scenes/basic.ts): a volume of exactly `budget` probes in the room's open space, the stages
 * reported in order, fitted to the candidates' captures (its record says so) and better on
 * held-out points than the same pipeline without the fit; a candidate resolution below the
 * volume's adds the recapture stage; objects marked dynamic are hidden from every capture.
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/fromScene.gpu.test.ts`.
 */

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { volumeFromScene, type FromSceneProgress } from '../../src/runtime/volumeFromScene.js';
import type { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { irradianceError } from '../../src/placement/irradianceError.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { seededRandom } from '../helpers/pointSets.js';
import { boxDistance } from '../placement/helpers.js';
import { createBasicRoom } from '../../scenes/basic.js';
import { placeCandidates } from '../../src/runtime/probeCandidates.js';
import { gatherStaticGeometry } from '../../src/runtime/staticGeometry.js';

const ctx = await createHeadlessRenderer( 16, 16 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** The volume's blend at each point. */
function sampled( volume: LightProbeVolume, points: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 9 * points.length );
	for ( let i = 0; i < points.length / 3; i ++ ) {

		volume.sample( [ points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] ], out.subarray( 27 * i, 27 * i + 27 ) );

	}

	return out;

}

/** The stages in the order they were reported. */
function stagesOf( events: FromSceneProgress[] ): string[] {

	const order: string[] = [];
	for ( const { stage } of events ) if ( order[ order.length - 1 ] !== stage ) order.push( stage );
	return order;

}

describe.skipIf( ! ctx.renderer )( `LightProbeVolume.fromScene on headless-gl${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const scene = new THREE.Scene();
	scene.add( createBasicRoom().room );
	const spawn = [ 0, 1.6, 0 ];
	const BULB = [ 0.2, 2.1, 0.3 ];
	// 60 held-out points in the room, 0.3 or more from the walls and 0.4 from the bulb, captured at 16².
	const held: number[] = [];
	const random = seededRandom( 21 );
	while ( held.length < 3 * 60 ) {

		const x = 3.4 * random() - 1.7, y = 0.3 + 2.4 * random(), z = 3.4 * random() - 1.7;
		if ( Math.hypot( x - BULB[ 0 ], y - BULB[ 1 ], z - BULB[ 2 ] ) >= 0.4 ) held.push( x, y, z );

	}

	let truth: Float32Array;
	beforeAll( async () => {

		const capturer = new ProbeCapturer( renderer, { resolution: 16 } );
		truth = await capturer.capture( scene, held, new Float32Array( 27 * 60 ) );
		capturer.dispose();

	} );
	afterAll( () => ctx.dispose() );

	it( 'budget 12: exactly 12 probes in the room\'s open space, stages in order, fitted, better held out than without the fit', async () => {

		const events: FromSceneProgress[] = [];
		const onProgress = ( p: FromSceneProgress ) => events.push( { ...p } );
		const options = { budget: 12, resolution: 16, reachableFrom: spawn, onProgress };
		const volume = await volumeFromScene( renderer, scene, options );
		expect( volume.count ).toBe( 12 );
		expect( stagesOf( events ) ).toEqual( [ 'candidates', 'capture', 'reduce', 'fit' ] );
		for ( const stage of [ 'candidates', 'capture', 'reduce', 'fit' ] ) {

			const of = events.filter( ( p ) => p.stage === stage );
			expect( of[ of.length - 1 ].done ).toBe( of[ of.length - 1 ].total );

		}

		const candidates = events.filter( ( p ) => p.stage === 'capture' ).pop()!.total;
		for ( let i = 0; i < volume.positions.length; i += 3 ) {

			const [ x, y, z ] = [ volume.positions[ i ], volume.positions[ i + 1 ], volume.positions[ i + 2 ] ];
			expect( boxDistance( x, y, z, 0, 1.5, 0, 2, 1.5, 2 ) ).toBeLessThan( - 0.1 );

		}

		expect( volume.fitSettings ).toMatchObject( { samples: candidates, gradients: false } );
		expect( volume.fitSettings!.source ).toBe( `the ${candidates} candidates of fromScene, captured at 16²` );
		expect( volume.captureSettings.resolution ).toBe( 16 );
		expect( volume.metadata ).toMatch( /^LightProbeVolume\.fromScene: 12 probes of \d+ candidates captured at 16² \(fitted\)/ );

		const unfitted = await volumeFromScene( renderer, scene, { ...options, fit: false, onProgress: undefined } );
		expect( unfitted.fitSettings ).toBeNull();
		const fittedError = irradianceError( sampled( volume, held ), truth ).mean;
		const plainError = irradianceError( sampled( unfitted, held ), truth ).mean;
		console.log( `fromScene, Basic room, 12 probes: held-out mean error ${fittedError.toFixed( 4 )} fitted, ${plainError.toFixed( 4 )} without the fit` );
		expect( fittedError ).toBeLessThan( plainError );
		volume.dispose();
		unfitted.dispose();

	} );

	it( 'a candidate resolution below the volume\'s: the chosen probes are captured again (stage recapture), at the volume\'s', async () => {

		const events: FromSceneProgress[] = [];
		const volume = await volumeFromScene( renderer, scene, {
			budget: 8, resolution: 16, candidateResolution: 8, candidates: 96, reachableFrom: spawn, gradients: true,
			onProgress: ( p ) => events.push( { ...p } ),
		} );
		expect( stagesOf( events ) ).toEqual( [ 'candidates', 'capture', 'reduce', 'recapture', 'fit' ] );
		expect( events.filter( ( p ) => p.stage === 'recapture' ).pop() ).toEqual( { stage: 'recapture', done: 8, total: 8 } );
		expect( volume.captureSettings.resolution ).toBe( 16 );
		expect( volume.gradients?.length ).toBe( 81 * 8 );
		expect( volume.fitSettings ).toMatchObject( { gradients: true } );
		expect( volume.fitSettings!.source ).toMatch( /captured at 8²$/ );
		volume.dispose();

	} );

	it( 'spacing instead of budget: one probe per spacing³ of the open volume (the Basic room: 48 m³ at 1.2 m, 28 probes)', async () => {

		// The open volume as fromScene measures it — the level's box times the share of a grid at half
		// the spacing not inside geometry — is the whole room: 4 × 3 × 4 = 48 m³ (the bulb holds no grid point).
		const placed = placeCandidates( 'test', gatherStaticGeometry( scene ), {
			spacing: 0.6, candidates: 256, measureOpenVolume: true, reachableFrom: Float64Array.from( spawn ),
		} );
		expect( placed.openVolume ).toBeCloseTo( 48, 6 );
		const volume = await volumeFromScene( renderer, scene, { spacing: 1.2, resolution: 8, reachableFrom: spawn, fit: false } );
		expect( volume.count ).toBe( Math.round( 48 / 1.2 ** 3 ) ); // 27.8
		volume.dispose();

	} );

	it( 'where: \'walkable\' weights the choice and the fit by the floor\'s height band, and still gives the budget', async () => {

		const volume = await volumeFromScene( renderer, scene, {
			budget: 8, resolution: 8, candidates: 96, reachableFrom: spawn, where: 'walkable', walkable: { height: 1 },
		} );
		expect( volume.count ).toBe( 8 );
		expect( volume.fitSettings?.samples ).toBeGreaterThan( 8 );
		volume.dispose();

	} );

	it( 'objects marked dynamic and those in exclude are hidden from every capture and left out of the level', async () => {

		// A bright emissive block in the middle of the room, lit as moving: it must change nothing.
		const glowing = new THREE.MeshStandardMaterial( { emissive: 0xffffff, emissiveIntensity: 20 } );
		const block = new THREE.Mesh( new THREE.BoxGeometry( 0.8, 0.8, 0.8 ), glowing );
		block.position.set( - 0.5, 1, 0.5 );
		const options = { budget: 6, resolution: 8, candidates: 64, reachableFrom: spawn };
		const without = await volumeFromScene( renderer, scene, options );
		scene.add( block );
		try {

			block.userData.probeLighting = 'dynamic';
			const marked = await volumeFromScene( renderer, scene, options );
			delete block.userData.probeLighting;
			const excluded = await volumeFromScene( renderer, scene, { ...options, exclude: [ block ] } );
			const seen = await volumeFromScene( renderer, scene, options );
			for ( const volume of [ marked, excluded ] ) {

				expect( Array.from( volume.positions ) ).toEqual( Array.from( without.positions ) );
				expect( Array.from( volume.sh ) ).toEqual( Array.from( without.sh ) );

			}

			// Seen, the block lights the probes (and takes room from the candidates).
			expect( Array.from( seen.sh ) ).not.toEqual( Array.from( without.sh ) );

		} finally {

			scene.remove( block );

		}

	} );

} );
