import { describe, expect, it } from 'vitest';
import {
	Box3, BoxGeometry, BufferGeometry, Float32BufferAttribute, Group, InstancedMesh, Line, Matrix4, Mesh, MeshBasicMaterial,
	SphereGeometry, TorusGeometry, TorusKnotGeometry, Vector3,
} from 'three';
import { placeFromMeshes } from '../../src/placement/placeFromMeshes.js';
import { gatherWorldGeometry } from '../../src/geometry/gatherWorldGeometry.js';
import { TriangleBVH } from '../../src/geometry/TriangleBVH.js';
import { boxDistance, sphereDistance, torusDistance } from './helpers.js';

const material = new MeshBasicMaterial();

/**
 * A room with 0.5 thick walls, floor and ceiling — the space between an outer box (normals out,
 * x, z in [−5.5, 5.5], y in [−0.5, 6.5]) and an inner one turned inside out (normals into the
 * room, x, z in [−5, 5], y in [0, 6]) — with three solids: a block standing on the floor, a
 * sphere sunk into the west wall and a torus half buried in the floor. Wall and floor vertices
 * every 0.5 put room candidates inside the sphere and the torus, and the solids' own vertices put
 * candidates inside the wall and floor. Open space is the room and the outdoors, minus the solids.
 */
function room(): { root: Group; clearance: ( x: number, y: number, z: number ) => number } {

	const root = new Group();
	const outer = new Mesh( new BoxGeometry( 11, 7, 11, 22, 14, 22 ), material );
	outer.position.set( 0, 3, 0 );
	root.add( outer );
	const inner = new Mesh( insideOut( new BoxGeometry( 10, 6, 10, 20, 12, 20 ) ), material );
	inner.position.set( 0, 3, 0 );
	root.add( inner );

	const block = new Mesh( new BoxGeometry( 1, 2, 1, 2, 4, 2 ), material );
	block.position.set( 2, 1, - 2 );
	root.add( block );

	const sphere = new Mesh( new SphereGeometry( 0.6, 48, 32 ), material );
	sphere.position.set( - 4.8, 2, 0.5 );
	root.add( sphere );

	// TorusGeometry lies in the xy plane; a child of a rotated group, to exercise nested matrices.
	const tilt = new Group();
	tilt.rotation.x = - Math.PI / 2;
	tilt.position.set( 1.5, 0.15, 2.5 );
	tilt.add( new Mesh( new TorusGeometry( 1.2, 0.4, 32, 96 ), material ) );
	root.add( tilt );

	// Not a mesh: must be ignored (a Line's vertices are no surface).
	root.add( new Line( new BufferGeometry().setAttribute( 'position', new Float32BufferAttribute( [ 0, 3, 0, 1, 3, 0 ], 3 ) ) ) );

	/** Signed clearance from all solid matter (negative inside it). */
	const clearance = ( x: number, y: number, z: number ) => Math.min(
		// The shell between the boxes; exact in the room and outdoors, the right sign inside it.
		Math.max( boxDistance( x, y, z, 0, 3, 0, 5.5, 3.5, 5.5 ), - boxDistance( x, y, z, 0, 3, 0, 5, 3, 5 ) ),
		boxDistance( x, y, z, 2, 1, - 2, 0.5, 1, 0.5 ),
		sphereDistance( x, y, z, - 4.8, 2, 0.5, 0.6 ),
		torusDistance( x, y, z, 1.5, 0.15, 2.5, 1.2, 0.4, 'y' ),
	);
	return { root, clearance };

}

/** Normals negated and triangles reversed: the box seen from inside. */
function insideOut( geometry: BufferGeometry ): BufferGeometry {

	const normal = geometry.getAttribute( 'normal' );
	for ( let i = 0; i < normal.array.length; i ++ ) ( normal.array as Float32Array )[ i ] *= - 1;
	const index = geometry.index!;
	for ( let i = 0; i < index.count; i += 3 ) {

		const b = index.getX( i + 1 );
		index.setX( i + 1, index.getX( i + 2 ) );
		index.setX( i + 2, b );

	}

	return geometry;

}

/** How far three's tessellations (48 × 32 sphere, 32 × 96 torus) deviate from the analytic shapes. */
const TESSELLATION = 0.006;

describe( 'placeFromMeshes (paper 2.1: automatic probes from the background mesh)', () => {

	const offset = 0.3, minSpacing = 0.45;
	const { root, clearance } = room();
	// Everything the vertices give (thinned), and what survives the geometry tests.
	const all = placeFromMeshes( root, { offset, minSpacing, rejectInside: false, minDistance: 0 } );
	const kept = placeFromMeshes( root, { offset, minSpacing } );

	it( 'never keeps a candidate inside a solid, nor within offset/2 of a surface (analytic check)', () => {

		expect( kept.length / 3 ).toBeGreaterThan( 200 );
		for ( let i = 0; i < kept.length / 3; i ++ ) {

			const c = clearance( kept[ 3 * i ], kept[ 3 * i + 1 ], kept[ 3 * i + 2 ] );
			expect( c, `candidate ${i} at (${Array.from( kept.subarray( 3 * i, 3 * i + 3 ) ).map( ( v ) => v.toFixed( 3 ) )})` ).toBeGreaterThan( offset / 2 - TESSELLATION );

		}

	} );

	it( 'needed the rejection: unfiltered, the vertices put candidates inside solids and on walls', () => {

		// Without this the previous test could pass on a scene that never produces a bad candidate.
		let inside = 0, close = 0;
		for ( let i = 0; i < all.length / 3; i ++ ) {

			const c = clearance( all[ 3 * i ], all[ 3 * i + 1 ], all[ 3 * i + 2 ] );
			if ( c < - TESSELLATION ) inside ++;
			else if ( c < offset / 2 - TESSELLATION ) close ++;

		}

		expect( inside ).toBeGreaterThan( 20 );
		expect( close ).toBeGreaterThan( 50 ); // e.g. room corner vertices moved along one wall's normal lie in the other walls' planes

	} );

	it( 'keeps every candidate that is clearly in open space (rejects nothing it should not)', () => {

		// Kept ⊆ all (same thinning); every candidate of `all` with a clear margin must be in kept.
		const keys = new Set<string>();
		for ( let i = 0; i < kept.length; i += 3 ) keys.add( `${kept[ i ]},${kept[ i + 1 ]},${kept[ i + 2 ]}` );
		let open = 0;
		for ( let i = 0; i < all.length; i += 3 ) {

			if ( clearance( all[ i ], all[ i + 1 ], all[ i + 2 ] ) <= offset / 2 + TESSELLATION ) continue;
			open ++;
			expect( keys.has( `${all[ i ]},${all[ i + 1 ]},${all[ i + 2 ]}` ) ).toBe( true );

		}

		// And nothing else was kept but candidates in the uncertain band: kept = open ∪ (kept ∩ band).
		expect( open ).toBeGreaterThan( 1000 );
		expect( open + countInBand( kept, clearance, offset ) ).toBe( kept.length / 3 );

	} );

	it( 'keeps all pairs at least minSpacing apart (brute force)', () => {

		let closest = Infinity;
		for ( let i = 0; i < kept.length / 3; i ++ ) for ( let j = i + 1; j < kept.length / 3; j ++ ) {

			closest = Math.min( closest, Math.hypot(
				kept[ 3 * i ] - kept[ 3 * j ], kept[ 3 * i + 1 ] - kept[ 3 * j + 1 ], kept[ 3 * i + 2 ] - kept[ 3 * j + 2 ]
			) );

		}

		expect( closest ).toBeGreaterThanOrEqual( minSpacing );

	} );

	it( 'restricts to bounds', () => {

		const bounds = new Box3( new Vector3( - 5, 0, - 5 ), new Vector3( 0, 1, 5 ) );
		const inBox = placeFromMeshes( root, { offset, minSpacing, bounds } );
		expect( inBox.length ).toBeGreaterThan( 0 );
		for ( let i = 0; i < inBox.length / 3; i ++ ) {

			expect( bounds.containsPoint( new Vector3().fromArray( inBox, 3 * i ) ) ).toBe( true );

		}


	} );

	for ( const [ name, mesh, distance ] of [
		[ 'BoxGeometry', new Mesh( new BoxGeometry( 2, 2, 2, 4, 4, 4 ), material ), ( p: Vector3 ) => boxDistance( p.x, p.y, p.z, 0, 0, 0, 1, 1, 1 ) ],
		[ 'SphereGeometry', new Mesh( new SphereGeometry( 1, 48, 32 ), material ), ( p: Vector3 ) => sphereDistance( p.x, p.y, p.z, 0, 0, 0, 1 ) ],
		[ 'TorusGeometry', new Mesh( new TorusGeometry( 1, 0.35, 32, 96 ), material ), ( p: Vector3 ) => torusDistance( p.x, p.y, p.z, 0, 0, 0, 1, 0.35 ) ],
	] as const ) {

		it( `puts candidates of a closed ${name} outside it, one offset away along the normals`, () => {

			const out = placeFromMeshes( mesh, { offset: 0.1, minSpacing: 0.05 } );
			expect( out.length / 3 ).toBeGreaterThan( 50 );
			const p = new Vector3();
			for ( let i = 0; i < out.length / 3; i ++ ) {

				// A vertex on the surface moved 0.1 along the outward normal is 0.1 from the surface.
				expect( distance( p.fromArray( out, 3 * i ) ) ).toBeCloseTo( 0.1, 2 );

			}

		} );

	}

	it( 'uses world matrices, instances and normal matrices', () => {

		// One box (2 × 2 × 2) per instance, under a translated, rotated and non-uniformly scaled parent.
		const parent = new Group();
		parent.position.set( 10, 0, 0 );
		parent.rotation.z = Math.PI / 2; // (x, y, z) → (−y, x, z)
		parent.scale.set( 1, 3, 1 ); // world box: 6 in x, 2 in y, 2 in z
		const boxes = new InstancedMesh( new BoxGeometry( 2, 2, 2 ), material, 2 );
		boxes.setMatrixAt( 0, new Matrix4() );
		boxes.setMatrixAt( 1, new Matrix4().makeTranslation( 0, 0, 10 ) );
		parent.add( boxes );

		const { vertexPositions, vertexNormals, triangles } = gatherWorldGeometry( parent );
		expect( vertexPositions.length ).toBe( 2 * 3 * 24 );
		expect( triangles.length ).toBe( 2 * 9 * 12 );
		const worldBox = ( x: number, y: number, z: number ) => Math.min(
			boxDistance( x, y, z, 10, 0, 0, 3, 1, 1 ), boxDistance( x, y, z, 10, 0, 10, 3, 1, 1 )
		);
		for ( let v = 0; v < vertexPositions.length / 3; v ++ ) {

			const x = vertexPositions[ 3 * v ], y = vertexPositions[ 3 * v + 1 ], z = vertexPositions[ 3 * v + 2 ];
			expect( Math.abs( worldBox( x, y, z ) ) ).toBeLessThan( 1e-9 );
			// The normal must point out of the world box: moving along it leaves the box.
			const n = [ vertexNormals[ 3 * v ], vertexNormals[ 3 * v + 1 ], vertexNormals[ 3 * v + 2 ] ];
			expect( Math.hypot( ...n ) ).toBeCloseTo( 1, 12 );
			expect( worldBox( x + 0.1 * n[ 0 ], y + 0.1 * n[ 1 ], z + 0.1 * n[ 2 ] ) ).toBeCloseTo( 0.1, 9 );

		}

		const out = placeFromMeshes( parent, { offset: 0.1, minSpacing: 0 } );
		expect( out.length / 3 ).toBe( 48 );

	} );

	it( 'transforms normals by the inverse transpose: a sphere stretched into an ellipsoid gets the ellipsoid\'s normals', () => {

		// Box faces stay axis-aligned under any axis scale, so the box test above cannot tell the
		// normal matrix from the plain matrix. A unit sphere scaled by (1, 3, 1) is the ellipsoid
		// x² + y²/9 + z² = 1, whose normal at (X, Y, Z) is ∝ (X, Y / 9, Z) (the gradient); the plain
		// matrix would give (X, Y, Z) instead.
		const ellipsoid = new Mesh( new SphereGeometry( 1, 16, 12 ), material );
		ellipsoid.scale.set( 1, 3, 1 );
		const { vertexPositions: p, vertexNormals: n } = gatherWorldGeometry( ellipsoid );
		for ( let v = 0; v < p.length / 3; v ++ ) {

			const g = new Vector3( p[ 3 * v ], p[ 3 * v + 1 ] / 9, p[ 3 * v + 2 ] ).normalize();
			expect( g.dot( new Vector3( n[ 3 * v ], n[ 3 * v + 1 ], n[ 3 * v + 2 ] ) ) ).toBeGreaterThan( 1 - 1e-6 );

		}

	} );

	it( 'handles 100k triangles and thousands of candidates (its time: bench/placement.bench.ts)', () => {

		const knot = new Mesh( new TorusKnotGeometry( 1, 0.3, 1000, 50 ), material ); // 100 000 triangles
		const out = placeFromMeshes( knot, { offset: 0.1, minSpacing: 0.06 } );
		expect( out.length / 3 ).toBeGreaterThan( 3000 );
		// Every kept candidate keeps the default minDistance (offset / 2) from the surface.
		const surface = new TriangleBVH( gatherWorldGeometry( knot ).triangles );
		let closest = Infinity;
		for ( let i = 0; i < out.length; i += 3 ) {

			closest = Math.min( closest, surface.nearestDistance( out[ i ], out[ i + 1 ], out[ i + 2 ] ) );

		}

		expect( closest ).toBeGreaterThanOrEqual( 0.05 );

	} );

	it( 'rejects bad arguments, naming placeFromMeshes and the option', () => {

		expect( () => placeFromMeshes( {} as Group, { offset: 1, minSpacing: 1 } ) ).toThrow( /^placeFromMeshes: root must be a three.js Object3D/ );
		expect( () => placeFromMeshes( root, { offset: NaN, minSpacing: 1 } ) ).toThrow( /^placeFromMeshes: options.offset must be a finite number/ );
		expect( () => placeFromMeshes( root, { offset: 1, minSpacing: - 1 } ) ).toThrow( /^placeFromMeshes: options.minSpacing must be ≥ 0/ );
		expect( () => placeFromMeshes( root, { offset: 1, minSpacing: 1, minDistance: - 1 } ) ).toThrow( /^placeFromMeshes: options.minDistance must be ≥ 0/ );
		expect( () => placeFromMeshes( root, { offset: 1, minSpacing: 1, bounds: {} as Box3 } ) ).toThrow( /^placeFromMeshes: options.bounds must be a three.js Box3/ );

	} );

} );

/** Kept candidates whose analytic clearance is in the band where tessellation makes the verdict uncertain. */
function countInBand( points: Float64Array, clearance: ( x: number, y: number, z: number ) => number, offset: number ): number {

	let n = 0;
	for ( let i = 0; i < points.length; i += 3 ) {

		if ( clearance( points[ i ], points[ i + 1 ], points[ i + 2 ] ) <= offset / 2 + TESSELLATION ) n ++;

	}

	return n;

}
