import { hilbertIndex3, mulberry32 } from '../tetrahedra/spatialOrder.js';
import { boundsOf } from '../geometry/boundsOf.js';
import { completeSpan } from './completeSpan.js';

/** The subset `reduceProbes` grows: dense indices in the order chosen, and a flag per dense probe. */
export interface Subset {

	/** Dense indices, in the order they were chosen. */
	order: number[];

	/** Per dense probe: 1 when in the subset. */
	selected: Uint8Array;

}

/**
 * `reduceProbes`' starting set: the required probes, as few more as it takes to span the dense
 * set's dimension (so the subset can be tetrahedralized, or triangulated when the set is flat),
 * then the box corners' extremes while `targetCount` leaves room — on a box-shaped set those cover
 * the whole hull.
 * @param points Dense positions.
 * @param rank Seeded rank per dense probe, for ties.
 * @throws RangeError when the required probes need more spanning probes than `targetCount` allows.
 */
export function startingSet(
	where: string, points: Float64Array, rank: Uint32Array, required: readonly number[], targetCount: number | undefined,
): Subset {

	const selected = new Uint8Array( points.length / 3 );
	const order: number[] = [];
	const add = ( i: number ): void => {

		if ( selected[ i ] === 0 ) {

			selected[ i ] = 1;
			order.push( i );

		}

	};

	required.forEach( add );
	completeSpan( where, points, rank, order ).forEach( add );
	if ( targetCount !== undefined && order.length > targetCount ) {

		throw new RangeError( `${where}: options.keep needs ${order.length - required.length} more probes to span a volume, which exceeds options.targetCount (${targetCount}).` );

	}

	for ( const i of boxExtremes( points, rank ) ) {

		if ( targetCount !== undefined && order.length >= targetCount ) break;
		add( i );

	}

	return { order, selected };

}

/**
 * The probe farthest towards each of the 8 corners of the bounding box, in coordinates scaled to
 * the box (so a long, flat set still gets its real corners). On a box-shaped set these are its
 * corners, whose hull is the whole set's.
 */
function boxExtremes( points: Float64Array, rank: Uint32Array ): number[] {

	const count = points.length / 3;
	const { min, max } = boxOf( points );

	const scale = [ 0, 1, 2 ].map( ( a ) => max[ a ] > min[ a ] ? 2 / ( max[ a ] - min[ a ] ) : 0 );
	const out: number[] = [];
	for ( let corner = 0; corner < 8; corner ++ ) {

		const sx = corner & 1 ? 1 : - 1, sy = corner & 2 ? 1 : - 1, sz = corner & 4 ? 1 : - 1;
		let best = - 1, bestValue = - Infinity;
		for ( let p = 0; p < count; p ++ ) {

			const value = sx * ( points[ 3 * p ] - min[ 0 ] ) * scale[ 0 ] + sy * ( points[ 3 * p + 1 ] - min[ 1 ] ) * scale[ 1 ]
				+ sz * ( points[ 3 * p + 2 ] - min[ 2 ] ) * scale[ 2 ];
			if ( value > bestValue || ( value === bestValue && rank[ p ] < rank[ best ] ) ) {

				best = p;
				bestValue = value;

			}

		}

		out.push( best );

	}

	return out;

}

/** A seeded random rank per probe, used only to break exact ties. */
export function seededRanks( count: number, seed: number ): Uint32Array {

	const random = mulberry32( seed );
	const keys = new Float64Array( count );
	for ( let i = 0; i < count; i ++ ) keys[ i ] = random();
	// Equal keys (1 in 2³² per pair) fall back to the index, so ranks are always a permutation.
	const byKey = Array.from( { length: count }, ( _, i ) => i ).sort( ( i, j ) => keys[ i ] - keys[ j ] || i - j );
	const rank = new Uint32Array( count );
	byKey.forEach( ( i, r ) => { rank[ i ] = r; } );
	return rank;

}

/** Point indices sorted along a 3D Hilbert curve over their bounding box (10 bits per axis): the visiting order that keeps walks short. */
export function hilbertOrder( points: Float64Array ): Uint32Array {

	const count = points.length / 3, bits = 10, cells = ( 1 << bits ) - 1;
	const { min, max } = boxOf( points );

	const cell = ( p: number, a: number ) => max[ a ] > min[ a ]
		? Math.round( ( points[ 3 * p + a ] - min[ a ] ) / ( max[ a ] - min[ a ] ) * cells ) : 0;
	const keys = new Float64Array( count );
	for ( let p = 0; p < count; p ++ ) keys[ p ] = hilbertIndex3( cell( p, 0 ), cell( p, 1 ), cell( p, 2 ), bits );
	return Uint32Array.from( { length: count }, ( _, i ) => i ).sort( ( i, j ) => keys[ i ] - keys[ j ] || i - j );

}

/** The points' bounding box as [x, y, z] corners (`boundsOf`). */
function boxOf( points: Float64Array ): { min: number[]; max: number[] } {

	const b = boundsOf( points );
	return { min: [ b[ 0 ], b[ 1 ], b[ 2 ] ], max: [ b[ 3 ], b[ 4 ], b[ 5 ] ] };

}
