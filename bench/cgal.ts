/**
 * The CGAL peer: compiles bench/cgal/delaunay3.cpp into bench/build/ (only when Debian's
 * libcgal-dev is installed, and only when the source is newer than the binary) and runs it on a
 * points file.
 */

import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, statSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';

const run = promisify( execFile );

const CGAL_HEADERS = '/usr/include/CGAL';
const SOURCE = fileURLToPath( new URL( './cgal/delaunay3.cpp', import.meta.url ) );
export const BUILD_DIR = fileURLToPath( new URL( './build/', import.meta.url ) );
const BINARY = BUILD_DIR + 'delaunay3';

export const CGAL_MISSING = 'not installed (apt-get install libcgal-dev)';

export interface CgalResult {
	/** Seconds per triangulation, timed inside the C++ (file I/O excluded). */
	seconds: number[];
	cells: number;
	vertices: number;
	/** Volume of the finite cells added up: the convex hull's volume. */
	volume: number;
	valid: boolean;
}

/** CGAL's version from its header, e.g. `'5.5.1'`, or null when not installed. */
export function cgalVersion(): string | null {

	const header = CGAL_HEADERS + '/version.h';
	if ( ! existsSync( header ) ) return null;
	const match = /#define CGAL_VERSION\s+(\S+)/.exec( readFileSync( header, 'utf8' ) );
	return match ? match[ 1 ] : 'unknown';

}

/**
 * Compiles the CGAL benchmark if needed.
 * @returns The binary's path, or null (with the reason) when CGAL is not there or the build failed.
 */
export async function buildCgal( log: ( message: string ) => void ): Promise<{ binary: string | null, reason: string }> {

	if ( ! existsSync( CGAL_HEADERS ) ) return { binary: null, reason: CGAL_MISSING };
	if ( existsSync( BINARY ) && statSync( BINARY ).mtimeMs >= statSync( SOURCE ).mtimeMs ) return { binary: BINARY, reason: '' };

	mkdirSync( BUILD_DIR, { recursive: true } );
	log( 'compiling bench/cgal/delaunay3.cpp (g++ -O2, about 10 s) …' );
	try {

		// -DNDEBUG turns off CGAL's internal assertions, as its own release builds do.
		await run( 'g++', [ '-O2', '-DNDEBUG', '-std=c++17', SOURCE, '-o', BINARY, '-lgmp' ] );
		return { binary: BINARY, reason: '' };

	} catch ( error ) {

		const message = ( error as { stderr?: string } ).stderr || String( error );
		return { binary: null, reason: 'build failed: ' + message.split( '\n' )[ 0 ] };

	}

}

/** Triangulates the points of `pointsFile` `repeats` times in one process. */
export async function runCgal( binary: string, pointsFile: string, repeats: number ): Promise<CgalResult> {

	const { stdout } = await run( binary, [ pointsFile, String( repeats ) ], { maxBuffer: 1 << 20 } );
	return JSON.parse( stdout ) as CgalResult;

}
