/**
 * The experiment's plot: an SVG string (run.ts rasterises it to PNG in the same headless Chromium).
 */

import type { LayoutResult } from './evaluate.js';
import type { ExperimentResult } from './report.js';

/** Options of {@link plotSVG}. */
export interface PlotOptions { title: string; width?: number; height?: number }

const COLORS = {
	grid: '#d62728', gridTet: '#ff7f0e', gridFit: '#e377c2', auto: '#1f77b4', greedy: '#9467bd', greedyFit: '#17becf', swaps: '#555500',
	hand: '#2ca02c', handFit: '#98df8a', dense: '#8c564b', paper: '#000000', guide: '#777777',
};

/** One curve: its rows, colour, marker, and whether it is a gradient curve (dashed line, open marker). */
interface Series { rows: LayoutResult[]; color: string; shape: string; gradients: boolean; dash?: string }

/**
 * The answer to the claim in one picture: mean (left) and 95th-percentile (right) error (log scale)
 * against probe count (log scale) — captured probes: grid curves (trilinear, and the same grids
 * tetrahedralized), the two captured automatic curves, the hand-made layout; fitted probes: the
 * fitted grids and the fitted automatic curves, plain (solid line, filled markers) and with
 * gradients (dashed, open markers); the paper's grid ringed, the layouts judged ringed in their
 * colour, the 20 % budget and the paper's grid's error as dashed guides. The walkable-region
 * layouts are left out (they are judged where characters go, not over the volume).
 */
export function plotSVG( result: Pick<ExperimentResult, 'layouts' | 'paper' | 'verdict'> & Partial<Pick<ExperimentResult, 'targets'>>, options: PlotOptions ): string {

	const width = options.width ?? 1200, height = options.height ?? 640;
	const panels: { key: 'meanError' | 'p95Error'; label: string }[] = [
		{ key: 'meanError', label: 'mean error' },
		{ key: 'p95Error', label: '95th-percentile error' },
	];
	const top = 134, bottom = 64, left = 78, gap = 90, right = 24;
	const panelWidth = ( width - left - right - gap ) / 2, panelHeight = height - top - bottom;
	const layouts = result.layouts.filter( ( row ) => ! row.region );
	const probes = layouts.map( ( row ) => row.probes );
	const headlineName = result.verdict.auto?.name;
	const targetName = result.targets?.find( ( check ) => check.id === 'auto' )?.layout ?? null;
	const xMin = Math.pow( 10, Math.floor( Math.log10( Math.min( ...probes ) * 0.8 ) * 4 ) / 4 );
	const xMax = Math.pow( 10, Math.ceil( Math.log10( Math.max( ...probes ) * 1.25 ) * 4 ) / 4 );
	const out: string[] = [];
	out.push( `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="DejaVu Sans, Arial, sans-serif">` );
	out.push( `<rect width="${width}" height="${height}" fill="#ffffff"/>` );
	out.push( `<text x="${width / 2}" y="28" font-size="20" font-weight="bold" text-anchor="middle">${escape( options.title )}</text>` );

	// Legend, across the top: three rows of four.
	const legend: [ string, string, string, 'solid' | 'dashed' | 'none' ][] = [
		[ 'grid, trilinear', COLORS.grid, 'square', 'solid' ],
		[ 'same grid, tetrahedralized', COLORS.gridTet, 'diamond', 'dashed' ],
		[ 'automatic: reduceProbes', COLORS.auto, 'circle', 'solid' ],
		[ 'automatic: mean-greedy', COLORS.greedy, 'hexagon', 'solid' ],
		[ 'grid, fitted', COLORS.gridFit, 'square', 'solid' ],
		[ 'automatic: greedy-fit', COLORS.greedyFit, 'circle', 'solid' ],
		[ 'automatic: greedy-fit + swaps', COLORS.swaps, 'circle', 'solid' ],
		[ 'dashed, open: + gradients', '#444444', 'open-circle', 'dashed' ],
		[ 'hand-made: captured, fitted', COLORS.hand, 'triangle-pair', 'none' ],
		[ 'hand-made, fitted + gradients', COLORS.hand, 'open-triangle', 'none' ],
		[ 'all dense candidates', COLORS.dense, 'cross', 'none' ],
		[ "paper's grid", COLORS.paper, 'ring', 'none' ],
	];
	legend.forEach( ( [ label, color, shape, line ], i ) => {

		const lx = left + ( i % 4 ) * ( ( width - left - right ) / 4 ), ly = 52 + 22 * Math.floor( i / 4 );
		if ( line !== 'none' ) out.push( `<line x1="${lx}" y1="${ly}" x2="${lx + 30}" y2="${ly}" stroke="${color}" stroke-width="2.5"${line === 'dashed' ? ' stroke-dasharray="6 4"' : ''}/>` );
		if ( shape === 'triangle-pair' ) out.push( marker( 'triangle', lx + 7, ly, COLORS.hand ), marker( 'triangle', lx + 23, ly, COLORS.handFit ) );
		else out.push( marker( shape, lx + 15, ly, color ) );
		out.push( `<text x="${lx + 38}" y="${ly + 5}" font-size="14">${escape( label )}</text>` );

	} );

	const fittedAuto = ( method: string, gradients: boolean ) => layouts.filter( ( row ) => row.kind === 'auto' && row.method === method && row.gradients === gradients );
	const fittedGrid = ( gradients: boolean ) => layouts.filter( ( row ) => row.kind === 'grid' && row.fitted && row.gradients === gradients );
	const series: Series[] = [
		{ rows: layouts.filter( ( row ) => row.kind === 'grid' && ! row.fitted && row.interpolation === 'trilinear' ), color: COLORS.grid, shape: 'square', gradients: false },
		{ rows: layouts.filter( ( row ) => row.kind === 'grid' && ! row.fitted && row.interpolation === 'tetrahedral' ), color: COLORS.gridTet, shape: 'diamond', gradients: false, dash: '6 4' },
		{ rows: layouts.filter( ( row ) => row.kind === 'auto' && row.method === 'reduceProbes' ), color: COLORS.auto, shape: 'circle', gradients: false },
		{ rows: layouts.filter( ( row ) => row.kind === 'auto' && row.method === 'mean-greedy' ), color: COLORS.greedy, shape: 'hexagon', gradients: false },
		{ rows: fittedGrid( false ), color: COLORS.gridFit, shape: 'square', gradients: false },
		{ rows: fittedGrid( true ), color: COLORS.gridFit, shape: 'square', gradients: true },
		{ rows: fittedAuto( 'greedy-fit', false ), color: COLORS.greedyFit, shape: 'circle', gradients: false },
		{ rows: fittedAuto( 'greedy-fit', true ), color: COLORS.greedyFit, shape: 'circle', gradients: true },
		{ rows: fittedAuto( 'greedy-fit + swaps', false ), color: COLORS.swaps, shape: 'circle', gradients: false },
		{ rows: fittedAuto( 'greedy-fit + swaps', true ), color: COLORS.swaps, shape: 'circle', gradients: true },
	];

	for ( let p = 0; p < panels.length; p ++ ) {

		const { key, label } = panels[ p ];
		const x0 = left + p * ( panelWidth + gap ), y0 = top;
		const values = layouts.map( ( row ) => row[ key ] ).filter( ( v ) => v > 0 );
		const yMin = Math.pow( 10, Math.floor( Math.log10( Math.min( ...values ) * 0.85 ) * 4 ) / 4 );
		const yMax = Math.pow( 10, Math.ceil( Math.log10( Math.max( ...values ) * 1.15 ) * 4 ) / 4 );
		const sx = ( n: number ) => x0 +
			( Math.log10( n ) - Math.log10( xMin ) ) / ( Math.log10( xMax ) - Math.log10( xMin ) ) * panelWidth;
		const sy = ( e: number ) => y0 + panelHeight -
			( Math.log10( Math.max( e, yMin ) ) - Math.log10( yMin ) ) / ( Math.log10( yMax ) - Math.log10( yMin ) ) * panelHeight;

		// Axes and grid lines.
		out.push( `<rect x="${x0}" y="${y0}" width="${panelWidth}" height="${panelHeight}" fill="none" stroke="#333" stroke-width="1"/>` );
		for ( const tick of logTicks( yMin, yMax ) ) {

			out.push( `<line x1="${x0}" y1="${sy( tick )}" x2="${x0 + panelWidth}" y2="${sy( tick )}" stroke="#e4e4e4"/>` );
			out.push( `<text x="${x0 - 8}" y="${sy( tick ) + 5}" font-size="13" text-anchor="end">${formatPercent( tick )}</text>` );

		}

		for ( const tick of logTicks( xMin, xMax ) ) {

			out.push( `<line x1="${sx( tick )}" y1="${y0}" x2="${sx( tick )}" y2="${y0 + panelHeight}" stroke="#e4e4e4"/>` );
			out.push( `<text x="${sx( tick )}" y="${y0 + panelHeight + 20}" font-size="13" text-anchor="middle">${tick}</text>` );

		}

		out.push( `<text x="${x0 + panelWidth / 2}" y="${height - 18}" font-size="15" text-anchor="middle">probes (log scale)</text>` );
		out.push( `<text transform="translate(${x0 - 58} ${y0 + panelHeight / 2}) rotate(-90)" font-size="15" text-anchor="middle">${label} (log scale)</text>` );

		// Guides: the budget (20 % of the paper's grid) and the paper's grid's error.
		const gridRow = layouts.find( ( row ) => row.kind === 'grid' && ! row.fitted && row.interpolation === 'trilinear' && row.probes === result.paper.gridProbes );
		const budget = result.verdict.budget;
		if ( budget >= xMin && budget <= xMax ) {

			out.push( `<line x1="${sx( budget )}" y1="${y0}" x2="${sx( budget )}" y2="${y0 + panelHeight}" stroke="${COLORS.guide}" stroke-width="1.5" stroke-dasharray="5 4"/>` );
			out.push( `<text x="${sx( budget ) + 5}" y="${y0 + 16}" font-size="12" fill="#444">20 % of paper's grid (${budget})</text>` );

		}

		if ( gridRow ) {

			out.push( `<line x1="${x0}" y1="${sy( gridRow[ key ] )}" x2="${x0 + panelWidth}" y2="${sy( gridRow[ key ] )}" stroke="${COLORS.guide}" stroke-width="1.5" stroke-dasharray="2 3"/>` );
			// Named in the top right corner, which the falling curves leave free.
			out.push( `<text x="${x0 + panelWidth - 6}" y="${y0 + 34}" font-size="12" fill="#444" text-anchor="end">dotted: paper's grid ${result.paper.gridCounts.join( 'x' )}: ${formatPercent( gridRow[ key ] )}</text>` );

		}

		for ( const { rows, color, shape, gradients, dash } of series ) {

			const sorted = rows.slice().sort( ( a, b ) => a.probes - b.probes );
			const lineDash = gradients ? '6 4' : dash;
			if ( sorted.length > 1 ) out.push( `<polyline fill="none" stroke="${color}" stroke-width="2.5"${lineDash ? ` stroke-dasharray="${lineDash}"` : ''} points="${sorted.map( ( row ) => `${sx( row.probes ).toFixed( 1 )},${sy( row[ key ] ).toFixed( 1 )}` ).join( ' ' )}"/>` );
			for ( const row of sorted ) out.push( marker( gradients ? `open-${shape}` : shape, sx( row.probes ), sy( row[ key ] ), color ) );

		}

		for ( const row of layouts.filter( ( r ) => r.kind === 'hand' ) ) {

			const shape = row.gradients ? 'open-triangle' : 'triangle';
			out.push( marker( shape, sx( row.probes ), sy( row[ key ] ), row.fitted && ! row.gradients ? COLORS.handFit : COLORS.hand ) );
			if ( ! row.fitted ) out.push( `<text x="${sx( row.probes ) - 10}" y="${sy( row[ key ] ) - 14}" font-size="12" fill="${COLORS.hand}" text-anchor="end">hand ${row.probes}</text>` );

		}

		for ( const row of layouts.filter( ( r ) => r.kind === 'dense' ) ) {

			out.push( marker( 'cross', sx( row.probes ), sy( row[ key ] ), COLORS.dense ) );
			out.push( `<text x="${sx( row.probes ) + 4}" y="${sy( row[ key ] ) - 12}" font-size="12" fill="${COLORS.dense}" text-anchor="middle">all ${row.probes}</text>` );

		}

		if ( gridRow ) out.push( marker( 'ring', sx( gridRow.probes ), sy( gridRow[ key ] ), COLORS.paper ) );
		const marks: [ string | null | undefined, string ][] = [ [ headlineName, 'paper\'s claim' ], [ targetName, 'target' ] ];
		marks.forEach( ( [ name, text ], m ) => {

			const row = name ? layouts.find( ( r ) => r.name === name ) : undefined;
			if ( ! row ) return;
			const color = colorOf( row );
			out.push( `<circle cx="${sx( row.probes ).toFixed( 1 )}" cy="${sy( row[ key ] ).toFixed( 1 )}" r="11" fill="none" stroke="${color}" stroke-width="2"/>` );
			out.push( `<text x="${sx( row.probes ) + 14}" y="${sy( row[ key ] ) + ( m === 0 ? - 10 : 26 )}" font-size="12" fill="${color}">${escape( text )}: ${row.probes}</text>` );

		} );

	}

	out.push( '</svg>' );
	return out.join( '\n' );

}

/** The colour of a row's curve. */
function colorOf( row: LayoutResult ): string {

	if ( row.kind === 'grid' ) return row.fitted ? COLORS.gridFit : row.interpolation === 'trilinear' ? COLORS.grid : COLORS.gridTet;
	if ( row.kind === 'hand' ) return COLORS.hand;
	if ( row.kind === 'dense' ) return COLORS.dense;
	return row.method === 'mean-greedy' ? COLORS.greedy : row.method === 'greedy-fit' ? COLORS.greedyFit : row.method === 'greedy-fit + swaps' ? COLORS.swaps : COLORS.auto;

}

function marker( shape: string, x: number, y: number, color: string ): string {

	const r = 5.5;
	if ( shape.startsWith( 'open-' ) ) {

		// The filled marker's outline on white: a gradient layout.
		const filled = marker( shape.slice( 5 ), x, y, color );
		return filled.replace( `fill="${color}"`, `fill="#ffffff" stroke="${color}" stroke-width="2"` );

	}

	switch ( shape ) {

		case 'square': return `<rect x="${( x - r ).toFixed( 1 )}" y="${( y - r ).toFixed( 1 )}" width="${2 * r}" height="${2 * r}" fill="${color}"/>`;
		case 'diamond': return `<polygon points="${x.toFixed( 1 )},${( y - r - 1.5 ).toFixed( 1 )} ${( x + r + 1.5 ).toFixed( 1 )},${y.toFixed( 1 )} ${x.toFixed( 1 )},${( y + r + 1.5 ).toFixed( 1 )} ${( x - r - 1.5 ).toFixed( 1 )},${y.toFixed( 1 )}" fill="#fff" stroke="${color}" stroke-width="2"/>`;
		case 'triangle': return `<polygon points="${x.toFixed( 1 )},${( y - r - 2 ).toFixed( 1 )} ${( x + r + 1 ).toFixed( 1 )},${( y + r ).toFixed( 1 )} ${( x - r - 1 ).toFixed( 1 )},${( y + r ).toFixed( 1 )}" fill="${color}"/>`;
		case 'hexagon': return `<polygon points="${[ 0, 1, 2, 3, 4, 5 ].map( ( k ) => `${( x + ( r + 1 ) * Math.cos( k * Math.PI / 3 ) ).toFixed( 1 )},${( y + ( r + 1 ) * Math.sin( k * Math.PI / 3 ) ).toFixed( 1 )}` ).join( ' ' )}" fill="${color}"/>`;
		case 'cross': return `<path d="M${x - r - 1},${y - r - 1} L${x + r + 1},${y + r + 1} M${x - r - 1},${y + r + 1} L${x + r + 1},${y - r - 1}" stroke="${color}" stroke-width="3"/>`;
		case 'ring': return `<circle cx="${x.toFixed( 1 )}" cy="${y.toFixed( 1 )}" r="${r + 5}" fill="none" stroke="${color}" stroke-width="2"/>`;
		default: return `<circle cx="${x.toFixed( 1 )}" cy="${y.toFixed( 1 )}" r="${r}" fill="${color}"/>`;

	}

}

/** 1, 2, 5 × 10^k within [min, max]. */
export function logTicks( min: number, max: number ): number[] {

	const out: number[] = [];
	for ( let k = Math.floor( Math.log10( min ) ); k <= Math.ceil( Math.log10( max ) ); k ++ ) {

		for ( const m of [ 1, 2, 5 ] ) {

			const v = +( m * Math.pow( 10, k ) ).toPrecision( 6 );
			if ( v >= min * ( 1 - 1e-9 ) && v <= max * ( 1 + 1e-9 ) ) out.push( v );

		}

	}

	return out;

}

function formatPercent( value: number ): string {

	return `${+( 100 * value ).toPrecision( 3 )} %`;

}

function escape( text: string ): string {

	return text.replace( /&/g, '&amp;' ).replace( /</g, '&lt;' ).replace( />/g, '&gt;' );

}
