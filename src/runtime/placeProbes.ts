import type { Box3, Object3D, Scene, WebGLRenderer } from 'three';
import { assertRenderer, assertScene, checkCaptureCall } from '../capture/captureSettings.js';
import { readPointList, type PointList } from '../placement/readPointList.js';
import type { FitSamples } from '../fitting/fitProbeSH.js';
import { readReduceOptions } from '../placement/reduceOptions.js';
import { reduceProbes, type ReduceProbesOptions, type ReduceProbesResult } from '../placement/reduceProbes.js';
import type { RegionOfInterest } from '../placement/regionOfInterest.js';
import { SH_FLOATS, assertInteger, assertNumber, assertOptionalNumber, assertOptions, describeValue } from '../validate.js';
import { LightProbeVolume } from './LightProbeVolume.js';
import type { LightProbeVolumeCaptureOptions } from './LightProbeVolumeOptions.js';
import { describeCandidates, placeCandidates } from './probeCandidates.js';
import { gatherStaticGeometry } from './staticGeometry.js';

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

	/**
	 * The static level to place the probes in (default: `scene`). Leave characters and other moving
	 * objects out (the objects of `capture.exclude` are left out of it).
	 */
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

	/**
	 * The least distance from a probe to any surface, in scene units (≥ 0; default a quarter of the
	 * spacing): candidates nearer a wall are dropped, as a probe there would capture mostly the
	 * wall in front of it.
	 */
	clearance?: number;

	/** Cube-map size of the candidates' capture (default 16: enough for SH9, whose detail is 2 bands). */
	candidateResolution?: number;

	/** Other options of the candidates' capture (`LightProbeVolume.capture`), e.g. `{ nonNegative: true }`. */
	capture?: Omit<LightProbeVolumeCaptureOptions, 'resolution' | 'indices'>;

	/**
	 * Re-fit the probes' SH to the candidates at every step of the reduction (`reduceProbes`' `fit`): `true`, or
	 * `{ gradients, lambda, gradientLambda, nonNegative }`. The result's `reduction.sh` (and `gradients`) are then fitted.
	 */
	fit?: ReduceProbesOptions[ 'fit' ];

	/** Swap passes after the insertions (`reduceProbes`' `swaps`; only with `fit`, default 2 passes with it). */
	swaps?: boolean | number;

	/** Where the light matters most (`reduceProbes`' `region`, e.g. where characters go): weights the choice and the error. */
	region?: RegionOfInterest;

	/**
	 * How much each candidate's error counts (`reduceProbes`' `weights`, ≥ 0): a function of the candidate's position
	 * (the candidates are found inside this call), or one weight per candidate (as many as this call finds).
	 */
	weights?: ArrayLike<number> | ( ( x: number, y: number, z: number ) => number );

	/** Extra captured points the reduction's error (and fit) also uses (`reduceProbes`' `fitSamples`). */
	fitSamples?: FitSamples;

}

/** Result of {@link placeProbes}. */
export interface PlaceProbesResult {

	/** The chosen probe positions, x, y, z each: `new LightProbeVolume( { positions } )`. */
	positions: Float64Array;

	/** Every candidate that was captured (open space, reachable), x, y, z each. */
	candidates: Float64Array;

	/** Their captured SH, 27 floats each, at `candidateResolution`. */
	candidateSH: Float32Array;

	/**
	 * The reduction (`reduceProbes`): `keep` indexes `candidates`; `error` is the layout's irradiance error over them.
	 * With `fit`, its `sh` and `gradients` are fitted to the candidates' capture at `candidateResolution`: a volume made
	 * from `positions` and captured again (at another resolution) must be fitted again — capture option `fit`.
	 */
	reduction: ReduceProbesResult;

	/** Candidates dropped before the capture, per reason. */
	rejected: { nearSurface: number; insideGeometry: number; unreachable: number };

}

/**
 * Automatic probe placement, the whole pipeline in one call: candidates on a grid over the level
 * and at its mesh vertices (moved off their surfaces), those in open space kept (`classifyPoints`:
 * at least `clearance` from every surface, not inside a solid, reachable from `reachableFrom`), all captured at low
 * resolution, then reduced to `count` probes whose tetrahedral interpolation best reproduces the
 * candidates' irradiance (`reduceProbes`; with `fit`, `swaps`, `region`, `weights` and `fitSamples` passed to it).
 * Capture the result at full resolution (with `fit`, fitting again: the fitted SH are the candidates' resolution's):
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
	assertClearance( where, options.clearance );
	const resolution = options.candidateResolution ?? 16;
	assertInteger( where, 'options.candidateResolution', resolution, 1, 4096 );
	assertOptions( where, 'options.capture', options.capture );
	const seeds = options.reachableFrom === undefined ? undefined : readPointList( where, 'options.reachableFrom', options.reachableFrom );

	// The capture's `exclude` (an iterable, maybe one-shot) read once: left out of the geometry and hidden in the capture.
	const { exclude } = checkCaptureCall( where, 'options.capture.', { exclude: options.capture?.exclude } );
	const geometry = gatherStaticGeometry( root, exclude );
	if ( geometry.triangles.length === 0 ) throw new RangeError( `${where}: ${options.geometry ? 'options.geometry' : 'scene'} has no triangles to place probes in.` );
	const placed = placeCandidates( where, geometry, {
		reachableFrom: seeds, bounds: options.bounds, spacing: options.spacing, clearance: options.clearance,
		candidates: options.candidates ?? Math.max( 256, 8 * options.count ),
	} );
	const { positions: candidates, rejected } = placed;
	if ( candidates.length / 3 < options.count ) {

		throw new RangeError( `${where}: ${describeCandidates( placed )}, fewer than options.count (${options.count}); `
			+ 'pass a smaller options.spacing or options.clearance, a smaller count, or check options.bounds and options.reachableFrom.' );

	}

	const reduceOptions = reductionOptions( where, candidates, options );

	const dense = new LightProbeVolume( { positions: candidates } );
	try {

		await dense.capture( renderer, scene, { ...options.capture, exclude, resolution } );

	} catch ( error ) {

		throw renamed( error, where );

	} finally {

		dense.dispose();

	}

	const candidateSH = dense.sh.slice();
	const reduction = reduceProbes( candidates, candidateSH, reduceOptions );
	return { positions: reduction.positions, candidates, candidateSH, reduction, rejected };

}

/**
 * The options of the reduction, checked before the capture (errors name `placeProbes` and the option): `count`
 * probes by the 'mean' strategy, with the fit, swaps, region, weights (a function evaluated at each candidate) and
 * fit samples given.
 */
function reductionOptions( where: string, candidates: Float64Array, options: PlaceProbesOptions ): ReduceProbesOptions {

	const { fit, swaps, region, fitSamples } = options;
	const count = candidates.length / 3;
	let weights = options.weights;
	if ( typeof weights === 'function' ) {

		const weigh = weights;
		weights = Float64Array.from( { length: count }, ( _, i ) => {

			const [ x, y, z ] = candidates.subarray( 3 * i, 3 * i + 3 );
			const weight = weigh( x, y, z );
			if ( typeof weight !== 'number' || ! ( weight >= 0 && weight < Infinity ) ) {

				throw new RangeError( `${where}: options.weights returned ${describeValue( weight )} at candidate ${i} (${x}, ${y}, ${z}); `
					+ 'weights must be finite numbers ≥ 0.' );

			}

			return weight;

		} );

	}

	const reduce: ReduceProbesOptions = { targetCount: options.count, strategy: 'mean', fit, swaps, region, weights, fitSamples };
	// The SH are not captured yet: zeros stand in, as the checks read only their length.
	readReduceOptions( where, candidates, new Float32Array( SH_FLOATS * count ), count, reduce );
	return reduce;

}

/** `options.clearance`: undefined, or a finite number ≥ 0. */
export function assertClearance( where: string, clearance: unknown ): void {

	if ( clearance === undefined ) return;
	assertNumber( where, 'options.clearance', clearance );
	if ( clearance < 0 ) throw new RangeError( `${where}: options.clearance must be ≥ 0, got ${clearance}.` );

}

/** A capture error re-addressed to the option the caller gave: `LightProbeVolume.capture: options.x` → `placeProbes: options.capture.x`. */
function renamed( error: unknown, where: string ): unknown {

	if ( ! ( error instanceof Error ) || ! error.message.startsWith( 'LightProbeVolume.capture: ' ) ) return error;
	const message = error.message.replace( /^LightProbeVolume\.capture: (options\.)?/, ( _, option ) => `${where}: ${option ? 'options.capture.' : ''}` );
	const Type = error instanceof TypeError ? TypeError : error instanceof RangeError ? RangeError : Error;
	return new Type( message, { cause: error } );

}
