/**
 * What the Node side of `capture-lighting bake` (cli/capture.ts) and the bake page (page.ts)
 * exchange through puppeteer. Types only.
 */

/** One bake, as the page runs it. */
export interface BakeRequest {

	/** URL of the scene file, in a folder served as it is on disk (so .mtl, .bin and textures next to it load). */
	sceneUrl: string;

	/** Which loader reads it. */
	kind: 'gltf' | 'obj';

	/** Flat x, y, z per probe. */
	positions: number[];

	/** Cube face size in texels. */
	resolution: number;

	near: number;
	far: number;

	/** What the captures see at infinity: an sRGB colour (components 0..1), an equirectangular .hdr URL, or black. */
	sky: { color: [ number, number, number ] } | { hdrUrl: string } | null;

	/** A directional light with shadows, from `direction` (towards the sun). */
	sun: { direction: [ number, number, number ]; intensity: number } | null;

	/** Intensity of a white ambient light; 0 for none. */
	ambient: number;

}

/** What the page returns. */
export interface BakeResult {

	/** 27 floats per probe (Float32, little-endian bytes as base64). */
	sh: string;

	/** Time of the capture itself, shader compilation included, in ms. */
	captureMs: number;

	/** Time to load the scene, in ms. */
	loadMs: number;

	/**
	 * Facts for the summary. `nonFiniteVertices` counts vertex positions with a NaN or infinite
	 * coordinate; when it is not 0, or the scene has no triangles and no sky, the page skips the capture
	 * (`sh` is empty) and the CLI reports bad input.
	 */
	info: { renderer: string; meshes: number; triangles: number; lights: number; shadows: boolean; nonFiniteVertices: number };

}

/** The page's entry points (`window.bake`). */
export interface BakePageApi {

	run( request: BakeRequest ): Promise<BakeResult>;

}

/** Name of the function the Node side exposes to the page for progress: ( stage, done, total ). */
export const PROGRESS_FUNCTION = '__captureLightingProgress';
