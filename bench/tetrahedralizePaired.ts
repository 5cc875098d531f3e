/**
 * Paired timing of `tetrahedralize` for speed work on a shared, noisy machine: the current code
 * against another build of it (an older checkout, e.g. a `git worktree` of the last commit) and
 * against CGAL, interleaved in one process so that both sides of each pair see the same load.
 * Not part of `npm run bench` (no `.bench.ts` suffix); run it by hand:
 *
 *   node --import tsx bench/tetrahedralizePaired.ts [--old path/to/src/tetrahedra/tetrahedralize.ts]
 *     [--cgal] [--cpu] [--pairs 7] [--sets 'random 10k,random 100k'] [--verbose]
 *
 * Each pair runs, after warm-up calls of each side: CGAL (a batch of triangulations in one process,
 * their median; with --cgal; with --cpu too, cgal/delaunay3Cpu.cpp, the same program timed by its
 * CPU clock, built into build/delaunay3-cpu), then the old and the new code alternately, a batch of calls each
 * (9 below 2,000 points, 5 below 20,000, else 1; a full GC before each call), their medians. It
 * prints per set the medians of the times and of the per-pair ratios, and checks that the new
 * code's output is byte for byte the old one's.
 */

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, statSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { buildCgal, BUILD_DIR, runCgal } from './cgal.js';
import { allDatasets, pointCount, writePointsFile } from './datasets.js';
import { collectGarbage, summarize } from './stats.js';

type Tetrahedralize = ( points: ArrayLike<number> ) => { tetrahedra: Uint32Array; neighbors: Int32Array; duplicates: Uint32Array };

function option( name: string ): string | undefined {

	const index = process.argv.indexOf( name );
	return index >= 0 ? process.argv[ index + 1 ] : undefined;

}

function sameBytes( a: ArrayBufferView, b: ArrayBufferView ): boolean {

	if ( a.byteLength !== b.byteLength ) return false;
	const x = new Uint8Array( a.buffer, a.byteOffset, a.byteLength ), y = new Uint8Array( b.buffer, b.byteOffset, b.byteLength );
	for ( let i = 0; i < x.length; i ++ ) if ( x[ i ] !== y[ i ] ) return false;
	return true;

}

// --cpu: time the process's CPU (user + system) instead of the wall clock, which on an
// oversubscribed machine also counts the time the process waited for a core.
const cpuClock = process.argv.includes( '--cpu' );

/** Compiles cgal/delaunay3Cpu.cpp when it is newer than its binary (as cgal.ts does for delaunay3.cpp). */
function buildCgalCpu(): string {

	const source = fileURLToPath( new URL( './cgal/delaunay3Cpu.cpp', import.meta.url ) ), binary = BUILD_DIR + 'delaunay3-cpu';
	if ( ! existsSync( binary ) || statSync( binary ).mtimeMs < statSync( source ).mtimeMs ) {

		execFileSync( 'g++', [ '-O2', '-DNDEBUG', '-std=c++17', source, '-o', binary, '-lgmp' ] );

	}

	return binary;

}

/** Milliseconds of one call, after a full GC. */
function timeOnce( fn: Tetrahedralize, points: Float64Array ): number {

	collectGarbage();
	if ( cpuClock ) {

		const before = process.cpuUsage();
		fn( points );
		const spent = process.cpuUsage( before );
		return ( spent.user + spent.system ) / 1000;

	}

	const start = performance.now();
	fn( points );
	return performance.now() - start;

}

async function main(): Promise<void> {

	const oldPath = option( '--old' ) ?? '/tmp/tetra-old/src/tetrahedra/tetrahedralize.ts';
	const pairs = Number( option( '--pairs' ) ?? 7 );
	const wanted = option( '--sets' )?.split( ',' );
	const withCgal = process.argv.includes( '--cgal' );

	const current = ( await import( '../src/tetrahedra/tetrahedralize.js' ) ).tetrahedralize as Tetrahedralize;
	const old = ( await import( oldPath ) ).tetrahedralize as Tetrahedralize;
	mkdirSync( BUILD_DIR, { recursive: true } );
	let cgal = withCgal ? ( await buildCgal( ( message ) => process.stderr.write( message + '\n' ) ) ).binary : null;
	if ( withCgal && ! cgal ) throw new Error( 'CGAL is not available (bench/cgal.ts buildCgal)' );
	if ( cgal && cpuClock ) cgal = buildCgalCpu();

	const rows: string[] = [];
	for ( const dataset of allDatasets().filter( ( d ) => ! wanted || wanted.includes( d.name ) ) ) {

		const { points } = dataset;
		const reference = old( points ), result = current( points );
		const identical = sameBytes( reference.tetrahedra, result.tetrahedra ) && sameBytes( reference.neighbors, result.neighbors ) &&
			sameBytes( reference.duplicates, result.duplicates );
		const warmUps = pointCount( dataset ) > 20000 ? 2 : 10;
		for ( let i = 0; i < warmUps; i ++ ) {

			timeOnce( old, points );
			timeOnce( current, points );

		}

		const pointsFile = `${BUILD_DIR}points-paired-${dataset.name.replace( /\W+/g, '-' )}.f64`;
		if ( cgal ) writePointsFile( pointsFile, points );

		const count = pointCount( dataset );
		const batch = count < 2000 ? 9 : count < 20000 ? 5 : 1;
		const median = ( values: number[] ) => values.length ? summarize( values ).median : NaN;
		const oldTimes: number[] = [], newTimes: number[] = [], cgalTimes: number[] = [];
		const newOverOld: number[] = [], newOverCgal: number[] = [], oldOverCgal: number[] = [];
		for ( let i = 0; i < pairs; i ++ ) {

			let cgalMs = NaN;
			if ( cgal ) cgalMs = median( ( await runCgal( cgal, pointsFile, Math.max( 3, batch ) ) ).seconds.map( ( s ) => s * 1000 ) );
			const oldBatch: number[] = [], newBatch: number[] = [];
			for ( let j = 0; j < batch; j ++ ) {

				if ( ( i + j ) % 2 === 0 ) {

					oldBatch.push( timeOnce( old, points ) );
					newBatch.push( timeOnce( current, points ) );

				} else {

					newBatch.push( timeOnce( current, points ) );
					oldBatch.push( timeOnce( old, points ) );

				}

			}

			const oldMs = median( oldBatch ), newMs = median( newBatch );

			oldTimes.push( oldMs ); newTimes.push( newMs ); newOverOld.push( newMs / oldMs );
			if ( cgal ) {

				cgalTimes.push( cgalMs ); newOverCgal.push( newMs / cgalMs ); oldOverCgal.push( oldMs / cgalMs );

			}

		}

		const row = [
			dataset.name.padEnd( 12 ), `old ${median( oldTimes ).toFixed( 2 )} ms`, `new ${median( newTimes ).toFixed( 2 )} ms`,
			`new/old ${median( newOverOld ).toFixed( 3 )}`,
			...( cgal ? [ `CGAL ${median( cgalTimes ).toFixed( 2 )} ms`, `new/CGAL ${median( newOverCgal ).toFixed( 3 )}`,
				`old/CGAL ${median( oldOverCgal ).toFixed( 3 )}` ] : [] ),
			identical ? 'output identical' : 'OUTPUT DIFFERS',
		].join( ' | ' );
		rows.push( row );
		process.stdout.write( row + '\n' );
		if ( process.argv.includes( '--verbose' ) ) {

			process.stdout.write( `  new/old per pair: ${newOverOld.map( ( r ) => r.toFixed( 3 ) ).join( ' ' )}\n` );
			if ( cgal ) process.stdout.write( `  new/CGAL per pair: ${newOverCgal.map( ( r ) => r.toFixed( 3 ) ).join( ' ' )}\n` );

		}

	}

	process.stdout.write( `(${pairs} pairs per set, ${cpuClock ? 'process CPU time' : 'wall clock'}, old = ${oldPath})\n` );

}

await main();
