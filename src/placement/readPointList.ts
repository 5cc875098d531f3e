import { assertFinite, describeValue } from '../validate.js';

/** Points as the placement options take them: `[ x, y, z, … ]`, `[ [ x, y, z ], … ]` or `[ { x, y, z }, … ]` (e.g. `Vector3`s). */
export type PointList = ArrayLike<number> | ReadonlyArray<ArrayLike<number> | { x: number; y: number; z: number }>;

/**
 * Reads a {@link PointList} into a flat x, y, z array, checking that every coordinate is finite.
 * @throws TypeError / RangeError naming `where` and `name` (and the bad entry).
 */
export function readPointList( where: string, name: string, value: unknown, minPoints = 1 ): Float64Array {

	if ( value === null || typeof value !== 'object' || typeof ( value as ArrayLike<unknown> ).length !== 'number' ) {

		throw new TypeError( `${where}: ${name} must be points: [ x, y, z, … ], [ [ x, y, z ], … ] or [ { x, y, z }, … ], got ${describeValue( value )}.` );

	}

	const list = value as ArrayLike<unknown>;
	let out: Float64Array;
	if ( list.length > 0 && typeof list[ 0 ] === 'object' && list[ 0 ] !== null ) {

		out = new Float64Array( 3 * list.length );
		for ( let i = 0; i < list.length; i ++ ) {

			const p = list[ i ] as Record<string, unknown> & ArrayLike<unknown>;
			const xyz = p !== null && typeof p === 'object' && 'x' in p ? [ p.x, p.y, p.z ]
				: p !== null && typeof p === 'object' && p.length === 3 ? [ p[ 0 ], p[ 1 ], p[ 2 ] ] : null;
			if ( xyz === null ) throw new TypeError( `${where}: ${name}[${i}] must be [ x, y, z ] or { x, y, z }, got ${describeValue( p )}.` );
			for ( let a = 0; a < 3; a ++ ) {

				const v = xyz[ a ];
				if ( typeof v !== 'number' || ! Number.isFinite( v ) ) {

					throw new RangeError( `${where}: ${name}[${i}].${'xyz'[ a ]} is ${String( v )}; coordinates must be finite numbers.` );

				}

				out[ 3 * i + a ] = v;

			}

		}

	} else {

		if ( list.length % 3 !== 0 ) {

			throw new RangeError( `${where}: ${name} must hold x, y, z per point (length a multiple of 3), got length ${list.length}.` );

		}

		assertFinite( where, name, list as ArrayLike<number> );
		out = Float64Array.from( list as ArrayLike<number> );

	}

	if ( out.length / 3 < minPoints ) throw new RangeError( `${where}: ${name} needs at least ${minPoints} point(s), got ${out.length / 3}.` );
	return out;

}
