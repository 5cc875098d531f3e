/**
 * De-ringing of SH9 probes: a band-wise Hann window (Sloan 2008), applied in place to a range of
 * probes in the library's layout without allocation. Nine coefficients cannot hold a small, very
 * bright source: the series rings and irradiance goes negative facing away from it. The window's
 * table, its error bound and the measurements are in docs/ringing.md.
 *
 * Also re-exports the exact minimum over the sphere (`minimumOverSphere.ts`) and the non-negative
 * switch (`makeNonNegative.ts`), so the whole de-ringing API is importable from here.
 */

import { SH_FLOATS, assertOutput } from '../validate.js';
import { assertProbeRange, assertStrength } from './deringingArguments.js';
import { hannBandFactor } from './hannBandFactor.js';
import type { WritableArrayLike } from './irradiance.js';

export { minIrradiance, minRadiance } from './minimumOverSphere.js';
export { makeIrradianceNonNegative, makeRadianceNonNegative } from './makeNonNegative.js';

/**
 * The window's per-band factors [h₀, h₁, h₂] at `strength` s: h_l = ½·(1 + cos(π·l·s)) for l·s < 1,
 * else 0 (s = 1/w for Sloan's width w). h₀ = 1, so the mean radiance and irradiance are kept; h₁
 * and h₂ fall monotonically with s (table of values: docs/ringing.md).
 * @param strength Window strength in [0, 1] (0 = identity, 1 = only L00 left).
 * @param target Receives h₀ = 1, h₁, h₂ in entries 0..2; a new Float64Array(3) when omitted.
 * @returns `target`.
 */
export function windowSHFactors<T extends WritableArrayLike = Float64Array>( strength: number, target?: T ): T {

	assertStrength( 'windowSHFactors', 'strength', strength );
	const out = ( target ?? new Float64Array( 3 ) ) as T;
	assertOutput( 'windowSHFactors', 'target', out, 3 );
	out[ 0 ] = 1;
	out[ 1 ] = hannBandFactor( 1, strength );
	out[ 2 ] = hannBandFactor( 2, strength );
	return out;

}

/**
 * Windows SH9 band by band to reduce ringing: band 1 (indices 1..3) is multiplied by h₁, band 2
 * (4..8) by h₂ ({@link windowSHFactors}); L00 is untouched. 0 is the identity, 0.1–0.2 softens the
 * overshoot of a bright sun or lamp, 1/3 is a strong blur, 1 leaves only the ambient term. The
 * result does not depend on the probe's orientation. Allocation-free; pass `target = sh` to
 * window in place.
 * @param sh SH array, 27 floats per probe (length a positive multiple of 27).
 * @param strength Window strength s in [0, 1].
 * @param target Receives the windowed probes at the same indices as in `sh`; a new
 * Float32Array( sh.length ) (other probes copied unchanged) when omitted.
 * @param firstProbe First probe windowed (default 0).
 * @param probeCount Probes windowed (default: all from `firstProbe` on).
 * @returns `target`.
 */
export function windowSH<T extends WritableArrayLike = Float32Array>(
	sh: ArrayLike<number>, strength: number, target?: T, firstProbe = 0, probeCount?: number,
): T {

	const where = 'windowSH';
	const count = assertProbeRange( where, sh, firstProbe, probeCount );
	assertStrength( where, 'strength', strength );
	let out: T;
	if ( target === undefined ) {

		out = Float32Array.from( sh ) as unknown as T;

	} else {

		out = target;
		assertOutput( where, 'target', out, sh.length );

	}

	const h1 = hannBandFactor( 1, strength ), h2 = hannBandFactor( 2, strength );
	for ( let p = firstProbe; p < firstProbe + count; p ++ ) {

		const o = p * SH_FLOATS;
		out[ o ] = sh[ o ]; out[ o + 1 ] = sh[ o + 1 ]; out[ o + 2 ] = sh[ o + 2 ];
		for ( let i = 3; i < 12; i ++ ) out[ o + i ] = h1 * sh[ o + i ];
		for ( let i = 12; i < SH_FLOATS; i ++ ) out[ o + i ] = h2 * sh[ o + i ];

	}

	return out;

}
