/*
 * The per-draw form of a patched material's probe term (object mode, per pixel or per vertex).
 * E(n) = nᵀMn with n = (world normal, 1) becomes a polynomial in the unit view-space normal v that
 * three's shaders already have: with R the view matrix's rotation (world → view), n = Rᵀv, so
 * E = vᵀ(R A Rᵀ)v + (R b)·v + k for A, b, k the quadratic, linear and constant parts of M, and
 * z² = 1 − x² − y² folds nine terms into eight plus a constant. The shader then skips the
 * world-normal transform and its normalisation, and does eight multiply-adds of vec3 where the
 * matrix products took fifteen four-component dot products (issue 16; docs/frame-cost.md).
 */

/** Floats of {@link viewIrradiance}'s output: 9 RGB coefficients (`uniform vec3 probeVolumeViewIrradiance[ 9 ]`). */
export const VIEW_IRRADIANCE_FLOATS = 27;

/**
 * Writes the coefficients of E(v) = c0 + c1·x + c2·y + c3·z + c4·x² + c5·y² + c6·xy + c7·xz + c8·yz
 * for a unit view-space normal v = (x, y, z), each an RGB triple (`out[ 3·k + channel ]`), from the
 * three world-space irradiance matrices and the intensity they are scaled by. The matrices' symmetric
 * part is used (a quadratic form has no other), so any M gives nᵀMn. The view matrix's rows are
 * normalised, so a uniformly scaled one gives the light of three's own (normalising) inverse transform.
 * Allocation-free: called for every draw of a patched material.
 * @param matrices 48 floats: R's, G's, B's 4×4 matrix, column-major (`irradianceMatrices`).
 * @param intensity Scale of the probe term.
 * @param view The camera's `matrixWorldInverse.elements` (column-major 4×4).
 * @param out Receives 27 floats.
 */
export function viewIrradiance( matrices: ArrayLike<number>, intensity: number, view: ArrayLike<number>, out: Float32Array ): void {

	// Rows of the view rotation (element (i, j) is view[ 4j + i ]), normalised.
	let s = 1 / Math.sqrt( view[ 0 ] * view[ 0 ] + view[ 4 ] * view[ 4 ] + view[ 8 ] * view[ 8 ] );
	const r00 = view[ 0 ] * s, r01 = view[ 4 ] * s, r02 = view[ 8 ] * s;
	s = 1 / Math.sqrt( view[ 1 ] * view[ 1 ] + view[ 5 ] * view[ 5 ] + view[ 9 ] * view[ 9 ] );
	const r10 = view[ 1 ] * s, r11 = view[ 5 ] * s, r12 = view[ 9 ] * s;
	s = 1 / Math.sqrt( view[ 2 ] * view[ 2 ] + view[ 6 ] * view[ 6 ] + view[ 10 ] * view[ 10 ] );
	const r20 = view[ 2 ] * s, r21 = view[ 6 ] * s, r22 = view[ 10 ] * s;

	for ( let c = 0; c < 3; c ++ ) {

		const m = 16 * c;
		// Symmetric part of M: A (3 × 3), the linear term b (= 2 M[i][3] for a symmetric M), k.
		const a00 = matrices[ m ], a11 = matrices[ m + 5 ], a22 = matrices[ m + 10 ];
		const a01 = 0.5 * ( matrices[ m + 1 ] + matrices[ m + 4 ] );
		const a02 = 0.5 * ( matrices[ m + 2 ] + matrices[ m + 8 ] );
		const a12 = 0.5 * ( matrices[ m + 6 ] + matrices[ m + 9 ] );
		const b0 = matrices[ m + 3 ] + matrices[ m + 12 ];
		const b1 = matrices[ m + 7 ] + matrices[ m + 13 ];
		const b2 = matrices[ m + 11 ] + matrices[ m + 14 ];
		const k = matrices[ m + 15 ];

		// T = A Rᵀ (column q of T = A · row q of R), then A' = R T (its six distinct entries).
		const t00 = a00 * r00 + a01 * r01 + a02 * r02, t10 = a01 * r00 + a11 * r01 + a12 * r02, t20 = a02 * r00 + a12 * r01 + a22 * r02;
		const t01 = a00 * r10 + a01 * r11 + a02 * r12, t11 = a01 * r10 + a11 * r11 + a12 * r12, t21 = a02 * r10 + a12 * r11 + a22 * r12;
		const t02 = a00 * r20 + a01 * r21 + a02 * r22, t12 = a01 * r20 + a11 * r21 + a12 * r22, t22 = a02 * r20 + a12 * r21 + a22 * r22;
		const q00 = r00 * t00 + r01 * t10 + r02 * t20;
		const q11 = r10 * t01 + r11 * t11 + r12 * t21;
		const q22 = r20 * t02 + r21 * t12 + r22 * t22;
		const q01 = r00 * t01 + r01 * t11 + r02 * t21;
		const q02 = r00 * t02 + r01 * t12 + r02 * t22;
		const q12 = r10 * t02 + r11 * t12 + r12 * t22;

		out[ c ] = intensity * ( k + q22 );
		out[ 3 + c ] = intensity * ( r00 * b0 + r01 * b1 + r02 * b2 );
		out[ 6 + c ] = intensity * ( r10 * b0 + r11 * b1 + r12 * b2 );
		out[ 9 + c ] = intensity * ( r20 * b0 + r21 * b1 + r22 * b2 );
		out[ 12 + c ] = intensity * ( q00 - q22 );
		out[ 15 + c ] = intensity * ( q11 - q22 );
		out[ 18 + c ] = intensity * 2 * q01;
		out[ 21 + c ] = intensity * 2 * q02;
		out[ 24 + c ] = intensity * 2 * q12;

	}

}
