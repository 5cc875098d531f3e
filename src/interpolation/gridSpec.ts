import { assertArrayLike, assertFinite, assertInteger } from '../validate.js';

/**
 * Checks the box and probe counts of a regular probe grid, as `GridInterpolator` and
 * `placeGrid` take them: `min`, `max` and `counts` of 3 finite entries each, `max` greater than
 * `min` on every axis, each count an integer in 2..65536.
 * @param where Function name for error messages (the function the user called).
 * @throws {TypeError} when an argument is not array-like.
 * @throws {RangeError} for a wrong length, a non-finite entry, a bad count or an empty box.
 */
export function checkGridSpec( where: string, min: ArrayLike<number>, max: ArrayLike<number>, counts: ArrayLike<number> ): void {

	for ( const [ name, value ] of [ [ 'min', min ], [ 'max', max ], [ 'counts', counts ] ] as const ) {

		assertArrayLike( where, name, value );
		if ( value.length !== 3 ) throw new RangeError( `${where}: ${name} must have 3 entries (x, y, z), got ${value.length}.` );
		assertFinite( where, name, value );

	}

	for ( let a = 0; a < 3; a ++ ) {

		assertInteger( where, `counts[${a}]`, counts[ a ], 2, 1 << 16 );
		if ( ! ( max[ a ] > min[ a ] ) ) throw new RangeError( `${where}: max[${a}] (${max[ a ]}) must be greater than min[${a}] (${min[ a ]}).` );

	}

}
