import * as THREE from 'three';
import type GUI from 'lil-gui';
import {
	LightProbeVolume, LightProbeVolumeExporter, LightProbeVolumeLoader, VisibilityGuard, type CaptureBouncesOptions,
} from 'three-capture-lighting';
import { GridInterpolator } from 'three-capture-lighting/math';
import { withoutAmbientStandIns } from './ambientStandIns.js';
import { CaptureProgress } from './CaptureProgress.js';
import { download, fileName } from './download.js';
import type { DynamicObjects } from './DynamicObjects.js';
import { AutomaticLayout, type AutomaticSetup } from './AutomaticLayout.js';
import { createPanel } from './gui.js';
import { dropProbes, type ProbeLayout } from './layouts.js';
import { ProbeEditing, type EditableVolume } from './ProbeEditing.js';
import { ProbeMarkers } from './ProbeMarkers.js';
import { exposeForTests } from './testHooks.js';
import { applyViewMode, hemisphereMatrices } from './viewModes.js';
import type { Viewer } from './Viewer.js';

/** A page's volume setup: the library calls, in the page; the demo calls them when needed. */
export interface VolumeSetup {

	/** The page's probe layouts; the panel switches between them (`drop=` leaves probes out). */
	layouts: ProbeLayout[];
	/** A volume for a layout: `sh` holds the probes' SH when a volume is rebuilt (else none yet). */
	createVolume( layout: ProbeLayout, sh?: Float32Array ): LightProbeVolume;
	/** Registers what the probes light with a new volume (the tetrahedral one, or the trilinear baseline). */
	addObjects( volume: LightProbeVolume ): void;
	/**
	 * Captures the volume's probes (or `options.indices`) with the panel's settings in `options`;
	 * `options.bounces` > 0: as many diffuse bounces (`captureBounces`); `options.fit`: fitted to
	 * dense captures.
	 */
	capture( volume: LightProbeVolume, options: CaptureBouncesOptions ): Promise<unknown>;
	/** The "automatic layout" and "fit to dense captures" toggles (issue 14), when the page has them. */
	automatic?: AutomaticSetup;

}

/**
 * The probe volume of a scene page across the panel's changes: the layout shown and its volume
 * (from the page's `createVolume`), the trilinear baseline for grid layouts, the visibility guard,
 * captures with a progress bar, baked files (`volume=URL`, "export baked volume"), probe markers,
 * probe editing, the panel, the status line and the view modes.
 */
export class ProbeVolumeDemo implements EditableVolume {

	/** The lil-gui panel (null with `hide=gui`): pages add their own controls to it after `start()`. */
	gui: GUI | null = null;
	/** The tetrahedral volume of the layout shown (what is captured and edited). */
	volume!: LightProbeVolume;
	/** The page's layouts (without the dropped probes), and a baked file's. */
	readonly layouts: ProbeLayout[];
	/** The probe markers and cells drawn. */
	readonly markers: ProbeMarkers;
	/** Probe editing (select, drag, add, delete, export). */
	readonly editing: ProbeEditing;
	private readonly viewer: Viewer;
	private readonly objects: DynamicObjects;
	private readonly setup: VolumeSetup;
	/** The paper's trilinear baseline over a grid layout's probes (same SH), or null. */
	private trilinear: LightProbeVolume | null = null;
	/** The automatic layout toggle's fromScene runs, or null when the page has none. */
	private readonly automatic: AutomaticLayout | null;
	/** The layout made by fromScene while "automatic layout" is on, else null. */
	private automaticLayout: ProbeLayout | null = null;
	/** The BVH of the static scene for the visibility guard, built the first time it is switched on. */
	private guard: VisibilityGuard | null = null;
	private capturing = false;
	private readonly hemisphere = hemisphereMatrices();
	private readonly characterCentre = new THREE.Vector3();

	/** Sets the volume up for `viewer`'s page; `objects` are left out of captures and of the guard. */
	constructor( viewer: Viewer, objects: DynamicObjects, setup: VolumeSetup ) {

		this.viewer = viewer;
		this.objects = objects;
		this.setup = setup;
		this.layouts = setup.layouts.map( ( layout ) => dropProbes( layout, viewer.query.drop ) );
		if ( viewer.settings.layout === '' ) viewer.settings.layout = this.layouts[ 0 ].name;
		this.markers = new ProbeMarkers( viewer.helpers, objects.height * 0.12 );
		this.editing = new ProbeEditing( viewer, this, this.markers );
		this.automatic = setup.automatic ? new AutomaticLayout( viewer, setup.automatic ) : null;
		if ( ! this.automatic ) viewer.settings.automatic = viewer.settings.fit = false;
		exposeForTests( viewer, objects, this );

	}

	/** Loads the baked volume (`volume=URL`) or creates and captures the first layout's; opens the panel. */
	async start(): Promise<void> {

		// A WebGPURenderer renders (and captures) only once its init() is done.
		await this.viewer.ready;
		const baked = this.viewer.query.volume;
		if ( baked ) await this.loadBaked( baked );
		if ( ! this.viewer.query.hideGui ) this.gui = this.createPanel();
		if ( ! baked ) await this.showLayout();

	}

	/** The layout shown: the automatic one while "automatic layout" is on, else the panel's. */
	get layout(): ProbeLayout {

		if ( this.automaticLayout ) return this.automaticLayout;
		return this.layouts.find( ( layout ) => layout.name === this.viewer.settings.layout ) ?? this.layouts[ 0 ];

	}

	/**
	 * A volume for the layout the panel says, captured: the automatic one (`fromScene`, which
	 * captures it) or the panel's layout (a new volume, captured with the panel's settings).
	 */
	async showLayout(): Promise<void> {

		const { settings } = this.viewer;
		if ( ! settings.automatic || ! this.automatic ) {

			this.automaticLayout = null;
			this.rebuildVolume();
			await this.recapture();
			return;

		}

		if ( this.capturing ) return;
		this.capturing = true;
		const start = performance.now();
		try {

			const { volume, layout } = await this.automatic.create( settings.fit, [ this.viewer.helpers, ...this.objects.list ] );
			this.automaticLayout = layout;
			if ( settings.interpolation === 'trilinear' ) settings.interpolation = 'tetrahedral';
			this.rebuildVolume( undefined, volume );
			this.viewer.report.captureMs = performance.now() - start;
			this.updateMarkers();

		} finally {

			this.capturing = false;

		}

	}

	/** Names of the page's probe layouts (for tests and benchmarks). */
	layoutNames(): string[] {

		return this.layouts.map( ( layout ) => layout.name );

	}

	/** The volume lighting the objects now (tetrahedral, or the trilinear baseline): update it every frame. */
	get activeVolume(): LightProbeVolume {

		return this.viewer.settings.interpolation === 'trilinear' && this.trilinear ? this.trilinear : this.volume;

	}

	/**
	 * A new volume for the layout shown, with `sh` (e.g. the probes' SH kept across a change of
	 * interpolation), or `baked`, a volume loaded from a file, as it is. The objects move to it.
	 */
	rebuildVolume( sh?: Float32Array, baked?: LightProbeVolume ): void {

		const layout = this.layout, settings = this.viewer.settings;
		// dispose(): the old volumes let go of the objects, restoring their materials.
		this.volume?.dispose();
		this.trilinear?.dispose();
		this.volume = baked ?? this.setup.createVolume( layout, sh );
		this.trilinear = null;
		if ( layout.grid ) {

			const grid = new GridInterpolator( layout.grid.min, layout.grid.max, layout.grid.counts );
			this.trilinear = new LightProbeVolume( { positions: grid.positions, interpolator: grid, sh: this.volume.sh } );

		}

		if ( settings.interpolation === 'trilinear' && ! this.trilinear ) settings.interpolation = 'tetrahedral';
		this.applyGuard();
		// What moves is added before any capture: a volume hides the objects it lights while it
		// captures, so the fox never ends up in its own probes.
		this.setup.addObjects( this.activeVolume );
		this.viewer.report.probes = this.volume.count;
		this.gui?.controllersRecursive().forEach( ( controller ) => controller.updateDisplay() );

	}

	/** Captures all probes (or `indices`) with the panel's settings, with a progress bar. */
	async recapture( indices?: number[] ): Promise<void> {

		if ( this.capturing ) return;
		this.capturing = true;
		const start = performance.now();
		const { settings, overlay, report } = this.viewer;
		const progress = new CaptureProgress( overlay, `at ${settings.resolution}²`, settings.bounces + 1 );
		try {

			// Fitted to a grid of dense captures when "fit to dense captures" is on; an edit's capture (indices) refits.
			const fit = settings.fit && indices === undefined ? { spacing: this.automatic!.setup.fitSpacing } : undefined;
			const options: CaptureBouncesOptions = {
				resolution: settings.resolution, indices, deringing: settings.deringing, nonNegative: settings.nonNegative, fit,
				// The objects are added to the active volume, which the capture hides; with the trilinear
				// baseline active, the tetrahedral volume captured here does not know them: excluded by hand.
				exclude: [ this.viewer.helpers, ...this.objects.list ],
				onProgress: ( done: number, total: number, stage?: string ) => progress.probes( done, total, stage ),
				bounces: settings.bounces,
				onPass: ( pass: number ) => progress.passDone( pass ),
			};
			// The bounces replace the scenes' faint emissive stand-in for indirect light.
			if ( settings.bounces > 0 ) await withoutAmbientStandIns( this.viewer.scene, () => this.setup.capture( this.volume, options ) );
			else await this.setup.capture( this.volume, options );
			// The trilinear baseline blends other weights: fitted, it is fitted for its own (a capture of its own).
			if ( this.trilinear && fit ) await this.setup.capture( this.trilinear, options );
			else if ( this.trilinear ) this.trilinear.sh.set( this.volume.sh );
			report.captureMs = performance.now() - start;
			this.updateMarkers();

		} finally {

			progress.done();
			this.capturing = false;

		}

	}

	/** Redraws the probe markers and cells of the volume. */
	updateMarkers(): void {

		this.markers.update( this.volume );
		this.viewer.report.cells = this.volume.interpolator.cellCount;

	}

	/**
	 * Every frame, after `activeVolume.update()`: the panel's view mode on `objects` (what the page
	 * lit), the probe markers and the character's cell, the status line.
	 */
	showView( objects: readonly THREE.Object3D[] ): void {

		const { settings, overlay, report } = this.viewer;
		const volume = this.activeVolume;
		applyViewMode( volume, objects, settings.view, this.hemisphere );
		// The cell the fox itself is lit from (its anchor), or the centre of the walk without a fox.
		const highlighted = this.objects.character?.object ?? this.objects.characterCentre( this.characterCentre );
		this.markers.show( settings.showProbes, settings.showCells, this.volume, highlighted );
		const cells = `${volume.interpolator.cellCount} ${settings.interpolation === 'trilinear' ? 'boxes' : 'cells'}`;
		const how = this.automatic ? `${this.automatic.describe( volume, this.automaticLayout !== null )}\n` : '';
		overlay.status( `${this.layout.name} — ${settings.interpolation}\n${volume.count} probes, ${cells}\n${how}`
			+ `capture ${report.captureMs.toFixed( 0 )} ms at ${settings.resolution}²\n${this.viewer.fps.toFixed( 0 )} fps` );

	}

	/** Turns the visibility guard on or off on both volumes; its BVH of the static scene is built once. */
	private applyGuard(): void {

		const { settings, scene, helpers, report } = this.viewer;
		if ( settings.guard && ! this.guard ) {

			const dynamic = new Set<THREE.Object3D>( [ helpers, ...this.objects.list ] );
			this.guard = new VisibilityGuard( scene.children.filter( ( object ) => ! dynamic.has( object ) ) );

		}

		const occluders = settings.guard ? this.guard : null;
		this.volume.setOccluders( occluders );
		this.trilinear?.setOccluders( occluders );
		report.leakingCells = settings.guard ? this.volume.findLeakingTetrahedra().length : 0;

	}

	/**
	 * A baked volume instead of a capture (`volume=URL`, a file from "export baked volume" or
	 * `capture-lighting bake`): its stored tetrahedralization is used as it is.
	 */
	private async loadBaked( url: string ): Promise<void> {

		const { overlay, report, settings } = this.viewer;
		overlay.progress( `loading ${url}…`, 0 );
		const response = await fetch( url );
		if ( ! response.ok ) throw new Error( `Baked volume not found: ${url} (HTTP ${response.status}).` );
		const buffer = await response.arrayBuffer();
		const start = performance.now();
		const volume = new LightProbeVolumeLoader().parse( buffer );
		report.loadMs = performance.now() - start;
		const name = `baked: ${url.split( /[/?#]/ ).filter( Boolean ).pop()}`;
		this.layouts.push( { name, positions: Array.from( volume.positions ), names: volume.names.slice(), roles: volume.roles.slice() } );
		settings.layout = name;
		this.rebuildVolume( undefined, volume );
		overlay.progress( '', 1 );
		this.updateMarkers();

	}

	/**
	 * A new volume for the layout shown with the light it has: the same SH — or, when fitted, a new
	 * capture, since fitted SH (and gradients) hold only for the weights they were fitted to.
	 */
	private rebuildKeepingLight(): void {

		if ( this.volume.fitSettings === null && ! this.viewer.settings.fit ) {

			this.rebuildVolume( this.volume.sh );
			return;

		}

		this.rebuildVolume();
		this.recapture();

	}

	private createPanel(): GUI {

		return createPanel( this.viewer.settings, this.layouts, {
			layoutChanged: () => {

				// A layout chosen in the list replaces the automatic one.
				this.viewer.settings.automatic = false;
				this.gui?.controllersRecursive().forEach( ( controller ) => controller.updateDisplay() );
				this.showLayout();

			},
			automatic: this.automatic ? { name: this.automatic.name, changed: () => this.showLayout() } : null,
			// Fitting changes how the automatic layout is chosen: fromScene runs again; other layouts are captured again, fitted or not.
			fitChanged: () => ( this.automaticLayout ? this.showLayout() : this.recapture() ),
			interpolationChanged: () => {

				if ( this.viewer.settings.interpolation === 'trilinear' && ! this.trilinear ) {

					this.viewer.settings.interpolation = 'tetrahedral';
					this.viewer.overlay.notice( 'Trilinear interpolation needs a grid layout.' );

				}

				this.rebuildKeepingLight();

			},
			recapture: () => this.recapture(),
			rebuildVolume: () => this.rebuildKeepingLight(),
			guardChanged: () => this.applyGuard(),
			editChanged: () => this.editing.select( - 1 ),
			addProbe: () => this.editing.addProbe(),
			removeSelectedProbe: () => this.editing.removeSelectedProbe(),
			exportLayout: () => this.editing.exportLayout(),
			// A baked file (float16 SH) of the volume, to load with `?volume=`.
			exportBaked: () => {

				const file = new LightProbeVolumeExporter().parse( this.volume, { precision: 'float16' } );
				download( fileName( this.layout.name, 'lpv' ), file, 'application/octet-stream' );

			},
		}, this.viewer.rendererChoice );

	}

}
