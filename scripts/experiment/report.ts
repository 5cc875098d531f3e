/**
 * Pure parts of the experiment's output: the result JSON, the Markdown report and the plot (an
 * SVG string; run.ts rasterises it to PNG in the same headless Chromium).
 */

import type { LayoutResult, PaperFigures, Verdict } from './evaluate.js';

/** The result file `DIR/<scene>.json`. */
export interface ExperimentResult {

	scene: string;
	/** Number of ground-truth sample points M. */
	samples: number;
	layouts: LayoutResult[];
	verdict: Verdict;
	paper: PaperFigures;
	/** How the ground truth was drawn. */
	groundTruth: {
		seed: number; region: { min: number[]; max: number[] }; minDistance: number; maxSky: number;
		drawn: number; rejectedNear: number; rejectedInside: number; rejectedOutside: number; captureMs: number; normals: number;
	};
	/** The dense candidate set the automatic reduction ran on. */
	dense: {
		seed: number; probes: number; fromGrid: number; fromVertices: number; captureMs: number; reduceMs: number;
		/** Mean error of each automatic cut over the dense set itself (what the reduction minimised). */
		denseMeanError: Record<string, number>;
		/** Largest |SH difference| between an automatic layout's own capture and the dense capture at the same points, relative to the largest L00. */
		recaptureMaxDifference: number;
	};
	capture: { resolution: number; near: number; far: number; type: string; solidAngle: string };
	environment: Record<string, string | number | boolean>;
	/** Total wall time of the run (ms). */
	runMs: number;

}

/** Checks the shape the issue asks for; returns the problems (empty when fine). */
export function validateResult( result: unknown ): string[] {

	const problems: string[] = [];
	const r = result as Record<string, unknown>;
	if ( typeof r !== 'object' || r === null ) return [ 'not an object' ];
	if ( typeof r.scene !== 'string' ) problems.push( 'scene must be a string' );
	if ( ! Number.isInteger( r.samples ) || ( r.samples as number ) <= 0 ) problems.push( 'samples must be a positive integer' );
	if ( ! Array.isArray( r.layouts ) || r.layouts.length === 0 ) return [ ...problems, 'layouts must be a non-empty array' ];
	( r.layouts as Record<string, unknown>[] ).forEach( ( row, i ) => {

		if ( typeof row.name !== 'string' || row.name === '' ) problems.push( `layouts[${i}].name must be a non-empty string` );
		if ( row.interpolation !== 'trilinear' && row.interpolation !== 'tetrahedral' ) problems.push( `layouts[${i}].interpolation must be "trilinear" or "tetrahedral"` );
		for ( const key of [ 'probes', 'cells' ] ) if ( ! Number.isInteger( row[ key ] ) || ( row[ key ] as number ) <= 0 ) problems.push( `layouts[${i}].${key} must be a positive integer` );
		for ( const key of [ 'meanError', 'p95Error', 'captureMs' ] ) if ( typeof row[ key ] !== 'number' || ! Number.isFinite( row[ key ] ) || ( row[ key ] as number ) < 0 ) problems.push( `layouts[${i}].${key} must be a finite number ≥ 0` );

	} );
	return problems;

}

const pct = ( value: number, digits = 1 ) => `${( 100 * value ).toFixed( digits )} %`;

/** The Markdown table of the layouts (the paper's Table 4 columns plus the errors). */
export function layoutTable( layouts: readonly LayoutResult[] ): string {

	const lines = [
		'| layout | interpolation | probes | cells | capture (ms) | mean error | p95 error | probes not in open space |',
		'|---|---|--:|--:|--:|--:|--:|--:|',
	];
	for ( const row of layouts ) {

		const cells = `${row.cells} ${row.interpolation === 'trilinear' ? 'boxes' : 'tetrahedra'}`;
		lines.push( `| ${row.name} | ${row.interpolation} | ${row.probes} | ${cells} | ${Math.round( row.captureMs )} | ${pct( row.meanError )} | ${pct( row.p95Error )} | ${row.probesNotInOpenSpace} |` );

	}

	return lines.join( '\n' );

}

/** `DIR/<scene>.md`: a short readable report. */
export function markdownReport( result: ExperimentResult, plotFile: string ): string {

	const { verdict: v, paper, groundTruth: gt, dense, capture } = result;
	const title = result.scene[ 0 ].toUpperCase() + result.scene.slice( 1 );
	const paperGrid = result.layouts.find( ( row ) => row.kind === 'grid' && row.interpolation === 'trilinear' && row.probes === paper.gridProbes );
	const paperGridTet = result.layouts.find( ( row ) => row.kind === 'grid' && row.interpolation === 'tetrahedral' && row.probes === paper.gridProbes );
	const hand = result.layouts.find( ( row ) => row.kind === 'hand' );
	const lines: string[] = [];
	lines.push( `# ${title}: the paper's claim, measured`, '' );
	lines.push( `**Claim** (paper, Table 4): arbitrary probes with tetrahedral interpolation light the scene as well as the ${paper.gridCounts.join( 'x' )} grid (${paper.gridProbes} probes, trilinear) with about 20 % of its probes (the paper's hand-placed layout: ${paper.handProbes}).`, '' );
	lines.push( `**Verdict: ${v.text}**`, '' );
	if ( v.hand ) lines.push( `The scene module's hand-made layout (${v.hand.probes} probes): mean error ${pct( v.hand.meanError )}, ${v.hand.ratio.toFixed( 2 )}× the grid's.`, '' );
	if ( v.fewestAutoMatchingGrid !== null ) lines.push( `Fewest automatically placed probes measured that match the grid's mean error: ${v.fewestAutoMatchingGrid} (${pct( v.fewestAutoMatchingGrid / v.grid.probes, 0 )} of the grid); its 95th percentile: ${v.fewestAutoMatchingGridP95 ?? 'none of those measured'}.`, '' );
	lines.push( layoutTable( result.layouts ), '' );
	lines.push( `![${title}: mean and 95th-percentile irradiance error vs probe count](${plotFile})`, '' );
	lines.push( '| Table 4 | grid probes | arbitrary probes | boxes (grid) | tetrahedra |', '|---|--:|--:|--:|--:|' );
	lines.push( `| paper | ${paper.gridProbes} | ${paper.handProbes} | ${paper.boxes} | ${paper.tetrahedra} |` );
	lines.push( `| here (grid; hand-made layout) | ${paperGrid?.probes ?? '–'} | ${hand?.probes ?? '–'} | ${paperGrid?.cells ?? '–'} | ${hand?.cells ?? '–'} |` );
	if ( v.auto ) {

		const auto = result.layouts.find( ( row ) => row.name === v.auto!.name );
		lines.push( `| here (grid; automatic ${v.auto.probes}) | ${paperGrid?.probes ?? '–'} | ${v.auto.probes} | ${paperGrid?.cells ?? '–'} | ${auto?.cells ?? '–'} |` );

	}

	if ( paperGridTet ) lines.push( '', `The paper's grid tetrahedralized: ${paperGridTet.cells} tetrahedra (a Delaunay tetrahedralization of a grid splits each box into 5–6).` );
	lines.push( '', '## How it was measured', '' );
	lines.push( `- **Error**: the library's \`irradianceError\`: per sample point, the mean over 26 normals of max over RGB |E_interp(n) − E_true(n)|, divided by the mean true irradiance over all samples, normals and channels; mean and 95th percentile over the ${result.samples} samples.` );
	lines.push( `- **Ground truth**: ${result.samples} points drawn uniformly (seed ${gt.seed}) in the scene module's grid box [${gt.region.min.join( ', ' )}] – [${gt.region.max.join( ', ' )}], keeping those in open space: no surface within ${gt.minDistance} m, at most 10 % of 32 rays first hitting the undrawn side of a surface (a cube camera there sees through walls)${gt.maxSky < 1 ? `, at most ${pct( gt.maxSky, 0 )} of the rays leaving the scene (a closed interior: the air above the roof is not part of it)` : ''}. ${gt.drawn} drawn: ${gt.rejectedNear} near a surface, ${gt.rejectedInside} inside geometry${gt.maxSky < 1 ? `, ${gt.rejectedOutside} outside the interior` : ''}. Each captured like a probe (${Math.round( gt.captureMs / 1000 )} s).` );
	lines.push( `- **Capture**: one \`ProbeCapturer\` for everything, ${capture.resolution}² per face, ${capture.type} targets, near ${capture.near}, far ${capture.far}, solid angle '${capture.solidAngle}'; the scene module's own build (geometry, materials${result.scene === 'basic' ? '' : ', textures, sun with its shadow map, sky dome'}, lights). Capture time: wall time of \`capture()\` for the layout's probes after a warm-up, ${result.environment.renderer}.` );
	lines.push( `- **Grids** over the scene module's grid box; trilinear with \`GridInterpolator\`, and the same captured probes tetrahedralized (\`createProbeInterpolator\`); both rows share one capture time.` );
	lines.push( `- **Automatic layouts**: \`reduceProbes\` (greedy insertion, mean error) on a dense candidate set captured separately — ${dense.probes} points in open space: a jittered grid (seed ${dense.seed}, ${dense.fromGrid} points) and vertex candidates (\`candidatesFromVertices\`, ${dense.fromVertices} points) — ${Math.round( dense.captureMs / 1000 )} s capture + ${( dense.reduceMs / 1000 ).toFixed( 1 )} s reduction. One run; each count is the prefix of its insertion order. Never reduced on the ground truth. Each cut was captured again as its own layout (capture time above); its SH equal the dense capture's to ${dense.recaptureMaxDifference.toExponential( 1 )} of the largest L00.` );
	lines.push( `- **Hand-made layout**: the scene module's (\`scenes/${result.scene}.json\`), tetrahedral.` );
	lines.push( `- Run: ${Math.round( result.runMs / 1000 )} s, ${result.environment.browser}.` );
	return lines.join( '\n' ) + '\n';

}

/** Options of {@link plotSVG}. */
export interface PlotOptions { title: string; width?: number; height?: number }

const COLORS = { grid: '#d62728', gridTet: '#ff7f0e', auto: '#1f77b4', hand: '#2ca02c', paper: '#000000', guide: '#777777' };

/**
 * The answer to the claim in one picture: mean (left) and 95th-percentile (right) error against
 * probe count (log scale) — grid curves (trilinear, and the same grids tetrahedralized), the
 * automatic tetrahedral curve, the hand-made layout, the paper's grid ringed, the 20 % budget and
 * the paper's grid's error as dashed guides.
 */
export function plotSVG( result: Pick<ExperimentResult, 'layouts' | 'paper' | 'verdict'>, options: PlotOptions ): string {

	const width = options.width ?? 1200, height = options.height ?? 560;
	const panels: { key: 'meanError' | 'p95Error'; label: string }[] = [
		{ key: 'meanError', label: 'mean error' },
		{ key: 'p95Error', label: '95th-percentile error' },
	];
	const top = 92, bottom = 64, left = 78, gap = 90, right = 24;
	const panelWidth = ( width - left - right - gap ) / 2, panelHeight = height - top - bottom;
	const probes = result.layouts.map( ( row ) => row.probes );
	const xMin = Math.pow( 10, Math.floor( Math.log10( Math.min( ...probes ) * 0.8 ) * 4 ) / 4 );
	const xMax = Math.pow( 10, Math.ceil( Math.log10( Math.max( ...probes ) * 1.25 ) * 4 ) / 4 );
	const out: string[] = [];
	out.push( `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="DejaVu Sans, Arial, sans-serif">` );
	out.push( `<rect width="${width}" height="${height}" fill="#ffffff"/>` );
	out.push( `<text x="${width / 2}" y="28" font-size="20" font-weight="bold" text-anchor="middle">${escape( options.title )}</text>` );

	// Legend, across the top.
	const legend: [ string, string, string, boolean ][] = [
		[ 'grid, trilinear', COLORS.grid, 'square', true ],
		[ 'same grid, tetrahedralized', COLORS.gridTet, 'diamond', true ],
		[ 'automatic (reduceProbes), tetrahedral', COLORS.auto, 'circle', true ],
		[ 'hand-made (scene module)', COLORS.hand, 'triangle', false ],
		[ "paper's grid", COLORS.paper, 'ring', false ],
	];
	let lx = left;
	for ( const [ label, color, shape, line ] of legend ) {

		if ( line ) out.push( `<line x1="${lx}" y1="56" x2="${lx + 30}" y2="56" stroke="${color}" stroke-width="2.5"${shape === 'diamond' ? ' stroke-dasharray="6 4"' : ''}/>` );
		out.push( marker( shape, lx + 15, 56, color ) );
		out.push( `<text x="${lx + 38}" y="61" font-size="14">${escape( label )}</text>` );
		lx += 56 + 8.2 * label.length;

	}

	for ( let p = 0; p < panels.length; p ++ ) {

		const { key, label } = panels[ p ];
		const x0 = left + p * ( panelWidth + gap ), y0 = top;
		const values = result.layouts.map( ( row ) => row[ key ] );
		const yMax = niceCeiling( Math.max( ...values ) * 1.08 );
		const sx = ( n: number ) => x0 + ( Math.log10( n ) - Math.log10( xMin ) ) / ( Math.log10( xMax ) - Math.log10( xMin ) ) * panelWidth;
		const sy = ( e: number ) => y0 + panelHeight - e / yMax * panelHeight;

		// Axes and grid lines.
		out.push( `<rect x="${x0}" y="${y0}" width="${panelWidth}" height="${panelHeight}" fill="none" stroke="#333" stroke-width="1"/>` );
		for ( const tick of yTicks( yMax ) ) {

			out.push( `<line x1="${x0}" y1="${sy( tick )}" x2="${x0 + panelWidth}" y2="${sy( tick )}" stroke="#e4e4e4"/>` );
			out.push( `<text x="${x0 - 8}" y="${sy( tick ) + 5}" font-size="13" text-anchor="end">${formatPercent( tick, yMax )}</text>` );

		}

		for ( const tick of logTicks( xMin, xMax ) ) {

			out.push( `<line x1="${sx( tick )}" y1="${y0}" x2="${sx( tick )}" y2="${y0 + panelHeight}" stroke="#e4e4e4"/>` );
			out.push( `<text x="${sx( tick )}" y="${y0 + panelHeight + 20}" font-size="13" text-anchor="middle">${tick}</text>` );

		}

		out.push( `<text x="${x0 + panelWidth / 2}" y="${height - 18}" font-size="15" text-anchor="middle">probes (log scale)</text>` );
		out.push( `<text transform="translate(${x0 - 58} ${y0 + panelHeight / 2}) rotate(-90)" font-size="15" text-anchor="middle">${label}</text>` );

		// Guides: the budget (20 % of the paper's grid) and the paper's grid's error.
		const gridRow = result.layouts.find( ( row ) => row.kind === 'grid' && row.interpolation === 'trilinear' && row.probes === result.paper.gridProbes );
		const budget = result.verdict.budget;
		if ( budget >= xMin && budget <= xMax ) {

			out.push( `<line x1="${sx( budget )}" y1="${y0}" x2="${sx( budget )}" y2="${y0 + panelHeight}" stroke="${COLORS.guide}" stroke-width="1.5" stroke-dasharray="5 4"/>` );
			out.push( `<text x="${sx( budget ) + 5}" y="${y0 + 16}" font-size="12" fill="#444">20 % of paper's grid (${budget})</text>` );

		}

		if ( gridRow ) {

			out.push( `<line x1="${x0}" y1="${sy( gridRow[ key ] )}" x2="${x0 + panelWidth}" y2="${sy( gridRow[ key ] )}" stroke="${COLORS.guide}" stroke-width="1.5" stroke-dasharray="2 3"/>` );
			out.push( `<text x="${x0 + panelWidth - 5}" y="${sy( gridRow[ key ] ) - 6}" font-size="12" fill="#444" text-anchor="end">paper's grid ${result.paper.gridCounts.join( 'x' )}: ${formatPercent( gridRow[ key ], 0.1 )}</text>` );

		}

		// Curves.
		const series: [ LayoutResult[], string, string, string ][] = [
			[ result.layouts.filter( ( row ) => row.kind === 'grid' && row.interpolation === 'trilinear' ), COLORS.grid, 'square', '' ],
			[ result.layouts.filter( ( row ) => row.kind === 'grid' && row.interpolation === 'tetrahedral' ), COLORS.gridTet, 'diamond', '6 4' ],
			[ result.layouts.filter( ( row ) => row.kind === 'auto' ), COLORS.auto, 'circle', '' ],
		];
		for ( const [ rows, color, shape, dash ] of series ) {

			const sorted = rows.slice().sort( ( a, b ) => a.probes - b.probes );
			if ( sorted.length > 1 ) out.push( `<polyline fill="none" stroke="${color}" stroke-width="2.5"${dash ? ` stroke-dasharray="${dash}"` : ''} points="${sorted.map( ( row ) => `${sx( row.probes ).toFixed( 1 )},${sy( row[ key ] ).toFixed( 1 )}` ).join( ' ' )}"/>` );
			for ( const row of sorted ) out.push( marker( shape, sx( row.probes ), sy( row[ key ] ), color ) );

		}

		for ( const row of result.layouts.filter( ( r ) => r.kind === 'hand' ) ) {

			out.push( marker( 'triangle', sx( row.probes ), sy( row[ key ] ), COLORS.hand ) );
			out.push( `<text x="${sx( row.probes ) - 9}" y="${sy( row[ key ] ) - 10}" font-size="12" fill="${COLORS.hand}" text-anchor="end">hand ${row.probes}</text>` );

		}

		if ( gridRow ) out.push( marker( 'ring', sx( gridRow.probes ), sy( gridRow[ key ] ), COLORS.paper ) );
		const headline = result.verdict.auto ? result.layouts.find( ( row ) => row.name === result.verdict.auto!.name ) : undefined;
		if ( headline ) out.push( `<text x="${sx( headline.probes ) + 10}" y="${sy( headline[ key ] ) + 20}" font-size="12" fill="${COLORS.auto}">auto ${headline.probes}</text>` );

	}

	out.push( '</svg>' );
	return out.join( '\n' );

}

function marker( shape: string, x: number, y: number, color: string ): string {

	const r = 5.5;
	switch ( shape ) {

		case 'square': return `<rect x="${( x - r ).toFixed( 1 )}" y="${( y - r ).toFixed( 1 )}" width="${2 * r}" height="${2 * r}" fill="${color}"/>`;
		case 'diamond': return `<polygon points="${x.toFixed( 1 )},${( y - r - 1.5 ).toFixed( 1 )} ${( x + r + 1.5 ).toFixed( 1 )},${y.toFixed( 1 )} ${x.toFixed( 1 )},${( y + r + 1.5 ).toFixed( 1 )} ${( x - r - 1.5 ).toFixed( 1 )},${y.toFixed( 1 )}" fill="#fff" stroke="${color}" stroke-width="2"/>`;
		case 'triangle': return `<polygon points="${x.toFixed( 1 )},${( y - r - 2 ).toFixed( 1 )} ${( x + r + 1 ).toFixed( 1 )},${( y + r ).toFixed( 1 )} ${( x - r - 1 ).toFixed( 1 )},${( y + r ).toFixed( 1 )}" fill="${color}"/>`;
		case 'ring': return `<circle cx="${x.toFixed( 1 )}" cy="${y.toFixed( 1 )}" r="${r + 5}" fill="none" stroke="${color}" stroke-width="2"/>`;
		default: return `<circle cx="${x.toFixed( 1 )}" cy="${y.toFixed( 1 )}" r="${r}" fill="${color}"/>`;

	}

}

/** The smallest 1, 2, 2.5 or 5 × 10^k ≥ value. */
export function niceCeiling( value: number ): number {

	if ( ! ( value > 0 ) ) return 1;
	const power = Math.pow( 10, Math.floor( Math.log10( value ) ) );
	for ( const m of [ 1, 2, 2.5, 5, 10 ] ) if ( m * power >= value * ( 1 - 1e-12 ) ) return m * power;
	return 10 * power;

}

function yTicks( max: number ): number[] {

	const step = niceCeiling( max / 6 );
	const out: number[] = [];
	for ( let v = 0; v <= max * ( 1 + 1e-9 ); v += step ) out.push( v );
	return out;

}

/** 1, 2, 5 × 10^k within [min, max]. */
export function logTicks( min: number, max: number ): number[] {

	const out: number[] = [];
	for ( let k = Math.floor( Math.log10( min ) ); k <= Math.ceil( Math.log10( max ) ); k ++ ) {

		for ( const m of [ 1, 2, 5 ] ) {

			const v = m * Math.pow( 10, k );
			if ( v >= min * ( 1 - 1e-9 ) && v <= max * ( 1 + 1e-9 ) ) out.push( v );

		}

	}

	return out;

}

function formatPercent( value: number, scale: number ): string {

	return `${( 100 * value ).toFixed( scale < 0.05 ? 1 : 0 )} %`;

}

function escape( text: string ): string {

	return text.replace( /&/g, '&amp;' ).replace( /</g, '&lt;' ).replace( />/g, '&gt;' );

}
