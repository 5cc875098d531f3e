/**
 * Cyclic Jacobi eigen-decomposition of a symmetric 3×3 matrix: row-major `m` is overwritten (its
 * diagonal becomes the eigenvalues) and `v` receives the eigenvectors as columns. Used by the
 * minimum over the sphere ({@link SHSphereMinimum}); accurate for repeated eigenvalues.
 * @internal
 */
export function eigenSymmetric3( m: Float64Array, v: Float64Array ): void {

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
