import { assertArrayLike, assertFinite, assertPoints, describeValue } from '../validate.js';
import { cellHash } from '../geometry/cellHash.js';
import { WalkableRegion } from './walkableRegion.js';

/** An axis-aligned box of a {@link RegionOfInterest}: min ≤ max on every axis. */
export interface RegionBox {

	/** Lowest corner, x, y, z. */
	min: ArrayLike<number>;

	/** Highest corner, x, y, z. */
	max: ArrayLike<number>;

}

/**
 * Where the lighting matters most — where characters and moving objects go. A point is inside when
 * it lies in any of the boxes, within `radius` of any of the points, or in the walkable region;
 * give at least one of them. `reduceProbes` weights both its choice of probes and its reported
 * error with {@link regionWeights}.
 */
export interface RegionOfInterest {

	/** Boxes, inclusive of their faces. */
	boxes?: readonly RegionBox[];

	/** Points, x, y, z each (e.g. a nav mesh's vertices): inside = within `radius` of one. */
	points?: ArrayLike<number>;

	/** Radius around `points` (> 0; required with `points`). */
	radius?: number;

	/** "Where characters go": floor-facing triangles plus a height band above them. */
	walkable?: WalkableRegion;

	/** Weight of points outside the region (0..1), default 0.1: they still count a little, so the rest of the level is not left dark. */
	outsideWeight?: number;

}

/**
 * One weight per position: 1 inside the region, `outsideWeight` (default 0.1) outside.
 * @param positions x, y, z per point.
 * @throws RangeError when none of the positions lies inside the region (it would weight nothing
 *   as meant), for NaN, boxes with min > max, a missing or non-positive radius, an outside weight
 *   not in 0..1; TypeError for a region that is not an object or names nothing.
 */
export function regionWeights( positions: ArrayLike<number>, region: RegionOfInterest ): Float64Array {

	return weightsInRegion( 'regionWeights', 'region', positions, region );

}

/**
 * {@link regionWeights} with the caller's names in its messages (`reduceProbes` checks its
 * `options.region` through this).
 * @param where Function name for messages.
 * @param name The region argument's name for messages.
 */
export function weightsInRegion( where: string, name: string, positions: ArrayLike<number>, region: RegionOfInterest ): Float64Array {

	const count = assertPoints( where, 'positions', positions );
	const read = readRegion( where, name, region );
	const weights = new Float64Array( count ).fill( read.outsideWeight );
	let insideCount = 0;
	for ( let p = 0; p < count; p ++ ) {

		const x = positions[ 3 * p ], y = positions[ 3 * p + 1 ], z = positions[ 3 * p + 2 ];
		const inside = inBoxes( read.boxes, x, y, z ) || ( read.near !== null && read.near( x, y, z ) )
			|| ( read.walkable !== undefined && read.walkable.contains( x, y, z ) );
		if ( inside ) {

			weights[ p ] = 1;
			insideCount ++;

		}

	}

	if ( insideCount === 0 ) {

		throw new RangeError( `${where}: ${name} contains none of the ${count} positions it should weight (its boxes, points and walkable area `
			+ 'miss them all); check its units and placement, or leave it out.' );

	}

	return weights;

}

/** A checked region: boxes as 6 floats each, a radius query over the points, the walkable region. */
interface ReadRegion {

	boxes: Float64Array;
	near: ( ( x: number, y: number, z: number ) => boolean ) | null;
	walkable: WalkableRegion | undefined;
	outsideWeight: number;

}

function readRegion( where: string, name: string, region: RegionOfInterest ): ReadRegion {

	if ( region === null || typeof region !== 'object' || Array.isArray( region ) ) {

		throw new TypeError( `${where}: ${name} must be an object with boxes, points (and radius) or walkable, got ${describeValue( region )}.` );

	}

	const { boxes = [], points, radius, walkable, outsideWeight = 0.1 } = region;
	if ( ! Array.isArray( boxes ) ) throw new TypeError( `${where}: ${name}.boxes must be an array of { min, max }, got ${describeValue( boxes )}.` );
	const flat = new Float64Array( 6 * boxes.length );
	boxes.forEach( ( box, b ) => {

		const label = `${name}.boxes[${b}]`;
		if ( box === null || typeof box !== 'object' ) throw new TypeError( `${where}: ${label} must be { min, max }, got ${describeValue( box )}.` );
		for ( const [ corner, offset ] of [ [ 'min', 0 ], [ 'max', 3 ] ] as const ) {

			const value = box[ corner ];
			assertArrayLike( where, `${label}.${corner}`, value );
			if ( value.length !== 3 ) throw new RangeError( `${where}: ${label}.${corner} must hold x, y, z, got length ${value.length}.` );
			assertFinite( where, `${label}.${corner}`, value );
			flat.set( value, 6 * b + offset );

		}

		for ( let a = 0; a < 3; a ++ ) {

			if ( flat[ 6 * b + a ] > flat[ 6 * b + 3 + a ] ) {

				throw new RangeError( `${where}: ${label} has min ${'xyz'[ a ]} ${flat[ 6 * b + a ]} > max ${flat[ 6 * b + 3 + a ]}; a box needs min ≤ max on every axis.` );

			}

		}

	} );

	let near: ReadRegion[ 'near' ] = null;
	if ( points !== undefined ) {

		const count = assertPoints( where, `${name}.points`, points );
		if ( typeof radius !== 'number' || ! ( radius > 0 ) || radius === Infinity ) {

			throw new RangeError( `${where}: ${name}.radius must be a finite number > 0 with ${name}.points, got ${describeValue( radius )}.` );

		}

		if ( count > 0 ) near = pointsWithin( points, count, radius );

	} else if ( radius !== undefined ) {

		throw new TypeError( `${where}: ${name}.radius was given without ${name}.points.` );

	}

	if ( walkable !== undefined && ! ( walkable instanceof WalkableRegion ) ) {

		throw new TypeError( `${where}: ${name}.walkable must be a WalkableRegion, got ${describeValue( walkable )}.` );

	}

	if ( typeof outsideWeight !== 'number' || ! ( outsideWeight >= 0 && outsideWeight <= 1 ) ) {

		throw new RangeError( `${where}: ${name}.outsideWeight must be a number in 0..1, got ${describeValue( outsideWeight )}.` );

	}

	if ( boxes.length === 0 && near === null && walkable === undefined ) {

		throw new TypeError( `${where}: ${name} names no boxes, no points and no walkable region: it would contain nothing.` );

	}

	return { boxes: flat, near, walkable, outsideWeight };

}

function inBoxes( boxes: Float64Array, x: number, y: number, z: number ): boolean {

	for ( let b = 0; b < boxes.length; b += 6 ) {

		if ( x >= boxes[ b ] && y >= boxes[ b + 1 ] && z >= boxes[ b + 2 ]
			&& x <= boxes[ b + 3 ] && y <= boxes[ b + 4 ] && z <= boxes[ b + 5 ] ) return true;

	}

	return false;

}

/**
 * "Is a point within `radius` of one of `points`?" over a hashed grid of cells `radius` wide (a
 * chained hash table in typed arrays), so each query tests the 27 cells around it, not every point.
 */
function pointsWithin(
	points: ArrayLike<number>, count: number, radius: number,
): ( x: number, y: number, z: number ) => boolean {

	let buckets = 1;
	while ( buckets < 2 * count ) buckets *= 2;
	const mask = buckets - 1, inverse = 1 / radius, r2 = radius * radius;
	const head = new Int32Array( buckets ).fill( - 1 ), next = new Int32Array( count );
	for ( let i = 0; i < count; i ++ ) {

		const cx = Math.floor( points[ 3 * i ] * inverse ), cy = Math.floor( points[ 3 * i + 1 ] * inverse );
		const bucket = cellHash( cx, cy, Math.floor( points[ 3 * i + 2 ] * inverse ) ) & mask;
		next[ i ] = head[ bucket ];
		head[ bucket ] = i;

	}

	return ( x, y, z ) => {

		const cx = Math.floor( x * inverse ), cy = Math.floor( y * inverse ), cz = Math.floor( z * inverse );
		for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

			for ( let k = head[ cellHash( cx + dx, cy + dy, cz + dz ) & mask ]; k !== - 1; k = next[ k ] ) {

				const ex = points[ 3 * k ] - x, ey = points[ 3 * k + 1 ] - y, ez = points[ 3 * k + 2 ] - z;
				if ( ex * ex + ey * ey + ez * ez <= r2 ) return true;

			}

		}

		return false;

	};

}
