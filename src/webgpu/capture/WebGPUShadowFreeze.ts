import type { Light, LightShadow, Object3D } from 'three/webgpu';

/**
 * `ShadowMapFreeze` for `WebGPURenderer`: its shadow maps are drawn per light (`light.shadow.autoUpdate`
 * / `needsUpdate`, read by three's ShadowNode; `renderer.shadowMap` has no `autoUpdate`), so the
 * freeze sets every shadow-casting light of the scene to draw its map once, at the capture's first
 * face, and reuse it for every face and probe after; each light's flags are restored at the end. A
 * redraw asked for while the capture yields (`shadow.needsUpdate = true`) is drawn for the capture
 * and still pending after it. Lights added to the scene during the capture are not frozen.
 */
export class WebGPUShadowFreeze {

	private readonly saved = new Map<LightShadow, { autoUpdate: boolean; needsUpdate: boolean; requested: boolean; atPause: boolean }>();

	/** Freezes the shadow maps of `scene`'s shadow-casting lights (when `enabled`, i.e. `renderer.shadowMap.enabled`). */
	begin( scene: Object3D, enabled: boolean ): void {

		if ( this.saved.size > 0 || ! enabled ) return;
		scene.traverse( ( object ) => {

			const light = object as Light & { shadow?: LightShadow };
			const shadow = light.shadow;
			if ( light.isLight !== true || light.castShadow !== true || ! shadow || this.saved.has( shadow ) ) return;
			this.saved.set( shadow, { autoUpdate: shadow.autoUpdate, needsUpdate: shadow.needsUpdate, requested: false, atPause: false } );
			shadow.autoUpdate = false;
			shadow.needsUpdate = true;

		} );

	}

	/** Call before the capture yields to the page. */
	pause(): void {

		for ( const [ shadow, state ] of this.saved ) state.atPause = shadow.needsUpdate;

	}

	/** Call when the capture goes on after a yield: a redraw asked for meanwhile is drawn now and kept for after. */
	resume(): void {

		for ( const [ shadow, state ] of this.saved ) {

			if ( shadow.needsUpdate && ! state.atPause ) state.requested = true;
			shadow.autoUpdate = false;

		}

	}

	/** Restores every frozen light's `autoUpdate` and `needsUpdate` (also when the capture throws). */
	end(): void {

		for ( const [ shadow, state ] of this.saved ) {

			shadow.autoUpdate = state.autoUpdate;
			shadow.needsUpdate = state.needsUpdate || state.requested;

		}

		this.saved.clear();

	}

}
