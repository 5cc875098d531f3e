import type { Box3, Mesh, Object3D, Scene } from 'three';
import { assertCaptureBackend, prepareRenderer } from '../capture/captureBackends.js';
import { assertScene, checkCaptureCall, type CaptureRenderer } from '../capture/captureSettings.js';
import { readPointList, type PointList } from '../placement/readPointList.js';
import { reduceProbes, type ReduceProbesResult } from '../placement/reduceProbes.js';
import { weightsInRegion, type RegionOfInterest } from '../placement/regionOfInterest.js';
import { WalkableRegion, type WalkableRegionOptions } from '../placement/walkableRegion.js';
import {
	SH_FLOATS, assertInteger, assertNumber, assertOptionalBoolean, assertOptionalFunction, assertOptions, describeValue,
} from '../validate.js';
import { CAPTURE_ACCESS } from './captureProbes.js';
import { LightProbeVolume } from './LightProbeVolume.js';
import type { BakedCapture } from '../io/index.js';
import type { LightProbeVolumeCaptureOptions } from './LightProbeVolumeOptions.js';
import { assertClearance } from './placeProbes.js';
import { describeCandidates, placeCandidates, type ProbeCandidates } from './probeCandidates.js';
import { gatherStaticGeometry, type StaticGeometry } from './staticGeometry.js';
import { VolumeFit } from './VolumeFit.js';

/** The stages of {@link volumeFromScene}, in the order they run (`'recapture'` only when the resolutions differ). */
export type FromSceneStage = 'candidates' | 'capture' | 'reduce' | 'recapture' | 'fit';

/** What `onProgress` of `LightProbeVolume.fromScene` receives: `done` of `total` steps of a stage. */
export interface FromSceneProgress {

	stage: FromSceneStage;
	done: number;
	total: number;

}

/** Options of `LightProbeVolume.fromScene`. Give `budget` or `spacing`. */
export interface FromSceneOptions {

	/** How many probes the volume gets (an integer ≥ 4). */
	budget?: number;

	/**
	 * Or: about one probe per `spacing`³ of the level's open space (scene units): the budget is the
	 * open volume (the level's box times the share of a candidate grid half that spacing not inside
	 * geometry or unreachable) over `spacing`³, at least 4.
	 */
	spacing?: number;

	/**
	 * Where the light matters most, weighting both the choice of probes and the fit: a
	 * `RegionOfInterest` (boxes, points within a radius, a `WalkableRegion`), or `'walkable'` —
	 * "where characters go", the level's floor-facing triangles plus a height band
	 * (`walkable` options). Default: everywhere alike.
	 */
	where?: RegionOfInterest | 'walkable';

	/** With `where: 'walkable'`: the `WalkableRegion` options (up, height, maxSlope). */
	walkable?: Omit<WalkableRegionOptions, 'sides'>;

	/** Cube size of the volume's probes (default 32). */
	resolution?: number;

	/**
	 * Cube size of the candidates' capture (default: `resolution`, so the chosen probes need no
	 * second capture — their candidate captures are theirs). A smaller one captures the candidates
	 * faster, then the chosen probes again at `resolution`; the fit samples stay at this size.
	 */
	candidateResolution?: number;

	/**
	 * Fit the probes to the candidates' captures: the choice re-fits at every insertion and swaps
	 * (`reduceProbes` with `fit`), and the volume's SH are fitted to every candidate (the `fit`
	 * capture option's store, so edits refit). Default true; an object sets λ (`'auto'`: by
	 * cross-validation) and `nonNegative`.
	 */
	fit?: boolean | { lambda?: number | 'auto'; gradientLambda?: number | 'auto'; nonNegative?: boolean };

	/** Gradient probes (`volume.gradients`), fitted jointly with the SH; needs `fit`. Default false. */
	gradients?: boolean;

	/** Swap passes of the reduction (see `reduceProbes`); default: its default with `fit`. */
	swaps?: boolean | number;

	/** Seeds of the level's open space, e.g. `[ spawn ]` (see `placeProbes`). Strongly recommended. */
	reachableFrom?: PointList;

	/**
	 * Objects hidden while capturing and left out of the level's geometry (characters, vehicles).
	 * Objects marked `userData.probeLighting = 'dynamic'`, skinned meshes and what hangs from bones
	 * are hidden too — what `add( scene )` would light as moving.
	 */
	exclude?: Iterable<Object3D>;

	/** Place candidates only inside this box (default: the level's bounding box). */
	bounds?: Box3;

	/** About how many grid candidates with `budget` (default max( 256, 8 × budget )). */
	candidates?: number;

	/** Grid spacing of the candidates (default: from `candidates`, or half of `spacing`). */
	candidateSpacing?: number;

	/** Least distance from a probe to any surface (default a quarter of the candidate spacing). */
	clearance?: number;

	/** Other capture options (`near`, `far`, `nonNegative`, `deringing`, `bounces` …) for every capture. */
	capture?: Omit<LightProbeVolumeCaptureOptions, 'resolution' | 'indices' | 'exclude' | 'onProgress' | 'fit'>;

	/** Called as each stage starts (`done` 0) and as it advances; see {@link FromSceneProgress}. */
	onProgress?: ( progress: FromSceneProgress ) => void;

}

const OPTION_KEYS = [
	'budget', 'spacing', 'where', 'walkable', 'resolution', 'candidateResolution', 'fit', 'gradients', 'swaps', 'reachableFrom',
	'exclude', 'bounds', 'candidates', 'candidateSpacing', 'clearance', 'capture', 'onProgress',
];

/**
 * `LightProbeVolume.fromScene`: a ready volume for a level in one call — candidates (mesh vertices
 * and a grid in the open space, `placeProbes`' machinery), one capture of them, the reduction to
 * `budget` probes (re-fitting and swapping with `fit`, weighted by `where`), the chosen probes
 * captured again only when `candidateResolution` differs, and the fit of their SH (and gradients)
 * to every candidate's capture. Nothing is added to the volume: add the character and the scene
 * afterwards as usual.
 */
export async function volumeFromScene( renderer: CaptureRenderer, scene: Scene, options: FromSceneOptions ): Promise<LightProbeVolume> {

	const where = 'LightProbeVolume.fromScene';
	const checked = checkOptions( where, renderer, scene, options );
	await prepareRenderer( renderer );
	const { resolution, candidateResolution, fit, gradients, progress } = checked;
	const hidden = [ ...( checked.exclude ?? [] ), ...movingObjects( scene ) ];

	progress( 'candidates', 0, 1 );
	const geometry = gatherStaticGeometry( scene, hidden );
	if ( geometry.triangles.length === 0 ) throw new RangeError( `${where}: scene has no triangles to place probes in (without the hidden objects).` );
	const byDensity = options.spacing !== undefined;
	const placed = placeCandidates( where, geometry, {
		reachableFrom: checked.seeds, bounds: options.bounds, clearance: options.clearance, measureOpenVolume: byDensity,
		spacing: options.candidateSpacing ?? ( byDensity ? options.spacing! / 2 : undefined ),
		candidates: options.candidates ?? Math.max( 256, 8 * ( options.budget ?? 4 ) ),
	} );
	const budget = byDensity ? budgetFromSpacing( where, placed, options.spacing! ) : options.budget!;
	const candidates = placed.positions, found = candidates.length / 3;
	if ( found < budget ) {

		throw new RangeError( `${where}: ${describeCandidates( placed )}, fewer than the budget (${budget}); pass a smaller `
			+ 'options.candidateSpacing or options.clearance, a smaller budget, or check options.bounds and options.reachableFrom.' );

	}

	const region = regionOf( where, options, geometry );
	const weights = region !== null ? weightsInRegion( where, 'options.where', candidates, region ) : null;
	progress( 'candidates', 1, 1 );

	const candidateCapture = { ...checked.capture, exclude: hidden, resolution: candidateResolution };
	const { sh: candidateSH, settings: candidateSettings } = await captureAt( where, renderer, scene, candidates, candidateCapture,
		( done, total ) => progress( 'capture', done, total ) );

	progress( 'reduce', 0, 1 );
	const fitOptions = fit === null ? undefined : { ...fit, gradients };
	const reduction = reduceProbes( candidates, candidateSH, {
		targetCount: budget, strategy: 'mean', fit: fitOptions, swaps: options.swaps, region: region ?? undefined,
	} );
	progress( 'reduce', 1, 1 );

	const positions = reduction.positions, count = positions.length / 3;
	let captured: Float32Array = new Float32Array( SH_FLOATS * count ), settings = candidateSettings;
	reduction.keep.forEach( ( c, k ) => captured.set( candidateSH.subarray( SH_FLOATS * c, SH_FLOATS * ( c + 1 ) ), SH_FLOATS * k ) );
	if ( candidateResolution !== resolution ) {

		const probeCapture = { ...checked.capture, exclude: hidden, resolution };
		( { sh: captured, settings } = await captureAt( where, renderer, scene, positions, probeCapture,
			( done, total ) => progress( 'recapture', done, total ) ) );

	}

	const volume = new LightProbeVolume( { positions, sh: captured } );
	volume.captureSettings = settings;
	progress( 'fit', 0, 1 );
	if ( fit !== null ) {

		const samples = { positions: candidates, sh: candidateSH, weights };
		const settings = { gradients, lambda: fit.lambda, gradientLambda: fit.gradientLambda, nonNegative: fit.nonNegative };
		const source = `the ${found} candidates of fromScene, captured at ${candidateResolution}²`;
		const result = VolumeFit.fit( volume, captured, samples, settings, source );
		volume.sh.set( result.sh );
		volume.setGradients( result.gradients );
		volume.fitSettings = result.record;
		volume[ CAPTURE_ACCESS ]().adoptFit( result.store );

	}

	volume.metadata = describeLayout( reduction, found, candidateResolution, fit !== null, gradients );
	progress( 'fit', 1, 1 );
	return volume;

}

/** What a volume from `fromScene` says of itself (its `metadata`). */
function describeLayout( reduction: ReduceProbesResult, found: number, resolution: number, fitted: boolean, gradients: boolean ): string {

	const how = fitted ? ( gradients ? 'fitted, with gradients' : 'fitted' ) : 'captured SH';
	return `LightProbeVolume.fromScene: ${reduction.keep.length} probes of ${found} candidates captured at ${resolution}² (${how}); `
		+ `mean irradiance error over the candidates ${reduction.error.mean.toFixed( 4 )}`;

}

/** The checked options, with defaults. */
function checkOptions( where: string, renderer: unknown, scene: unknown, options: FromSceneOptions ) {

	assertCaptureBackend( where, renderer );
	assertScene( where, scene );
	if ( options === null || typeof options !== 'object' ) {

		throw new TypeError( `${where}: options must be { budget | spacing, where?, resolution?, fit?, gradients?, onProgress?, … }, `
			+ `got ${describeValue( options )}.` );

	}

	for ( const key of Object.keys( options ) ) {

		if ( ! OPTION_KEYS.includes( key ) ) throw new TypeError( `${where}: unknown option "${key}"; the options are ${OPTION_KEYS.join( ', ' )}.` );

	}

	if ( ( options.budget === undefined ) === ( options.spacing === undefined ) ) {

		throw new RangeError( `${where}: options needs either budget (a probe count) or spacing (about one probe per spacing³ of open space), `
			+ `got ${options.budget === undefined ? 'neither' : 'both'}.` );

	}

	if ( options.budget !== undefined ) assertInteger( where, 'options.budget', options.budget, 4, Number.MAX_SAFE_INTEGER );
	if ( options.spacing !== undefined ) positive( where, 'options.spacing', options.spacing );
	if ( options.candidateSpacing !== undefined ) positive( where, 'options.candidateSpacing', options.candidateSpacing );
	if ( options.candidates !== undefined ) assertInteger( where, 'options.candidates', options.candidates, 8, 1e6 );
	assertClearance( where, options.clearance );
	if ( options.bounds !== undefined && options.bounds?.isBox3 !== true ) throw new TypeError( `${where}: options.bounds must be a three.js Box3.` );
	const resolution = options.resolution ?? 32;
	assertInteger( where, 'options.resolution', resolution, 1, 4096 );
	const candidateResolution = options.candidateResolution ?? resolution;
	assertInteger( where, 'options.candidateResolution', candidateResolution, 1, 4096 );
	assertOptionalBoolean( where, 'options.gradients', options.gradients );
	const gradients = options.gradients === true;
	const fit = readFit( where, options.fit, options.capture?.nonNegative === true );
	if ( gradients && fit === null ) throw new RangeError( `${where}: options.gradients needs options.fit (gradients are fitted, not captured).` );
	if ( options.swaps !== undefined && typeof options.swaps !== 'boolean' ) assertInteger( where, 'options.swaps', options.swaps, 0, 1000 );
	assertOptionalFunction( where, 'options.onProgress', options.onProgress );
	assertOptions( where, 'options.capture', options.capture );
	for ( const key of [ 'resolution', 'indices', 'exclude', 'onProgress', 'fit' ] ) {

		if ( ( options.capture as Record<string, unknown> | undefined )?.[ key ] !== undefined ) {

			throw new TypeError( `${where}: options.capture.${key} is not taken; ${key === 'indices' ? 'every probe is captured' : `pass options.${key}`}.` );

		}

	}

	if ( options.where !== undefined && options.where !== 'walkable' ) assertOptions( where, 'options.where', options.where );
	if ( options.walkable !== undefined && options.where !== 'walkable' ) throw new TypeError( `${where}: options.walkable is taken only with where: 'walkable'.` );
	const seeds = options.reachableFrom === undefined ? undefined : readPointList( where, 'options.reachableFrom', options.reachableFrom );
	const { exclude } = checkCaptureCall( where, 'options.', { exclude: options.exclude } );
	const onProgress = options.onProgress;
	const progress = ( stage: FromSceneStage, done: number, total: number ) => onProgress?.( { stage, done, total } );
	return { resolution, candidateResolution, fit, gradients, seeds, exclude, progress, capture: options.capture ?? {} };

}

function positive( where: string, name: string, value: unknown ): void {

	assertNumber( where, name, value );
	if ( ! ( value > 0 ) ) throw new RangeError( `${where}: ${name} must be > 0, got ${value}.` );

}

/** `options.fit`: null (off), or the fit settings with defaults (true: λ by cross-validation). */
function readFit( where: string, fit: FromSceneOptions[ 'fit' ], nonNegative: boolean ) {

	if ( fit === false ) return null;
	if ( fit === undefined || fit === true ) return { lambda: 'auto' as const, gradientLambda: 'auto' as const, nonNegative };
	assertOptions( where, 'options.fit', fit );
	for ( const key of Object.keys( fit ) ) {

		if ( ! [ 'lambda', 'gradientLambda', 'nonNegative' ].includes( key ) ) {

			throw new TypeError( `${where}: options.fit has the unknown option "${key}"; the options are lambda, gradientLambda, nonNegative.` );

		}

	}

	assertOptionalBoolean( where, 'options.fit.nonNegative', fit.nonNegative );
	return {
		lambda: readLambda( where, 'options.fit.lambda', fit.lambda ),
		gradientLambda: readLambda( where, 'options.fit.gradientLambda', fit.gradientLambda ),
		nonNegative: fit.nonNegative ?? nonNegative,
	};

}

function readLambda( where: string, name: string, value: unknown ): number | 'auto' {

	if ( value === undefined || value === 'auto' ) return 'auto';
	if ( typeof value === 'number' && Number.isFinite( value ) && value >= 0 ) return value;
	const message = `${where}: ${name} must be 'auto' or a finite number ≥ 0, got ${describeValue( value )}.`;
	throw typeof value === 'number' ? new RangeError( message ) : new TypeError( message );

}

/** The probe count for `spacing`: the open volume over spacing³, at least 4. */
function budgetFromSpacing( where: string, placed: ProbeCandidates, spacing: number ): number {

	const budget = Math.round( placed.openVolume / ( spacing * spacing * spacing ) );
	if ( budget < 4 ) {

		throw new RangeError( `${where}: the level's open space (about ${placed.openVolume.toPrecision( 3 )} units³) holds ${budget} probes `
			+ `at options.spacing ${spacing}; a volume needs at least 4: pass a smaller spacing or a budget.` );

	}

	return budget;

}

/** `options.where` as a region (the walkable region of the static level for `'walkable'`), or null. */
function regionOf( where: string, options: FromSceneOptions, geometry: StaticGeometry ): RegionOfInterest | null {

	if ( options.where === undefined ) return null;
	if ( options.where !== 'walkable' ) return options.where;
	try {

		return { walkable: new WalkableRegion( geometry.triangles, { ...options.walkable, sides: geometry.sides } ) };

	} catch ( error ) {

		throw renamed( error, 'WalkableRegion', where, 'options.walkable' );

	}

}

/**
 * The objects `add( scene )` would light as moving, hidden while capturing: marked
 * `userData.probeLighting = 'dynamic'`, skinned meshes, and meshes below a bone (attachments).
 */
export function movingObjects( scene: Object3D ): Object3D[] {

	const out: Object3D[] = [];
	const visit = ( node: Object3D, underBone: boolean ): void => {

		const mesh = node as Mesh & { isSkinnedMesh?: boolean };
		if ( node.userData?.probeLighting === 'dynamic' || mesh.isSkinnedMesh === true || ( underBone && mesh.isMesh === true ) ) {

			out.push( node );
			return;

		}

		const below = underBone || ( node as { isBone?: boolean } ).isBone === true;
		for ( const child of node.children ) visit( child, below );

	};

	visit( scene, false );
	return out;

}

/** SH (and settings) of points captured by a temporary volume (hiding `exclude`), with errors re-addressed to fromScene. */
async function captureAt(
	where: string, renderer: CaptureRenderer, scene: Scene, positions: Float64Array, options: LightProbeVolumeCaptureOptions,
	onProgress: ( done: number, total: number ) => void,
): Promise<{ sh: Float32Array; settings: BakedCapture }> {

	const volume = new LightProbeVolume( { positions } );
	try {

		await volume.capture( renderer, scene, { ...options, onProgress } );
		return { sh: volume.sh.slice(), settings: volume.captureSettings };

	} catch ( error ) {

		throw renamed( error, 'LightProbeVolume.capture', where, 'options.capture' );

	} finally {

		volume.dispose();

	}

}

/** An error of `from` re-addressed: `from: options.x …` → `where: option.x …`, `from: …` → `where: …`. */
function renamed( error: unknown, from: string, where: string, option: string ): unknown {

	if ( ! ( error instanceof Error ) || ! error.message.startsWith( `${from}: ` ) ) return error;
	const rest = error.message.slice( from.length + 2 );
	const message = rest.startsWith( 'options.' ) ? `${where}: ${option}.${rest.slice( 8 )}` : `${where}: ${rest}`;
	const Type = error instanceof TypeError ? TypeError : error instanceof RangeError ? RangeError : Error;
	return new Type( message, { cause: error } );

}
