/**
 * The npm `delaunay-triangulate` peer, run in a child process with a hard time limit: it lifts
 * the points to a 4D convex hull and takes about a minute for 10k points.
 */

import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const WORKER = fileURLToPath( new URL( './delaunayTriangulateWorker.ts', import.meta.url ) );

export const TIME_LIMIT_MS = 60_000;

export type DelaunayTriangulateResult =
	| { ok: true, ms: number, tetrahedra: number, flat: number, inverted: number, volume: number }
	| { ok: false, reason: string, timedOut: boolean };

/** Triangulates the points of `pointsFile` (float64 xyz) once, killing the child after `timeLimitMs`. */
export function runDelaunayTriangulate( pointsFile: string, timeLimitMs = TIME_LIMIT_MS ): Promise<DelaunayTriangulateResult> {

	return new Promise( ( resolve ) => {

		const child = spawn( process.execPath, [ '--import', 'tsx', WORKER, pointsFile ], { stdio: [ 'ignore', 'pipe', 'pipe' ] } );
		let stdout = '', stderr = '', timedOut = false;
		child.stdout.on( 'data', ( chunk ) => stdout += chunk );
		child.stderr.on( 'data', ( chunk ) => stderr += chunk );

		const timer = setTimeout( () => {

			timedOut = true;
			child.kill( 'SIGKILL' );

		}, timeLimitMs );

		child.on( 'close', ( code ) => {

			clearTimeout( timer );
			if ( timedOut ) resolve( { ok: false, reason: `timeout >${timeLimitMs / 1000} s`, timedOut } );
			else if ( code !== 0 ) resolve( { ok: false, reason: 'failed: ' + ( stderr.trim().split( '\n' ).pop() || `exit ${code}` ), timedOut } );
			else resolve( { ok: true, ...JSON.parse( stdout ) } );

		} );

	} );

}
