import { describe, expect, it } from 'vitest';
import { placeGrid, reduceProbes } from '../../src/index.js';
import { selectByMeanError } from '../../scripts/experiment/selectByMeanError.js';

/** Grey SH whose L00 has a bright spot at (1, 1, 1) on top of a linear ramp. */
function spotField( positions: ArrayLike<number> ): Float32Array {

	const count = positions.length / 3, sh = new Float32Array( 27 * count );
	for ( let p = 0; p < count; p ++ ) {

		const x = positions[ 3 * p ], y = positions[ 3 * p + 1 ], z = positions[ 3 * p + 2 ];
		sh.fill( 1 + 0.1 * x + 3 * Math.exp( - ( ( x - 1 ) ** 2 + ( y - 1 ) ** 2 + ( z - 1 ) ** 2 ) / 0.3 ), 27 * p, 27 * p + 3 );

	}

	return sh;

}

describe( 'experiment: mean-greedy selection', () => {

	it( 'starts from the given set, adds one probe per step, never repeats one, and lowers the dense mean error', () => {

		const positions = placeGrid( [ - 2, - 2, - 2 ], [ 2, 2, 2 ], [ 7, 7, 7 ] );
		const sh = spotField( positions );
		const reduced = reduceProbes( positions, sh, { targetCount: 20 } );
		const start = reduced.order.subarray( 0, reduced.history.count[ 0 ] );
		const selected = selectByMeanError( positions, sh, { start, targetCount: 20, candidatesPerStep: 16 } );
		expect( selected.order.length ).toBe( 20 );
		expect( Array.from( selected.order.subarray( 0, start.length ) ) ).toEqual( Array.from( start ) );
		expect( new Set( selected.order ).size ).toBe( 20 );
		expect( selected.mean.length ).toBe( 20 - start.length + 1 );
		expect( selected.mean[ selected.mean.length - 1 ] ).toBeLessThan( selected.mean[ 0 ] );
		// It picks by the mean, so at the same size it is at least as good as reduceProbes on it.
		const reducedMean = reduced.history.mean[ reduced.history.mean.length - 1 ];
		expect( selected.mean[ selected.mean.length - 1 ] ).toBeLessThanOrEqual( reducedMean + 1e-12 );
		expect( () => selectByMeanError( positions, sh, { start, targetCount: 3 } ) ).toThrow( /targetCount 3/ );

	} );

} );
