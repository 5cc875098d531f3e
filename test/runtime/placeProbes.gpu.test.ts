/**
 * The placement recipe end to end on a real GL context (headless-gl, WebGL2): `placeProbes`
 * (candidates → capture at 16² → reduce) on the Basic room, then the reduced layout captured at
 * 32² as a new volume, judged on held-out points whose truth is a capture at each point.
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/placeProbes.gpu.test.ts`.
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { placeProbes, type PlaceProbesResult } from '../../src/runtime/placeProbes.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { irradianceError } from '../../src/placement/irradianceError.js';
import { placeFromMeshes } from '../../src/placement/placeFromMeshes.js';
import { reduceProbes } from '../../src/placement/reduceProbes.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { seededRandom } from '../helpers/pointSets.js';
import { boxDistance } from '../placement/helpers.js';
import { cornellBox, insideBlock } from '../placement/openScenes.js';
import { createBasicRoom } from '../../scenes/basic.js';

const ctx = await createHeadlessRenderer( 32, 32 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** The lamp's bulb in the Basic room (scenes/basic.ts): centre and radius. */
const BULB = [ 0.2, 2.1, 0.3 ], BULB_RADIUS = 0.08;

/** SH of each point from a layout: the nearest probe's own (the nearest-neighbour baseline). */
function nearestSH( positions: ArrayLike<number>, sh: ArrayLike<number>, points: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 9 * points.length );
	for ( let i = 0; i < points.length / 3; i ++ ) {

		let best = 0, bestDistance = Infinity;
		for ( let j = 0; j < positions.length / 3; j ++ ) {

			const dx = positions[ 3 * j ] - points[ 3 * i ], dy = positions[ 3 * j + 1 ] - points[ 3 * i + 1 ];
			const d = Math.hypot( dx, dy, positions[ 3 * j + 2 ] - points[ 3 * i + 2 ] );
			if ( d < bestDistance ) {

				bestDistance = d;
				best = j;

			}

		}

		for ( let k = 0; k < 27; k ++ ) out[ 27 * i + k ] = sh[ 27 * best + k ];

	}

	return out;

}

/** The volume's blend at each point (`sample`: what an object there is lit with). */
function sampled( volume: LightProbeVolume, points: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 9 * points.length );
	for ( let i = 0; i < points.length / 3; i ++ ) {

		volume.sample( [ points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] ], out.subarray( 27 * i, 27 * i + 27 ) );

	}

	return out;

}

describe.skipIf( ! ctx.renderer )( `placeProbes: the placement recipe on headless-gl${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	afterAll( () => ctx.dispose() );

	describe( 'the Basic room (scenes/basic.ts), 32 probes', () => {

		const scene = new THREE.Scene();
		scene.add( createBasicRoom().room );
		const spawn = [ 0, 1.6, 0 ];
		let placed: PlaceProbesResult;
		let volume: LightProbeVolume;
		// 60 held-out points, uniform in the room 0.3 or more from the walls and 0.4 from the bulb
		// (next to a point lamp irradiance grows as 1 / r²: no layout is judged there), captured at 32².
		const held: number[] = [];
		const random = seededRandom( 5 );
		while ( held.length < 3 * 60 ) {

			const x = 3.4 * random() - 1.7, y = 0.3 + 2.4 * random(), z = 3.4 * random() - 1.7;
			if ( Math.hypot( x - BULB[ 0 ], y - BULB[ 1 ], z - BULB[ 2 ] ) >= 0.4 ) held.push( x, y, z );

		}

		let truth: Float32Array;

		it( 'places exactly 32 probes, all in the room\'s open space (a quarter spacing from the walls and the bulb)', async () => {

			placed = await placeProbes( renderer, scene, { count: 32, reachableFrom: spawn } );
			volume = new LightProbeVolume( { positions: placed.positions } );
			await volume.capture( renderer, scene, { resolution: 32 } );
			const capturer = new ProbeCapturer( renderer, { resolution: 32 } );
			truth = await capturer.capture( scene, held, new Float32Array( 27 * 60 ) );
			capturer.dispose();

			expect( placed.positions.length ).toBe( 3 * 32 );
			// The default spacing: the 4 × 3 × 4 room split into 256 cubes, 0.57 wide; candidates
			// within a quarter of it (0.14) of a surface were rejected.
			const margin = Math.cbrt( 48 / 256 ) / 4;
			const all = [ placed.positions, placed.candidates ];
			for ( const points of all ) {

				for ( let i = 0; i < points.length; i += 3 ) {

					const [ x, y, z ] = [ points[ i ], points[ i + 1 ], points[ i + 2 ] ];
					expect( - boxDistance( x, y, z, 0, 1.5, 0, 2, 1.5, 2 ) ).toBeGreaterThanOrEqual( margin - 1e-9 );
					// The bulb's 32 × 16 tessellation lies within r (1 − cos( π / 16 )) = 0.0015 of the sphere.
					const fromBulb = Math.hypot( x - BULB[ 0 ], y - BULB[ 1 ], z - BULB[ 2 ] ) - BULB_RADIUS;
					expect( fromBulb ).toBeGreaterThanOrEqual( margin - 0.002 );

				}

			}

			// The candidates: a grid of 7 × 5 × 7 cell centres (245) and the bulb's vertices moved half a
			// spacing off it, thinned to half a spacing; measured: 24 of them near the bulb rejected, 257
			// captured, none inside geometry, every one reachable from the spawn.
			expect( placed.candidates.length / 3 ).toBeGreaterThan( 200 );
			expect( placed.rejected.unreachable ).toBe( 0 );
			expect( placed.rejected.insideGeometry ).toBe( 0 );
			expect( placed.reduction.keep.length ).toBe( 32 );

		} );

		it( 'the layout\'s error on 60 held-out points is the one reduceProbes reported on the candidates, within 20 %', () => {

			// Measured (llvmpipe): 0.106 held out vs 0.109 reported — the figure placeProbes returns
			// holds on points it never saw.
			const error = irradianceError( sampled( volume, held ), truth ).mean;
			expect( error ).toBeLessThan( 1.2 * placed.reduction.error.mean );
			expect( error ).toBeGreaterThan( 0.01 ); // a real interpolation, not the truth itself

		} );

		it( 'beats 32 candidates chosen at random (5 draws), and matches the nearest of all the candidates within 10 %', () => {

			// Measured (llvmpipe): 0.106 vs random 0.126–0.163 (median 0.144) and nearest candidate
			// 0.108. A point lamp inside the room makes the light far from linear near the ceiling: 32
			// well-placed probes tetrahedrally interpolated are as good as the nearest of all 257.
			const error = irradianceError( sampled( volume, held ), truth ).mean;
			const candidates = placed.candidates, n = candidates.length / 3;
			const randomErrors: number[] = [];
			for ( let draw = 0; draw < 5; draw ++ ) {

				const pick = seededRandom( 100 + draw ), chosen = new Set<number>();
				while ( chosen.size < 32 ) chosen.add( Math.floor( pick() * n ) );
				const positions = new Float64Array( 96 ), sh = new Float32Array( 27 * 32 );
				[ ...chosen ].forEach( ( j, k ) => {

					positions.set( candidates.subarray( 3 * j, 3 * j + 3 ), 3 * k );
					sh.set( placed.candidateSH.subarray( 27 * j, 27 * j + 27 ), 27 * k );

				} );
				const subset = new LightProbeVolume( { positions, sh } );
				randomErrors.push( irradianceError( sampled( subset, held ), truth ).mean );
				subset.dispose();

			}

			randomErrors.sort( ( a, b ) => a - b );
			const nearest = irradianceError( nearestSH( candidates, placed.candidateSH, held ), truth ).mean;
			const message = `placed ${error.toFixed( 4 )}, random ${randomErrors.map( ( e ) => e.toFixed( 4 ) ).join( ' ' )}, nearest candidate ${nearest.toFixed( 4 )}`;
			expect( error, message ).toBeLessThan( 0.85 * randomErrors[ 2 ] );
			expect( error, message ).toBeLessThan( 1.1 * nearest );
			volume.dispose();

		} );

	} );

	it( 'the step-by-step recipe of docs/placement.md, as written there, on a tessellated Basic room: 32 probes in the room', async () => {

		const { room: level } = createBasicRoom( 8 );
		const scene = new THREE.Scene().add( level );
		const spawn = new THREE.Vector3( 0, 1.6, 0 );
		// --- docs/placement.md, "Step by step" ---
		const candidates = placeFromMeshes( level, { offset: 0.3, minSpacing: 0.5, reachableFrom: [ spawn ] } );
		const dense = new LightProbeVolume( { positions: candidates } );
		await dense.capture( renderer, scene, { resolution: 16 } );
		const { positions } = reduceProbes( candidates, dense.sh, { targetCount: 32, strategy: 'mean' } );
		dense.dispose();
		const volume = new LightProbeVolume( { positions } );
		await volume.capture( renderer, scene, { resolution: 64 } );
		// ---
		expect( candidates.length / 3 ).toBeGreaterThan( 100 );
		expect( volume.count ).toBe( 32 );
		for ( let i = 0; i < positions.length; i += 3 ) {

			// In the room, half the offset or more from the walls (placeFromMeshes' default minDistance).
			const inside = - boxDistance( positions[ i ], positions[ i + 1 ], positions[ i + 2 ], 0, 1.5, 0, 2, 1.5, 2 );
			expect( inside ).toBeGreaterThanOrEqual( 0.15 - 1e-9 );

		}

		// Captured: the lamp lights every probe (L00 > 0 in every channel).
		for ( let p = 0; p < 32; p ++ ) for ( let c = 0; c < 3; c ++ ) expect( volume.sh[ 27 * p + c ] ).toBeGreaterThan( 0 );
		volume.dispose();

	} );

	it( 'the Cornell box of open quads (the issue\'s scene): 16 probes, all inside the box and out of its blocks', async () => {

		const { root, blocks } = cornellBox( THREE.FrontSide );
		const scene = new THREE.Scene();
		const light = new THREE.PointLight( 0xffffff, 4, 0, 2 );
		light.position.set( 0, 1.9, 0 );
		scene.add( root, light );
		const result = await placeProbes( renderer, scene, { count: 16, reachableFrom: [ 0.5, 1.5, 0.5 ] } );
		expect( result.positions.length ).toBe( 3 * 16 );
		for ( let i = 0; i < result.positions.length; i += 3 ) {

			const [ x, y, z ] = [ result.positions[ i ], result.positions[ i + 1 ], result.positions[ i + 2 ] ];
			expect( boxDistance( x, y, z, 0, 1, 0, 1, 1, 1 ) ).toBeLessThan( 0 );
			expect( blocks.some( ( b ) => insideBlock( b, x, y, z ) ) ).toBe( false );

		}

		// The blocks' insides were candidates of the grid, and rejected.
		expect( result.rejected.insideGeometry ).toBeGreaterThan( 10 );

	} );

} );
