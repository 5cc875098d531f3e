import type { Box3, Object3D } from 'three';
import { assertNumber, assertOptionalNumber } from '../validate.js';
import { candidatesFromVertices } from './candidatesFromVertices.js';
import { classifyPointsFor, OPEN_SPACE } from './classifyPoints.js';
import { keepClass } from './keepClass.js';
import { DRAWN_AGAINST_NORMAL, DRAWN_ALONG_NORMAL, gatherDrawnSides } from './gatherDrawnSides.js';
import { readPointList, type PointList } from './readPointList.js';
import { gatherWorldGeometry } from '../geometry/gatherWorldGeometry.js';
import { TriangleBVH } from '../geometry/TriangleBVH.js';

/** Options of {@link placeFromMeshes}. */
export interface PlaceFromMeshesOptions {

	/** How far each vertex is moved along its normal (scene units); see `candidatesFromVertices`. */
	offset: number;

	/** No two candidates closer than this (scene units). */
	minSpacing: number;

	/**
	 * Drop candidates inside solids (default true): inside closed props and walls, and behind the
	 * undrawn side of open single-sided surfaces — `classifyPoints`' inside test, with each
	 * triangle's drawn side read from its material. Rooms of open quads and rooms drawn from inside
	 * (`BackSide`) are open space.
	 */
	rejectInside?: boolean;

	/**
	 * Seeds of open space, e.g. `[ spawn ]` (the player's spawn, above the floor): candidates that
	 * no seed reaches without crossing a surface are dropped — those in sealed rooms and cavities,
	 * and outside the scene's bounding box. Recommended: it is the one test that knows which side
	 * of a double-sided wall is the level. See docs/placement.md.
	 */
	reachableFrom?: PointList;

	/** Lattice spacing of the `reachableFrom` flood fill (default: the scene's longest side / 64). */
	reachCellSize?: number;

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
 * mesh's vertices"): the world-space vertices of every mesh under `root`, moved `offset` towards
 * the side their material draws (along the normal for `FrontSide`, against it for `BackSide`,
 * both ways for `DoubleSide`), thinned to `minSpacing`, restricted to `bounds`, then stripped of
 * those near a surface, inside geometry or (with `reachableFrom`) out of the player's reach. The
 * result is a dense candidate set: capture it and pass it to `reduceProbes` (docs/placement.md
 * has the recipe; `placeProbes` runs it), or edit it by hand.
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
	const { offset, minSpacing, rejectInside = true, bounds, reachCellSize } = options;
	assertNumber( where, 'options.offset', offset );
	assertNumber( where, 'options.minSpacing', minSpacing );
	if ( minSpacing < 0 ) throw new RangeError( `${where}: options.minSpacing must be ≥ 0, got ${minSpacing}.` );
	const minDistance = options.minDistance ?? Math.abs( offset ) / 2;
	assertNumber( where, 'options.minDistance', minDistance );
	if ( minDistance < 0 ) throw new RangeError( `${where}: options.minDistance must be ≥ 0, got ${minDistance}.` );
	if ( bounds !== undefined && ( bounds === null || ( bounds as Box3 ).isBox3 !== true ) ) throw new TypeError( `${where}: options.bounds must be a three.js Box3.` );
	assertOptionalNumber( where, 'options.reachCellSize', reachCellSize, Number.MIN_VALUE );
	const seeds = options.reachableFrom === undefined ? undefined : readPointList( where, 'options.reachableFrom', options.reachableFrom );

	const geometry = gatherWorldGeometry( root );
	const { triangleSides, vertexSides } = gatherDrawnSides( root );
	const { positions, normals } = drawnSideVertices( geometry.vertexPositions, geometry.vertexNormals, vertexSides );
	let candidates = candidatesFromVertices( positions, normals, { offset, minSpacing } );
	if ( bounds ) candidates = filterInBox( candidates, bounds );
	if ( ! rejectInside && minDistance === 0 && seeds === undefined ) return candidates;

	const bvh = new TriangleBVH( geometry.triangles );
	const classes = classifyPointsFor( where, candidates, bvh, {
		minDistance, inside: rejectInside, sides: triangleSides, reachableFrom: seeds, reachCellSize,
	} );
	return keepClass( candidates, classes, OPEN_SPACE );

}

/**
 * Each vertex once per side its material draws: with its normal (`FrontSide`), with the normal
 * negated (`BackSide`: a room drawn from inside has normals pointing out of it), or both.
 */
function drawnSideVertices(
	positions: Float64Array, normals: Float64Array, sides: Uint8Array
): { positions: Float64Array; normals: Float64Array } {

	let count = 0;
	for ( let v = 0; v < sides.length; v ++ ) {

		count += ( sides[ v ] & DRAWN_ALONG_NORMAL ? 1 : 0 ) + ( sides[ v ] & DRAWN_AGAINST_NORMAL ? 1 : 0 );

	}

	const outPositions = new Float64Array( 3 * count ), outNormals = new Float64Array( 3 * count );
	let o = 0;
	for ( let v = 0; v < sides.length; v ++ ) {

		for ( const [ flag, sign ] of SIDE_SIGNS ) {

			if ( ( sides[ v ] & flag ) === 0 ) continue;
			for ( let a = 0; a < 3; a ++ ) {

				outPositions[ 3 * o + a ] = positions[ 3 * v + a ];
				outNormals[ 3 * o + a ] = sign * normals[ 3 * v + a ];

			}

			o ++;

		}

	}

	return { positions: outPositions, normals: outNormals };

}

const SIDE_SIGNS = [ [ DRAWN_ALONG_NORMAL, 1 ], [ DRAWN_AGAINST_NORMAL, - 1 ] ] as const;

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
