import { describe, expect, it } from 'vitest';
import { BoxGeometry } from 'three';
import {
	INSIDE, NEAR, OPEN, OUTSIDE, OpenSpaceTest, jitteredGrid, mulberry32, sampleOpenSpace, sphereDirections, thinIndices, vertexCandidates,
} from '../../scripts/experiment/samples.js';

/** World triangles (9 floats each) of a box, and its side per triangle. */
function box(
	width: number, height: number, depth: number, [ cx, cy, cz ]: number[], side: number, skipFaces: number[] = []
): { triangles: number[]; sides: number[] } {

	const geometry = new BoxGeometry( width, height, depth ).toNonIndexed();
	const p = geometry.getAttribute( 'position' );
	const triangles: number[] = [], sides: number[] = [];
	for ( let t = 0; t < p.count / 3; t ++ ) {

		// BoxGeometry: 2 triangles per face, faces +x, −x, +y, −y, +z, −z.
		if ( skipFaces.includes( Math.floor( t / 2 ) ) ) continue;
		for ( let c = 0; c < 3; c ++ ) triangles.push( p.getX( 3 * t + c ) + cx, p.getY( 3 * t + c ) + cy, p.getZ( 3 * t + c ) + cz );
		sides.push( side );

	}

	return { triangles, sides };

}

/** A 4 × 3 × 4 room seen from inside (BackSide, like scenes/basic.ts) with a solid 1 m cube on the floor. */
function roomWithCube( openTop = false ): { triangles: number[]; sides: number[] } {

	const room = box( 4, 3, 4, [ 0, 1.5, 0 ], - 1, openTop ? [ 2 ] : [] );
	const cube = box( 1, 1, 1, [ 1, 0.5, 1 ], 1 );
	return { triangles: [ ...room.triangles, ...cube.triangles ], sides: [ ...room.sides, ...cube.sides ] };

}

const ROOM = { min: [ - 2, 0, - 2 ], max: [ 2, 3, 2 ] };

describe( 'experiment: point sets', () => {

	it( 'mulberry32 is seeded, deterministic and in [0, 1)', () => {

		const a = mulberry32( 7 ), b = mulberry32( 7 ), c = mulberry32( 8 );
		const sa = Array.from( { length: 1000 }, a ), sb = Array.from( { length: 1000 }, b ), sc = Array.from( { length: 1000 }, c );
		expect( sa ).toEqual( sb );
		expect( sa ).not.toEqual( sc );
		for ( const v of sa ) expect( v >= 0 && v < 1 ).toBe( true );
		expect( sa.reduce( ( s, v ) => s + v, 0 ) / 1000 ).toBeCloseTo( 0.5, 1 );

	} );

	it( 'spreads unit ray directions over the whole sphere', () => {

		const d = sphereDirections( 32 );
		const sum = [ 0, 0, 0 ];
		for ( let i = 0; i < 32; i ++ ) {

			expect( Math.hypot( d[ 3 * i ], d[ 3 * i + 1 ], d[ 3 * i + 2 ] ) ).toBeCloseTo( 1, 12 );
			for ( let a = 0; a < 3; a ++ ) sum[ a ] += d[ 3 * i + a ];

		}

		for ( const s of sum ) expect( Math.abs( s ) ).toBeLessThan( 0.5 );

	} );

	it( 'classifies open space, near a surface, inside geometry (seen through its undrawn side) and outside an interior', () => {

		const { triangles, sides } = roomWithCube();
		const test = new OpenSpaceTest( triangles, sides, { minDistance: 0.1 } );
		expect( test.classify( 0, 1.5, 0 ) ).toBe( OPEN );
		expect( test.classify( - 1.95, 1.5, 0 ) ).toBe( NEAR ); // 5 cm from the red wall
		expect( test.classify( 1, 0.5, 1 ) ).toBe( INSIDE ); // in the solid cube: every ray sees its back faces
		expect( test.classify( 0, 5, 0 ) ).toBe( INSIDE ); // above the room: its walls are drawn from inside only

		// Without the ceiling, points in the room see the sky through the opening.
		const open = roomWithCube( true );
		const closedInterior = new OpenSpaceTest( open.triangles, open.sides, { minDistance: 0.1, maxSky: 0.25 } );
		expect( closedInterior.classify( 0, 0.3, 0 ) ).toBe( OPEN ); // low: most rays hit walls and floor
		expect( closedInterior.classify( 0, 2.9, 0 ) ).toBe( OUTSIDE ); // half the rays leave through the top
		const anySky = new OpenSpaceTest( open.triangles, open.sides, { minDistance: 0.1 } );
		expect( anySky.classify( 0, 2.9, 0 ) ).toBe( OPEN );

	} );

	it( 'draws ground-truth samples in open space only, the same for the same seed', () => {

		const { triangles, sides } = roomWithCube();
		const test = new OpenSpaceTest( triangles, sides, { minDistance: 0.1 } );
		const a = sampleOpenSpace( test, ROOM, 500, 1 );
		const b = sampleOpenSpace( test, ROOM, 500, 1 );
		const c = sampleOpenSpace( test, ROOM, 500, 2 );
		expect( a.positions.length ).toBe( 1500 );
		expect( Array.from( a.positions ) ).toEqual( Array.from( b.positions ) );
		expect( Array.from( a.positions ) ).not.toEqual( Array.from( c.positions ) );
		expect( a.drawn ).toBe( 500 + a.near + a.inside + a.outside );
		expect( a.inside ).toBeGreaterThan( 0 ); // the cube is 1/48 of the room: some draws land in it
		for ( let i = 0; i < 1500; i += 3 ) {

			const [ x, y, z ] = [ a.positions[ i ], a.positions[ i + 1 ], a.positions[ i + 2 ] ];
			// In the room, ≥ 0.1 from its walls, and not in (or within 0.1 of) the cube.
			expect( Math.min( x + 2, 2 - x, y, 3 - y, z + 2, 2 - z ) ).toBeGreaterThanOrEqual( 0.1 );
			expect( Math.max( Math.abs( x - 1 ), Math.abs( y - 0.5 ), Math.abs( z - 1 ) ) ).toBeGreaterThan( 0.5 );

		}

		// Roughly uniform: the fraction in the room's left half is about a half.
		let left = 0;
		for ( let i = 0; i < 1500; i += 3 ) if ( a.positions[ i ] < 0 ) left ++;
		expect( left / 500 ).toBeGreaterThan( 0.43 );
		expect( left / 500 ).toBeLessThan( 0.6 );

	} );

	it( 'gives up with a message when the box holds no open space', () => {

		const { triangles, sides } = roomWithCube();
		const test = new OpenSpaceTest( triangles, sides, { minDistance: 0.1 } );
		expect( () => sampleOpenSpace( test, { min: [ 0.7, 0.2, 0.7 ], max: [ 1.3, 0.8, 1.3 ] }, 10, 1 ) ).toThrow( /only 0 of 10 points in open space/ );

	} );

	it( 'builds the dense candidates: a seeded jittered grid in the box, vertex candidates on the drawn side, thinned', () => {

		const grid = jitteredGrid( ROOM, 0.5, 0.35, 3 );
		expect( grid.length / 3 ).toBe( 9 * 7 * 9 );
		expect( Array.from( grid ) ).toEqual( Array.from( jitteredGrid( ROOM, 0.5, 0.35, 3 ) ) );
		for ( let i = 0; i < grid.length; i += 3 ) for ( let a = 0; a < 3; a ++ ) {

			expect( grid[ i + a ] ).toBeGreaterThanOrEqual( ROOM.min[ a ] );
			expect( grid[ i + a ] ).toBeLessThanOrEqual( ROOM.max[ a ] );

		}

		// The cube's corners moved 0.3 outwards along each face's normal: into the room, not into the cube.
		const cube = box( 1, 1, 1, [ 1, 0.5, 1 ], 1 );
		const candidates = vertexCandidates( cube.triangles, cube.sides, ROOM, 0.3, 0.01 );
		expect( candidates.length / 3 ).toBe( 20 ); // 8 corners × 3 faces, but the 4 moved below the floor (out of the box)
		for ( let i = 0; i < candidates.length; i += 3 ) {

			expect( Math.max(
				Math.abs( candidates[ i ] - 1 ), Math.abs( candidates[ i + 1 ] - 0.5 ), Math.abs( candidates[ i + 2 ] - 1 )
			) ).toBeCloseTo( 0.8, 6 );

		}

		// The room is drawn from inside: its corners move into it (with the outward normals of the
		// geometry they would all land outside the box and be dropped).
		const room = box( 4, 3, 4, [ 0, 1.5, 0 ], - 1 );
		const inward = vertexCandidates( room.triangles, room.sides, ROOM, 0.3, 0.01 );
		expect( inward.length / 3 ).toBe( 24 );
		const outward = vertexCandidates( room.triangles, room.sides.map( () => 1 ), ROOM, 0.3, 0.01 );
		expect( outward.length ).toBe( 0 );

		const kept = thinIndices( grid, 0.6 );
		for ( let i = 0; i < kept.length; i ++ ) for ( let j = 0; j < i; j ++ ) {

			const p = 3 * kept[ i ], q = 3 * kept[ j ];
			expect( Math.hypot( grid[ p ] - grid[ q ], grid[ p + 1 ] - grid[ q + 1 ], grid[ p + 2 ] - grid[ q + 2 ] ) )
				.toBeGreaterThanOrEqual( 0.6 );

		}

	} );

} );
