import { boundsOf } from '../geometry/boundsOf.js';
import { orientAnyScale } from '../tetrahedra/predicates.js';

/**
 * The bounding box of the vertices of hull triangles `faces` (each vertex taken once per corner,
 * in face order) as boundsOf writes it, `[ minX, minY, minZ, maxX, maxY, maxZ ]`: the probes' box when `faces` is the hull
 * (extremes are hull vertices), ignoring positions in no face (probes removed from an incremental
 * mesh). Empty bounds (min = +∞, max = −∞) for no faces.
 */
export function hullBounds( p: Float64Array, faces: Uint32Array, target = new Float64Array( 6 ) ): Float64Array {

	const corners = new Float64Array( 3 * faces.length );
	for ( let j = 0; j < faces.length; j ++ ) {

		const i = 3 * faces[ j ];
		corners[ 3 * j ] = p[ i ]; corners[ 3 * j + 1 ] = p[ i + 1 ]; corners[ 3 * j + 2 ] = p[ i + 2 ];

	}

	boundsOf( corners, faces.length, target );
	return target;

}

/**
 * Edge adjacency of hull triangles `faces` (counter-clockwise from outside): `adjacency[3f + k]` is
 * the triangle across the edge of f opposite its vertex k. Checks that the triangles form one closed
 * convex surface, which the outer cells' walk relies on (the checks: docs/outer-cells.md).
 * @param where Function name for error messages.
 * @throws Error when an edge is not shared by exactly two faces, the faces form several surfaces, or
 *   an edge is reflex.
 */
export function hullAdjacency( p: Float64Array, faces: Uint32Array, where: string ): Int32Array {

	const faceCount = faces.length / 3;
	// Edge adjacency: the directed edge (u → v) of one face is (v → u) in its neighbour.
	const probeCount = p.length / 3;
	const edges = new Map<number, number>();
	for ( let f = 0; f < faceCount; f ++ ) {

		for ( let k = 0; k < 3; k ++ ) {

			const u = faces[ 3 * f + ( k + 1 ) % 3 ], v = faces[ 3 * f + ( k + 2 ) % 3 ];
			const key = u * probeCount + v;
			if ( edges.has( key ) ) {

				throw new Error( `${where}: hull edge (${u}, ${v}) belongs to more than one hull face in the same direction; the hull is not a closed surface (bad tetrahedra or neighbours).` );

			}

			edges.set( key, 3 * f + k );

		}

	}

	const adjacency = new Int32Array( 3 * faceCount );
	for ( let f = 0; f < faceCount; f ++ ) {

		for ( let k = 0; k < 3; k ++ ) {

			const u = faces[ 3 * f + ( k + 1 ) % 3 ], v = faces[ 3 * f + ( k + 2 ) % 3 ];
			const other = edges.get( v * probeCount + u );
			if ( other === undefined ) {

				throw new Error( `${where}: hull edge (${u}, ${v}) has a hull face on one side only; the hull is not a closed surface (bad tetrahedra or neighbours).` );

			}

			adjacency[ 3 * f + k ] = ( other / 3 ) | 0;

		}

	}

	// Convex at every edge (exact): the neighbour's far vertex is not above this face's plane.
	// With one connected closed surface (below) that makes the hull convex, which the walks
	// (leaving through a hull face means outside) rely on.
	for ( let f = 0; f < faceCount; f ++ ) {

		const a = faces[ 3 * f ], b = faces[ 3 * f + 1 ], c = faces[ 3 * f + 2 ];
		for ( let k = 0; k < 3; k ++ ) {

			const g = adjacency[ 3 * f + k ], key = 3 * g;
			const u = faces[ 3 * f + ( k + 1 ) % 3 ], v = faces[ 3 * f + ( k + 2 ) % 3 ];
			let far = faces[ key ];
			if ( far === u || far === v ) far = faces[ key + 1 ];
			if ( far === u || far === v ) far = faces[ key + 2 ];
			if ( orientAnyScale( p, a, b, c, far ) > 0 ) {

				throw new Error( `${where}: the hull is not convex at edge (${u}, ${v}): the tetrahedra do not fill the probes' convex hull.` );

			}


		}

	}

	// One connected surface: a face pair wrongly marked as hull inside the volume closes up on
	// itself and would pass the edge test above. Depth-first over the adjacency, O(faces).
	if ( faceCount > 0 ) {

		const seen = new Uint8Array( faceCount ), stack = new Int32Array( faceCount );
		let top = 0, reached = 1;
		stack[ top ++ ] = 0; seen[ 0 ] = 1;
		while ( top > 0 ) {

			const f = stack[ -- top ];
			for ( let k = 0; k < 3; k ++ ) {

				const g = adjacency[ 3 * f + k ];
				if ( seen[ g ] === 0 ) { seen[ g ] = 1; reached ++; stack[ top ++ ] = g; }

			}

		}

		if ( reached !== faceCount ) {

			throw new Error( `${where}: the hull faces form more than one closed surface (${reached} of ${faceCount} faces reachable from the first); some faces marked as hull (neighbour −1) are inside the volume.` );

		}

	}

	return adjacency;

}
