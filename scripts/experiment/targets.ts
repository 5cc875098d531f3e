/**
 * Issue 14's targets on one scene's rows, and the equal-storage comparison. Where a target speaks
 * of "an automatic layout" or "the best fitted layout", the layout judged is chosen without the
 * ground truth: of the candidates (at the largest count allowed), the one with the lowest
 * cross-validation error of its fit (held-out fit samples), else its error over the fit samples.
 * Each check also names the candidate that is best on the ground truth, so a wrong choice shows.
 */

import type { SceneTargets } from './config.js';
import type { LayoutResult, PaperFigures } from './evaluate.js';

/** One target, checked. */
export interface TargetCheck {

	/** Short id: 'auto', 'hand-fitted', 'plain-fitted', 'grid-count'. */
	id: string;
	/** The target in words. */
	text: string;
	/** The layout judged (chosen without the ground truth), or null when none was measured. */
	layout: string | null;
	/** Its mean error (for 'grid-count': its ratio to the captured grid's). */
	value: number | null;
	/** The bound. */
	limit: number;
	holds: boolean;
	/** Of the candidates, the one best on the ground truth, and its value. */
	bestOnTruth: { layout: string; value: number } | null;

}

/** One equal-storage pair: a gradient layout of N probes against a plain fitted one of 4N. */
export interface EqualStoragePair {

	gradient: { layout: string; probes: number; shFloats: number; meanError: number; meanErrorWalkable?: number } | null;
	plain: { layout: string; probes: number; shFloats: number; meanError: number; meanErrorWalkable?: number } | null;

}

/** The score a layout is chosen by, without the ground truth (lower is better). */
export function selectionScore( row: LayoutResult ): number {

	return row.fit?.crossValidationError ?? row.fitSetError ?? Infinity;

}

/** The paper's grid, captured, trilinear. */
export function capturedPaperGrid( rows: readonly LayoutResult[], paper: PaperFigures ): LayoutResult {

	const grid = rows.find( ( row ) => row.kind === 'grid' && ! row.fitted && row.interpolation === 'trilinear' && row.probes === paper.gridProbes );
	if ( ! grid ) throw new Error( `targets: no captured trilinear grid of ${paper.gridProbes} probes among the rows.` );
	return grid;

}

/** Checks the scene's targets on `rows` (one ground truth). */
export function checkTargets( rows: readonly LayoutResult[], paper: PaperFigures, targets: SceneTargets ): TargetCheck[] {

	const grid = capturedPaperGrid( rows, paper );
	const pct = ( v: number ) => `${( 100 * v ).toFixed( 1 )} %`;
	const wholeVolume = rows.filter( ( row ) => row.kind === 'auto' && ! row.region );
	const checks: TargetCheck[] = [];
	const autoLimit = targets.autoError === 'grid' ? grid.meanError : targets.autoError;
	checks.push( check(
		'auto', `an automatic layout of ≤ ${targets.autoProbes} probes at ≤ ${targets.autoError === 'grid' ? `the captured grid's ${pct( autoLimit )}` : pct( autoLimit )}`,
		atLargestCount( wholeVolume, targets.autoProbes ), autoLimit, ( row ) => row.meanError,
	) );
	if ( targets.handFitted !== undefined ) {

		checks.push( check( 'hand-fitted', `the hand-made layout, fitted, at ≤ ${pct( targets.handFitted )}`, rows.filter( ( row ) => row.kind === 'hand' && row.fitted ), targets.handFitted, ( row ) => row.meanError ) );

	}

	if ( targets.plainFitted !== undefined ) {

		const plain = atLargestCount( wholeVolume.filter( ( row ) => row.fitted && ! row.gradients ), targets.autoProbes );
		checks.push( check( 'plain-fitted', `a plain fitted automatic layout of ≤ ${targets.autoProbes} probes at ≤ ${pct( targets.plainFitted )}`, plain, targets.plainFitted, ( row ) => row.meanError ) );

	}

	const atGridCount = rows.filter( ( row ) => row.fitted && ! row.region && row.probes === paper.gridProbes );
	checks.push( check(
		'grid-count', `the best fitted layout of ${paper.gridProbes} probes at ≤ ${targets.gridCountRatio}× the captured grid's ${pct( grid.meanError )}`,
		atGridCount, targets.gridCountRatio, ( row ) => row.meanError / grid.meanError,
	) );
	return checks;

}

/** The candidates at the largest probe count ≤ `maxProbes` among them. */
function atLargestCount( rows: readonly LayoutResult[], maxProbes: number ): LayoutResult[] {

	const within = rows.filter( ( row ) => row.probes <= maxProbes );
	const largest = Math.max( ...within.map( ( row ) => row.probes ) );
	return within.filter( ( row ) => row.probes === largest );

}

function check(
	id: string, text: string, candidates: readonly LayoutResult[], limit: number, value: ( row: LayoutResult ) => number
): TargetCheck {

	if ( candidates.length === 0 ) return { id, text, layout: null, value: null, limit, holds: false, bestOnTruth: null };
	const chosen = [ ...candidates ].sort( ( a, b ) => selectionScore( a ) - selectionScore( b ) )[ 0 ];
	const best = [ ...candidates ].sort( ( a, b ) => value( a ) - value( b ) )[ 0 ];
	return {
		id, text, layout: chosen.name, value: value( chosen ), limit, holds: value( chosen ) <= limit,
		bestOnTruth: { layout: best.name, value: value( best ) },
	};

}

/**
 * Equal storage: for each [N, 4N], the gradient layout of N probes and the plain fitted one of 4N
 * (whole-volume fitted automatic layouts; of several at a count, the one chosen without the ground truth).
 */
export function equalStorage( rows: readonly LayoutResult[], pairs: readonly [ number, number ][] ): EqualStoragePair[] {

	const pick = ( probes: number, gradients: boolean ) => {

		const candidates = rows.filter( ( row ) => row.kind === 'auto' && row.fitted && ! row.region && row.gradients === gradients && row.probes === probes );
		if ( candidates.length === 0 ) return null;
		const row = [ ...candidates ].sort( ( a, b ) => selectionScore( a ) - selectionScore( b ) )[ 0 ];
		return {
			layout: row.name, probes: row.probes, shFloats: row.shFloats, meanError: row.meanError,
			...( row.meanErrorWalkable !== undefined ? { meanErrorWalkable: row.meanErrorWalkable } : {} ),
		};

	};

	return pairs.map( ( [ n, fourN ] ) => ( { gradient: pick( n, true ), plain: pick( fourN, false ) } ) );

}
