/**
 * Recapturing only what an edit changed (headless-gl, WebGL2): after moveProbe / addProbe,
 * recaptureDirty() captures the dirty probes alone, and the volume's SH then equal a full capture
 * of the edited layout. Needs an X display: run under `xvfb-run -a npx vitest run <this file>`.
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';

const ctx = await createHeadlessRenderer( 16, 16 );

/** A room with a different colour on each wall and a bright ball off-centre: the light depends on where a probe is. */
function roomScene(): THREE.Scene {

	const scene = new THREE.Scene();
	const colours = [ [ 1, 0.2, 0.2 ], [ 0.2, 1, 0.2 ], [ 0.2, 0.2, 1 ], [ 1, 1, 0.2 ], [ 0.2, 1, 1 ], [ 1, 0.2, 1 ] ];
	const walls = colours.map( ( [ r, g, b ] ) => new THREE.MeshBasicMaterial( { color: new THREE.Color( r, g, b ), side: THREE.BackSide } ) );
	scene.add( new THREE.Mesh( new THREE.BoxGeometry( 10, 10, 10 ), walls ) );
	const ball = new THREE.Mesh( new THREE.SphereGeometry( 0.8, 16, 8 ), new THREE.MeshBasicMaterial( { color: new THREE.Color( 8, 8, 8 ) } ) );
	ball.position.set( 2, 1, 0 );
	scene.add( ball );
	return scene;

}

const POSITIONS = [ - 3, - 3, - 3, 3, - 3, - 3, - 3, 3, - 3, 3, 3, - 3, - 3, - 3, 3, 3, - 3, 3, - 3, 3, 3, 3, 3, 3, 0, 0, 0 ];
const SETTINGS = { resolution: 16, type: THREE.FloatType } as const;

function probeSH( volume: LightProbeVolume, i: number ): number[] {

	return Array.from( volume.sh.subarray( 27 * i, 27 * i + 27 ) );

}

function maxDifference( a: ArrayLike<number>, b: ArrayLike<number> ): number {

	let worst = 0;
	for ( let k = 0; k < a.length; k ++ ) worst = Math.max( worst, Math.abs( a[ k ] - b[ k ] ) );
	return worst;

}

describe.skipIf( ! ctx.renderer )( `recapture of dirty probes after edits${ctx.skipReason ? ' — SKIPPED: ' + ctx.skipReason : ''}`, () => {

	afterAll( () => ctx.dispose() );

	it( 'moveProbe + recaptureDirty captures 1 probe, and the SH equal a full capture of the moved layout', async () => {

		const scene = roomScene();
		const volume = await new LightProbeVolume( { positions: POSITIONS } ).capture( ctx.renderer!, scene, SETTINGS );
		expect( volume.dirtyProbes() ).toEqual( [] );
		const before = volume.sh.slice();
		volume.moveProbe( 8, [ 1.2, 0.8, 0.5 ] ); // next to the ball
		expect( volume.dirtyProbes() ).toEqual( [ 8 ] );
		// Until recaptured the probe keeps its SH.
		expect( probeSH( volume, 8 ) ).toEqual( Array.from( before.subarray( 216, 243 ) ) );

		const progress: [ number, number ][] = [];
		await volume.recaptureDirty( ctx.renderer!, scene, { ...SETTINGS, onProgress: ( done, total ) => progress.push( [ done, total ] ) } );
		expect( progress.length ).toBeGreaterThan( 0 );
		expect( progress.every( ( [ , total ] ) => total === 1 ) ).toBe( true );
		expect( progress[ progress.length - 1 ][ 0 ] ).toBe( 1 );
		expect( volume.dirtyProbes() ).toEqual( [] );

		const moved = POSITIONS.slice();
		moved.splice( 24, 3, 1.2, 0.8, 0.5 );
		const full = await new LightProbeVolume( { positions: moved } ).capture( ctx.renderer!, scene, SETTINGS );
		expect( maxDifference( volume.sh, full.sh ) ).toBeLessThan( 1e-4 * full.sh[ 0 ] );
		// The move mattered: near the ball the probe sees much more light.
		expect( volume.sh[ 216 ] ).toBeGreaterThan( 1.2 * before[ 216 ] );
		// The other probes were not touched.
		expect( Array.from( volume.sh.subarray( 0, 216 ) ) ).toEqual( Array.from( before.subarray( 0, 216 ) ) );

		// Nothing dirty: nothing captured.
		let calls = 0;
		await volume.recaptureDirty( ctx.renderer!, scene, { ...SETTINGS, onProgress: () => calls ++ } );
		expect( calls ).toBe( 0 );

	} );

	it( 'addProbe + removeProbe + recaptureDirty: only the added probe is captured; SH equal a full capture of the edited layout', async () => {

		const scene = roomScene();
		const volume = await new LightProbeVolume( { positions: POSITIONS } ).capture( ctx.renderer!, scene, SETTINGS );
		const id = volume.addProbe( [ - 1, 2, 1 ] );
		volume.removeProbe( 0 );
		expect( volume.dirtyProbes() ).toEqual( [ id ] );
		const totals: number[] = [];
		await volume.recaptureDirty( ctx.renderer!, scene, { ...SETTINGS, onProgress: ( _, total ) => totals.push( total ) } );
		expect( new Set( totals ) ).toEqual( new Set( [ 1 ] ) );

		const edited = [ ...POSITIONS.slice( 3 ), - 1, 2, 1 ];
		const full = await new LightProbeVolume( { positions: edited } ).capture( ctx.renderer!, scene, SETTINGS );
		expect( maxDifference( volume.sh.subarray( 27 ), full.sh ) ).toBeLessThan( 1e-4 * full.sh[ 0 ] );
		// And the blended light anywhere is that of the full capture.
		const a = new Float32Array( 27 ), b = new Float32Array( 27 );
		for ( const p of [ [ 0, 0, 0 ], [ - 1, 1.5, 0.5 ], [ 2.5, - 2, 1 ], [ 4, 4, 4 ] ] ) {

			expect( maxDifference( volume.sample( p, a ), full.sample( p, b ) ) ).toBeLessThan( 1e-4 * b[ 0 ] + 1e-6 );

		}

	} );

} );
