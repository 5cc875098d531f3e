/** The paper's view modes: Fig. 8/13 (indirect only) and Fig. 9/14 (direct + hemisphere). */
export type ViewMode = 'tetrahedral + diffuse' | 'indirect only' | 'direct + hemisphere';

/** The view modes, in the panel's order. */
export const VIEWS: ViewMode[] = [ 'tetrahedral + diffuse', 'indirect only', 'direct + hemisphere' ];

/** The panel's state, read first from the query parameters; the panel edits it. */
export interface DemoSettings {

	/** Name of the probe layout shown. */
	layout: string;
	/** Tetrahedral, or the paper's trilinear baseline (grid layouts). */
	interpolation: 'tetrahedral' | 'trilinear';
	/** The paper's view modes. */
	view: ViewMode;
	/** Cube-map size of the captures. */
	resolution: number;
	/** Probe markers shown (`probes=0`: no). */
	showProbes: boolean;
	/** The tetrahedra shown, the character's in yellow. */
	showCells: boolean;
	/** Time runs. */
	animate: boolean;
	/** Probe editing: a click on a probe selects it for dragging. */
	edit: boolean;
	/** Visibility guard: probes an object cannot see (through static geometry) do not light it. */
	guard: boolean;
	/** Lighting zones from the layout (when it has them): each its own tetrahedralization. */
	zones: boolean;
	/** Outside the probes' hull: outer cells (continuous fade-out) or the nearest hull point (the old rule). */
	outside: 'outerCells' | 'nearestFace';
	/** De-ringing window strength applied to each captured probe (0 = none). */
	deringing: number;
	/** Raise the de-ringing where needed so that no probe's irradiance is negative. */
	nonNegative: boolean;
	/** Diffuse bounces added by capturing again with the static scene lit by the probes. */
	bounces: number;
	/** The layout made by `LightProbeVolume.fromScene` instead of the panel's (`auto=1`; pages that have it). */
	automatic: boolean;
	/** Probes fitted to dense captures (`fit=1`): the capture's `fit` option, fromScene's fit. */
	fit: boolean;

}

/** Everything a scene page reads from its address (see the README, "Demo pages"). */
export interface DemoQuery {

	/** All parameters, for a page's own (e.g. Sponza's `floor`). */
	params: URLSearchParams;
	/** The panel's first state. */
	settings: DemoSettings;
	/** Base URL of the third-party assets (`assets`, default /assets/). */
	assets: string;
	/** Names of probes to leave out (`drop=name,name`). */
	drop: string[];
	/** Extra probe-lit spheres following the character (`spheres=N`). */
	spheres: number;
	/** Where a white probe-lit test ball stands (`ball=x,y,z`), or null. */
	ball: number[] | null;
	/** Whether the character walks (`character=0`: no). */
	character: boolean;
	/** A frozen time in seconds (`t`), or null: time runs. */
	time: number | null;
	/** `hide=gui`: no panel, no stats, no text that changes (screenshots for tests). */
	hideGui: boolean;
	/** `tonemapping=none`: colour ratios kept, for measurements. */
	noToneMapping: boolean;
	/** `volume=URL`: a baked volume file instead of a capture, or null. */
	volume: string | null;
	/**
	 * `present=0`: frames are drawn into an offscreen render target, not the canvas (tests: headless
	 * Chromium on SwiftShader loses a WebGPU device soon after its first canvas present).
	 */
	offscreen: boolean;

}

/** Reads the query parameters of a scene page (`location.search`). */
export function readDemoQuery( search: string ): DemoQuery {

	const params = new URLSearchParams( search );
	const view = params.get( 'view' ) ?? '';
	const frozen = params.get( 't' );
	const ball = params.get( 'ball' );
	const settings: DemoSettings = {
		layout: params.get( 'layout' ) ?? '',
		interpolation: params.get( 'interpolation' ) === 'trilinear' ? 'trilinear' : 'tetrahedral',
		view: ( VIEWS as string[] ).includes( view ) ? view as ViewMode : 'tetrahedral + diffuse',
		resolution: Number( params.get( 'resolution' ) ?? 32 ),
		showProbes: params.get( 'probes' ) !== '0',
		showCells: false,
		animate: true,
		edit: false,
		guard: params.get( 'guard' ) === '1',
		zones: params.get( 'zones' ) === '1',
		outside: params.get( 'outside' ) === 'nearest' ? 'nearestFace' : 'outerCells',
		deringing: Number( params.get( 'deringing' ) ?? 0 ),
		nonNegative: params.get( 'nonnegative' ) === '1',
		bounces: Number( params.get( 'bounces' ) ?? 0 ),
		automatic: params.get( 'auto' ) === '1',
		fit: params.get( 'fit' ) === '1',
	};
	return {
		params,
		settings,
		assets: params.get( 'assets' ) ?? '/assets/',
		drop: ( params.get( 'drop' ) ?? '' ).split( ',' ).filter( Boolean ),
		spheres: Number( params.get( 'spheres' ) ?? 0 ),
		ball: ball ? ball.split( ',' ).map( Number ) : null,
		character: params.get( 'character' ) !== '0',
		time: frozen !== null ? Number( frozen ) : null,
		hideGui: params.get( 'hide' ) === 'gui',
		noToneMapping: params.get( 'tonemapping' ) === 'none',
		volume: params.get( 'volume' ) || null,
		offscreen: params.get( 'present' ) === '0',
	};

}
