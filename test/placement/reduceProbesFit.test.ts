import { describe, expect, it } from 'vitest';
import { reduceProbes } from '../../src/placement/reduceProbes.js';
import { irradianceError } from '../../src/placement/irradianceError.js';
import { createProbeInterpolator } from '../../src/interpolation/createProbeInterpolator.js';
import { evaluateGradientField } from '../../src/fitting/evaluateGradientField.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { placeGrid } from '../../src/placement/placeGrid.js';
import { bumpField, linearField, sampleField } from './fields.js';

/*
 * reduceProbes' region of interest, per-point weights, extra fit samples, re-fit at every insertion
 * and swap passes (issue 14). Every reported error is checked against an independent measurement:
 * the layout's own interpolator (createProbeInterpolator over the returned positions), the returned
 * SH (and gradients) blended by fitting's evaluateGradientField, and irradianceError — nothing of
 * reduceProbes' incremental tables or local trial fits.
 */

const random = mulberry32( 2 );

/** An n × n × n grid in the unit cube, each point jittered by up to a quarter cell (no cospherical sets). */
function jittered( n: number ): Float64Array {

	const out: number[] = [];
	for ( let k = 0; k < n; k ++ ) for ( let j = 0; j < n; j ++ ) for ( let i = 0; i < n; i ++ ) {

		out.push( ...[ i, j, k ].map( ( c ) => ( c + 0.5 + 0.5 * ( random() - 0.5 ) ) / n ) );

	}

	return Float64Array.from( out );

}

const uniform = ( count: number ): Float64Array => Float64Array.from( { length: 3 * count }, () => random() );

/** Two reddish bumps of light of the same size, one near each of two opposite corners, on the linear field. */
const BUMP_A = [ 0.2, 0.5, 0.2 ], BUMP_B = [ 0.8, 0.5, 0.8 ];
function twoBumps( x: number, y: number, z: number, out: Float32Array | Float64Array, offset = 0 ): void {

	linearField( x, y, z, out, offset );
	for ( const [ cx, cy, cz ] of [ BUMP_A, BUMP_B ] ) {

		const g = Math.exp( - ( ( x - cx ) ** 2 + ( y - cy ) ** 2 + ( z - cz ) ** 2 ) / ( 2 * 0.1 * 0.1 ) );
		out[ offset ] += 2 * g; out[ offset + 1 ] += 0.8 * g; out[ offset + 3 ] += g;

	}

}

/** bumpField plus a point lamp (irradiance ∝ 1 / r²): far from linear near the lamp. */
function lampField( x: number, y: number, z: number, out: Float32Array | Float64Array, offset = 0 ): void {

	bumpField( x, y, z, out, offset );
	const lamp = 0.08 / ( ( x - 0.3 ) ** 2 + ( y - 0.9 ) ** 2 + ( z - 0.4 ) ** 2 + 0.01 );
	for ( let c = 0; c < 3; c ++ ) out[ offset + c ] += lamp;
	out[ offset + 3 ] += 0.5 * lamp;

}

/** The layout's field (its positions, SH and gradients, as returned) at `points`, as the runtime blends it. */
function predict( result: ReturnType<typeof reduceProbes>, points: Float64Array ): Float32Array {

	return evaluateGradientField( createProbeInterpolator( result.positions ), result.positions, result.sh, result.gradients, points );

}

const near = ( positions: Float64Array, i: number, centre: number[], radius: number ): boolean => Math.hypot(
	positions[ 3 * i ] - centre[ 0 ], positions[ 3 * i + 1 ] - centre[ 1 ], positions[ 3 * i + 2 ] - centre[ 2 ]
) < radius;

const countNear = ( positions: Float64Array, centre: number[] ): number => {

	let n = 0;
	for ( let i = 0; i < positions.length / 3; i ++ ) if ( near( positions, i, centre, 0.3 ) ) n ++;
	return n;

};

describe( 'reduceProbes with a region of interest, weights and fit samples', () => {

	const dense = jittered( 7 ); // 343 candidates
	const sh = sampleField( twoBumps, dense );
	const regionA = { boxes: [ { min: [ 0, 0, 0 ], max: [ 0.45, 1, 0.45 ] } ] }; // around bump A only

	it( 'puts the probes where the region is: a box over one of two equal bumps draws them there, with and without fit', () => {

		// Errors outside the box count a tenth, so the insertions go to the bump inside it: the box
		// over A gives A more probes than B, the box over B the other way round.
		const regionB = { boxes: [ { min: [ 0.55, 0, 0.55 ], max: [ 1, 1, 1 ] } ] };
		for ( const fit of [ false, { lambda: 0.3 } ] ) {

			const overA = reduceProbes( dense, sh, { targetCount: 24, fit, swaps: false, region: regionA } );
			const overB = reduceProbes( dense, sh, { targetCount: 24, fit, swaps: false, region: regionB } );
			const a = [ countNear( overA.positions, BUMP_A ), countNear( overA.positions, BUMP_B ) ];
			const b = [ countNear( overB.positions, BUMP_A ), countNear( overB.positions, BUMP_B ) ];
			const message = `fit ${JSON.stringify( fit )}: box over A → ${a[ 0 ]} near A, ${a[ 1 ]} near B; over B → ${b[ 0 ]} near A, ${b[ 1 ]} near B`;
			expect( a[ 0 ], message ).toBeGreaterThanOrEqual( 2 * a[ 1 ] + 3 );
			expect( b[ 1 ], message ).toBeGreaterThanOrEqual( 2 * b[ 0 ] + 3 );

		}

	} );

	it( 'with weight 0 outside, reports the error of the inside alone (as irradianceError measures it there)', () => {

		const region = { ...regionA, outsideWeight: 0 };
		const inside: number[] = [];
		for ( let p = 0; p < dense.length / 3; p ++ ) if ( dense[ 3 * p ] <= 0.45 && dense[ 3 * p + 2 ] <= 0.45 ) inside.push( p );
		const insidePoints = Float64Array.from( inside.flatMap( ( p ) => Array.from( dense.subarray( 3 * p, 3 * p + 3 ) ) ) );
		const insideSH = Float32Array.from( inside.flatMap( ( p ) => Array.from( sh.subarray( 27 * p, 27 * p + 27 ) ) ) );
		for ( const fit of [ false, { lambda: 0.3 } ] ) {

			const result = reduceProbes( dense, sh, { targetCount: 16, fit, swaps: false, region } );
			const measured = irradianceError( predict( result, insidePoints ), insideSH );
			expect( result.error.mean ).toBeCloseTo( measured.mean, 6 );
			expect( result.error.max ).toBeCloseTo( measured.max, 6 );
			// The whole set's error is another number: the outside is not in the report.
			expect( Math.abs( irradianceError( predict( result, dense ), sh ).mean - result.error.mean ) ).toBeGreaterThan( 1e-4 );

		}

	} );

	it( 'measures (and fits) at the extra fit samples too, weighted by the given weights', () => {

		const extra = uniform( 200 ), extraSH = sampleField( twoBumps, extra );
		const weights = Float64Array.from( { length: 343 }, ( _, p ) => 1 + ( p % 3 ) );
		const all = Float64Array.of( ...dense, ...extra ), allSH = Float32Array.of( ...sh, ...extraSH );
		const allWeights = Float64Array.of( ...weights, ...new Float64Array( 200 ).fill( 0.5 ) );
		for ( const fit of [ false, { lambda: 0.3 } ] ) {

			const result = reduceProbes( dense, sh, {
				targetCount: 14, fit, swaps: false, weights,
				fitSamples: { positions: extra, sh: extraSH, weights: new Float64Array( 200 ).fill( 0.5 ) },
			} );
			const measured = irradianceError( predict( result, all ), allSH, undefined, allWeights );
			expect( result.error.mean ).toBeCloseTo( measured.mean, 6 );
			expect( result.error.p95 ).toBeCloseTo( measured.p95, 6 );
			expect( result.perPoint.length ).toBe( 343 );

		}

	} );

} );

describe( 'reduceProbes with fit (re-fit at every insertion) and swap passes', () => {

	const dense = jittered( 7 ), extra = uniform( 300 ), evaluation = uniform( 1500 );
	const sh = sampleField( lampField, dense ), extraSH = sampleField( lampField, extra );
	const evaluationSH = sampleField( lampField, evaluation );
	const fitSamples = { positions: extra, sh: extraSH };
	const heldOut = ( result: ReturnType<typeof reduceProbes> ) => irradianceError( predict( result, evaluation ), evaluationSH ).mean;

	it( 'finds a better layout than fit off at the same count, judged on separate evaluation points', () => {

		// Fit off: the captured SH, worst-first or best-of-16; fit on (defaults: λ by cross-validation,
		// swaps): fitted SH at every step. Measured here: 0.060 against 0.086 and 0.085 at 20 probes
		// (the margin is smaller at some other counts: at 24, 0.056 against 0.079 and 0.055).
		const on = reduceProbes( dense, sh, { targetCount: 20, fit: true, fitSamples } );
		const worst = reduceProbes( dense, sh, { targetCount: 20 } ), mean = reduceProbes( dense, sh, { targetCount: 20, strategy: 'mean' } );
		const errors = { on: heldOut( on ), worst: heldOut( worst ), mean: heldOut( mean ) };
		expect( on.keep.length ).toBe( 20 );
		expect( errors.on, JSON.stringify( errors ) ).toBeLessThan( 0.85 * Math.min( errors.worst, errors.mean ) );
		// The reported λ and cross-validation error come from the final fit ('auto').
		expect( on.fit!.lambda ).toBeGreaterThanOrEqual( 0 );
		expect( on.fit!.crossValidationError ).toBeGreaterThan( 0 );
		expect( on.gradients ).toBeNull();

	} );

	it( 'reports the fitted field\'s error, as measured independently over the dense set and the fit samples', () => {

		for ( const gradients of [ false, true ] ) {

			const fit = { gradients, lambda: 0.3, gradientLambda: 0.01 };
			const result = reduceProbes( dense, sh, { targetCount: 12, fit, fitSamples } );
			const all = Float64Array.of( ...dense, ...extra ), allSH = Float32Array.of( ...sh, ...extraSH );
			const measured = irradianceError( predict( result, all ), allSH );
			expect( result.error.mean ).toBeCloseTo( measured.mean, 6 );
			expect( result.error.max ).toBeCloseTo( measured.max, 6 );
			expect( result.fit ).toEqual( { lambda: 0.3, gradientLambda: gradients ? 0.01 : 0, crossValidationError: null } );

		}

	} );

	it( 'swap passes never increase the fitted error (same λ), and do lower it here', () => {

		const options = { targetCount: 14, fit: { lambda: 0.3 }, fitSamples };
		const before = reduceProbes( dense, sh, { ...options, swaps: false } );
		const after = reduceProbes( dense, sh, { ...options, swaps: 3 } );
		expect( after.error.mean ).toBeLessThan( before.error.mean );
		// The insertions are the same run; the swaps only replace probes of it.
		expect( Array.from( after.history.mean ) ).toEqual( Array.from( before.history.mean ) );
		expect( after.keep.length ).toBe( 14 );
		const replaced = Array.from( after.order ).filter( ( i, k ) => i !== before.order[ k ] ).length;
		expect( replaced ).toBeGreaterThan( 0 );
		// Every pass count: the error after more passes is never above the error after fewer.
		let last = before.error.mean;
		for ( const swaps of [ 1, 2, 3 ] ) {

			const e = reduceProbes( dense, sh, { ...options, swaps } ).error.mean;
			expect( e ).toBeLessThanOrEqual( last );
			last = e;

		}

	} );

	it( 'swap passes also move starting-set probes, box-corner extremes on the hull included', () => {

		// The points with x > 0.5 count 0 (weights), so the layout's probes belong at x ≤ 0.5; measured
		// here: the corner extremes near (0, 0, 0) and (0, 1, 1) move inwards (before issue 14's change
		// the starting set's hull probes never moved).
		const weights = Float64Array.from( { length: dense.length / 3 }, ( _, i ) => dense[ 3 * i ] > 0.5 ? 0 : 1 );
		const options = { targetCount: 14, fit: { lambda: 0.3 }, weights };
		const before = reduceProbes( dense, sh, { ...options, swaps: false } );
		const after = reduceProbes( dense, sh, { ...options, swaps: 3 } );
		const starting = before.history.count[ 0 ];
		const atCorner = ( i: number ) => [ 0, 1, 2 ].every( ( a ) => Math.min( dense[ 3 * i + a ], 1 - dense[ 3 * i + a ] ) < 0.15 );
		const startingSet = Array.from( before.order.subarray( 0, starting ) );
		const movedCorners = startingSet.filter( ( i, k ) => atCorner( i ) && after.order[ k ] !== i );
		expect( movedCorners.length ).toBeGreaterThan( 0 );
		expect( after.error.mean ).toBeLessThan( before.error.mean );

	} );

	it( 'more swap trials per probe (swapTrials) never end above fewer at the same insertions here, and 1 works', () => {

		const options = { targetCount: 14, fit: { lambda: 0.3 }, fitSamples, swaps: 3 };
		const few = reduceProbes( dense, sh, { ...options, swapTrials: 1 } );
		const many = reduceProbes( dense, sh, { ...options, swapTrials: 12 } );
		const none = reduceProbes( dense, sh, { ...options, swaps: false } );
		expect( few.error.mean ).toBeLessThanOrEqual( none.error.mean );
		expect( many.error.mean ).toBeLessThan( few.error.mean );
		expect( many.keep.length ).toBe( 14 );

	} );

	it( 'hullTrials \'local\': swap passes still only lower the fitted error, and the error reported is the layout\'s own fit', () => {

		// At a fixed λ the swap passes keep a swap only when the exact fit's error drops, however trials are ranked.
		const options = { targetCount: 14, fit: { lambda: 0.3 }, fitSamples, hullTrials: 'local' as const };
		const local = reduceProbes( dense, sh, options ), none = reduceProbes( dense, sh, { ...options, swaps: false } );
		const relocate = reduceProbes( dense, sh, { ...options, hullTrials: 'relocate' } );
		expect( local.keep.length ).toBe( 14 );
		expect( local.error.mean ).toBeLessThan( none.error.mean );
		expect( relocate.error.mean ).toBeLessThan( none.error.mean );
		// The reported error is the layout's own fit (measured independently): the option changes no fit.
		const refit = reduceProbes( dense, sh, { ...options, keep: Array.from( local.keep ), swaps: false } );
		expect( refit.error.mean ).toBeCloseTo( local.error.mean, 12 );

	} );

	it( 'fits gradients when asked (the gradient objective), and they lower the error on this field', () => {

		const plain = reduceProbes( dense, sh, { targetCount: 12, fit: { lambda: 0.3 }, swaps: false, fitSamples } );
		const withGradients = reduceProbes( dense, sh, { targetCount: 12, fit: { gradients: true }, swaps: false, fitSamples } );
		expect( withGradients.gradients ).toBeInstanceOf( Float32Array );
		expect( withGradients.gradients!.length ).toBe( 81 * 12 );
		expect( withGradients.sh.length ).toBe( 27 * 12 );
		expect( withGradients.fit!.gradientLambda ).toBeGreaterThan( 0 );
		expect( heldOut( withGradients ) ).toBeLessThan( 0.8 * heldOut( plain ) );

	} );

	it( 'is exact on a linear field: the starting set, fitted, reproduces it (inside the dense hull)', () => {

		// A grid: its 8 corners (the box extremes of the starting set) span the whole dense hull.
		const grid = placeGrid( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 6, 6, 6 ] ), linear = sampleField( linearField, grid );
		const result = reduceProbes( grid, linear, { targetError: 1e-4, fit: { lambda: 0 }, swaps: false } );
		expect( result.keep.length ).toBe( result.history.count[ 0 ] );
		expect( result.error.mean ).toBeLessThan( 1e-4 );

	} );

	it( 'is deterministic: the same call gives the same layout, SH and gradients', () => {

		const options = { targetCount: 10, fit: { gradients: true }, fitSamples };
		const a = reduceProbes( dense, sh, options ), b = reduceProbes( dense, sh, options );
		expect( Array.from( b.order ) ).toEqual( Array.from( a.order ) );
		expect( Array.from( b.sh ) ).toEqual( Array.from( a.sh ) );
		expect( Array.from( b.gradients! ) ).toEqual( Array.from( a.gradients! ) );
		expect( b.fit ).toEqual( a.fit );

	} );

	it( 'rejects bad options, naming reduceProbes and the option', () => {

		const few = dense.slice( 0, 60 ), fewSH = sh.slice( 0, 540 );
		const nan = extra.slice( 0, 30 ); nan[ 7 ] = NaN;
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, weights: [ 1, 2 ] } ) )
			.toThrow( /^reduceProbes: options.weights must have one weight per point \(20\), got length 2/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, weights: new Array( 20 ).fill( - 1 ) } ) )
			.toThrow( /^reduceProbes: options.weights\[0\] is -1; weights must be ≥ 0/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, weights: new Array( 20 ).fill( 0 ) } ) ).toThrow( /^reduceProbes: every point has weight 0/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fitSamples: { positions: nan, sh: extraSH.slice( 0, 270 ) } } ) )
			.toThrow( /^reduceProbes: options.fitSamples.positions\[7\] is NaN/ );
		const short = { positions: extra.slice( 0, 30 ), sh: extraSH.slice( 0, 27 ) };
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fitSamples: short } ) )
			.toThrow( /^reduceProbes: options.fitSamples.sh must have length 270/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, region: { boxes: [ { min: [ 5, 5, 5 ], max: [ 6, 6, 6 ] } ] } } ) )
			.toThrow( /^reduceProbes: options.region contains none of the 20 positions/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: { lambda: - 1 } } ) ).toThrow( /^reduceProbes: options.fit.lambda must be 'auto' or a finite number ≥ 0/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: { gradient: true } as never } ) )
			.toThrow( /^reduceProbes: options.fit has unknown option "gradient"/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: { gradients: 'yes' } as never } ) )
			.toThrow( /^reduceProbes: options.fit.gradients must be true or false/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: 'on' as never } ) ).toThrow( /^reduceProbes: options.fit must be true, false or/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, swaps: true } ) ).toThrow( /^reduceProbes: options.swaps needs options.fit/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: true, swaps: - 1 } ) ).toThrow( /^reduceProbes: options.swaps must be an integer ≥ 0/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: true, swapTrials: 0 } ) ).toThrow( /^reduceProbes: options.swapTrials must be an integer ≥ 1/ );
		expect( () => reduceProbes( few, fewSH, { targetCount: 5, fit: true, hullTrials: 'exact' as never } ) )
			.toThrow( /^reduceProbes: options.hullTrials must be 'relocate' or 'local', got the string "exact"/ );

	} );

} );
