import type { WebGLRenderer } from 'three';

/**
 * Draws a renderer's shadow maps once for a whole capture and keeps them for every cube face after
 * it: static scenery does not move while it is captured, and three.js would otherwise draw every
 * shadow map again for each of the six faces of every probe. Frames a page draws while the capture
 * awaits reuse them too. `shadowMap.autoUpdate` and `needsUpdate` are restored at the end; a redraw
 * asked for meanwhile (`needsUpdate = true` from a page or a context-restored handler) is drawn for
 * the capture and is still pending after it.
 *
 * ```js
 * freeze.begin();
 * try {
 * 	// render faces; before each await: freeze.pause(), after it: freeze.resume()
 * } finally {
 * 	freeze.end();
 * }
 * ```
 */
export class ShadowMapFreeze {

	/** The renderer whose shadow maps are frozen. */
	readonly renderer: WebGLRenderer;

	private active = false;
	private savedAutoUpdate = true;
	private savedNeedsUpdate = false;
	private requested = false;
	private needsUpdateAtPause = false;

	/** @param renderer The renderer that draws the capture. */
	constructor( renderer: WebGLRenderer ) {

		this.renderer = renderer;

	}

	/**
	 * Call before the first face: saves the settings and makes the next render draw the shadow maps
	 * and the later ones reuse them. Does nothing when `shadowMap.enabled` is false.
	 */
	begin(): void {

		const shadowMap = this.renderer.shadowMap;
		if ( this.active || ! shadowMap.enabled ) return;
		this.savedAutoUpdate = shadowMap.autoUpdate;
		this.savedNeedsUpdate = shadowMap.needsUpdate;
		this.requested = false;
		this.active = true;
		shadowMap.autoUpdate = false;
		shadowMap.needsUpdate = true;

	}

	/** Call before the capture yields to the page: notes the state, so `resume` can tell a new redraw request. */
	pause(): void {

		if ( this.active ) this.needsUpdateAtPause = this.renderer.shadowMap.needsUpdate;

	}

	/**
	 * Call when the capture goes on after a yield: a `needsUpdate = true` set meanwhile (the scene or
	 * the context changed) is drawn by the next face and kept for after the capture.
	 */
	resume(): void {

		if ( ! this.active ) return;
		const shadowMap = this.renderer.shadowMap;
		if ( shadowMap.needsUpdate && ! this.needsUpdateAtPause ) this.requested = true;
		shadowMap.autoUpdate = false;

	}

	/** Call when the capture ends, also when it throws: restores `autoUpdate` and `needsUpdate`. */
	end(): void {

		if ( ! this.active ) return;
		const shadowMap = this.renderer.shadowMap;
		shadowMap.autoUpdate = this.savedAutoUpdate;
		shadowMap.needsUpdate = this.savedNeedsUpdate || this.requested;
		this.active = false;

	}

}
