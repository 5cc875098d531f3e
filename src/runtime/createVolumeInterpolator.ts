import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { DegenerateInputError } from '../tetrahedra/tetrahedralize.js';
import { ProbeLineInterpolator } from './ProbeLineInterpolator.js';

/**
 * The default interpolator of a volume or a zone: `createProbeInterpolator` (a `TetrahedralMesh`,
 * or a `PlanarMesh` for coplanar probes), and a {@link ProbeLineInterpolator} for probes that span
 * no plane (fewer than 3 distinct, or all on one line) — any set of at least one probe interpolates.
 */
export function createVolumeInterpolator( positions: ArrayLike<number> ): ProbeInterpolator {

	try {

		return createProbeInterpolator( positions );

	} catch ( error ) {

		const reason = error instanceof DegenerateInputError ? error.reason : null;
		if ( reason === 'too-few-points' || reason === 'coincident' || reason === 'collinear' ) return new ProbeLineInterpolator( positions );
		throw error;

	}

}
