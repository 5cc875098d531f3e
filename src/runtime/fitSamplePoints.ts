import { TriangleBVH } from '../geometry/TriangleBVH.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import { classifyPointsFor, OPEN_SPACE } from '../placement/classifyPoints.js';
import { keepClass } from '../placement/keepClass.js';
import { cellCentres } from './probeCandidates.js';
import type { StaticGeometry } from './staticGeometry.js';
import type { FittedLayout } from './VolumeFit.js';

/** The most fit points a `fit: { spacing }` capture lays out (before the open-space test). */
export const MAX_FIT_GRID_POINTS = 200_000;

/**
 * The fit points of a `fit: { spacing }` capture: the centres of a grid of cells about `spacing`
 * wide over the live probes' bounding box, kept when inside the probes' hull (the tetrahedra;
 * the whole box for other interpolators) and in open space — at least a quarter spacing from every
 * surface, not inside a solid, and reachable from `reachableFrom` (default: the live probes that
 * are themselves in open space), by `classifyPoints` over the static level.
 * @throws RangeError naming `where` when the grid would exceed {@link MAX_FIT_GRID_POINTS} or no
 * point is left.
 */
export function fitSamplePoints(
	where: string, layout: FittedLayout, geometry: StaticGeometry, spacing: number, reachableFrom?: Float64Array,
): Float64Array {

	const box = liveBounds( layout );
	const counts = [ 0, 1, 2 ].map( ( a ) => Math.max( 2, Math.round( ( box[ 3 + a ] - box[ a ] ) / spacing ) ) );
	const total = counts[ 0 ] * counts[ 1 ] * counts[ 2 ];
	if ( total > MAX_FIT_GRID_POINTS ) {

		throw new RangeError( `${where}: options.fit.spacing ${spacing} lays ${counts.join( ' × ' )} = ${total} fit points over the probes' box, `
			+ `more than ${MAX_FIT_GRID_POINTS}; pass a larger spacing.` );

	}

	const grid = insideHull( layout, cellCentres( box, spacing ) );
	let points = grid;
	if ( geometry.triangles.length > 0 && grid.length > 0 ) {

		const bvh = new TriangleBVH( geometry.triangles );
		const clearance = spacing / 4;
		const seeds = reachableFrom ?? openProbes( where, layout, bvh, geometry.sides, clearance );
		const classes = classifyPointsFor( where, grid, bvh, {
			minDistance: clearance, sides: geometry.sides, reachableFrom: seeds !== null && seeds.length > 0 ? seeds : undefined,
		} );
		points = keepClass( grid, classes, OPEN_SPACE );

	}

	if ( points.length === 0 ) {

		throw new RangeError( `${where}: options.fit.spacing ${spacing} leaves no fit point in open space inside the probes' hull `
			+ `(${grid.length / 3} of ${total} grid points inside it); pass a smaller spacing or options.fit.samples.` );

	}

	return points;

}

/** The live probes' bounding box, [ minX, minY, minZ, maxX, maxY, maxZ ]. */
function liveBounds( layout: FittedLayout ): number[] {

	const box = [ Infinity, Infinity, Infinity, - Infinity, - Infinity, - Infinity ];
	const p = layout.positions;
	for ( let i = 0; i < p.length / 3; i ++ ) {

		if ( ! layout.isProbeActive( i ) ) continue;
		for ( let a = 0; a < 3; a ++ ) {

			box[ a ] = Math.min( box[ a ], p[ 3 * i + a ] );
			box[ 3 + a ] = Math.max( box[ 3 + a ], p[ 3 * i + a ] );

		}

	}

	return box;

}

/** The points inside the layout's tetrahedra (all of them for a grid, planar or line interpolator). */
function insideHull( layout: FittedLayout, points: Float64Array ): Float64Array {

	const mesh = layout.interpolator;
	if ( ! ( mesh instanceof TetrahedralMesh ) ) return points;
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 ), classes = new Uint8Array( points.length / 3 );
	let hint = - 1;
	for ( let i = 0; i < points.length / 3; i ++ ) {

		hint = mesh.interpolate( points[ 3 * i ], points[ 3 * i + 1 ], points[ 3 * i + 2 ], indices, weights, hint );
		classes[ i ] = hint < mesh.cellCount ? 1 : 0;

	}

	return keepClass( points, classes, 1 );

}

/**
 * The live probes in open space (a quarter spacing or more from every surface, not inside a
 * solid): the seeds of the reachability fill, so fit points sealed off from every probe are dropped.
 */
function openProbes( where: string, layout: FittedLayout, bvh: TriangleBVH, sides: Int8Array, clearance: number ): Float64Array {

	const live: number[] = [];
	for ( let i = 0; i < layout.positions.length / 3; i ++ ) {

		if ( layout.isProbeActive( i ) ) live.push( ...layout.positions.subarray( 3 * i, 3 * i + 3 ) );

	}

	const probes = Float64Array.from( live );
	return keepClass( probes, classifyPointsFor( where, probes, bvh, { minDistance: clearance, sides } ), OPEN_SPACE );

}
