import type { Box3, Object3D } from 'three';
import { assertNumber } from '../validate.js';
import { candidatesFromVertices } from './candidatesFromVertices.js';
import { classifyPoints, INSIDE_GEOMETRY, NEAR_SURFACE } from './classifyPoints.js';
import { gatherWorldGeometry } from '../geometry/gatherWorldGeometry.js';
import { TriangleBVH } from '../geometry/TriangleBVH.js';

/** Options of {@link placeFromMeshes}. */
export interface PlaceFromMeshesOptions {

	/** How far each vertex is moved along its normal (scene units); see `candidatesFromVertices`. */
	offset: number;

	/** No two candidates closer than this (scene units). */
	minSpacing: number;

	/**
	 * Drop candidates inside closed geometry, by a majority vote of ray parity (default true). Turn
	 * off for scenes made of open surfaces, where parity means nothing.
	 */
	rejectInside?: boolean;

	/**
	 * Drop candidates with any triangle closer than this (default `|offset| / 2`; 0 turns it off).
	 * A vertex moved along its own normal can land on or next to another surface — at a concave
	 * corner, beside a thin wall, on the neighbouring face where normals are split (a box's corner
	 * vertex moved along one face's normal lies in the planes of the other two faces). A probe
	 * there captures mostly that surface, and ray parity is undefined on a surface. Half the offset
	 * keeps every candidate whose own move went as planned (it is `offset` from its own surface)
	 * and rejects only those that another surface came within half that distance of.
	 */
	minDistance?: number;

	/** Keep only candidates inside this box (e.g. the playable area, not the roof or outside walls). */
	bounds?: Box3;

}

/**
 * Probe candidates from a scene's meshes (paper 2.1, "automatic generation from the background
 * mesh's vertices"): the world-space vertices of every mesh under `root`, moved `offset` along
 * their normals, thinned to `minSpacing`, restricted to `bounds`, then stripped of those near a
 * surface or inside geometry. The result is a dense candidate set: capture it and pass it to
 * `reduceProbes`, or edit it by hand.
 *
 * The geometry tests run on the pure `TriangleBVH` over all triangles under `root` (not three's
 * Raycaster), so 100k triangles and a few thousand candidates take well under a few seconds.
 * @param root The background: a loaded glTF scene, a Group of meshes, a Mesh.
 * @returns Flat x, y, z per candidate, world space, in vertex order.
 */
export function placeFromMeshes( root: Object3D, options: PlaceFromMeshesOptions ): Float64Array {

	const where = 'placeFromMeshes';
	if ( root === null || typeof root !== 'object' || ( root as Object3D ).isObject3D !== true ) {

		throw new TypeError( `${where}: root must be a three.js Object3D.` );

	}

	if ( options === null || typeof options !== 'object' ) throw new TypeError( `${where}: options must be { offset, minSpacing, … }.` );
	const { offset, minSpacing, rejectInside = true, bounds } = options;
	assertNumber( where, 'options.offset', offset );
	assertNumber( where, 'options.minSpacing', minSpacing );
	if ( minSpacing < 0 ) throw new RangeError( `${where}: options.minSpacing must be ≥ 0, got ${minSpacing}.` );
	const minDistance = options.minDistance ?? Math.abs( offset ) / 2;
	assertNumber( where, 'options.minDistance', minDistance );
	if ( minDistance < 0 ) throw new RangeError( `${where}: options.minDistance must be ≥ 0, got ${minDistance}.` );
	if ( bounds !== undefined && ( bounds === null || ( bounds as Box3 ).isBox3 !== true ) ) throw new TypeError( `${where}: options.bounds must be a three.js Box3.` );

	const geometry = gatherWorldGeometry( root );
	let candidates = candidatesFromVertices( geometry.vertexPositions, geometry.vertexNormals, { offset, minSpacing } );
	if ( bounds ) candidates = filterInBox( candidates, bounds );
	if ( ! rejectInside && minDistance === 0 ) return candidates;

	const bvh = new TriangleBVH( geometry.triangles );
	const classes = classifyPoints( candidates, bvh, { minDistance, parity: rejectInside } );

	let kept = 0;
	const out = new Float64Array( candidates.length );
	for ( let i = 0; i < classes.length; i ++ ) {

		const c = classes[ i ];
		if ( c === NEAR_SURFACE || c === INSIDE_GEOMETRY ) continue;
		out[ 3 * kept ] = candidates[ 3 * i ]; out[ 3 * kept + 1 ] = candidates[ 3 * i + 1 ]; out[ 3 * kept + 2 ] = candidates[ 3 * i + 2 ];
		kept ++;

	}

	return out.slice( 0, 3 * kept );

}

function filterInBox( points: Float64Array, box: Box3 ): Float64Array {

	const out = new Float64Array( points.length );
	let kept = 0;
	for ( let i = 0; i < points.length; i += 3 ) {

		const x = points[ i ], y = points[ i + 1 ], z = points[ i + 2 ];
		if ( x < box.min.x || x > box.max.x || y < box.min.y || y > box.max.y || z < box.min.z || z > box.max.z ) continue;
		out[ 3 * kept ] = x; out[ 3 * kept + 1 ] = y; out[ 3 * kept + 2 ] = z;
		kept ++;

	}

	return out.slice( 0, 3 * kept );

}
