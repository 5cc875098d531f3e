import { TetrahedralizationError, validateTetrahedralization, type ValidTetrahedralization } from '../tetrahedra/validateTetrahedralization.js';
import { isProbeRole, PROBE_ROLES, type RuleReject, type RuleViolation } from '../roles.js';
import { POSITION_LIMIT, SH_LIMIT, firstBeyond, gradientLimit, isStorableText } from '../validate.js';
import { BakedVolumeError, type BakedVolumeErrorCode } from './BakedVolumeError.js';
import type { BakedCapture, BakedCaptureSettings, BakedFit } from './bakedVolumeTypes.js';

/*
 * Field checks shared by the binary reader, the JSON reader and the writers: each throws a
 * BakedVolumeError whose message starts with `where` and names the field and index.
 */

/** Throws a {@link BakedVolumeError} `code` with the message `where: message`. */
export function fail( code: BakedVolumeErrorCode, where: string, message: string ): never {

	throw new BakedVolumeError( code, `${where}: ${message}` );

}

/**
 * {@link validateTetrahedralization} with its errors as {@link BakedVolumeError}s of the same code
 * ('range', 'orientation', 'neighbors') and message.
 */
export function checkTetrahedralization(
	where: string, positions: Float64Array, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number>,
): ValidTetrahedralization {

	try {

		return validateTetrahedralization( where, positions, tetrahedra, neighbors );

	} catch ( error ) {

		if ( error instanceof TetrahedralizationError ) throw new BakedVolumeError( error.code, error.message );
		throw error;

	}

}

/** Every value finite ('nan' otherwise). */
export function checkFinite( where: string, name: string, values: ArrayLike<number> ): void {

	for ( let i = 0, n = values.length; i < n; i ++ ) {

		const v = values[ i ];
		// v - v is 0 for finite numbers and NaN for NaN and ±Infinity: one comparison per value.
		if ( v - v !== 0 ) fail( 'nan', where, `${name}[${i}] is ${String( v )}; every value must be a finite number.` );

	}

}

/** A string storable as UTF-8 ('utf8' for a lone surrogate). */
export function checkText( where: string, name: string, text: string ): void {

	if ( ! isStorableText( text ) ) fail( 'utf8', where, `${name} has a lone surrogate and cannot be stored as UTF-8.` );

}

const REJECT_CODES: Record<RuleViolation, BakedVolumeErrorCode> = { type: 'argument', count: 'count', range: 'range', text: 'utf8' };

/** The codec's {@link RuleReject} for the shared rules of src/roles.ts: a BakedVolumeError of the matching code. */
export function codecReject( where: string ): RuleReject {

	return ( kind, message ) => fail( REJECT_CODES[ kind ], where, message );

}

/** Finite positions ('nan') with every |coordinate| ≤ POSITION_LIMIT ('range'). */
export function checkPositions( where: string, positions: ArrayLike<number> ): void {

	checkFinite( where, 'positions', positions );
	const i = firstBeyond( positions, POSITION_LIMIT );
	if ( i >= 0 ) fail( 'range', where, `positions[${i}] is ${positions[ i ]}; probe coordinates must be within ±${POSITION_LIMIT.toExponential()}.` );

}

/** Finite SH ('nan') with every |value| ≤ SH_LIMIT ('range'). */
export function checkSH( where: string, name: string, sh: ArrayLike<number> ): void {

	checkFinite( where, name, sh );
	const i = firstBeyond( sh, SH_LIMIT );
	if ( i >= 0 ) fail( 'range', where, `${name}[${i}] is ${sh[ i ]}; probe SH values must be within ±${SH_LIMIT.toPrecision( 3 )}.` );

}

/**
 * Finite gradients ('nan') within ±{@link gradientLimit} ('range'), checked on the stored values
 * (float32 or float16 roundings) so that the reader finds what the writer checked.
 */
export function checkGradients( where: string, gradients: ArrayLike<number>, positions: Float64Array ): void {

	checkFinite( where, 'gradients', gradients );
	const limit = gradientLimit( positions );
	const i = firstBeyond( gradients, limit );
	if ( i >= 0 ) {

		fail( 'range', where, `gradients[${i}] is ${gradients[ i ]}; gradient values must be within ±${limit.toPrecision( 3 )} `
			+ `(${SH_LIMIT.toPrecision( 3 )} / the probes' bounding-box diagonal: the gradient term across the layout stays within the SH bound).` );

	}

}

/**
 * A fit record (the FITS section's JSON, the JSON form's `fit`, an encoder's input), checked and
 * copied without unknown members; null or undefined: null. A record saying gradients were fitted
 * needs the gradients ('count' when `hasGradients` is false).
 */
export function checkFit( where: string, fit: unknown, hasGradients: boolean ): BakedFit | null {

	if ( fit === undefined || fit === null ) return null;
	if ( typeof fit !== 'object' || Array.isArray( fit ) ) fail( 'json', where, 'fit must be an object { samples, gradients, lambda, gradientLambda, crossValidationError, source? }.' );
	const f = fit as Record<string, unknown>;
	const number = ( key: string, nullable: boolean ): number | null => {

		const v = f[ key ];
		if ( nullable && v === null ) return null;
		const expected = nullable ? 'a number ≥ 0 or null' : 'a number ≥ 0';
		if ( typeof v !== 'number' ) fail( 'json', where, `fit.${key} is ${JSON.stringify( v ) ?? String( v )}; expected ${expected}.` );
		if ( ! Number.isFinite( v ) ) fail( 'nan', where, `fit.${key} is ${v}; expected a finite number ≥ 0.` );
		if ( v < 0 ) fail( 'range', where, `fit.${key} is ${v}; expected ≥ 0.` );
		return v;

	};

	const samples = number( 'samples', false )!;
	if ( ! Number.isInteger( samples ) ) fail( 'range', where, `fit.samples is ${samples}; expected an integer ≥ 0 (the number of fit samples).` );
	if ( typeof f.gradients !== 'boolean' ) fail( 'json', where, `fit.gradients is ${JSON.stringify( f.gradients ) ?? String( f.gradients )}; expected true or false.` );
	if ( f.gradients && ! hasGradients ) fail( 'count', where, 'fit.gradients is true but the volume holds no gradients; store them or say the fit had none.' );
	const out: BakedFit = {
		samples, gradients: f.gradients, lambda: number( 'lambda', false )!, gradientLambda: number( 'gradientLambda', false )!,
		crossValidationError: number( 'crossValidationError', true ),
	};
	if ( f.source !== undefined ) {

		if ( typeof f.source !== 'string' ) fail( 'json', where, `fit.source is ${JSON.stringify( f.source ) ?? String( f.source )}; expected a string.` );
		checkText( where, 'fit.source', f.source );
		out.source = f.source;

	}

	return out;

}

/** Box min ≤ max on each axis ('range' otherwise); `offset` is the box's first index. */
export function checkBox( where: string, name: string, box: ArrayLike<number>, offset: number ): void {

	for ( let k = 0; k < 3; k ++ ) {

		if ( ! ( box[ offset + k ] <= box[ offset + 3 + k ] ) ) {

			fail( 'range', where, `${name}[${offset + k}] = ${box[ offset + k ]} exceeds its maximum ${name}[${offset + 3 + k}] = ${box[ offset + 3 + k ]}.` );

		}

	}

}

/** Capture settings parsed from JSON (undefined or null: {}), checked and copied. */
export function checkCapture( where: string, capture: unknown ): BakedCapture {

	if ( capture === undefined || capture === null ) return {};
	if ( typeof capture !== 'object' || Array.isArray( capture ) ) fail( 'json', where, 'capture must be an object.' );
	const source = capture as Record<string, unknown>;
	const out: BakedCapture = checkCaptureSettings( where, 'capture', source );
	if ( source.roles !== undefined ) {

		if ( typeof source.roles !== 'object' || source.roles === null || Array.isArray( source.roles ) ) fail( 'json', where, 'capture.roles must be an object.' );
		out.roles = {};
		for ( const [ role, settings ] of Object.entries( source.roles as Record<string, unknown> ) ) {

			if ( ! isProbeRole( role ) ) fail( 'range', where, `capture.roles has the unknown role "${role}"; expected one of ${PROBE_ROLES.join( ', ' )}.` );
			if ( typeof settings !== 'object' || settings === null || Array.isArray( settings ) ) fail( 'json', where, `capture.roles.${role} must be an object.` );
			out.roles[ role ] = checkCaptureSettings( where, `capture.roles.${role}`, settings as Record<string, unknown> );

		}

	}

	return out;

}

/** One role's (or the common) capture settings, checked and copied. */
function checkCaptureSettings( where: string, name: string, s: Record<string, unknown> ): BakedCaptureSettings {

	const out: BakedCaptureSettings = {};
	const number = ( key: 'resolution' | 'near' | 'far' ): number | undefined => {

		const v = s[ key ];
		if ( v === undefined ) return undefined;
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) fail( typeof v === 'number' ? 'nan' : 'json', where, `${name}.${key} is ${String( v )}; expected a finite number.` );
		return v;

	};

	const resolution = number( 'resolution' ), near = number( 'near' ), far = number( 'far' );
	if ( resolution !== undefined ) {

		if ( ! Number.isInteger( resolution ) || resolution < 1 ) fail( 'range', where, `${name}.resolution is ${resolution}; expected an integer ≥ 1.` );
		out.resolution = resolution;

	}

	if ( near !== undefined ) {

		if ( ! ( near > 0 ) ) fail( 'range', where, `${name}.near is ${near}; expected > 0.` );
		out.near = near;

	}

	if ( far !== undefined ) {

		if ( ! ( far > ( near ?? 0 ) ) ) fail( 'range', where, `${name}.far is ${far}; expected > near (${near ?? 0}).` );
		out.far = far;

	}

	if ( s.type !== undefined ) {

		if ( s.type !== 'half' && s.type !== 'float' ) fail( 'range', where, `${name}.type is ${JSON.stringify( s.type )}; expected "half" or "float".` );
		out.type = s.type;

	}

	if ( s.solidAngle !== undefined ) {

		if ( s.solidAngle !== 'exact' && s.solidAngle !== 'paper' ) fail( 'range', where, `${name}.solidAngle is ${JSON.stringify( s.solidAngle )}; expected "exact" or "paper".` );
		out.solidAngle = s.solidAngle;

	}

	return out;

}

/** An array or a typed array (not a DataView). */
function isNumberArray( value: unknown ): value is ArrayLike<number> {

	return ArrayBuffer.isView( value ) ? ! ( value instanceof DataView ) : Array.isArray( value );

}

/**
 * An array or typed array of numbers whose length is a multiple of `elementsPer` ('argument',
 * 'count', 'nan' for JSON's null otherwise); plain arrays are checked element by element.
 */
export function numbers( where: string, name: string, value: unknown, elementsPer: number ): ArrayLike<number> {

	if ( ! isNumberArray( value ) ) fail( 'argument', where, `${name} must be an array or typed array of numbers.` );
	const array = value as ArrayLike<number>;
	if ( array.length % elementsPer !== 0 ) fail( 'count', where, `${name} has length ${array.length}, not a multiple of ${elementsPer}.` );
	if ( Array.isArray( array ) ) {

		for ( let i = 0; i < array.length; i ++ ) {

			const v = array[ i ];
			// JSON.stringify writes NaN and ±Infinity as null.
			if ( v === null ) fail( 'nan', where, `${name}[${i}] is null (NaN or Infinity written as JSON); every value must be a finite number.` );
			if ( typeof v !== 'number' ) fail( 'argument', where, `${name}[${i}] is ${JSON.stringify( v ) ?? String( v )}, not a number.` );

		}

	}

	return array;

}

/** The box of the positions: min x, y, z, max x, y, z. */
export function boxOf( positions: Float64Array ): Float64Array {

	const box = new Float64Array( [ Infinity, Infinity, Infinity, - Infinity, - Infinity, - Infinity ] );
	for ( let i = 0; i < positions.length; i += 3 ) {

		for ( let k = 0; k < 3; k ++ ) {

			const v = positions[ i + k ];
			if ( v < box[ k ] ) box[ k ] = v;
			if ( v > box[ 3 + k ] ) box[ 3 + k ] = v;

		}

	}

	return box;

}
