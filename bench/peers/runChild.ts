/**
 * Runs a peer in a child process with a hard time limit and reads its one JSON line of results:
 * peers that may take minutes (or never finish) must not hold up the benchmark.
 */

import { spawn } from 'node:child_process';

/** What the child printed as JSON, or why there is nothing. */
export type ChildResult<T> = ( { ok: true } & T ) | { ok: false, reason: string, timedOut: boolean };

/** Runs `command args`, killing it after `timeLimitMs`; a non-zero exit reports stderr's last line. */
export function runChild<T extends object>( command: string, args: string[], timeLimitMs: number ): Promise<ChildResult<T>> {

	return new Promise( ( resolve ) => {

		const child = spawn( command, args, { stdio: [ 'ignore', 'pipe', 'pipe' ] } );
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
			else resolve( { ok: true, ...JSON.parse( stdout ) as T } );

		} );

	} );

}
