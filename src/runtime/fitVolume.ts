import type { Object3D, Scene } from 'three';
import { readPointList, type PointList } from '../placement/readPointList.js';
import { weightsInRegion, type RegionOfInterest } from '../placement/regionOfInterest.js';
import { SH_FLOATS, assertNumber, assertOptionalBoolean, assertOptions, assertPoints, describeValue } from '../validate.js';
import type { CaptureAccess, CapturedProbes } from './captureProbes.js';
import { fitSamplePoints } from './fitSamplePoints.js';
import type { LightProbeVolume } from './LightProbeVolume.js';
import { gatherStaticGeometry } from './staticGeometry.js';
import { VolumeFit, type VolumeFitSettings } from './VolumeFit.js';

/**
 * The `fit` option of `LightProbeVolume.capture`: after the probes, capture extra points and fit
 * the probes' SH (and optionally gradients) so the blended field matches them (`fitProbeSH`).
 * Give `samples` or `spacing`.
 */
export interface LightProbeVolumeFitOptions {

	/** Where to capture the fit points, x, y, z each (e.g. where characters walk). */
	samples?: ArrayLike<number>;

	/**
	 * Or: a grid of fit points about this far apart (scene units) over the probes' hull, only those in
	 * open space (a quarter spacing or more from every surface, not inside a solid, reachable from
	 * the probes), the volume's hidden objects left out of the level as in the capture.
	 */
	spacing?: number;

	/** Fit a spatial gradient per probe too (`volume.gradients`, 81 floats each). Default false. */
	gradients?: boolean;

	/** Pull toward each probe's captured SH (scale-free, see `fitProbeSH`), or 'auto' (default): cross-validation. */
	lambda?: number | 'auto';

	/** Pull toward zero gradient (scale-free), or 'auto' (default); with `gradients` only. */
	gradientLambda?: number | 'auto';

	/** Keep the fitted irradiance ≥ 0 in every direction. Default: the capture's own `nonNegative`. */
	nonNegative?: boolean;

	/** Weight the fit points: 1 inside the region, its `outsideWeight` outside (see `RegionOfInterest`). */
	region?: RegionOfInterest;

	/** With `spacing`: seeds of the open space the fit points must be reachable from. Default: the probes in open space. */
	reachableFrom?: PointList;

}

/** What a capture does about fitting, decided (and checked) before anything is captured. */
export interface FitPlan {

	/**
	 * `'none'`: a plain capture; `'fit'`: capture `points` too and fit; `'refit'`: refit to the stored
	 * samples (a partial capture of a fitted volume, e.g. `recaptureDirty`); `'drop'`: a full capture
	 * without `fit` of a fitted volume, which becomes plain (gradients and fit record cleared); `'unfit'`: a
	 * partial capture of a volume with a fit record but no samples to refit to (loaded from a file), whose
	 * captured probes get zero gradients and whose record is cleared.
	 */
	mode: 'none' | 'fit' | 'refit' | 'drop' | 'unfit';

	/** The fit points to capture (mode `'fit'`), else null. */
	points: Float64Array | null;

	/** Their weights from `fit.region`, or null. */
	weights: Float64Array | null;

	/** Mode `'fit'`: the checked settings and how the points were made. */
	settings: VolumeFitSettings | null;
	source: string;

}

const FIT_KEYS = [ 'samples', 'spacing', 'gradients', 'lambda', 'gradientLambda', 'nonNegative', 'region', 'reachableFrom' ];

/**
 * Plans the fitting part of a capture of `indices` (see {@link FitPlan}): checks `options.fit`
 * and lays out its points (`samples`, or a grid at `spacing` over the probes' hull in the open
 * space of the scene without the hidden objects).
 * @param hidden The objects the capture hides (the volume's dynamic objects and `exclude`).
 * @throws TypeError / RangeError naming `where` for a bad `fit`, a volume with zones, no fit points.
 */
export function planFit(
	where: string, volume: LightProbeVolume, access: CaptureAccess, options: { fit?: unknown; indices?: unknown; nonNegative?: boolean },
	scene: Scene, hidden: readonly Object3D[],
): FitPlan {

	const plan: FitPlan = { mode: 'none', points: null, weights: null, settings: null, source: '' };
	if ( options.fit === undefined ) {

		const fitted = access.fit !== null || volume.fitSettings !== null;
		if ( options.indices === undefined ) plan.mode = fitted ? 'drop' : 'none';
		else plan.mode = access.fit !== null ? 'refit' : ( fitted ? 'unfit' : 'none' );
		return plan;

	}

	assertOptions( where, 'options.fit', options.fit );
	const fit = options.fit as Record<string, unknown>;
	for ( const key of Object.keys( fit ) ) {

		if ( ! FIT_KEYS.includes( key ) ) throw new TypeError( `${where}: options.fit has the unknown option "${key}"; the options are ${FIT_KEYS.join( ', ' )}.` );

	}

	if ( volume.zones !== null ) {

		throw new Error( `${where}: options.fit is not taken for a volume with lighting zones (each zone blends its own probes); `
			+ 'fit a volume without zones.' );

	}

	if ( ( fit.samples === undefined ) === ( fit.spacing === undefined ) ) {

		throw new RangeError( `${where}: options.fit needs either samples (fit point positions) or spacing (a grid over the probes), `
			+ `got ${fit.samples === undefined ? 'neither' : 'both'}.` );

	}

	const settings: VolumeFitSettings = {
		gradients: readBoolean( where, 'gradients', fit.gradients, false ),
		lambda: readLambda( where, 'lambda', fit.lambda ),
		gradientLambda: readLambda( where, 'gradientLambda', fit.gradientLambda ),
		nonNegative: readBoolean( where, 'nonNegative', fit.nonNegative, options.nonNegative === true ),
	};
	let points: Float64Array;
	if ( fit.samples !== undefined ) {

		const count = assertPoints( where, 'options.fit.samples', fit.samples, 1 );
		points = Float64Array.from( fit.samples as ArrayLike<number> );
		plan.source = `${count} given points`;

	} else {

		assertNumber( where, 'options.fit.spacing', fit.spacing );
		if ( ! ( fit.spacing > 0 ) ) throw new RangeError( `${where}: options.fit.spacing must be > 0, got ${fit.spacing}.` );
		const seeds = fit.reachableFrom !== undefined ? readPointList( where, 'options.fit.reachableFrom', fit.reachableFrom ) : undefined;
		points = fitSamplePoints( where, volume, gatherStaticGeometry( scene, hidden ), fit.spacing, seeds );
		plan.source = `dense captures at spacing ${fit.spacing}`;

	}

	plan.mode = 'fit';
	plan.points = points;
	plan.weights = fit.region !== undefined ? weightsInRegion( where, 'options.fit.region', points, fit.region as RegionOfInterest ) : null;
	plan.settings = settings;
	return plan;

}

/**
 * Puts a finished capture into the volume with its fit, all at once: the fit (or refit) is
 * computed first — a fit that throws leaves the volume as it was — then the captured SH go in
 * (`access.commit`: SH, dirty set, capture settings), then the fitted SH over them, the gradients,
 * the fit record and the store.
 * @param captured The capture (its `pointSH` the fit points' SH in mode `'fit'`), or null when nothing was captured.
 */
export function commitWithFit( plan: FitPlan, volume: LightProbeVolume, access: CaptureAccess, captured: CapturedProbes | null ): void {

	const capture = captured ?? EMPTY_CAPTURE;
	const store = access.fit;
	if ( plan.mode === 'none' ) {

		if ( captured !== null ) access.commit( captured );
		return;

	}

	if ( plan.mode === 'unfit' ) {

		// No samples to refit to: the captured probes hold captured SH, so their fitted gradients go and the record is no longer true.
		if ( capture.indices.length === 0 ) return;
		for ( const index of capture.indices ) volume.gradients?.fill( 0, 3 * SH_FLOATS * index, 3 * SH_FLOATS * ( index + 1 ) );
		access.commit( capture );
		volume.fitSettings = null;
		return;

	}

	if ( plan.mode === 'drop' ) {

		access.commit( capture );
		volume.setGradients( null );
		volume.fitSettings = null;
		access.adoptFit( null );
		return;

	}

	let result;
	if ( plan.mode === 'refit' ) {

		if ( store === null ) return;
		if ( capture.indices.length === 0 && ! store.isStale( volume ) ) return;
		result = store.refit( volume, volume.sh, capture.indices, capture.sh );

	} else {

		// The targets: every probe's captured SH (the store's for a volume fitted before, else its SH), this capture's over them.
		const targets = store !== null ? store.capturedOver( volume.sh ) : volume.sh.slice();
		capture.indices.forEach( ( index, k ) => {

			targets.set( capture.sh.subarray( SH_FLOATS * k, SH_FLOATS * ( k + 1 ) ), SH_FLOATS * index );

		} );
		const samples = { positions: plan.points!, sh: capture.pointSH!, weights: plan.weights };
		result = VolumeFit.fit( volume, targets, samples, plan.settings!, plan.source );

	}

	access.commit( capture );
	volume.sh.set( result.sh );
	volume.setGradients( result.gradients );
	volume.fitSettings = result.record;
	access.adoptFit( result.store );

}

/** A capture of nothing: what a refit after removing probes commits. */
const EMPTY_CAPTURE: CapturedProbes = {
	indices: [], positions: new Float64Array( 0 ), sh: new Float32Array( 0 ), settings: {}, pointSH: null,
};

function readBoolean( where: string, key: string, value: unknown, fallback: boolean ): boolean {

	assertOptionalBoolean( where, `options.fit.${key}`, value );
	return value === undefined ? fallback : value as boolean;

}

function readLambda( where: string, key: string, value: unknown ): number | 'auto' {

	if ( value === undefined || value === 'auto' ) return 'auto';
	if ( typeof value === 'number' && Number.isFinite( value ) && value >= 0 ) return value;
	const message = `${where}: options.fit.${key} must be 'auto' or a finite number ≥ 0, got ${describeValue( value )}.`;
	throw typeof value === 'number' ? new RangeError( message ) : new TypeError( message );

}
