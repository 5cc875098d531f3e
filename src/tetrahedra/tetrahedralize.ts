import { assertPoints } from '../validate.js';
import { orient } from './predicates.js';
import { DelaunayBuilder } from './DelaunayBuilder.js';
import { insertionOrder } from './spatialOrder.js';
import { mergeDuplicates } from './mergeDuplicates.js';

/** Options of {@link tetrahedralize}. */
export interface TetrahedralizeOptions {

	/**
	 * Points closer than this fraction of the bounding-box diagonal are merged into one; the merged
	 * ones are reported in `duplicates`. Default 1e-9.
	 */
	duplicateTolerance?: number;

	/**
	 * When every point lies within this fraction of the bounding-box diagonal of one plane, the set
	 * is rejected as coplanar (a {@link DegenerateInputError} with `reason: 'coplanar'`). Default 1e-9.
	 */
	planarTolerance?: number;

	/** Seed of the randomized insertion order; the output does not depend on it. Default 1. */
	seed?: number;

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

/** Why a point set cannot be tetrahedralized. */
export type DegenerateReason = 'too-few-points' | 'coincident' | 'collinear' | 'coplanar';

/**
 * Thrown by {@link tetrahedralize} when the points do not span a volume. Coplanar layouts (a
 * single floor of probes) can still be interpolated with a planar mesh; see `createProbeInterpolator`.
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

/**
 * Builds the 3D Delaunay tetrahedralization of a point set.
 *
 * Bowyer–Watson insertion in a biased randomized Hilbert order, with ghost tetrahedra on the hull,
 * exact predicates and symbolic perturbation: regular grids (co-spherical everywhere), co-planar
 * subsets and clustered points all give a valid result — tetrahedra that exactly tile the convex
 * hull, none flat, none with an input point strictly inside its circumsphere.
 *
 * @param points Flat x, y, z coordinates.
 * @throws {RangeError} on NaN/Infinity or a length that is not a multiple of 3.
 * @throws {DegenerateInputError} for fewer than 4 distinct points, or points that are all coplanar.
 */
export function tetrahedralize( points: ArrayLike<number>, options: TetrahedralizeOptions = {} ): Tetrahedralization {

	const { builder, duplicates } = buildDelaunay( 'tetrahedralize', points, options );
	const result = { ...finiteCells( builder ), duplicates };
	builder.retire();
	return result;

}

/**
 * The shared first half of `tetrahedralize` and `DynamicTetrahedralization`: validates the points,
 * merges duplicates, rejects degenerate sets and inserts every kept point (BRIO + Hilbert order).
 * @param caller Function name for error messages.
 * @internal
 */
export function buildDelaunay(
	caller: string, points: ArrayLike<number>, options: TetrahedralizeOptions,
): { builder: DelaunayBuilder; p: Float64Array; count: number; duplicates: Uint32Array; diagonal: number } {

	const count = assertPoints( caller, 'points', points );
	if ( count < 4 ) {

		throw new DegenerateInputError( 'too-few-points', `${caller}: points needs at least 4 points to span a volume, got ${count}.` );

	}

	const p = Float64Array.from( points );
	const { duplicateTolerance = 1e-9, planarTolerance = 1e-9, seed = 1 } = options;

	const { unique, duplicates, diagonal } = mergeDuplicates( p, duplicateTolerance );
	if ( unique.length < 4 ) {

		throw new DegenerateInputError( 'too-few-points', `${caller}: points has only ${unique.length} distinct points (${duplicates.length / 2} merged as duplicates); at least 4 are needed.` );

	}

	const builder = new DelaunayBuilder( p, count, diagonal );
	insertAll( caller, builder, p, unique, diagonal, planarTolerance, seed );
	return { builder, p, count, duplicates, diagonal };

}

/**
 * Builds the Delaunay tetrahedralization of the points `indices` of `p` (distinct, at least 4) in
 * an empty `builder`: initial tetrahedron, then the rest in BRIO + Hilbert order.
 * @throws {DegenerateInputError} when the points are collinear or coplanar (before touching `builder`).
 * @internal
 */
export function insertAll(
	caller: string, builder: DelaunayBuilder, p: Float64Array, indices: Uint32Array,
	diagonal: number, planarTolerance: number, seed: number,
): void {

	const initial = findInitialTetrahedron( caller, p, indices, diagonal, planarTolerance );
	builder.start( initial );

	const rest = new Uint32Array( indices.length - 4 );
	for ( let i = 0, j = 0; i < indices.length; i ++ ) {

		const v = indices[ i ];
		if ( v !== initial[ 0 ] && v !== initial[ 1 ] && v !== initial[ 2 ] && v !== initial[ 3 ] ) rest[ j ++ ] = v;

	}

	const order = insertionOrder( p, rest, seed );
	for ( let i = 0; i < order.length; i ++ ) builder.insert( order[ i ] );

}

/**
 * Four affinely independent points, far apart: the first of the extreme points in x, then the
 * farthest from it, from their line, from their plane. Tolerances make near-degenerate sets fail
 * loudly here instead of producing a mesh of slivers.
 */
export function findInitialTetrahedron(
	caller: string, p: Float64Array, unique: Uint32Array, diagonal: number, planarTolerance: number,
): [ number, number, number, number ] {

	let i0 = unique[ 0 ];
	for ( let i = 1; i < unique.length; i ++ ) if ( p[ 3 * unique[ i ] ] < p[ 3 * i0 ] ) i0 = unique[ i ];
	const ax = p[ 3 * i0 ], ay = p[ 3 * i0 + 1 ], az = p[ 3 * i0 + 2 ];

	let i1 = - 1, best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const dx = p[ 3 * v ] - ax, dy = p[ 3 * v + 1 ] - ay, dz = p[ 3 * v + 2 ] - az;
		const d = dx * dx + dy * dy + dz * dz;
		if ( d > best ) { best = d; i1 = v; }

	}

	const ux = p[ 3 * i1 ] - ax, uy = p[ 3 * i1 + 1 ] - ay, uz = p[ 3 * i1 + 2 ] - az;
	let i2 = - 1;
	best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const dx = p[ 3 * v ] - ax, dy = p[ 3 * v + 1 ] - ay, dz = p[ 3 * v + 2 ] - az;
		const cx = uy * dz - uz * dy, cy = uz * dx - ux * dz, cz = ux * dy - uy * dx;
		const d = cx * cx + cy * cy + cz * cz; // |u × d|² = |u|² · distance² to the line
		if ( d > best ) { best = d; i2 = v; }

	}

	const lineDistance = Math.sqrt( best / ( ux * ux + uy * uy + uz * uz ) );
	if ( lineDistance <= planarTolerance * diagonal ) {

		throw new DegenerateInputError( 'collinear', `${caller}: all ${unique.length} distinct points lie on one line (within ${planarTolerance} of the extent); they span no area or volume.` );

	}

	const vx = p[ 3 * i2 ] - ax, vy = p[ 3 * i2 + 1 ] - ay, vz = p[ 3 * i2 + 2 ] - az;
	let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
	const nl = Math.hypot( nx, ny, nz );
	nx /= nl; ny /= nl; nz /= nl;

	let i3 = - 1;
	best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const d = Math.abs( ( p[ 3 * v ] - ax ) * nx + ( p[ 3 * v + 1 ] - ay ) * ny + ( p[ 3 * v + 2 ] - az ) * nz );
		if ( d > best ) { best = d; i3 = v; }

	}

	if ( best <= planarTolerance * diagonal || orient( p, i0, i1, i2, i3 ) === 0 ) {

		throw new DegenerateInputError( 'coplanar', `${caller}: all ${unique.length} distinct points lie in one plane (within ${planarTolerance} of the extent); a volume needs at least one point off that plane. Use createProbeInterpolator for planar layouts.` );

	}

	return orient( p, i0, i1, i2, i3 ) > 0 ? [ i0, i1, i2, i3 ] : [ i0, i2, i1, i3 ];

}

/** Compacts the finite cells of `builder` into the output arrays. */
function finiteCells( builder: DelaunayBuilder ): { tetrahedra: Uint32Array; neighbors: Int32Array } {

	const v = builder.vertices, adj = builder.adjacency, used = builder.used;
	const index = new Int32Array( used ).fill( - 1 );
	let count = 0;
	for ( let t = 0; t < used; t ++ ) {

		const k = 4 * t;
		// FREE is also negative, so one test per vertex rules out released slots and ghosts.
		if ( v[ k ] >= 0 && v[ k + 1 ] >= 0 && v[ k + 2 ] >= 0 && v[ k + 3 ] >= 0 ) index[ t ] = count ++;

	}

	const tetrahedra = new Uint32Array( 4 * count );
	const neighbors = new Int32Array( 4 * count );
	for ( let t = 0; t < used; t ++ ) {

		const o = index[ t ];
		if ( o < 0 ) continue;
		for ( let i = 0; i < 4; i ++ ) {

			tetrahedra[ 4 * o + i ] = v[ 4 * t + i ];
			neighbors[ 4 * o + i ] = index[ adj[ 4 * t + i ] >> 2 ];

		}

	}

	return { tetrahedra, neighbors };

}
