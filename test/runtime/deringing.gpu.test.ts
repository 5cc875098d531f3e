import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/index.js';
import { minIrradiance, windowSH } from '../../src/sh/windowSH.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';

const ctx = await createHeadlessRenderer( 16, 16 );

/**
 * A dim sky (a constant 0.05 inside a large back-facing box) and a small sun: a disc-like sphere of
 * radiance 2000 subtending ~3°. SH9 cannot hold the sun: the reconstructed irradiance goes negative
 * for normals facing away from it. Both are MeshBasicMaterial, so the radiance is the colour.
 */
function sunScene(): THREE.Scene {

	const scene = new THREE.Scene();
	scene.add( new THREE.Mesh( new THREE.BoxGeometry( 40, 40, 40 ), new THREE.MeshBasicMaterial( { color: new THREE.Color( 0.05, 0.05, 0.05 ), side: THREE.BackSide } ) ) );
	const sun = new THREE.Mesh( new THREE.SphereGeometry( 0.5, 16, 8 ), new THREE.MeshBasicMaterial( { color: new THREE.Color( 2000, 2000, 2000 ) } ) );
	sun.position.set( 6, 6, 0 );
	scene.add( sun );
	return scene;

}

const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ];

describe.skipIf( ! ctx.renderer )( `capture with de-ringing and the non-negative switch${ctx.skipReason ? ' — SKIPPED: ' + ctx.skipReason : ''}`, () => {

	afterAll( () => ctx.dispose() );

	it( 'nonNegative: a captured bright sun rings below zero without it, and every probe\'s irradiance is ≥ 0 with it', async () => {

		const scene = sunScene();
		const plain = await new LightProbeVolume( { positions } ).capture( ctx.renderer!, scene, { resolution: 32, type: THREE.FloatType } );
		const fixed = await new LightProbeVolume( { positions } ).capture( ctx.renderer!, scene, { resolution: 32, type: THREE.FloatType, nonNegative: true } );
		for ( let i = 0; i < 4; i ++ ) {

			// Without the switch the sun makes the irradiance facing away from it negative...
			expect( minIrradiance( plain.sh, 27 * i ) ).toBeLessThan( - 0.01 * plain.sh[ 27 * i ] );
			// ...with it, never, and the mean (L00) is untouched.
			expect( minIrradiance( fixed.sh, 27 * i ) ).toBeGreaterThanOrEqual( 0 );
			expect( fixed.sh[ 27 * i ] ).toBeCloseTo( plain.sh[ 27 * i ], 3 );

		}

		// And so is any blend of them the volume hands to an object.
		const blended = fixed.sample( [ 0.2, 0.3, 0.1 ] );
		expect( minIrradiance( blended ) ).toBeGreaterThanOrEqual( - 1e-6 * blended[ 0 ] );

	} );

	it( 'deringing: the captured SH equal the plain capture windowed with the same strength', async () => {

		const scene = sunScene();
		const plain = await new LightProbeVolume( { positions } ).capture( ctx.renderer!, scene, { resolution: 16, type: THREE.FloatType } );
		const windowed = await new LightProbeVolume( { positions } ).capture( ctx.renderer!, scene, { resolution: 16, type: THREE.FloatType, deringing: 0.2 } );
		const expected = windowSH( plain.sh, 0.2, new Float32Array( plain.sh.length ) );
		for ( let k = 0; k < expected.length; k ++ ) expect( windowed.sh[ k ] ).toBeCloseTo( expected[ k ], 3 );
		// Band 1 really changed (strength 0.2: h1 = 0.905).
		expect( Math.abs( windowed.sh[ 3 ] - plain.sh[ 3 ] ) ).toBeGreaterThan( 0.05 * Math.abs( plain.sh[ 3 ] ) );
		await expect( new LightProbeVolume( { positions } ).capture( ctx.renderer!, scene, { deringing: 2 } ) ).rejects.toThrow( /deringing must be in \[0, 1\]/ );

	} );

} );
