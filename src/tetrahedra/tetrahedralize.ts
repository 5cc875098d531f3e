import { assertOptionalNumber, assertOptions, assertPoints } from '../validate.js';
import { DegenerateInputError } from './DegenerateInputError.js';
import { CELL, CELL_SHIFT, DelaunayBuilder } from './DelaunayBuilder.js';
import { findInitialTetrahedron } from './initialTetrahedron.js';
import { insertionOrder } from './spatialOrder.js';
import { mergeDuplicates } from './mergeDuplicates.js';
import { normalizePoints } from './normalizePoints.js';

export { DegenerateInputError } from './DegenerateInputError.js';
export type { DegenerateReason } from './DegenerateInputError.js';

/** Options of {@link tetrahedralize}. */
export interface TetrahedralizeOptions {

	/**
	 * Points closer than this fraction of the bounding-box diagonal are merged into one; the merged
	 * ones are reported in `duplicates`. A finite number ≥ 0 (0: only exact duplicates). Default 1e-9.
	 */
	duplicateTolerance?: number;

	/**
	 * When every point lies within this fraction of the bounding-box diagonal of one plane, the set
	 * is rejected as coplanar (a {@link DegenerateInputError} with `reason: 'coplanar'`). A finite
	 * number ≥ 0 (0: only exactly coplanar sets). Default 1e-9.
	 */
	planarTolerance?: number;

	/** Seed of the randomized insertion order (a finite number); the output does not depend on it. Default 1. */
	seed?: number;

}

/** {@link TetrahedralizeOptions} with the defaults filled in, as checked by `readOptions`. */
export interface CheckedTetrahedralizeOptions {

	duplicateTolerance: number;
	planarTolerance: number;
	seed: number;

}

/** Result of {@link tetrahedralize}. */
export interface Tetrahedralization {

	/** Four point indices per tetrahedron, positively oriented: det[p1 − p0, p2 − p0, p3 − p0] > 0. */
	tetrahedra: Uint32Array;

	/** `neighbors[4t + i]` is the tetrahedron across the face opposite vertex i of t, or −1 on the convex hull. */
	neighbors: Int32Array;

	/** Pairs (merged point, point it was merged into), flat; empty when no point was merged. */
	duplicates: Uint32Array;

}

/**
 * Builds the 3D Delaunay tetrahedralization of a point set.
 *
 * Bowyer–Watson insertion in a biased randomized Hilbert order, with ghost tetrahedra on the hull,
 * exact predicates and symbolic perturbation: regular grids (co-spherical everywhere), co-planar
 * subsets and clustered points all give a valid result — tetrahedra that exactly tile the convex
 * hull, none flat, none with an input point strictly inside its circumsphere. Any scale: the points
 * are scaled by a power of two to unit size first (exact), so `points × 2^k` gives the same
 * tetrahedra as `points` (docs/robustness.md).
 *
 * @param points Flat x, y, z coordinates.
 * @throws {RangeError} on NaN/Infinity, a length that is not a multiple of 3, or an option that is
 *   not a finite number ≥ 0 ({@link TypeError} when it is not a number).
 * @throws {DegenerateInputError} for fewer than 4 distinct points, points that are all coplanar, or
 *   a coordinate float64 cannot hold beside the layout's extent (`'unrepresentable'`).
 */
export function tetrahedralize( points: ArrayLike<number>, options: TetrahedralizeOptions = {} ): Tetrahedralization {

	return tetrahedralizeFor( 'tetrahedralize', points, options );

}

/**
 * {@link tetrahedralize} with `caller` starting its error messages (for the meshes built on it).
 * @internal
 */
export function tetrahedralizeFor( caller: string, points: ArrayLike<number>, options: TetrahedralizeOptions = {} ): Tetrahedralization {

	const { builder, ids, duplicates } = buildDelaunay( caller, points, options );
	const result = { ...finiteCells( builder, ids ), duplicates };
	builder.retire();
	return result;

}

/**
 * Checks the options of {@link tetrahedralize} (an object or undefined; each number finite and
 * ≥ 0) and fills in the defaults.
 * @internal
 */
export function readOptions( caller: string, options: TetrahedralizeOptions | undefined ): CheckedTetrahedralizeOptions {

	assertOptions( caller, 'options', options );
	const { duplicateTolerance = 1e-9, planarTolerance = 1e-9, seed = 1 } = options ?? {};
	assertOptionalNumber( caller, 'options.duplicateTolerance', duplicateTolerance, 0 );
	assertOptionalNumber( caller, 'options.planarTolerance', planarTolerance, 0 );
	assertOptionalNumber( caller, 'options.seed', seed );
	return { duplicateTolerance, planarTolerance, seed };

}

/**
 * The shared first half of `tetrahedralize` and `DynamicTetrahedralization`: validates the points
 * and options, copies the points scaled by 2^−exponent to unit size (`normalizePoints`), merges
 * duplicates, rejects degenerate sets and inserts every kept point (BRIO + Hilbert order).
 * @param caller Function name for error messages.
 * @returns The builder, numbered as `insertAll` leaves it (`ids`), `p` (the normalised copy), and
 *   the normalised diagonal.
 * @internal
 */
export function buildDelaunay( caller: string, points: ArrayLike<number>, options: TetrahedralizeOptions | undefined ): {
	builder: DelaunayBuilder; ids: Uint32Array; p: Float64Array; count: number; duplicates: Uint32Array; diagonal: number; exponent: number;
} {

	const count = assertPoints( caller, 'points', points );
	const { duplicateTolerance, planarTolerance, seed } = readOptions( caller, options );
	if ( count < 4 ) {

		throw new DegenerateInputError( 'too-few-points', `${caller}: points needs at least 4 points to span a volume, got ${count}.` );

	}

	const p = Float64Array.from( points );
	const exponent = normalizePoints( caller, 'points', p, count );

	const { unique, duplicates, diagonal } = mergeDuplicates( p, duplicateTolerance );
	if ( unique.length < 4 ) {

		throw new DegenerateInputError( 'too-few-points', `${caller}: points has only ${unique.length} distinct points (${duplicates.length / 2} merged as duplicates); at least 4 are needed.` );

	}

	const builder = new DelaunayBuilder( p, count, diagonal );
	builder.limitPoints( diagonal ); // the bounding box of exactly these points
	const ids = insertAll( caller, builder, p, unique, diagonal, planarTolerance, seed );
	return { builder, ids, p, count, duplicates, diagonal, exponent };

}

/**
 * Builds the Delaunay tetrahedralization of the points `indices` of `p` (distinct, at least 4) in
 * an empty `builder`: initial tetrahedron, then the rest in BRIO + Hilbert order. The builder is left
 * on a copy of the points renumbered in insertion order: its vertex v is point `ids[ v ]` of `p`
 * (`builder.renumber( ids, p )` brings it back to `p`'s numbering).
 * @returns `ids`.
 * @throws {DegenerateInputError} when the points are collinear or coplanar (before touching `builder`).
 * @internal
 */
export function insertAll(
	caller: string, builder: DelaunayBuilder, p: Float64Array, indices: Uint32Array,
	diagonal: number, planarTolerance: number, seed: number,
): Uint32Array {

	const initial = findInitialTetrahedron( caller, p, indices, diagonal, planarTolerance );

	const rest = new Uint32Array( indices.length - 4 );
	for ( let i = 0, j = 0; i < indices.length; i ++ ) {

		const v = indices[ i ];
		if ( v !== initial[ 0 ] && v !== initial[ 1 ] && v !== initial[ 2 ] && v !== initial[ 3 ] ) rest[ j ++ ] = v;

	}

	const order = insertionOrder( p, rest, seed );

	// Build on a copy of the points renumbered in insertion order, so that the points of nearby
	// cells are near in memory too; the predicates see the same coordinates, so the same cells.
	const ids = new Uint32Array( indices.length );
	ids.set( initial );
	ids.set( order, 4 );
	const local = new Float64Array( 3 * ids.length );
	for ( let i = 0; i < ids.length; i ++ ) {

		const k = 3 * ids[ i ];
		local[ 3 * i ] = p[ k ]; local[ 3 * i + 1 ] = p[ k + 1 ]; local[ 3 * i + 2 ] = p[ k + 2 ];

	}

	builder.p = local;
	builder.start( [ 0, 1, 2, 3 ] );
	for ( let i = 4; i < ids.length; i ++ ) builder.insert( i );
	return ids;

}

/**
 * Compacts the finite cells of `builder` (numbered as `insertAll` left it) into the output arrays,
 * vertex v of a cell becoming point `ids[ v ]`.
 */
function finiteCells( builder: DelaunayBuilder, ids: Uint32Array ): { tetrahedra: Uint32Array; neighbors: Int32Array } {

	const v = builder.cells, used = builder.used;
	const index = new Int32Array( used );
	let count = 0;
	for ( let t = 0, k = 0; t < used; t ++, k += CELL ) {

		// FREE and INF are negative, so one sign test of the four vertices ORed rules out released slots and ghosts.
		index[ t ] = ( v[ k ] | v[ k + 1 ] | v[ k + 2 ] | v[ k + 3 ] ) >= 0 ? count ++ : - 1;

	}

	const tetrahedra = new Uint32Array( 4 * count );
	const neighbors = new Int32Array( 4 * count );
	for ( let t = 0, k = 0, o = 0; t < used; t ++, k += CELL ) {

		if ( index[ t ] < 0 ) continue;
		tetrahedra[ o ] = ids[ v[ k ] ]; tetrahedra[ o + 1 ] = ids[ v[ k + 1 ] ];
		tetrahedra[ o + 2 ] = ids[ v[ k + 2 ] ]; tetrahedra[ o + 3 ] = ids[ v[ k + 3 ] ];
		neighbors[ o ] = index[ v[ k + 4 ] >> CELL_SHIFT ]; neighbors[ o + 1 ] = index[ v[ k + 5 ] >> CELL_SHIFT ];
		neighbors[ o + 2 ] = index[ v[ k + 6 ] >> CELL_SHIFT ]; neighbors[ o + 3 ] = index[ v[ k + 7 ] >> CELL_SHIFT ];
		o += 4;

	}

	return { tetrahedra, neighbors };

}
