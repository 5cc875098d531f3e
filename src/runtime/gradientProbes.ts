/* The gradients of gradient probes (81 floats per probe): the checks of what a volume is given (bound: validate.ts gradientLimit). */
import { SH_LIMIT, assertArrayLike, firstBeyond, gradientLimit } from '../validate.js';

/** Floats of one probe's gradient: `gradients[ 81·i + 27·a + k ]` = ∂(SH float k)/∂(axis a). */
export const GRADIENT_FLOATS = 81;

/**
 * The index of the first gradient value that is not a finite number within ±{@link gradientLimit}, or −1.
 */
export function firstBadGradient( gradients: ArrayLike<number>, positions: ArrayLike<number> ): number {

	return firstBeyond( gradients, gradientLimit( positions ) );

}

/** The error for gradient value `index` of `name` that {@link firstBadGradient} found. */
export function badGradientError(
	where: string, name: string, gradients: ArrayLike<number>, index: number, positions: ArrayLike<number>,
): RangeError {

	return new RangeError( `${where}: ${name}[${index}] is ${gradients[ index ]}; probe gradients must be finite and within `
		+ `±${gradientLimit( positions ).toPrecision( 3 )} (${SH_LIMIT.toPrecision( 3 )} / the probes' bounding-box diagonal: `
		+ 'the gradient term across the layout stays within the SH limit).' );

}

/**
 * Checks gradients given to a volume of `count` probes at `positions` — an array-like of 81 × count finite numbers
 * within ±{@link gradientLimit} — and returns them as a new Float32Array.
 */
export function readGradients( where: string, name: string, value: unknown, positions: ArrayLike<number>, count: number ): Float32Array {

	assertArrayLike( where, name, value );
	if ( value.length !== GRADIENT_FLOATS * count ) {

		throw new RangeError( `${where}: ${name} must have length ${GRADIENT_FLOATS * count} (81 floats: ∂SH/∂x, ∂SH/∂y, ∂SH/∂z × `
			+ `${count} probes), got ${value.length}.` );

	}

	for ( let i = 0; i < value.length; i ++ ) {

		if ( typeof value[ i ] !== 'number' ) throw new TypeError( `${where}: ${name}[${i}] is ${typeof value[ i ]}; expected numbers.` );

	}

	// Checked as stored (float32), so what is kept passes the same check again later.
	const gradients = Float32Array.from( value );
	const i = firstBadGradient( gradients, positions );
	if ( i >= 0 ) throw badGradientError( where, name, value, i, positions );
	return gradients;

}
