/**
 * The non-negative switch: per probe, the smallest window strength whose reconstructed irradiance
 * (or radiance) is ≥ 0 in every direction, applied in place. Why it always succeeds, why blends keep
 * the guarantee and how the search runs: docs/ringing.md.
 */

import { SH_FLOATS, assertOutput } from '../validate.js';
import { SHSphereMinimum, type SphereQuantity } from './SHSphereMinimum.js';
import { assertProbeRange, assertStrength } from './deringingArguments.js';
import { hannBandFactor } from './hannBandFactor.js';
import type { WritableArrayLike } from './irradiance.js';

// Reusable scratch for one probe at a time, passed explicitly to the helpers below.
const sphereMinimum = new SHSphereMinimum();
const original = new Float64Array( SH_FLOATS ); // the probe's 27 coefficients as captured
const originalZeroed = new Uint8Array( 3 ); // 1 for a channel with L00 < 0, set to zero

/**
 * Windows each probe's SH ({@link windowSH}) in place with the smallest strength s ≥
 * `minimumStrength` whose reconstructed irradiance ({@link minIrradiance}) is ≥ 0 for every normal
 * in all three channels; a channel with L00 < 0 (not a capture) is set to zero. Probes already
 * non-negative are only windowed with `minimumStrength` (untouched when it is 0). Non-negative
 * probes give non-negative blends, so this covers every object lit by the volume.
 * @param sh SH array, 27 floats per probe, changed in place.
 * @param minimumStrength Window strength applied at least (default 0), in [0, 1].
 * @param firstProbe First probe treated (default 0).
 * @param probeCount Probes treated (default: all from `firstProbe` on).
 * @param strengths Receives each treated probe's strength at its probe index (entry
 * `firstProbe + i`) when given.
 * @returns How many probes needed more than `minimumStrength`.
 */
export function makeIrradianceNonNegative(
	sh: WritableArrayLike, minimumStrength = 0, firstProbe = 0, probeCount?: number, strengths?: WritableArrayLike,
): number {

	return makeNonNegative( 'makeIrradianceNonNegative', 'irradiance', sh, minimumStrength, firstProbe, probeCount, strengths );

}

/**
 * {@link makeIrradianceNonNegative} for the reconstructed radiance ({@link minRadiance}): for SH
 * shown directly (a probe's sky, reflections). It needs a stronger window than irradiance and
 * implies non-negative irradiance.
 * @param sh SH array, 27 floats per probe, changed in place.
 * @param minimumStrength Window strength applied at least (default 0), in [0, 1].
 * @param firstProbe First probe treated (default 0).
 * @param probeCount Probes treated (default: all from `firstProbe` on).
 * @param strengths Receives each treated probe's strength at entry `firstProbe + i` when given.
 * @returns How many probes needed more than `minimumStrength`.
 */
export function makeRadianceNonNegative(
	sh: WritableArrayLike, minimumStrength = 0, firstProbe = 0, probeCount?: number, strengths?: WritableArrayLike,
): number {

	return makeNonNegative( 'makeRadianceNonNegative', 'radiance', sh, minimumStrength, firstProbe, probeCount, strengths );

}

function makeNonNegative(
	where: string, quantity: SphereQuantity, sh: WritableArrayLike, minimumStrength: number,
	firstProbe: number, probeCount: number | undefined, strengths: WritableArrayLike | undefined,
): number {

	const count = assertProbeRange( where, sh, firstProbe, probeCount );
	assertStrength( where, 'minimumStrength', minimumStrength );
	if ( strengths !== undefined ) assertOutput( where, 'strengths', strengths, firstProbe + count );

	let raised = 0;
	for ( let p = firstProbe; p < firstProbe + count; p ++ ) {

		const o = p * SH_FLOATS;
		sphereMinimum.prepare( quantity, sh, o );
		// The captured values: every attempt windows these, never already-windowed ones.
		for ( let i = 0; i < SH_FLOATS; i ++ ) original[ i ] = sh[ o + i ];
		let zeroed = false;
		for ( let channel = 0; channel < 3; channel ++ ) {

			// At s = 1 a channel is c₀₀ (∝ L00): below zero no window helps.
			const below = sphereMinimum.constantTerm( channel ) < 0;
			sphereMinimum.setSkipped( channel, below );
			originalZeroed[ channel ] = below ? 1 : 0;
			if ( below ) zeroed = true;

		}

		let strength = minimumStrength;
		if ( ! feasible( sphereMinimum, strength ) ) {

			strength = smallestFeasibleStrength( sphereMinimum, strength );

		} else if ( strength === 0 && ! zeroed ) {

			// Already non-negative as stored: nothing to write or verify.
			if ( strengths !== undefined ) strengths[ p ] = 0;
			continue;

		}

		for ( let step = 1e-7; ; step *= 2 ) {

			writeWindowed( sh, o, strength, original, originalZeroed );
			if ( strength >= 1 ) break; // only L00 ≥ 0 (or zero) left: E = c4·L00 ≥ 0 as stored
			sphereMinimum.prepare( quantity, sh, o );
			if ( feasible( sphereMinimum, 0 ) ) break;
			// Rounding of the stored values (float32) pushed a minimum just below zero: go a bit
			// further, doubling the step so that this ends after a few tries.
			strength = Math.min( 1, strength + step );

		}

		if ( strengths !== undefined ) strengths[ p ] = strength;
		if ( strength > minimumStrength || zeroed ) raised ++;

	}

	return raised;

}

/** Writes `coefficients` (27) windowed by `strength` to the probe at `o`, zeroed channels as 0. */
function writeWindowed(
	sh: WritableArrayLike, o: number, strength: number, coefficients: Float64Array, zeroedChannels: Uint8Array,
): void {

	const h1 = hannBandFactor( 1, strength ), h2 = hannBandFactor( 2, strength );
	for ( let k = 0; k < 9; k ++ ) {

		const h = k === 0 ? 1 : k < 4 ? h1 : h2;
		for ( let c = 0; c < 3; c ++ ) sh[ o + 3 * k + c ] = zeroedChannels[ c ] ? 0 : h * coefficients[ 3 * k + c ];

	}

}

/** The first s on a 1/32 grid above `from` that is feasible, refined by bisection to 1e-7. */
function smallestFeasibleStrength( minimum: SHSphereMinimum, from: number ): number {

	let lo = from;
	let hi = 1;
	for ( let k = 1; k <= 32; k ++ ) {

		const s = Math.min( 1, from + k / 32 );
		if ( feasible( minimum, s ) ) {

			hi = s;
			break;

		}

		lo = s;
		if ( s >= 1 ) break;

	}

	while ( hi - lo > 1e-7 ) {

		const mid = 0.5 * ( lo + hi );
		if ( feasible( minimum, mid ) ) hi = mid; else lo = mid;

	}

	return hi;

}

/** True when every prepared, not skipped channel's minimum at `strength` is ≥ 0. */
function feasible( minimum: SHSphereMinimum, strength: number ): boolean {

	const h1 = hannBandFactor( 1, strength ), h2 = hannBandFactor( 2, strength );
	for ( let channel = 0; channel < 3; channel ++ ) {

		if ( minimum.isSkipped( channel ) ) continue;
		if ( minimum.channelMinimum( channel, h1, h2 ) < 0 ) return false;

	}

	return true;

}
