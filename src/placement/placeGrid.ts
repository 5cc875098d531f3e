import { GridInterpolator } from '../interpolation/GridInterpolator.js';
import { checkGridSpec } from '../interpolation/gridSpec.js';

/**
 * Probe positions on a regular grid over a box: the paper's baseline layout and the usual starting
 * point before {@link reduceProbes} turns it into an arbitrary one (paper 3.4).
 *
 * Probe (i, j, k) is at index `i + counts[0] · (j + counts[1] · k)`, x varying fastest — the same
 * order as {@link GridInterpolator}, which lays the probes out here, so a grid placed and captured
 * with this function can be fed to a `GridInterpolator` over the same box unchanged.
 * @param min Box minimum [x, y, z]; the first probe sits here.
 * @param max Box maximum [x, y, z], greater than `min` on every axis; the last probe sits here.
 * @param counts Probes per axis [nx, ny, nz], each ≥ 2.
 * @returns Flat x, y, z per probe (length 3 · nx · ny · nz).
 */
export function placeGrid( min: ArrayLike<number>, max: ArrayLike<number>, counts: ArrayLike<number> ): Float64Array {

	// Checked here as well as in GridInterpolator so that a bad call names placeGrid, the function
	// the user called.
	checkGridSpec( 'placeGrid', min, max, counts );
	return new GridInterpolator( min, max, counts ).positions;

}
