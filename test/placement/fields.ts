/**
 * Synthetic probe fields with known truth for the reduction tests: SH9 defined analytically per
 * position, so "how well does a subset reproduce the dense set" has an exact answer.
 */

/**
 * A field linear in position: every coefficient of every channel is a + b·x + c·y + d·z. L00 is
 * large enough that irradiance stays positive over [0, 1]³. Tetrahedral (barycentric)
 * interpolation reproduces any linear function exactly, so any subset whose hull covers the
 * points reproduces this field up to float rounding.
 */
export function linearField( x: number, y: number, z: number, out: Float32Array | Float64Array, offset = 0 ): void {

	for ( let j = 0; j < 9; j ++ ) for ( let c = 0; c < 3; c ++ ) {

		const base = j === 0 ? 2 + 0.3 * c : 0.05 * ( ( j * 7 + c * 3 ) % 5 - 2 );
		out[ offset + 3 * j + c ] = base + 0.4 * Math.sin( j + c ) * x + 0.3 * Math.cos( 2 * j + c ) * y - 0.2 * Math.sin( 3 * j - c ) * z;

	}

}

/** Centre and width (standard deviation) of the bump of {@link bumpField}. */
export const BUMP_CENTRE = [ 0.8, 0.75, 0.85 ] as const;
export const BUMP_SIGMA = 0.12;

/**
 * {@link linearField} plus a localised reddish Gaussian bump of light near one corner of the unit
 * cube (as a coloured lamp or a sun patch would add), brighter from +y: L00 and L1−1 (the y
 * coefficient) grow by up to 1.5 and 0.8 at {@link BUMP_CENTRE}. Away from the bump the field is
 * linear, so only the bump needs probes beyond the hull.
 */
export function bumpField( x: number, y: number, z: number, out: Float32Array | Float64Array, offset = 0 ): void {

	linearField( x, y, z, out, offset );
	const r2 = ( x - BUMP_CENTRE[ 0 ] ) ** 2 + ( y - BUMP_CENTRE[ 1 ] ) ** 2 + ( z - BUMP_CENTRE[ 2 ] ) ** 2;
	const g = Math.exp( - r2 / ( 2 * BUMP_SIGMA * BUMP_SIGMA ) );
	const tint = [ 1, 0.4, 0.2 ];
	for ( let c = 0; c < 3; c ++ ) {

		out[ offset + c ] += 3 * g * tint[ c ];
		out[ offset + 3 + c ] += 1.5 * g * tint[ c ];

	}

}

/** Evaluates a field at every point: 27 floats per point (Float32, as captures are stored). */
export function sampleField( field: typeof linearField, positions: Float64Array ): Float32Array {

	const sh = new Float32Array( 9 * positions.length );
	for ( let p = 0; p < positions.length / 3; p ++ ) {

		field( positions[ 3 * p ], positions[ 3 * p + 1 ], positions[ 3 * p + 2 ], sh, 27 * p );

	}

	return sh;

}
