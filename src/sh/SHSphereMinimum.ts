/**
 * The exact minimum over the unit sphere of one probe's reconstructed irradiance or radiance, per
 * colour channel and for any window strength; the method is derived in docs/ringing.md.
 */

import {
	IRRADIANCE_C1, IRRADIANCE_C2, IRRADIANCE_C3, IRRADIANCE_C4, IRRADIANCE_C5,
	SH_Y00, SH_Y1, SH_Y2_PRODUCT, SH_Y20, SH_Y22,
} from './SHBasis.js';
import { eigenSymmetric3 } from './eigenSymmetric3.js';
import type { WritableArrayLike } from './irradiance.js';

/** What is minimised: the irradiance E(n) the patched materials shade, or the radiance L(ω). */
export type SphereQuantity = 'irradiance' | 'radiance';

/*
 * Floats per channel in `channels`: eigenvalues d₀ (3), β₀ = Qᵀb₀/2 (3), c₀₀, c₂₀, Q (9, row-major,
 * columns = eigenvectors), skipped flag.
 */
const CHANNEL_FLOATS = 18;

/**
 * Minimum of a probe's reconstructed E(n) or L(ω) over all unit directions, per channel. `prepare`
 * reads a probe once (band-split quadratic, eigenvectors of its band-2 matrix); each
 * `channelMinimum` then costs one secular solve for a window's band factors h₁, h₂, and
 * `writeDirection` gives the direction that attains the last minimum. Allocation-free after
 * construction; one instance is reusable scratch for any number of probes.
 * @internal
 */
export class SHSphereMinimum {

	/** Per channel, the prepared quadratic (layout CHANNEL_FLOATS). */
	private readonly channels = new Float64Array( 3 * CHANNEL_FLOATS );

	private readonly matrix = new Float64Array( 9 );

	private readonly vectors = new Float64Array( 9 );

	private readonly linear = new Float64Array( 3 );

	/** The last channelMinimum's t, and its minimiser in the eigenbasis. */
	private readonly solution = new Float64Array( 4 );

	/**
	 * Builds, for each channel of the probe whose first float is `sh[ o ]`, the band-split quadratic
	 * and the eigen-decomposition of its band-2 matrix A₀; clears the skipped flags.
	 */
	prepare( quantity: SphereQuantity, sh: ArrayLike<number>, o: number ): void {

		const { channels, matrix, vectors, linear } = this;
		for ( let channel = 0; channel < 3; channel ++ ) {

			const s = o + channel;
			const L00 = sh[ s ], L1m1 = sh[ s + 3 ], L10 = sh[ s + 6 ], L11 = sh[ s + 9 ];
			const L2m2 = sh[ s + 12 ], L2m1 = sh[ s + 15 ], L20 = sh[ s + 18 ], L21 = sh[ s + 21 ], L22 = sh[ s + 24 ];
			const q = channel * CHANNEL_FLOATS;
			let xx, yy, zz, xy, yz, xz, band1, c00, c20;
			if ( quantity === 'irradiance' ) {

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
				channels[ q + 3 + i ] = 0.5 * (
					vectors[ i ] * linear[ 0 ] + vectors[ 3 + i ] * linear[ 1 ] + vectors[ 6 + i ] * linear[ 2 ]
				);

			}

			channels[ q + 6 ] = c00;
			channels[ q + 7 ] = c20;
			for ( let i = 0; i < 9; i ++ ) channels[ q + 8 + i ] = vectors[ i ];
			channels[ q + 17 ] = 0;

		}

	}

	/** The prepared channel's constant term c₀₀ (∝ L00): its value once the window leaves only L00. */
	constantTerm( channel: number ): number {

		return this.channels[ channel * CHANNEL_FLOATS + 6 ];

	}

	/** Marks a prepared channel as skipped (or not) by the non-negative search; `prepare` clears it. */
	setSkipped( channel: number, skipped: boolean ): void {

		this.channels[ channel * CHANNEL_FLOATS + 17 ] = skipped ? 1 : 0;

	}

	/** Whether {@link setSkipped} marked the channel since the last `prepare`. */
	isSkipped( channel: number ): boolean {

		return this.channels[ channel * CHANNEL_FLOATS + 17 ] !== 0;

	}

	/**
	 * The minimum over |n| = 1 of a prepared channel windowed by band factors h₁, h₂:
	 * h₂·(nᵀA₀n) + h₁·(b₀ᵀn) + c₀₀ + h₂·c₂₀. Never above the true minimum (a dual lower bound).
	 */
	channelMinimum( channel: number, h1: number, h2: number ): number {

		const { channels, solution } = this;
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

	/**
	 * Writes the unit direction attaining the last {@link channelMinimum} of `channel` (rotated back
	 * to world axes) to `out[ offset .. offset + 2 ]`.
	 */
	writeDirection( channel: number, out: WritableArrayLike, offset: number ): void {

		const { channels, solution } = this;
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

}

/** h(t) = Σ βᵢ²/(eᵢ + t)²: the squared length of the minimiser at t. */
function secular( t: number, e0: number, e1: number, e2: number, q0: number, q1: number, q2: number ): number {

	let h = 0;
	if ( q0 > 0 ) h += q0 / ( ( e0 + t ) * ( e0 + t ) );
	if ( q1 > 0 ) h += q1 / ( ( e1 + t ) * ( e1 + t ) );
	if ( q2 > 0 ) h += q2 / ( ( e2 + t ) * ( e2 + t ) );
	return h; // q > 0 with e + t = 0 gives +Infinity, which is what the bracket needs

}

/** Σ βᵢ²/(eᵢ + t)³ (−½ h'(t)). */
function secularDerivative( t: number, e0: number, e1: number, e2: number, q0: number, q1: number, q2: number ): number {

	let s = 0;
	if ( q0 > 0 ) { const u = e0 + t; s += q0 / ( u * u * u ); }
	if ( q1 > 0 ) { const u = e1 + t; s += q1 / ( u * u * u ); }
	if ( q2 > 0 ) { const u = e2 + t; s += q2 / ( u * u * u ); }
	return s;

}
