import { weldCorners } from './weldCorners.js';

/** The closed surfaces of a triangle soup, oriented: what {@link findClosedShells} returns. */
export interface ClosedShells {

	/**
	 * Per triangle: +1 or −1, the sign by which its winding normal (counter-clockwise a → b → c)
	 * points out of the solid its shell bounds; 0 when the triangle is on no closed shell. A shell
	 * drawn from inside (a room of `BackSide` walls) points into its room: the solid is outside it.
	 */
	orientation: Int8Array;

	/** Per triangle: the index of its closed shell, or −1. */
	shell: Int32Array;

	/** Number of closed shells. */
	count: number;

	/**
	 * Per shell: 1 when its orientation comes from single-sided materials (the side drawn faces out
	 * of the solid), 0 when it was chosen — a double-sided or inconsistently drawn shell, oriented
	 * so that it encloses a positive volume (a solid, not a room).
	 */
	fromSides: Uint8Array;

}

/**
 * Finds the closed shells of a triangle soup and orients them. Corners are welded
 * (`weldCorners`); triangles sharing an edge belong to the same piece; a piece is closed when
 * every one of its edges is used an even number of times (twice on a manifold surface).
 *
 * Orientation, per closed piece:
 * - every triangle single-sided (`sides` ±1) and every edge used equally often in both directions
 *   once each triangle is turned to face its drawn side: that orientation (the drawn side is the
 *   outside — of a prop, or of the solid around a room drawn from inside);
 * - otherwise (double-sided triangles, or sides that contradict each other): the winding made
 *   consistent across the shell's edges and turned so that the shell encloses a positive volume,
 *   a solid. A shell that cannot be made consistent (non-manifold edges, a Klein bottle) is left
 *   open.
 *
 * Degenerate triangles (two welded corners equal) belong to no piece.
 * @param triangles 9 floats (a, b, c) per triangle.
 * @param sides Per triangle: 1 the front (counter-clockwise) side is drawn, −1 the back, 0 both.
 */
export function findClosedShells( triangles: ArrayLike<number>, sides: ArrayLike<number> ): ClosedShells {

	const count = Math.floor( triangles.length / 9 );
	const { ids, count: vertexCount } = weldCorners( triangles );

	// Edges: one entry per welded vertex pair, with its triangles' count and direction balance.
	const edgeOf = new Map<number, number>();
	const edgeCount: number[] = [], edgeBalance: number[] = [], edgeFirst: number[] = [], edgeSecond: number[] = [];
	const triangleEdges = new Int32Array( 3 * count ).fill( - 1 );
	const parent = new Int32Array( count );
	for ( let t = 0; t < count; t ++ ) parent[ t ] = t;
	const drawn = ( t: number ) => ( sides[ t ] < 0 ? - 1 : 1 );
	for ( let t = 0; t < count; t ++ ) {

		const a = ids[ 3 * t ], b = ids[ 3 * t + 1 ], c = ids[ 3 * t + 2 ];
		if ( a === b || b === c || c === a ) continue;
		const corners = [ a, b, c ];
		for ( let k = 0; k < 3; k ++ ) {

			const from = corners[ k ], to = corners[ ( k + 1 ) % 3 ];
			const low = Math.min( from, to ), high = Math.max( from, to ), key = low * vertexCount + high;
			let e = edgeOf.get( key );
			if ( e === undefined ) {

				e = edgeCount.length;
				edgeOf.set( key, e );
				edgeCount.push( 0 ); edgeBalance.push( 0 ); edgeFirst.push( t ); edgeSecond.push( - 1 );

			} else {

				union( parent, edgeFirst[ e ], t );
				if ( edgeSecond[ e ] < 0 ) edgeSecond[ e ] = t;

			}

			edgeCount[ e ] ++;
			edgeBalance[ e ] += ( from === low ? 1 : - 1 ) * drawn( t );
			triangleEdges[ 3 * t + k ] = e;

		}

	}

	// Per piece (its union-find root): closed, oriented by its sides, manifold.
	const closed = new Uint8Array( count ).fill( 1 ), bySides = new Uint8Array( count ).fill( 1 );
	const manifold = new Uint8Array( count ).fill( 1 );
	for ( let e = 0; e < edgeCount.length; e ++ ) {

		const root = find( parent, edgeFirst[ e ] );
		if ( edgeCount[ e ] % 2 === 1 ) closed[ root ] = 0;
		if ( edgeBalance[ e ] !== 0 ) bySides[ root ] = 0;
		if ( edgeCount[ e ] !== 2 ) manifold[ root ] = 0;

	}

	for ( let t = 0; t < count; t ++ ) if ( sides[ t ] === 0 ) bySides[ find( parent, t ) ] = 0;

	const orientation = new Int8Array( count ), shell = new Int32Array( count ).fill( - 1 ), fromSidesList: number[] = [];
	const members = new Map<number, number[]>();
	for ( let t = 0; t < count; t ++ ) {

		if ( triangleEdges[ 3 * t ] < 0 ) continue;
		const root = find( parent, t );
		if ( closed[ root ] === 0 ) continue;
		let list = members.get( root );
		if ( list === undefined ) members.set( root, list = [] );
		list.push( t );

	}

	for ( const [ root, list ] of members ) {

		let oriented: boolean;
		if ( bySides[ root ] === 1 ) {

			for ( const t of list ) orientation[ t ] = drawn( t );
			oriented = true;

		} else {

			oriented = manifold[ root ] === 1 && orientConsistently( list, ids, triangleEdges, edgeFirst, edgeSecond, orientation );
			if ( oriented && signedVolume( triangles, list, orientation ) < 0 ) {

				for ( const t of list ) orientation[ t ] = - orientation[ t ];

			}

		}

		if ( ! oriented ) {

			for ( const t of list ) orientation[ t ] = 0;
			continue;

		}

		const index = fromSidesList.length;
		fromSidesList.push( bySides[ root ] );
		for ( const t of list ) shell[ t ] = index;

	}

	return { orientation, shell, count: fromSidesList.length, fromSides: Uint8Array.from( fromSidesList ) };

}

/**
 * Gives every triangle of a closed manifold piece an orientation (±1) such that each edge is
 * crossed in opposite directions by its two triangles, by a breadth-first walk from the first.
 * @returns false when the piece is not orientable (the walk meets a contradiction).
 */
function orientConsistently(
	list: readonly number[], ids: Uint32Array, triangleEdges: Int32Array, edgeFirst: readonly number[], edgeSecond: readonly number[],
	orientation: Int8Array,
): boolean {

	orientation[ list[ 0 ] ] = 1;
	const queue = [ list[ 0 ] ];
	for ( let q = 0; q < queue.length; q ++ ) {

		const t = queue[ q ];
		for ( let k = 0; k < 3; k ++ ) {

			const e = triangleEdges[ 3 * t + k ];
			const other = edgeFirst[ e ] === t ? edgeSecond[ e ] : edgeFirst[ e ];
			// The neighbour must run along the shared edge the other way: same direction, opposite sign.
			const same = direction( ids, t, e, triangleEdges ) === direction( ids, other, e, triangleEdges );
			const want = same ? - orientation[ t ] : orientation[ t ];
			if ( orientation[ other ] === 0 ) {

				orientation[ other ] = want;
				queue.push( other );

			} else if ( orientation[ other ] !== want ) {

				return false;

			}

		}

	}

	return true;

}

/** +1 when triangle t runs along edge e from its lower vertex id to its higher one, −1 otherwise. */
function direction( ids: Uint32Array, t: number, e: number, triangleEdges: Int32Array ): number {

	const k = triangleEdges[ 3 * t ] === e ? 0 : triangleEdges[ 3 * t + 1 ] === e ? 1 : 2;
	return ids[ 3 * t + k ] < ids[ 3 * t + ( k + 1 ) % 3 ] ? 1 : - 1;

}

/** Six times the volume the oriented triangles enclose (divergence theorem), about the first corner to limit cancellation. */
function signedVolume( triangles: ArrayLike<number>, list: readonly number[], orientation: Int8Array ): number {

	const k0 = 9 * list[ 0 ], ox = triangles[ k0 ], oy = triangles[ k0 + 1 ], oz = triangles[ k0 + 2 ];
	let volume = 0;
	for ( const t of list ) {

		const k = 9 * t;
		const ax = triangles[ k ] - ox, ay = triangles[ k + 1 ] - oy, az = triangles[ k + 2 ] - oz;
		const bx = triangles[ k + 3 ] - ox, by = triangles[ k + 4 ] - oy, bz = triangles[ k + 5 ] - oz;
		const cx = triangles[ k + 6 ] - ox, cy = triangles[ k + 7 ] - oy, cz = triangles[ k + 8 ] - oz;
		volume += orientation[ t ] * ( ax * ( by * cz - bz * cy ) - ay * ( bx * cz - bz * cx ) + az * ( bx * cy - by * cx ) );

	}

	return volume;

}

function find( parent: Int32Array, t: number ): number {

	while ( parent[ t ] !== t ) {

		parent[ t ] = parent[ parent[ t ] ];
		t = parent[ t ];

	}

	return t;

}

function union( parent: Int32Array, a: number, b: number ): void {

	const ra = find( parent, a ), rb = find( parent, b );
	if ( ra !== rb ) parent[ Math.max( ra, rb ) ] = Math.min( ra, rb );

}
