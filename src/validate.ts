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

		throw new TypeError( `${where}: ${name} must be an array or typed array of numbers, got ${describeValue( value )}.` );

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

		throw new RangeError( `${where}: ${name} must be a finite number, got ${describeValue( value )}.` );

	}

}

/**
 * Checks that `value` is an integer in [min, max].
 */
export function assertInteger(
	where: string, name: string, value: unknown, min: number, max = Number.MAX_SAFE_INTEGER,
): asserts value is number {

	if ( typeof value !== 'number' || ! Number.isInteger( value ) || value < min || value > max ) {

		const range = max === Number.MAX_SAFE_INTEGER ? `≥ ${min}` : `in ${min}..${max}`;
		throw new RangeError( `${where}: ${name} must be an integer ${range}, got ${describeValue( value )}.` );

	}

}

/**
 * Checks that x, y and z are finite numbers (one point given as three arguments).
 */
export function assertCoordinates( where: string, x: unknown, y: unknown, z: unknown ): void {

	if ( Number.isFinite( x ) && Number.isFinite( y ) && Number.isFinite( z ) ) return;
	const [ name, value ] = ! Number.isFinite( x ) ? [ 'x', x ] : ! Number.isFinite( y ) ? [ 'y', y ] : [ 'z', z ];
	throw new RangeError( `${where}: ${name} is ${typeof value === 'number' ? value : describeValue( value )}; coordinates must be finite numbers.` );

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

/**
 * The largest |SH coefficient| a probe may hold. Blends are convex combinations (weights ≥ 0
 * summing to 1), irradiance matrix entries are sums of two coefficients times constants below 1,
 * and a shader's nᵀMn sums 16 entries: from |L| ≤ 1e30 every value stays below 1e32, far inside
 * float32 (3.4e38), with room for intensities and light scales. See docs/format.md.
 */
export const SH_LIMIT = Math.fround( 1e30 ); // 1e30 as float32 stores it, so a Float32Array holding 1e30 passes

/**
 * The largest |coordinate| a probe position may have. Differences are then ≤ 2e18, and products
 * of up to 16 of them (squared distances, determinants, in-sphere tests, their squares) stay
 * below 1e293 in float64: nothing the runtime computes from positions can overflow. 1e18 m is
 * a hundred light-years. See docs/format.md.
 */
export const POSITION_LIMIT = 1e18;

/** The largest finite float32: a larger gradient would be stored as ±Infinity. */
const FLOAT32_MAX = 3.4028234663852886e38;

/**
 * The largest |gradient value| (∂SH/∂x, ∂SH/∂y, ∂SH/∂z) probes at `positions` (x, y, z each) may hold: {@link SH_LIMIT}
 * over the diagonal of their bounding box, so the gradient term across the layout stays within the SH bound (scale-free:
 * a layout ten times larger takes gradients ten times smaller); the largest float32 when they span no distance. The
 * runtime and the baked-file codec both check gradients against it, on the values as stored (float32 or float16).
 */
export function gradientLimit( positions: ArrayLike<number> ): number {

	let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
	for ( let i = 0; i + 2 < positions.length; i += 3 ) {

		const x = positions[ i ], y = positions[ i + 1 ], z = positions[ i + 2 ];
		if ( x < minX ) minX = x;
		if ( x > maxX ) maxX = x;
		if ( y < minY ) minY = y;
		if ( y > maxY ) maxY = y;
		if ( z < minZ ) minZ = z;
		if ( z > maxZ ) maxZ = z;

	}

	const diagonal = Math.hypot( maxX - minX, maxY - minY, maxZ - minZ );
	return diagonal > 0 ? Math.min( SH_LIMIT / diagonal, FLOAT32_MAX ) : FLOAT32_MAX;

}

/**
 * The index of the first entry that is not a number in [−limit, limit] (NaN, ±Infinity and
 * non-numbers included), or −1 when every entry is.
 */
export function firstBeyond( values: ArrayLike<number>, limit: number ): number {

	for ( let i = 0, n = values.length; i < n; i ++ ) {

		const v = values[ i ];
		if ( ! ( v <= limit && v >= - limit ) ) return i;

	}

	return - 1;

}

/**
 * {@link assertSH} for SH a volume stores: also every |value| ≤ {@link SH_LIMIT}.
 * @returns The number of probes it holds.
 */
export function assertProbeSH( where: string, name: string, value: unknown, count?: number ): number {

	const probes = assertSH( where, name, value, count );
	const sh = value as ArrayLike<number>;
	const i = firstBeyond( sh, SH_LIMIT );
	if ( i >= 0 ) {

		throw new RangeError( `${where}: ${name}[${i}] is ${sh[ i ]}; probe SH values must be within ±${SH_LIMIT.toPrecision( 3 )} (so every blend and irradiance `
			+ 'matrix stays finite in float32).' );

	}

	return probes;

}

/**
 * {@link assertPoints} for probe positions: also every |coordinate| ≤ {@link POSITION_LIMIT}.
 * @returns The number of points.
 */
export function assertProbePositions( where: string, name: string, value: unknown, minPoints = 0 ): number {

	const count = assertPoints( where, name, value, minPoints );
	const points = value as ArrayLike<number>;
	const i = firstBeyond( points, POSITION_LIMIT );
	if ( i >= 0 ) {

		throw new RangeError( `${where}: ${name}[${i}] is ${points[ i ]}; probe coordinates must be within ±${POSITION_LIMIT.toExponential()}.` );

	}

	return count;

}

/**
 * Checks an optional number (undefined passes): a finite number ≥ `min`. A value that is not a
 * number throws a TypeError, NaN, ±Infinity or one below `min` a RangeError.
 */
export function assertOptionalNumber( where: string, name: string, value: unknown, min = - Infinity ): void {

	if ( value === undefined || ( typeof value === 'number' && Number.isFinite( value ) && value >= min ) ) return;
	const message = `${where}: ${name} must be a finite number${min === - Infinity ? '' : ` ≥ ${min}`}, got ${describeValue( value )}.`;
	throw typeof value === 'number' ? new RangeError( message ) : new TypeError( message );

}

/**
 * Checks that an optional value is a boolean (undefined passes).
 */
export function assertOptionalBoolean( where: string, name: string, value: unknown ): void {

	if ( value !== undefined && typeof value !== 'boolean' ) {

		throw new TypeError( `${where}: ${name} must be true or false, got ${describeValue( value )}.` );

	}

}

/**
 * Checks that an optional value is a function (undefined passes).
 */
export function assertOptionalFunction( where: string, name: string, value: unknown ): void {

	if ( value !== undefined && typeof value !== 'function' ) {

		throw new TypeError( `${where}: ${name} must be a function, got ${describeValue( value )}.` );

	}

}

/**
 * Checks that an options argument is an object (undefined passes: the defaults apply).
 */
export function assertOptions( where: string, name: string, value: unknown ): void {

	if ( value !== undefined && ( value === null || typeof value !== 'object' || Array.isArray( value ) ) ) {

		throw new TypeError( `${where}: ${name} must be an object, got ${describeValue( value )}.` );

	}

}

// A lone UTF-16 surrogate has no UTF-8 encoding (TextEncoder would silently write U+FFFD).
const LONE_SURROGATE = /[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/;

/** Whether a string can be stored as UTF-8 (it has no lone surrogate). */
export function isStorableText( text: string ): boolean {

	return ! LONE_SURROGATE.test( text );

}

/** A short description of a value for messages: `null`, `an array of length 3`, `the string "…"`, `a Float32Array`, `number 2`. */
export function describeValue( value: unknown ): string {

	if ( value === null ) return 'null';
	if ( Array.isArray( value ) ) return `an array of length ${value.length}`;
	if ( ArrayBuffer.isView( value ) ) return `a ${value.constructor.name}`;
	if ( typeof value === 'number' ) return String( value );
	if ( typeof value === 'string' ) return `the string "${value.length > 40 ? value.slice( 0, 40 ) + '…' : value}"`;
	return typeof value;

}
