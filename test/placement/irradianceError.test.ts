import { describe, expect, it } from 'vitest';
import { IRRADIANCE_ERROR_NORMALS, irradianceError } from '../../src/placement/irradianceError.js';

/** SH of a uniform environment: only L00, per channel. Its irradiance is the same in every direction. */
function uniform( ...l00PerProbe: [ number, number, number ][] ): Float32Array {

	const sh = new Float32Array( 27 * l00PerProbe.length );
	l00PerProbe.forEach( ( rgb, p ) => sh.set( rgb, 27 * p ) );
	return sh;

}

describe( 'irradianceError (the one error measure of layouts)', () => {

	it( 'measures 26 unit normals: the neighbours of a 3×3×3 block, symmetric and distinct', () => {

		const n = IRRADIANCE_ERROR_NORMALS;
		expect( n.length ).toBe( 78 );
		const keys = new Set<string>();
		const sum = [ 0, 0, 0 ];
		for ( let k = 0; k < 26; k ++ ) {

			expect( Math.hypot( n[ 3 * k ], n[ 3 * k + 1 ], n[ 3 * k + 2 ] ) ).toBeCloseTo( 1, 14 );
			keys.add( [ 0, 1, 2 ].map( ( a ) => Math.sign( n[ 3 * k + a ] ) ).join() );
			for ( let a = 0; a < 3; a ++ ) sum[ a ] += n[ 3 * k + a ];

		}

		expect( keys.size ).toBe( 26 ); // every sign pattern except (0, 0, 0): the 26 neighbours
		for ( const s of sum ) expect( s ).toBeCloseTo( 0, 12 );

	} );

	it( 'is 0.1 everywhere when the prediction is 10 % too bright', () => {

		// Irradiance is linear in the SH: 1.1 × SH gives 1.1 × E in every direction, and for a single
		// grey probe the normaliser Ē is that probe's own E, so |1.1 E − E| / E = 0.1 exactly.
		const truth = uniform( [ 1, 1, 1 ] ), predicted = truth.map( ( v ) => 1.1 * v );
		const e = irradianceError( predicted, truth );
		expect( e.mean ).toBeCloseTo( 0.1, 6 );
		expect( e.p95 ).toBeCloseTo( 0.1, 6 );
		expect( e.max ).toBeCloseTo( 0.1, 6 );

	} );

	it( 'takes the worst colour channel: a blue-only error counts in full (luminance would weigh it 0.07)', () => {

		const truth = uniform( [ 1, 1, 1 ] ), predicted = uniform( [ 1, 1, 1.5 ] );
		expect( irradianceError( predicted, truth ).mean ).toBeCloseTo( 0.5, 6 );

	} );

	it( 'normalises by the mean irradiance of all points, not each point\'s own', () => {

		// Two grey probes with L00 = 1 and 3: Ē = 2 · c (c = E per unit L00). The dark one is
		// predicted 0.2 too high: its error is 0.2 c / 2 c = 0.1 (not 0.2 / 1 relative to itself),
		// the bright one's is 0. Mean 0.05, max 0.1, and the 95th percentile of two values is the larger.
		const truth = uniform( [ 1, 1, 1 ], [ 3, 3, 3 ] ), predicted = uniform( [ 1.2, 1.2, 1.2 ], [ 3, 3, 3 ] );
		const e = irradianceError( predicted, truth );
		expect( Array.from( e.perPoint ).map( ( v ) => +v.toFixed( 6 ) ) ).toEqual( [ 0.1, 0 ] );
		expect( e.mean ).toBeCloseTo( 0.05, 6 );
		expect( e.max ).toBeCloseTo( 0.1, 6 );
		expect( e.p95 ).toBeCloseTo( 0.1, 6 );

	} );

	it( 'averages over the normals: an error in one direction only counts for the normals that see it', () => {

		// Truth: uniform grey. Prediction adds L10 (the z coefficient), which changes E(n) by
		// c2 · L10 · n_z (c2 = 2π/3 · 0.488603): + on the 9 normals with n_z > 0, − on the 9 with
		// n_z < 0, 0 on the 8 with n_z = 0. The normal z components are 1, 1/√2 (×4), 1/√3 (×4) per side.
		const truth = uniform( [ 1, 1, 1 ] ), predicted = uniform( [ 1, 1, 1 ] );
		predicted.fill( 0.1, 6, 9 );
		const e0 = 0.886227; // E per unit L00
		const c2 = ( 2 * Math.PI / 3 ) * 0.488603;
		const sumAbsZ = 2 * ( 1 + 4 / Math.SQRT2 + 4 / Math.sqrt( 3 ) );
		expect( irradianceError( predicted, truth ).mean ).toBeCloseTo( c2 * 0.1 * sumAbsZ / 26 / e0, 5 );

	} );

	it( 'rejects mismatched lengths, NaN and an all-black truth, naming irradianceError', () => {

		expect( () => irradianceError( new Float32Array( 27 ), new Float32Array( 54 ).fill( 1 ) ) ).toThrow( /^irradianceError: predictedSH must have length 54/ );
		expect( () => irradianceError( new Float32Array( 27 ).fill( NaN ), new Float32Array( 27 ).fill( 1 ) ) ).toThrow( /^irradianceError: predictedSH\[0\] is NaN/ );
		expect( () => irradianceError( new Float32Array( 27 ), new Float32Array( 27 ) ) ).toThrow( /^irradianceError: the true irradiance averages 0/ );

	} );

} );
