import GUI from 'lil-gui';
import { VIEWS, type DemoSettings } from './queryParameters.js';
import type { ProbeLayout } from './layouts.js';
import { addRendererSwitch, type RendererChoice } from './rendererChoice.js';

/** What the panel's controls do (besides editing `DemoSettings`). */
export interface PanelActions {

	/** Another layout was chosen: a new volume, captured. */
	layoutChanged(): void;
	/** Tetrahedral ↔ trilinear. */
	interpolationChanged(): void;
	/** Captures every probe again. */
	recapture(): void;
	/** A setting of the interpolation changed (outside the hull, zones): a new volume, same SH. */
	rebuildVolume(): void;
	/** The visibility guard was switched. */
	guardChanged(): void;
	/** "automatic layout (budget N)" (pages that have it, else null): its label, and what to do when switched. */
	automatic: { name: string; changed(): void } | null;
	/** "fit to dense captures" was switched. */
	fitChanged(): void;
	/** Editing was switched on or off. */
	editChanged(): void;
	/** The edit folder's buttons. */
	addProbe(): void;
	removeSelectedProbe(): void;
	exportLayout(): void;
	exportBaked(): void;

}

/**
 * The lil-gui panel of a scene page: the renderer (a reload with `?renderer=`), layout,
 * interpolation, view mode, capture resolution, what is drawn, the features beyond the paper and
 * probe editing. Pages add their own controls.
 */
export function createPanel( settings: DemoSettings, layouts: ProbeLayout[], actions: PanelActions, renderer: RendererChoice ): GUI {

	const gui = new GUI();
	addRendererSwitch( gui, renderer );
	gui.add( settings, 'layout', layouts.map( ( layout ) => layout.name ) ).onChange( () => actions.layoutChanged() );
	gui.add( settings, 'interpolation', [ 'tetrahedral', 'trilinear' ] ).onChange( () => actions.interpolationChanged() ).listen();
	gui.add( settings, 'view', VIEWS );
	gui.add( settings, 'resolution', [ 8, 16, 32, 64, 128 ] ).name( 'capture resolution' ).onChange( () => actions.recapture() );
	gui.add( { recapture: () => actions.recapture() }, 'recapture' );
	gui.add( settings, 'showProbes' ).name( 'show probes' );
	gui.add( settings, 'showCells' ).name( 'show tetrahedra' );
	gui.add( settings, 'animate' );

	const beyond = gui.addFolder( 'beyond the paper' );
	const outside = { 'outer cells': 'outerCells', 'nearest face': 'nearestFace' };
	beyond.add( settings, 'outside', outside ).name( 'outside the hull' ).onChange( () => actions.rebuildVolume() );
	beyond.add( settings, 'guard' ).name( 'no light through walls' ).onChange( () => actions.guardChanged() );
	if ( layouts.some( ( layout ) => layout.zones ) ) {

		beyond.add( settings, 'zones' ).name( 'lighting zones' ).onChange( () => actions.rebuildVolume() );

	}

	beyond.add( settings, 'deringing', 0, 0.5, 0.01 ).name( 'de-ringing strength' ).onFinishChange( () => actions.recapture() );
	beyond.add( settings, 'nonNegative' ).name( 'irradiance never negative' ).onChange( () => actions.recapture() );
	beyond.add( settings, 'bounces', 0, 3, 1 ).name( 'diffuse bounces' ).onFinishChange( () => actions.recapture() );
	if ( actions.automatic ) {

		// Issue 14: a layout chosen by LightProbeVolume.fromScene, and probes fitted to dense captures.
		const automatic = actions.automatic;
		beyond.add( settings, 'automatic' ).name( automatic.name ).onChange( () => automatic.changed() ).listen();
		beyond.add( settings, 'fit' ).name( 'fit to dense captures' ).onChange( () => actions.fitChanged() );

	}

	const edit = gui.addFolder( 'edit probes' );
	edit.add( settings, 'edit' ).name( 'click a probe to move it' ).onChange( () => actions.editChanged() );
	edit.add( { add: () => actions.addProbe() }, 'add' ).name( 'add probe at target' );
	edit.add( { remove: () => actions.removeSelectedProbe() }, 'remove' ).name( 'delete selected probe' );
	edit.add( { export: () => actions.exportLayout() }, 'export' ).name( 'export layout JSON' );
	edit.add( { export: () => actions.exportBaked() }, 'export' ).name( 'export baked volume (.lpv)' );
	// On a narrow page the open panel would cover the title (main.css moves the title under it).
	if ( window.innerWidth < 900 ) gui.close();
	return gui;

}
