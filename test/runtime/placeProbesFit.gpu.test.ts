/**
 * `placeProbes` with the fitted reduction on a real GL context (headless-gl, WebGL2), in the Basic room
 * (scenes/basic.ts): `fit`, `swaps`, `region`, `weights` (a function of the candidate's position) and
 * `fitSamples` reach `reduceProbes` unchanged, the result's `reduction.sh` / `gradients` are the fitted
 * field whose error it reports, and on held-out points in the region captured at the candidates'
 * resolution that field beats the same layout's captured SH.
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/placeProbesFit.gpu.test.ts`.
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { placeProbes, type PlaceProbesResult } from '../../src/runtime/placeProbes.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { irradianceError } from '../../src/placement/irradianceError.js';
import { reduceProbes } from '../../src/placement/reduceProbes.js';
import { regionWeights, type RegionOfInterest } from '../../src/placement/regionOfInterest.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { seededRandom } from '../helpers/pointSets.js';
import { createBasicRoom } from '../../scenes/basic.js';

const ctx = await createHeadlessRenderer( 16, 16 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** The volume's blend at each point (`sample`: what an object there is lit with). */
function sampled( volume: LightProbeVolume, points: ArrayLike<number> ): Float32Array {

	const out = new Float32Array( 9 * points.length );
	for ( let i = 0; i < points.length / 3; i ++ ) {

		volume.sample( [ points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] ], out.subarray( 27 * i, 27 * i + 27 ) );

	}

	return out;

}

/** `count` points uniform in the room's lower part (where the region is), 0.3 or more from the walls. */
function pointsInRegion( seed: number, count: number ): Float64Array {

	const random = seededRandom( seed ), points = new Float64Array( 3 * count );
	for ( let i = 0; i < count; i ++ ) points.set( [ 3.4 * random() - 1.7, 0.3 + 0.9 * random(), 3.4 * random() - 1.7 ], 3 * i );
	return points;

}

describe.skipIf( ! ctx.renderer )( `placeProbes with fit, swaps, region, weights and fitSamples on headless-gl${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	afterAll( () => ctx.dispose() );

	const scene = new THREE.Scene();
	scene.add( createBasicRoom().room );
	const spawn = [ 0, 1.6, 0 ];
	// Where characters go: the room's lower 1.2 m (the lamp hangs at 2.1 m).
	const region: RegionOfInterest = { boxes: [ { min: [ - 2, 0, - 2 ], max: [ 2, 1.2, 2 ] } ] };
	const weigh = ( x: number ) => ( x < 0 ? 2 : 1 );
	const fit = { gradients: true };
	let placed: PlaceProbesResult;
	let fitSamples: { positions: Float64Array; sh: Float32Array };
	let held: Float64Array, truth: Float32Array;

	it( 'passes the options through: the reduction is reduceProbes\' own on the candidates it captured', async () => {

		// 20 extra fit points and 40 held-out points in the region, captured at 16² as the candidates are.
		const capturer = new ProbeCapturer( renderer, { resolution: 16 } );
		const extra = pointsInRegion( 7, 20 );
		fitSamples = { positions: extra, sh: await capturer.capture( scene, extra, new Float32Array( 27 * 20 ) ) };
		held = pointsInRegion( 11, 40 );
		truth = await capturer.capture( scene, held, new Float32Array( 27 * 40 ) );
		capturer.dispose();

		placed = await placeProbes( renderer, scene, {
			count: 16, reachableFrom: spawn, fit, swaps: 1, region, weights: ( x ) => weigh( x ), fitSamples,
		} );
		const { candidates, candidateSH, reduction } = placed;
		const weights = Array.from( { length: candidates.length / 3 }, ( _, i ) => weigh( candidates[ 3 * i ] ) );
		const direct = reduceProbes( candidates, candidateSH, { targetCount: 16, strategy: 'mean', fit, swaps: 1, region, weights, fitSamples } );
		expect( Array.from( reduction.keep ) ).toEqual( Array.from( direct.keep ) );
		expect( Array.from( reduction.sh ) ).toEqual( Array.from( direct.sh ) );
		expect( reduction.error.mean ).toBe( direct.error.mean );
		// Fitted with gradients: 81 floats per probe and a λ; without the options there are neither.
		expect( reduction.gradients?.length ).toBe( 81 * 16 );
		expect( reduction.fit?.lambda ).toBeGreaterThanOrEqual( 0 );
		const plain = reduceProbes( candidates, candidateSH, { targetCount: 16, strategy: 'mean' } );
		expect( plain.gradients ).toBeNull();
		expect( plain.fit ).toBeNull();

	} );

	it( 'reduction.sh and gradients are the field whose weighted error over the candidates and fit points it reports', () => {

		const { candidates, candidateSH, reduction } = placed;
		const volume = new LightProbeVolume( { positions: reduction.positions, sh: reduction.sh, gradients: reduction.gradients! } );
		const n = candidates.length / 3;
		const points = new Float64Array( [ ...candidates, ...fitSamples.positions ] );
		const pointTruth = new Float32Array( [ ...candidateSH, ...fitSamples.sh ] );
		const weights = regionWeights( points, region ).map( ( w, i ) => ( i < n ? w * weigh( points[ 3 * i ] ) : w ) );
		const error = irradianceError( sampled( volume, points ), pointTruth, undefined, weights ).mean;
		// The runtime's blend (outer cells, the gradient formula) is the one reduceProbes fits and measures with (measured: equal to 1e-9).
		expect( error ).toBeCloseTo( reduction.error.mean, 4 );
		volume.dispose();

	} );

	it( 'on 40 held-out points in the region the fitted field beats the same layout\'s captured SH', async () => {

		const { reduction } = placed;
		const captured = new LightProbeVolume( { positions: reduction.positions } );
		await captured.capture( renderer, scene, { resolution: 16 } );
		const fitted = new LightProbeVolume( { positions: reduction.positions, sh: reduction.sh, gradients: reduction.gradients! } );
		const fittedError = irradianceError( sampled( fitted, held ), truth ).mean;
		const capturedError = irradianceError( sampled( captured, held ), truth ).mean;
		// Measured (llvmpipe): fitted 0.039, captured 0.196 — the 16 probes' own SH miss the lamp's fall-off between them.
		expect( fittedError, `fitted ${fittedError.toFixed( 4 )}, captured ${capturedError.toFixed( 4 )}` ).toBeLessThan( 0.5 * capturedError );
		captured.dispose();
		fitted.dispose();

	} );

} );
