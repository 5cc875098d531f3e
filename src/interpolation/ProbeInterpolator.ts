/**
 * What every probe interpolation structure offers: for a world position, which probes to blend and
 * with which weights. The tetrahedral mesh gives 4, the regular grid 8, the planar mesh 3 (padded to
 * 4 with a zero weight). Feed the result to `blendSH`.
 */
export interface ProbeInterpolator {

	/** Number of probes the structure indexes. */
	readonly probeCount: number;

	/** Number of cells: tetrahedra, grid boxes or triangles. */
	readonly cellCount: number;

	/** How many (index, weight) pairs {@link ProbeInterpolator.interpolate} writes. */
	readonly weightCount: number;

	/**
	 * Writes the probes and weights that interpolate the field at (x, y, z). Weights are ≥ 0 and sum
	 * to 1. Allocation-free.
	 * @param indices Receives `weightCount` probe indices.
	 * @param weights Receives `weightCount` weights.
	 * @param hint The value this method returned for a nearby position (e.g. last frame), or −1.
	 * @returns A cell index to pass back as the next `hint`.
	 */
	interpolate(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint?: number,
	): number;

}
