import * as THREE from 'three';

/** An object's bounding box projected to the canvas, in CSS pixels: [ left, top, right, bottom ]. */
export function screenBox( object: THREE.Object3D, camera: THREE.Camera, canvas: HTMLCanvasElement ): number[] {

	const box = new THREE.Box3().setFromObject( object );
	const rect = canvas.getBoundingClientRect();
	let left = Infinity, top = Infinity, right = - Infinity, bottom = - Infinity;
	for ( let i = 0; i < 8; i ++ ) {

		const corner = new THREE.Vector3( i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z );
		corner.project( camera );
		const x = ( corner.x + 1 ) / 2 * rect.width, y = ( 1 - corner.y ) / 2 * rect.height;
		left = Math.min( left, x ); right = Math.max( right, x ); top = Math.min( top, y ); bottom = Math.max( bottom, y );

	}

	return [ left, top, right, bottom ];

}
