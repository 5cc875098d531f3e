import { findInitialTetrahedron } from '../src/tetrahedra/initialTetrahedron.js';
import { mergeDuplicates } from '../src/tetrahedra/mergeDuplicates.js';
import { normalizePoints } from '../src/tetrahedra/normalizePoints.js';
import { DegenerateInputError } from '../src/tetrahedra/tetrahedralize.js';

/** What a probe layout spans, decided as `tetrahedralize` and `LightProbeVolume` decide it. */
export type LayoutShape = 'volume' | 'plane' | 'line' | 'point';

/** The shape of a layout and its duplicate probes ({@link layoutShape}). */
export interface LayoutShapeResult {

	shape: LayoutShape;

	/** Merged pairs, flat: (merged probe, the earlier probe it coincides with). */
	duplicates: Uint32Array;

	/** Distinct probes. */
	distinct: number;

}

// tetrahedralize's defaults: the same layouts merge and flatten here as in the library.
const DUPLICATE_TOLERANCE = 1e-9;
const PLANAR_TOLERANCE = 1e-9;

/**
 * Whether probe positions span a volume (tetrahedralized), a plane (`LightProbeVolume` triangulates
 * them in it), a line (interpolated along it) or one point, and which probes coincide — with
 * `tetrahedralize`'s own normalisation, duplicate merging and tolerances, in time linear in the probes.
 * @param positions x, y, z per probe (at least one probe, finite).
 * @throws {DegenerateInputError} ('unrepresentable') for a coordinate float64 cannot hold beside the layout's extent.
 */
export function layoutShape( positions: ArrayLike<number> ): LayoutShapeResult {

	const count = positions.length / 3;
	const p = Float64Array.from( positions );
	normalizePoints( 'capture-lighting', 'positions', p, count );
	const { unique, duplicates, diagonal } = mergeDuplicates( p, DUPLICATE_TOLERANCE );
	const result = ( shape: LayoutShape ): LayoutShapeResult => ( { shape, duplicates, distinct: unique.length } );
	if ( unique.length === 1 ) return result( 'point' );
	try {

		// Decides for 2 or 3 distinct probes too: they are on a line, or (3 off a line) in a plane.

		findInitialTetrahedron( 'capture-lighting', p, unique, diagonal, PLANAR_TOLERANCE );
		return result( 'volume' );

	} catch ( error ) {

		if ( error instanceof DegenerateInputError && error.reason === 'coplanar' ) return result( 'plane' );
		if ( error instanceof DegenerateInputError && error.reason === 'collinear' ) return result( 'line' );
		throw error;

	}

}
