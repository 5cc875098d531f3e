import * as THREE from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import type { LightProbeVolume } from 'three-capture-lighting';
import { download, fileName } from './download.js';
import type { ProbeLayout } from './layouts.js';
import type { ProbeMarkers } from './ProbeMarkers.js';
import type { Viewer } from './Viewer.js';

/** What probe editing changes: the shown layout and its volume (a `ProbeVolumeDemo`). */
export interface EditableVolume {

	/** The tetrahedral volume shown. */
	readonly volume: LightProbeVolume;
	/** The layout shown (edited in place). */
	readonly layout: ProbeLayout;
	/** A new volume for the (edited) layout with these SH. */
	rebuildVolume( sh?: Float32Array ): void;
	/** Captures these probes again (and redraws the markers). */
	recapture( indices?: number[] ): Promise<void>;
	/** Redraws the markers and cells without a capture. */
	updateMarkers(): void;

}

/**
 * Live probe editing on a scene page, while the panel's "edit" is on: click a probe marker to
 * select it, drag it with the transform gizmo; add a probe at the orbit target, delete the
 * selected one, export the layout as JSON. Only the edited probe is captured again.
 */
export class ProbeEditing {

	private readonly viewer: Viewer;
	private readonly target: EditableVolume;
	private readonly markers: ProbeMarkers;
	private readonly transform: TransformControls;
	private selected = - 1;

	/** Adds the transform gizmo to `viewer.helpers` and listens for clicks on the canvas. */
	constructor( viewer: Viewer, target: EditableVolume, markers: ProbeMarkers ) {

		this.viewer = viewer;
		this.target = target;
		this.markers = markers;
		this.transform = new TransformControls( viewer.camera, viewer.renderer.domElement );
		this.transform.addEventListener( 'dragging-changed', ( event ) => {

			viewer.controls.enabled = ! event.value;
			if ( ! event.value ) this.moveSelectedProbe();

		} );
		viewer.helpers.add( this.transform.getHelper() );
		viewer.renderer.domElement.addEventListener( 'pointerdown', ( event ) => this.pick( event ) );

	}

	/** Selects probe `index` for dragging (−1: none). */
	select( index: number ): void {

		this.selected = index;
		const marker = this.markers.markerOf( index );
		if ( marker && this.viewer.settings.edit ) this.transform.attach( marker ); else this.transform.detach();

	}

	/** After a drag: the moved probe's cells are updated and the probe alone is captured again. */
	async moveSelectedProbe(): Promise<void> {

		const index = this.selected, target = this.target;
		const marker = this.markers.markerOf( index );
		if ( index < 0 || ! marker ) return;
		const layout = target.layout, positions = layout.positions, inPlace = this.editsInPlace;
		try {

			if ( inPlace ) target.volume.moveProbe( index, marker.position );
			const previous = positions.slice( 3 * index, 3 * index + 3 );
			marker.position.toArray( positions, 3 * index );
			if ( ! inPlace ) {

				delete layout.grid; // no longer a regular grid
				try {

					target.rebuildVolume( target.volume.sh.slice() );

				} catch ( error ) {

					positions.splice( 3 * index, 3, ...previous );
					target.rebuildVolume( target.volume.sh.slice() );
					throw error;

				}

			}

		} catch ( error ) {

			this.viewer.overlay.notice( `Cannot move the probe there: ${( error as Error ).message}` );
			marker.position.fromArray( positions, 3 * index );
			return;

		}

		await target.recapture( [ index ] );
		this.select( index );

	}

	/** Adds a probe at the orbit target and captures it. */
	async addProbe(): Promise<void> {

		const target = this.target, layout = target.layout, point = this.viewer.controls.target;
		const name = `probe ${layout.positions.length / 3 + 1}`, inPlace = this.editsInPlace;
		let index: number;
		if ( inPlace ) {

			index = target.volume.addProbe( point, { name, role: 'fill' } );

		} else {

			const sh = new Float32Array( target.volume.sh.length + 27 );
			sh.set( target.volume.sh );
			delete layout.grid;
			layout.positions.push( ...point.toArray() );
			layout.names?.push( name );
			layout.roles?.push( 'fill' );
			target.rebuildVolume( sh );
			index = target.volume.count - 1;

		}

		if ( inPlace ) {

			layout.positions.push( ...point.toArray() );
			layout.names?.push( name );
			layout.roles?.push( 'fill' );

		}

		await target.recapture( [ index ] );
		this.select( index );

	}

	/** Deletes the selected probe (a new volume without it; the other probes keep their SH). */
	async removeSelectedProbe(): Promise<void> {

		const index = this.selected, target = this.target, layout = target.layout;
		if ( index < 0 ) { this.viewer.overlay.notice( 'Select a probe first (turn on editing and click one).' ); return; }
		this.select( - 1 );
		const sh = new Float32Array( target.volume.sh.length - 27 );
		sh.set( target.volume.sh.subarray( 0, 27 * index ) );
		sh.set( target.volume.sh.subarray( 27 * ( index + 1 ) ), 27 * index );
		const saved = layout.positions.splice( 3 * index, 3 );
		try {

			layout.names?.splice( index, 1 );
			layout.roles?.splice( index, 1 );
			delete layout.grid;
			delete layout.zones; // its probe indices shifted
			target.rebuildVolume( sh );
			target.updateMarkers();

		} catch ( error ) {

			layout.positions.splice( 3 * index, 0, ...saved );
			this.viewer.overlay.notice( `Cannot delete that probe: ${( error as Error ).message}` );

		}

	}

	/** Downloads the shown layout as JSON (positions rounded to mm). */
	exportLayout(): void {

		const { name, positions, names, roles } = this.target.layout;
		const rounded = positions.map( ( v ) => Math.round( v * 1000 ) / 1000 );
		const json = JSON.stringify( { name, positions: rounded, names, roles }, null, '\t' );
		download( fileName( name, 'json' ), json, 'application/json' );

	}

	/**
	 * Whether probe edits can update the volume in place (`moveProbe` / `addProbe`: the
	 * tetrahedralization changes locally, only the edited probe is captured again). A grid layout's
	 * first edit and volumes with zones are rebuilt instead.
	 */
	private get editsInPlace(): boolean {

		return ! this.target.layout.grid && ! this.target.volume.zones;

	}

	private pick( event: PointerEvent ): void {

		if ( ! this.viewer.settings.edit || this.transform.dragging ) return;
		const rect = this.viewer.renderer.domElement.getBoundingClientRect();
		const pointer = new THREE.Vector2(
			( ( event.clientX - rect.left ) / rect.width ) * 2 - 1,
			- ( ( event.clientY - rect.top ) / rect.height ) * 2 + 1,
		);
		const raycaster = new THREE.Raycaster();
		raycaster.setFromCamera( pointer, this.viewer.camera );
		const hit = raycaster.intersectObjects( this.markers.markers.children, false )[ 0 ];
		if ( hit ) this.select( hit.object.userData.probe as number );

	}

}
