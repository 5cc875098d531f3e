/**
 * blendGradientSH against truths computed here: the contract's formula written out term by term, blendSH itself when
 * the gradients are zero, and a field linear in space (each probe holding its value and gradient), which the formula
 * must reproduce at any point for any weights summing to 1.
 */
import { describe, expect, it } from 'vitest';
import { blendGradientSH } from '../../src/interpolation/blendGradientSH.js';
import { blendSH } from '../../src/interpolation/blendSH.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

const PROBES = 20;

function randomProbes( seed: number ) {

	const random = mulberry32( seed );
	const sh = Float32Array.from( { length: 27 * PROBES }, () => random() * 4 - 1 );
	const gradients = Float32Array.from( { length: 81 * PROBES }, () => random() * 2 - 1 );
	const positions = Float64Array.from( { length: 3 * PROBES }, () => random() * 10 - 5 );
	return { random, sh, gradients, positions };

}

/** Σ_j w_j · ( c_j[k] + Σ_a G_j[a][k] · ( q[a] − p_j[a] ) ), as the contract writes it. */
function direct(
	indices: number[], weights: number[], sh: ArrayLike<number>, gradients: ArrayLike<number>, positions: ArrayLike<number>, q: number[],
): number[] {

	const out: number[] = [];
	for ( let k = 0; k < 27; k ++ ) {

		let sum = 0;
		indices.forEach( ( i, j ) => {

			let value = sh[ 27 * i + k ];
			for ( let a = 0; a < 3; a ++ ) value += gradients[ 81 * i + 27 * a + k ] * ( q[ a ] - positions[ 3 * i + a ] );
			sum += weights[ j ] * value;

		} );
		out.push( sum );

	}

	return out;

}

describe( 'blendGradientSH', () => {

	it( 'equals the formula Σ w (c + G·(q − p)), written out here, for 1 to 9 weights (the 4 and 8 passes included), inside and far from the probes', () => {

		const { random, sh, gradients, positions } = randomProbes( 3 );
		for ( let count = 1; count <= 9; count ++ ) for ( const reach of [ 5, 500 ] ) {

			const indices = Array.from( { length: count }, () => Math.floor( random() * PROBES ) );
			const weights = Array.from( { length: count }, () => random() );
			const q = [ 0, 1, 2 ].map( () => reach * ( 2 * random() - 1 ) );
			const out = blendGradientSH( indices, weights, sh, gradients, positions, q[ 0 ], q[ 1 ], q[ 2 ], new Float64Array( 27 ) );
			const expected = direct( indices, weights, sh, gradients, positions, q );
			const scale = Math.max( ...expected.map( Math.abs ) );
			for ( let k = 0; k < 27; k ++ ) expect( Math.abs( out[ k ] - expected[ k ] ) ).toBeLessThan( 1e-13 * scale );

		}

	} );

	it( 'with zero gradients gives blendSH\'s very result (bit for bit), for 1 to 9 weights', () => {

		const { random, sh, positions } = randomProbes( 4 );
		const zero = new Float32Array( 81 * PROBES );
		for ( let count = 1; count <= 9; count ++ ) {

			const indices = Array.from( { length: count }, () => Math.floor( random() * PROBES ) );
			const weights = Float32Array.from( { length: count }, () => random() );
			if ( count === 5 ) weights[ 2 ] = 0; // the generic path skips zero weights, as blendSH's does
			const plain = blendSH( indices, weights, sh, new Float32Array( 27 ) );
			const blended = blendGradientSH( indices, weights, sh, zero, positions, 1.5, - 2, 0.25, new Float32Array( 27 ) );
			expect( Array.from( blended ) ).toEqual( Array.from( plain ) );

		}

	} );

	it( 'reproduces a linear field c(q) = a + B·q exactly at any point, for any weights summing to 1 (also weights no interpolator would give)', () => {

		const random = mulberry32( 9 );
		const a = Array.from( { length: 27 }, () => random() * 2 - 1 );
		const B = Array.from( { length: 81 }, () => random() * 0.4 - 0.2 ); // B[ 27·axis + k ]
		const field = ( q: number[], k: number ) => a[ k ] + B[ k ] * q[ 0 ] + B[ 27 + k ] * q[ 1 ] + B[ 54 + k ] * q[ 2 ];
		const positions = Float64Array.from( { length: 3 * PROBES }, () => random() * 10 - 5 );
		const sh = new Float64Array( 27 * PROBES ), gradients = new Float64Array( 81 * PROBES );
		for ( let i = 0; i < PROBES; i ++ ) {

			const p = Array.from( positions.subarray( 3 * i, 3 * i + 3 ) );
			for ( let k = 0; k < 27; k ++ ) sh[ 27 * i + k ] = field( p, k );
			gradients.set( B, 81 * i );

		}

		for ( const count of [ 1, 2, 3, 4, 8 ] ) for ( let trial = 0; trial < 5; trial ++ ) {

			const indices = Array.from( { length: count }, () => Math.floor( random() * PROBES ) );
			const raw = Array.from( { length: count }, () => random() );
			const total = raw.reduce( ( s, w ) => s + w, 0 );
			const weights = raw.map( ( w ) => w / total );
			const q = [ 40 * random() - 20, 40 * random() - 20, 40 * random() - 20 ];
			const out = blendGradientSH( indices, weights, sh, gradients, positions, q[ 0 ], q[ 1 ], q[ 2 ], [] as number[], count );
			for ( let k = 0; k < 27; k ++ ) expect( out[ k ] ).toBeCloseTo( field( q, k ), 12 );
			// The plain blend of the same probes is not the field there (the test can fail).
			const plain = blendSH( indices, weights, sh, new Float64Array( 27 ) );
			if ( count > 1 ) expect( Math.max( ...plain.map( ( v, k ) => Math.abs( v - field( q, k ) ) ) ) ).toBeGreaterThan( 1e-3 );

		}

	} );

	it( 'uses count pairs only (default indices.length), writes the target it returns, and accepts Float32Array, Float64Array and arrays', () => {

		const { sh, gradients, positions } = randomProbes( 5 );
		const indices = [ 3, 7, 1, 12, 19, 19 ], weights = [ 0.1, 0.2, 0.3, 0.4, 5, 5 ];
		const four = blendGradientSH( indices, weights, sh, gradients, positions, 0.5, 0.5, 0.5, new Float64Array( 27 ), 4 );
		const expected = direct( indices.slice( 0, 4 ), weights.slice( 0, 4 ), sh, gradients, positions, [ 0.5, 0.5, 0.5 ] );
		for ( let k = 0; k < 27; k ++ ) expect( four[ k ] ).toBeCloseTo( expected[ k ], 12 );
		const all = blendGradientSH( indices, weights, sh, gradients, positions, 0.5, 0.5, 0.5, new Float64Array( 27 ) );
		expect( all[ 0 ] ).not.toBeCloseTo( four[ 0 ], 3 );
		const target = new Float32Array( 27 );
		expect( blendGradientSH( indices, weights, sh, gradients, positions, 0.5, 0.5, 0.5, target, 4 ) ).toBe( target );
		for ( let k = 0; k < 27; k ++ ) expect( target[ k ] ).toBeCloseTo( expected[ k ], 4 );
		const array = blendGradientSH( indices, weights, sh, gradients, positions, 0.5, 0.5, 0.5, new Array<number>( 27 ), 4 );
		for ( let k = 0; k < 27; k ++ ) expect( array[ k ] ).toBeCloseTo( expected[ k ], 12 );

	} );

	it( 'names an index that is not a probe of all three arrays (SH, gradients, positions)', () => {

		const { sh, gradients, positions } = randomProbes( 6 );
		const weights = new Array( 4 ).fill( 0.25 ), out = new Float32Array( 27 );
		expect( () => blendGradientSH( [ 0, 1, 2, 99 ], weights, sh, gradients, positions, 0, 0, 0, out ) ).toThrow( /blendGradientSH: indices\[3\] = 99/ );
		// Probe 15 has SH and a position but no gradient in a shorter array.
		expect( () => blendGradientSH( [ 0, 15, 2, 3 ], weights, sh, gradients.subarray( 0, 81 * 10 ), positions, 0, 0, 0, out ) ).toThrow( /indices\[1\] = 15.*10 probes/ );
		expect( () => blendGradientSH( [ 0, 1, 12 ], [ 0.3, 0.3, 0.4 ], sh, gradients, positions.subarray( 0, 30 ), 0, 0, 0, out ) ).toThrow( /indices\[2\] = 12/ );

	} );

} );
