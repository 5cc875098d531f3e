import { describe, expect, it } from 'vitest';
import { placeGrid } from '../../src/placement/placeGrid.js';
import { GridInterpolator } from '../../src/interpolation/GridInterpolator.js';

describe( 'placeGrid', () => {

	const min = [ - 2, 0.5, 1 ], max = [ 4, 3, 2 ], counts = [ 4, 3, 2 ];
	const positions = placeGrid( min, max, counts );

	it( 'places nx · ny · nz probes, 3 floats each', () => {

		expect( positions ).toBeInstanceOf( Float64Array );
		expect( positions.length ).toBe( 3 * 4 * 3 * 2 );

	} );

	it( 'puts probe (i, j, k) at min + (i, j, k) · (max − min) / (counts − 1), x fastest', () => {

		// The definition of a regular grid, written out independently of GridInterpolator.
		const step = [ 0, 1, 2 ].map( ( a ) => ( max[ a ] - min[ a ] ) / ( counts[ a ] - 1 ) );
		let index = 0;
		for ( let k = 0; k < counts[ 2 ]; k ++ ) for ( let j = 0; j < counts[ 1 ]; j ++ ) {

			for ( let i = 0; i < counts[ 0 ]; i ++, index ++ ) {

				expect( positions[ 3 * index ] ).toBeCloseTo( min[ 0 ] + i * step[ 0 ], 12 );
				expect( positions[ 3 * index + 1 ] ).toBeCloseTo( min[ 1 ] + j * step[ 1 ], 12 );
				expect( positions[ 3 * index + 2 ] ).toBeCloseTo( min[ 2 ] + k * step[ 2 ], 12 );

			}

		}

	} );

	it( 'has the box corners exactly at the first, last and axis-end probes', () => {

		// Exact (not just close): a probe meant to sit on a wall must not drift into it by rounding.
		const at = ( i: number, j: number, k: number ) => Array.from(
			positions.subarray( 3 * ( i + 4 * ( j + 3 * k ) ), 3 * ( i + 4 * ( j + 3 * k ) ) + 3 )
		);
		expect( at( 0, 0, 0 ) ).toEqual( min );
		expect( at( 3, 2, 1 ) ).toEqual( max );
		expect( at( 3, 0, 0 ) ).toEqual( [ max[ 0 ], min[ 1 ], min[ 2 ] ] );
		expect( at( 0, 2, 0 ) ).toEqual( [ min[ 0 ], max[ 1 ], min[ 2 ] ] );
		expect( at( 0, 0, 1 ) ).toEqual( [ min[ 0 ], min[ 1 ], max[ 2 ] ] );

	} );

	it( 'uses GridInterpolator\'s probe order, so a placed grid can be interpolated trilinearly as is', () => {

		// At each probe position the trilinear weights must put all weight on that probe's index.
		const grid = new GridInterpolator( min, max, counts );
		const indices = new Uint32Array( 8 ), weights = new Float64Array( 8 );
		for ( let v = 0; v < positions.length / 3; v ++ ) {

			grid.interpolate( positions[ 3 * v ], positions[ 3 * v + 1 ], positions[ 3 * v + 2 ], indices, weights );
			let weightOnV = 0;
			for ( let k = 0; k < 8; k ++ ) if ( indices[ k ] === v ) weightOnV += weights[ k ];
			expect( weightOnV ).toBeCloseTo( 1, 12 );

		}

	} );

	it( 'rejects bad boxes and counts, naming placeGrid and the argument', () => {

		expect( () => placeGrid( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 1, 2, 2 ] ) ).toThrow( /^placeGrid: counts\[0\] must be an integer in 2\.\./ );
		expect( () => placeGrid( [ 0, 0, 0 ], [ 1, 0, 1 ], [ 2, 2, 2 ] ) ).toThrow( /^placeGrid: max\[1\] \(0\) must be greater than min\[1\]/ );
		expect( () => placeGrid( [ 0, NaN, 0 ], [ 1, 1, 1 ], [ 2, 2, 2 ] ) ).toThrow( /^placeGrid: min\[1\] is NaN/ );
		expect( () => placeGrid( [ 0, 0 ], [ 1, 1, 1 ], [ 2, 2, 2 ] ) ).toThrow( /^placeGrid: min must have 3 entries/ );
		expect( () => placeGrid( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 2, 2.5, 2 ] ) ).toThrow( /^placeGrid: counts\[1\]/ );

	} );

} );
