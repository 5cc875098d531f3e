import { assertArrayLike, assertNumber, assertOptionalBoolean, assertOptionalNumber, assertPoints, describeValue } from '../validate.js';
import { TriangleBVH } from '../geometry/TriangleBVH.js';
import { InsideTest } from './InsideTest.js';
import { ReachableSpace } from './ReachableSpace.js';
import { readPointList, type PointList } from './readPointList.js';

/** {@link classifyPoints}: the point is in open space — a usable probe position. */
export const OPEN_SPACE = 0;

/** {@link classifyPoints}: the point is inside a solid (see `InsideTest` for the rule). */
export const INSIDE_GEOMETRY = 1;

/** {@link classifyPoints}: a triangle lies closer than `minDistance` to the point. */
export const NEAR_SURFACE = 2;

/** {@link classifyPoints}: the point is in open space that no `reachableFrom` seed can reach. */
export const UNREACHABLE = 3;

/**
 * The fixed ray directions of the inside vote: 7 points of a Fibonacci sphere, turned by an
 * arbitrary rotation so that none is parallel to an axis, an axis plane or a 45° diagonal — the
 * directions along which modelled scenes (and three's BoxGeometry, split on its face diagonals)
 * put their edges, where a ray would count a shared edge twice or slip between two triangles.
 * An odd count so the vote cannot tie.
 */
export const INSIDE_RAY_DIRECTIONS: Float64Array = ( () => {

	const count = 7, golden = Math.PI * ( 3 - Math.sqrt( 5 ) );
	const out = new Float64Array( 3 * count );
	// Rotation by 0.7 rad about the unit axis (1, 2, 3) / √14 (Rodrigues' formula).
	const kx = 1 / Math.sqrt( 14 ), ky = 2 / Math.sqrt( 14 ), kz = 3 / Math.sqrt( 14 ), c = Math.cos( 0.7 ), s = Math.sin( 0.7 );
	for ( let i = 0; i < count; i ++ ) {

		const y = 1 - 2 * ( i + 0.5 ) / count, r = Math.sqrt( 1 - y * y ), phi = golden * i + 0.3;
		const x = r * Math.cos( phi ), z = r * Math.sin( phi );
		const dot = kx * x + ky * y + kz * z;
		out[ 3 * i ] = x * c + ( ky * z - kz * y ) * s + kx * dot * ( 1 - c );
		out[ 3 * i + 1 ] = y * c + ( kz * x - kx * z ) * s + ky * dot * ( 1 - c );
		out[ 3 * i + 2 ] = z * c + ( kx * y - ky * x ) * s + kz * dot * ( 1 - c );

	}

	return out;

} )();

/** Options of {@link classifyPoints}. */
export interface ClassifyPointsOptions {

	/**
	 * Points with a triangle closer than this are {@link NEAR_SURFACE} (default 0: no distance test).
	 * Checked first: on or next to a surface, the inside test is unreliable and a probe would
	 * capture mostly the surface in front of it.
	 */
	minDistance?: number;

	/** Run the inside test (default true). With false no point is {@link INSIDE_GEOMETRY}. */
	inside?: boolean;

	/** @deprecated The old name of `inside` (the test is no longer a parity count); `inside` wins when both are given. */
	parity?: boolean;

	/**
	 * Per triangle (in the scene's order): the side its material draws — 1 the front
	 * (counter-clockwise) side, as three's `FrontSide`; −1 the back, as `BackSide` (a room seen from
	 * inside); 0 both, as `DoubleSide`. Default: all 1. `placeFromMeshes` reads them from the materials.
	 */
	sides?: ArrayLike<number>;

	/** Ray directions of the inside vote, x, y, z each (default {@link INSIDE_RAY_DIRECTIONS}); an odd count avoids ties. */
	directions?: ArrayLike<number>;

	/**
	 * Seeds of open space, e.g. `[ spawn ]` (the player's spawn, above the floor): points that no
	 * seed reaches through open space are {@link UNREACHABLE} — inside sealed rooms or cavities,
	 * and outside the bounding box of the triangles and seeds. See `ReachableSpace` for the flood
	 * fill. A closed double-sided shell that holds a seed is a room (its inside is open space).
	 */
	reachableFrom?: PointList;

	/** Lattice spacing of the `reachableFrom` flood fill (> 0; default: the longest side of the box / 64). */
	reachCellSize?: number;

	/**
	 * The box of the `reachableFrom` flood fill, [ minX, minY, minZ, maxX, maxY, maxZ ] (default: the
	 * triangles' bounds, grown to hold the seeds): points outside it are {@link UNREACHABLE}. A level
	 * inside a sky dome floods only the level's box, at the lattice spacing that box gives.
	 */
	reachBounds?: ArrayLike<number>;

}

/**
 * Classifies candidate probe positions against a triangle scene: {@link NEAR_SURFACE} when a
 * triangle is within `minDistance`; else {@link INSIDE_GEOMETRY} when the point is inside a solid
 * — by a majority of rays in fixed directions, each voting "inside" when it leaves more closed
 * shells than it enters or when it first meets an open surface's undrawn side (`InsideTest`);
 * else {@link UNREACHABLE} when `reachableFrom` is given and no seed reaches it; else
 * {@link OPEN_SPACE}.
 *
 * Open rooms work: a room of open quads (no front wall, single- or double-sided) is open space
 * inside, and so is a room drawn from inside (`BackSide`). A closed double-sided shell counts as a
 * solid unless it holds a `reachableFrom` seed. The rules, their reasons and the cases they get
 * wrong are in docs/placement.md.
 * @param points Flat x, y, z per point.
 * @param scene The triangles, as a {@link TriangleBVH} or a flat array of 9 floats per triangle.
 * @returns One class per point: {@link OPEN_SPACE}, {@link INSIDE_GEOMETRY}, {@link NEAR_SURFACE} or {@link UNREACHABLE}.
 */
export function classifyPoints(
	points: ArrayLike<number>, scene: TriangleBVH | ArrayLike<number>, options: ClassifyPointsOptions = {}
): Uint8Array {

	return classifyPointsFor( 'classifyPoints', points, scene, options );

}

/** {@link classifyPoints} with error messages naming `where`: for the functions built on it (`placeFromMeshes`, `placeProbes`). */
export function classifyPointsFor(
	where: string, points: ArrayLike<number>, scene: TriangleBVH | ArrayLike<number>, options: ClassifyPointsOptions = {}
): Uint8Array {

	const count = assertPoints( where, 'points', points );
	if ( options === null || typeof options !== 'object' ) throw new TypeError( `${where}: options must be an object, got ${describeValue( options )}.` );
	const minDistance = options.minDistance ?? 0;
	assertNumber( where, 'options.minDistance', minDistance );
	if ( minDistance < 0 ) throw new RangeError( `${where}: options.minDistance must be ≥ 0, got ${minDistance}.` );
	assertOptionalBoolean( where, 'options.inside', options.inside );
	assertOptionalBoolean( where, 'options.parity', options.parity );
	const directions = readDirections( where, options.directions ?? INSIDE_RAY_DIRECTIONS );
	assertOptionalNumber( where, 'options.reachCellSize', options.reachCellSize, Number.MIN_VALUE );
	const seeds = options.reachableFrom === undefined ? null : readPointList( where, 'options.reachableFrom', options.reachableFrom );

	const bvh = scene instanceof TriangleBVH ? scene : new TriangleBVH( scene );
	const sides = readSides( where, options.sides, bvh.triangleCount );
	const inside = options.inside ?? options.parity ?? true;
	const test = inside ? new InsideTest( bvh, sides, directions ) : null;
	let reachable: ReachableSpace | null = null;
	if ( seeds !== null ) {

		test?.treatAsRooms( seeds );
		for ( let s = 0; s < seeds.length / 3; s ++ ) {

			if ( test !== null && test.isInside( seeds[ 3 * s ], seeds[ 3 * s + 1 ], seeds[ 3 * s + 2 ] ) ) {

				throw new RangeError( `${where}: options.reachableFrom[${s}] (${Array.from( seeds.subarray( 3 * s, 3 * s + 3 ) ).join( ', ' )}) is inside geometry `
					+ '(inside a closed surface drawn from outside, or behind the undrawn side of a wall); give a point in open space, such as the player\'s spawn.' );

			}

		}

		reachable = new ReachableSpace( bvh, seeds, { cellSize: options.reachCellSize, bounds: options.reachBounds }, where, 'options.reachableFrom' );

	}

	const classes = new Uint8Array( count );
	for ( let i = 0; i < count; i ++ ) {

		const x = points[ 3 * i ], y = points[ 3 * i + 1 ], z = points[ 3 * i + 2 ];
		if ( minDistance > 0 && bvh.anyWithin( x, y, z, minDistance ) ) classes[ i ] = NEAR_SURFACE;
		else if ( test !== null && test.isInside( x, y, z ) ) classes[ i ] = INSIDE_GEOMETRY;
		else if ( reachable !== null && ! reachable.contains( x, y, z ) ) classes[ i ] = UNREACHABLE;

	}

	return classes;

}

/** Checked ray directions: x, y, z each, at least one, none the zero vector. */
function readDirections( where: string, directions: ArrayLike<number> ): ArrayLike<number> {

	const rays = assertPoints( where, 'options.directions', directions, 1 );
	for ( let r = 0; r < rays; r ++ ) {

		if ( directions[ 3 * r ] === 0 && directions[ 3 * r + 1 ] === 0 && directions[ 3 * r + 2 ] === 0 ) {

			throw new RangeError( `${where}: options.directions[${r}] is the zero vector.` );

		}

	}

	return directions;

}

/** Checked per-triangle sides (1, −1 or 0 each, one per triangle); all 1 when not given. */
function readSides( where: string, sides: ArrayLike<number> | undefined, triangleCount: number ): Int8Array {

	if ( sides === undefined ) return new Int8Array( triangleCount ).fill( 1 );
	assertArrayLike( where, 'options.sides', sides );
	if ( sides.length !== triangleCount ) {

		throw new RangeError( `${where}: options.sides must have one entry per triangle (${triangleCount}), got length ${sides.length}.` );

	}

	for ( let t = 0; t < triangleCount; t ++ ) {

		if ( sides[ t ] !== 1 && sides[ t ] !== - 1 && sides[ t ] !== 0 ) {

			throw new RangeError( `${where}: options.sides[${t}] is ${String( sides[ t ] )}; each must be 1 (front drawn), −1 (back drawn) or 0 (both).` );

		}

	}

	return Int8Array.from( sides );

}
