/**
 * Open-room scenes for the placement tests, with their analytic open space: a Cornell box of open
 * quads, rooms drawn from inside (`BackSide`, as scenes/basic.ts), a prop, a sealed room.
 */
import * as THREE from 'three';
import { INSIDE_RAY_DIRECTIONS } from '../../src/placement/classifyPoints.js';
import type { TriangleBVH } from '../../src/geometry/TriangleBVH.js';

/** A box prop: centre, half sizes and rotation about y (radians). */
export interface Block { centre: [ number, number, number ]; half: [ number, number, number ]; angle: number }

/** Whether (x, y, z) is strictly inside the block, more than `margin` from its faces. */
export function insideBlock( block: Block, x: number, y: number, z: number, margin = 0 ): boolean {

	// Into the block's frame: translate, then rotate by −angle about y.
	const dx = x - block.centre[ 0 ], dy = y - block.centre[ 1 ], dz = z - block.centre[ 2 ];
	const c = Math.cos( block.angle ), s = Math.sin( block.angle );
	const lx = c * dx - s * dz, lz = s * dx + c * dz;
	const [ hx, hy, hz ] = block.half;
	return Math.abs( lx ) < hx - margin && Math.abs( dy ) < hy - margin && Math.abs( lz ) < hz - margin;

}

/** A closed box mesh for a {@link Block} (BoxGeometry: outward winding and normals). */
export function blockMesh( block: Block, material: THREE.Material ): THREE.Mesh {

	const mesh = new THREE.Mesh( new THREE.BoxGeometry( 2 * block.half[ 0 ], 2 * block.half[ 1 ], 2 * block.half[ 2 ] ), material );
	mesh.position.set( ...block.centre );
	mesh.rotation.y = block.angle;
	return mesh;

}

/**
 * The Cornell box as its OBJ models it: five open quads — floor, ceiling, back, left and right
 * walls of the box x ∈ [−1, 1], y ∈ [0, 2], z ∈ [−1, 1], no front wall (the camera looks in through
 * z = 1) — each single-sided and facing into the box (or double-sided), a short and a tall block
 * standing on the floor (closed boxes, turned like the original's), and the lamp: a small quad
 * just under the ceiling facing down. `segments` subdivides the walls (vertex candidates need
 * vertices away from the corners).
 */
export function cornellBox( side: THREE.Side, segments = 1 ): { root: THREE.Group; blocks: Block[] } {

	const material = new THREE.MeshStandardMaterial( { side } );
	const root = new THREE.Group();
	const wall = ( rx: number, ry: number, x: number, y: number, z: number ) => {

		const mesh = new THREE.Mesh( new THREE.PlaneGeometry( 2, 2, segments, segments ), material );
		mesh.rotation.set( rx, ry, 0 );
		mesh.position.set( x, y, z );
		mesh.name = 'wall';
		root.add( mesh );

	};

	// PlaneGeometry faces +z; each is turned to face into the box.
	wall( - Math.PI / 2, 0, 0, 0, 0 ); // floor, facing +y
	wall( Math.PI / 2, 0, 0, 2, 0 ); // ceiling, facing −y
	wall( 0, 0, 0, 1, - 1 ); // back wall, facing +z
	wall( 0, Math.PI / 2, - 1, 1, 0 ); // left wall, facing +x
	wall( 0, - Math.PI / 2, 1, 1, 0 ); // right wall, facing −x
	const blocks: Block[] = [
		{ centre: [ 0.33, 0.3, 0.37 ], half: [ 0.3, 0.3, 0.3 ], angle: - 0.3 },
		{ centre: [ - 0.335, 0.6, - 0.29 ], half: [ 0.3, 0.6, 0.3 ], angle: 0.3 },
	];
	for ( const block of blocks ) root.add( blockMesh( block, material ) );
	const lamp = new THREE.Mesh( new THREE.PlaneGeometry( 0.5, 0.5 ), new THREE.MeshBasicMaterial() );
	lamp.rotation.x = Math.PI / 2;
	lamp.position.set( 0, 1.99, 0 );
	root.add( lamp );
	return { root, blocks };

}

/**
 * The classification before issue 13: inside when more than half of the 7 rays cross the
 * triangles an odd number of times (ray parity, blind to drawn sides and open surfaces).
 * @returns One boolean per point: inside by parity.
 */
export function parityVote( points: ArrayLike<number>, bvh: TriangleBVH ): boolean[] {

	const d = INSIDE_RAY_DIRECTIONS, rays = d.length / 3, out: boolean[] = [];
	for ( let i = 0; i < points.length; i += 3 ) {

		let odd = 0;
		for ( let r = 0; r < rays; r ++ ) {

			const [ x, y, z ] = [ points[ i ], points[ i + 1 ], points[ i + 2 ] ];
			const crossings = bvh.countCrossings( x, y, z, d[ 3 * r ], d[ 3 * r + 1 ], d[ 3 * r + 2 ] );
			if ( crossings % 2 === 1 ) odd ++;

		}

		out.push( 2 * odd > rays );

	}

	return out;

}

/**
 * Two 4 × 3 × 4 rooms side by side, x ∈ [−4, 0] (A) and [0, 4] (B), y ∈ [0, 3], z ∈ [−2, 2], built
 * from open single-sided quads facing into the rooms (floor, ceiling, outer walls), split by a
 * double-sided wall at x = 0 with a doorway z ∈ [−0.5, 0.5], y ∈ [0, 2] — left open, or closed by a
 * double-sided door quad (then B is a sealed room).
 */
export function twoRoomLevel( doorOpen: boolean ): THREE.Group {

	const single = new THREE.MeshStandardMaterial(), double = new THREE.MeshStandardMaterial( { side: THREE.DoubleSide } );
	const root = new THREE.Group();
	const quad = ( width: number, height: number, rx: number, ry: number, x: number, y: number, z: number, material: THREE.Material ) => {

		const mesh = new THREE.Mesh( new THREE.PlaneGeometry( width, height ), material );
		mesh.rotation.set( rx, ry, 0 );
		mesh.position.set( x, y, z );
		root.add( mesh );

	};

	quad( 8, 4, - Math.PI / 2, 0, 0, 0, 0, single ); // floor, facing +y
	quad( 8, 4, Math.PI / 2, 0, 0, 3, 0, single ); // ceiling, facing −y
	quad( 8, 3, 0, 0, 0, 1.5, - 2, single ); // z = −2, facing +z
	quad( 8, 3, 0, Math.PI, 0, 1.5, 2, single ); // z = 2, facing −z
	quad( 4, 3, 0, Math.PI / 2, - 4, 1.5, 0, single ); // x = −4, facing +x
	quad( 4, 3, 0, - Math.PI / 2, 4, 1.5, 0, single ); // x = 4, facing −x
	// The middle wall (in the plane x = 0): two full-height pieces beside the doorway and a lintel.
	quad( 1.5, 3, 0, Math.PI / 2, 0, 1.5, - 1.25, double );
	quad( 1.5, 3, 0, Math.PI / 2, 0, 1.5, 1.25, double );
	quad( 1, 1, 0, Math.PI / 2, 0, 2.5, 0, double );
	if ( ! doorOpen ) quad( 1, 2, 0, Math.PI / 2, 0, 1, 0, double );
	return root;

}
