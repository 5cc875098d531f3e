/**
 * De-ringing of SH9 probes: a band-wise window (Hann, per Sloan 2008) and a switch that makes the
 * reconstructed irradiance provably non-negative in every direction.
 *
 * Why: nine coefficients cannot represent a small, very bright source (a sun disc, a lamp seen
 * through a window). The truncated series overshoots and rings, and the reconstructed irradiance
 * E(n) goes negative for normals facing away from the source — a surface then shades darker than
 * black (or, after the renderer's clamp, loses all its other indirect light).
 *
 * Everything here works in place on the library's SH layout (27 floats per probe, three's
 * `SphericalHarmonics3` order) for a range of probes, without allocation, and imports nothing from
 * three.js.
 */

import { SH_FLOATS, assertArrayLike, assertInteger, assertNumber, assertOutput } from '../validate.js';
import {
	IRRADIANCE_C1, IRRADIANCE_C2, IRRADIANCE_C3, IRRADIANCE_C4, IRRADIANCE_C5,
	SH_Y00, SH_Y1, SH_Y2_PRODUCT, SH_Y20, SH_Y22,
} from './SHBasis.js';
import type { WritableArrayLike } from './irradiance.js';

/** h_l at strength s: the Hann window of {@link windowSHFactors}. */
function bandFactor( band: number, strength: number ): number {

	const x = band * strength;
	return x >= 1 ? 0 : 0.5 * ( 1 + Math.cos( Math.PI * x ) );

}

/**
 * The window's per-band factors [h₀, h₁, h₂] at `strength` s: a Hann window (P.-P. Sloan,
 * "Stupid Spherical Harmonics (SH) Tricks", GDC 2008, "Windowing"),
 * h_l = ½·(1 + cos(π·l·s)) for l·s < 1, else 0. s is the reciprocal of Sloan's window width w
 * (the band at which the window reaches zero):
 *
 * | strength s | h₁ | h₂ | effect |
 * |---|---|---|---|
 * | 0 | 1 | 1 | identity |
 * | 0.1 | 0.976 | 0.905 | light: softens overshoot, keeps almost all directional contrast |
 * | 0.158 | 0.940 | 0.774 | what {@link makeIrradianceNonNegative} chose for a sun disc 5000× the sky (sun-facing irradiance −8.9 %) |
 * | 0.2 | 0.905 | 0.655 | |
 * | 1/3 (w = 3, the number of bands) | 0.75 | 0.25 | strong blur |
 * | 0.5 | 0.5 | 0 | band 2 gone: only a linear (dipole) gradient left |
 * | 1 | 0 | 0 | only L00: constant, ambient light |
 *
 * Both factors decrease monotonically with s; h₀ = 1 always, so the mean radiance and the mean
 * irradiance are preserved.
 * @param strength Window strength in [0, 1] (0 = identity, 1 = only L00 left).
 * @param target Receives h₀ = 1, h₁, h₂ in entries 0..2; a new Float64Array(3) when omitted.
 * @returns `target`.
 */
export function windowSHFactors<T extends WritableArrayLike = Float64Array>( strength: number, target?: T ): T {

	assertStrength( 'windowSHFactors', 'strength', strength );
	const out = ( target ?? new Float64Array( 3 ) ) as T;
	assertOutput( 'windowSHFactors', 'target', out, 3 );
	out[ 0 ] = 1;
	out[ 1 ] = bandFactor( 1, strength );
	out[ 2 ] = bandFactor( 2, strength );
	return out;

}

/**
 * Windows SH9 band by band to reduce ringing: coefficients of band l (1 → indices 1..3, 2 → 4..8)
 * are multiplied by h_l = ½·(1 + cos(π·l·s)) (0 once l·s ≥ 1), a Hann window of width w = 1/s in
 * bands (P.-P. Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008). L00 is untouched.
 *
 * What strength does for a user: 0 is the identity; 0.1–0.2 softens overshoot around a bright sun
 * or lamp while keeping most of the directional contrast; 1/3 (w = 3) is strong blur;
 * 0.5 keeps only the dipole (band 1 halved); 1 leaves the constant ambient term alone. The
 * factors are in the table of {@link windowSHFactors}.
 *
 * Because a band-wise scaling commutes with rotations, the result does not depend on how the
 * probe is oriented. Irradiance changes by at most, for every normal n,
 * |E_s(n) − E(n)| ≤ (1 − h₁)·|E₁(n)| + (1 − h₂)·|E₂(n)|, with E_l band l's part of E; for
 * non-negative radiance |E₁| ≤ 2·Ē and |E₂| ≤ 1.25·Ē (Ē = c4·L00, the sphere's mean irradiance),
 * so |E_s(n) − E(n)| ≤ (2·(1 − h₁) + 1.25·(1 − h₂))·Ē.
 *
 * Allocation-free. Pass `target = sh` to window in place.
 * @param sh SH array, 27 floats per probe (length a positive multiple of 27).
 * @param strength Window strength s in [0, 1].
 * @param target Receives the windowed probes at the same indices as in `sh`; a new
 * Float32Array( sh.length ) (other probes copied unchanged) when omitted.
 * @param firstProbe First probe windowed (default 0).
 * @param probeCount Probes windowed (default: all from `firstProbe` on).
 * @returns `target`.
 */
export function windowSH<T extends WritableArrayLike = Float32Array>( sh: ArrayLike<number>, strength: number, target?: T, firstProbe = 0, probeCount?: number ): T {

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

	const h1 = bandFactor( 1, strength ), h2 = bandFactor( 2, strength );
	for ( let p = firstProbe; p < firstProbe + count; p ++ ) {

		const o = p * SH_FLOATS;
		out[ o ] = sh[ o ]; out[ o + 1 ] = sh[ o + 1 ]; out[ o + 2 ] = sh[ o + 2 ];
		for ( let i = 3; i < 12; i ++ ) out[ o + i ] = h1 * sh[ o + i ];
		for ( let i = 12; i < SH_FLOATS; i ++ ) out[ o + i ] = h2 * sh[ o + i ];

	}

	return out;

}

/**
 * The exact minimum over all unit normals of the irradiance E(n) reconstructed from one probe's
 * SH9 (the quadratic form nᵀMn of {@link irradianceMatrices}, what the patched materials shade),
 * per colour channel.
 *
 * On the unit sphere E(n) = nᵀAn + bᵀn + c. Its minimum is found from the Lagrange condition
 * (A − λI)n = −b/2 with A − λI positive semi-definite (the trust-region subproblem): after a
 * Jacobi eigen-decomposition of A the multiplier solves a one-dimensional secular equation
 * (safeguarded Newton), and the value returned is the Lagrangian dual
 * g(λ) = c + λ − ¼·bᵀ(A − λI)⁻¹b, which equals the minimum at the solution (no duality gap for
 * one quadratic constraint) and is a lower bound for every admissible λ — so rounding in the
 * iteration can only make the answer conservative, never report a minimum that is too high.
 * @param sh SH array, 27 floats per probe.
 * @param shOffset Index of the probe's first float (default 0), e.g. 27·probeIndex.
 * @param perChannel Receives the R, G, B minima in entries 0..2 when given.
 * @param directions Receives, when given, a unit normal attaining each channel's minimum
 * (R's x, y, z, then G's, then B's: 9 floats).
 * @returns The smallest of the three channel minima.
 */
export function minIrradiance( sh: ArrayLike<number>, shOffset = 0, perChannel?: WritableArrayLike, directions?: WritableArrayLike ): number {

	return minimumOf( 'minIrradiance', IRRADIANCE, sh, shOffset, perChannel, directions );

}

/**
 * The exact minimum over all directions of the radiance L(ω) reconstructed from one probe's SH9
 * (three's `SphericalHarmonics3.getAt`), per channel; the method of {@link minIrradiance}.
 * Radiance rings much more than irradiance (the cosine lobe damps band 2 to a quarter), so a
 * probe with non-negative irradiance can still show negative radiance when its SH is drawn as a
 * sky or a reflection.
 * @param sh SH array, 27 floats per probe.
 * @param shOffset Index of the probe's first float (default 0).
 * @param perChannel Receives the R, G, B minima in entries 0..2 when given.
 * @param directions Receives a unit direction attaining each channel's minimum (9 floats) when given.
 * @returns The smallest of the three channel minima.
 */
export function minRadiance( sh: ArrayLike<number>, shOffset = 0, perChannel?: WritableArrayLike, directions?: WritableArrayLike ): number {

	return minimumOf( 'minRadiance', RADIANCE, sh, shOffset, perChannel, directions );

}

/**
 * The non-negative switch: for each probe, windows its SH ({@link windowSH}) with the smallest
 * strength s ≥ `minimumStrength` whose reconstructed irradiance ({@link minIrradiance}) is ≥ 0 for
 * every normal in all three channels, in place. Probes that are already non-negative at
 * `minimumStrength` are only windowed with it; with `minimumStrength = 0` they are left exactly
 * as they were. So `makeIrradianceNonNegative( sh, deringing )` is "window by `deringing`, and
 * more where needed".
 *
 * Why it always succeeds: at s = 1 only L00 is left and E = c4·L00, which is ≥ 0 whenever the
 * captured radiance is (L00 = ∫ L·Y00). A channel with L00 < 0 (negative input radiance, not a
 * capture) cannot be fixed by a window: that channel is set to zero, the minimal change.
 *
 * The smallest s is searched on a grid of 1/32 from `minimumStrength` and refined by bisection
 * to 1e-7, so the result is the first crossing to zero even where the minimum is not monotone in
 * s. The check is repeated on the values as stored (a Float32Array rounds them) and s raised
 * until those pass too.
 *
 * Guarantee, and why blends keep it: the volume shades a point with Σ wᵢ·SHᵢ, wᵢ ≥ 0, Σ wᵢ = 1
 * (barycentric or trilinear weights, also outside the hull). Irradiance is linear in the SH, so
 * E_blend(n) = Σ wᵢ·Eᵢ(n) ≥ 0 for every n when every probe has Eᵢ ≥ 0: the switch per probe covers
 * every blended object. It covers irradiance (what diffuse materials shade), not radiance: a
 * probe drawn as a sky or used for reflections can still ring below zero (see
 * {@link makeRadianceNonNegative}).
 * @param sh SH array, 27 floats per probe, changed in place.
 * @param minimumStrength Window strength applied at least (default 0), in [0, 1].
 * @param firstProbe First probe treated (default 0).
 * @param probeCount Probes treated (default: all from `firstProbe` on).
 * @param strengths Receives each treated probe's strength at its probe index (entry
 * `firstProbe + i`) when given.
 * @returns How many probes needed more than `minimumStrength`.
 */
export function makeIrradianceNonNegative( sh: WritableArrayLike, minimumStrength = 0, firstProbe = 0, probeCount?: number, strengths?: WritableArrayLike ): number {

	return makeNonNegative( 'makeIrradianceNonNegative', IRRADIANCE, sh, minimumStrength, firstProbe, probeCount, strengths );

}

/**
 * {@link makeIrradianceNonNegative} for the reconstructed radiance ({@link minRadiance}): for SH
 * shown directly (a probe's sky, reflections). It needs a stronger window than irradiance and
 * implies non-negative irradiance (E is a cosine-weighted integral of L ≥ 0).
 * @param sh SH array, 27 floats per probe, changed in place.
 * @param minimumStrength Window strength applied at least (default 0), in [0, 1].
 * @param firstProbe First probe treated (default 0).
 * @param probeCount Probes treated (default: all from `firstProbe` on).
 * @param strengths Receives each treated probe's strength at entry `firstProbe + i` when given.
 * @returns How many probes needed more than `minimumStrength`.
 */
export function makeRadianceNonNegative( sh: WritableArrayLike, minimumStrength = 0, firstProbe = 0, probeCount?: number, strengths?: WritableArrayLike ): number {

	return makeNonNegative( 'makeRadianceNonNegative', RADIANCE, sh, minimumStrength, firstProbe, probeCount, strengths );

}

// --- internals ---------------------------------------------------------------------------------

const IRRADIANCE = 0;
const RADIANCE = 1;

/*
 * Per channel, the quadratic on the unit sphere split by band, so that a window only rescales it:
 * A = h₂·A₀ (band 2), b = h₁·b₀ (band 1), c = c₀₀ + h₂·c₂₀. A's eigenvectors therefore do not
 * depend on the strength and are computed once per channel; a strength costs one secular solve.
 * Layout per channel (CHANNEL_FLOATS): eigenvalues d₀ (3), β₀ = Qᵀb₀/2 (3), c₀₀, c₂₀, Q (9,
 * row-major, columns = eigenvectors), zeroed flag.
 */
const CHANNEL_FLOATS = 18;
const channels = new Float64Array( 3 * CHANNEL_FLOATS );
const matrix = new Float64Array( 9 );
const vectors = new Float64Array( 9 );
const linear = new Float64Array( 3 );
const channelMinima = new Float64Array( 3 );
const solution = new Float64Array( 4 ); // t, and the minimiser in the eigenbasis

function minimumOf( where: string, quantity: number, sh: ArrayLike<number>, shOffset: number, perChannel?: WritableArrayLike, directions?: WritableArrayLike ): number {

	assertArrayLike( where, 'sh', sh );
	if ( sh.length === 0 || sh.length % SH_FLOATS !== 0 ) {

		throw new RangeError( `${where}: sh must have a length that is a positive multiple of 27 (9 RGB coefficients per probe), got ${sh.length}.` );

	}

	assertInteger( where, 'shOffset', shOffset, 0, sh.length - SH_FLOATS );
	assertProbeFinite( where, sh, shOffset );
	if ( perChannel !== undefined ) assertOutput( where, 'perChannel', perChannel, 3 );
	if ( directions !== undefined ) assertOutput( where, 'directions', directions, 9 );

	prepareChannels( quantity, sh, shOffset );
	let smallest = Infinity;
	for ( let channel = 0; channel < 3; channel ++ ) {

		const value = channelMinimum( channel, 1, 1 );
		if ( perChannel !== undefined ) perChannel[ channel ] = value;
		if ( value < smallest ) smallest = value;
		if ( directions !== undefined ) writeDirection( channel, directions, 3 * channel );

	}

	return smallest;

}

function makeNonNegative( where: string, quantity: number, sh: WritableArrayLike, minimumStrength: number, firstProbe: number, probeCount: number | undefined, strengths: WritableArrayLike | undefined ): number {

	const count = assertProbeRange( where, sh, firstProbe, probeCount );
	assertStrength( where, 'minimumStrength', minimumStrength );
	if ( strengths !== undefined ) assertOutput( where, 'strengths', strengths, firstProbe + count );

	let raised = 0;
	for ( let p = firstProbe; p < firstProbe + count; p ++ ) {

		const o = p * SH_FLOATS;
		prepareChannels( quantity, sh, o );
		// The captured values: every attempt windows these, never already-windowed ones.
		for ( let i = 0; i < SH_FLOATS; i ++ ) original[ i ] = sh[ o + i ];
		let zeroed = false;
		for ( let channel = 0; channel < 3; channel ++ ) {

			// At s = 1 a channel is c₀₀ (∝ L00): below zero no window helps.
			const below = channels[ channel * CHANNEL_FLOATS + 6 ] < 0;
			channels[ channel * CHANNEL_FLOATS + 17 ] = below ? 1 : 0;
			originalZeroed[ channel ] = below ? 1 : 0;
			if ( below ) zeroed = true;

		}

		let strength = minimumStrength;
		if ( ! feasible( strength ) ) {

			strength = smallestFeasibleStrength( strength );

		} else if ( strength === 0 && ! zeroed ) {

			// Already non-negative as stored: nothing to write or verify.
			if ( strengths !== undefined ) strengths[ p ] = 0;
			continue;

		}

		for ( let step = 1e-7; ; step *= 2 ) {

			writeWindowed( sh, o, strength );
			if ( strength >= 1 ) break; // only L00 ≥ 0 (or zero) left: E = c4·L00 ≥ 0 as stored
			prepareChannels( quantity, sh, o );
			if ( feasible( 0 ) ) break;
			// Rounding of the stored values (float32) pushed a minimum just below zero: go a bit
			// further, doubling the step so that this ends after a few tries.
			strength = Math.min( 1, strength + step );

		}

		if ( strengths !== undefined ) strengths[ p ] = strength;
		if ( strength > minimumStrength || zeroed ) raised ++;

	}

	return raised;

}

// The original 27 coefficients of the probe being treated and which channels are zeroed.
const original = new Float64Array( SH_FLOATS );
const originalZeroed = new Uint8Array( 3 );

function writeWindowed( sh: WritableArrayLike, o: number, strength: number ): void {

	const h1 = bandFactor( 1, strength ), h2 = bandFactor( 2, strength );
	for ( let k = 0; k < 9; k ++ ) {

		const h = k === 0 ? 1 : k < 4 ? h1 : h2;
		for ( let c = 0; c < 3; c ++ ) sh[ o + 3 * k + c ] = originalZeroed[ c ] ? 0 : h * original[ 3 * k + c ];

	}

}

/** The first s on a 1/32 grid above `from` that is feasible, refined by bisection. */
function smallestFeasibleStrength( from: number ): number {

	let lo = from;
	let hi = 1;
	for ( let k = 1; k <= 32; k ++ ) {

		const s = Math.min( 1, from + k / 32 );
		if ( feasible( s ) ) {

			hi = s;
			break;

		}

		lo = s;
		if ( s >= 1 ) break;

	}

	while ( hi - lo > 1e-7 ) {

		const mid = 0.5 * ( lo + hi );
		if ( feasible( mid ) ) hi = mid; else lo = mid;

	}

	return hi;

}

/** True when every (not zeroed) channel's minimum at `strength` is ≥ 0. */
function feasible( strength: number ): boolean {

	const h1 = bandFactor( 1, strength ), h2 = bandFactor( 2, strength );
	for ( let channel = 0; channel < 3; channel ++ ) {

		if ( channels[ channel * CHANNEL_FLOATS + 17 ] ) continue;
		if ( channelMinimum( channel, h1, h2 ) < 0 ) return false;

	}

	return true;

}

/**
 * Builds, for each channel of the probe at `o`, the band-split quadratic and the eigen-decomposition
 * of its band-2 matrix A₀.
 */
function prepareChannels( quantity: number, sh: ArrayLike<number>, o: number ): void {

	for ( let channel = 0; channel < 3; channel ++ ) {

		const s = o + channel;
		const L00 = sh[ s ], L1m1 = sh[ s + 3 ], L10 = sh[ s + 6 ], L11 = sh[ s + 9 ];
		const L2m2 = sh[ s + 12 ], L2m1 = sh[ s + 15 ], L20 = sh[ s + 18 ], L21 = sh[ s + 21 ], L22 = sh[ s + 24 ];
		const q = channel * CHANNEL_FLOATS;
		let xx, yy, zz, xy, yz, xz, band1, c00, c20;
		if ( quantity === IRRADIANCE ) {

			// The rows of irradianceMatrices: A = M[0..2][0..2], b = 2·M[0..2][3], c = M[3][3].
			xx = IRRADIANCE_C1 * L22; yy = - IRRADIANCE_C1 * L22; zz = IRRADIANCE_C3 * L20;
			xy = IRRADIANCE_C1 * L2m2; yz = IRRADIANCE_C1 * L2m1; xz = IRRADIANCE_C1 * L21;
			band1 = 2 * IRRADIANCE_C2;
			c00 = IRRADIANCE_C4 * L00; c20 = - IRRADIANCE_C5 * L20;

		} else {

			// getAt: Y00·L00 + Y1·(L1−1·y + L10·z + L11·x) + band 2 written as a quadratic form.
			xx = SH_Y22 * L22; yy = - SH_Y22 * L22; zz = 3 * SH_Y20 * L20;
			xy = 0.5 * SH_Y2_PRODUCT * L2m2; yz = 0.5 * SH_Y2_PRODUCT * L2m1; xz = 0.5 * SH_Y2_PRODUCT * L21;
			band1 = SH_Y1;
			c00 = SH_Y00 * L00; c20 = - SH_Y20 * L20;

		}

		matrix[ 0 ] = xx; matrix[ 1 ] = xy; matrix[ 2 ] = xz;
		matrix[ 3 ] = xy; matrix[ 4 ] = yy; matrix[ 5 ] = yz;
		matrix[ 6 ] = xz; matrix[ 7 ] = yz; matrix[ 8 ] = zz;
		eigenSymmetric3( matrix, vectors );

		linear[ 0 ] = band1 * L11; linear[ 1 ] = band1 * L1m1; linear[ 2 ] = band1 * L10;
		for ( let i = 0; i < 3; i ++ ) {

			channels[ q + i ] = matrix[ 4 * i ];
			// β₀ᵢ = (column i of Q) · b₀ / 2.
			channels[ q + 3 + i ] = 0.5 * ( vectors[ i ] * linear[ 0 ] + vectors[ 3 + i ] * linear[ 1 ] + vectors[ 6 + i ] * linear[ 2 ] );

		}

		channels[ q + 6 ] = c00;
		channels[ q + 7 ] = c20;
		for ( let i = 0; i < 9; i ++ ) channels[ q + 8 + i ] = vectors[ i ];
		channels[ q + 17 ] = 0;

	}

}

/**
 * The minimum of h₂·(nᵀA₀n) + h₁·(b₀ᵀn) + c₀₀ + h₂·c₂₀ over |n| = 1 for one prepared channel, as
 * the dual value g(t) = c + d_min − t − Σ βᵢ²/(eᵢ + t), eᵢ = dᵢ − d_min ≥ 0, t = d_min − λ ≥ 0;
 * g is concave in t and every t ≥ 0 gives a lower bound, maximal where Σ βᵢ²/(eᵢ + t)² = 1.
 * Leaves t and the minimiser (eigenbasis) in `solution`.
 */
function channelMinimum( channel: number, h1: number, h2: number ): number {

	const q = channel * CHANNEL_FLOATS;
	const d0 = h2 * channels[ q ], d1 = h2 * channels[ q + 1 ], d2 = h2 * channels[ q + 2 ];
	const b0 = h1 * channels[ q + 3 ], b1 = h1 * channels[ q + 4 ], b2 = h1 * channels[ q + 5 ];
	const c = channels[ q + 6 ] + h2 * channels[ q + 7 ];
	const dMin = Math.min( d0, d1, d2 );
	const e0 = d0 - dMin, e1 = d1 - dMin, e2 = d2 - dMin;
	const q0 = b0 * b0, q1 = b1 * b1, q2 = b2 * b2;

	// The "hard case": no linear term along the lowest eigenvector(s) and a weak one elsewhere; then
	// λ = d_min and the minimiser is completed with a component along that eigenvector.
	let t = 0;
	const atZero = secular( 0, e0, e1, e2, q0, q1, q2 );
	if ( atZero > 1 ) {

		// h(t) ≥ βᵢ²/(eᵢ + t)² and h(t) ≤ |β|²/t² bracket the root.
		let lo = Math.max( 0, Math.abs( b0 ) - e0, Math.abs( b1 ) - e1, Math.abs( b2 ) - e2 );
		let hi = Math.sqrt( q0 + q1 + q2 );
		t = hi;
		for ( let iteration = 0; iteration < 100; iteration ++ ) {

			// Newton on ψ(t) = 1 − 1/√h(t), nearly linear in t (exactly, for one term; Moré &
			// Sorensen 1983): ψ' = −Σ βᵢ²/(eᵢ + t)³ / h^(3/2), so the step is ψ·h^(3/2)/Σ.
			const h = secular( t, e0, e1, e2, q0, q1, q2 );
			if ( h > 1 ) lo = t; else hi = t;
			const derivative = secularDerivative( t, e0, e1, e2, q0, q1, q2 );
			const psi = 1 - 1 / Math.sqrt( h );
			const step = derivative > 0 ? psi * h * Math.sqrt( h ) / derivative : NaN;
			// Converged (any t ≥ 0 is a valid lower bound; near the root g is flat in t).
			if ( Math.abs( step ) <= 1e-14 * t || hi - lo <= 1e-14 * hi ) break;
			const next = t + step;
			t = next > lo && next < hi ? next : 0.5 * ( lo + hi );

		}

	}

	let value = c + dMin - t;
	if ( q0 > 0 ) value -= q0 / ( e0 + t );
	if ( q1 > 0 ) value -= q1 / ( e1 + t );
	if ( q2 > 0 ) value -= q2 / ( e2 + t );

	// Minimiser: pᵢ = −βᵢ/(eᵢ + t), plus the hard-case completion along the lowest eigenvector.
	solution[ 0 ] = t;
	solution[ 1 ] = q0 > 0 ? - b0 / ( e0 + t ) : 0;
	solution[ 2 ] = q1 > 0 ? - b1 / ( e1 + t ) : 0;
	solution[ 3 ] = q2 > 0 ? - b2 / ( e2 + t ) : 0;
	const norm2 = solution[ 1 ] * solution[ 1 ] + solution[ 2 ] * solution[ 2 ] + solution[ 3 ] * solution[ 3 ];
	if ( norm2 < 1 ) {

		const lowest = e0 === 0 ? 1 : e1 === 0 ? 2 : 3;
		solution[ lowest ] += Math.sqrt( 1 - norm2 ) * ( solution[ lowest ] < 0 ? - 1 : 1 );

	}

	return value;

}

function secular( t: number, e0: number, e1: number, e2: number, q0: number, q1: number, q2: number ): number {

	let h = 0;
	if ( q0 > 0 ) h += q0 / ( ( e0 + t ) * ( e0 + t ) );
	if ( q1 > 0 ) h += q1 / ( ( e1 + t ) * ( e1 + t ) );
	if ( q2 > 0 ) h += q2 / ( ( e2 + t ) * ( e2 + t ) );
	return h; // q > 0 with e + t = 0 gives +Infinity, which is what the bracket needs

}

function secularDerivative( t: number, e0: number, e1: number, e2: number, q0: number, q1: number, q2: number ): number {

	let s = 0;
	if ( q0 > 0 ) { const u = e0 + t; s += q0 / ( u * u * u ); }
	if ( q1 > 0 ) { const u = e1 + t; s += q1 / ( u * u * u ); }
	if ( q2 > 0 ) { const u = e2 + t; s += q2 / ( u * u * u ); }
	return s;

}

/** The last channelMinimum's minimiser, rotated back to world axes and normalised. */
function writeDirection( channel: number, out: WritableArrayLike, offset: number ): void {

	const q = channel * CHANNEL_FLOATS + 8;
	let x = 0, y = 0, z = 0;
	for ( let i = 0; i < 3; i ++ ) {

		const p = solution[ 1 + i ];
		x += channels[ q + i ] * p;
		y += channels[ q + 3 + i ] * p;
		z += channels[ q + 6 + i ] * p;

	}

	const length = Math.hypot( x, y, z );
	out[ offset ] = length > 0 ? x / length : 0;
	out[ offset + 1 ] = length > 0 ? y / length : 0;
	out[ offset + 2 ] = length > 0 ? z / length : 1;

}

/**
 * Cyclic Jacobi eigen-decomposition of a symmetric 3×3 matrix (row-major `m`, overwritten: its
 * diagonal becomes the eigenvalues); `v` receives the eigenvectors as columns. Jacobi rather than
 * the closed-form cubic because it stays accurate for the repeated eigenvalues that symmetric
 * lighting produces.
 */
function eigenSymmetric3( m: Float64Array, v: Float64Array ): void {

	v.fill( 0 );
	v[ 0 ] = v[ 4 ] = v[ 8 ] = 1;
	for ( let sweep = 0; sweep < 50; sweep ++ ) {

		const off = m[ 1 ] * m[ 1 ] + m[ 2 ] * m[ 2 ] + m[ 5 ] * m[ 5 ];
		const diagonal = m[ 0 ] * m[ 0 ] + m[ 4 ] * m[ 4 ] + m[ 8 ] * m[ 8 ];
		if ( off === 0 || off <= 1e-34 * diagonal ) break;
		rotate( m, v, 0, 1 );
		rotate( m, v, 0, 2 );
		rotate( m, v, 1, 2 );

	}

}

/** One Jacobi rotation zeroing m[p][q] (Numerical Recipes §11.1 formulation). */
function rotate( m: Float64Array, v: Float64Array, p: number, q: number ): void {

	const apq = m[ 3 * p + q ];
	if ( apq === 0 ) return;
	const theta = ( m[ 3 * q + q ] - m[ 3 * p + p ] ) / ( 2 * apq );
	const t = ( theta >= 0 ? 1 : - 1 ) / ( Math.abs( theta ) + Math.sqrt( theta * theta + 1 ) );
	if ( ! Number.isFinite( t ) || t === 0 ) {

		m[ 3 * p + q ] = m[ 3 * q + p ] = 0; // |apq| negligible next to the diagonal gap
		return;

	}

	const c = 1 / Math.sqrt( t * t + 1 ), s = t * c;
	for ( let k = 0; k < 3; k ++ ) {

		const akp = m[ 3 * k + p ], akq = m[ 3 * k + q ];
		m[ 3 * k + p ] = c * akp - s * akq;
		m[ 3 * k + q ] = s * akp + c * akq;

	}

	for ( let k = 0; k < 3; k ++ ) {

		const apk = m[ 3 * p + k ], aqk = m[ 3 * q + k ];
		m[ 3 * p + k ] = c * apk - s * aqk;
		m[ 3 * q + k ] = s * apk + c * aqk;

	}

	m[ 3 * p + q ] = m[ 3 * q + p ] = 0;
	for ( let k = 0; k < 3; k ++ ) {

		const vkp = v[ 3 * k + p ], vkq = v[ 3 * k + q ];
		v[ 3 * k + p ] = c * vkp - s * vkq;
		v[ 3 * k + q ] = s * vkp + c * vkq;

	}

}

function assertStrength( where: string, name: string, value: unknown ): asserts value is number {

	assertNumber( where, name, value );
	if ( value < 0 || value > 1 ) {

		throw new RangeError( `${where}: ${name} must be in [0, 1] (0 = no window, 1 = only L00 kept), got ${value}.` );

	}

}

/** Validates `sh` and the probe range; checks only the probes in the range for finiteness. */
function assertProbeRange( where: string, sh: unknown, firstProbe: unknown, probeCount: unknown ): number {

	assertArrayLike( where, 'sh', sh );
	if ( sh.length === 0 || sh.length % SH_FLOATS !== 0 ) {

		throw new RangeError( `${where}: sh must have a length that is a positive multiple of 27 (9 RGB coefficients per probe), got ${sh.length}.` );

	}

	const total = sh.length / SH_FLOATS;
	assertInteger( where, 'firstProbe', firstProbe, 0, total - 1 );
	const count = probeCount ?? total - firstProbe;
	assertInteger( where, 'probeCount', count, 0, total - firstProbe );
	for ( let p = firstProbe; p < firstProbe + count; p ++ ) assertProbeFinite( where, sh, p * SH_FLOATS );
	return count;

}

function assertProbeFinite( where: string, sh: ArrayLike<number>, o: number ): void {

	for ( let i = o; i < o + SH_FLOATS; i ++ ) {

		const v = sh[ i ];
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) {

			throw new RangeError( `${where}: sh[${i}] is ${String( v )}; all values must be finite numbers.` );

		}

	}

}
