/**
 * The pieces of the inside test: corner welding, closed shells and their orientation, the winding
 * number along a ray, the reachability flood fill, point lists and drawn sides.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { weldCorners } from '../../src/geometry/weldCorners.js';
import { findClosedShells } from '../../src/geometry/findClosedShells.js';
import { windingAlongRay } from '../../src/geometry/windingAlongRay.js';
import { intersectRayTriangle } from '../../src/geometry/intersectRayTriangle.js';
import { TriangleBVH } from '../../src/geometry/TriangleBVH.js';
import { gatherWorldGeometry } from '../../src/geometry/gatherWorldGeometry.js';
import { ReachableSpace } from '../../src/placement/ReachableSpace.js';
import { blockedLatticeEdges } from '../../src/placement/blockedLatticeEdges.js';
import { readPointList } from '../../src/placement/readPointList.js';
import { DRAWN_AGAINST_NORMAL, DRAWN_ALONG_NORMAL, gatherDrawnSides } from '../../src/placement/gatherDrawnSides.js';
import { classifyPoints, INSIDE_GEOMETRY, OPEN_SPACE } from '../../src/placement/classifyPoints.js';
import { seededRandom } from '../helpers/pointSets.js';
import { trianglesOf } from './helpers.js';
import { twoRoomLevel } from './openScenes.js';

const ones = ( n: number, value = 1 ) => new Int8Array( n ).fill( value );

/** Six times the signed volume of the triangles taken with their orientation (divergence theorem). */
function orientedVolume( triangles: Float64Array, orientation: Int8Array ): number {

	let v = 0;
	for ( let t = 0; t < orientation.length; t ++ ) {

		const k = 9 * t, a = triangles.subarray( k, k + 3 ), b = triangles.subarray( k + 3, k + 6 ), c = triangles.subarray( k + 6, k + 9 );
		v += orientation[ t ] * ( a[ 0 ] * ( b[ 1 ] * c[ 2 ] - b[ 2 ] * c[ 1 ] ) - a[ 1 ] * ( b[ 0 ] * c[ 2 ] - b[ 2 ] * c[ 0 ] )
			+ a[ 2 ] * ( b[ 0 ] * c[ 1 ] - b[ 1 ] * c[ 0 ] ) );

	}

	return v;

}

/** The triangles of `geometry` with the winding of the triangles in `flip` reversed. */
function flipped( triangles: Float64Array, flip: ( t: number ) => boolean ): Float64Array {

	const out = triangles.slice();
	for ( let t = 0; t < out.length / 9; t ++ ) {

		if ( ! flip( t ) ) continue;
		out.set( triangles.subarray( 9 * t + 3, 9 * t + 6 ), 9 * t + 6 );
		out.set( triangles.subarray( 9 * t + 6, 9 * t + 9 ), 9 * t + 3 );

	}

	return out;

}

describe( 'weldCorners', () => {

	it( 'gives the corners of three\'s sphere one id per distinct position (seam and poles welded)', () => {

		// SphereGeometry( 1, 16, 8 ) repeats its seam column and its pole per segment: 17 × 9 vertices,
		// of which 16 × 7 + 2 are distinct points.
		const { ids, count } = weldCorners( trianglesOf( new THREE.SphereGeometry( 1, 16, 8 ) ) );
		expect( count ).toBe( 16 * 7 + 2 );
		expect( Math.max( ...ids ) ).toBe( count - 1 );

	} );

	it( 'keeps corners apart that are farther than 1e-6 of the diagonal, and welds those closer', () => {

		const near = weldCorners( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 1e-8, 0, 0, 1, 1e-8, 0, 0, 1, 1e-8 ] );
		expect( Array.from( near.ids ) ).toEqual( [ 0, 1, 2, 0, 1, 2 ] );
		const far = weldCorners( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 1e-5, 0, 0, 1, 1e-5, 0, 0, 1, 1e-5 ] );
		expect( far.count ).toBe( 6 );

	} );

} );

describe( 'findClosedShells', () => {

	const box = trianglesOf( new THREE.BoxGeometry( 2, 1, 1.5, 2, 2, 2 ) );
	const boxCount = box.length / 9;

	it( 'a box is one closed shell, oriented by its drawn side: out for FrontSide, in for BackSide, out (positive volume) for DoubleSide', () => {

		for ( const [ side, expected ] of [ [ 1, 1 ], [ - 1, - 1 ], [ 0, 1 ] ] ) {

			const shells = findClosedShells( box, ones( boxCount, side ) );
			expect( shells.count ).toBe( 1 );
			expect( Array.from( shells.orientation ) ).toEqual( Array( boxCount ).fill( expected ) );
			expect( Array.from( shells.fromSides ) ).toEqual( [ side === 0 ? 0 : 1 ] );

		}

		// The box's volume is 3, so six times it is 18: the orientation makes the volume positive or negative.
		expect( orientedVolume( box, findClosedShells( box, ones( boxCount ) ).orientation ) ).toBeCloseTo( 18, 9 );

	} );

	it( 'an inside-out double-sided box, or one with two faces wound the wrong way, is turned into an outward solid', () => {

		const insideOut = flipped( box, () => true );
		expect( orientedVolume( insideOut, findClosedShells( insideOut, ones( boxCount, 0 ) ).orientation ) ).toBeCloseTo( 18, 9 );
		// BoxGeometry( …, 2, 2, 2 ) puts 8 triangles per face: faces 0 and 3 (+x, −y) reversed.
		const mixed = flipped( box, ( t ) => t < 8 || ( t >= 24 && t < 32 ) );
		const shells = findClosedShells( mixed, ones( boxCount ) );
		expect( shells.count ).toBe( 1 );
		expect( shells.fromSides[ 0 ] ).toBe( 0 ); // the sides contradict each other: orientation chosen
		expect( orientedVolume( mixed, shells.orientation ) ).toBeCloseTo( 18, 9 );

	} );

	it( 'a box without one face, or without one triangle, is open; two boxes are two shells', () => {

		expect( findClosedShells( box.slice( 0, 9 * ( boxCount - 8 ) ), ones( boxCount - 8 ) ).count ).toBe( 0 );
		expect( findClosedShells( box.slice( 9 ), ones( boxCount - 1 ) ).count ).toBe( 0 );
		const two = new Float64Array( 2 * box.length );
		two.set( box );
		two.set( box.map( ( v, i ) => ( i % 3 === 0 ? v + 5 : v ) ), box.length );
		const shells = findClosedShells( two, ones( 2 * boxCount ) );
		expect( shells.count ).toBe( 2 );
		expect( new Set( shells.shell ).size ).toBe( 2 );

	} );

	it( 'welds three\'s sphere and torus seams into closed shells', () => {

		for ( const geometry of [ new THREE.SphereGeometry( 1, 48, 32 ), new THREE.TorusGeometry( 1, 0.35, 32, 96 ) ] ) {

			const triangles = trianglesOf( geometry );
			const shells = findClosedShells( triangles, ones( triangles.length / 9 ) );
			expect( shells.count ).toBe( 1 );
			expect( shells.orientation.every( ( o ) => o === 1 ) ).toBe( true );

		}

	} );

} );

describe( 'windingAlongRay', () => {

	it( 'finds the first hit of raycastFirst and sums orientation · sign( d · n ) over all hits, like a scan of every triangle', () => {

		const random = seededRandom( 31 );
		const triangles = new Float64Array( 9 * 3000 );
		for ( let t = 0; t < 3000; t ++ ) {

			const cx = random(), cy = random(), cz = random();
			for ( let k = 0; k < 9; k ++ ) triangles[ 9 * t + k ] = [ cx, cy, cz ][ k % 3 ] + 0.15 * ( random() - 0.5 );

		}

		const orientation = Int8Array.from( { length: 3000 }, () => [ - 1, 0, 1 ][ Math.floor( 3 * random() ) ] );
		const bvh = new TriangleBVH( triangles );
		const hit = { t: 0, triangle: 0 }, reference = { t: 0, triangle: 0 };
		let nonZero = 0;
		for ( let r = 0; r < 300; r ++ ) {

			const o = [ random(), random(), random() ], d = [ random() - 0.5, random() - 0.5, random() - 0.5 ];
			let sum = 0;
			for ( let t = 0; t < 3000; t ++ ) {

				if ( intersectRayTriangle( triangles, t, o[ 0 ], o[ 1 ], o[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ] ) <= 0 ) continue;
				const k = 9 * t;
				const e1 = [ 0, 1, 2 ].map( ( a ) => triangles[ k + 3 + a ] - triangles[ k + a ] );
				const e2 = [ 0, 1, 2 ].map( ( a ) => triangles[ k + 6 + a ] - triangles[ k + a ] );
				const n = [ 0, 1, 2 ].map( ( a ) => e1[ ( a + 1 ) % 3 ] * e2[ ( a + 2 ) % 3 ] - e1[ ( a + 2 ) % 3 ] * e2[ ( a + 1 ) % 3 ] );
				sum += orientation[ t ] * Math.sign( d[ 0 ] * n[ 0 ] + d[ 1 ] * n[ 1 ] + d[ 2 ] * n[ 2 ] );

			}

			expect( windingAlongRay( bvh, orientation, o[ 0 ], o[ 1 ], o[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ], hit ) ).toBe( sum );
			bvh.raycastFirst( o[ 0 ], o[ 1 ], o[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ], Infinity, reference );
			expect( hit ).toEqual( reference );
			if ( sum !== 0 ) nonZero ++;

		}

		expect( nonZero ).toBeGreaterThan( 100 );

	} );

	it( 'is the number of solids a point is in: 2 inside two overlapping spheres, 1 in one, 0 outside', () => {

		const a = trianglesOf( new THREE.SphereGeometry( 1, 32, 16 ) );
		const b = a.map( ( v, i ) => ( i % 3 === 0 ? v + 1 : v ) );
		const both = new Float64Array( a.length + b.length );
		both.set( a ); both.set( b, a.length );
		const orientation = findClosedShells( both, ones( both.length / 9 ) ).orientation;
		const bvh = new TriangleBVH( both ), hit = { t: 0, triangle: 0 };
		for ( const [ x, expected ] of [ [ 0.5, 2 ], [ - 0.5, 1 ], [ 1.5, 1 ], [ 2.5, 0 ] ] ) {

			expect( windingAlongRay( bvh, orientation, x, 0.05, 0.02, 0.3, 0.8, 0.5, hit ) ).toBe( expected );

		}

		// Parity would call the overlap (2 crossings) outside; the inside test does not.
		expect( Array.from( classifyPoints( [ 0.5, 0.05, 0.02 ], both ) ) ).toEqual( [ INSIDE_GEOMETRY ] );

	} );

} );

describe( 'ReachableSpace', () => {

	const bvh = new TriangleBVH( gatherWorldGeometry( twoRoomLevel( false ) ).triangles );

	it( 'floods room A of the sealed level and none of room B', () => {

		const space = new ReachableSpace( bvh, [ - 2, 1.6, 0 ] );
		// The box is the level's bounds, 8 × 3 × 4: 64 cells along x, 24 and 32 on the others.
		expect( Array.from( space.counts ) ).toEqual( [ 64, 24, 32 ] );
		expect( space.reachedCount ).toBe( 32 * 24 * 32 ); // exactly the half with x < 0
		expect( space.contains( - 1, 1, 1 ) ).toBe( true );
		expect( space.contains( 1, 1, 1 ) ).toBe( false );
		expect( space.contains( - 1, 1, 2.5 ) ).toBe( false ); // outside the box

	} );

	it( 'honours bounds and cellSize, and rejects seeds on a surface or blind to the lattice', () => {

		const space = new ReachableSpace( bvh, [ - 2, 1.6, 0 ], { bounds: [ - 4, 0, - 2, 0, 3, 2 ], cellSize: 0.5 } );
		expect( Array.from( space.counts ) ).toEqual( [ 8, 6, 8 ] );
		expect( space.reachedCount ).toBe( 8 * 6 * 8 );
		expect( () => new ReachableSpace( bvh, [ - 2, 0, 0 ] ) ).toThrow( /^ReachableSpace: seeds\[0\] \(-2, 0, 0\) lies on a surface/ );
		// A seed inside a 0.1 box, with 0.5 cells: every lattice point around it is outside the box.
		const boxed = trianglesOf( new THREE.BoxGeometry( 0.1, 0.1, 0.1 ) );
		expect( () => new ReachableSpace( new TriangleBVH( boxed ), [ 0, 0, 0 ], { bounds: [ - 1, - 1, - 1, 1, 1, 1 ], cellSize: 0.5 } ) )
			.toThrow( /^ReachableSpace: seeds\[0\] \(0, 0, 0\) sees none of the lattice points around it/ );
		expect( () => new ReachableSpace( bvh, [] ) ).toThrow( /^ReachableSpace: seeds needs at least 1/ );
		expect( () => new ReachableSpace( bvh, [ 0, 1, 0 ], { cellSize: - 1 } ) ).toThrow( /^ReachableSpace: options\.cellSize must be a finite number/ );
		expect( () => new ReachableSpace( bvh, [ 0, 1, 0 ], { bounds: [ 1, 1, 1, 0, 0, 0 ] } ) ).toThrow( /^ReachableSpace: options\.bounds must be/ );

	} );

	it( 'blockedLatticeEdges marks exactly the edges TriangleBVH.segmentBlocked finds blocked (random triangles, uneven lattice)', () => {

		const random = seededRandom( 7 );
		// 60 triangles of all sizes, some reaching past the lattice, one in an axis plane (parallel to two axes).
		const triangles = new Float64Array( 9 * 61 );
		for ( let t = 0; t < 60; t ++ ) {

			const size = t % 3 === 0 ? 3 : 0.6, cx = 4 * random() - 0.5, cy = 3 * random() - 0.5, cz = 3.5 * random() - 0.5;
			for ( let v = 0; v < 3; v ++ ) {

				triangles[ 9 * t + 3 * v ] = cx + size * ( random() - 0.5 );
				triangles[ 9 * t + 3 * v + 1 ] = cy + size * ( random() - 0.5 );
				triangles[ 9 * t + 3 * v + 2 ] = cz + size * ( random() - 0.5 );

			}

		}

		triangles.set( [ 0.1, 0.2, 1.3, 3.1, 0.3, 1.3, 1.5, 2.4, 1.3 ], 9 * 60 );
		const tree = new TriangleBVH( triangles );
		const origin = [ 0.013, - 0.021, 0.007 ], spacing = [ 0.31, 0.27, 0.33 ], counts = [ 12, 10, 9 ];
		const blocked = blockedLatticeEdges( triangles, { origin, spacing, counts } );
		const point = ( i: number, j: number, k: number ) => [ i, j, k ].map( ( n, a ) => origin[ a ] + n * spacing[ a ] );
		let edges = 0, crossed = 0, mismatches = 0;
		for ( let k = 0; k < counts[ 2 ]; k ++ ) for ( let j = 0; j < counts[ 1 ]; j ++ ) for ( let i = 0; i < counts[ 0 ]; i ++ ) {

			const node = i + counts[ 0 ] * ( j + counts[ 1 ] * k );
			for ( let a = 0; a < 3; a ++ ) {

				const next = [ i, j, k ];
				next[ a ] ++;
				if ( next[ a ] >= counts[ a ] ) {

					expect( blocked[ a ][ node ] ).toBe( 0 ); // the last point of a line has no edge
					continue;

				}

				const p = point( i, j, k ), q = point( next[ 0 ], next[ 1 ], next[ 2 ] );
				const truth = tree.segmentBlocked( p[ 0 ], p[ 1 ], p[ 2 ], q[ 0 ], q[ 1 ], q[ 2 ] );
				edges ++;
				if ( truth ) crossed ++;
				if ( truth !== ( blocked[ a ][ node ] === 1 ) ) mismatches ++;

			}

		}

		expect( edges ).toBe( 11 * 10 * 9 + 12 * 9 * 9 + 12 * 10 * 8 );
		expect( crossed ).toBeGreaterThan( 200 ); // the test means something: many edges are crossed
		expect( mismatches ).toBe( 0 );

	} );

} );

describe( 'readPointList', () => {

	it( 'reads flat arrays, [ x, y, z ] lists and { x, y, z } objects', () => {

		expect( Array.from( readPointList( 'f', 'p', [ 1, 2, 3, 4, 5, 6 ] ) ) ).toEqual( [ 1, 2, 3, 4, 5, 6 ] );
		expect( Array.from( readPointList( 'f', 'p', [ [ 1, 2, 3 ], new THREE.Vector3( 4, 5, 6 ) ] ) ) ).toEqual( [ 1, 2, 3, 4, 5, 6 ] );
		expect( Array.from( readPointList( 'f', 'p', Float32Array.of( 1, 2, 3 ) ) ) ).toEqual( [ 1, 2, 3 ] );
		expect( () => readPointList( 'f', 'p', 'abc' ) ).toThrow( /^f: p must be points/ );
		expect( () => readPointList( 'f', 'p', [ [ 1, 2 ] ] ) ).toThrow( /^f: p\[0\] must be \[ x, y, z \] or \{ x, y, z \}/ );
		expect( () => readPointList( 'f', 'p', [ { x: 1, y: 2, z: Infinity } ] ) ).toThrow( /^f: p\[0\]\.z is Infinity/ );

	} );

} );

describe( 'gatherDrawnSides', () => {

	it( 'gives every triangle of gatherWorldGeometry its material\'s side, per group, mirrored and instanced', () => {

		const root = new THREE.Group();
		const front = new THREE.MeshBasicMaterial(), back = new THREE.MeshBasicMaterial( { side: THREE.BackSide } );
		const both = new THREE.MeshBasicMaterial( { side: THREE.DoubleSide } );
		// BoxGeometry: 2 triangles per face, groups +x, −x, +y, −y, +z, −z.
		root.add( new THREE.Mesh( new THREE.BoxGeometry(), [ front, back, both, front, back, both ] ) );
		const mirrored = new THREE.Mesh( new THREE.PlaneGeometry(), front );
		mirrored.scale.x = - 1;
		root.add( mirrored );
		const instances = new THREE.InstancedMesh( new THREE.PlaneGeometry(), back, 2 );
		instances.setMatrixAt( 0, new THREE.Matrix4() );
		instances.setMatrixAt( 1, new THREE.Matrix4().makeTranslation( 0, 0, 3 ) );
		root.add( instances );
		const partial = new THREE.Mesh( new THREE.PlaneGeometry( 1, 1, 2, 1 ), [ both ] ); // 4 triangles, one group of 2
		partial.geometry.addGroup( 0, 6, 0 );
		root.add( partial );

		const { triangleSides, vertexSides } = gatherDrawnSides( root );
		const world = gatherWorldGeometry( root );
		expect( triangleSides.length ).toBe( world.triangles.length / 9 );
		expect( vertexSides.length ).toBe( world.vertexPositions.length / 3 );
		expect( Array.from( triangleSides ) ).toEqual( [
			1, 1, - 1, - 1, 0, 0, 1, 1, - 1, - 1, 0, 0, // the box, per face
			- 1, - 1, // the mirrored plane: three draws its front, which the mirror turned to the back of the world winding
			- 1, - 1, - 1, - 1, // two instances, BackSide
			0, 0, 0, 0, // the group of the partial plane, and the triangles outside every group (not drawn)
		] );
		// Vertices: the box's +x face front, −x back, +y both; the partial plane's last two vertices are in no drawn triangle.
		expect( vertexSides[ 0 ] ).toBe( DRAWN_ALONG_NORMAL );
		expect( vertexSides[ 4 ] ).toBe( DRAWN_AGAINST_NORMAL );
		expect( vertexSides[ 8 ] ).toBe( DRAWN_ALONG_NORMAL | DRAWN_AGAINST_NORMAL );
		expect( Array.from( vertexSides.subarray( vertexSides.length - 6 ) ) ).toEqual( [ 3, 3, 0, 3, 3, 0 ] );

	} );

	it( 'makes a mirrored room of open quads open space inside (its drawn sides still face in)', () => {

		const level = twoRoomLevel( true );
		level.scale.x = - 1;
		const { triangles } = gatherWorldGeometry( level );
		const classes = classifyPoints( [ - 2, 1.5, 0, 2, 1.5, 0 ], triangles, { sides: gatherDrawnSides( level ).triangleSides } );
		expect( Array.from( classes ) ).toEqual( [ OPEN_SPACE, OPEN_SPACE ] );
		// Without the sides (winding taken as drawn), the mirrored quads face out: inside by rule 2.
		expect( Array.from( classifyPoints( [ - 2, 1.5, 0, 2, 1.5, 0 ], triangles ) ) ).toEqual( [ INSIDE_GEOMETRY, INSIDE_GEOMETRY ] );

	} );

} );
