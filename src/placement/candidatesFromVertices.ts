import { assertNumber, assertPoints } from '../validate.js';
import { thinToSpacing } from './thinToSpacing.js';

/** Options of {@link candidatesFromVertices}. */
export interface CandidatesFromVerticesOptions {

	/**
	 * How far each vertex is moved along its normal, in scene units. Positive moves towards the
	 * side the normal points to (outside a solid, into a room whose normals face inwards).
	 */
	offset: number;

	/**
	 * No two returned candidates are closer than this (≥ 0; 0 keeps every moved vertex). Dense
	 * meshes have far more vertices than a scene needs probes; this is the coarse first cut.
	 */
	minSpacing: number;

}

/**
 * Probe candidates from a background mesh's vertices (paper 2.1): each vertex moved `offset` along
 * its unit normal, then thinned so that no two are closer than `minSpacing`.
 *
 * Thinning is greedy in vertex order — a moved vertex is kept unless an already kept one lies
 * within `minSpacing` — with a hashed grid of cells `minSpacing` wide so that each candidate only
 * looks at its 27 neighbouring cells: O(n) and deterministic (the same input always gives the same
 * output, in vertex order). Every dropped candidate has a kept one within `minSpacing`, so the kept
 * set still covers the surface at that resolution.
 *
 * Vertices whose normal has zero length (degenerate triangles) are skipped: they have no side to
 * move to, and a probe on the surface would capture the inside of the mesh.
 *
 * This is the pure core; `placeFromMeshes` gathers world-space vertices from a three.js scene,
 * calls it and rejects candidates inside geometry.
 * @param positions Flat x, y, z per vertex.
 * @param normals Flat x, y, z per vertex, same length as `positions`; need not be unit length.
 * @returns Flat x, y, z per kept candidate.
 */
export function candidatesFromVertices(
	positions: ArrayLike<number>, normals: ArrayLike<number>, options: CandidatesFromVerticesOptions
): Float64Array {

	const where = 'candidatesFromVertices';
	const count = assertPoints( where, 'positions', positions );
	assertPoints( where, 'normals', normals );
	if ( normals.length !== positions.length ) {

		throw new RangeError( `${where}: normals must have one normal per vertex (length ${positions.length}), got length ${normals.length}.` );

	}

	if ( options === null || typeof options !== 'object' ) throw new TypeError( `${where}: options must be { offset, minSpacing }.` );
	const { offset, minSpacing } = options;
	assertNumber( where, 'options.offset', offset );
	assertNumber( where, 'options.minSpacing', minSpacing );
	if ( minSpacing < 0 ) throw new RangeError( `${where}: options.minSpacing must be ≥ 0, got ${minSpacing}.` );

	const moved = new Float64Array( 3 * count );
	let movedCount = 0;
	for ( let v = 0; v < count; v ++ ) {

		const nx = normals[ 3 * v ], ny = normals[ 3 * v + 1 ], nz = normals[ 3 * v + 2 ];
		const length = Math.sqrt( nx * nx + ny * ny + nz * nz );
		if ( ! ( length > 0 ) ) continue;
		const s = offset / length, o = 3 * movedCount ++;
		moved[ o ] = positions[ 3 * v ] + nx * s;
		moved[ o + 1 ] = positions[ 3 * v + 1 ] + ny * s;
		moved[ o + 2 ] = positions[ 3 * v + 2 ] + nz * s;

	}

	if ( minSpacing === 0 ) return moved.slice( 0, 3 * movedCount );
	return thinToSpacing( moved, movedCount, minSpacing );

}
