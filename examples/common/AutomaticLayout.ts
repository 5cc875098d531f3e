import * as THREE from 'three';
import { LightProbeVolume } from 'three-capture-lighting';
import { formatTimeLeft } from './CaptureProgress.js';
import type { ProbeLayout } from './layouts.js';
import type { Viewer } from './Viewer.js';

/** A page's settings for the automatic layout and the fit (issue 14). */
export interface AutomaticSetup {

	/** Probes of the automatic layout (`LightProbeVolume.fromScene`'s budget). */
	budget: number;
	/** Where the player starts: the seed of the open space the candidates must be reachable from. */
	reachableFrom: number[];
	/** Spacing of the fit points of "fit to dense captures" on a hand-made or grid layout (`capture`'s `fit.spacing`). */
	fitSpacing: number;
	/** The page's own capture settings (near, far) for fromScene's captures. */
	capture: { near?: number; far?: number };

	/** The box to place candidates in (fromScene's `bounds`; default the level's box): a level inside a sky dome gives its own. */
	bounds?: { min: number[]; max: number[] };

	/** About how many grid candidates (fromScene's `candidates`; default max( 256, 8 × budget )). */
	candidates?: number;

	/**
	 * The largest cube size of the candidates' capture (fromScene's `candidateResolution` is the
	 * smaller of this and the panel's resolution; default: the panel's): a smaller one captures the
	 * many candidates faster, then fromScene captures the chosen probes again at the panel's.
	 */
	candidateResolution?: number;

}

/**
 * "automatic layout (budget N)": a layout made by `LightProbeVolume.fromScene` — candidates in the
 * level's open space, captured once, reduced to the budget (with "fit to dense captures": re-fitting
 * at every insertion and fitting the probes to every candidate's capture) — with a progress bar
 * per stage; and the status line that says how a volume's SH were made.
 */
export class AutomaticLayout {

	/** The page's settings. */
	readonly setup: AutomaticSetup;
	private readonly viewer: Viewer;

	constructor( viewer: Viewer, setup: AutomaticSetup ) {

		this.viewer = viewer;
		this.setup = setup;

	}

	/** The panel's name for the layout. */
	get name(): string {

		return `automatic layout (budget ${this.setup.budget})`;

	}

	/** Runs fromScene with the panel's resolution, fitted or not; `hidden` are left out of its captures (the fox, the helpers). */
	async create( fit: boolean, hidden: THREE.Object3D[] ): Promise<{ volume: LightProbeVolume; layout: ProbeLayout }> {

		const { overlay, settings, renderer, scene } = this.viewer;
		const { budget, reachableFrom, capture, candidates } = this.setup;
		const box = this.setup.bounds;
		const bounds = box && new THREE.Box3( new THREE.Vector3().fromArray( box.min ), new THREE.Vector3().fromArray( box.max ) );
		const candidateResolution = Math.min( this.setup.candidateResolution ?? Infinity, settings.resolution );
		let started = 0;
		const onProgress = ( { stage, done, total }: { stage: string; done: number; total: number } ) => {

			if ( stage !== 'capture' && stage !== 'recapture' ) {

				overlay.progress( STAGE_LABELS[ stage ].replace( 'N', String( budget ) ), 0 );
				return;

			}

			// The first candidate also compiles the shaders: the rate is measured from there on.
			if ( done <= 1 ) started = performance.now();
			const left = done > 1 ? ( performance.now() - started ) / ( done - 1 ) * ( total - done ) : NaN;
			const what = stage === 'capture' ? `candidate ${done} / ${total} at ${candidateResolution}²` : `probe ${done} / ${total} at ${settings.resolution}²`;
			overlay.progress( `capturing ${what} — ${formatTimeLeft( left )}`, done / total );

		};

		try {

			const volume = await LightProbeVolume.fromScene( renderer, scene, {
				budget, reachableFrom, fit, resolution: settings.resolution, candidateResolution, bounds, candidates, exclude: hidden,
				capture, onProgress,
			} );
			const layout: ProbeLayout = { name: this.name, positions: Array.from( volume.positions ) };
			return { volume, layout };

		} finally {

			overlay.progress( '', 1 );

		}

	}

	/**
	 * Status lines: how the volume's SH were made (fitted, to what, its cross-validation error) and,
	 * for an automatic layout, its error over the candidates.
	 */
	describe( volume: LightProbeVolume, automatic: boolean ): string {

		const fit = volume.fitSettings;
		const lines: string[] = [];
		if ( automatic ) {

			const error = /mean irradiance error over the candidates ([\d.]+)/.exec( volume.metadata )?.[ 1 ];
			if ( error ) lines.push( `automatic: error ${( 100 * Number( error ) ).toFixed( 1 )} % over the candidates` );

		}

		if ( fit === null ) {

			lines.push( 'captured SH (not fitted)' );

		} else {

			const cv = fit.crossValidationError !== null ? `, held-out error ${( 100 * fit.crossValidationError ).toFixed( 1 )} %` : '';
			lines.push( `fitted to ${fit.samples} dense captures${fit.gradients ? ' with gradients' : ''}${cv}` );

		}

		return lines.join( '\n' );

	}

}

/** What the progress bar says in the stages without a per-probe count. */
const STAGE_LABELS: Record<string, string> = {
	candidates: 'placing candidates in the open space…',
	capture: '',
	reduce: 'choosing N probes from the candidates…',
	recapture: '',
	fit: 'fitting the probes to the candidates\' captures…',
};
