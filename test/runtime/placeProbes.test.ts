/**
 * placeProbes' argument checks and its "too few candidates" error, which come before any capture:
 * a stand-in renderer is enough (the recipe itself: placeProbes.gpu.test.ts).
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { placeProbes } from '../../src/runtime/placeProbes.js';
import { cornellBox } from '../placement/openScenes.js';
import { createBasicRoom } from '../../scenes/basic.js';

const renderer = { isWebGLRenderer: true, getContext() {} } as unknown as THREE.WebGLRenderer;

describe( 'placeProbes (checks before the capture)', () => {

	const scene = new THREE.Scene();
	scene.add( createBasicRoom().room );

	it( 'names placeProbes and the bad argument', async () => {

		const call = ( options: unknown, target: unknown = scene, r: unknown = renderer ) => placeProbes(
			r as THREE.WebGLRenderer, target as THREE.Scene, options as Parameters<typeof placeProbes>[ 2 ]
		);
		await expect( call( { count: 8 }, scene, {} ) ).rejects.toThrow( /^placeProbes: renderer must be a three.js WebGLRenderer/ );
		await expect( call( { count: 8 }, {} ) ).rejects.toThrow( /^placeProbes: scene must be a three.js Scene/ );
		await expect( call( null ) ).rejects.toThrow( /^placeProbes: options must be \{ count, reachableFrom\?, … \}/ );
		await expect( call( { count: 3 } ) ).rejects.toThrow( /^placeProbes: options.count must be an integer ≥ 4, got 3/ );
		await expect( call( { count: 8, geometry: {} } ) ).rejects.toThrow( /^placeProbes: options.geometry must be a three.js Object3D/ );
		await expect( call( { count: 8, bounds: {} } ) ).rejects.toThrow( /^placeProbes: options.bounds must be a three.js Box3/ );
		await expect( call( { count: 8, spacing: 0 } ) ).rejects.toThrow( /^placeProbes: options.spacing must be a finite number/ );
		await expect( call( { count: 8, candidateResolution: 0 } ) ).rejects.toThrow( /^placeProbes: options.candidateResolution must be an integer in 1\.\.4096/ );
		await expect( call( { count: 8, capture: 5 } ) ).rejects.toThrow( /^placeProbes: options.capture must be an object/ );
		await expect( call( { count: 8, reachableFrom: [ 0, 1 ] } ) ).rejects.toThrow( /^placeProbes: options.reachableFrom must hold x, y, z/ );
		await expect( call( { count: 8, reachableFrom: [ 0, 0, 0 ] } ) ).rejects.toThrow( /^placeProbes: options.reachableFrom\[0\] \(0, 0, 0\) lies on a surface/ );
		await expect( call( { count: 8 }, new THREE.Scene() ) ).rejects.toThrow( /^placeProbes: scene has no triangles to place probes in/ );
		const bounds = new THREE.Box3( new THREE.Vector3( 5, 5, 5 ), new THREE.Vector3( 6, 6, 6 ) );
		await expect( call( { count: 8, bounds } ) ).rejects.toThrow( /^placeProbes: the box to place probes in is empty or flat/ );

	} );

	it( 'checks the reduction\'s options (fit, swaps, region, weights, fitSamples) before the capture, naming placeProbes', async () => {

		// The stand-in renderer cannot capture: each of these errors comes before the capture would start.
		const call = ( options: object ) => placeProbes( renderer, scene, { count: 8, reachableFrom: [ 0, 1.6, 0 ], ...options } );
		await expect( call( { fit: { gradient: true } } ) ).rejects.toThrow( /^placeProbes: options.fit has unknown option "gradient"/ );
		await expect( call( { fit: { lambda: - 1 } } ) ).rejects.toThrow( /^placeProbes: options.fit.lambda must be 'auto' or a finite number ≥ 0/ );
		await expect( call( { swaps: 2 } ) ).rejects.toThrow( /^placeProbes: options.swaps needs options.fit/ );
		await expect( call( { weights: [ 1, 2, 3 ] } ) ).rejects.toThrow( /^placeProbes: options.weights must have one weight per point \(\d+\), got length 3/ );
		await expect( call( { weights: () => Number.NaN } ) ).rejects.toThrow( /^placeProbes: options.weights returned NaN at candidate 0 \(/ );
		await expect( call( { weights: ( x: number ) => ( x < 0 ? - 1 : 1 ) } ) ).rejects.toThrow( /^placeProbes: options.weights returned -1 at candidate \d+/ );
		await expect( call( { weights: () => 0 } ) ).rejects.toThrow( /^placeProbes: every point has weight 0/ );
		await expect( call( { region: { boxes: 5 } } ) ).rejects.toThrow( /^placeProbes: options.region/ );
		await expect( call( { fitSamples: { positions: [ 0, 1, 0 ], sh: [ 1 ] } } ) ).rejects.toThrow( /^placeProbes: options.fitSamples.sh/ );
		// Valid options get as far as the capture, which the stand-in renderer cannot do.
		await expect( call( { fit: true, weights: () => 1 } ) ).rejects.not.toThrow( /options\.(fit|weights)/ );

	} );

	it( 'says how many candidates were found and why the others were dropped when there are fewer than count', async () => {

		// The Cornell box (2 × 2 × 2) at 0.5 spacing: 4 × 4 × 4 grid points and the walls' corners,
		// far fewer than 500; the grid points in the blocks are inside geometry.
		const { root } = cornellBox( THREE.FrontSide );
		const box = new THREE.Scene().add( root );
		await expect( placeProbes( renderer, box, { count: 500, spacing: 0.5, reachableFrom: [ 0.5, 1.5, 0.5 ] } ) )
			.rejects.toThrow( /^placeProbes: only \d+ of \d+ candidates are in open space \(\d+ near a surface, [1-9]\d* inside geometry, \d+ unreachable\), fewer than options.count \(500\)/ );

	} );

} );
