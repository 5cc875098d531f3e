/*
 * The defaults of `prepareCaptureScene`, without three.js, so the CLI's argument parser and its
 * `--help` text state the same numbers as the library without loading three.js.
 */

/** What `prepareCaptureScene` does when an option is not given. */
export const CAPTURE_SCENE_DEFAULTS = {

	/** Shadows on for every light that can cast them and every lit mesh. */
	shadows: true,

	/** Shadow map edge of every shadow-casting light, in texels (finer than a capture's cube texels need). */
	shadowMapSize: 1024,

	/** `shadow.bias` of every shadow-casting light. */
	shadowBias: - 0.0005,

	/** Directional lights' shadow cameras fitted around the scene's lit meshes. */
	fitShadowCameras: true,

	/** Materials keep three's shadow side (back faces; both for double-sided materials): no self-shadowing of lit faces. */
	doubleSidedShadows: false,

} as const;
