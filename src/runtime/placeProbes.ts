import type { Box3, Object3D, Scene, WebGLRenderer } from 'three';
import { assertRenderer, assertScene } from '../capture/captureSettings.js';
import { gatherWorldGeometry } from '../geometry/gatherWorldGeometry.js';
import { TriangleBVH } from '../geometry/TriangleBVH.js';
import { boundsOf } from '../geometry/boundsOf.js';
import { classifyPointsFor, INSIDE_GEOMETRY, NEAR_SURFACE, OPEN_SPACE, UNREACHABLE } from '../placement/classifyPoints.js';
import { gatherDrawnSides } from '../placement/gatherDrawnSides.js';
import { keepClass } from '../placement/keepClass.js';
import { placeFromMeshes } from '../placement/placeFromMeshes.js';
import { placeGrid } from '../placement/placeGrid.js';
import { readPointList, type PointList } from '../placement/readPointList.js';
import { reduceProbes, type ReduceProbesResult } from '../placement/reduceProbes.js';
import { thinToSpacing } from '../placement/thinToSpacing.js';
import { assertInteger, assertOptionalNumber, assertOptions, describeValue } from '../validate.js';
import { LightProbeVolume } from './LightProbeVolume.js';
import type { LightProbeVolumeCaptureOptions } from './LightProbeVolumeOptions.js';

/** Options of {@link placeProbes}. */
export interface PlaceProbesOptions {

	/** How many probes to place (an integer ≥ 4): the size of the returned layout. */
	count: number;

	/**
	 * Seeds of the level's open space, e.g. `[ spawn ]` — the player's spawn at eye height, not on
	 * the floor. Candidates that no seed reaches without crossing a surface are dropped: sealed
	 * rooms, the inside of walls and props, and everything outside the level's bounding box.
	 * Strongly recommended (without it, the space behind double-sided walls counts as open).
	 */
	reachableFrom?: PointList;

	/** The static level to place the probes in (default: `scene`). Leave characters and other moving objects out. */
	geometry?: Object3D;

	/** Place candidates only inside this box (default: the bounding box of `geometry`). */
	bounds?: Box3;

	/**
	 * Spacing of the candidate grid, in scene units (default: the box split into about
	 * `candidates` cubes). Mesh vertices moved half a spacing off their surfaces add candidates.
	 */
	spacing?: number;

	/** About how many grid candidates to capture when `spacing` is not given (default max( 256, 8 × count )). */
	candidates?: number;

	/** Cube-map size of the candidates' capture (default 16: enough for SH9, whose detail is 2 bands). */
	candidateResolution?: number;

	/** Other options of the candidates' capture (`LightProbeVolume.capture`), e.g. `{ nonNegative: true }`. */
	capture?: Omit<LightProbeVolumeCaptureOptions, 'resolution' | 'indices'>;

}

/** Result of {@link placeProbes}. */
export interface PlaceProbesResult {

	/** The chosen probe positions, x, y, z each: `new LightProbeVolume( { positions } )`. */
	positions: Float64Array;

	/** Every candidate that was captured (open space, reachable), x, y, z each. */
	candidates: Float64Array;

	/** Their captured SH, 27 floats each, at `candidateResolution`. */
	candidateSH: Float32Array;

	/** The reduction (`reduceProbes`): `keep` indexes `candidates`; `error` is the layout's irradiance error over them. */
	reduction: ReduceProbesResult;

	/** Candidates dropped before the capture, per reason. */
	rejected: { nearSurface: number; insideGeometry: number; unreachable: number };

}

/**
 * Automatic probe placement, the whole pipeline in one call: candidates on a grid over the level
 * and at its mesh vertices (moved off their surfaces), those in open space kept (`classifyPoints`:
 * not near a surface, not inside a solid, reachable from `reachableFrom`), all captured at low
 * resolution, then reduced to `count` probes whose tetrahedral interpolation best reproduces the
 * candidates' irradiance (`reduceProbes`). Capture the result at full resolution:
 *
 * ```js
 * const { positions } = await placeProbes( renderer, scene, { count: 32, reachableFrom: [ spawn ] } );
 * const volume = new LightProbeVolume( { positions } );
 * await volume.capture( renderer, scene, { resolution: 64 } );
 * ```
 *
 * The recipe it runs, its defaults and when to call the steps yourself are in docs/placement.md.
 * @param renderer The renderer of the candidates' capture.
 * @param scene What the candidates capture (lights, sky and level, without moving objects).
 */
export async function placeProbes( renderer: WebGLRenderer, scene: Scene, options: PlaceProbesOptions ): Promise<PlaceProbesResult> {

	const where = 'placeProbes';
	assertRenderer( where, renderer );
	assertScene( where, scene );
	if ( options === null || typeof options !== 'object' ) throw new TypeError( `${where}: options must be { count, reachableFrom?, … }, got ${describeValue( options )}.` );
	assertInteger( where, 'options.count', options.count, 4, Number.MAX_SAFE_INTEGER );
	const root = options.geometry ?? scene;
	if ( ( root as Object3D | null )?.isObject3D !== true ) throw new TypeError( `${where}: options.geometry must be a three.js Object3D.` );
	if ( options.bounds !== undefined && options.bounds?.isBox3 !== true ) throw new TypeError( `${where}: options.bounds must be a three.js Box3.` );
	assertOptionalNumber( where, 'options.spacing', options.spacing, Number.MIN_VALUE );
	if ( options.candidates !== undefined ) assertInteger( where, 'options.candidates', options.candidates, 8, 1e6 );
	const resolution = options.candidateResolution ?? 16;
	assertInteger( where, 'options.candidateResolution', resolution, 1, 4096 );
	assertOptions( where, 'options.capture', options.capture );
	const seeds = options.reachableFrom === undefined ? undefined : readPointList( where, 'options.reachableFrom', options.reachableFrom );

	const world = gatherWorldGeometry( root );
	if ( world.triangles.length === 0 ) throw new RangeError( `${where}: ${options.geometry ? 'options.geometry' : 'scene'} has no triangles to place probes in.` );
	const box = candidateBox( where, world.triangles, options.bounds );
	const spacing = options.spacing ?? defaultSpacing( box, options.candidates ?? Math.max( 256, 8 * options.count ) );

	// Mesh vertices first (the paper's candidates, where the light changes), then the grid; thinned
	// together so that no two candidates are closer than half a spacing.
	const moved = placeFromMeshes( root, { offset: spacing / 2, minSpacing: spacing / 2, rejectInside: false, minDistance: 0 } );
	const vertices = inBox( moved, box );
	const grid = cellCentres( box, spacing );
	const all = new Float64Array( vertices.length + grid.length );
	all.set( vertices );
	all.set( grid, vertices.length );
	const union = thinToSpacing( all, all.length / 3, spacing / 2 );

	const classes = classifyPointsFor( where, union, new TriangleBVH( world.triangles ), {
		minDistance: spacing / 4, sides: gatherDrawnSides( root ).triangleSides, reachableFrom: seeds,
	} );
	const candidates = keepClass( union, classes, OPEN_SPACE );
	const rejected = {
		nearSurface: classes.filter( ( c ) => c === NEAR_SURFACE ).length,
		insideGeometry: classes.filter( ( c ) => c === INSIDE_GEOMETRY ).length,
		unreachable: classes.filter( ( c ) => c === UNREACHABLE ).length,
	};
	const found = candidates.length / 3;
	if ( found < options.count ) {

		throw new RangeError( `${where}: only ${found} of ${union.length / 3} candidates are in open space (${rejected.nearSurface} near a surface, `
			+ `${rejected.insideGeometry} inside geometry, ${rejected.unreachable} unreachable), fewer than options.count (${options.count}); `
			+ 'pass a smaller options.spacing, a smaller count, or check options.bounds and options.reachableFrom.' );

	}

	const dense = new LightProbeVolume( { positions: candidates } );
	try {

		await dense.capture( renderer, scene, { ...options.capture, resolution } );

	} catch ( error ) {

		throw renamed( error, where );

	} finally {

		dense.dispose();

	}

	const candidateSH = dense.sh.slice();
	const reduction = reduceProbes( candidates, candidateSH, { targetCount: options.count, strategy: 'mean' } );
	return { positions: reduction.positions, candidates, candidateSH, reduction, rejected };

}

/** The triangles' bounding box, cut to `bounds`: [ minX, minY, minZ, maxX, maxY, maxZ ], every side > 0. */
function candidateBox( where: string, triangles: Float64Array, bounds: Box3 | undefined ): number[] {

	const b = Array.from( boundsOf( triangles, triangles.length / 3 ) );
	if ( bounds !== undefined ) {

		b[ 0 ] = Math.max( b[ 0 ], bounds.min.x ); b[ 1 ] = Math.max( b[ 1 ], bounds.min.y ); b[ 2 ] = Math.max( b[ 2 ], bounds.min.z );
		b[ 3 ] = Math.min( b[ 3 ], bounds.max.x ); b[ 4 ] = Math.min( b[ 4 ], bounds.max.y ); b[ 5 ] = Math.min( b[ 5 ], bounds.max.z );

	}

	if ( ! ( b[ 3 ] > b[ 0 ] && b[ 4 ] > b[ 1 ] && b[ 5 ] > b[ 2 ] ) ) {

		throw new RangeError( `${where}: the box to place probes in is empty or flat (${b.map( ( v ) => v.toPrecision( 4 ) ).join( ', ' )}); `
			+ 'probes need a volume: check options.bounds.' );

	}

	return b;

}

/** The points inside the box (outside the level's bounds a vertex moved off a double-sided wall is no use). */
function inBox( points: Float64Array, box: number[] ): Float64Array {

	const out: number[] = [];
	for ( let i = 0; i < points.length; i += 3 ) {

		const x = points[ i ], y = points[ i + 1 ], z = points[ i + 2 ];
		if ( x >= box[ 0 ] && x <= box[ 3 ] && y >= box[ 1 ] && y <= box[ 4 ] && z >= box[ 2 ] && z <= box[ 5 ] ) out.push( x, y, z );

	}

	return Float64Array.from( out );

}

/** The side of `count` cubes filling the box. */
function defaultSpacing( box: number[], count: number ): number {

	return Math.cbrt( ( box[ 3 ] - box[ 0 ] ) * ( box[ 4 ] - box[ 1 ] ) * ( box[ 5 ] - box[ 2 ] ) / count );

}

/** The centres of a grid of cells about `spacing` wide filling the box (at least 2 per axis): half a cell from each face. */
function cellCentres( box: number[], spacing: number ): Float64Array {

	const counts = [ 0, 1, 2 ].map( ( a ) => Math.max( 2, Math.round( ( box[ 3 + a ] - box[ a ] ) / spacing ) ) );
	const half = [ 0, 1, 2 ].map( ( a ) => ( box[ 3 + a ] - box[ a ] ) / ( 2 * counts[ a ] ) );
	return placeGrid( [ 0, 1, 2 ].map( ( a ) => box[ a ] + half[ a ] ), [ 0, 1, 2 ].map( ( a ) => box[ 3 + a ] - half[ a ] ), counts );

}

/** A capture error re-addressed to the option the caller gave: `LightProbeVolume.capture: options.x` → `placeProbes: options.capture.x`. */
function renamed( error: unknown, where: string ): unknown {

	if ( ! ( error instanceof Error ) || ! error.message.startsWith( 'LightProbeVolume.capture: ' ) ) return error;
	const message = error.message.replace( /^LightProbeVolume\.capture: (options\.)?/, ( _, option ) => `${where}: ${option ? 'options.capture.' : ''}` );
	const Type = error instanceof TypeError ? TypeError : error instanceof RangeError ? RangeError : Error;
	return new Type( message, { cause: error } );

}
