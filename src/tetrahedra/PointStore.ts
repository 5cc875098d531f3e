import { extentExponent, timesPowerOfTwo } from './powerOfTwo.js';
import { unrepresentable } from './normalizePoints.js';

// Largest coordinate magnitude kept in the local frame (within the predicates' range, with room
// for their auxiliary points); beyond it an edit normalises the points anew.
const LOCAL_RANGE = 2 ** 60;

// Below this squared tolerance, squared distances may underflow: compare distances (hypot) instead.
const SQUARES_UNDERFLOW = 2 ** - 1000;

const _bounds = new Float64Array( 6 );

/** The normalised frame of a {@link PointStore}: coordinates and lengths in units of 2^exponent. */
export interface LocalFrame {

	/** x, y, z per point id, times 2^−exponent. */
	local: Float64Array;
	exponent: number;
	/** The duplicate tolerance (a distance) and its square. */
	tolerance: number;
	tolerance2: number;
	/** The extent the tolerances are relative to (the initial bounding-box diagonal). */
	diagonal: number;

}

/**
 * The points of a `DynamicTetrahedralization` as given (`raw`, what `positions` shows) and in a
 * local frame scaled by a power of two to about unit size (exact), where the predicates and the
 * duplicate tolerance work (docs/robustness.md). Internal to src/tetrahedra.
 */
export class PointStore {

	/** x, y, z per point id as given (slots beyond the points are free capacity). */
	raw: Float64Array;

	/** The local frame (replaced as a whole when the points are normalised anew). */
	frame: LocalFrame;

	constructor( raw: Float64Array, frame: LocalFrame ) {

		this.raw = raw;
		this.frame = frame;

	}

	/** Room for `capacity` points in both frames (copies the first `count`). */
	grow( capacity: number, count: number ): void {

		const raw = new Float64Array( 3 * capacity ), local = new Float64Array( 3 * capacity );
		raw.set( this.raw.subarray( 0, 3 * count ) );
		local.set( this.frame.local.subarray( 0, 3 * count ) );
		this.raw = raw;
		this.frame.local = local;

	}

	/** Whether (x, y, z) scales exactly into the local frame and stays within its range. */
	fits( x: number, y: number, z: number ): boolean {

		return this.fitsOne( x ) && this.fitsOne( y ) && this.fitsOne( z );

	}

	private fitsOne( v: number ): boolean {

		const e = this.frame.exponent, s = timesPowerOfTwo( v, - e );
		return Math.abs( s ) <= LOCAL_RANGE && timesPowerOfTwo( s, e ) === v;

	}

	/** Writes point i in both frames (the local one exactly when `fits`). */
	set( i: number, x: number, y: number, z: number ): void {

		const raw = this.raw, local = this.frame.local, e = - this.frame.exponent, k = 3 * i;
		raw[ k ] = x; raw[ k + 1 ] = y; raw[ k + 2 ] = z;
		local[ k ] = timesPowerOfTwo( x, e ); local[ k + 1 ] = timesPowerOfTwo( y, e ); local[ k + 2 ] = timesPowerOfTwo( z, e );

	}

	/** Whether a difference (dx, dy, dz) in `frame` is at most `factor` × its duplicate tolerance. */
	within( dx: number, dy: number, dz: number, factor: number, frame = this.frame ): boolean {

		if ( frame.tolerance2 >= SQUARES_UNDERFLOW ) return dx * dx + dy * dy + dz * dz <= factor * factor * frame.tolerance2;
		return Math.hypot( dx, dy, dz ) <= factor * frame.tolerance;

	}

	/**
	 * The first active point (`active[w]`, w < count, w ≠ q, w ≠ ignore) within the duplicate
	 * tolerance of point q in `frame`, or −1. O(count).
	 */
	duplicateOf( q: number, ignore: number, count: number, active: Uint8Array, frame = this.frame ): number {

		const p = frame.local, x = p[ 3 * q ], y = p[ 3 * q + 1 ], z = p[ 3 * q + 2 ];
		for ( let w = 0; w < count; w ++ ) {

			if ( w === ignore || w === q || ! active[ w ] ) continue;
			if ( this.within( p[ 3 * w ] - x, p[ 3 * w + 1 ] - y, p[ 3 * w + 2 ] - z, 1, frame ) ) return w;

		}

		return - 1;

	}

	/**
	 * A new local frame for the points `ids` with point `index` at (x, y, z) (an id in `ids`, or a
	 * new one below the capacity), normalised from their bounding box; other slots are 0. Changes nothing.
	 * @throws {DegenerateInputError} (`'unrepresentable'`) when a coordinate does not scale exactly.
	 */
	renormalized( where: string, ids: Uint32Array, index: number, x: number, y: number, z: number ): LocalFrame {

		const raw = this.raw;
		let minX = x, minY = y, minZ = z, maxX = x, maxY = y, maxZ = z;
		for ( let j = 0; j < ids.length; j ++ ) {

			const i = ids[ j ];
			if ( i === index ) continue;
			const a = raw[ 3 * i ], b = raw[ 3 * i + 1 ], c = raw[ 3 * i + 2 ];
			if ( a < minX ) minX = a;
			if ( a > maxX ) maxX = a;
			if ( b < minY ) minY = b;
			if ( b > maxY ) maxY = b;
			if ( c < minZ ) minZ = c;
			if ( c > maxZ ) maxZ = c;

		}

		_bounds[ 0 ] = minX; _bounds[ 1 ] = minY; _bounds[ 2 ] = minZ; _bounds[ 3 ] = maxX; _bounds[ 4 ] = maxY; _bounds[ 5 ] = maxZ;
		const exponent = extentExponent( _bounds );
		const local = new Float64Array( raw.length );
		const write = ( i: number, k: number, v: number, what: string ): void => {

			const s = timesPowerOfTwo( v, - exponent );
			if ( timesPowerOfTwo( s, exponent ) !== v ) throw unrepresentable( where, what, v, exponent );
			local[ 3 * i + k ] = s;

		};

		for ( let j = 0; j < ids.length; j ++ ) {

			const i = ids[ j ];
			if ( i !== index ) for ( let k = 0; k < 3; k ++ ) write( i, k, raw[ 3 * i + k ], `coordinate ${k} of point ${i}` );

		}

		write( index, 0, x, 'x' ); write( index, 1, y, 'y' ); write( index, 2, z, 'z' );
		const shift = this.frame.exponent - exponent, tolerance = timesPowerOfTwo( this.frame.tolerance, shift );
		return { local, exponent, tolerance, tolerance2: tolerance * tolerance, diagonal: timesPowerOfTwo( this.frame.diagonal, shift ) };

	}

}
