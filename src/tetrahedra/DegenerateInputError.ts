/**
 * Why a point set cannot be tetrahedralized: `'unrepresentable'` when float64 cannot hold the
 * points once scaled to unit size (a coordinate below 2^−1022 of the layout's extent; docs/robustness.md).
 */
export type DegenerateReason = 'too-few-points' | 'coincident' | 'collinear' | 'coplanar' | 'unrepresentable';

/**
 * Thrown by `tetrahedralize` (and the meshes built on it) when the points do not span a volume.
 * Coplanar layouts (a single floor of probes) can still be interpolated with a planar mesh; see
 * `createProbeInterpolator`.
 */
export class DegenerateInputError extends Error {

	/** Which degeneracy was found. */
	readonly reason: DegenerateReason;

	constructor( reason: DegenerateReason, message: string ) {

		super( message );
		this.name = 'DegenerateInputError';
		this.reason = reason;

	}

}
