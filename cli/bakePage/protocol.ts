/**
 * What the Node side of `capture-lighting bake` (cli/capture.ts) and the bake page (page.ts)
 * exchange through puppeteer. Types only.
 */

import type { CaptureLightKind, CaptureScenePreparation } from '../../src/capture/prepareCaptureScene.js';

/** x, y, z. */
export type Vec3 = [ number, number, number ];

/** Where a light the CLI adds was asked for: `--sun` / `--point` / `--spot` / `--ambient`, or the layout's "lights". */
export type BakeLightSource = 'flags' | 'layout';

/**
 * A light the CLI adds to the scene. Colours are sRGB hex numbers (three's `new Color( 0xrrggbb )`),
 * intensities in three's physical units (lux for directional, candela for point and spot lights),
 * `decay` 2 is physically based (three's default), `distance` 0 means no cut-off, `angle` is the
 * spot's half angle in degrees.
 */
export type BakeLight =
	| { type: 'directional'; direction: Vec3; intensity: number; color: number; source: BakeLightSource }
	| { type: 'point'; position: Vec3; intensity: number; color: number; distance: number; decay: number; source: BakeLightSource }
	| {
		type: 'spot'; position: Vec3; target: Vec3; intensity: number; color: number; distance: number; decay: number;
		angle: number; penumbra: number; source: BakeLightSource;
	};

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

	/** Lights added to the scene's own, in this order (flags first, then the layout's). */
	lights: BakeLight[];

	/** Intensity of a white ambient light (`--ambient`); 0 for none. */
	ambient: number;

	/** What `prepareCaptureScene` does to the scene before the capture. */
	prepare: CaptureScenePreparation;

}

/** A light that lit the capture: its kind and where it came from (`'file'`: the scene file itself). */
export interface BakeLightInfo {

	kind: CaptureLightKind;
	source: 'file' | BakeLightSource;

}

/** Facts about the scene, for the summary and the warnings. */
export interface BakeSceneInfo {

	/** The GPU (SwiftShader's name under headless Chromium). */
	renderer: string;
	meshes: number;
	triangles: number;

	/** Vertex positions with a NaN or infinite coordinate. */
	nonFiniteVertices: number;

	/** The lights that gave light (intensity > 0), file lights included. */
	lights: BakeLightInfo[];

	/** Lit materials with emission, and unlit materials that are not black. */
	emissiveMaterials: number;
	unlitMaterials: number;

	/** What `prepareCaptureScene` changed: shadow-casting lights, meshes casting and receiving, double-sided materials. */
	shadowLights: number;
	shadowMeshes: number;
	doubleSidedMaterials: number;

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
	 * Facts for the summary. When `nonFiniteVertices` is not 0, or the scene has no triangles and no
	 * sky, the page skips the capture (`sh` is empty) and the CLI reports bad input.
	 */
	info: BakeSceneInfo;

}

/** The page's entry points (`window.bake`). */
export interface BakePageApi {

	run( request: BakeRequest ): Promise<BakeResult>;

}

/** Name of the function the Node side exposes to the page for progress: ( stage, done, total ). */
export const PROGRESS_FUNCTION = '__captureLightingProgress';
