/**
 * The lights `capture-lighting bake` adds to a scene: `--sun` / `--point` / `--spot` and the
 * layout's "lights" as three's DirectionalLight / PointLight / SpotLight, `--ambient` as an
 * AmbientLight. What a page writes to add the same light by hand.
 */

import * as THREE from 'three';
import type { BakeLight, BakeLightSource } from './protocol.js';

/**
 * Adds the lights to `scene`, after what is in it. A directional light is placed at twice the
 * bounding radius of `bounds` from its centre, towards the light, aiming at the centre (only the
 * direction lights; the position matters for the shadow camera, which `prepareCaptureScene` fits).
 * @returns Each added light with where it was asked for.
 */
export function addBakeLights(
	scene: THREE.Scene, lights: readonly BakeLight[], ambient: number, bounds: THREE.Sphere,
): Map<THREE.Light, BakeLightSource> {

	const added = new Map<THREE.Light, BakeLightSource>();
	if ( ambient > 0 ) {

		const light = new THREE.AmbientLight( 0xffffff, ambient );
		light.name = '--ambient';
		scene.add( light );
		added.set( light, 'flags' );

	}

	lights.forEach( ( spec, i ) => {

		const light = createLight( spec );
		light.name = `${spec.source === 'flags' ? 'flag' : 'layout'} light ${i}`;
		if ( spec.type === 'directional' ) {

			const d = light as THREE.DirectionalLight;
			d.position.fromArray( spec.direction ).normalize().multiplyScalar( 2 * bounds.radius ).add( bounds.center );
			d.target.position.copy( bounds.center );
			scene.add( d, d.target );

		} else {

			scene.add( light );
			if ( spec.type === 'spot' ) scene.add( ( light as THREE.SpotLight ).target );

		}

		added.set( light, spec.source );

	} );
	scene.updateMatrixWorld( true );
	return added;

}

/** One light as three builds it. */
export function createLight( spec: BakeLight ): THREE.Light {

	if ( spec.type === 'directional' ) return new THREE.DirectionalLight( spec.color, spec.intensity );
	if ( spec.type === 'point' ) {

		const light = new THREE.PointLight( spec.color, spec.intensity, spec.distance, spec.decay );
		light.position.fromArray( spec.position );
		return light;

	}

	const light = new THREE.SpotLight(
		spec.color, spec.intensity, spec.distance, THREE.MathUtils.degToRad( spec.angle ), spec.penumbra, spec.decay,
	);
	light.position.fromArray( spec.position );
	light.target.position.fromArray( spec.target );
	return light;

}
