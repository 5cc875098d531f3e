/**
 * Runs the benchmarks: every bench/*.bench.ts, or those whose file name contains one of the
 * arguments (`npm run bench -- tetra`). Prints the tables and writes bench/results/latest.md and
 * bench/results/latest.json with the machine, Node and package versions.
 */

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { availableParallelism, cpus, loadavg, platform, release, totalmem } from 'node:os';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { resolveChromiumPath } from '../cli/chromium.js';
import { cgalVersion } from './cgal.js';
import { scipyVersions } from './peers/scipyQhull.js';
import type { BenchModule, BenchRow } from './types.js';

const BENCH_DIR = fileURLToPath( new URL( '.', import.meta.url ) );
const ROOT = fileURLToPath( new URL( '..', import.meta.url ) );
const RESULTS_DIR = BENCH_DIR + 'results/';

interface BenchReport {
	name: string;
	title: string;
	notes: string[];
	seconds: number;
	rows: BenchRow[];
	error?: string;
	/** When and on which revision this bench ran (a filtered run keeps the others' earlier results). */
	measured?: string;
}

async function main(): Promise<void> {

	const filters = process.argv.slice( 2 );
	const files = readdirSync( BENCH_DIR )
		.filter( ( file ) => file.endsWith( '.bench.ts' ) )
		.filter( ( file ) => filters.length === 0 || filters.some( ( filter ) => file.includes( filter ) ) )
		.sort();
	if ( files.length === 0 ) throw new Error( `no bench/*.bench.ts matches ${filters.join( ', ' )}` );

	const environment = describeEnvironment();
	const started = performance.now();
	const benches: BenchReport[] = [];

	for ( const file of files ) {

		const name = file.replace( /\.bench\.ts$/, '' );
		const log = ( message: string ) => process.stderr.write( `[${name}] ${message}\n` );
		const start = performance.now();
		let report: BenchReport;
		try {

			const bench = await import( pathToFileURL( BENCH_DIR + file ).href ) as BenchModule;
			const rows = await bench.run( log );
			report = { name, title: bench.title, notes: bench.notes ?? [], seconds: ( performance.now() - start ) / 1000, rows };

		} catch ( error ) {

			log( 'failed: ' + ( ( error as Error ).stack ?? error ) );
			const seconds = ( performance.now() - start ) / 1000;
			report = { name, title: name, notes: [], seconds, rows: [], error: String( ( error as Error ).message ?? error ) };

		}

		benches.push( report );
		process.stdout.write( '\n' + benchMarkdown( report ) + '\n' );

	}

	const totalSeconds = ( performance.now() - started ) / 1000;
	environment.load.end = loadAverage();
	const stamp = `${environment.date.slice( 0, 16 ).replace( 'T', ' ' )} UTC, ${environment.packages[ 'three-capture-lighting' ]}`;
	for ( const bench of benches ) bench.measured = stamp;

	// A filtered run (npm run bench -- capture) replaces only its own benches in the results.
	if ( filters.length > 0 && existsSync( RESULTS_DIR + 'latest.json' ) ) {

		const previous = JSON.parse( readFileSync( RESULTS_DIR + 'latest.json', 'utf8' ) ) as { benches?: BenchReport[] };
		for ( const old of previous.benches ?? [] ) {

			if ( ! benches.some( ( bench ) => bench.name === old.name ) ) benches.push( old );

		}

		benches.sort( ( a, b ) => a.name.localeCompare( b.name ) );

	}

	const results = { ...environment, filters, totalSeconds, benches };
	const markdown = [ headerMarkdown( environment, filters, totalSeconds ), ...benches.map( benchMarkdown ) ].join( '\n' );

	mkdirSync( RESULTS_DIR, { recursive: true } );
	writeFileSync( RESULTS_DIR + 'latest.md', markdown );
	writeFileSync( RESULTS_DIR + 'latest.json', JSON.stringify( results, null, '\t' ) + '\n' );
	process.stdout.write( `\nTotal ${totalSeconds.toFixed( 0 )} s. Written bench/results/latest.md and bench/results/latest.json\n` );

}

function describeEnvironment() {

	const cpuInfo = existsSync( '/proc/cpuinfo' ) ? readFileSync( '/proc/cpuinfo', 'utf8' ) : '';
	const cpu = /^model name\s*:\s*(.+)$/m.exec( cpuInfo )?.[ 1 ] ?? cpus()[ 0 ]?.model ?? 'unknown';
	const scipy = scipyVersions();
	const osRelease = existsSync( '/etc/os-release' ) ? /^PRETTY_NAME="?([^"\n]+)"?$/m.exec( readFileSync( '/etc/os-release', 'utf8' ) )?.[ 1 ] : undefined;

	return {
		date: new Date().toISOString(),
		machine: {
			cpu,
			cores: availableParallelism(),
			memoryGiB: Math.round( totalmem() / 2 ** 30 * 10 ) / 10,
			os: `${osRelease ? osRelease + ', ' : ''}${platform()} ${release()}`,
		},
		/** 1/5/15-minute load averages at the start and the end: other work on the machine distorts the figures. */
		load: { start: loadAverage(), end: '' },
		node: process.version,
		packages: {
			'three-capture-lighting': packageVersion( ROOT ) + gitRevision(),
			three: packageVersion( ROOT + 'node_modules/three/' ),
			'delaunay-triangulate': packageVersion( ROOT + 'node_modules/delaunay-triangulate/' ),
			CGAL: cgalVersion() ?? 'not installed',
			'g++': command( 'g++', [ '-dumpfullversion' ] ) ?? 'not installed',
			Chromium: chromiumVersion(),
			'puppeteer-core': packageVersion( ROOT + 'node_modules/puppeteer-core/' ),
			gl: packageVersion( ROOT + 'node_modules/gl/' ),
			python3: command( 'python3', [ '-c', 'import sys; print(sys.version.split()[0])' ] ) ?? 'not installed',
			SciPy: scipy ? `${scipy.scipy} (NumPy ${scipy.numpy})` : 'not installed',
		},
	};

}

function loadAverage(): string {

	return loadavg().map( ( value ) => value.toFixed( 2 ) ).join( ' / ' );

}

/** The browser the Chromium benches drive (by cli/chromium.ts's rule), e.g. `'156.0.8078.79'`. */
function chromiumVersion(): string {

	const binary = resolveChromiumPath().path;
	const version = existsSync( binary ) ? command( binary, [ '--version' ] ) : null;
	return version ? ( /[\d.]+/.exec( version )?.[ 0 ] ?? version ) : 'not installed';

}

function packageVersion( directory: string ): string {

	try {

		return ( JSON.parse( readFileSync( directory + 'package.json', 'utf8' ) ) as { version: string } ).version;

	} catch {

		return 'not installed';

	}

}

/** ` (abc1234)` or ` (abc1234, modified)`, or '' outside git or before the first commit. */
function gitRevision(): string {

	const revision = command( 'git', [ 'rev-parse', '--short', 'HEAD' ] );
	if ( ! revision ) return '';
	const modified = command( 'git', [ 'status', '--porcelain', '--', 'src' ] );
	return ` (${revision}${modified ? ', src modified' : ''})`;

}

function command( file: string, args: string[] ): string | null {

	try {

		return execFileSync( file, args, { cwd: ROOT, encoding: 'utf8', stdio: [ 'ignore', 'pipe', 'ignore' ] } ).trim();

	} catch {

		return null;

	}

}

function headerMarkdown( environment: ReturnType<typeof describeEnvironment>, filters: string[], totalSeconds: number ): string {

	const { machine, packages } = environment;
	return [
		'# three-capture-lighting benchmarks',
		'',
		`- Date: ${environment.date}`,
		`- Machine: ${machine.cpu}, ${machine.cores} cores, ${machine.memoryGiB} GiB, ${machine.os}`,
		`- Load average (1 / 5 / 15 min): ${environment.load.start} at the start, ${environment.load.end} at the end (on ${machine.cores} cores; above ~1 other work distorts the figures, ratios from one run stay comparable)`,
		`- Node ${environment.node}; ` + Object.entries( packages ).map( ( [ name, version ] ) => `${name} ${version}` ).join( ', ' ),
		`- Command: npm run bench${filters.length ? ' -- ' + filters.join( ' ' ) : ''} (${totalSeconds.toFixed( 0 )} s)`,
		'',
	].join( '\n' );

}

function benchMarkdown( report: BenchReport ): string {

	const lines = [ `## ${report.title}`, '' ];
	if ( report.measured ) lines.push( `Measured ${report.measured}.`, '' );
	if ( report.error ) lines.push( `Failed: ${report.error}`, '' );

	if ( report.rows.length ) {

		const units = [ ...new Set( report.rows.map( ( row ) => row.unit ) ) ].join( ', ' );
		const header = [ 'Case', 'Subject', `Median (${units})`, 'Min', 'Max', 'Runs', 'Output', 'Check', 'Ratio', 'Target' ];
		const body = report.rows.map( ( row ) => [
			row.case,
			row.subject,
			formatNumber( row.median ),
			formatNumber( row.min ),
			formatNumber( row.max ),
			row.runs ? String( row.runs ) : '',
			row.output ?? '',
			row.status ?? '',
			[ ...( row.ratio !== undefined ? [ { peer: row.peer ?? '', ratio: row.ratio } ] : [] ), ...( row.ratios ?? [] ) ].map( ( { peer, ratio } ) => `${formatRatio( ratio )}× ${peer}` ).join( ', ' ),
			( row.targets ?? [] ).map( ( { text, met } ) => text + ( met === undefined ? '' : met ? ' ✓' : ' ✗' ) ).join( ', ' ),
		] );
		lines.push( ...table( header, body ), '' );

	}

	for ( const note of report.notes ) lines.push( `- ${note}` );
	lines.push( '', `(${report.seconds.toFixed( 0 )} s)`, '' );
	return lines.join( '\n' );

}

function formatNumber( value: number | null ): string {

	if ( value === null ) return '—';
	return value >= 100 ? value.toFixed( 0 ) : value >= 10 ? value.toFixed( 1 ) : value.toFixed( 2 );

}

/** Two decimals, or two significant digits below 0.1 (ours ÷ a peer 300 times slower is 0.0033×, not 0.00×). */
function formatRatio( ratio: number ): string {

	return ratio >= 0.1 || ratio === 0 ? ratio.toFixed( 2 ) : ratio.toPrecision( 2 );

}

/** A Markdown table with padded columns, readable as plain text too. */
function table( header: string[], body: string[][] ): string[] {

	const cells = [ header, ...body ].map( ( row ) => row.map( ( cell ) => cell.replace( /\|/g, '\\|' ) ) );
	const widths = header.map( ( _, column ) => Math.max( 3, ...cells.map( ( row ) => row[ column ].length ) ) );
	const line = ( row: string[] ) => '| ' + row.map( ( cell, column ) => cell.padEnd( widths[ column ] ) ).join( ' | ' ) + ' |';
	return [ line( cells[ 0 ] ), '| ' + widths.map( ( width ) => '-'.repeat( width ) ).join( ' | ' ) + ' |', ...cells.slice( 1 ).map( line ) ];

}

try {

	await main();

} catch ( error ) {

	process.stderr.write( `bench: ${( error as Error ).message}\n` );
	process.exitCode = 1;

}
