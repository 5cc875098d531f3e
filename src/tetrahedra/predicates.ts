import { orient3d, insphere, orient2d } from 'robust-predicates';

/*
 * Exact geometric predicates on points stored as a flat Float64Array (x, y, z per point), plus
 * the symbolic perturbation that makes co-spherical and co-circular ties consistent.
 *
 * Sign conventions used throughout src/tetrahedra (note robust-predicates' orient3d has the
 * opposite sign):
 *   orient( a, b, c, d ) > 0  ⇔  det[ b − a, c − a, d − a ] > 0 (a positively oriented tetrahedron)
 *   inSphere( a, b, c, d, e ) > 0  ⇔  e strictly inside the circumsphere of the positive tetrahedron abcd
 *
 * The perturbation follows Devillers & Teillaud, "Perturbations for Delaunay and weighted Delaunay
 * 3D triangulations" (2011), the scheme CGAL uses: every point is lifted by an infinitesimal that
 * grows with its rank in lexicographic (x, y, z) order, so ties are broken by the same rule whatever
 * the insertion order, and the result is the Delaunay triangulation of the perturbed set — a valid
 * Delaunay triangulation of the input in which no tetrahedron is flat.
 */

/** Sign of det[ b − a, c − a, d − a ], exact. */
export function orient( p: Float64Array, a: number, b: number, c: number, d: number ): number {

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c, d3 = 3 * d;
	return - orient3d(
		p[ a3 ], p[ a3 + 1 ], p[ a3 + 2 ],
		p[ b3 ], p[ b3 + 1 ], p[ b3 + 2 ],
		p[ c3 ], p[ c3 + 1 ], p[ c3 + 2 ],
		p[ d3 ], p[ d3 + 1 ], p[ d3 + 2 ]
	);

}

/** Exact in-sphere value for a positively oriented tetrahedron abcd; > 0 when e is strictly inside. */
export function inSphere( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c, d3 = 3 * d, e3 = 3 * e;
	return insphere(
		p[ a3 ], p[ a3 + 1 ], p[ a3 + 2 ],
		p[ b3 ], p[ b3 + 1 ], p[ b3 + 2 ],
		p[ c3 ], p[ c3 + 1 ], p[ c3 + 2 ],
		p[ d3 ], p[ d3 + 1 ], p[ d3 + 2 ],
		p[ e3 ], p[ e3 + 1 ], p[ e3 + 2 ]
	);

}

/** Lexicographic (x, y, z) comparison: the perturbation's rank order. */
function lexLess( p: Float64Array, a: number, b: number ): boolean {

	const a3 = 3 * a, b3 = 3 * b;
	if ( p[ a3 ] !== p[ b3 ] ) return p[ a3 ] < p[ b3 ];
	if ( p[ a3 + 1 ] !== p[ b3 + 1 ] ) return p[ a3 + 1 ] < p[ b3 + 1 ];
	return p[ a3 + 2 ] < p[ b3 + 2 ];

}

const _sorted = new Int32Array( 5 );

function sortByRank( p: Float64Array, count: number ): void {

	// Insertion sort of at most five indices.
	for ( let i = 1; i < count; i ++ ) {

		const v = _sorted[ i ];
		let j = i - 1;
		while ( j >= 0 && lexLess( p, v, _sorted[ j ] ) ) {

			_sorted[ j + 1 ] = _sorted[ j ];
			j --;

		}

		_sorted[ j + 1 ] = v;

	}

}

/**
 * In-sphere test with symbolic perturbation for a positively oriented tetrahedron abcd:
 * +1 when e is inside the perturbed circumsphere, −1 when outside; never 0 for distinct points.
 */
export function inSpherePerturbed( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

	const s = inSphere( p, a, b, c, d, e );
	if ( s > 0 ) return 1;
	if ( s < 0 ) return - 1;
	return inSphereTieBreak( p, a, b, c, d, e );

}

/**
 * The perturbed in-sphere sign when the exact in-sphere value is 0 (e on the circumsphere of the
 * positive tetrahedron abcd): +1 inside, −1 outside.
 */
export function inSphereTieBreak( p: Float64Array, a: number, b: number, c: number, d: number, e: number ): number {

	_sorted[ 0 ] = a; _sorted[ 1 ] = b; _sorted[ 2 ] = c; _sorted[ 3 ] = d; _sorted[ 4 ] = e;
	sortByRank( p, 5 );

	// The leading non-zero term of the perturbed determinant belongs to the highest-ranked point;
	// its cofactor is the orientation of the other four.
	for ( let i = 4; i > 1; i -- ) {

		const q = _sorted[ i ];
		if ( q === e ) return - 1;
		let o = 0;
		if ( q === d ) o = orient( p, a, b, c, e );
		else if ( q === c ) o = orient( p, a, b, e, d );
		else if ( q === b ) o = orient( p, a, e, c, d );
		else if ( q === a ) o = orient( p, e, b, c, d );
		if ( o !== 0 ) return o > 0 ? 1 : - 1;

	}

	return - 1;

}

/**
 * Orientation of three points inside their common plane, exact: the first coordinate-plane
 * projection (xy, yz, xz) in which they are not collinear. Which projection is used depends only
 * on the plane, so signs are comparable between triples of one plane. 0 when collinear.
 */
export function coplanarOrient( p: Float64Array, a: number, b: number, c: number ): number {

	const a3 = 3 * a, b3 = 3 * b, c3 = 3 * c;
	let o = orient2d( p[ a3 ], p[ a3 + 1 ], p[ b3 ], p[ b3 + 1 ], p[ c3 ], p[ c3 + 1 ] );
	if ( o !== 0 ) return o > 0 ? 1 : - 1;
	o = orient2d( p[ a3 + 1 ], p[ a3 + 2 ], p[ b3 + 1 ], p[ b3 + 2 ], p[ c3 + 1 ], p[ c3 + 2 ] );
	if ( o !== 0 ) return o > 0 ? 1 : - 1;
	o = orient2d( p[ a3 ], p[ a3 + 2 ], p[ b3 ], p[ b3 + 2 ], p[ c3 ], p[ c3 + 2 ] );
	return o > 0 ? 1 : ( o < 0 ? - 1 : 0 );

}

// Scratch point slot for the auxiliary off-plane point of inCircleCoplanar.
const _aux = new Float64Array( 18 );

/**
 * Exact: +1 when e (coplanar with abc) is strictly inside the circumcircle of abc, −1 outside, 0 on it.
 * Any sphere through a, b, c cuts their plane in exactly that circle, so an in-sphere test against
 * a, b, c and any point q off the plane decides it exactly; q only has to be off the plane, which
 * orient() checks exactly.
 */
export function inCircleCoplanar( p: Float64Array, a: number, b: number, c: number, e: number, extent: number ): number {

	for ( let k = 0; k < 3; k ++ ) {

		_aux[ k ] = p[ 3 * a + k ];
		_aux[ 3 + k ] = p[ 3 * b + k ];
		_aux[ 6 + k ] = p[ 3 * c + k ];
		_aux[ 12 + k ] = p[ 3 * e + k ];

	}

	// Push q along the axis where the plane's normal is largest; try the others if rounding made q coplanar.
	const ux = _aux[ 3 ] - _aux[ 0 ], uy = _aux[ 4 ] - _aux[ 1 ], uz = _aux[ 5 ] - _aux[ 2 ];
	const vx = _aux[ 6 ] - _aux[ 0 ], vy = _aux[ 7 ] - _aux[ 1 ], vz = _aux[ 8 ] - _aux[ 2 ];
	const nx = Math.abs( uy * vz - uz * vy ), ny = Math.abs( uz * vx - ux * vz ), nz = Math.abs( ux * vy - uy * vx );
	const first = nx >= ny && nx >= nz ? 0 : ( ny >= nz ? 1 : 2 );

	for ( let k = 0; k < 3; k ++ ) {

		const axis = ( first + k ) % 3;
		_aux[ 9 ] = _aux[ 0 ]; _aux[ 10 ] = _aux[ 1 ]; _aux[ 11 ] = _aux[ 2 ];
		_aux[ 9 + axis ] += extent;
		const o = orient( _aux, 0, 1, 2, 3 );
		if ( o === 0 ) continue;
		const s = inSphere( _aux, 0, 1, 2, 3, 4 );
		if ( s === 0 ) return 0;
		return ( s > 0 ) === ( o > 0 ) ? 1 : - 1;

	}

	return 0; // abc collinear: no circle

}

/**
 * In-circle test with symbolic perturbation for e coplanar with the non-collinear triangle abc:
 * +1 inside the perturbed circumcircle, −1 outside. Used for points on the plane of a hull face.
 */
export function inCirclePerturbed( p: Float64Array, a: number, b: number, c: number, e: number, extent: number ): number {

	const s = inCircleCoplanar( p, a, b, c, e, extent );
	if ( s !== 0 ) return s;

	_sorted[ 0 ] = a; _sorted[ 1 ] = b; _sorted[ 2 ] = c; _sorted[ 3 ] = e;
	sortByRank( p, 4 );
	const local = coplanarOrient( p, a, b, c );

	for ( let i = 3; i > 0; i -- ) {

		const q = _sorted[ i ];
		if ( q === e ) return - 1;
		let o = 0;
		if ( q === c ) o = coplanarOrient( p, a, b, e );
		else if ( q === b ) o = coplanarOrient( p, a, e, c );
		else if ( q === a ) o = coplanarOrient( p, e, b, c );
		if ( o !== 0 ) return o * local > 0 ? 1 : - 1;

	}

	return - 1;

}
