import type * as THREE from 'three';
import type { LightProbeVolume } from 'three-capture-lighting';
import type { DynamicObjects } from './DynamicObjects.js';
import type { AnyRenderer } from './rendererChoice.js';
import type { ProbeVolumeDemo } from './ProbeVolumeDemo.js';
import type { DemoSettings } from './queryParameters.js';
import type { Viewer } from './Viewer.js';

/** What a scene page leaves on `window.__demoApp` for the browser tests and the page benchmarks. */
export interface DemoHandle {

	/** The page's renderer: a WebGLRenderer, or a WebGPURenderer (`?renderer=webgpu|webgl2`). */
	readonly renderer: AnyRenderer;
	readonly camera: THREE.PerspectiveCamera;
	/** The panel's state. */
	readonly params: DemoSettings;
	/** The tetrahedral volume of the layout shown. */
	readonly volume: LightProbeVolume;
	/** The volume lighting the objects (tetrahedral or trilinear). */
	readonly activeVolume: LightProbeVolume;
	/** The probe markers' group (`userData.probe` on each). */
	readonly markers: THREE.Group;
	/** Captures again with `params` (the benchmarks time it). */
	recapture( indices?: number[] ): Promise<void>;
	/** Probe editing, as the panel and the gizmo drive it. */
	select( index: number ): void;
	moveSelectedProbe(): Promise<void>;
	addProbe(): Promise<void>;
	/** The page's layout names. */
	layoutNames(): string[];
	/** The character's and the test ball's boxes on screen, CSS pixels: [ left, top, right, bottom ]. */
	characterScreenBox(): number[];
	ballScreenBox(): number[];

}

/** Sets `window.__demoApp` (see {@link DemoHandle}). */
export function exposeForTests( viewer: Viewer, objects: DynamicObjects, demo: ProbeVolumeDemo ): void {

	const canvas = viewer.renderer.domElement;
	const handle: DemoHandle = {
		renderer: viewer.renderer,
		camera: viewer.camera,
		params: viewer.settings,
		get volume() { return demo.volume; },
		get activeVolume() { return demo.activeVolume; },
		markers: demo.markers.markers,
		recapture: ( indices ) => demo.recapture( indices ),
		select: ( index ) => demo.editing.select( index ),
		moveSelectedProbe: () => demo.editing.moveSelectedProbe(),
		addProbe: () => demo.editing.addProbe(),
		layoutNames: () => demo.layoutNames(),
		characterScreenBox: () => objects.characterScreenBox( viewer.camera, canvas ),
		ballScreenBox: () => objects.ballScreenBox( viewer.camera, canvas ),
	};
	Object.assign( window, { __demoApp: handle } );

}
