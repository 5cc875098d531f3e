/**
 * Tetrahedralization time on the same points, side by side: ours, CGAL (C++, if installed),
 * npm delaunay-triangulate (in a child process with a 60 s limit) and Qhull through SciPy (a
 * Python child process, only when SciPy is installed), with cheap checks of ours.
 */

import { mkdirSync } from 'node:fs';
import { buildCgal, BUILD_DIR, cgalVersion, runCgal, type CgalResult } from './cgal.js';
import { allDatasets, boxVolume, pointCount, writePointsFile, type Dataset } from './datasets.js';
import { orientation, signedVolume } from './geometry.js';
import { loadOurs, whyMissing, type Tetrahedralization } from './ours.js';
import { runDelaunayTriangulate } from './peers/delaunayTriangulate.js';
import { runQhull, scipyVersions } from './peers/scipyQhull.js';
import { collectGarbage, summarize, timeRuns, type Summary } from './stats.js';
import type { BenchRow, Target } from './types.js';

export const title = 'Tetrahedralization (ms, lower is better)';

export const notes = [
	'ours and CGAL interleaved: after warm-up calls of ours, rounds (15 up to 2,000 points, 9 up to 20,000, else 5) of one CGAL process triangulating 3 times then one run of ours, a GC before each; the ours row is the median of its runs, the CGAL row of all its runs. CGAL: Delaunay_triangulation_3 with Epick, range insert (spatially sorted), timed inside C++; delaunay-triangulate: one run in a child process, killed after 60 s, skipped on larger sets once it timed out; Qhull: scipy.spatial.Delaunay (default options, Qt triangulated output) in a python3 child process, several runs timed inside Python (file I/O and NumPy conversion excluded), only when SciPy is installed (the bench installs nothing).',
	'Ratio column: ours ÷ CGAL is the median of the rounds\' ratios (each run of ours ÷ the median of the CGAL process before it), so that load on a shared machine, which comes and goes, weighs on both sides of each ratio alike; ours ÷ the other peers is median over median (below 1: ours is faster).',
	'Qhull\'s check column: simplices with |volume| ≤ 1e-12 of the box count as flat; Qhull does not orient simplices consistently, so no inverted count. On grids it, like delaunay-triangulate, keeps flat tetrahedra that our output and CGAL\'s must not have.',
	'ours is checked cheaply: exact orientation of every tetrahedron (none may be flat or inverted), mutual neighbors, volume sum = the grid\'s box (grids) or CGAL\'s hull volume (random sets), and for random sets (unique Delaunay) the same tetrahedron count as CGAL.',
	'On a grid every cell is split into 5 or 6 tetrahedra, so counts may differ from CGAL on grids while both are valid; CGAL gives 6 per cell (1,650 for 12x6x6).',
	'Targets are printed, not asserted: random 10k ≤ 250 ms, random 100k ≤ 1.0 s, grid 40³ ≤ 3 s and valid; within 1.3× of CGAL on every set (issue 16).',
];

/** Time targets for ours, in ms. */
const TARGET_MS: Record<string, number> = { 'random 10k': 250, 'random 100k': 1000, 'grid 40³': 3000 };
const TARGET_RATIO = 1.3;

/** Rounds of CGAL-then-ours, and CGAL triangulations per round (one process). */
function roundsFor( count: number ): number {

	return count <= 2000 ? 15 : count <= 20000 ? 9 : 5;

}

const CGAL_PER_ROUND = 3;

/** Relative tolerance of the volume check (float sums of up to ~400k tetrahedra). */
const VOLUME_TOLERANCE = 1e-9;

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const ours = await loadOurs();
	const oursMissing = whyMissing( ours, [ 'tetrahedralize' ] );
	const cgal = await buildCgal( log );
	const cgalName = `CGAL ${cgalVersion() ?? ''}`.trim();
	mkdirSync( BUILD_DIR, { recursive: true } );

	// CGAL and ours on every set first, then the slow peer, whose minute-long runs and killed
	// child process would otherwise disturb the timings that follow them.
	const measured = [];
	for ( const dataset of allDatasets() ) {

		const pointsFile = `${BUILD_DIR}points-${dataset.name.replace( '³', '3' ).replace( /\W+/g, '-' )}.f64`;
		writePointsFile( pointsFile, dataset.points );
		const timed = await timeWithCgal( dataset, pointsFile, ours.api.tetrahedralize, oursMissing, cgal, cgalName, log );
		const oursTimed = oursRow( dataset, timed.ours, oursMissing, timed.cgal, cgalName );
		measured.push( { dataset, pointsFile, cgalResult: timed.cgal?.result ?? null, rows: [ oursTimed, timed.cgalRow ] } );

	}

	for ( const { dataset, pointsFile, cgalResult, rows } of measured ) rows.push( await qhullRow( dataset, pointsFile, cgalResult, log ) );

	let timedOutAt = Infinity; // point count on which delaunay-triangulate timed out
	for ( const { dataset, pointsFile, cgalResult, rows } of measured ) {

		const row = await peerRow( dataset, pointsFile, cgalResult, timedOutAt, log );
		if ( row.status?.startsWith( 'timeout' ) ) timedOutAt = pointCount( dataset );
		rows.push( row );

	}

	// Ours ÷ the peers other than CGAL (CGAL's ratio is already `ratio`), in the ours row.
	for ( const { rows } of measured ) {

		const [ oursRow, , ...peers ] = rows;
		if ( oursRow.median === null ) continue;
		for ( const peer of peers ) {

			if ( peer.median !== null ) ( oursRow.ratios ??= [] ).push( { peer: peer.subject, ratio: oursRow.median / peer.median } );

		}

	}

	return measured.flatMap( ( { rows } ) => rows );

}

interface OursTimed {
	summary: Summary;
	result: Tetrahedralization;
}

interface CgalTimed {
	/** CGAL's result (cells, volume, validity), which also serves to check ours. */
	result: CgalResult;
	/** Each run of ours ÷ the median of the CGAL process before it. */
	ratios: number[];
}

/**
 * Ours and CGAL on one set, interleaved (see the notes): warm-up calls of ours, then rounds of one
 * CGAL process (CGAL_PER_ROUND triangulations) and one run of ours. Without CGAL, ours alone as timeRuns does.
 */
async function timeWithCgal(
	dataset: Dataset, pointsFile: string, tetrahedralize: ( ( points: ArrayLike<number> ) => Tetrahedralization ) | undefined,
	missing: string | null, cgal: { binary: string | null, reason: string }, subject: string, log: ( message: string ) => void,
): Promise<{ ours: OursTimed | string, cgal: CgalTimed | null, cgalRow: BenchRow }> {

	const count = pointCount( dataset );
	const cgalRow: BenchRow = { case: dataset.name, subject, unit: 'ms', median: null, min: null, max: null, runs: 0, status: cgal.reason };
	if ( ! tetrahedralize || missing ) return { ours: missing ?? 'not available', cgal: null, cgalRow };

	const run = (): { ms: number, result: Tetrahedralization } => {

		collectGarbage();
		const start = performance.now();
		const result = tetrahedralize( dataset.points );
		return { ms: performance.now() - start, result };

	};

	if ( ! cgal.binary ) {

		log( `${dataset.name}: ours …` );
		try {

			const maxRuns = count <= 2000 ? 15 : count <= 20000 ? 9 : 5;
			return { ours: timeRuns( () => tetrahedralize( dataset.points ), maxRuns, 8000 ), cgal: null, cgalRow };

		} catch ( error ) {

			return { ours: 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ], cgal: null, cgalRow };

		}

	}

	log( `${dataset.name}: ours and CGAL, interleaved …` );
	let result: Tetrahedralization;
	try {

		// Warm up (JIT) as timeRuns does: up to 10 calls or 300 ms.
		let spent = 0;
		result = run().result;
		for ( let calls = 1; calls < 10 && spent < 300; calls ++ ) spent += run().ms;

	} catch ( error ) {

		return { ours: 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ], cgal: null, cgalRow };

	}

	const oursMs: number[] = [], cgalMs: number[] = [], ratios: number[] = [];
	let cgalResult: CgalResult | null = null;
	for ( let round = 0; round < roundsFor( count ); round ++ ) {

		collectGarbage();
		try {

			const batch = await runCgal( cgal.binary, pointsFile, CGAL_PER_ROUND );
			cgalResult ??= batch;
			const ms = batch.seconds.map( ( seconds ) => seconds * 1000 );
			cgalMs.push( ...ms );
			const { ms: ours } = run();
			oursMs.push( ours );
			ratios.push( ours / summarize( ms ).median );

		} catch ( error ) {

			cgalRow.status = 'failed: ' + ( error as Error ).message.split( '\n' )[ 0 ];
			return { ours: timeRuns( () => tetrahedralize( dataset.points ), 5, 8000 ), cgal: null, cgalRow };

		}

	}

	const valid = cgalResult!.valid ? 'valid (is_valid)' : 'INVALID (is_valid)';
	Object.assign( cgalRow, summarize( cgalMs ), { output: tetrahedraLabel( cgalResult!.cells, dataset ), status: valid } );
	return { ours: { summary: summarize( oursMs ), result }, cgal: { result: cgalResult!, ratios }, cgalRow };

}

/** Qhull via SciPy in a Python child process, several runs; skipped when SciPy is absent. */
async function qhullRow(
	dataset: Dataset, pointsFile: string, cgal: CgalResult | null, log: ( message: string ) => void
): Promise<BenchRow> {

	const versions = scipyVersions();
	const subject = versions ? `Qhull (SciPy ${versions.scipy})` : 'Qhull (SciPy)';
	const row: BenchRow = { case: dataset.name, subject, unit: 'ms', median: null, min: null, max: null, runs: 0 };
	if ( versions ) log( `${dataset.name}: Qhull via SciPy (python3 child process) …` );
	const result = await runQhull( pointsFile, pointCount( dataset ) > 20000 ? 3 : 9 );
	if ( ! result.ok ) return { ...row, status: result.reason };

	const checks = [ `${result.flat} flat`, ...compareWithHull( dataset, result.tetrahedra, result.volume, cgal ) ];
	return { ...row, ...summarize( result.seconds.map( ( s ) => s * 1000 ) ), output: tetrahedraLabel( result.tetrahedra, dataset ), status: checks.join( '; ' ) };

}

/** npm delaunay-triangulate, one run in a child process; skipped from the set size it timed out on. */
async function peerRow(
	dataset: Dataset, pointsFile: string, cgal: CgalResult | null, timedOutAt: number, log: ( message: string ) => void
): Promise<BenchRow> {

	const row: BenchRow = { case: dataset.name, subject: 'delaunay-triangulate', unit: 'ms', median: null, min: null, max: null, runs: 0 };
	if ( pointCount( dataset ) >= timedOutAt ) return { ...row, status: `skipped (timed out on ${timedOutAt.toLocaleString( 'en-US' )} points)` };

	log( `${dataset.name}: delaunay-triangulate (child process, ≤ 60 s) …` );
	const result = await runDelaunayTriangulate( pointsFile );
	if ( ! result.ok ) return { ...row, status: result.reason };

	const checks = [ `${result.flat} flat`, `${result.inverted} inverted`, ...compareWithHull( dataset, result.tetrahedra, result.volume, cgal ) ];
	return { ...row, median: result.ms, min: result.ms, max: result.ms, runs: 1, output: tetrahedraLabel( result.tetrahedra, dataset ), status: checks.join( '; ' ) };

}

function oursRow(
	dataset: Dataset, timed: OursTimed | string, missing: string | null, cgal: CgalTimed | null, cgalName: string,
): BenchRow {

	const targetMs = TARGET_MS[ dataset.name ];
	const timeTarget: Target = { text: `≤ ${targetMs >= 1000 ? targetMs / 1000 + ' s' : targetMs + ' ms'}` };
	const validTarget: Target = { text: 'valid' };
	const ratioTarget: Target = { text: `≤ ${TARGET_RATIO}× CGAL` };
	const targets = targetMs ? [ timeTarget, ...( dataset.grid ? [ validTarget ] : [] ), ratioTarget ] : [ ratioTarget ];
	const row: BenchRow = { case: dataset.name, subject: 'ours', unit: 'ms', median: null, min: null, max: null, runs: 0, targets };
	if ( typeof timed === 'string' ) return { ...row, status: missing ?? timed };

	const { summary, result } = timed;
	const tetrahedronCount = result.tetrahedra.length / 4;
	const failures = check( dataset, result, cgal?.result ?? null );
	Object.assign( row, summary, { output: tetrahedraLabel( tetrahedronCount, dataset ), status: failures.length ? 'INVALID: ' + failures.join( '; ' ) : 'valid' } );

	if ( cgal ) {

		row.peer = cgalName;
		row.ratio = summarize( cgal.ratios ).median;

	}

	timeTarget.met = summary.median <= targetMs;
	validTarget.met = failures.length === 0;
	if ( row.ratio !== undefined ) ratioTarget.met = row.ratio <= TARGET_RATIO;
	return row;

}

/** Cheap checks of our output; returns what failed (empty when valid). */
function check( dataset: Dataset, result: Tetrahedralization, cgal: CgalResult | null ): string[] {

	const { points } = dataset;
	const { tetrahedra, neighbors, duplicates } = result;
	const count = tetrahedra.length / 4;
	const failures: string[] = [];

	let flat = 0, inverted = 0, volume = 0;
	for ( let t = 0; t < count; t ++ ) {

		const a = tetrahedra[ 4 * t ], b = tetrahedra[ 4 * t + 1 ], c = tetrahedra[ 4 * t + 2 ], d = tetrahedra[ 4 * t + 3 ];
		const sign = orientation( points, a, b, c, d );
		if ( sign === 0 ) flat ++;
		else if ( sign < 0 ) inverted ++;
		volume += signedVolume( points, a, b, c, d );

	}

	if ( flat ) failures.push( `${flat} flat` );
	if ( inverted ) failures.push( `${inverted} inverted` );

	let oneSided = 0;
	for ( let t = 0; t < count; t ++ ) {

		for ( let i = 0; i < 4; i ++ ) {

			const n = neighbors[ 4 * t + i ];
			if ( n < 0 ) continue;
			if ( n >= count || (
				neighbors[ 4 * n ] !== t && neighbors[ 4 * n + 1 ] !== t && neighbors[ 4 * n + 2 ] !== t && neighbors[ 4 * n + 3 ] !== t
			) ) oneSided ++;

		}

	}

	if ( oneSided ) failures.push( `${oneSided} neighbor links not mutual` );
	if ( duplicates.length ) failures.push( `${duplicates.length} duplicates reported (the set has none)` );

	return failures.concat( compareWithHull( dataset, count, volume, cgal ) );

}

/**
 * The volume must fill the grid's box (grids) or CGAL's convex hull (random sets), and for random
 * sets, in general position, the Delaunay tetrahedralization is unique: CGAL's count is the count.
 */
function compareWithHull( dataset: Dataset, count: number, volume: number, cgal: CgalResult | null ): string[] {

	const failures: string[] = [];
	const expectedVolume = dataset.grid ? boxVolume( dataset.points ) : cgal?.volume;
	if ( expectedVolume !== undefined && Math.abs( volume - expectedVolume ) > VOLUME_TOLERANCE * expectedVolume ) {

		failures.push( `volume ${volume.toPrecision( 10 )} ≠ ${dataset.grid ? 'box' : 'hull'} ${expectedVolume.toPrecision( 10 )}` );

	}

	if ( ! dataset.grid && cgal && cgal.cells !== count ) failures.push( `${count} tetrahedra ≠ CGAL's ${cgal.cells}` );
	return failures;

}

function tetrahedraLabel( count: number, dataset: Dataset ): string {

	const label = `${count.toLocaleString( 'en-US' )} tetrahedra`;
	if ( ! dataset.grid ) return label;
	const [ nx, ny, nz ] = dataset.grid;
	return `${label} (${( count / ( ( nx - 1 ) * ( ny - 1 ) * ( nz - 1 ) ) ).toFixed( 2 )}/cell)`;

}
