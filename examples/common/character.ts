import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

/** The walking character: the Fox (skinned, animated) or a stand-in when the asset is missing. */
export interface Character {

	kind: 'fox' | 'fallback';
	object: THREE.Object3D;
	mixer: THREE.AnimationMixer | null;
	/** Why the stand-in is shown. */
	reason: string;

}

/**
 * Loads `Fox.glb` (stand-in for the paper's "dog trot" character), scales it to `height` and
 * plays its Walk clip. A missing or broken file gives a capsule with a nose instead.
 */
export async function loadCharacter( url: string, height: number ): Promise<Character> {

	try {

		const gltf = await new GLTFLoader().loadAsync( url );
		const fox = gltf.scene;
		const box = new THREE.Box3().setFromObject( fox );
		fox.scale.setScalar( height / ( box.max.y - box.min.y ) );
		// The model faces +z; DynamicObjects turns the root with lookAt, which aims +z along the path.
		const root = new THREE.Group();
		root.add( fox );
		fox.traverse( ( child ) => {

			const mesh = child as THREE.Mesh;
			if ( mesh.isMesh ) {

				const material = mesh.material as THREE.Material & { map?: THREE.Texture | null; isMeshStandardMaterial?: boolean };
				if ( ! material.isMeshStandardMaterial ) mesh.material = new THREE.MeshStandardMaterial( { map: material.map ?? null } );
				mesh.frustumCulled = false; // skinned bounds do not follow the animation

			}

		} );
		const mixer = new THREE.AnimationMixer( fox );
		const walk = gltf.animations.find( ( clip ) => clip.name === 'Walk' ) ?? gltf.animations[ 0 ];
		if ( walk ) mixer.clipAction( walk ).play();
		return { kind: 'fox', object: root, mixer, reason: '' };

	} catch ( error ) {

		const material = new THREE.MeshStandardMaterial( { color: 0xd08040, roughness: 0.7 } );
		const body = new THREE.Mesh( new THREE.CapsuleGeometry( height * 0.25, height * 0.5, 4, 12 ), material );
		body.position.y = height * 0.5;
		const nose = new THREE.Mesh( new THREE.ConeGeometry( height * 0.1, height * 0.3, 12 ), material );
		nose.rotation.x = Math.PI / 2;
		nose.position.set( 0, height * 0.7, height * 0.3 );
		const root = new THREE.Group();
		root.add( body, nose );
		return { kind: 'fallback', object: root, mixer: null, reason: `(${( error as Error ).message}) Get Fox.glb from the Khronos glTF sample models into <assets>/fox/, or pass ?assets=URL.` };

	}

}
