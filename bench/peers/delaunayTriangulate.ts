/**
 * The npm `delaunay-triangulate` peer, run in a child process with a hard time limit: it lifts
 * the points to a 4D convex hull and takes about a minute for 10k points.
 */

import { fileURLToPath } from 'node:url';
import { runChild, type ChildResult } from './runChild.js';

const WORKER = fileURLToPath( new URL( './delaunayTriangulateWorker.ts', import.meta.url ) );

export const TIME_LIMIT_MS = 60_000;

export type DelaunayTriangulateResult = ChildResult<{ ms: number, tetrahedra: number, flat: number, inverted: number, volume: number }>;

/** Triangulates the points of `pointsFile` (float64 xyz) once, killing the child after `timeLimitMs`. */
export function runDelaunayTriangulate( pointsFile: string, timeLimitMs = TIME_LIMIT_MS ): Promise<DelaunayTriangulateResult> {

	return runChild( process.execPath, [ '--import', 'tsx', WORKER, pointsFile ], timeLimitMs );

}
