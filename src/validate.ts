/**
 * Argument checks shared by every public entry point. Each throws an Error whose message starts
 * with the function and argument name, so a user sees which call was wrong instead of a crash deep
 * inside three.js or a silently wrong picture.
 */

/** The number of floats one probe's SH9 occupies: 9 coefficients × RGB. */
export const SH_FLOATS = 27;

/**
 * Checks that `value` is an array-like of numbers (plain array or typed array).
 * @param where Function name for the message, e.g. `'tetrahedralize'`.
 * @param name Argument name for the message, e.g. `'points'`.
 */
export function assertArrayLike( where: string, name: string, value: unknown ): asserts value is ArrayLike<number> {

	if ( value === null || value === undefined || typeof value !== 'object' || typeof ( value as ArrayLike<number> ).length !== 'number' ) {

		throw new TypeError( `${where}: ${name} must be an array or typed array of numbers, got ${describe( value )}.` );

	}

}

/**
 * Checks that every entry of `values` is a finite number; names the first bad index.
 */
export function assertFinite( where: string, name: string, values: ArrayLike<number> ): void {

	for ( let i = 0, n = values.length; i < n; i ++ ) {

		const v = values[ i ];
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) {

			throw new RangeError( `${where}: ${name}[${i}] is ${String( v )}; all values must be finite numbers.` );

		}

	}

}

/**
 * Checks a flat xyz array: array-like, length a multiple of 3, at least `minPoints` points, all finite.
 * @returns The number of points.
 */
export function assertPoints( where: string, name: string, value: unknown, minPoints = 0 ): number {

	assertArrayLike( where, name, value );
	if ( value.length % 3 !== 0 ) {

		throw new RangeError( `${where}: ${name} must hold x, y, z per point (length a multiple of 3), got length ${value.length}.` );

	}

	const count = value.length / 3;
	if ( count < minPoints ) {

		throw new RangeError( `${where}: ${name} needs at least ${minPoints} points, got ${count}.` );

	}

	assertFinite( where, name, value );
	return count;

}

/**
 * Checks an SH array: array-like whose length is exactly `SH_FLOATS × count`
 * (or, when `count` is omitted, any positive multiple of `SH_FLOATS`), all finite.
 * @returns The number of probes it holds.
 */
export function assertSH( where: string, name: string, value: unknown, count?: number ): number {

	assertArrayLike( where, name, value );
	if ( count !== undefined ) {

		if ( value.length !== SH_FLOATS * count ) {

			throw new RangeError( `${where}: ${name} must have length ${SH_FLOATS * count} (27 floats × ${count}), got ${value.length}.` );

		}

	} else if ( value.length === 0 || value.length % SH_FLOATS !== 0 ) {

		throw new RangeError( `${where}: ${name} must have a length that is a positive multiple of 27 (9 RGB coefficients per probe), got ${value.length}.` );

	}

	assertFinite( where, name, value );
	return value.length / SH_FLOATS;

}

/**
 * Checks that `value` is a finite number.
 */
export function assertNumber( where: string, name: string, value: unknown ): asserts value is number {

	if ( typeof value !== 'number' || ! Number.isFinite( value ) ) {

		throw new RangeError( `${where}: ${name} must be a finite number, got ${describe( value )}.` );

	}

}

/**
 * Checks that `value` is an integer in [min, max].
 */
export function assertInteger( where: string, name: string, value: unknown, min: number, max = Number.MAX_SAFE_INTEGER ): asserts value is number {

	if ( typeof value !== 'number' || ! Number.isInteger( value ) || value < min || value > max ) {

		const range = max === Number.MAX_SAFE_INTEGER ? `≥ ${min}` : `in ${min}..${max}`;
		throw new RangeError( `${where}: ${name} must be an integer ${range}, got ${describe( value )}.` );

	}

}

/**
 * Checks that an output array-like has room for at least `length` entries.
 */
export function assertOutput( where: string, name: string, value: unknown, length: number ): void {

	assertArrayLike( where, name, value );
	if ( value.length < length ) {

		throw new RangeError( `${where}: ${name} must have room for ${length} values, got length ${value.length}.` );

	}

}

function describe( value: unknown ): string {

	if ( value === null ) return 'null';
	if ( Array.isArray( value ) ) return `an array of length ${value.length}`;
	if ( ArrayBuffer.isView( value ) ) return `a ${value.constructor.name}`;
	if ( typeof value === 'number' ) return String( value );
	if ( typeof value === 'string' ) return `the string "${value.length > 40 ? value.slice( 0, 40 ) + '…' : value}"`;
	return typeof value;

}
