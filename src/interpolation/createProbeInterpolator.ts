import { DegenerateInputError, readOptions } from '../tetrahedra/tetrahedralize.js';
import { TetrahedralMesh, type TetrahedralMeshOptions } from './TetrahedralMesh.js';
import { PlanarMesh } from './PlanarMesh.js';

/**
 * The interpolation structure for arbitrary probe positions: a {@link TetrahedralMesh}, or — when
 * the probes all lie in one plane (a single floor of probes, a photo map) — a {@link PlanarMesh}
 * in their best-fit plane, so flat layouts still interpolate.
 * @throws {DegenerateInputError} for fewer than 3 distinct probes or probes on one line.
 * @throws {TypeError|RangeError} for options that are not an object or tolerances that are not
 *   finite numbers ≥ 0, named as this function's.
 */
export function createProbeInterpolator(
	positions: ArrayLike<number>, options: TetrahedralMeshOptions = {},
): TetrahedralMesh | PlanarMesh {

	readOptions( 'createProbeInterpolator', options );
	try {

		return new TetrahedralMesh( positions, options );

	} catch ( error ) {

		if ( error instanceof DegenerateInputError && ( error.reason === 'coplanar' || error.reason === 'too-few-points' ) ) {

			return new PlanarMesh( positions, options.duplicateTolerance );

		}

		throw error;

	}

}
