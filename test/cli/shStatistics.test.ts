import { SphericalHarmonics3, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { BLACK_FRACTION, NEGATIVE_FRACTION, formatShStatistics, shStatistics } from '../../cli/shStatistics.js';
import { bakeWarnings } from '../../cli/bakeWarnings.js';
import { makeIrradianceNonNegative } from '../../src/sh/windowSH.js';
import { fromFloat16Bits, toFloat16Bits } from '../../src/io/float16.js';

/*
 * The CLI's SH statistics and warnings against hand-computed values. Irradiance of an SH9 probe
 * (Ramamoorthi & Hanrahan, three's getIrradianceAt): E(n) = c4·L00 + 2·c2·(L1−1·y + L10·z + L11·x) + band 2,
 * so a probe with only L00 and L10 has E between c4·L00 − 2·c2·|L10| (n = −z) and c4·L00 + 2·c2·|L10|.
 */

const C2 = 0.511664, C4 = 0.886227;

/** SH of `probes`, each given as { l00: [r, g, b] or one value, l10?: value for every channel }. */
function shOf( probes: { l00: number | number[]; l10?: number }[] ): Float32Array {

	const sh = new Float32Array( 27 * probes.length );
	probes.forEach( ( { l00, l10 = 0 }, p ) => {

		for ( let c = 0; c < 3; c ++ ) {

			sh[ 27 * p + c ] = typeof l00 === 'number' ? l00 : l00[ c ];
			sh[ 27 * p + 3 * 2 + c ] = l10;

		}

	} );
	return sh;

}

describe( 'shStatistics', () => {

	it( 'L00 min / median / max per channel (odd and even counts)', () => {

		const probes = [ { l00: [ 1, 5, 0.5 ] }, { l00: [ 3, 6, 0.25 ] }, { l00: [ 2, 7, 1 ] }, { l00: [ 10, 8, 2 ] } ];
		const even = shStatistics( shOf( probes ), 4 );
		expect( even.l00.min ).toEqual( [ 1, 5, 0.25 ] );
		expect( even.l00.median ).toEqual( [ 2.5, 6.5, 0.75 ] );
		expect( even.l00.max ).toEqual( [ 10, 8, 2 ] );
		const odd = shStatistics( shOf( [ { l00: 4 }, { l00: 1 }, { l00: 9 } ] ), 3 );
		expect( odd.l00.median ).toEqual( [ 4, 4, 4 ] );

	} );

	it( 'a probe with only L00 has E = c4·L00 everywhere; a strong L10 over a small L00 dips below 0 by c4·L00 − 2·c2·L10', () => {

		const stats = shStatistics( shOf( [ { l00: 2 }, { l00: 0.1, l10: 1 }, { l00: 1, l10: 0.5 } ] ), 3 );
		// Probe 1: E(−z) = c4·0.1 − 2·c2·1 = −0.9347; probe 2: E(−z) = c4 − c2 = 0.3746 > 0; probe 0: 2·c4 > 0.
		expect( stats.negative ).toBe( 1 );
		expect( stats.negativeProbes ).toEqual( [ 1 ] );
		expect( stats.lowestProbe ).toBe( 1 );
		expect( stats.lowestIrradiance ).toBeCloseTo( C4 * 0.1 - 2 * C2, 5 );

		const lit = shStatistics( shOf( [ { l00: 2 }, { l00: 1, l10: 0.5 } ] ), 2 );
		expect( lit.negative ).toBe( 0 );
		expect( lit.lowestProbe ).toBe( 1 );
		expect( lit.lowestIrradiance ).toBeCloseTo( C4 - C2, 5 );
		const only = shStatistics( shOf( [ { l00: 2 } ] ), 1 );
		expect( only.lowestIrradiance ).toBeCloseTo( 2 * C4, 5 );

	} );

	it( 'the lowest irradiance of random probes is at most three\'s getIrradianceAt over 2,000 normals, and within 1e-3 of it', () => {

		let seed = 7;
		const random = () => ( seed = ( seed * 16807 ) % 2147483647 ) / 2147483647;
		const sh = new Float32Array( 27 * 20 ).map( ( _, i ) => ( i % 27 < 3 ? 0.5 : 0 ) + ( random() - 0.5 ) * 0.8 );
		const normals: Vector3[] = [];
		for ( let i = 0; i < 2000; i ++ ) {

			// A Fibonacci sphere: even cover, so the sampled minimum is close to the true one.
			const z = 1 - ( 2 * i + 1 ) / 2000, r = Math.sqrt( 1 - z * z ), phi = i * Math.PI * ( 3 - Math.sqrt( 5 ) );
			normals.push( new Vector3( r * Math.cos( phi ), r * Math.sin( phi ), z ) );

		}

		const probe = new SphericalHarmonics3(), e = new Vector3();
		let sampled = Infinity;
		for ( let p = 0; p < 20; p ++ ) {

			probe.fromArray( Array.from( sh.subarray( 27 * p, 27 * p + 27 ) ) );
			for ( const n of normals ) {

				probe.getIrradianceAt( n, e );
				sampled = Math.min( sampled, e.x, e.y, e.z );

			}

		}

		const stats = shStatistics( sh, 20 );
		expect( sampled ).toBeLessThan( 0 ); // the set has negative probes, so the comparison means something
		expect( stats.lowestIrradiance ).toBeLessThanOrEqual( sampled + 1e-6 );
		expect( stats.lowestIrradiance ).toBeGreaterThan( sampled - 1e-3 );

	} );

	it( 'the worst ring relative to the probe\'s mean and the lowest value can be at different probes', () => {

		// Probe 0: L00 10, L10 9: min E = 10·c4 − 2·c2·9 = −0.348, mean 8.862 → −3.9 %.
		// Probe 1: L00 0.1, L10 0.1: min E = 0.0886 − 0.1023 = −0.0137, mean 0.0886 → −15.5 %.
		const stats = shStatistics( shOf( [ { l00: 10, l10: 9 }, { l00: 0.1, l10: 0.1 } ] ), 2 );
		expect( stats.lowestProbe ).toBe( 0 );
		expect( stats.lowestIrradiance ).toBeCloseTo( 10 * C4 - 18 * C2, 4 );
		expect( stats.deepestRingProbe ).toBe( 1 );
		expect( stats.deepestRing ).toBeCloseTo( ( 0.1 * C4 - 0.2 * C2 ) / ( 0.1 * C4 ), 5 );

	} );

	it( 'a uniform cap of 60° (a ceiling light seen from below) rings to E(−z) = −0.0245, −3.1 % of its mean, by hand', () => {

		// Radiance 1 for θ < 60° about +z: L_l0 = 2π ∫ Y_l0 over cos θ ∈ [½, 1]: L00 = 2π·Y00·½,
		// L10 = 2π·Y1·(1 − ¼)/2, L20 = 2π·Y20·(½ − ⅛). E(−z) = c4·L00 − 2·c2·L10 + (c3 − c5)·L20.
		const L00 = Math.PI * 0.282095, L10 = 2 * Math.PI * 0.488603 * 0.375, L20 = 2 * Math.PI * 0.315392 * 0.375;
		const sh = new Float32Array( 27 );
		for ( let c = 0; c < 3; c ++ ) {

			sh[ c ] = L00;
			sh[ 6 + c ] = L10;
			sh[ 18 + c ] = L20;

		}

		const expected = C4 * L00 - 2 * C2 * L10 + ( 0.743125 - 0.247708 ) * L20;
		expect( expected ).toBeCloseTo( - 0.02454, 5 );
		const stats = shStatistics( sh, 1 );
		expect( stats.lowestIrradiance ).toBeCloseTo( expected, 5 );
		expect( stats.deepestRing ).toBeCloseTo( expected / ( C4 * L00 ), 5 );
		expect( stats.negative ).toBe( 1 );

	} );

	it( `black: every channel's L00 ≤ ${BLACK_FRACTION} of the brightest probe's largest L00, or ≤ 1e-6`, () => {

		// Brightest L00 = 4 (blue of probe 0): threshold 4e-3.
		const stats = shStatistics( shOf( [
			{ l00: [ 1, 2, 4 ] },
			{ l00: 0.99 * 4e-3 }, // just below in every channel: black
			{ l00: [ 1.01 * 4e-3, 0, 0 ] }, // one channel just above: not black
			{ l00: 0 },
			{ l00: [ - 0.5, 0, 0 ] }, // negative L00 (no capture gives it) is black too
		] ), 5 );
		expect( stats.blackThreshold ).toBeCloseTo( 4e-3, 12 );
		expect( stats.blackProbes ).toEqual( [ 1, 3, 4 ] );
		expect( stats.black ).toBe( 3 );

		// All dim: the threshold is the 1e-6 floor.
		const dim = shStatistics( shOf( [ { l00: 0.99e-6 }, { l00: 1.01e-6 }, { l00: 0 } ] ), 3 );
		expect( dim.blackThreshold ).toBe( 1e-6 );
		expect( dim.blackProbes ).toEqual( [ 0, 2 ] );

	} );

	it( `negative only beyond ${NEGATIVE_FRACTION.toFixed( 5 )} of the probe's mean irradiance c4·L00`, () => {

		// L00 = 1, L10 = t: min E = c4 − 2·c2·t; choose t for min E = −(1 ± 10 %)·c4/256.
		const t = ( k: number ) => ( C4 + k * NEGATIVE_FRACTION * C4 ) / ( 2 * C2 );
		const stats = shStatistics( shOf( [ { l00: 1, l10: t( 1.1 ) }, { l00: 1, l10: t( 0.9 ) } ] ), 2 );
		expect( stats.lowestIrradiance ).toBeCloseTo( - 1.1 * NEGATIVE_FRACTION * C4, 6 );
		expect( stats.negativeProbes ).toEqual( [ 0 ] );

	} );

	it( 'probes made non-negative and stored as float16 are not counted; the same probes before the switch are', () => {

		let seed = 3;
		const random = () => ( seed = ( seed * 16807 ) % 2147483647 ) / 2147483647;
		const count = 2000;
		const sh = new Float32Array( 27 * count );
		for ( let p = 0; p < count; p ++ ) {

			// Magnitudes 1e-3 … 1e3; L1 and L2 up to 1.5× the L00 scale, so most ring.
			const scale = 10 ** ( 6 * random() - 3 );
			for ( let k = 0; k < 27; k ++ ) sh[ 27 * p + k ] = scale * ( k < 3 ? 0.1 + random() : 1.5 * ( 2 * random() - 1 ) );

		}

		expect( shStatistics( sh, count ).negative ).toBeGreaterThan( count / 2 );
		makeIrradianceNonNegative( sh );
		const float16 = sh.map( ( v ) => fromFloat16Bits( toFloat16Bits( v ) ) );
		const stats = shStatistics( float16, count );
		expect( stats.negative ).toBe( 0 );
		expect( stats.lowestIrradiance ).toBeLessThan( 0 ); // float16 rounding did go below 0: the margin is what hides it

	} );

	it( 'refuses a bad count, a wrong length and non-finite values, naming itself', () => {

		expect( () => shStatistics( new Float32Array( 27 ), 0 ) ).toThrow( /^shStatistics: count must be an integer ≥ 1, got 0\.$/ );
		expect( () => shStatistics( new Float32Array( 54 ), 1 ) ).toThrow( /^shStatistics: sh must have length 27/ );
		const nan = new Float32Array( 27 );
		nan[ 5 ] = NaN;
		expect( () => shStatistics( nan, 1 ) ).toThrow( /^shStatistics: sh\[5\]/ );

	} );

	it( 'formatShStatistics: rows with the counts, the threshold, the lowest value and the probe indices', () => {

		const rows = formatShStatistics( shStatistics( shOf( [ { l00: [ 1, 2, 4 ] }, { l00: 0 }, { l00: 0.1, l10: 1 } ] ), 3 ) );
		expect( rows ).toEqual( [
			[ 'L00 min/median/max', 'R 0 / 0.1 / 1, G 0 / 0.1 / 2, B 0 / 0.1 / 4' ],
			[ 'black probes', '1 of 3 (L00 ≤ 0.004 in every channel, 1/1000 of the brightest; probe 1)' ],
			[ 'negative irradiance', '1 of 3 (E(n) below −1/256 of the probe\'s mean for some normal n; probe 2; lowest E(n) -0.9347 at probe 2, '
				+ 'lowest E(n)/mean -1100 % at probe 2)' ],
		] );

	} );

} );

describe( 'bakeWarnings', () => {

	const lit = { lights: 2, emissive: 0 };

	it( 'none for a lit, non-negative set', () => {

		expect( bakeWarnings( shStatistics( shOf( [ { l00: 1 }, { l00: 2, l10: 0.5 } ] ), 2 ), lit ) ).toEqual( [] );
		expect( bakeWarnings( shStatistics( shOf( [ { l00: 1 } ] ), 1 ) ) ).toEqual( [] );

	} );

	it( 'some black probes: the count, the indices and "inside walls"; all black: no light reached any probe', () => {

		const dark = Array.from( { length: 11 }, () => ( { l00: 0 } ) ), dim = Array.from( { length: 52 }, () => ( { l00: 0.5 } ) );
		const probes = [ { l00: 1 }, ...dark, ...dim ];
		const [ warning, ...rest ] = bakeWarnings( shStatistics( shOf( probes ), 64 ), lit );
		expect( rest ).toEqual( [] );
		expect( warning ).toMatch( /^11 of 64 probes are black \(L00 ≤ 0\.001 in every channel; probes 1, 2, 3, 4, 5, 6, 7, 8 and 3 more\): / );
		expect( warning ).toMatch( /inside walls or closed objects/ );

		const all = bakeWarnings( shStatistics( new Float32Array( 27 * 5 ), 5 ) );
		expect( all ).toHaveLength( 1 );
		expect( all[ 0 ] ).toMatch( /^5 of 5 probes are black \(L00 ≤ 1e-6 in every channel; probes 0, 1, 2, 3, 4\): no light reached any probe/ );
		expect( all[ 0 ] ).toMatch( /--point/ );

	} );

	it( 'a scene without lights or emissive materials: one warning with the black count and the flags to pass', () => {

		const warnings = bakeWarnings( shStatistics( new Float32Array( 27 * 12 ), 12 ), { lights: 0, emissive: 0 } );
		expect( warnings ).toHaveLength( 1 );
		expect( warnings[ 0 ] ).toMatch( /^the scene has no lights, no emissive materials and no --sky, so 12 of 12 probes are black \(/ );
		expect( warnings[ 0 ] ).toMatch( /--sun, --point, --spot, --ambient or --sky, add "lights" to the layout/ );
		// An emissive ceiling is a light source: black probes are then blamed on where they are.
		expect( bakeWarnings( shStatistics( shOf( [ { l00: 1 }, { l00: 0 } ] ), 2 ), { lights: 0, emissive: 1 } )[ 0 ] ).toMatch( /inside walls/ );

	} );

	it( 'negative irradiance: the count, the lowest value, its probe and the two fixes', () => {

		const warnings = bakeWarnings( shStatistics( shOf( [ { l00: 1 }, { l00: 0.1, l10: 1 }, { l00: 0.2, l10: 1 } ] ), 3 ), lit );
		expect( warnings ).toHaveLength( 1 );
		// Probe 1: −0.9347 / (c4·0.1) = −10.5; probe 2: (c4·0.2 − 2·c2) / (c4·0.2) = −4.8.
		expect( warnings[ 0 ] ).toMatch( /^2 of 3 probes have negative irradiance \(E\(n\) down to -1100 % of the probe's mean at probe 1, lowest E\(n\) -0\.9347 at probe 1; probes 1, 2\): ringing/ );
		expect( warnings[ 0 ] ).toMatch( /--non-negative, or --deringing 0\.1/ );

	} );

} );
