import type * as THREE from 'three';

/**
 * Runs `run` with the scene's faint emissive stand-ins for indirect light (loadOBJScene's
 * `ambient`, materials marked `userData.ambientStandIn`) switched off, and restores them after:
 * computed bounces replace them.
 */
export async function withoutAmbientStandIns( scene: THREE.Scene, run: () => Promise<unknown> ): Promise<void> {

	const standIns = new Map<THREE.MeshStandardMaterial, THREE.Color>();
	scene.traverse( ( object ) => {

		for ( const material of ( [] as THREE.Material[] ).concat( ( object as THREE.Mesh ).material ?? [] ) ) {

			const standard = material as THREE.MeshStandardMaterial;
			const standIn = material.userData.ambientStandIn === true;
			if ( standIn && ! standIns.has( standard ) ) standIns.set( standard, standard.emissive.clone() );

		}

	} );
	for ( const material of standIns.keys() ) material.emissive.setRGB( 0, 0, 0 );
	try {

		await run();

	} finally {

		for ( const [ material, emissive ] of standIns ) material.emissive.copy( emissive );

	}

}
