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
		/** Samples whose paper's-grid cell has all its probes in open space. */
		gridValidSamples: number;
	};
	/** The dense candidate set the automatic reduction ran on. */
	dense: {
		seed: number; probes: number; fromGrid: number; fromVertices: number; captureMs: number; reduceMs: number; selectMs: number;
		/** Mean error of each automatic cut over the dense set itself (what the reduction minimised). */
		denseMeanError: Record<string, number>;
		/**
		 * Largest |SH difference| between an automatic layout's own capture and the dense capture at the same points,
		 * relative to the largest L00.
		 */
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

	const valid = layouts.some( ( row ) => row.meanErrorGridValid !== undefined );
	const lines = [
		`| layout | interpolation | probes | cells | capture (ms) | mean error | p95 error |${valid ? ' mean / p95 where the grid is valid |' : ''} probes not in open space |`,
		`|---|---|--:|--:|--:|--:|--:|${valid ? '--:|' : ''}--:|`,
	];
	for ( const row of layouts ) {

		const cells = `${row.cells} ${row.interpolation === 'trilinear' ? 'boxes' : 'tetrahedra'}`;
		const extra = valid ? ` ${row.meanErrorGridValid !== undefined ? `${pct( row.meanErrorGridValid )} / ${pct( row.p95ErrorGridValid! )}` : '–'} |` : '';
		lines.push( `| ${row.name} | ${row.interpolation} | ${row.probes} | ${cells} | ${row.captureMsEstimated ? '≈ ' : ''}${Math.round( row.captureMs )} | ${pct( row.meanError )} | ${pct( row.p95Error )} |${extra} ${row.probesNotInOpenSpace} |` );

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
	const notes: string[] = [];
	if ( v.gridValid ) notes.push( `Only ${v.gridValid.samples} of the ${result.samples} samples have all the probes of their ${paper.gridCounts.join( 'x' )} cell in open space (${paperGrid?.probesNotInOpenSpace ?? '?'} of the grid's ${paper.gridProbes} probes are in walls, against a surface or outside the interior). On those samples alone the grid's mean error is ${pct( v.gridValid.gridMeanError )} and the judged automatic layout's ${v.gridValid.autoMeanError !== null ? pct( v.gridValid.autoMeanError ) : '–'}${v.gridValid.ratio !== null ? ` (${v.gridValid.ratio.toFixed( 2 )}×): the claim ${v.gridValid.holds ? 'holds there too' : 'does not hold there'}` : ''}.` );
	if ( v.dense ) notes.push( `All ${v.dense.probes} dense candidates together (what the automatic layouts are cut from) reach ${pct( v.dense.meanError )} mean${v.dense.meanError > v.grid.meanError ? ` — above the grid's ${pct( v.grid.meanError )}: with these candidates no automatic layout can match the grid` : ''}.` );
	if ( v.fewestAutoMatchingGrid !== null ) notes.push( `Fewest automatically placed probes measured that match the grid's mean error: ${v.fewestAutoMatchingGrid} (${pct( v.fewestAutoMatchingGrid / v.grid.probes, 0 )} of the grid); its 95th percentile: ${v.fewestAutoMatchingGridP95 ?? 'none of those measured'}.` );
	if ( paperGridTet && paperGrid ) notes.push( `The same ${paper.gridProbes} grid probes tetrahedralized: ${pct( paperGridTet.meanError )} mean against ${pct( paperGrid.meanError )} trilinear (${( paperGridTet.meanError / paperGrid.meanError ).toFixed( 2 )}×) — 4-probe tetrahedral blending by itself is ${paperGridTet.meanError > paperGrid.meanError ? 'less' : 'more'} accurate than 8-probe trilinear.` );
	if ( v.hand && hand ) notes.push( `The scene module's hand-made layout (${v.hand.probes} probes${hand.probesNotInOpenSpace > 0 ? `, ${hand.probesNotInOpenSpace} of them outside the open space — e.g. a sky probe above the roof` : ''}): mean error ${pct( v.hand.meanError )}, ${v.hand.ratio.toFixed( 2 )}× the grid's${hand.meanErrorGridValid !== undefined ? `; ${pct( hand.meanErrorGridValid )} where the grid is valid` : ''}.` );
	for ( const note of notes ) lines.push( `- ${note}` );
	lines.push( '' );
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
	lines.push( `- **Automatic layouts** come from a dense candidate set captured separately — ${dense.probes} points in open space: a jittered grid (seed ${dense.seed}, ${dense.fromGrid} points) and vertex candidates (\`candidatesFromVertices\`, ${dense.fromVertices} points); ${Math.round( dense.captureMs / 1000 )} s capture — never from the ground truth. Two placements, each one run whose prefixes give every count: **reduceProbes** (the library: insert the worst-predicted candidate; ${( dense.reduceMs / 1000 ).toFixed( 1 )} s) and **mean-greedy** (this experiment's: from reduceProbes' starting set, insert whichever of the 32 worst-predicted candidates lowers the dense set's mean error most; ${( dense.selectMs / 1000 ).toFixed( 1 )} s), to tell the placement's limits from the claim's. The verdict judges the largest count within 20 % of the paper's grid, and of the two placements the one with the lower error on the dense set. Those layouts were captured again as layouts of their own (their capture time; their SH equal the dense capture's to ${dense.recaptureMaxDifference.toExponential( 1 )} of the largest L00); the other automatic rows reuse the dense capture and show its time per probe × probes (≈).` );
	lines.push( `- **All dense candidates**: the whole dense set tetrahedralized, the best the automatic layouts could do with these candidates.` );
	lines.push( `- **Hand-made layout**: the scene module's (\`scenes/${result.scene}.json\`), tetrahedral.` );
	lines.push( `- Run: ${Math.round( result.runMs / 1000 )} s, ${result.environment.browser}.` );
	return lines.join( '\n' ) + '\n';

}

/** Options of {@link plotSVG}. */
export interface PlotOptions { title: string; width?: number; height?: number }

const COLORS = { grid: '#d62728', gridTet: '#ff7f0e', auto: '#1f77b4', greedy: '#9467bd', hand: '#2ca02c', dense: '#8c564b', paper: '#000000', guide: '#777777' };

/**
 * The answer to the claim in one picture: mean (left) and 95th-percentile (right) error (log scale) against
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
	const top = 110, bottom = 64, left = 78, gap = 90, right = 24;
	const panelWidth = ( width - left - right - gap ) / 2, panelHeight = height - top - bottom;
	const probes = result.layouts.map( ( row ) => row.probes );
	const headlineName = result.verdict.auto?.name;
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
		[ 'automatic: reduceProbes', COLORS.auto, 'circle', true ],
		[ 'automatic: mean-greedy', COLORS.greedy, 'hexagon', true ],
		[ 'hand-made (scene module)', COLORS.hand, 'triangle', false ],
		[ 'all dense candidates', COLORS.dense, 'cross', false ],
		[ "paper's grid", COLORS.paper, 'ring', false ],
	];
	// Two rows of four.
	legend.forEach( ( [ label, color, shape, line ], i ) => {

		const lx = left + ( i % 4 ) * ( ( width - left - right ) / 4 ), ly = 52 + 22 * Math.floor( i / 4 );
		if ( line ) out.push( `<line x1="${lx}" y1="${ly}" x2="${lx + 30}" y2="${ly}" stroke="${color}" stroke-width="2.5"${shape === 'diamond' ? ' stroke-dasharray="6 4"' : ''}/>` );
		out.push( marker( shape, lx + 15, ly, color ) );
		out.push( `<text x="${lx + 38}" y="${ly + 5}" font-size="14">${escape( label )}</text>` );

	} );

	for ( let p = 0; p < panels.length; p ++ ) {

		const { key, label } = panels[ p ];
		const x0 = left + p * ( panelWidth + gap ), y0 = top;
		const values = result.layouts.map( ( row ) => row[ key ] );
		const yMin = Math.pow( 10, Math.floor( Math.log10( Math.min( ...values ) * 0.85 ) * 4 ) / 4 );
		const yMax = Math.pow( 10, Math.ceil( Math.log10( Math.max( ...values ) * 1.15 ) * 4 ) / 4 );
		const sx = ( n: number ) => x0 +
			( Math.log10( n ) - Math.log10( xMin ) ) / ( Math.log10( xMax ) - Math.log10( xMin ) ) * panelWidth;
		const sy = ( e: number ) => y0 + panelHeight -
			( Math.log10( e ) - Math.log10( yMin ) ) / ( Math.log10( yMax ) - Math.log10( yMin ) ) * panelHeight;

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
		const gridRow = result.layouts.find( ( row ) => row.kind === 'grid' && row.interpolation === 'trilinear' && row.probes === result.paper.gridProbes );
		const budget = result.verdict.budget;
		if ( budget >= xMin && budget <= xMax ) {

			out.push( `<line x1="${sx( budget )}" y1="${y0}" x2="${sx( budget )}" y2="${y0 + panelHeight}" stroke="${COLORS.guide}" stroke-width="1.5" stroke-dasharray="5 4"/>` );
			out.push( `<text x="${sx( budget ) + 5}" y="${y0 + 16}" font-size="12" fill="#444">20 % of paper's grid (${budget})</text>` );

		}

		if ( gridRow ) {

			out.push( `<line x1="${x0}" y1="${sy( gridRow[ key ] )}" x2="${x0 + panelWidth}" y2="${sy( gridRow[ key ] )}" stroke="${COLORS.guide}" stroke-width="1.5" stroke-dasharray="2 3"/>` );
			out.push( `<text x="${x0 + 5}" y="${sy( gridRow[ key ] ) - 6}" font-size="12" fill="#444">paper's grid ${result.paper.gridCounts.join( 'x' )}: ${formatPercent( gridRow[ key ] )}</text>` );

		}

		// Curves.
		const series: [ LayoutResult[], string, string, string ][] = [
			[ result.layouts.filter( ( row ) => row.kind === 'grid' && row.interpolation === 'trilinear' ), COLORS.grid, 'square', '' ],
			[ result.layouts.filter( ( row ) => row.kind === 'grid' && row.interpolation === 'tetrahedral' ), COLORS.gridTet, 'diamond', '6 4' ],
			[ result.layouts.filter( ( row ) => row.kind === 'auto' && row.method !== 'mean-greedy' ), COLORS.auto, 'circle', '' ],
			[ result.layouts.filter( ( row ) => row.kind === 'auto' && row.method === 'mean-greedy' ), COLORS.greedy, 'hexagon', '' ],
		];
		for ( const [ rows, color, shape, dash ] of series ) {

			const sorted = rows.slice().sort( ( a, b ) => a.probes - b.probes );
			if ( sorted.length > 1 ) out.push( `<polyline fill="none" stroke="${color}" stroke-width="2.5"${dash ? ` stroke-dasharray="${dash}"` : ''} points="${sorted.map( ( row ) => `${sx( row.probes ).toFixed( 1 )},${sy( row[ key ] ).toFixed( 1 )}` ).join( ' ' )}"/>` );
			for ( const row of sorted ) out.push( marker( shape, sx( row.probes ), sy( row[ key ] ), color ) );

		}

		for ( const row of result.layouts.filter( ( r ) => r.kind === 'hand' ) ) {

			out.push( marker( 'triangle', sx( row.probes ), sy( row[ key ] ), COLORS.hand ) );
			out.push( `<text x="${sx( row.probes ) - 10}" y="${sy( row[ key ] ) - 14}" font-size="12" fill="${COLORS.hand}" text-anchor="end">hand ${row.probes}</text>` );

		}

		for ( const row of result.layouts.filter( ( r ) => r.kind === 'dense' ) ) {

			out.push( marker( 'cross', sx( row.probes ), sy( row[ key ] ), COLORS.dense ) );
			out.push( `<text x="${sx( row.probes ) + 4}" y="${sy( row[ key ] ) - 12}" font-size="12" fill="${COLORS.dense}" text-anchor="middle">all ${row.probes}</text>` );

		}

		if ( gridRow ) out.push( marker( 'ring', sx( gridRow.probes ), sy( gridRow[ key ] ), COLORS.paper ) );
		const headline = headlineName ? result.layouts.find( ( row ) => row.name === headlineName ) : undefined;
		if ( headline ) {

			const color = headline.method === 'mean-greedy' ? COLORS.greedy : COLORS.auto;
			out.push( `<circle cx="${sx( headline.probes ).toFixed( 1 )}" cy="${sy( headline[ key ] ).toFixed( 1 )}" r="11" fill="none" stroke="${color}" stroke-width="2"/>` );
			out.push( `<text x="${sx( headline.probes ) + 12}" y="${sy( headline[ key ] ) + 28}" font-size="12" fill="${color}">judged: ${headline.probes}</text>` );

		}

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
