import { describe, expect, it } from 'vitest';
import { candidatesFromVertices } from '../../src/placement/candidatesFromVertices.js';
import { seededRandom } from '../helpers/pointSets.js';

/** n random vertices in the unit cube with random, non-unit normals. */
function randomVertices( n: number, seed: number ): { positions: Float64Array; normals: Float64Array } {

	const random = seededRandom( seed );
	const positions = new Float64Array( 3 * n ), normals = new Float64Array( 3 * n );
	for ( let i = 0; i < 3 * n; i ++ ) {

		positions[ i ] = random();
		normals[ i ] = 2 * random() - 1;

	}

	return { positions, normals };

}

/** For each candidate, the index of the vertex it came from (vertex + offset · unit normal), or −1. */
function sourcesOf( candidates: Float64Array, positions: Float64Array, normals: Float64Array, offset: number ): number[] {

	const sources: number[] = [];
	for ( let c = 0; c < candidates.length / 3; c ++ ) {

		let found = - 1;
		for ( let v = 0; v < positions.length / 3 && found < 0; v ++ ) {

			const length = Math.hypot( normals[ 3 * v ], normals[ 3 * v + 1 ], normals[ 3 * v + 2 ] );
			let distance = 0;
			for ( let a = 0; a < 3; a ++ ) {

				const expected = positions[ 3 * v + a ] + offset * normals[ 3 * v + a ] / length;
				distance = Math.max( distance, Math.abs( expected - candidates[ 3 * c + a ] ) );

			}

			if ( distance < 1e-12 ) found = v;

		}

		sources.push( found );

	}

	return sources;

}

describe( 'candidatesFromVertices (paper 2.1: probes from the background mesh\'s vertices)', () => {

	const { positions, normals } = randomVertices( 3000, 11 );
	const offset = 0.05, minSpacing = 0.08;
	const candidates = candidatesFromVertices( positions, normals, { offset, minSpacing } );
	const count = candidates.length / 3;

	it( 'moves each kept vertex exactly `offset` along its unit normal, keeping vertex order', () => {

		const sources = sourcesOf( candidates, positions, normals, offset );
		expect( sources ).not.toContain( - 1 );
		// Greedy in vertex order: the survivors come out in the order of their vertices.
		for ( let i = 1; i < sources.length; i ++ ) expect( sources[ i ] ).toBeGreaterThan( sources[ i - 1 ] );

	} );

	it( 'keeps every pair at least minSpacing apart (all pairs, brute force)', () => {

		expect( count ).toBeGreaterThan( 100 );
		let closest = Infinity;
		for ( let i = 0; i < count; i ++ ) for ( let j = i + 1; j < count; j ++ ) {

			closest = Math.min( closest, Math.hypot(
				candidates[ 3 * i ] - candidates[ 3 * j ], candidates[ 3 * i + 1 ] - candidates[ 3 * j + 1 ],
				candidates[ 3 * i + 2 ] - candidates[ 3 * j + 2 ]
			) );

		}

		expect( closest ).toBeGreaterThanOrEqual( minSpacing );

	} );

	it( 'drops only what another kept candidate covers: every moved vertex is within minSpacing of a kept one', () => {

		// The other half of a correct thinning: too aggressive a filter (a cell test instead of the
		// true distance) would leave holes, which this catches.
		let worst = 0;
		for ( let v = 0; v < positions.length / 3; v ++ ) {

			const length = Math.hypot( normals[ 3 * v ], normals[ 3 * v + 1 ], normals[ 3 * v + 2 ] );
			const x = positions[ 3 * v ] + offset * normals[ 3 * v ] / length;
			const y = positions[ 3 * v + 1 ] + offset * normals[ 3 * v + 1 ] / length;
			const z = positions[ 3 * v + 2 ] + offset * normals[ 3 * v + 2 ] / length;
			let nearest = Infinity;
			for ( let c = 0; c < count; c ++ ) {

				const gap = Math.hypot( candidates[ 3 * c ] - x, candidates[ 3 * c + 1 ] - y, candidates[ 3 * c + 2 ] - z );
				nearest = Math.min( nearest, gap );

			}

			worst = Math.max( worst, nearest );

		}

		expect( worst ).toBeLessThan( minSpacing );

	} );

	it( 'is deterministic, and keeps every moved vertex when minSpacing is 0', () => {

		expect( Array.from( candidatesFromVertices( positions, normals, { offset, minSpacing } ) ) ).toEqual( Array.from( candidates ) );
		const all = candidatesFromVertices( positions, normals, { offset, minSpacing: 0 } );
		expect( all.length ).toBe( positions.length );
		expect( sourcesOf( all.subarray( 0, 30 ), positions, normals, offset ) ).toEqual( [ ...Array( 10 ).keys() ] );

	} );

	it( 'works at any coordinate scale (negative and large coordinates, tiny spacing)', () => {

		// Cell coordinates far from 0 and negative exercise the hash; the spacing guarantee must hold.
		const shifted = positions.map( ( v, i ) => ( i % 3 === 1 ? - 1e4 : 3e3 ) + v * 0.01 );
		const out = candidatesFromVertices( shifted, normals, { offset: 0.001, minSpacing: 0.002 } );
		for ( let i = 0; i < out.length / 3; i ++ ) for ( let j = i + 1; j < out.length / 3; j ++ ) {

			const gap = Math.hypot( out[ 3 * i ] - out[ 3 * j ], out[ 3 * i + 1 ] - out[ 3 * j + 1 ], out[ 3 * i + 2 ] - out[ 3 * j + 2 ] );
			expect( gap ).toBeGreaterThanOrEqual( 0.002 );

		}

	} );

	it( 'skips vertices with zero normals (no side to move to)', () => {

		const out = candidatesFromVertices( [ 0, 0, 0, 1, 0, 0 ], [ 0, 0, 0, 0, 2, 0 ], { offset: 0.5, minSpacing: 0 } );
		expect( Array.from( out ) ).toEqual( [ 1, 0.5, 0 ] );

	} );

	it( 'rejects bad input, naming the function and argument', () => {

		expect( () => candidatesFromVertices( [ 0, 0, 0 ], [ 0, 1 ], { offset: 1, minSpacing: 1 } ) ).toThrow( /^candidatesFromVertices: normals must hold x, y, z/ );
		expect( () => candidatesFromVertices( [ 0, 0, 0, 1, 1, 1 ], [ 0, 1, 0 ], { offset: 1, minSpacing: 1 } ) ).toThrow( /^candidatesFromVertices: normals must have one normal per vertex/ );
		expect( () => candidatesFromVertices( [ 0, NaN, 0 ], [ 0, 1, 0 ], { offset: 1, minSpacing: 1 } ) ).toThrow( /^candidatesFromVertices: positions\[1\] is NaN/ );
		expect( () => candidatesFromVertices( [ 0, 0, 0 ], [ 0, 1, 0 ], { offset: 1, minSpacing: - 1 } ) ).toThrow( /^candidatesFromVertices: options.minSpacing must be ≥ 0/ );
		expect( () => candidatesFromVertices( [ 0, 0, 0 ], [ 0, 1, 0 ], { offset: Infinity, minSpacing: 1 } ) ).toThrow( /^candidatesFromVertices: options.offset must be a finite number/ );

	} );

} );
