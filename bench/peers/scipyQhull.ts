/**
 * The optional Qhull peer: scipy.spatial.Delaunay in a Python child process (scipy_delaunay.py),
 * timed inside Python. Nothing is installed: when `python3 -c "import scipy.spatial"` fails the
 * peer is reported as skipped.
 */

import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { runChild, type ChildResult } from './runChild.js';

const SCRIPT = fileURLToPath( new URL( './scipy_delaunay.py', import.meta.url ) );

/** Why the peer is skipped when SciPy cannot be imported. */
export const SCIPY_MISSING = 'skipped: SciPy not installed (pip install scipy)';

export const QHULL_TIME_LIMIT_MS = 120_000;

export type QhullResult = ChildResult<{ seconds: number[], tetrahedra: number, flat: number, volume: number }>;

let versions: { scipy: string, numpy: string, python: string } | null | undefined;

/** SciPy, NumPy and Python versions, or null when `python3` cannot import scipy.spatial. */
export function scipyVersions(): { scipy: string, numpy: string, python: string } | null {

	if ( versions !== undefined ) return versions;
	try {

		const out = execFileSync( 'python3', [ '-c', 'import sys, numpy, scipy, scipy.spatial; print(scipy.__version__, numpy.__version__, sys.version.split()[0])' ], { encoding: 'utf8', stdio: [ 'ignore', 'pipe', 'ignore' ], timeout: 30_000 } ).trim().split( ' ' );
		versions = { scipy: out[ 0 ], numpy: out[ 1 ], python: out[ 2 ] };

	} catch {

		versions = null;

	}

	return versions;

}

/** Triangulates the points of `pointsFile` (float64 xyz) `repeats` times in one Python process. */
export function runQhull( pointsFile: string, repeats: number, timeLimitMs = QHULL_TIME_LIMIT_MS ): Promise<QhullResult> {

	if ( ! scipyVersions() ) return Promise.resolve( { ok: false, reason: SCIPY_MISSING, timedOut: false } );

	return runChild( 'python3', [ SCRIPT, pointsFile, String( repeats ) ], timeLimitMs );

}
