import { describeValue } from '../validate.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';

/**
 * Checks that `value` offers the {@link ProbeInterpolator} interface (an `interpolate` method, an
 * integer `probeCount` ≥ 1 and `weightCount` in 1..64) and returns the two counts.
 */
export function assertInterpolator( where: string, value: unknown ): { probeCount: number; weightCount: number } {

	const candidate = value as Partial<ProbeInterpolator> | null;
	if ( candidate === null || typeof candidate !== 'object' || typeof candidate.interpolate !== 'function' ) {

		throw new TypeError( `${where}: interpolator must be a ProbeInterpolator (TetrahedralMesh, GridInterpolator, PlanarMesh, …), got ${describeValue( value )}.` );

	}

	const { probeCount, weightCount } = candidate;
	if ( typeof probeCount !== 'number' || ! Number.isInteger( probeCount ) || probeCount < 1 ) {

		throw new RangeError( `${where}: interpolator.probeCount must be an integer ≥ 1, got ${describeValue( probeCount )}.` );

	}

	if ( typeof weightCount !== 'number' || ! Number.isInteger( weightCount ) || weightCount < 1 || weightCount > 64 ) {

		throw new RangeError( `${where}: interpolator.weightCount must be an integer in 1..64, got ${describeValue( weightCount )}.` );

	}

	return { probeCount, weightCount };

}
