import { boundsOf } from '../geometry/boundsOf.js';

/**
 * The probes to add to `initial` so that together they span the dense set's dimension (a volume,
 * or an area when the whole set is flat): each new one the farthest from the affine hull of those
 * before — starting, when `initial` is empty, from the probe farthest from the bounding box's
 * centre (a corner of a box-shaped set). At most 4 probes, none when `initial` already spans.
 * @throws RangeError when the dense set lies on a line (no area or volume to interpolate over).
 */
export function completeSpan( where: string, points: Float64Array, rank: Uint32Array, initial: readonly number[] ): number[] {

	const count = points.length / 3;
	const b = boundsOf( points );
	const min = [ b[ 0 ], b[ 1 ], b[ 2 ] ], max = [ b[ 3 ], b[ 4 ], b[ 5 ] ];

	// Same relative tolerance as the tetrahedralizer's duplicate and planarity tests.
	const tolerance = 1e-9 * Math.hypot( max[ 0 ] - min[ 0 ], max[ 1 ] - min[ 1 ], max[ 2 ] - min[ 2 ] );
	const centre = [ 0, 1, 2 ].map( ( a ) => ( min[ a ] + max[ a ] ) / 2 );

	/** Affine basis of the chosen points: an origin and up to 3 orthonormal directions. */
	let origin: number[] | null = null;
	const basis: number[][] = [];
	const distanceFromHull = ( p: number ): number => {

		if ( origin === null ) {

			return Math.hypot( points[ 3 * p ] - centre[ 0 ], points[ 3 * p + 1 ] - centre[ 1 ], points[ 3 * p + 2 ] - centre[ 2 ] );

		}

		const d = [ points[ 3 * p ] - origin[ 0 ], points[ 3 * p + 1 ] - origin[ 1 ], points[ 3 * p + 2 ] - origin[ 2 ] ];
		for ( const u of basis ) {

			const t = d[ 0 ] * u[ 0 ] + d[ 1 ] * u[ 1 ] + d[ 2 ] * u[ 2 ];
			d[ 0 ] -= t * u[ 0 ]; d[ 1 ] -= t * u[ 1 ]; d[ 2 ] -= t * u[ 2 ];

		}

		return Math.hypot( d[ 0 ], d[ 1 ], d[ 2 ] );

	};

	/** Adds p to the affine hull when it lies off it (Gram–Schmidt on its offset from the origin). */
	const extend = ( p: number ): boolean => {

		if ( origin === null ) {

			origin = [ points[ 3 * p ], points[ 3 * p + 1 ], points[ 3 * p + 2 ] ];
			return true;

		}

		const d = [ points[ 3 * p ] - origin[ 0 ], points[ 3 * p + 1 ] - origin[ 1 ], points[ 3 * p + 2 ] - origin[ 2 ] ];
		for ( const u of basis ) {

			const t = d[ 0 ] * u[ 0 ] + d[ 1 ] * u[ 1 ] + d[ 2 ] * u[ 2 ];
			d[ 0 ] -= t * u[ 0 ]; d[ 1 ] -= t * u[ 1 ]; d[ 2 ] -= t * u[ 2 ];

		}

		const length = Math.hypot( d[ 0 ], d[ 1 ], d[ 2 ] );
		if ( ! ( length > tolerance ) ) return false;
		basis.push( [ d[ 0 ] / length, d[ 1 ] / length, d[ 2 ] / length ] );
		return true;

	};

	// The dimension the given probes already span: each extends the hull if it lies off it. One
	// pass suffices for a basis, not for the farthest choice, which only the added probes need.
	for ( const p of initial ) if ( basis.length < 3 ) extend( p );

	const added: number[] = [];
	while ( basis.length < 3 ) {

		// The farthest from the hull; among near-ties (a box's whole face is equally far from a plane
		// through its diagonal) the one farthest from the centre — a corner — then the seeded rank.
		let farthest = 0;
		for ( let p = 0; p < count; p ++ ) farthest = Math.max( farthest, distanceFromHull( p ) );
		let best = - 1, bestCentre = - 1;
		for ( let p = 0; p < count; p ++ ) {

			if ( distanceFromHull( p ) < farthest * ( 1 - 1e-9 ) ) continue;
			const c = Math.hypot( points[ 3 * p ] - centre[ 0 ], points[ 3 * p + 1 ] - centre[ 1 ], points[ 3 * p + 2 ] - centre[ 2 ] );
			if ( c > bestCentre * ( 1 + 1e-9 ) || ( c >= bestCentre * ( 1 - 1e-9 ) && rank[ p ] < rank[ best ] ) ) {

				best = p;
				bestCentre = c;

			}

		}

		// Nothing off the hull: the set spans no more dimensions. (A probe of `initial` lies on the
		// hull, so `best` is always a new one.)
		if ( ! extend( best ) ) break;
		added.push( best );

	}

	if ( basis.length < 2 ) {

		throw new RangeError( `${where}: positions lie on one line (or in one point); probes must span an area or a volume to be interpolated.` );

	}

	return added;

}
