/**
 * The visibility guard (no light through walls) without a GPU: VisibilityGuard's segment query
 * against an independent signed-volume test, and LightProbeVolume's guarded weights against
 * weights recomputed by hand from the unguarded interpolation and which side of a wall each
 * probe is on.
 */

import { describe, expect, it, vi } from 'vitest';
import * as THREE from 'three';
import { VisibilityGuard } from '../../src/runtime/VisibilityGuard.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { TriangleBVH } from '../../src/geometry/TriangleBVH.js';
import { GridInterpolator } from '../../src/interpolation/GridInterpolator.js';
import type { ProbeInterpolator } from '../../src/interpolation/ProbeInterpolator.js';
import { irradianceMatrices } from '../../src/sh/index.js';
import { seededRandom } from '../helpers/pointSets.js';

/** Signed volume of (b − a, c − a, d − a), ×6. */
function orient( a: number[], b: number[], c: number[], d: number[] ): number {

	const u = [ 0, 1, 2 ].map( ( i ) => b[ i ] - a[ i ] ), v = [ 0, 1, 2 ].map( ( i ) => c[ i ] - a[ i ] );
	const w = [ 0, 1, 2 ].map( ( i ) => d[ i ] - a[ i ] );
	return u[ 0 ] * ( v[ 1 ] * w[ 2 ] - v[ 2 ] * w[ 1 ] ) - u[ 1 ] * ( v[ 0 ] * w[ 2 ] - v[ 2 ] * w[ 0 ] )
		+ u[ 2 ] * ( v[ 0 ] * w[ 1 ] - v[ 1 ] * w[ 0 ] );

}

/** Segment pq crosses triangle abc (general position): p and q on opposite sides of its plane, and pq passes inside its three edges. */
function segmentCrossesTriangle( p: number[], q: number[], a: number[], b: number[], c: number[] ): boolean {

	if ( Math.sign( orient( a, b, c, p ) ) === Math.sign( orient( a, b, c, q ) ) ) return false;
	const s1 = Math.sign( orient( p, q, a, b ) ), s2 = Math.sign( orient( p, q, b, c ) ), s3 = Math.sign( orient( p, q, c, a ) );
	return s1 === s2 && s2 === s3;

}

/** Two triangles: the square x = `x`, y and z in [−size, size]. */
function wallAt( x: number, size = 10 ): Float64Array {

	return Float64Array.of( x, - size, - size, x, size, - size, x, size, size, x, - size, - size, x, size, size, x, - size, size );

}

/**
 * A probe grid x ∈ {−2, −1, 1, 2} (two layers each side of x = 0), y, z ∈ {0, 2}; SH: L00 red = 1 for x < 0,
 * L00 blue = 1 for x > 0, L00 green = the probe's index + 1.
 */
function sidedProbes() {

	const positions: number[] = [];
	for ( const x of [ - 2, - 1, 1, 2 ] ) for ( const y of [ 0, 2 ] ) for ( const z of [ 0, 2 ] ) positions.push( x, y, z );
	const count = positions.length / 3;
	const sh = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) {

		sh[ 27 * i + ( positions[ 3 * i ] < 0 ? 0 : 2 ) ] = 1;
		sh[ 27 * i + 1 ] = i + 1;

	}

	return { positions, sh, count };

}

/** An interpolator that always answers the same probes and weights (to put a point's "cell" where a test needs it). */
function fixedInterpolator( probeCount: number, indices: number[], weights: number[] ): ProbeInterpolator {

	return {
		probeCount, cellCount: 1, weightCount: indices.length,
		interpolate( _x, _y, _z, outIndices, outWeights ) {

			indices.forEach( ( index, k ) => { outIndices[ k ] = index; outWeights[ k ] = weights[ k ]; } );
			return 0;

		},
	};

}

describe( 'VisibilityGuard.segmentBlocked', () => {

	it( 'equals a brute-force signed-volume test on 300 random triangles × 1000 random segments (BVH traversal loses no hit, adds none)', () => {

		const random = seededRandom( 7 );
		const triangles = new Float64Array( 9 * 300 );
		for ( let t = 0; t < 300; t ++ ) {

			const c = [ random(), random(), random() ];
			for ( let v = 0; v < 3; v ++ ) {

				for ( let a = 0; a < 3; a ++ ) triangles[ 9 * t + 3 * v + a ] = c[ a ] + 0.15 * ( random() - 0.5 );

			}

		}

		const guard = new VisibilityGuard( triangles );
		const vertices = Array.from(
			{ length: 300 }, ( _, t ) => [ 0, 1, 2 ].map( ( v ) => [ 0, 1, 2 ].map( ( a ) => triangles[ 9 * t + 3 * v + a ] ) )
		);
		const tri = ( t: number, v: number ) => vertices[ t ][ v ];
		let blocked = 0;
		for ( let s = 0; s < 1000; s ++ ) {

			const p = [ random(), random(), random() ], q = [ random(), random(), random() ];
			let expected = false;
			for ( let t = 0; t < 300 && ! expected; t ++ ) expected = segmentCrossesTriangle( p, q, tri( t, 0 ), tri( t, 1 ), tri( t, 2 ) );
			expect( guard.segmentBlocked( p[ 0 ], p[ 1 ], p[ 2 ], q[ 0 ], q[ 1 ], q[ 2 ] ), `segment ${s}` ).toBe( expected );
			if ( expected ) blocked ++;

		}

		// Both answers occur often enough for the comparison to mean something.
		expect( blocked ).toBeGreaterThan( 100 );
		expect( blocked ).toBeLessThan( 900 );

	} );

	it( 'a wall x = 0: crossing segments are blocked; segments on one side, parallel to it, or ending on it are not; axis-parallel segments work', () => {

		const guard = new VisibilityGuard( wallAt( 0 ) );
		expect( guard.segmentBlocked( - 1, 0.3, 0.2, 1, 0.3, 0.2 ) ).toBe( true ); // along x only (y, z reciprocals infinite)
		expect( guard.segmentBlocked( - 0.01, 5, 5, 3, - 2, 1 ) ).toBe( true );
		expect( guard.segmentBlocked( 0.5, 0, 0, 3, 1, 1 ) ).toBe( false );
		expect( guard.segmentBlocked( - 1, 0, 0, - 1, 3, 0 ) ).toBe( false ); // parallel, beside it
		expect( guard.segmentBlocked( - 1, 0, 0, 0, 0, 0 ) ).toBe( false ); // ends on it
		// Passes beyond its edge (y = 15 at x = 0; the wall ends at 10).
		expect( guard.segmentBlocked( - 1, 0, 0, 1, 30, 0 ) ).toBe( false );
		expect( guard.segmentBlocked( 1, 1, 1, 1, 1, 1 ) ).toBe( false ); // a point
		expect( new VisibilityGuard( [] ).segmentBlocked( - 1, 0, 0, 1, 0, 0 ) ).toBe( false );

	} );

	it( 'builds from three.js objects in world space (a moved, scaled box) and from a TriangleBVH', () => {

		const box = new THREE.Mesh( new THREE.BoxGeometry( 1, 1, 1 ) );
		box.position.set( 5, 0, 0 );
		box.scale.set( 1, 4, 1 );
		const group = new THREE.Group().add( box );
		const fromObject = new VisibilityGuard( group );
		expect( fromObject.segmentBlocked( 3, 1.8, 0, 7, 1.8, 0 ) ).toBe( true ); // y = 1.8 is inside the scaled box (half height 2)
		expect( fromObject.segmentBlocked( 3, 2.2, 0, 7, 2.2, 0 ) ).toBe( false );
		expect( fromObject.segmentBlocked( - 1, 0, 0, 1, 0, 0 ) ).toBe( false ); // where the box was before moving
		expect( new VisibilityGuard( [ group ] ).segmentBlocked( 3, 1.8, 0, 7, 1.8, 0 ) ).toBe( true );
		const bvh = new TriangleBVH( wallAt( 0 ) );
		expect( new VisibilityGuard( bvh ).bvh ).toBe( bvh );
		box.geometry.dispose();

	} );

	it( 'rejects bad occluders and options with errors naming VisibilityGuard', () => {

		expect( () => new VisibilityGuard( 'walls' as never ) ).toThrow( /VisibilityGuard: occluders/ );
		expect( () => new VisibilityGuard( null as never ) ).toThrow( /VisibilityGuard: occluders/ );
		expect( () => new VisibilityGuard( new Float64Array( 10 ) ) ).toThrow( /TriangleBVH: triangles must hold 9 floats/ );
		expect( () => new VisibilityGuard( [ 0, 0, 0, 1, 0, 0, 0, NaN, 0 ] ) ).toThrow( /triangles\[7\] is NaN/ );
		expect( () => new VisibilityGuard( wallAt( 0 ), { blockedWeight: 1 } ) ).toThrow( /blockedWeight must be in \[0, 1\)/ );
		expect( () => new VisibilityGuard( wallAt( 0 ), { blockedWeight: - 0.1 } ) ).toThrow( /blockedWeight/ );
		expect( () => new VisibilityGuard( wallAt( 0 ), { moveThreshold: - 1 } ) ).toThrow( /moveThreshold must be ≥ 0/ );
		expect( () => new VisibilityGuard( wallAt( 0 ), { moveThreshold: NaN } ) ).toThrow( /moveThreshold must be a finite number/ );

	} );

	it( 'filterWeights: blocked slots scaled by blockedWeight, the rest renormalised, in place; all blocked → 0 and weights unchanged', () => {

		const positions = [ - 1, 0, 0, 1, 0, 0, 2, 0, 0, - 2, 0, 0 ];
		const weights = Float64Array.of( 0.4, 0.3, 0.2, 0.1 );
		const visible = new VisibilityGuard( wallAt( 0 ) ).filterWeights( 0.5, 0, 0, positions, [ 0, 1, 2, 3 ], weights, 4 );
		expect( visible ).toBeCloseTo( 0.5, 12 );
		expect( Array.from( weights ) ).toEqual( [ 0, 0.3 / 0.5, 0.2 / 0.5, 0 ].map( ( w ) => expect.closeTo( w, 12 ) ) );
		const soft = Float64Array.of( 0.4, 0.3, 0.2, 0.1 );
		new VisibilityGuard( wallAt( 0 ), { blockedWeight: 0.5 } ).filterWeights( 0.5, 0, 0, positions, [ 0, 1, 2, 3 ], soft, 4 );
		expect( Array.from( soft ) ).toEqual( [ 0.2, 0.3, 0.2, 0.05 ].map( ( w ) => expect.closeTo( w / 0.75, 12 ) ) );
		const none = Float64Array.of( 0.5, 0.5 );
		expect( new VisibilityGuard( wallAt( 0 ) ).filterWeights( 0.5, 0, 0, positions, [ 0, 3 ], none, 2 ) ).toBe( 0 );
		expect( Array.from( none ) ).toEqual( [ 0.5, 0.5 ] );

	} );

	it( 'findLeakingTetrahedra: the tetrahedra with probes on both sides of a wall, exactly; none without the wall in the way', () => {

		const { positions } = sidedProbes();
		const volume = new LightProbeVolume( { positions, occluders: wallAt( 0 ) } );
		const mesh = volume.interpolator as unknown as { tetrahedra: Uint32Array };
		const straddling: number[] = [];
		for ( let t = 0; t < mesh.tetrahedra.length / 4; t ++ ) {

			const sides = new Set( Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ), ( i ) => positions[ 3 * i ] < 0 ) );
			if ( sides.size === 2 ) straddling.push( t );

		}

		expect( straddling.length ).toBeGreaterThan( 0 );
		expect( Array.from( volume.findLeakingTetrahedra() ) ).toEqual( straddling );
		expect( volume.setOccluders( wallAt( 5 ) ).findLeakingTetrahedra().length ).toBe( 0 );
		expect( () => volume.setOccluders( null ).findLeakingTetrahedra() ).toThrow( /findLeakingTetrahedra: no occluders/ );
		const grid = new GridInterpolator( [ - 2, 0, 0 ], [ 2, 2, 2 ], [ 2, 2, 2 ] );
		expect( () => new LightProbeVolume( { positions: grid.positions, interpolator: grid, occluders: wallAt( 0 ) } ).findLeakingTetrahedra() ).toThrow( /no tetrahedra/ );

	} );

} );

describe( 'LightProbeVolume with occluders', () => {

	/** The unguarded weights at p, blocked (x < 0) probes scaled by `factor`, renormalised, blended: the expected SH. */
	function expectedSH( positions: number[], sh: Float32Array, p: number[], factor = 0 ): Float32Array {

		const plain = new LightProbeVolume( { positions } );
		const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 );
		plain.interpolator.interpolate( p[ 0 ], p[ 1 ], p[ 2 ], indices, weights );
		let total = 0;
		for ( let k = 0; k < 4; k ++ ) {

			if ( ( positions[ 3 * indices[ k ] ] < 0 ) !== ( p[ 0 ] < 0 ) ) weights[ k ] *= factor;
			total += weights[ k ];

		}

		const out = new Float32Array( 27 );
		for ( let k = 0; k < 4; k ++ ) for ( let i = 0; i < 27; i ++ ) out[ i ] += weights[ k ] / total * sh[ 27 * indices[ k ] + i ];
		return out;

	}

	it( 'sample(): probes behind the wall get weight 0, the others are renormalised — equal to weights recomputed by hand at 200 points, with no red on the blue side', () => {

		const { positions, sh } = sidedProbes();
		const guarded = new LightProbeVolume( { positions, sh, occluders: wallAt( 0 ) } );
		const plain = new LightProbeVolume( { positions, sh } );
		const random = seededRandom( 3 );
		let leakedWithout = 0;
		for ( let i = 0; i < 200; i ++ ) {

			const p = [ 1.8 * ( 2 * random() - 1 ), 2 * random(), 2 * random() ];
			if ( Math.abs( p[ 0 ] ) < 1e-3 ) continue;
			const actual = guarded.sample( p );
			const expected = expectedSH( positions, sh, p );
			for ( let k = 0; k < 27; k ++ ) expect( actual[ k ] ).toBeCloseTo( expected[ k ], 5 );
			// Red on the blue side (x > 0) and blue on the red side: none with the guard.
			expect( actual[ p[ 0 ] > 0 ? 0 : 2 ] ).toBe( 0 );
			if ( plain.sample( p )[ p[ 0 ] > 0 ? 0 : 2 ] > 0.05 ) leakedWithout ++;

		}

		// The leak the guard removes is there without it (the test can fail).
		expect( leakedWithout ).toBeGreaterThan( 50 );

	} );

	it( 'blockedWeight 0.1 keeps a tenth of the blocked weights before renormalising', () => {

		const { positions, sh } = sidedProbes();
		const volume = new LightProbeVolume( { positions, sh, occluders: wallAt( 0 ), guard: { blockedWeight: 0.1 } } );
		for ( const p of [ [ 0.3, 1, 1 ], [ - 0.5, 0.2, 1.7 ], [ 0.9, 1.9, 0.1 ] ] ) {

			const actual = volume.sample( p ), expected = expectedSH( positions, sh, p, 0.1 );
			for ( let k = 0; k < 27; k ++ ) expect( actual[ k ] ).toBeCloseTo( expected[ k ], 5 );
			expect( actual[ p[ 0 ] > 0 ? 0 : 2 ] ).toBeGreaterThan( 0 ); // some leak on purpose

		}

	} );

	it( 'works on top of the trilinear grid (8 weights)', () => {

		const grid = new GridInterpolator( [ - 1, 0, 0 ], [ 1, 2, 2 ], [ 2, 2, 2 ] );
		const count = grid.positions.length / 3;
		const sh = new Float32Array( 27 * count );
		for ( let i = 0; i < count; i ++ ) sh[ 27 * i + ( grid.positions[ 3 * i ] < 0 ? 0 : 2 ) ] = 1;
		const volume = new LightProbeVolume( { positions: grid.positions, sh, interpolator: grid, occluders: wallAt( 0 ) } );
		const sample = volume.sample( [ 0.2, 1, 1 ] );
		expect( sample[ 0 ] ).toBe( 0 );
		expect( sample[ 2 ] ).toBeCloseTo( 1, 6 );
		const plain = new LightProbeVolume( { positions: grid.positions, sh, interpolator: grid } );
		expect( plain.sample( [ 0.2, 1, 1 ] )[ 0 ] ).toBeCloseTo( 0.4, 6 );

	} );

	it( 'when every weighted probe is blocked, the nearest visible probe lights the point alone; when none of the 8 nearest is visible, the unguarded weights stay', () => {

		// Probes 0–3 are the point's "cell" (a fixed interpolator), behind a wall x = 1; probe 4
		// (x = −3) and probe 5 (x = −6) are on the point's side, 4 nearer.
		const positions = [ 2, 0, 0, 2, 1, 0, 2, 0, 1, 3, 0, 0, - 3, 0, 0, - 6, 0, 0 ];
		const sh = new Float32Array( 27 * 6 );
		for ( let i = 0; i < 6; i ++ ) sh[ 27 * i ] = i + 1;
		const interpolator = fixedInterpolator( 6, [ 0, 1, 2, 3 ], [ 0.25, 0.25, 0.25, 0.25 ] );
		const volume = new LightProbeVolume( { positions, sh, interpolator, occluders: wallAt( 1 ) } );
		expect( volume.sample( [ 0, 0, 0 ] )[ 0 ] ).toBeCloseTo( 5, 6 ); // probe 4 alone
		// The same for a registered object, first frame and cached frames.
		const mesh = new THREE.Mesh( new THREE.BufferGeometry(), new THREE.MeshStandardMaterial() );
		volume.add( mesh, { anchor: { x: 0, y: 0, z: 0 } } );
		const matrices = volume.getUniforms( mesh )!.probeVolumeMatrices.value;
		const expectedFrom = ( value: number ) => {

			const single = new Float32Array( 27 );
			single[ 0 ] = value;
			return irradianceMatrices( single, new Float32Array( 48 ) );

		};

		for ( let frame = 0; frame < 3; frame ++ ) {

			volume.update();
			expectedFrom( 5 ).forEach( ( v, k ) => expect( matrices[ k ] ).toBeCloseTo( v, 6 ) );

		}

		// Enclose the point: nothing is visible, so the cell's own weights are kept.
		const box = new THREE.Mesh( new THREE.BoxGeometry( 1, 1, 1 ) );
		volume.setOccluders( box );
		expect( volume.sample( [ 0, 0, 0 ] )[ 0 ] ).toBeCloseTo( ( 1 + 2 + 3 + 4 ) / 4, 6 );
		volume.update();
		expectedFrom( 2.5 ).forEach( ( v, k ) => expect( matrices[ k ] ).toBeCloseTo( v, 6 ) );
		volume.dispose();
		mesh.material.dispose();
		box.geometry.dispose();

	} );

	it( 'update(): the segments are tested when an object is added and again only after it moves more than moveThreshold; setOccluders( null ) turns the guard off', () => {

		const { positions, sh } = sidedProbes();
		const guard = new VisibilityGuard( wallAt( 0 ), { moveThreshold: 0.1 } );
		const volume = new LightProbeVolume( { positions, sh, occluders: guard } );
		const spy = vi.spyOn( guard, 'segmentBlocked' );
		const mesh = new THREE.Mesh( new THREE.BufferGeometry(), new THREE.MeshStandardMaterial() );
		mesh.position.set( 0.3, 1, 1 );
		volume.add( mesh, { anchor: { x: 0, y: 0, z: 0 } } );
		const tested = spy.mock.calls.length;
		expect( tested ).toBeGreaterThan( 0 );
		expect( tested ).toBeLessThanOrEqual( 4 );
		volume.update();
		mesh.position.set( 0.3, 1.05, 1 );
		volume.update();
		expect( spy.mock.calls.length ).toBe( tested ); // cached: same cell, moved 0.05 < 0.1
		const matrices = volume.getUniforms( mesh )!.probeVolumeMatrices.value;
		const redRow = Array.from( matrices.subarray( 0, 16 ) );
		expect( redRow.every( ( v ) => v === 0 ) ).toBe( true ); // red matrix empty: no red through the wall
		mesh.position.set( 0.3, 1.3, 1 );
		volume.update();
		expect( spy.mock.calls.length ).toBeGreaterThan( tested ); // moved 0.3: tested again
		volume.setOccluders( null );
		volume.update();
		expect( Array.from( matrices.subarray( 0, 16 ) ).some( ( v ) => v !== 0 ) ).toBe( true ); // the leak is back
		volume.dispose();
		mesh.material.dispose();

	} );

} );
