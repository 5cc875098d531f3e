import { describe, expect, it } from 'vitest';
import { GridInterpolator, blendSH } from '../../src/math.js';
import { seededRandom } from '../helpers/pointSets.js';

describe( 'GridInterpolator (the paper\'s 8-probe trilinear baseline)', () => {

	const grid = new GridInterpolator( [ - 2, 0, 1 ], [ 2, 3, 4 ], [ 4, 4, 4 ] );
	const indices = new Uint32Array( 8 ), weights = new Float64Array( 8 );

	it( 'lays out 4x4x4 probes (the paper\'s Basic grid), x fastest, with 3x3x3 = 27 boxes between them', () => {

		expect( grid.probeCount ).toBe( 64 );
		expect( grid.cellCount ).toBe( 27 );
		expect( Array.from( grid.positions.subarray( 0, 6 ) ) ).toEqual( [ - 2, 0, 1, - 2 + 4 / 3, 0, 1 ] );
		expect( Array.from( grid.positions.subarray( 3 * 63 ) ) ).toEqual( [ 2, 3, 4 ] );

	} );

	it( 'reproduces a trilinear field exactly and weights sum to 1', () => {

		// Trilinear interpolation is exact for f = a + bx + cy + dz + exy + fyz + gxz + hxyz.
		const f = ( x: number, y: number, z: number ) => 0.5 + x - 2 * y + 0.3 * z +
			0.7 * x * y - 0.2 * y * z + 0.1 * x * z + 0.05 * x * y * z;
		const random = seededRandom( 4 );
		for ( let q = 0; q < 5000; q ++ ) {

			const x = - 2 + 4 * random(), y = 3 * random(), z = 1 + 3 * random();
			grid.interpolate( x, y, z, indices, weights );
			let value = 0, sum = 0;
			for ( let k = 0; k < 8; k ++ ) {

				const v = indices[ k ];
				expect( weights[ k ] ).toBeGreaterThanOrEqual( 0 );
				sum += weights[ k ];
				value += weights[ k ] * f( grid.positions[ 3 * v ], grid.positions[ 3 * v + 1 ], grid.positions[ 3 * v + 2 ] );

			}

			expect( sum ).toBeCloseTo( 1, 12 );
			expect( value ).toBeCloseTo( f( x, y, z ), 9 );

		}

	} );

	it( 'clamps positions outside the box to its surface, and feeds blendSH', () => {

		const sh = new Float32Array( 27 * 64 );
		for ( let v = 0; v < 64; v ++ ) sh[ 27 * v ] = grid.positions[ 3 * v + 1 ]; // L00 = y of the probe
		const out = new Float32Array( 27 );
		grid.interpolate( 0.3, 100, 2, indices, weights );
		blendSH( indices, weights, sh, out );
		expect( out[ 0 ] ).toBeCloseTo( 3, 6 );
		grid.interpolate( 0.3, - 100, 2, indices, weights );
		expect( blendSH( indices, weights, sh, out )[ 0 ] ).toBeCloseTo( 0, 6 );

	} );

	it( 'rejects bad boxes and counts by name', () => {

		expect( () => new GridInterpolator( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 1, 4, 4 ] ) ).toThrow( /counts\[0\] must be an integer in 2\.\./ );
		expect( () => new GridInterpolator( [ 0, 0, 0 ], [ 1, 0, 1 ], [ 4, 4, 4 ] ) ).toThrow( /max\[1\] \(0\) must be greater than min\[1\]/ );
		expect( () => new GridInterpolator( [ 0, NaN, 0 ], [ 1, 1, 1 ], [ 4, 4, 4 ] ) ).toThrow( /min\[1\] is NaN/ );
		expect( () => new GridInterpolator( [ 0, 0 ], [ 1, 1, 1 ], [ 4, 4, 4 ] ) ).toThrow( /min must have 3 entries/ );

	} );

} );
