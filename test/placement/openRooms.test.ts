/**
 * Issue 13: the inside test on open rooms. Each scene has an analytic open space; the counts in
 * the test names are the candidates that survive, before (ray parity, `parityVote`) and after.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { classifyPoints, INSIDE_GEOMETRY, OPEN_SPACE, UNREACHABLE } from '../../src/placement/classifyPoints.js';
import { placeFromMeshes } from '../../src/placement/placeFromMeshes.js';
import { placeGrid } from '../../src/placement/placeGrid.js';
import { gatherDrawnSides } from '../../src/placement/gatherDrawnSides.js';
import { gatherWorldGeometry } from '../../src/geometry/gatherWorldGeometry.js';
import { TriangleBVH } from '../../src/geometry/TriangleBVH.js';
import { seededRandom } from '../helpers/pointSets.js';
import { boxDistance } from './helpers.js';
import { blockMesh, cornellBox, insideBlock, parityVote, twoRoomLevel, type Block } from './openScenes.js';
import { createBasicRoom } from '../../scenes/basic.js';

/** The scene's BVH and drawn sides, as placeFromMeshes reads them. */
function sceneOf( root: THREE.Object3D ): { bvh: TriangleBVH; sides: Int8Array } {

	const { triangles } = gatherWorldGeometry( root );
	return { bvh: new TriangleBVH( triangles ), sides: gatherDrawnSides( root ).triangleSides };

}

const count = ( classes: Uint8Array, c: number ) => classes.filter( ( v ) => v === c ).length;

describe( 'the inside test on a Cornell box of open quads (5 walls, no front, facing in; two closed blocks)', () => {

	// 27 grid points spaced 0.5 in the middle of the box: 6 fall inside the blocks (the analytic
	// block test below), 21 in open space.
	const grid = placeGrid( [ - 0.5, 0.5, - 0.5 ], [ 0.5, 1.5, 0.5 ], [ 3, 3, 3 ] );

	for ( const [ name, side ] of [ [ 'single-sided', THREE.FrontSide ], [ 'double-sided', THREE.DoubleSide ] ] as const ) {

		const { root, blocks } = cornellBox( side );
		const { bvh, sides } = sceneOf( root );
		const inBlock = ( x: number, y: number, z: number ) => blocks.some( ( b ) => insideBlock( b, x, y, z ) );

		it( `${name}: 21 of the 27 grid candidates are open space and the 6 in the blocks inside, as the analytic truth; ray parity kept 6 — exactly the 6 inside the blocks`, () => {

			const classes = classifyPoints( grid, bvh, { sides } );
			const parity = parityVote( grid, bvh );
			let inside = 0;
			for ( let i = 0; i < 27; i ++ ) {

				const truth = inBlock( grid[ 3 * i ], grid[ 3 * i + 1 ], grid[ 3 * i + 2 ] );
				if ( truth ) inside ++;
				expect( classes[ i ], `grid point ${i}` ).toBe( truth ? INSIDE_GEOMETRY : OPEN_SPACE );
				// Parity counts the open box's one wall crossing as "inside", and a block inside it as two.
				expect( parity[ i ], `grid point ${i}` ).toBe( ! truth );

			}

			expect( inside ).toBe( 6 );

		} );

		it( `${name}: agrees with the analytic inside on 3000 random points in the box (more than 0.01 from every surface)`, () => {

			const random = seededRandom( 21 );
			const points: number[] = [];
			while ( points.length < 3 * 3000 ) {

				const x = 2 * random() - 1, y = 2 * random(), z = 2 * random() - 1;
				if ( Math.min( 1 - Math.abs( x ), y, 2 - y, 1 - Math.abs( z ) ) < 0.01 ) continue;
				if ( blocks.some( ( b ) => insideBlock( b, x, y, z, - 0.01 ) !== insideBlock( b, x, y, z, 0.01 ) ) ) continue;
				points.push( x, y, z );

			}

			const classes = classifyPoints( points, bvh, { sides } );
			let inside = 0;
			for ( let i = 0; i < 3000; i ++ ) {

				const truth = inBlock( points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] );
				if ( truth ) inside ++;
				expect( classes[ i ], `point ${i}` ).toBe( truth ? INSIDE_GEOMETRY : OPEN_SPACE );

			}

			// Both outcomes occur (the blocks fill about 12 % of the box), or the test could not fail.
			expect( inside ).toBeGreaterThan( 150 );
			expect( 3000 - inside ).toBeGreaterThan( 2000 );

		} );

		it( `${name}: points beyond the walls pass the inside test, and reachableFrom (a spawn in the box) makes them unreachable; the open grid points stay`, () => {

			// Behind the back, left and right walls, under the floor, over the ceiling, in front of the
			// opening: fewer than half of their rays meet a wall (from its back), so they are not
			// inside anything — but they are outside the scene's bounding box, which the fill never leaves.
			const beyond = [ 0, 1, - 1.3, - 1.3, 1, 0, 1.3, 1, 0, 0, - 0.3, 0, 0, 2.3, 0, 0, 1, 1.5 ];
			expect( Array.from( classifyPoints( beyond, bvh, { sides } ) ) ).toEqual( Array( 6 ).fill( OPEN_SPACE ) );
			const classes = classifyPoints( [ ...grid, ...beyond ], bvh, { sides, reachableFrom: [ [ 0.5, 1.5, 0.5 ] ] } );
			expect( count( classes.subarray( 0, 27 ), OPEN_SPACE ) ).toBe( 21 );
			expect( count( classes.subarray( 0, 27 ), INSIDE_GEOMETRY ) ).toBe( 6 );
			expect( Array.from( classes.subarray( 27 ) ) ).toEqual( Array( 6 ).fill( UNREACHABLE ) );

		} );

	}

	it( 'placeFromMeshes on the double-sided box (walls 4 × 4 quads): vertex candidates both sides of every wall; reachableFrom keeps exactly those in the box', () => {

		// Double-sided walls are moved both ways: half the wall candidates land behind the walls,
		// which no inside test can reject (a double-sided wall has no wrong side); only reachability
		// can. Analytic check: every kept candidate is in the box, 0.05 or more from the walls and out
		// of the blocks; and every dropped one is out of the box or inside a block.
		const { root, blocks } = cornellBox( THREE.DoubleSide, 4 );
		const offset = 0.1, options = { offset, minSpacing: 0.05 };
		const all = placeFromMeshes( root, options );
		const reachable = placeFromMeshes( root, { ...options, reachableFrom: [ { x: 0.5, y: 1.5, z: 0.5 } ] } );
		// Signed distance to the box [−1, 1] × [0, 2] × [−1, 1]: > 0 beyond its walls (or in front of its opening).
		const fromBox = ( p: Float64Array, i: number ) => boxDistance( p[ i ], p[ i + 1 ], p[ i + 2 ], 0, 1, 0, 1, 1, 1 );
		const keys = new Set<string>();
		for ( let i = 0; i < reachable.length; i += 3 ) {

			keys.add( `${reachable[ i ]},${reachable[ i + 1 ]},${reachable[ i + 2 ]}` );
			// In the box (or in the plane of its opening, z = 1), out of the blocks.
			expect( fromBox( reachable, i ) ).toBeLessThanOrEqual( 1e-9 );
			expect( blocks.some( ( b ) => insideBlock( b, reachable[ i ], reachable[ i + 1 ], reachable[ i + 2 ] ) ) ).toBe( false );

		}

		let beyond = 0;
		for ( let i = 0; i < all.length; i += 3 ) {

			if ( fromBox( all, i ) > 1e-9 ) beyond ++;
			expect( keys.has( `${all[ i ]},${all[ i + 1 ]},${all[ i + 2 ]}` ) ).toBe( fromBox( all, i ) <= 1e-9 );

		}

		expect( beyond ).toBeGreaterThan( 40 );
		expect( reachable.length / 3 ).toBeGreaterThan( 40 );

	} );

} );

describe( 'the inside test on rooms drawn from inside (BackSide)', () => {

	it( 'the Basic room of scenes/basic.ts: all 64 points of its 4 × 4 × 4 grid are open space; ray parity kept 0 (a closed box: every ray crosses it once)', () => {

		const { room } = createBasicRoom();
		const { bvh, sides } = sceneOf( room );
		const grid = placeGrid( [ - 1.8, 0.2, - 1.8 ], [ 1.8, 2.8, 1.8 ], [ 4, 4, 4 ] ); // scenes/basic.ts basicGrid
		expect( count( classifyPoints( grid, bvh, { sides } ), OPEN_SPACE ) ).toBe( 64 );
		expect( parityVote( grid, bvh ).filter( ( inside ) => ! inside ).length ).toBe( 0 );

	} );

	it( 'placeFromMeshes moves the vertices of a BackSide room into it (before: out of it, along the outward normals)', () => {

		// Unsubdivided, as in scenes/basic.ts, every corner vertex moved along one wall's normal lies
		// on the two other walls at that corner (rejected as near a surface): only the bulb's
		// vertices give candidates. That is why `placeProbes` adds grid candidates.
		const bare = placeFromMeshes( createBasicRoom().room, { offset: 0.3, minSpacing: 0.25 } );
		for ( let i = 0; i < bare.length; i += 3 ) {

			expect( Math.hypot( bare[ i ] - 0.2, bare[ i + 1 ] - 2.1, bare[ i + 2 ] - 0.3 ) ).toBeCloseTo( 0.38, 1 );

		}



		// BoxGeometry's normals point out of the box; BackSide draws the inside. 8 × 6 × 8 segments:
		// the face vertices away from the edges land 0.3 inside the room, clear of the other walls.
		const { room } = createBasicRoom( 8 );
		const kept = placeFromMeshes( room, { offset: 0.3, minSpacing: 0.25 } );
		expect( kept.length / 3 ).toBeGreaterThan( 150 );
		for ( let i = 0; i < kept.length; i += 3 ) {

			// Inside the room by at least offset / 2, and not in the bulb (radius 0.08 at the lamp).
			expect( - boxDistance( kept[ i ], kept[ i + 1 ], kept[ i + 2 ], 0, 1.5, 0, 2, 1.5, 2 ) ).toBeGreaterThanOrEqual( 0.15 - 1e-9 );

		}

	} );

	it( 'a room with a closed box prop: grid and vertex candidates inside the prop are rejected, all others kept', () => {

		const { room } = createBasicRoom( 8 );
		const prop: Block = { centre: [ 0.5, 0.5, - 0.5 ], half: [ 0.5, 0.5, 0.5 ], angle: 0.4 };
		room.add( blockMesh( prop, new THREE.MeshStandardMaterial() ) );
		const { bvh, sides } = sceneOf( room );
		const grid = placeGrid( [ - 1.75, 0.25, - 1.75 ], [ 1.75, 2.75, 1.75 ], [ 8, 6, 8 ] );
		const classes = classifyPoints( grid, bvh, { sides, minDistance: 0.02 } );
		let inProp = 0;
		for ( let i = 0; i < grid.length / 3; i ++ ) {

			const x = grid[ 3 * i ], y = grid[ 3 * i + 1 ], z = grid[ 3 * i + 2 ];
			if ( insideBlock( prop, x, y, z, - 0.02 ) !== insideBlock( prop, x, y, z, 0.02 ) ) continue; // within 0.02 of its faces
			if ( Math.hypot( x - 0.2, y - 2.1, z - 0.3 ) < 0.1 ) continue; // the bulb
			const truth = insideBlock( prop, x, y, z );
			if ( truth ) inProp ++;
			expect( classes[ i ], `grid point ${i}` ).toBe( truth ? INSIDE_GEOMETRY : OPEN_SPACE );

		}

		expect( inProp ).toBeGreaterThan( 2 );

		// Floor vertices under the prop, moved 0.3 up, land inside it: all rejected, the rest kept.
		const all = placeFromMeshes( room, { offset: 0.3, minSpacing: 0.25, rejectInside: false, minDistance: 0 } );
		const kept = placeFromMeshes( room, { offset: 0.3, minSpacing: 0.25 } );
		let inside = 0;
		for ( let i = 0; i < all.length; i += 3 ) if ( insideBlock( prop, all[ i ], all[ i + 1 ], all[ i + 2 ] ) ) inside ++;
		expect( inside ).toBeGreaterThan( 3 );
		for ( let i = 0; i < kept.length; i += 3 ) {

			expect( insideBlock( prop, kept[ i ], kept[ i + 1 ], kept[ i + 2 ], - 0.15 ) ).toBe( false );

		}


	} );

	it( 'a closed double-sided room is a solid without a seed, and open space with one inside it', () => {

		// Geometry cannot tell a double-sided closed box from a crate: the spawn says which it is.
		const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 4 ), new THREE.MeshStandardMaterial( { side: THREE.DoubleSide } ) );
		room.position.y = 1.5;
		const { bvh, sides } = sceneOf( room );
		const grid = placeGrid( [ - 1.5, 0.5, - 1.5 ], [ 1.5, 2.5, 1.5 ], [ 3, 3, 3 ] );
		expect( count( classifyPoints( grid, bvh, { sides } ), INSIDE_GEOMETRY ) ).toBe( 27 );
		expect( count( classifyPoints( grid, bvh, { sides, reachableFrom: [ 0, 1.6, 0 ] } ), OPEN_SPACE ) ).toBe( 27 );

	} );

} );

describe( 'reachableFrom: a level with a sealed room', () => {

	// 8 × 6 × 4 grid points, spaced 1 (0.5 from the walls): 96 per room.
	const grid = placeGrid( [ - 3.5, 0.5, - 1.5 ], [ 3.5, 2.5, 1.5 ], [ 8, 3, 4 ] );
	const spawn = [ - 2, 1.6, 0 ];

	it( 'door closed: the 48 points of room B are unreachable from a spawn in room A, the 48 of A reachable; without a seed all 96 are open', () => {

		const { bvh, sides } = sceneOf( twoRoomLevel( false ) );
		const classes = classifyPoints( grid, bvh, { sides, reachableFrom: spawn } );
		for ( let i = 0; i < grid.length / 3; i ++ ) expect( classes[ i ], `grid point ${i}` ).toBe( grid[ 3 * i ] < 0 ? OPEN_SPACE : UNREACHABLE );
		expect( count( classes, UNREACHABLE ) ).toBe( 48 );
		expect( count( classifyPoints( grid, bvh, { sides } ), OPEN_SPACE ) ).toBe( 96 );

	} );

	it( 'door open: all 96 are reachable (the fill finds the 1 m doorway at the default cell of 8 / 64 m)', () => {

		const { bvh, sides } = sceneOf( twoRoomLevel( true ) );
		expect( count( classifyPoints( grid, bvh, { sides, reachableFrom: spawn } ), OPEN_SPACE ) ).toBe( 96 );

	} );

	it( 'rejects seeds inside geometry or on a surface, naming the seed', () => {

		const { root } = cornellBox( THREE.FrontSide );
		const { bvh, sides } = sceneOf( root );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { sides, reachableFrom: [ [ - 0.335, 0.6, - 0.29 ] ] } ) )
			.toThrow( /^classifyPoints: options\.reachableFrom\[0\] \(-0\.335, 0\.6, -0\.29\) is inside geometry/ );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { sides, reachableFrom: [ 0.5, 1.5, 0.5, 0.9, 0, 0.9 ] } ) )
			.toThrow( /^classifyPoints: options\.reachableFrom\[1\] \(0\.9, 0, 0\.9\) lies on a surface/ );
		expect( () => placeFromMeshes( root, { offset: 0.1, minSpacing: 0.1, reachableFrom: [ [ - 0.335, 0.6, - 0.29 ] ] } ) )
			.toThrow( /^placeFromMeshes: options\.reachableFrom\[0\] .* is inside geometry/ );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { reachableFrom: [ 1, 2 ] } ) ).toThrow( /^classifyPoints: options\.reachableFrom must hold x, y, z/ );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { reachableFrom: [ { x: 0, y: NaN, z: 0 } ] } ) )
			.toThrow( /^classifyPoints: options\.reachableFrom\[0\]\.y is NaN/ );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { reachableFrom: [] } ) ).toThrow( /^classifyPoints: options\.reachableFrom needs at least 1/ );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { sides: [ 1, 2 ] } ) ).toThrow( /^classifyPoints: options\.sides must have one entry per triangle/ );
		expect( () => classifyPoints( [ 0, 1, 0 ], bvh, { reachCellSize: 0 } ) ).toThrow( /^classifyPoints: options\.reachCellSize must be a finite number/ );

	} );

} );
