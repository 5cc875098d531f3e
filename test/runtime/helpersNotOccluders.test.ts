/**
 * Helpers drawn for the user are not level geometry: a `VisibilityGuard` (and placement, which
 * reads the same `gatherWorldGeometry`) built from a scene that holds a `LightProbeVolumeHelper`
 * or three's `LightProbeHelper` must not see their spheres as walls. Without the skip, every
 * segment from a point inside the cube to its 8 corner probes ends in a helper sphere and is
 * blocked — the control below shows that a plain mesh of the same sphere does block.
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeHelper } from 'three/examples/jsm/helpers/LightProbeHelper.js';
import { gatherWorldGeometry } from '../../src/geometry/gatherWorldGeometry.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeHelper } from '../../src/runtime/LightProbeVolumeHelper.js';
import { VisibilityGuard } from '../../src/runtime/VisibilityGuard.js';

const CUBE = [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 1, - 1, 1, 1, - 1, - 1, - 1, 1, 1, - 1, 1, - 1, 1, 1, 1, 1, 1 ];

function blockedSegments( guard: VisibilityGuard ): number {

	let blocked = 0;
	for ( let i = 0; i < 8; i ++ ) {

		if ( guard.segmentBlocked( 0.1, 0.2, 0.3, CUBE[ 3 * i ], CUBE[ 3 * i + 1 ], CUBE[ 3 * i + 2 ] ) ) blocked ++;

	}

	return blocked;

}

describe( 'helpers are not occluders', () => {

	it( 'a LightProbeVolumeHelper in the scene blocks none of the 8 segments to the probes', () => {

		const volume = new LightProbeVolume( { positions: CUBE } );
		const scene = new THREE.Scene();
		const helper = new LightProbeVolumeHelper( volume, 0.3 );
		scene.add( helper );
		expect( gatherWorldGeometry( scene ).triangles.length ).toBe( 0 );
		expect( blockedSegments( new VisibilityGuard( scene ) ) ).toBe( 0 );
		helper.dispose();

	} );

	it( 'three\'s LightProbeHelper (a Mesh) is skipped with its children; a plain sphere mesh at a probe blocks', () => {

		const scene = new THREE.Scene();
		const probeHelper = new LightProbeHelper( new THREE.LightProbe(), 0.3 );
		probeHelper.position.set( 1, 1, 1 );
		probeHelper.add( new THREE.Mesh( new THREE.SphereGeometry( 0.3 ) ) );
		scene.add( probeHelper );
		expect( gatherWorldGeometry( scene ).triangles.length ).toBe( 0 );

		// Control: the same sphere as level geometry is gathered and blocks the segment to (1, 1, 1).
		const ball = new THREE.Mesh( new THREE.SphereGeometry( 0.3 ) );
		ball.position.set( 1, 1, 1 );
		scene.add( ball );
		expect( gatherWorldGeometry( scene ).triangles.length ).toBeGreaterThan( 0 );
		expect( blockedSegments( new VisibilityGuard( scene ) ) ).toBe( 1 );

	} );

} );
