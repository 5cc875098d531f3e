import { describe, expect, it } from 'vitest';
import { regionWeights } from '../../src/placement/regionOfInterest.js';
import { WalkableRegion } from '../../src/placement/walkableRegion.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

/** Two triangles of the quad a, b, c, d (counter-clockwise seen from the side its front faces). */
const quad = ( a: number[], b: number[], c: number[], d: number[] ): number[] => [ ...a, ...b, ...c, ...a, ...c, ...d ];

/**
 * A small level, y up: a 4 × 4 floor at y = 0 facing up; a table top at y = 0.8 over [ 1, 2 ]² facing
 * up, its underside at y = 0.75 facing down; a 30° ramp rising from x = −2 (over z in [ −2, −1 ]);
 * a 60° slope (over z in [ 1, 2 ], x in [ −2, −1.5 ]); a wall at x = 2.
 */
function level(): Float64Array {

	const tan30 = Math.tan( Math.PI / 6 ), tan60 = Math.tan( Math.PI / 3 );
	return Float64Array.from( [
		...quad( [ - 2, 0, - 2 ], [ - 2, 0, 2 ], [ 2, 0, 2 ], [ 2, 0, - 2 ] ), // floor: (b − a) × (c − a) = +y
		...quad( [ 1, 0.8, 1 ], [ 1, 0.8, 2 ], [ 2, 0.8, 2 ], [ 2, 0.8, 1 ] ), // table top, up
		...quad( [ 1, 0.75, 1 ], [ 2, 0.75, 1 ], [ 2, 0.75, 2 ], [ 1, 0.75, 2 ] ), // underside, down
		...quad( [ - 2, 0.01, - 2 ], [ - 2, 0.01, - 1 ], [ - 1, 0.01 + tan30, - 1 ], [ - 1, 0.01 + tan30, - 2 ] ), // ramp, 30°
		...quad( [ - 2, 0.01, 1 ], [ - 2, 0.01, 2 ], [ - 1.5, 0.01 + 0.5 * tan60, 2 ], [ - 1.5, 0.01 + 0.5 * tan60, 1 ] ), // slope, 60°
		...quad( [ 2, 0, - 2 ], [ 2, 3, - 2 ], [ 2, 3, 2 ], [ 2, 0, 2 ] ), // wall
	] );

}

describe( 'WalkableRegion (where characters go: floor-facing triangles plus a height band)', () => {

	const walkable = new WalkableRegion( level() );

	it( 'finds the floor-facing triangles: floor, table top and the 30° ramp, not the underside, the 60° slope or the wall', () => {

		expect( Array.from( walkable.floorFacing ) ).toEqual( [ 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0, 0 ] );
		expect( walkable.floorTriangleCount ).toBe( 6 );

	} );

	it( 'contains the air within the height band above the first surface below, if that surface faces up', () => {

		expect( walkable.contains( 0, 1, 0 ) ).toBe( true ); // 1 above the floor
		expect( walkable.contains( 0, 1.99, 0 ) ).toBe( true );
		expect( walkable.contains( 0, 2.01, 0 ) ).toBe( false ); // above the 2 m band
		expect( walkable.contains( 1.5, 2.5, 1.5 ) ).toBe( true ); // 1.7 above the table top
		expect( walkable.contains( 1.5, 0.5, 1.5 ) ).toBe( true ); // under the table: the floor is first
		expect( walkable.contains( 1.5, 0.78, 1.5 ) ).toBe( false ); // inside the table slab: the underside is first
		expect( walkable.contains( - 1.5, 2, - 1.5 ) ).toBe( true ); // over the ramp, 1.7 above it
		expect( walkable.contains( - 1.75, 1.5, 1.5 ) ).toBe( false ); // over the 60° slope: too steep
		expect( walkable.contains( 3, 1, 0 ) ).toBe( false ); // beyond the wall: nothing below
		expect( walkable.contains( 0, - 0.5, 0 ) ).toBe( false ); // under the floor

	} );

	it( 'takes the height band, the slope limit, the up direction and the drawn sides from its options', () => {

		expect( new WalkableRegion( level(), { height: 3 } ).contains( 0, 2.5, 0 ) ).toBe( true );
		expect( new WalkableRegion( level(), { maxSlope: 70 } ).contains( - 1.75, 1.5, 1.5 ) ).toBe( true );
		expect( new WalkableRegion( level(), { maxSlope: 20 } ).contains( - 1.5, 1, - 1.5 ) ).toBe( false ); // the 30° ramp
		// The same level turned so that up is +z: (x, y, z) → (x, −z, y) keeps the winding's handedness.
		const source = level(), turned = new Float64Array( source.length );
		for ( let i = 0; i < source.length; i += 3 ) turned.set( [ source[ i ], - source[ i + 2 ], source[ i + 1 ] ], i );
		const zUp = new WalkableRegion( turned, { up: [ 0, 0, 5 ] } );
		expect( zUp.contains( 0, 0, 1 ) ).toBe( true );
		expect( zUp.contains( 0, 0, 2.5 ) ).toBe( false );
		expect( Array.from( zUp.floorFacing ) ).toEqual( Array.from( walkable.floorFacing ) );
		// A floor drawn only from below (BackSide) faces down; drawn on both sides it faces up too.
		const sides = new Int8Array( 12 ).fill( 1 );
		sides[ 0 ] = sides[ 1 ] = - 1;
		expect( new WalkableRegion( level(), { sides } ).contains( 0, 1, 0 ) ).toBe( false );
		sides[ 4 ] = sides[ 5 ] = 0; // the underside, double-sided: floor-facing now
		const both = new WalkableRegion( level(), { sides } );
		expect( both.contains( 1.5, 0.78, 1.5 ) ).toBe( true );

	} );

	it( 'rejects a level with no floor and bad options, naming WalkableRegion', () => {

		const wall = level().slice( 90 );
		expect( () => new WalkableRegion( wall ) ).toThrow( /^WalkableRegion: none of the 2 triangles faces up .*walkable region would be empty/ );
		expect( () => new WalkableRegion( [ 0, 0, 0 ] ) ).toThrow( /^WalkableRegion: triangles must hold 9 floats/ );
		const nan = level(); nan[ 5 ] = NaN;
		expect( () => new WalkableRegion( nan ) ).toThrow( /^WalkableRegion: triangles\[5\] is NaN/ );
		expect( () => new WalkableRegion( level(), { height: 0 } ) ).toThrow( /^WalkableRegion: options.height must be > 0/ );
		expect( () => new WalkableRegion( level(), { maxSlope: 90 } ) ).toThrow( /^WalkableRegion: options.maxSlope must be in 0..90/ );
		expect( () => new WalkableRegion( level(), { up: [ 0, 0, 0 ] } ) ).toThrow( /^WalkableRegion: options.up must be a non-zero direction/ );
		expect( () => new WalkableRegion( level(), { sides: [ 1 ] } ) ).toThrow( /^WalkableRegion: options.sides must have one entry per triangle \(12\)/ );
		expect( () => walkable.contains( 0, NaN, 0 ) ).toThrow( /^WalkableRegion.contains: y is NaN/ );

	} );

} );

describe( 'regionWeights (1 inside the region of interest, outsideWeight outside)', () => {

	const random = mulberry32( 3 );
	const points = Float64Array.from( { length: 3 * 2000 }, () => 4 * random() - 2 );

	it( 'weights points in boxes (faces included), near given points and in the walkable region', () => {

		const boxes = [ { min: [ - 1, - 1, - 1 ], max: [ 0, 0.5, 0 ] }, { min: [ 1, 1, 1 ], max: [ 1, 1, 1 ] } ];
		const navPoints = [ 1.5, 0, - 1.5, - 1.5, - 1.5, 1.5 ], r = 0.4;
		const walkable = new WalkableRegion( level() );
		const positions = Float64Array.of( ...points, 1, 1, 1 ); // the last lies exactly on the flat box
		const weights = regionWeights( positions, { boxes, points: navPoints, radius: 0.4, walkable } );
		let inside = 0;
		for ( let p = 0; p < positions.length / 3; p ++ ) {

			const [ x, y, z ] = positions.subarray( 3 * p, 3 * p + 3 );
			const inBox = boxes.some( ( b ) => [ x, y, z ].every( ( v, a ) => v >= b.min[ a ] && v <= b.max[ a ] ) );
			const near = [ 0, 3 ].some( ( k ) => Math.hypot( x - navPoints[ k ], y - navPoints[ k + 1 ], z - navPoints[ k + 2 ] ) <= r );
			const expected = inBox || near || walkable.contains( x, y, z ) ? 1 : 0.1;
			expect( weights[ p ] ).toBe( expected );
			if ( expected === 1 ) inside ++;

		}

		expect( weights[ 2000 ] ).toBe( 1 );
		// Every part contributed, and not everything is inside.
		expect( inside ).toBeGreaterThan( 100 );
		expect( inside ).toBeLessThan( 1900 );
		expect( regionWeights( positions, { points: navPoints, radius: 0.4 } ).filter( ( w ) => w === 1 ).length ).toBeGreaterThan( 0 );

	} );

	it( 'uses the given outside weight (0 leaves the outside out)', () => {

		const box = { min: [ - 1, - 1, - 1 ], max: [ 1, 1, 1 ] };
		const weights = regionWeights( [ 0, 0, 0, 5, 5, 5 ], { boxes: [ box ], outsideWeight: 0 } );
		expect( Array.from( weights ) ).toEqual( [ 1, 0 ] );

	} );

	it( 'rejects an empty region, NaN and bad boxes, naming regionWeights', () => {

		const box = { min: [ 0, 0, 0 ], max: [ 1, 1, 1 ] };
		expect( () => regionWeights( [ 5, 5, 5, 6, 6, 6 ], { boxes: [ box ] } ) )
			.toThrow( /^regionWeights: region contains none of the 2 positions it should weight/ );
		expect( () => regionWeights( [ 0, 0, 0 ], {} ) ).toThrow( /^regionWeights: region names no boxes, no points and no walkable region/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { boxes: [ { min: [ 1, 0, 0 ], max: [ 0, 1, 1 ] } ] } ) )
			.toThrow( /^regionWeights: region.boxes\[0\] has min x 1 > max 0/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { boxes: [ { min: [ NaN, 0, 0 ], max: [ 1, 1, 1 ] } ] } ) )
			.toThrow( /^regionWeights: region.boxes\[0\].min\[0\] is NaN/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { boxes: [ { min: [ 0, 0 ], max: [ 1, 1, 1 ] } ] } ) )
			.toThrow( /^regionWeights: region.boxes\[0\].min must hold x, y, z/ );
		expect( () => regionWeights( [ 0, NaN, 0 ], { boxes: [ box ] } ) ).toThrow( /^regionWeights: positions\[1\] is NaN/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { points: [ 0, 0, 0 ] } ) ).toThrow( /^regionWeights: region.radius must be a finite number > 0/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { points: [ 0, 0, NaN ], radius: 1 } ) ).toThrow( /^regionWeights: region.points\[2\] is NaN/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { boxes: [ box ], outsideWeight: 2 } ) ).toThrow( /^regionWeights: region.outsideWeight must be a number in 0..1/ );
		expect( () => regionWeights( [ 0, 0, 0 ], { walkable: {} as WalkableRegion } ) ).toThrow( /^regionWeights: region.walkable must be a WalkableRegion/ );
		expect( () => regionWeights( [ 0, 0, 0 ], null as never ) ).toThrow( /^regionWeights: region must be an object/ );

	} );

} );
