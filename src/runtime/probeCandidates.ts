import type { Box3 } from 'three';
import { boundsOf } from '../geometry/boundsOf.js';
import { TriangleBVH } from '../geometry/TriangleBVH.js';
import { classifyPointsFor, INSIDE_GEOMETRY, NEAR_SURFACE, OPEN_SPACE, UNREACHABLE } from '../placement/classifyPoints.js';
import { keepClass } from '../placement/keepClass.js';
import { placeFromMeshes } from '../placement/placeFromMeshes.js';
import { placeGrid } from '../placement/placeGrid.js';
import { thinToSpacing } from '../placement/thinToSpacing.js';
import type { StaticGeometry } from './staticGeometry.js';

/** What {@link placeCandidates} needs, checked by its caller. */
export interface CandidateSettings {

	/** Seeds of open space (x, y, z each), or undefined: no reachability test. */
	reachableFrom?: Float64Array;

	/** Place candidates only inside this box (default: the geometry's bounding box). */
	bounds?: Box3;

	/** Grid spacing; default: the box split into `candidates` cubes. */
	spacing?: number;

	/** About how many grid cells when `spacing` is not given. */
	candidates: number;

	/** Candidates closer than this to a surface are dropped; default a quarter of the spacing. */
	clearance?: number;

	/**
	 * Also classify the whole grid (before thinning) to measure the open volume: the box's volume
	 * times the share of grid points not inside geometry and not unreachable.
	 */
	measureOpenVolume?: boolean;

}

/** The candidates of {@link placeCandidates}, in open space. */
export interface ProbeCandidates {

	/** x, y, z per candidate: mesh vertices moved off their surfaces first, then grid cell centres. */
	positions: Float64Array;

	/** Candidates dropped, per reason. */
	rejected: { nearSurface: number; insideGeometry: number; unreachable: number };

	/** How many candidates were classified (before the open-space test). */
	classified: number;

	/** The grid spacing used. */
	spacing: number;

	/** The clearance used. */
	clearance: number;

	/** The box candidates were placed in: [ minX, minY, minZ, maxX, maxY, maxZ ]. */
	box: number[];

	/** With `measureOpenVolume`: the open volume in scene units³, else NaN. */
	openVolume: number;

}

/**
 * The candidates of `placeProbes` and `LightProbeVolume.fromScene`: mesh vertices moved half a
 * spacing off their surfaces towards the side their material draws (the paper's candidates) and a
 * grid of cell centres over the level's box, thinned together to half a spacing, then only those
 * in open space kept (`classifyPoints`: at least `clearance` from every surface, not inside a solid,
 * reachable from `reachableFrom` when given).
 * @throws RangeError for a level without triangles or an empty box.
 */
export function placeCandidates( where: string, geometry: StaticGeometry, settings: CandidateSettings ): ProbeCandidates {

	const { triangles, sides, roots } = geometry;
	if ( triangles.length === 0 ) throw new RangeError( `${where}: the level has no triangles to place probes in.` );
	const box = candidateBox( where, triangles, settings.bounds );
	const spacing = settings.spacing ?? defaultSpacing( box, settings.candidates );
	const clearance = settings.clearance ?? spacing / 4;

	// Mesh vertices first (the paper's candidates, where the light changes), then the grid; thinned
	// together so that no two candidates are closer than half a spacing.
	const fromVertices = { offset: spacing / 2, minSpacing: spacing / 2, rejectInside: false, minDistance: 0 };
	const moved = roots.map( ( root ) => placeFromMeshes( root, fromVertices ) );
	const vertices = inBox( concatenate( moved ), box );
	const grid = cellCentres( box, spacing );
	const union = thinToSpacing( concatenate( [ vertices, grid ] ), ( vertices.length + grid.length ) / 3, spacing / 2 );
	// The grid is classified after the candidates in the same call (one reachability fill) when the open volume is wanted.
	const points = settings.measureOpenVolume === true ? concatenate( [ union, grid ] ) : union;
	const seeds = settings.reachableFrom;
	const all = classifyPointsFor( where, points, new TriangleBVH( triangles ), {
		minDistance: clearance, sides, reachableFrom: seeds, reachBounds: seeds === undefined ? undefined : floodBox( box, seeds ),
	} );
	const classes = all.subarray( 0, union.length / 3 );
	let openVolume = NaN;
	if ( settings.measureOpenVolume === true ) {

		const gridClasses = all.subarray( union.length / 3 );
		const open = gridClasses.filter( ( c ) => c === OPEN_SPACE || c === NEAR_SURFACE ).length;
		openVolume = ( box[ 3 ] - box[ 0 ] ) * ( box[ 4 ] - box[ 1 ] ) * ( box[ 5 ] - box[ 2 ] ) * open / gridClasses.length;

	}

	return {
		positions: keepClass( union, classes, OPEN_SPACE ),
		rejected: {
			nearSurface: count( classes, NEAR_SURFACE ),
			insideGeometry: count( classes, INSIDE_GEOMETRY ),
			unreachable: count( classes, UNREACHABLE ),
		},
		classified: classes.length,
		spacing,
		clearance,
		box,
		openVolume,
	};

}

/** "only 12 of 40 candidates are in open space (…)": for the errors of callers that need more. */
export function describeCandidates( candidates: ProbeCandidates ): string {

	const { rejected } = candidates;
	return `only ${candidates.positions.length / 3} of ${candidates.classified} candidates are in open space (${rejected.nearSurface} near a surface, `
		+ `${rejected.insideGeometry} inside geometry, ${rejected.unreachable} unreachable)`;

}

function count( classes: Uint8Array, value: number ): number {

	let n = 0;
	for ( let i = 0; i < classes.length; i ++ ) if ( classes[ i ] === value ) n ++;
	return n;

}

function concatenate( parts: readonly Float64Array[] ): Float64Array {

	const out = new Float64Array( parts.reduce( ( sum, part ) => sum + part.length, 0 ) );
	let offset = 0;
	for ( const part of parts ) {

		out.set( part, offset );
		offset += part.length;

	}

	return out;

}

/** The triangles' bounding box, cut to `bounds`: [ minX, minY, minZ, maxX, maxY, maxZ ], every side > 0. */
function candidateBox( where: string, triangles: Float64Array, bounds: Box3 | undefined ): number[] {

	const b = Array.from( boundsOf( triangles, triangles.length / 3 ) );
	if ( bounds !== undefined ) {

		b[ 0 ] = Math.max( b[ 0 ], bounds.min.x ); b[ 1 ] = Math.max( b[ 1 ], bounds.min.y ); b[ 2 ] = Math.max( b[ 2 ], bounds.min.z );
		b[ 3 ] = Math.min( b[ 3 ], bounds.max.x ); b[ 4 ] = Math.min( b[ 4 ], bounds.max.y ); b[ 5 ] = Math.min( b[ 5 ], bounds.max.z );

	}

	if ( ! ( b[ 3 ] > b[ 0 ] && b[ 4 ] > b[ 1 ] && b[ 5 ] > b[ 2 ] ) ) {

		throw new RangeError( `${where}: the box to place probes in is empty or flat (${b.map( ( v ) => v.toPrecision( 4 ) ).join( ', ' )}); `
			+ 'probes need a volume: check options.bounds.' );

	}

	return b;

}

/** The points inside the box (outside the level's bounds a vertex moved off a double-sided wall is no use). */
function inBox( points: Float64Array, box: number[] ): Float64Array {

	const out: number[] = [];
	for ( let i = 0; i < points.length; i += 3 ) {

		const x = points[ i ], y = points[ i + 1 ], z = points[ i + 2 ];
		if ( x >= box[ 0 ] && x <= box[ 3 ] && y >= box[ 1 ] && y <= box[ 4 ] && z >= box[ 2 ] && z <= box[ 5 ] ) out.push( x, y, z );

	}

	return Float64Array.from( out );

}

/**
 * The box of the reachability flood: the candidates' box grown to hold the seeds. Without
 * `bounds` that is the flood's own default (the triangles' bounds and the seeds); with it, the
 * flood spends its lattice on the part of the level where candidates are (not on a sky dome
 * around it), and what lies outside that box is unreachable either way.
 */
function floodBox( box: number[], seeds: Float64Array ): number[] {

	const out = box.slice();
	for ( let i = 0; i < seeds.length; i += 3 ) {

		for ( let a = 0; a < 3; a ++ ) {

			out[ a ] = Math.min( out[ a ], seeds[ i + a ] );
			out[ 3 + a ] = Math.max( out[ 3 + a ], seeds[ i + a ] );

		}

	}

	return out;

}

/** The side of `count` cubes filling the box. */
export function defaultSpacing( box: number[], count: number ): number {

	return Math.cbrt( ( box[ 3 ] - box[ 0 ] ) * ( box[ 4 ] - box[ 1 ] ) * ( box[ 5 ] - box[ 2 ] ) / count );

}

/** The centres of a grid of cells about `spacing` wide filling the box (at least 2 per axis): half a cell from each face. */
export function cellCentres( box: ArrayLike<number>, spacing: number ): Float64Array {

	const counts = [ 0, 1, 2 ].map( ( a ) => Math.max( 2, Math.round( ( box[ 3 + a ] - box[ a ] ) / spacing ) ) );
	const half = [ 0, 1, 2 ].map( ( a ) => ( box[ 3 + a ] - box[ a ] ) / ( 2 * counts[ a ] ) );
	return placeGrid( [ 0, 1, 2 ].map( ( a ) => box[ a ] + half[ a ] ), [ 0, 1, 2 ].map( ( a ) => box[ 3 + a ] - half[ a ] ), counts );

}
