import { describe, expect, it } from 'vitest';
import { Matrix4, SphericalHarmonics3, Vector3, Vector4 } from 'three';
import { evaluateIrradiance, evaluateRadiance, irradianceMatrices, IRRADIANCE_MATRICES_FLOATS } from '../../src/sh/index.js';
import { random, randomDirection } from './helpers.js';

function randomSH( next: () => number, out = new Float32Array( 27 ), offset = 0 ): Float32Array {

	// Lighting-like: a dominant positive L00 plus signed higher bands.
	for ( let k = 0; k < 27; k ++ ) out[ offset + k ] = k < 3 ? 1 + 2 * next() : 2 * next() - 1;
	return out;

}

describe( 'irradiance reconstruction', () => {

	it( 'evaluateIrradiance / evaluateRadiance equal three getIrradianceAt / getAt (300 random SH × normals)', () => {

		// Same polynomial, so float64 results agree to rounding. The SH goes through three's
		// fromArray, which also proves the layout: coefficient k, channel c at index 3k + c.
		const next = random( 4 );
		const three = new SphericalHarmonics3();
		const normal = new Vector3(), expected = new Vector3();
		const ours = new Float64Array( 3 );
		for ( let n = 0; n < 300; n ++ ) {

			const sh = randomSH( next );
			three.fromArray( Array.from( sh ) );
			normal.fromArray( randomDirection( next ) );
			three.getIrradianceAt( normal, expected );
			evaluateIrradiance( sh, normal, ours );
			expect( ours[ 0 ] ).toBeCloseTo( expected.x, 12 );
			expect( ours[ 1 ] ).toBeCloseTo( expected.y, 12 );
			expect( ours[ 2 ] ).toBeCloseTo( expected.z, 12 );
			three.getAt( normal, expected );
			evaluateRadiance( sh, [ normal.x, normal.y, normal.z ], ours );
			expect( ours[ 0 ] ).toBeCloseTo( expected.x, 12 );
			expect( ours[ 1 ] ).toBeCloseTo( expected.y, 12 );
			expect( ours[ 2 ] ).toBeCloseTo( expected.z, 12 );

		}

	} );

	it( 'the Float32Array(27) layout round-trips through SphericalHarmonics3.fromArray / toArray', () => {

		const sh = randomSH( random( 5 ) );
		const three = new SphericalHarmonics3().fromArray( Array.from( sh ) );
		expect( Float32Array.from( three.toArray() ) ).toEqual( sh );
		// Coefficient 2 (Y10, z) of the green channel is three's coefficients[ 2 ].y.
		expect( three.coefficients[ 2 ].y ).toBe( sh[ 2 * 3 + 1 ] );

	} );

	it( 'nᵀ M n with n = (x, y, z, 1) equals evaluateIrradiance to 1e-6 (1000 random SH × normals, via three Matrix4)', () => {

		// M is built from the same 9 coefficients with R&H eq. 12; expanding nᵀMn gives exactly
		// three's getIrradianceAt polynomial. The only difference is float32 storage of M (6e-8
		// per entry), so |Δ| ≤ 1e-6 × Σ|term| — relative to the term magnitudes rather than to E,
		// which can be near zero by cancellation.
		const next = random( 6 );
		const matrices = new Float32Array( IRRADIANCE_MATRICES_FLOATS );
		const m = new Matrix4(), n4 = new Vector4(), mn = new Vector4();
		const e = new Float64Array( 3 );
		for ( let trial = 0; trial < 1000; trial ++ ) {

			const sh = randomSH( next );
			const [ x, y, z ] = randomDirection( next );
			irradianceMatrices( sh, matrices );
			evaluateIrradiance( sh, [ x, y, z ], e );
			for ( let c = 0; c < 3; c ++ ) {

				m.fromArray( matrices, c * 16 );
				n4.set( x, y, z, 1 );
				mn.copy( n4 ).applyMatrix4( m );
				const quadratic = n4.dot( mn );
				let scale = 0;
				for ( let k = 0; k < 9; k ++ ) scale += Math.abs( sh[ k * 3 + c ] );
				expect( Math.abs( quadratic - e[ c ] ) ).toBeLessThanOrEqual( 1e-6 * scale );

			}

		}

	} );

	it( 'with a Float64Array out, nᵀ M n equals evaluateIrradiance to 1e-6 of E itself (1000 random SH × normals)', () => {

		// Without float32 storage nothing but float64 rounding separates the two, so even E near
		// zero (cancellation) stays within 1e-6 relative. With Float32Array storage the pure
		// relative error reaches ~3e-3 where E ≈ 1e-5 (measured), hence the scale-relative bound above.
		const next = random( 9 );
		const matrices = new Float64Array( IRRADIANCE_MATRICES_FLOATS );
		const e = new Float64Array( 3 );
		for ( let trial = 0; trial < 1000; trial ++ ) {

			const sh = randomSH( next );
			const n = [ ...randomDirection( next ), 1 ];
			irradianceMatrices( sh, matrices );
			evaluateIrradiance( sh, n, e );
			for ( let c = 0; c < 3; c ++ ) {

				let quadratic = 0;
				for ( let col = 0; col < 4; col ++ ) for ( let row = 0; row < 4; row ++ ) {

					quadratic += n[ row ] * matrices[ c * 16 + col * 4 + row ] * n[ col ];

				}

				expect( Math.abs( quadratic - e[ c ] ) ).toBeLessThanOrEqual( 1e-6 * Math.abs( e[ c ] ) );

			}

		}

	} );

	it( 'each M is symmetric, M00 = −M11 = c1·L22 and column 3 holds c2·(L11, L1−1, L10) (R&H eq. 12 in three\'s order)', () => {

		const sh = randomSH( random( 7 ) );
		const out = irradianceMatrices( sh );
		for ( let c = 0; c < 3; c ++ ) {

			for ( let r = 0; r < 4; r ++ ) for ( let q = 0; q < 4; q ++ ) {

				expect( out[ c * 16 + q * 4 + r ] ).toBe( out[ c * 16 + r * 4 + q ] );

			}

			expect( out[ c * 16 ] ).toBeCloseTo( 0.429043 * sh[ 24 + c ], 6 );
			expect( out[ c * 16 + 5 ] ).toBeCloseTo( - 0.429043 * sh[ 24 + c ], 6 );
			// Translation slot (column 3, rows 0..2) holds c2 × band 1 (x, y, z) = c2 × (L11, L1−1, L10).
			expect( out[ c * 16 + 12 ] ).toBeCloseTo( 0.511664 * sh[ 9 + c ], 6 );
			expect( out[ c * 16 + 13 ] ).toBeCloseTo( 0.511664 * sh[ 3 + c ], 6 );
			expect( out[ c * 16 + 14 ] ).toBeCloseTo( 0.511664 * sh[ 6 + c ], 6 );

		}

	} );

	it( 'reads a probe inside a Float32Array(27·N) at shOffset and writes at outOffset, touching nothing else', () => {

		const next = random( 8 );
		const probes = new Float32Array( 27 * 5 );
		for ( let p = 0; p < 5; p ++ ) randomSH( next, probes, 27 * p );
		const single = probes.slice( 27 * 3, 27 * 4 );

		const out = new Float32Array( 48 * 4 ).fill( - 1 );
		expect( irradianceMatrices( probes, out, 48 * 2, 27 * 3 ) ).toBe( out );
		expect( Array.from( out.subarray( 96, 144 ) ) ).toEqual( Array.from( irradianceMatrices( single ) ) );
		expect( out.subarray( 0, 96 ).every( ( v ) => v === - 1 ) ).toBe( true );
		expect( out.subarray( 144 ).every( ( v ) => v === - 1 ) ).toBe( true );

		const normal = { x: 0.6, y: 0, z: - 0.8 };
		expect( Array.from( evaluateIrradiance( probes, normal, undefined, 27 * 3 ) ) )
			.toEqual( Array.from( evaluateIrradiance( single, normal ) ) );
		expect( Array.from( evaluateRadiance( probes, normal, undefined, 27 * 3 ) ) )
			.toEqual( Array.from( evaluateRadiance( single, normal ) ) );

	} );

} );
