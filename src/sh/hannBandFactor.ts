/**
 * The Hann window factor of SH band l at window strength s (P.-P. Sloan, "Stupid Spherical Harmonics
 * (SH) Tricks", GDC 2008): h_l = ½·(1 + cos(π·l·s)) for l·s < 1, else 0. Shared by the window
 * ({@link windowSH}) and the non-negative search, which must scale the bands identically.
 * @internal
 */
export function hannBandFactor( band: number, strength: number ): number {

	const x = band * strength;
	return x >= 1 ? 0 : 0.5 * ( 1 + Math.cos( Math.PI * x ) );

}
