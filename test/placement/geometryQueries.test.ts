import { describe, expect, it } from 'vitest';
import { BoxGeometry, SphereGeometry, TorusGeometry } from 'three';
import { intersectRayTriangle } from '../../src/geometry/intersectRayTriangle.js';
import { TriangleBVH } from '../../src/geometry/TriangleBVH.js';
import { classifyPoints, INSIDE_GEOMETRY, NEAR_SURFACE, OPEN_SPACE, INSIDE_RAY_DIRECTIONS } from '../../src/placement/classifyPoints.js';
import { closestPointOnTriangle } from '../../src/geometry/closestPointOnTriangle.js';
import { seededRandom } from '../helpers/pointSets.js';
import { boxDistance, sphereDistance, torusDistance, trianglesOf } from './helpers.js';

/** n random triangles of size ~0.1 in [0, 1]³. */
function randomTriangles( n: number, seed: number ): Float64Array {

	const random = seededRandom( seed );
	const out = new Float64Array( 9 * n );
	for ( let t = 0; t < n; t ++ ) {

		const cx = random(), cy = random(), cz = random();
		for ( let v = 0; v < 3; v ++ ) {

			out[ 9 * t + 3 * v ] = cx + 0.1 * ( random() - 0.5 );
			out[ 9 * t + 3 * v + 1 ] = cy + 0.1 * ( random() - 0.5 );
			out[ 9 * t + 3 * v + 2 ] = cz + 0.1 * ( random() - 0.5 );

		}

	}

	return out;

}

/** Ray–plane intersection and barycentric coordinates by Cramer's rule: a different derivation from Möller–Trumbore. */
function referenceHit( tri: Float64Array, t: number, o: number[], d: number[] ): { t: number; u: number; v: number } {

	const a = [ 0, 1, 2 ].map( ( i ) => tri[ 9 * t + i ] ), b = [ 0, 1, 2 ].map( ( i ) => tri[ 9 * t + 3 + i ] );
	const c = [ 0, 1, 2 ].map( ( i ) => tri[ 9 * t + 6 + i ] );
	// Solve o + s d = a + u (b − a) + v (c − a) for (s, u, v): columns [−d, b − a, c − a].
	const m = [ 0, 1, 2 ].map( ( i ) => [ - d[ i ], b[ i ] - a[ i ], c[ i ] - a[ i ] ] );
	const r = [ 0, 1, 2 ].map( ( i ) => o[ i ] - a[ i ] );
	const det3 = ( q: number[][] ) => q[ 0 ][ 0 ] * ( q[ 1 ][ 1 ] * q[ 2 ][ 2 ] - q[ 1 ][ 2 ] * q[ 2 ][ 1 ] )
		- q[ 0 ][ 1 ] * ( q[ 1 ][ 0 ] * q[ 2 ][ 2 ] - q[ 1 ][ 2 ] * q[ 2 ][ 0 ] )
		+ q[ 0 ][ 2 ] * ( q[ 1 ][ 0 ] * q[ 2 ][ 1 ] - q[ 1 ][ 1 ] * q[ 2 ][ 0 ] );
	const det = det3( m );
	const column = ( k: number ) => m.map( ( row, i ) => row.map( ( value, j ) => j === k ? r[ i ] : value ) );
	return { t: det3( column( 0 ) ) / det, u: det3( column( 1 ) ) / det, v: det3( column( 2 ) ) / det };

}

describe( 'intersectRayTriangle (Möller–Trumbore)', () => {

	const triangle = Float64Array.of( 0, 0, 0, 1, 0, 0, 0, 1, 0 );

	it( 'hits a triangle from either side at the right distance, misses outside, behind and parallel', () => {

		expect( intersectRayTriangle( triangle, 0, 0.2, 0.2, 1, 0, 0, - 2 ) ).toBeCloseTo( 0.5, 14 ); // t in units of |d|
		expect( intersectRayTriangle( triangle, 0, 0.2, 0.2, - 3, 0, 0, 1 ) ).toBeCloseTo( 3, 14 ); // back face counts too
		expect( intersectRayTriangle( triangle, 0, 0.6, 0.6, 1, 0, 0, - 1 ) ).toBe( - 1 ); // u + v > 1
		expect( intersectRayTriangle( triangle, 0, - 0.1, 0.2, 1, 0, 0, - 1 ) ).toBe( - 1 ); // u < 0
		expect( intersectRayTriangle( triangle, 0, 0.2, 0.2, 1, 0, 0, 1 ) ).toBe( - 1 ); // pointing away
		expect( intersectRayTriangle( triangle, 0, 0.2, 0.2, 0, 1, 0, 0 ) ).toBe( - 1 ); // in the plane, parallel
		expect( intersectRayTriangle( triangle, 0, - 1, 0.2, 1, 1, 0, 0 ) ).toBe( - 1 ); // parallel above it

	} );

	it( 'agrees with Cramer\'s rule on 2000 random rays and triangles', () => {

		const random = seededRandom( 5 );
		const triangles = randomTriangles( 2000, 6 );
		let hits = 0;
		for ( let t = 0; t < 2000; t ++ ) {

			const o = [ random(), random(), random() ], d = [ random() - 0.5, random() - 0.5, random() - 0.5 ];
			// Aim about half the rays at the triangle's centroid so both outcomes are well represented.
			if ( t % 2 === 0 ) {

				for ( let i = 0; i < 3; i ++ ) {

					const centroid = ( triangles[ 9 * t + i ] + triangles[ 9 * t + 3 + i ] + triangles[ 9 * t + 6 + i ] ) / 3;
					d[ i ] = centroid - o[ i ] + 0.03 * ( random() - 0.5 );

				}

			}

			const reference = referenceHit( triangles, t, o, d );
			const margin = Math.min( reference.u, reference.v, 1 - reference.u - reference.v, reference.t );
			if ( Math.abs( margin ) < 1e-9 ) continue; // on an edge: either answer is right
			const got = intersectRayTriangle( triangles, t, o[ 0 ], o[ 1 ], o[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ] );
			if ( margin > 0 ) {

				hits ++;
				expect( got ).toBeCloseTo( reference.t, 9 );

			} else {

				expect( got ).toBe( - 1 );

			}

		}

		expect( hits ).toBeGreaterThan( 300 );

	} );

} );

describe( 'TriangleBVH', () => {

	const triangles = randomTriangles( 5000, 7 );
	const bvh = new TriangleBVH( triangles );
	const random = seededRandom( 8 );

	it( 'counts the same ray crossings as testing every triangle', () => {

		// Brute force has no acceleration to get wrong: any box culled too eagerly shows up here.
		for ( let r = 0; r < 300; r ++ ) {

			const o = [ 1.4 * random() - 0.2, 1.4 * random() - 0.2, 1.4 * random() - 0.2 ];
			const d = [ random() - 0.5, random() - 0.5, random() - 0.5 ];
			if ( r % 10 === 0 ) { d[ 0 ] = 0; d[ 1 ] = 0; } // axis-parallel rays: zero reciprocal directions
			let brute = 0;
			for ( let t = 0; t < 5000; t ++ ) {

				if ( intersectRayTriangle( triangles, t, o[ 0 ], o[ 1 ], o[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ] ) > 0 ) brute ++;

			}

			expect( bvh.countCrossings( o[ 0 ], o[ 1 ], o[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ] ) ).toBe( brute );

		}

	} );

	it( 'finds the nearest distance and "any within r" like a scan of every triangle', () => {

		const scratch = new Float64Array( 6 );
		for ( let q = 0; q < 300; q ++ ) {

			const x = 1.4 * random() - 0.2, y = 1.4 * random() - 0.2, z = 1.4 * random() - 0.2;
			let nearest = Infinity;
			for ( let t = 0; t < 5000; t ++ ) {

				const k = 9 * t;
				nearest = Math.min( nearest, closestPointOnTriangle(
					x, y, z, triangles[ k ], triangles[ k + 1 ], triangles[ k + 2 ], triangles[ k + 3 ], triangles[ k + 4 ],
					triangles[ k + 5 ], triangles[ k + 6 ], triangles[ k + 7 ], triangles[ k + 8 ], scratch
				) );

			}

			nearest = Math.sqrt( nearest );
			expect( bvh.nearestDistance( x, y, z ) ).toBeCloseTo( nearest, 12 );
			expect( bvh.anyWithin( x, y, z, nearest * 1.001 ) ).toBe( true );
			expect( bvh.anyWithin( x, y, z, nearest * 0.999 ) ).toBe( false );

		}

	} );

	it( 'finds blocked segments and first hits like testing every triangle', () => {

		const hit = { t: 0, triangle: 0 };
		let blocked = 0, hits = 0;
		for ( let r = 0; r < 300; r ++ ) {

			const a = [ 1.4 * random() - 0.2, 1.4 * random() - 0.2, 1.4 * random() - 0.2 ];
			const b = [ 1.4 * random() - 0.2, 1.4 * random() - 0.2, 1.4 * random() - 0.2 ];
			if ( r % 10 === 0 ) { b[ 1 ] = a[ 1 ]; b[ 2 ] = a[ 2 ]; } // axis-parallel: zero reciprocal directions
			const d = [ b[ 0 ] - a[ 0 ], b[ 1 ] - a[ 1 ], b[ 2 ] - a[ 2 ] ];
			const tMax = r % 3 === 0 ? 0.5 : Infinity;
			let inside = false, bestT = Infinity, best = - 1;
			for ( let t = 0; t < 5000; t ++ ) {

				const s = intersectRayTriangle( triangles, t, a[ 0 ], a[ 1 ], a[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ] );
				if ( s > 1e-6 && s < 1 - 1e-6 ) inside = true;
				if ( s > 0 && s < tMax && s < bestT ) { bestT = s; best = t; }

			}

			expect( bvh.segmentBlocked( a[ 0 ], a[ 1 ], a[ 2 ], b[ 0 ], b[ 1 ], b[ 2 ] ), `segment ${r}` ).toBe( inside );
			const t = bvh.raycastFirst( a[ 0 ], a[ 1 ], a[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ], tMax, hit );
			expect( t ).toBe( best < 0 ? - 1 : bestT );
			expect( hit ).toEqual( { t, triangle: best } );
			if ( inside ) blocked ++;
			if ( best >= 0 ) hits ++;

		}

		// Both outcomes well represented.
		expect( blocked ).toBeGreaterThan( 30 );
		expect( 300 - blocked ).toBeGreaterThan( 30 );
		expect( hits ).toBeGreaterThan( 30 );

	} );

	it( 'measures distance to a tessellated sphere as |‖p‖ − r| within the tessellation error', () => {

		// Independent truth: the analytic sphere. 64 × 48 segments deviate from it by at most the
		// sagitta r (1 − cos(π / 48)) ≈ 0.0021 r.
		const sphere = new TriangleBVH( trianglesOf( new SphereGeometry( 1, 64, 48 ) ) );
		for ( let q = 0; q < 200; q ++ ) {

			const x = 4 * random() - 2, y = 4 * random() - 2, z = 4 * random() - 2;
			expect( Math.abs( sphere.nearestDistance( x, y, z ) - Math.abs( Math.hypot( x, y, z ) - 1 ) ) ).toBeLessThan( 0.0025 );

		}

	} );

	it( 'handles no triangles, and many triangles with one centroid', () => {

		const empty = new TriangleBVH( [] );
		expect( empty.countCrossings( 0, 0, 0, 1, 0, 0 ) ).toBe( 0 );
		expect( empty.anyWithin( 0, 0, 0, 1e9 ) ).toBe( false );
		expect( empty.nearestDistance( 0, 0, 0 ) ).toBe( Infinity );
		expect( empty.segmentBlocked( 0, 0, 0, 1, 0, 0 ) ).toBe( false );
		const miss = { t: 0, triangle: 0 };
		expect( empty.raycastFirst( 0, 0, 0, 1, 0, 0, Infinity, miss ) ).toBe( - 1 );
		expect( miss ).toEqual( { t: - 1, triangle: - 1 } );
		// 20 copies of one triangle cannot be split: one leaf holds them all, and all are found.
		const copies = new Float64Array( 9 * 20 );
		for ( let t = 0; t < 20; t ++ ) copies.set( [ 0, 0, 0, 1, 0, 0, 0, 1, 0 ], 9 * t );
		expect( new TriangleBVH( copies ).countCrossings( 0.2, 0.2, 1, 0.01, 0.02, - 1 ) ).toBe( 20 );

	} );

	it( 'rejects bad triangle arrays by name', () => {

		expect( () => new TriangleBVH( [ 0, 0, 0 ] ) ).toThrow( /^TriangleBVH: triangles must hold 9 floats/ );
		expect( () => new TriangleBVH( [ 0, 0, 0, 1, 0, 0, 0, NaN, 0 ] ) ).toThrow( /^TriangleBVH: triangles\[7\] is NaN/ );

	} );

} );

describe( 'classifyPoints (inside by majority of ray parities, near a surface by distance)', () => {

	// Closed shapes with analytic insides. three's sphere and torus repeat their seam vertices and
	// the sphere has degenerate pole triangles: the vote must survive rays through those.
	const shapes = [
		{ name: 'BoxGeometry', triangles: trianglesOf( new BoxGeometry( 2, 1, 1.5, 3, 2, 2 ) ), distance: ( x: number, y: number, z: number ) => boxDistance( x, y, z, 0, 0, 0, 1, 0.5, 0.75 ), tolerance: 1e-9 },
		{ name: 'SphereGeometry', triangles: trianglesOf( new SphereGeometry( 1, 48, 32 ) ), distance: ( x: number, y: number, z: number ) => sphereDistance( x, y, z, 0, 0, 0, 1 ), tolerance: 0.005 },
		{ name: 'TorusGeometry', triangles: trianglesOf( new TorusGeometry( 1, 0.35, 32, 96 ) ), distance: ( x: number, y: number, z: number ) => torusDistance( x, y, z, 0, 0, 0, 1, 0.35 ), tolerance: 0.003 },
	];

	for ( const shape of shapes ) {

		it( `agrees with the analytic inside of a closed ${shape.name} on 3000 random points`, () => {

			const random = seededRandom( 9 );
			const points = new Float64Array( 3 * 3000 );
			for ( let i = 0; i < points.length; i ++ ) points[ i ] = 3.2 * random() - 1.6;
			const classes = classifyPoints( points, shape.triangles );
			let inside = 0, checked = 0;
			for ( let i = 0; i < 3000; i ++ ) {

				const d = shape.distance( points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] );
				if ( Math.abs( d ) < shape.tolerance ) continue; // the tessellation and the analytic shape disagree here
				checked ++;
				if ( d < 0 ) inside ++;
				expect( classes[ i ], `point ${i} at signed distance ${d}` ).toBe( d < 0 ? INSIDE_GEOMETRY : OPEN_SPACE );

			}

			// Both outcomes must occur, or the test would pass for a classifier that always says one thing.
			expect( inside ).toBeGreaterThan( 100 );
			expect( checked - inside ).toBeGreaterThan( 100 );

		} );

	}

	it( 'marks points within minDistance as NEAR_SURFACE before voting', () => {

		const random = seededRandom( 10 );
		const points = new Float64Array( 3 * 2000 );
		for ( let i = 0; i < points.length; i ++ ) points[ i ] = 3 * random() - 1.5;
		const classes = classifyPoints( points, shapes[ 0 ].triangles, { minDistance: 0.2 } );
		for ( let i = 0; i < 2000; i ++ ) {

			const d = shapes[ 0 ].distance( points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ] );
			if ( Math.abs( Math.abs( d ) - 0.2 ) < 1e-9 ) continue;
			expect( classes[ i ] ).toBe( Math.abs( d ) < 0.2 ? NEAR_SURFACE : ( d < 0 ? INSIDE_GEOMETRY : OPEN_SPACE ) );

		}

		// parity: false → only the distance test.
		const noParity = classifyPoints( [ 0, 0, 0, 5, 5, 5 ], shapes[ 0 ].triangles, { parity: false } );
		expect( Array.from( noParity ) ).toEqual( [ OPEN_SPACE, OPEN_SPACE ] );

	} );

	it( 'uses 7 unit ray directions, none along an axis, axis plane or 45° diagonal', () => {

		expect( INSIDE_RAY_DIRECTIONS.length ).toBe( 21 );
		for ( let r = 0; r < 7; r ++ ) {

			const d = Array.from( INSIDE_RAY_DIRECTIONS.subarray( 3 * r, 3 * r + 3 ) );
			expect( Math.hypot( ...d ) ).toBeCloseTo( 1, 12 );
			for ( const c of d ) expect( Math.abs( c ) ).toBeGreaterThan( 0.02 );
			for ( const [ i, j ] of [ [ 0, 1 ], [ 1, 2 ], [ 0, 2 ] ] ) {

				expect( Math.abs( Math.abs( d[ i ] ) - Math.abs( d[ j ] ) ) ).toBeGreaterThan( 0.02 );

			}

		}

	} );

	it( 'rejects bad options by name', () => {

		expect( () => classifyPoints( [ 0, 0, 0 ], [], { minDistance: - 1 } ) ).toThrow( /^classifyPoints: options.minDistance must be ≥ 0/ );
		expect( () => classifyPoints( [ 0, 0, 0 ], [], { directions: [ 0, 0, 0 ] } ) ).toThrow( /^classifyPoints: options.directions\[0\] is the zero vector/ );
		expect( () => classifyPoints( [ 0, 0 ], [] ) ).toThrow( /^classifyPoints: points must hold x, y, z/ );

	} );

} );
