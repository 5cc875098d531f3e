import { describe, expect, it } from 'vitest';
import type { LayoutResult } from '../../scripts/experiment/evaluate.js';
import { checkTargets, equalStorage, selectionScore } from '../../scripts/experiment/targets.js';

const PAPER = { gridCounts: [ 4, 4, 4 ], gridProbes: 64, handProbes: 13, boxes: 27, tetrahedra: 14 };

/** A row; `cv` set makes it a fitted row with that cross-validation error. */
function row( name: string, kind: LayoutResult[ 'kind' ], probes: number, meanError: number, extra: Partial<LayoutResult> & { cv?: number } = {} ): LayoutResult {

	const { cv, ...rest } = extra;
	return {
		name, kind, interpolation: kind === 'grid' ? 'trilinear' : 'tetrahedral', probes, cells: probes, meanError, p95Error: 2 * meanError,
		maxError: 3 * meanError, captureMs: 1, probesNotInOpenSpace: 0, fitted: cv !== undefined, gradients: false,
		shFloats: ( rest.gradients ? 108 : 27 ) * probes, bakeCaptures: probes,
		...( cv !== undefined ? { fit: { samples: 100, lambda: 0.1, gradientLambda: 0, crossValidationError: cv, ms: 1 } } : {} ),
		...rest,
	};

}

const ROWS: LayoutResult[] = [
	row( 'grid 4x4x4', 'grid', 64, 0.08 ),
	row( 'grid 4x4x4, fitted', 'grid', 64, 0.06, { cv: 0.07 } ),
	row( 'grid 4x4x4, fitted + gradients', 'grid', 64, 0.016, { cv: 0.02, gradients: true } ),
	row( 'hand', 'hand', 13, 0.29 ),
	row( 'hand, fitted', 'hand', 13, 0.18, { cv: 0.2 } ),
	row( 'hand, fitted + gradients', 'hand', 13, 0.077, { cv: 0.09, gradients: true } ),
	row( 'automatic 12 (reduceProbes)', 'auto', 12, 0.3, { method: 'reduceProbes', fitSetError: 0.28 } ),
	// Chosen by its cross-validation error although another one is better on the truth: the choice never looks at it.
	row( 'automatic 12 (greedy-fit, gradients)', 'auto', 12, 0.07, { method: 'greedy-fit', gradients: true, cv: 0.05 } ),
	row( 'automatic 12 (greedy-fit + swaps, gradients)', 'auto', 12, 0.05, { method: 'greedy-fit + swaps', gradients: true, cv: 0.06 } ),
	row( 'automatic 12 (greedy-fit + swaps)', 'auto', 12, 0.15, { method: 'greedy-fit + swaps', cv: 0.16 } ),
	row( 'automatic 10 (greedy-fit + swaps, gradients)', 'auto', 10, 0.01, { method: 'greedy-fit + swaps', gradients: true, cv: 0.01 } ),
	row( 'automatic 12 (greedy-fit + swaps, gradients, walkable)', 'auto', 12, 0.001, { method: 'greedy-fit + swaps', gradients: true, cv: 0.001, region: 'walkable' } ),
	row( 'automatic 48 (greedy-fit + swaps)', 'auto', 48, 0.06, { method: 'greedy-fit + swaps', cv: 0.06, meanErrorWalkable: 0.05 } ),
	row( 'automatic 64 (greedy-fit + swaps, gradients)', 'auto', 64, 0.03, { method: 'greedy-fit + swaps', gradients: true, cv: 0.03 } ),
];

describe( 'experiment: targets', () => {

	it( 'judges the layout chosen without the ground truth, at the largest count allowed, and names the one best on it', () => {

		const checks = checkTargets( ROWS, PAPER, { autoProbes: 12, autoError: 'grid', handFitted: 0.08, plainFitted: 0.155, gridCountRatio: 0.8 } );
		const [ auto, hand, plain, gridCount ] = checks;
		expect( checks.map( ( c ) => c.id ) ).toEqual( [ 'auto', 'hand-fitted', 'plain-fitted', 'grid-count' ] );
		// 12 probes, not the 10 that is better; the walkable layout is not a whole-volume candidate.
		expect( auto.layout ).toBe( 'automatic 12 (greedy-fit, gradients)' );
		expect( auto.value ).toBe( 0.07 );
		expect( auto.limit ).toBe( 0.08 );
		expect( auto.holds ).toBe( true );
		expect( auto.bestOnTruth ).toEqual( { layout: 'automatic 12 (greedy-fit + swaps, gradients)', value: 0.05 } );
		expect( auto.text ).toBe( 'an automatic layout of ≤ 12 probes at ≤ the captured grid\'s 8.0 %' );
		expect( [ hand.layout, hand.holds ] ).toEqual( [ 'hand, fitted + gradients', true ] );
		expect( [ plain.layout, plain.value, plain.holds ] ).toEqual( [ 'automatic 12 (greedy-fit + swaps)', 0.15, true ] );
		expect( gridCount.layout ).toBe( 'grid 4x4x4, fitted + gradients' );
		expect( gridCount.value ).toBeCloseTo( 0.2, 12 );
		expect( gridCount.holds ).toBe( true );

	} );

	it( 'fails a target whose judged layout is above its bound, or when none was measured', () => {

		const worse = ROWS.map( ( r ) => r.name === 'automatic 12 (greedy-fit, gradients)' ? { ...r, meanError: 0.09 } : r );
		const [ auto ] = checkTargets( worse, PAPER, { autoProbes: 12, autoError: 0.085, gridCountRatio: 0.8 } );
		expect( [ auto.value, auto.limit, auto.holds ] ).toEqual( [ 0.09, 0.085, false ] );
		const none = checkTargets( ROWS.filter( ( r ) => r.kind !== 'auto' ), PAPER, { autoProbes: 12, autoError: 0.5, gridCountRatio: 0.1 } );
		expect( none[ 0 ] ).toMatchObject( { layout: null, value: null, holds: false, bestOnTruth: null } );
		expect( none[ 1 ] ).toMatchObject( { id: 'grid-count', holds: false } );
		expect( () => checkTargets( ROWS.slice( 1 ), PAPER, { autoProbes: 12, autoError: 'grid', gridCountRatio: 0.8 } ) ).toThrow( /no captured trilinear grid of 64/ );

	} );

	it( 'scores by the cross-validation error, else the fit-set error', () => {

		expect( selectionScore( ROWS[ 1 ] ) ).toBe( 0.07 );
		expect( selectionScore( ROWS[ 6 ] ) ).toBe( 0.28 );
		expect( selectionScore( ROWS[ 0 ] ) ).toBe( Infinity );

	} );

	it( 'pairs gradient layouts of N probes with plain fitted ones of 4N', () => {

		const [ pair, missing ] = equalStorage( ROWS, [ [ 12, 48 ], [ 16, 64 ] ] );
		expect( pair.gradient ).toEqual( { layout: 'automatic 12 (greedy-fit, gradients)', probes: 12, shFloats: 1296, meanError: 0.07 } );
		expect( pair.plain ).toEqual( { layout: 'automatic 48 (greedy-fit + swaps)', probes: 48, shFloats: 1296, meanError: 0.06, meanErrorWalkable: 0.05 } );
		expect( missing.gradient ).toBe( null );
		expect( missing.plain ).toBe( null );

	} );

} );
