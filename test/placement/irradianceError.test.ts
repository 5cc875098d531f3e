import { describe, expect, it } from 'vitest';
import { IRRADIANCE_ERROR_NORMALS, irradianceError, summarizeErrors } from '../../src/placement/irradianceError.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

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

	it( 'with weights: all 1 changes nothing; integer weights count a point that many times; 0/1 weights measure the inside alone', () => {

		const random = mulberry32( 5 );
		const count = 40;
		const truth = Float32Array.from( { length: 27 * count }, ( _, i ) => ( i % 27 < 3 ? 2 : 0 ) + 0.5 * random() );
		const predicted = truth.map( ( v ) => v + 0.3 * ( random() - 0.5 ) );
		const plain = irradianceError( predicted, truth );
		const ones = irradianceError( predicted, truth, undefined, new Float64Array( count ).fill( 1 ) );
		for ( const key of [ 'mean', 'p95', 'max', 'meanIrradiance' ] as const ) expect( ones[ key ] ).toBeCloseTo( plain[ key ], 12 );

		// Weight k ≡ the point repeated k times (the unweighted measure of the repeated set).
		const weights = Array.from( { length: count }, ( _, p ) => p % 4 );
		const repeated: number[] = [];
		for ( let p = 0; p < count; p ++ ) for ( let k = 0; k < weights[ p ]; k ++ ) repeated.push( p );
		const take = ( sh: Float32Array, points: number[] ) => Float32Array.from(
			points.flatMap( ( p ) => Array.from( sh.subarray( 27 * p, 27 * p + 27 ) ) )
		);
		const expanded = irradianceError( take( predicted, repeated ), take( truth, repeated ) );
		const weighted = irradianceError( predicted, truth, IRRADIANCE_ERROR_NORMALS, weights );
		expect( weighted.mean ).toBeCloseTo( expanded.mean, 12 );
		expect( weighted.p95 ).toBeCloseTo( expanded.p95, 12 );
		expect( weighted.max ).toBeCloseTo( expanded.max, 12 );
		expect( weighted.meanIrradiance ).toBeCloseTo( expanded.meanIrradiance, 12 );

		// 0/1: the inside points alone; the outside ones (weight 0) are still listed in perPoint.
		const inside = Array.from( { length: count }, ( _, p ) => p ).filter( ( p ) => p < 10 );
		const alone = irradianceError( take( predicted, inside ), take( truth, inside ) );
		const region = irradianceError( predicted, truth, undefined, Array.from( { length: count }, ( _, p ) => p < 10 ? 1 : 0 ) );
		expect( region.mean ).toBeCloseTo( alone.mean, 12 );
		expect( region.max ).toBeCloseTo( alone.max, 12 );
		for ( let p = 0; p < 10; p ++ ) expect( region.perPoint[ p ] ).toBeCloseTo( alone.perPoint[ p ], 12 );
		expect( region.perPoint.length ).toBe( count );

	} );

	it( 'weighted 95th percentile: the smallest error whose cumulative weight reaches 95 % (weighted nearest rank)', () => {

		const errors = [ 0.4, 0.1, 0.3, 0.2 ];
		expect( summarizeErrors( errors, [ 17, 1, 1, 1 ] ).p95 ).toBe( 0.4 ); // cumulative 1, 2, 3, 20 of 20
		expect( summarizeErrors( errors, [ 1, 10, 4, 5 ] ).p95 ).toBe( 0.3 ); // 10, 15, 19 ≥ 19
		expect( summarizeErrors( errors, [ 1, 10, 3.9, 5 ] ).p95 ).toBe( 0.4 ); // 10, 15, 18.9 < 18.905
		expect( summarizeErrors( errors, [ 0, 1, 1, 0 ] ) ).toEqual( { mean: 0.2, p95: 0.3, max: 0.3 } ); // max over weight > 0
		// Equal weights: the unweighted nearest rank, ceil( 0.95 n ).
		const twenty = Array.from( { length: 20 }, ( _, i ) => i / 20 );
		expect( summarizeErrors( twenty, new Array( 20 ).fill( 0.1 ) ).p95 ).toBe( summarizeErrors( twenty ).p95 );

	} );

	it( 'rejects weights of the wrong length, negative or NaN weights and all-zero weights', () => {

		const truth = uniform( [ 1, 1, 1 ], [ 2, 2, 2 ] );
		expect( () => irradianceError( truth, truth, undefined, [ 1 ] ) ).toThrow( /^irradianceError: weights must have one weight per point \(2\), got length 1/ );
		expect( () => irradianceError( truth, truth, undefined, [ 1, - 1 ] ) ).toThrow( /^irradianceError: weights\[1\] is -1; weights must be finite numbers ≥ 0/ );
		expect( () => irradianceError( truth, truth, undefined, [ NaN, 1 ] ) ).toThrow( /^irradianceError: weights\[0\] is NaN/ );
		expect( () => irradianceError( truth, truth, undefined, [ 0, 0 ] ) ).toThrow( /^irradianceError: weights are all 0/ );

	} );

} );
