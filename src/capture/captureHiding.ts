import type { Object3D, Scene } from 'three';

/** What {@link hideForCapture} hides: the `exclude` and `filter` of a capture call (`ProbeCaptureOptions`). */
export interface CaptureHidingOptions {

	/** Objects hidden while capturing. */
	exclude?: Iterable<Object3D>;

	/** Objects for which this returns false are hidden while capturing. */
	filter?: ( object: Object3D ) => boolean;

}

/**
 * Hides a capture's excluded and filtered-out objects (those visible now) and returns them, so
 * {@link showAfterCapture} can show exactly those again. Shared by the WebGL and WebGPU capturers.
 */
export function hideForCapture( scene: Scene, options: CaptureHidingOptions ): Object3D[] {

	const hidden: Object3D[] = [];
	const hideOne = ( object: Object3D ) => {

		if ( object.visible ) { object.visible = false; hidden.push( object ); }

	};

	if ( options.exclude ) for ( const object of options.exclude ) hideOne( object );
	if ( options.filter ) {

		const filter = options.filter;
		scene.traverseVisible( ( object ) => { if ( object !== scene && ! filter( object ) ) hideOne( object ); } );

	}

	return hidden;

}

/** Shows the objects {@link hideForCapture} hid. */
export function showAfterCapture( objects: readonly Object3D[] ): void {

	for ( const object of objects ) object.visible = true;

}

/** Milliseconds from a monotonic clock where there is one (a capture's time between yields). */
export function captureClock(): number {

	return typeof performance !== 'undefined' ? performance.now() : Date.now();

}

/** Yields to the event loop so a page can repaint a progress bar between probes. */
export function nextTask(): Promise<void> {

	return new Promise( ( resolve ) => setTimeout( resolve, 0 ) );

}
