/**
 * Reverse Cuthill–McKee numbering of the probes a fit solves for: breadth-first from a
 * pseudo-peripheral probe, neighbours by increasing degree, reversed. Probes that share a sample
 * end up with close numbers, so the normal matrix's envelope (and its Cholesky factor) stays a
 * narrow band — about the layout's cross-section instead of all probes.
 * @param adjacency Per probe, the probes it shares a sample with (itself excluded).
 * @returns `order[ newIndex ]` = old index.
 */
export function reverseCuthillMcKee( adjacency: readonly ( readonly number[] )[] ): Uint32Array {

	const count = adjacency.length;
	const order = new Uint32Array( count );
	const placed = new Uint8Array( count );
	const level = new Int32Array( count ).fill( - 1 );
	let filled = 0;
	for ( let seed = 0; seed < count; seed ++ ) {

		if ( placed[ seed ] ) continue;
		const start = peripheralProbe( adjacency, seed, level );
		const begin = filled;
		order[ filled ++ ] = start;
		placed[ start ] = 1;
		for ( let head = begin; head < filled; head ++ ) {

			const next = adjacency[ order[ head ] ].filter( ( n ) => ! placed[ n ] );
			next.sort( ( a, b ) => adjacency[ a ].length - adjacency[ b ].length || a - b );
			for ( const n of next ) {

				placed[ n ] = 1;
				order[ filled ++ ] = n;

			}

		}

		order.subarray( begin, filled ).reverse();

	}

	return order;

}

/**
 * A probe far from `seed` in its component (George & Liu's pseudo-peripheral search): repeat a
 * breadth-first search from the last level's lowest-degree probe while the depth grows.
 */
function peripheralProbe( adjacency: readonly ( readonly number[] )[], seed: number, level: Int32Array ): number {

	let start = seed, depth = - 1;
	for ( let round = 0; round < 8; round ++ ) {

		level[ start ] = 0;
		const queue = [ start ];
		for ( let head = 0; head < queue.length; head ++ ) {

			const p = queue[ head ];
			for ( const n of adjacency[ p ] ) {

				if ( level[ n ] >= 0 ) continue;
				level[ n ] = level[ p ] + 1;
				queue.push( n );

			}

		}

		const last = level[ queue[ queue.length - 1 ] ];
		let best = start, bestDegree = Infinity;
		for ( const p of queue ) {

			if ( level[ p ] === last && adjacency[ p ].length < bestDegree ) {

				best = p;
				bestDegree = adjacency[ p ].length;

			}

			level[ p ] = - 1;

		}

		if ( last <= depth ) break;
		depth = last;
		start = best;

	}

	return start;

}
