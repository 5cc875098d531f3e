import * as THREE from 'three';
import { projectToImage, type Image8 } from './gpuScenes.js';

/** The floor, [−10, 10]² at y = 0, facing up, white and fully rough; two triangles unless `segments` says otherwise. */
export function floorMesh( segments = 1 ): THREE.Mesh {

	const geometry = new THREE.PlaneGeometry( 20, 20, segments, segments ).rotateX( - Math.PI / 2 );
	return new THREE.Mesh( geometry, new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1, metalness: 0 } ) );

}

/** An orthographic camera looking straight down at the whole floor, −z up in the image. */
export function topCamera(): THREE.OrthographicCamera {

	const camera = new THREE.OrthographicCamera( - 10, 10, 10, - 10, 0.1, 50 );
	camera.position.set( 0, 20, 0 );
	camera.up.set( 0, 0, - 1 );
	camera.lookAt( 0, 0, 0 );
	camera.updateMatrixWorld();
	return camera;

}

/** Sample points (x, z) across the floor, inside its pixels (not on an edge). */
export const FLOOR_POINTS = [ [ - 8, - 8 ], [ 8, - 8 ], [ - 8, 8 ], [ 8, 8 ], [ 0, 0 ], [ - 4.3, 6.1 ], [ 5.7, - 2.2 ] ];

/** The RGB (0..255) of the pixel where the floor point (x, 0, z) lands. */
export function floorPixel( image: Image8, camera: THREE.Camera, x: number, z: number ): number[] {

	const [ u, v ] = projectToImage( new THREE.Vector3( x, 0, z ), camera, image.width, image.height );
	const p = Math.floor( v ) * image.width + Math.floor( u );
	return [ image.data[ 4 * p ], image.data[ 4 * p + 1 ], image.data[ 4 * p + 2 ] ];

}
