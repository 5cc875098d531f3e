/**
 * Pure parts of the experiment's output: the result JSON and the Markdown report (the plot is
 * plot.ts).
 */

import type { LayoutResult, PaperFigures, Verdict } from './evaluate.js';
import type { EqualStoragePair, TargetCheck } from './targets.js';

/** The same layouts judged on one ground truth (the reported one and each `--check-seeds` one). */
export interface SeedCheck {

	seed: number;
	/** Its samples inside the walkable region. */
	walkableSamples: number;
	targets: TargetCheck[];
	/** Mean error of every layout, by name. */
	meanError: Record<string, number>;
	/** Mean error over the walkable samples, by name. */
	meanErrorWalkable: Record<string, number | null>;

}

/** The result file `DIR/<scene>.json`. */
export interface ExperimentResult {

	scene: string;
	/** Number of ground-truth sample points M. */
	samples: number;
	layouts: LayoutResult[];
	/** The paper's claim (captured probes). */
	verdict: Verdict;
	/** Issue 14's targets on the reported ground truth. */
	targets: TargetCheck[];
	/** The reported ground truth and the further ones (`--check-seeds`), first the reported. */
	seeds: SeedCheck[];
	/** Gradient layouts of N probes against plain fitted ones of 4N. */
	equalStorage: EqualStoragePair[];
	paper: PaperFigures;
	/** How the ground truth was drawn. */
	groundTruth: {
		seed: number; region: { min: number[]; max: number[] }; minDistance: number; maxSky: number;
		drawn: number; rejectedNear: number; rejectedInside: number; rejectedOutside: number; captureMs: number; normals: number;
		/** Samples whose paper's-grid cell has all its probes in open space. */
		gridValidSamples: number;
		/** Samples inside the walkable region. */
		walkableSamples: number;
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
	/** The extra fit points (in open space, own seed) and the fit set (dense candidates + those). */
	fit: {
		seed: number; points: number; drawn: number; captureMs: number; samples: number;
		/** Set when fit points grow with the layout: a layout of n probes fits to the first max(base, ⌈perProbe × n⌉). */
		base?: number; perProbe?: number;
	};
	/** "Where characters go": `WalkableRegion` of the scene's triangles. */
	walkable: { height: number; floorTriangles: number };
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

/** The Markdown table of the captured layouts (the paper's Table 4 columns plus the errors). */
export function layoutTable( layouts: readonly LayoutResult[] ): string {

	const valid = layouts.some( ( row ) => row.meanErrorGridValid !== undefined );
	const walkable = layouts.some( ( row ) => row.meanErrorWalkable !== undefined );
	const lines = [
		`| layout | interpolation | probes | cells | SH floats | bake captures | capture (ms) | mean error | p95 error |${walkable ? ' where characters go |' : ''}${valid ? ' mean / p95 where the grid is valid |' : ''} probes not in open space |`,
		`|---|---|--:|--:|--:|--:|--:|--:|--:|${walkable ? '--:|' : ''}${valid ? '--:|' : ''}--:|`,
	];
	for ( const row of layouts ) {

		const cells = `${row.cells} ${row.interpolation === 'trilinear' ? 'boxes' : 'tetrahedra'}`;
		const where = walkable ? ` ${optionalPct( row.meanErrorWalkable )} |` : '';
		const extra = valid ? ` ${row.meanErrorGridValid !== undefined ? `${pct( row.meanErrorGridValid )} / ${pct( row.p95ErrorGridValid! )}` : '–'} |` : '';
		lines.push( `| ${row.name} | ${row.interpolation} | ${row.probes} | ${cells} | ${row.shFloats} | ${row.bakeCaptures} | ${row.captureMsEstimated ? '≈ ' : ''}${Math.round( row.captureMs )} | ${pct( row.meanError )} | ${pct( row.p95Error )} |${where}${extra} ${row.probesNotInOpenSpace} |` );

	}

	return lines.join( '\n' );

}

/** The Markdown table of the fitted layouts: errors, storage and the fit (λ, cross-validation error, time). */
export function fittedTable( layouts: readonly LayoutResult[] ): string {

	const lines = [
		'| layout | interpolation | probes | SH floats | bake captures | mean error | p95 error | where characters go | fit-set error | cross-validation error | λ | λ gradient | fit (and placement) time |',
		'|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|',
	];
	for ( const row of layouts ) {

		const fit = row.fit!;
		lines.push( `| ${row.name} | ${row.interpolation} | ${row.probes} | ${row.shFloats} | ${row.bakeCaptures} | ${pct( row.meanError )} | ${pct( row.p95Error )} | ${optionalPct( row.meanErrorWalkable )} | ${optionalPct( row.fitSetError )} | ${optionalPct( fit.crossValidationError ?? undefined )} | ${fit.lambda.toPrecision( 2 )} | ${row.gradients ? fit.gradientLambda.toPrecision( 2 ) : '–'} | ${seconds( fit.ms )} |` );

	}

	return lines.join( '\n' );

}

/**
 * The targets on every ground truth: one row per target, one column per seed; first the captured
 * paper's grid (`gridName`) for reference.
 */
export function targetTable( seeds: readonly SeedCheck[], gridName: string ): string {

	const lines = [
		`| target | layout judged (seed ${seeds[ 0 ].seed}) | ${seeds.map( ( s ) => `seed ${s.seed}` ).join( ' | ' )} | best candidate on the truth (seed ${seeds[ 0 ].seed}) |`,
		`|---|---|${seeds.map( () => '--:|' ).join( '' )}---|`,
		`| (reference: the captured paper's grid) | ${gridName} | ${seeds.map( ( s ) => s.meanError[ gridName ] !== undefined ? pct( s.meanError[ gridName ] ) : '–' ).join( ' | ' )} | |`,
	];
	seeds[ 0 ].targets.forEach( ( target, t ) => {

		const format = ( check: TargetCheck ) => check.value === null ? '–' :
			`${target.id === 'grid-count' ? `${check.value.toFixed( 2 )}×` : pct( check.value )} ${check.holds ? '✓' : '✗'}`;
		const best = target.bestOnTruth ? `${target.bestOnTruth.layout}: ${target.id === 'grid-count' ? `${target.bestOnTruth.value.toFixed( 2 )}×` : pct( target.bestOnTruth.value )}` : '–';
		lines.push( `| ${target.text} | ${target.layout ?? 'none measured'} | ${seeds.map( ( s ) => format( s.targets[ t ] ) ).join( ' | ' )} | ${best} |` );

	} );
	return lines.join( '\n' );

}

/** The equal-storage comparison. */
export function equalStorageTable( pairs: readonly EqualStoragePair[], seeds: readonly SeedCheck[] ): string {

	const lines = [
		`| gradient layout | SH floats | mean error (seeds ${seeds.map( ( s ) => s.seed ).join( ', ' )}) | where characters go | plain fitted layout | SH floats | mean error | where characters go |`,
		'|---|--:|--:|--:|---|--:|--:|--:|',
	];
	const errors = ( name: string ) => seeds.map( ( s ) => pct( s.meanError[ name ] ) ).join( ' / ' );
	for ( const { gradient: g, plain: p } of pairs ) {

		const side = ( x: EqualStoragePair[ 'plain' ] ) => x ? `${x.layout} | ${x.shFloats} | ${errors( x.layout )} | ${optionalPct( x.meanErrorWalkable )}` : 'not measured | – | – | –';
		lines.push( `| ${side( g )} | ${side( p )} |` );

	}

	return lines.join( '\n' );

}

/** `DIR/<scene>.md`: a short readable report. */
export function markdownReport( result: ExperimentResult, plotFile: string ): string {

	const { verdict: v, paper, groundTruth: gt, dense, capture, fit } = result;
	const title = result.scene[ 0 ].toUpperCase() + result.scene.slice( 1 );
	const captured = result.layouts.filter( ( row ) => ! row.fitted );
	const paperGrid = captured.find( ( row ) => row.kind === 'grid' && row.interpolation === 'trilinear' && row.probes === paper.gridProbes );
	const paperGridTet = captured.find( ( row ) => row.kind === 'grid' && row.interpolation === 'tetrahedral' && row.probes === paper.gridProbes );
	const hand = captured.find( ( row ) => row.kind === 'hand' );
	const lines: string[] = [];
	lines.push( `# ${title}: the paper's claim, measured`, '' );
	lines.push( `**Claim** (paper, Table 4): arbitrary probes with tetrahedral interpolation light the scene as well as the ${paper.gridCounts.join( 'x' )} grid (${paper.gridProbes} probes, trilinear) with about 20 % of its probes (the paper's hand-placed layout: ${paper.handProbes}).`, '' );
	lines.push( `**Verdict, captured probes (the paper's method): ${v.text}**`, '' );
	const notes: string[] = [];
	if ( v.gridValid ) notes.push( `Only ${v.gridValid.samples} of the ${result.samples} samples have all the probes of their ${paper.gridCounts.join( 'x' )} cell in open space (${paperGrid?.probesNotInOpenSpace ?? '?'} of the grid's ${paper.gridProbes} probes are in walls, against a surface or outside the interior). On those samples alone the grid's mean error is ${pct( v.gridValid.gridMeanError )} and the judged automatic layout's ${v.gridValid.autoMeanError !== null ? pct( v.gridValid.autoMeanError ) : '–'}${v.gridValid.ratio !== null ? ` (${v.gridValid.ratio.toFixed( 2 )}×): the claim ${v.gridValid.holds ? 'holds there too' : 'does not hold there'}` : ''}.` );
	if ( v.dense ) notes.push( `All ${v.dense.probes} dense candidates together (what the automatic layouts are cut from) reach ${pct( v.dense.meanError )} mean${v.dense.meanError > v.grid.meanError ? ` — above the grid's ${pct( v.grid.meanError )}: with these candidates no captured automatic layout can match the grid` : ''}.` );
	if ( v.fewestAutoMatchingGrid !== null ) notes.push( `Fewest captured automatic probes measured that match the grid's mean error: ${v.fewestAutoMatchingGrid} (${pct( v.fewestAutoMatchingGrid / v.grid.probes, 0 )} of the grid); its 95th percentile: ${v.fewestAutoMatchingGridP95 ?? 'none of those measured'}.` );
	if ( paperGridTet && paperGrid ) notes.push( `The same ${paper.gridProbes} grid probes tetrahedralized: ${pct( paperGridTet.meanError )} mean against ${pct( paperGrid.meanError )} trilinear (${( paperGridTet.meanError / paperGrid.meanError ).toFixed( 2 )}×).` );
	if ( v.hand && hand ) notes.push( `The scene module's hand-made layout (${v.hand.probes} probes${hand.probesNotInOpenSpace > 0 ? `, ${hand.probesNotInOpenSpace} of them outside the open space — e.g. a sky probe above the roof` : ''}): mean error ${pct( v.hand.meanError )}, ${v.hand.ratio.toFixed( 2 )}× the grid's${hand.meanErrorGridValid !== undefined ? `; ${pct( hand.meanErrorGridValid )} where the grid is valid` : ''}.` );
	for ( const note of notes ) lines.push( `- ${note}` );
	lines.push( '' );

	lines.push( '## Fitted probes: issue 14\'s targets', '' );
	lines.push( `The layout a target judges is chosen without the ground truth: of the candidates at the largest count allowed, the one with the lowest cross-validation error of its fit (else its error over the fit samples). ✓: the target holds on that ground truth. The same layouts are judged on ${result.seeds.length} ground truths (seeds ${result.seeds.map( ( s ) => s.seed ).join( ', ' )}, ${result.samples} points each).`, '' );
	lines.push( targetTable( result.seeds, paperGrid?.name ?? '' ), '' );
	lines.push( '### Equal storage', '', 'A gradient probe stores 108 floats (27 SH + 81 gradient), a plain one 27: gradient layouts of N probes against plain fitted layouts of 4N.', '' );
	lines.push( equalStorageTable( result.equalStorage, result.seeds ), '' );
	lines.push( '### Where characters go', '' );
	lines.push( `"Where characters go" is \`new WalkableRegion( sceneTriangles, { height: ${result.walkable.height} } )\` (${result.walkable.floorTriangles} floor-facing triangles and the ${result.walkable.height} m above them): ${gt.walkableSamples} of the ${result.samples} ground-truth points are inside; its column is the error over those points alone, normalised by their own mean irradiance. The layouts "(…, walkable)" were placed and fitted with \`region: { walkable }\` (points outside weigh 0.1).`, '' );
	const walkableRows = result.layouts.filter( ( row ) => row.region === 'walkable' );
	if ( walkableRows.length > 0 ) {

		lines.push( '| layout | mean error, whole volume | where characters go |', '|---|--:|--:|' );
		for ( const row of walkableRows ) {

			const same = result.layouts.find( ( r ) => ! r.region && r.kind === 'auto' && r.method === row.method && r.gradients === row.gradients && r.probes === row.probes );
			for ( const r of same ? [ same, row ] : [ row ] ) lines.push( `| ${r.name} | ${pct( r.meanError )} | ${optionalPct( r.meanErrorWalkable )} |` );

		}

		lines.push( '' );

	}

	lines.push( `![${title}: mean and 95th-percentile irradiance error vs probe count](${plotFile})`, '' );
	lines.push( '## Captured probes', '' );
	lines.push( layoutTable( captured ), '' );
	lines.push( '## Fitted probes', '' );
	lines.push( fittedTable( result.layouts.filter( ( row ) => row.fitted ) ), '' );
	lines.push( '| Table 4 | grid probes | arbitrary probes | boxes (grid) | tetrahedra |', '|---|--:|--:|--:|--:|' );
	lines.push( `| paper | ${paper.gridProbes} | ${paper.handProbes} | ${paper.boxes} | ${paper.tetrahedra} |` );
	lines.push( `| here (grid; hand-made layout) | ${paperGrid?.probes ?? '–'} | ${hand?.probes ?? '–'} | ${paperGrid?.cells ?? '–'} | ${hand?.cells ?? '–'} |` );
	if ( v.auto ) {

		const auto = result.layouts.find( ( row ) => row.name === v.auto!.name );
		lines.push( `| here (grid; automatic ${v.auto.probes}) | ${paperGrid?.probes ?? '–'} | ${v.auto.probes} | ${paperGrid?.cells ?? '–'} | ${auto?.cells ?? '–'} |` );

	}

	if ( paperGridTet ) lines.push( '', `The paper's grid tetrahedralized: ${paperGridTet.cells} tetrahedra (a Delaunay tetrahedralization of a grid splits each box into 5–6).` );
	lines.push( '', '## How it was measured', '' );
	lines.push( `- **Error**: the library's \`irradianceError\`: per sample point, the mean over 26 normals of max over RGB |E_interp(n) − E_true(n)|, divided by the mean true irradiance over all samples, normals and channels; mean and 95th percentile over the ${result.samples} samples. A gradient layout's field is Σᵢ wᵢ (cᵢ + Gᵢ·(q − pᵢ)) with the runtime's weights (\`evaluateGradientField\`).` );
	lines.push( `- **Ground truth**: ${result.samples} points drawn uniformly (seed ${gt.seed}; further seeds ${result.seeds.slice( 1 ).map( ( s ) => s.seed ).join( ', ' ) || 'none'}) in the scene module's grid box [${gt.region.min.join( ', ' )}] – [${gt.region.max.join( ', ' )}], keeping those in open space: no surface within ${gt.minDistance} m, at most 10 % of 32 rays first hitting the undrawn side of a surface (a cube camera there sees through walls)${gt.maxSky < 1 ? `, at most ${pct( gt.maxSky, 0 )} of the rays leaving the scene (a closed interior: the air above the roof is not part of it)` : ''}. ${gt.drawn} drawn: ${gt.rejectedNear} near a surface, ${gt.rejectedInside} inside geometry${gt.maxSky < 1 ? `, ${gt.rejectedOutside} outside the interior` : ''}. Each captured like a probe (${Math.round( gt.captureMs / 1000 )} s).` );
	lines.push( `- **Capture**: one \`ProbeCapturer\` for everything, ${capture.resolution}² per face, ${capture.type} targets, near ${capture.near}, far ${capture.far}, solid angle '${capture.solidAngle}'; the scene module's own build (geometry, materials${result.scene === 'basic' ? '' : ', textures, sun with its shadow map, sky dome'}, lights). Capture time: wall time of \`capture()\` for the layout's probes after a warm-up, ${result.environment.renderer}.` );
	lines.push( `- **Grids** over the scene module's grid box; trilinear with \`GridInterpolator\`, and the same captured probes tetrahedralized (\`createProbeInterpolator\`); both rows share one capture time.` );
	lines.push( `- **Automatic layouts, captured** come from a dense candidate set captured separately — ${dense.probes} points in open space: a jittered grid (seed ${dense.seed}, ${dense.fromGrid} points) and vertex candidates (\`candidatesFromVertices\`, ${dense.fromVertices} points); ${Math.round( dense.captureMs / 1000 )} s capture — never from the ground truth. Two placements, each one run whose prefixes give every count: **reduceProbes** (the library: insert the worst-predicted candidate; ${( dense.reduceMs / 1000 ).toFixed( 1 )} s) and **mean-greedy** (this experiment's: from reduceProbes' starting set, insert whichever of the 32 worst-predicted candidates lowers the dense set's mean error most; ${( dense.selectMs / 1000 ).toFixed( 1 )} s). The paper's verdict judges the largest count within 20 % of the paper's grid, and of the two placements the one with the lower error on the dense set. Those layouts were captured again as layouts of their own (their capture time; their SH equal the dense capture's to ${dense.recaptureMaxDifference.toExponential( 1 )} of the largest L00); the other automatic rows show the dense capture's time per probe × probes (≈).` );
	lines.push( `- **Fit samples**: the ${dense.probes} dense candidates${fit.points > 0 ? ` and ${fit.points} extra points drawn like the ground truth in open space but with their own seed (${fit.seed}; ${fit.drawn} drawn), captured like the dense set (${Math.round( fit.captureMs / 1000 )} s)` : ''}: ${fit.samples} in all, never a ground-truth point.${fit.perProbe ? ` A fitted layout of n probes fits to the dense candidates and the first max(${fit.base}, ⌈${fit.perProbe} × n⌉) extra points (a prefix of the one drawn set; its "bake captures" count them).` : ''} **Fitted** layouts: \`fitProbeSH\` (λ, and λ of the gradients, by 5-fold cross-validation) on the layout's own interpolation — trilinear for the grids, tetrahedral (outer cells included) for the rest — plain (27 floats per probe) or with gradients (108). **greedy-fit**: \`reduceProbes\` re-fitting at every insertion (\`fit\`, \`fitSamples\`), **greedy-fit + swaps** with swap passes after; one run per count. The fit-set error is each layout's mean error over the fit samples.` );
	lines.push( `- **All dense candidates**: the whole dense set tetrahedralized, the best the captured automatic layouts could do with these candidates.` );
	lines.push( `- **Hand-made layout**: the scene module's (\`scenes/${result.scene}.json\`), tetrahedral.` );
	lines.push( `- Run: ${Math.round( result.runMs / 1000 )} s (${result.environment.newCaptures ?? '?'} captures made in the browser, the rest from the saved captures), ${result.environment.browser}.` );
	return lines.join( '\n' ) + '\n';

}

function optionalPct( value: number | undefined ): string {

	return value === undefined ? '–' : pct( value );

}

function seconds( ms: number ): string {

	return ms >= 1000 ? `${( ms / 1000 ).toFixed( 1 )} s` : `${Math.round( ms )} ms`;

}
