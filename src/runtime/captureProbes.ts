import type { Object3D, Scene } from 'three';
import { createProbeCapturer, prepareRenderer } from '../capture/captureBackends.js';
import type { CaptureRenderer } from '../capture/captureSettings.js';
import type { BakedCapture } from '../io/index.js';
import type { ProbeRole } from '../roles.js';
import { makeIrradianceNonNegative, windowSH } from '../sh/windowSH.js';
import { SH_FLOATS } from '../validate.js';
import { bakedCaptureSettings } from './bakedVolumeData.js';
import type { LightProbeVolumeCaptureOptions } from './LightProbeVolumeOptions.js';
import type { LitObject } from './litObjects.js';
import type { ProbeEdits } from './ProbeEdits.js';
import type { ProbeField } from './ProbeField.js';
import { lightScenery, switchOffScenery } from './sceneryLight.js';
import type { VolumeFit } from './VolumeFit.js';

/** The fields of a `LightProbeVolume` that {@link captureProbes} reads (it writes nothing). */
export interface CapturedVolume {

	readonly positions: Float64Array;
	readonly roles: readonly ProbeRole[];
	readonly count: number;
	isProbeActive( index: number ): boolean;

}

/**
 * The key of `LightProbeVolume`'s member that gives `captureBounces` the volume's registered
 * objects and a way to commit a finished capture (not for users).
 */
export const CAPTURE_ACCESS: unique symbol = Symbol( 'three-capture-lighting.captureAccess' );

/** What `LightProbeVolume[ CAPTURE_ACCESS ]()` returns. */
export interface CaptureAccess {

	/** The registered objects (hidden, or their probe light off, while capturing). */
	readonly lit: readonly LitObject[];

	/** Puts a finished capture into the volume (SH, dirty set, capture settings), all at once. */
	commit( captured: CapturedProbes ): void;

	/**
	 * The volume's fit store — captured SH and fit samples, kept so that a capture after an edit
	 * refits — or null when the volume is not fitted.
	 */
	readonly fit: VolumeFit | null;

	/** Keeps a new fit store (a fitting capture, `fromScene`), or null: the volume is no longer fitted. */
	adoptFit( store: VolumeFit | null ): void;

}

/**
 * The {@link CaptureAccess} of a volume: its registered objects, its fit store (kept by its edits), and the commit of a
 * finished capture — SH and dirty set ({@link ProbeEdits.commitCapture}), then the capture settings — after which
 * `probesChanged` lets its objects blend again.
 */
export function captureAccessOf(
	volume: { captureSettings: BakedCapture }, edits: ProbeEdits, lit: readonly LitObject[], probesChanged: () => void,
): CaptureAccess {

	const commit = ( captured: CapturedProbes ) => {

		if ( edits.commitCapture( captured ) ) volume.captureSettings = captured.settings;
		probesChanged();

	};

	return { lit, commit, fit: edits.fit, adoptFit: ( store ) => { edits.fit = store; } };

}

/** The result of {@link captureProbes}, not yet in the volume: {@link applyCapturedProbes} puts it there. */
export interface CapturedProbes {

	/** The probes captured, in capture order. */
	readonly indices: readonly number[];

	/** Where each was captured: x, y, z per entry of `indices`. */
	readonly positions: Float64Array;

	/** 27 floats per entry of `indices`. */
	readonly sh: Float32Array;

	/** The settings to store with a bake (`LightProbeVolume.captureSettings`). */
	readonly settings: BakedCapture;

	/** The SH of the extra points captured with the probes (27 floats each, e.g. a fit's samples), or null. */
	readonly pointSH: Float32Array | null;

}

/**
 * What reports a capture's progress: `done` of `total` probes of the stage — `'probes'` (each pass
 * of the volume's probes) or `'fit'` (the points a `fit` capture fits the probes to).
 */
export type CaptureProgressCallback = ( done: number, total: number, stage: CaptureStage ) => void;

/** The stages a capture reports in `onProgress`, in order: the probes (once per pass), then the fit points. */
export type CaptureStage = 'probes' | 'fit';

/**
 * One capture of a volume's probes (`LightProbeVolume.capture` without bounces): the probes of
 * `indices` (checked by the caller), in one pass per role with settings of its own, then de-ringed
 * or made non-negative. Objects lit as `'dynamic'` (`hidden`) are hidden; scenery lit by the
 * volume (static props, large objects) stays visible with its probe light off — or, given
 * `scenery` (a bounce pass: the previous pass's probes), lit by those probes. Nothing of the volume changes: the result is staged, so a
 * capture that fails in any pass (a lost context, a throwing callback) leaves every probe as it was.
 * Given `points`, captures them too, after the probes, with the common settings and the same
 * hiding, scenery light and de-ringing (the samples a fit needs, seen as the probes see the scene).
 * @param options Checked by the caller (`checkVolumeCaptureOptions`); `exclude` an array.
 * @param scenery The probes that light the volume's scenery during this capture, or null (its probe light off).
 * @param points x, y, z per extra point, or null.
 */
export async function captureProbes(
	volume: CapturedVolume, lit: readonly LitObject[], indices: readonly number[],
	renderer: CaptureRenderer, scene: Scene, options: LightProbeVolumeCaptureOptions & { exclude?: Object3D[] },
	scenery: ProbeField | null = null, points: Float64Array | null = null,
): Promise<CapturedProbes> {

	// Probes whose role has its own settings (paper 3.4: sky, bounce and reflection captures
	// want different ranges and layers) are captured in their own pass.
	const groups = new Map<string, number[]>();
	const order: number[] = [];
	for ( const index of indices ) {

		const role = volume.roles[ index ];
		const key = options.roles?.[ role ] ? role : '';
		groups.set( key, [ ...( groups.get( key ) ?? [] ), index ] );

	}

	for ( const group of groups.values() ) order.push( ...group );
	const positions = new Float64Array( 3 * order.length );
	order.forEach( ( index, k ) => positions.set( volume.positions.subarray( 3 * index, 3 * index + 3 ), 3 * k ) );
	const sh = new Float32Array( SH_FLOATS * order.length );
	const deringing = options.deringing ?? 0;
	const nonNegative = options.nonNegative === true;
	// Visitors are hidden; scenery lit by the probes is seen as built (probe light off), or with a bounce pass's light.
	const exclude = [ ...lit.filter( ( entry ) => entry.hidden ).map( ( entry ) => entry.object ), ...( options.exclude ?? [] ) ];
	const restoreScenery = scenery !== null ? lightScenery( lit, scenery ) : switchOffScenery( lit );
	const total = order.length;
	const onProgress = options.onProgress as CaptureProgressCallback | undefined;
	let done = 0, pointSH: Float32Array | null = null;
	const finish = ( captured: Float32Array ) => {

		if ( nonNegative ) makeIrradianceNonNegative( captured, deringing );
		else if ( deringing > 0 ) windowSH( captured, deringing, captured );

	};

	try {

		// A WebGPURenderer draws only once initialised.
		await prepareRenderer( renderer );
		for ( const [ role, group ] of groups ) {

			const settings = { ...options, ...( role ? options.roles?.[ role as ProbeRole ] : {} ) };
			const capturer = createProbeCapturer( renderer, settings );
			try {

				const start = done;
				const groupPositions = positions.subarray( 3 * start, 3 * ( start + group.length ) );
				const captured = sh.subarray( SH_FLOATS * start, SH_FLOATS * ( start + group.length ) );
				await capturer.capture( scene, groupPositions, captured, {
					...settings, exclude, onProgress: onProgress && ( ( n ) => onProgress( start + n, total, 'probes' ) ),
				} );
				finish( captured );
				done += group.length;

			} finally {

				capturer.dispose();

			}

		}

		if ( points !== null && points.length > 0 ) {

			const capturer = createProbeCapturer( renderer, options );
			try {

				const count = points.length / 3;
				pointSH = await capturer.capture( scene, points, new Float32Array( SH_FLOATS * count ), {
					...options, exclude, onProgress: onProgress && ( ( n ) => onProgress( n, count, 'fit' ) ),
				} );
				finish( pointSH );

			} finally {

				capturer.dispose();

			}

		}

	} finally {

		restoreScenery();

	}

	return { indices: order, positions, sh, settings: bakedCaptureSettings( options ), pointSH };

}

/** Writes staged capture results into an SH array laid out like the volume's (27 floats per probe id). */
export function applyCapturedProbes( captured: CapturedProbes, sh: Float32Array ): void {

	captured.indices.forEach( ( index, k ) => sh.set( captured.sh.subarray( SH_FLOATS * k, SH_FLOATS * ( k + 1 ) ), SH_FLOATS * index ) );

}
