import { coplanarOrient, orient } from './predicates.js';
import { DegenerateInputError } from './DegenerateInputError.js';

// Below this a distance computed in floating point may be an underflowed square root; tolerances
// below it are then decided by the exact predicates instead (docs/robustness.md).
const RELIABLE = 2 ** - 500;

/**
 * Four affinely independent points, far apart: the first of the extreme points in x, then the
 * farthest from it, from their line, from their plane. Tolerances make near-degenerate sets fail
 * loudly here instead of producing a mesh of slivers; a tolerance below 2^−500 of the extent
 * (e.g. 0) leaves the decision to exact tests.
 * @param p Flat x, y, z, normalised (see `normalizePoints`).
 * @param unique Distinct point indices (at least 4).
 * @param diagonal The extent the tolerance is relative to.
 * @throws {DegenerateInputError} (`'collinear'` or `'coplanar'`) when no such four points exist.
 */
export function findInitialTetrahedron(
	caller: string, p: Float64Array, unique: Uint32Array, diagonal: number, planarTolerance: number,
): [ number, number, number, number ] {

	const tolerance = planarTolerance * diagonal;
	let i0 = unique[ 0 ];
	for ( let i = 1; i < unique.length; i ++ ) if ( p[ 3 * unique[ i ] ] < p[ 3 * i0 ] ) i0 = unique[ i ];
	const ax = p[ 3 * i0 ], ay = p[ 3 * i0 + 1 ], az = p[ 3 * i0 + 2 ];

	let i1 = - 1, best = 0;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const dx = p[ 3 * v ] - ax, dy = p[ 3 * v + 1 ] - ay, dz = p[ 3 * v + 2 ] - az;
		const d = dx * dx + dy * dy + dz * dz;
		if ( d > best || ( i1 < 0 && v !== i0 ) ) { best = d; i1 = v; }

	}

	const ux = p[ 3 * i1 ] - ax, uy = p[ 3 * i1 + 1 ] - ay, uz = p[ 3 * i1 + 2 ] - az;
	let i2 = - 1;
	best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const dx = p[ 3 * v ] - ax, dy = p[ 3 * v + 1 ] - ay, dz = p[ 3 * v + 2 ] - az;
		const cx = uy * dz - uz * dy, cy = uz * dx - ux * dz, cz = ux * dy - uy * dx;
		const d = cx * cx + cy * cy + cz * cz; // |u × d|² = |u|² · distance² to the line
		if ( d > best ) { best = d; i2 = v; }

	}

	const lineDistance = Math.sqrt( best / ( ux * ux + uy * uy + uz * uz ) );
	if ( ! ( lineDistance >= RELIABLE ) ) {

		// Squares underflowed: within any tolerance the float test can see, or decide exactly.
		i2 = tolerance >= RELIABLE ? - 1 : firstOffLine( p, unique, i0, i1 );
		if ( i2 < 0 ) throw collinear( caller, unique.length, planarTolerance );

	} else if ( lineDistance <= tolerance ) {

		throw collinear( caller, unique.length, planarTolerance );

	}

	const vx = p[ 3 * i2 ] - ax, vy = p[ 3 * i2 + 1 ] - ay, vz = p[ 3 * i2 + 2 ] - az;
	let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
	const nl = Math.hypot( nx, ny, nz );
	nx /= nl; ny /= nl; nz /= nl;

	let i3 = - 1;
	best = - 1;
	for ( let i = 0; i < unique.length; i ++ ) {

		const v = unique[ i ];
		const d = Math.abs( ( p[ 3 * v ] - ax ) * nx + ( p[ 3 * v + 1 ] - ay ) * ny + ( p[ 3 * v + 2 ] - az ) * nz );
		if ( d > best ) { best = d; i3 = v; }

	}

	if ( ! ( best >= RELIABLE ) ) {

		if ( tolerance >= RELIABLE ) throw coplanar( caller, unique.length, planarTolerance );
		i3 = - 1;

	} else if ( best <= tolerance ) {

		throw coplanar( caller, unique.length, planarTolerance );

	}

	// The float normal may be too rough to find a point off the plane that exists: ask exactly.
	if ( i3 < 0 || orient( p, i0, i1, i2, i3 ) === 0 ) i3 = firstOffPlane( p, unique, i0, i1, i2 );
	if ( i3 < 0 ) throw coplanar( caller, unique.length, planarTolerance );
	return orient( p, i0, i1, i2, i3 ) > 0 ? [ i0, i1, i2, i3 ] : [ i0, i2, i1, i3 ];

}

/** The first of `ids` not on the line through a and b (exact), or −1. */
function firstOffLine( p: Float64Array, ids: Uint32Array, a: number, b: number ): number {

	for ( let i = 0; i < ids.length; i ++ ) if ( coplanarOrient( p, a, b, ids[ i ] ) !== 0 ) return ids[ i ];
	return - 1;

}

/** The first of `ids` not in the plane through a, b and c (exact), or −1. */
function firstOffPlane( p: Float64Array, ids: Uint32Array, a: number, b: number, c: number ): number {

	for ( let i = 0; i < ids.length; i ++ ) if ( orient( p, a, b, c, ids[ i ] ) !== 0 ) return ids[ i ];
	return - 1;

}

function collinear( caller: string, count: number, tolerance: number ): DegenerateInputError {

	return new DegenerateInputError( 'collinear', `${caller}: all ${count} distinct points lie on one line (within ${tolerance} of the extent); they span no area or volume.` );

}

function coplanar( caller: string, count: number, tolerance: number ): DegenerateInputError {

	return new DegenerateInputError( 'coplanar', `${caller}: all ${count} distinct points lie in one plane (within ${tolerance} of the extent); a volume needs at least one point off that plane. Use createProbeInterpolator for planar layouts.` );

}
