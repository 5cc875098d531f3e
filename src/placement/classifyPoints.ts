import { assertNumber, assertPoints } from '../validate.js';
import { TriangleBVH } from '../geometry/TriangleBVH.js';

/** {@link classifyPoints}: the point is in open space — a usable probe position. */
export const OPEN_SPACE = 0;

/** {@link classifyPoints}: the majority of rays from the point cross the geometry an odd number of times. */
export const INSIDE_GEOMETRY = 1;

/** {@link classifyPoints}: a triangle lies closer than `minDistance` to the point. */
export const NEAR_SURFACE = 2;

/**
 * The fixed ray directions of the parity vote: 7 points of a Fibonacci sphere, turned by an
 * arbitrary rotation so that none is parallel to an axis, an axis plane or a 45° diagonal — the
 * directions along which modelled scenes (and three's BoxGeometry, split on its face diagonals)
 * put their edges, where a ray would count a shared edge twice or slip between two triangles.
 * An odd count so the vote cannot tie.
 */
export const PARITY_RAY_DIRECTIONS: Float64Array = ( () => {

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
	 * Checked first: on or next to a surface, parity is unreliable and a probe would capture mostly
	 * the surface in front of it.
	 */
	minDistance?: number;

	/**
	 * Run the ray-parity vote (default true). With false only the distance test runs and no point
	 * is {@link INSIDE_GEOMETRY}: for scenes of open surfaces, where parity means nothing.
	 */
	parity?: boolean;

	/** Ray directions, x, y, z each (default {@link PARITY_RAY_DIRECTIONS}); an odd count avoids ties. */
	directions?: ArrayLike<number>;

}

/**
 * Classifies candidate probe positions against a triangle scene: {@link NEAR_SURFACE} when a
 * triangle is within `minDistance`, else {@link INSIDE_GEOMETRY} when more than half of the rays
 * in fixed directions cross the triangles an odd number of times (Jordan: a ray leaving a closed
 * surface's inside crosses it an odd number of times), else {@link OPEN_SPACE}.
 *
 * The majority vote absorbs the rays that miscount — through a shared edge or vertex, or through a
 * small gap in a mesh that is not quite watertight. Parity assumes closed geometry: a lone open
 * surface (a ground quad with nothing below it) makes every ray that crosses it vote "inside", so
 * scenes built from open surfaces should be given closed floors, or use `bounds` and skip the test.
 * @param points Flat x, y, z per point.
 * @param scene The triangles, as a {@link TriangleBVH} or a flat array of 9 floats per triangle.
 * @returns One class per point: {@link OPEN_SPACE}, {@link INSIDE_GEOMETRY} or {@link NEAR_SURFACE}.
 */
export function classifyPoints(
	points: ArrayLike<number>, scene: TriangleBVH | ArrayLike<number>, options: ClassifyPointsOptions = {}
): Uint8Array {

	const where = 'classifyPoints';
	const count = assertPoints( where, 'points', points );
	const minDistance = options.minDistance ?? 0;
	assertNumber( where, 'options.minDistance', minDistance );
	if ( minDistance < 0 ) throw new RangeError( `${where}: options.minDistance must be ≥ 0, got ${minDistance}.` );
	const directions = options.directions ?? PARITY_RAY_DIRECTIONS;
	const rays = assertPoints( where, 'options.directions', directions, 1 );
	for ( let r = 0; r < rays; r ++ ) {

		if ( directions[ 3 * r ] === 0 && directions[ 3 * r + 1 ] === 0 && directions[ 3 * r + 2 ] === 0 ) {

			throw new RangeError( `${where}: options.directions[${r}] is the zero vector.` );

		}

	}

	const bvh = scene instanceof TriangleBVH ? scene : new TriangleBVH( scene );
	const classes = new Uint8Array( count );
	for ( let i = 0; i < count; i ++ ) {

		const x = points[ 3 * i ], y = points[ 3 * i + 1 ], z = points[ 3 * i + 2 ];
		if ( minDistance > 0 && bvh.anyWithin( x, y, z, minDistance ) ) {

			classes[ i ] = NEAR_SURFACE;
			continue;

		}

		if ( options.parity === false ) continue;
		let odd = 0;
		for ( let r = 0; r < rays; r ++ ) {

			// Stop as soon as the vote is decided either way: saves up to half the rays.
			if ( bvh.countCrossings( x, y, z, directions[ 3 * r ], directions[ 3 * r + 1 ], directions[ 3 * r + 2 ] ) % 2 === 1 ) odd ++;
			if ( 2 * odd > rays || 2 * ( r + 1 - odd ) >= rays ) break;

		}

		classes[ i ] = 2 * odd > rays ? INSIDE_GEOMETRY : OPEN_SPACE;

	}

	return classes;

}
