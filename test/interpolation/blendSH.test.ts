import { describe, expect, it } from 'vitest';
import { blendSH } from '../../src/math.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

describe( 'blendSH', () => {

	it( 'equals Σ w_k · SH(probe_k), computed here coefficient by coefficient, for 1 to 9 weights (the 4 and 8 fast paths included)', () => {

		const random = mulberry32( 5 );
		const probes = 20, sh = Float32Array.from( { length: 27 * probes }, () => random() * 4 - 1 );
		for ( let count = 1; count <= 9; count ++ ) {

			const indices = Array.from( { length: count }, () => Math.floor( random() * probes ) );
			const weights = Array.from( { length: count }, () => random() );
			const out = blendSH( indices, weights, sh, new Float64Array( 27 ) );
			for ( let i = 0; i < 27; i ++ ) {

				let expected = 0;
				for ( let k = 0; k < count; k ++ ) expected += weights[ k ] * sh[ 27 * indices[ k ] + i ];
				expect( out[ i ] ).toBeCloseTo( expected, 12 );

			}

		}

	} );

	it( 'names an index that is not a probe', () => {

		expect( () => blendSH( [ 0, 1, 2, 3, 4, 5, 6, 99 ], new Array( 8 ).fill( 0.125 ), new Float32Array( 27 * 10 ), new Float32Array( 27 ) ) ).toThrow( /indices\[7\] = 99/ );

	} );

} );
