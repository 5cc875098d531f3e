import type { ProbeRole } from '../roles.js';

/*
 * The shapes of a baked light probe volume: what the encoders accept, what the decoders return,
 * and the JSON form (docs/format.md).
 */

/** Role of a probe: the same strings as {@link ProbeRole}. */
export type BakedProbeRole = ProbeRole;

/** Capture settings of one role (the stored subset of `ProbeCaptureSettings`). */
export interface BakedCaptureSettings {

	/** Cube face edge in texels, an integer ≥ 1. */
	resolution?: number;

	/** Near plane, > 0. */
	near?: number;

	/** Far plane, > near. */
	far?: number;

	/** Render target type the capture used. */
	type?: 'half' | 'float';

	/** Texel solid-angle formula of the projection. */
	solidAngle?: 'exact' | 'paper';

}

/** Capture settings a volume was baked with: the common ones plus overrides per role. */
export interface BakedCapture extends BakedCaptureSettings {

	/** Settings per role, over the common ones. */
	roles?: Partial<Record<BakedProbeRole, BakedCaptureSettings>>;

}

/** A named group of probes, with optional boxes where it applies. */
export interface BakedZone {

	/** Zone name. */
	name: string;

	/** Indices of the zone's probes. */
	probes: Uint32Array;

	/** Boxes, 6 floats each: min x, y, z, max x, y, z (empty when the zone has none). */
	bounds: Float64Array;

}

/**
 * How a volume's SH were fitted (docs/format.md, "FITS"): the record of a least-squares fit of the
 * probes' SH (and gradients) to extra captured points, stored with the bake.
 */
export interface BakedFit {

	/** Number of fit samples, an integer ≥ 0. */
	samples: number;

	/** Whether gradients were fitted too. */
	gradients: boolean;

	/** Strength of the pull toward each probe's captured SH (scale-free), ≥ 0. */
	lambda: number;

	/** Strength of the pull toward zero gradient (scale-free), ≥ 0; 0 without gradients. */
	gradientLambda: number;

	/** Mean `irradianceError` (a fraction of the mean irradiance) over the held-out folds at the chosen λ; null when λ were given. */
	crossValidationError: number | null;

	/** Free text: how the samples were made, e.g. 'dense captures at spacing 0.5'. */
	source?: string;

}

/**
 * A baked volume, as {@link decodeBakedVolume} and {@link bakedVolumeFromJSON} return it: every
 * field present and valid.
 */
export interface BakedVolumeData {

	/** x, y, z per probe, float64: the tetrahedra are valid for exactly these coordinates. */
	positions: Float64Array;

	/** 27 floats per probe, three.js `SphericalHarmonics3` order (coefficient k's r, g, b at 3k..3k+2). */
	sh: Float32Array;

	/** 4 probe indices per tetrahedron, positively oriented; empty when none is stored. */
	tetrahedra: Uint32Array;

	/** `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i, or −1 on the hull. */
	neighbors: Int32Array;

	/** Name per probe ('' when none). */
	names: string[];

	/** Role per probe. */
	roles: BakedProbeRole[];

	/** Named groups of probes. */
	zones: BakedZone[];

	/** The volume's box: min x, y, z, max x, y, z (the positions' box unless given). */
	bounds: Float64Array;

	/** Capture settings the SH were baked with ({} when unknown). */
	capture: BakedCapture;

	/** Free-form text, e.g. the tool and scene that produced the bake ('' when none). */
	metadata: string;

	/**
	 * Spatial SH gradient per probe, 81 floats: `gradients[ 81 * i + 27 * a + k ]` = ∂(SH float k)/∂(axis a),
	 * a = 0 x, 1 y, 2 z; null for plain probes (and in files written before version 1.1).
	 */
	gradients: Float32Array | null;

	/** How the SH were fitted; null when they are the captured ones (or unknown). */
	fit: BakedFit | null;

}

/** What {@link encodeBakedVolume} and {@link bakedVolumeToJSON} accept: only positions and SH are required. */
export interface BakedVolumeInput {

	/** x, y, z per probe. Float32 input is widened exactly; the tetrahedra must be valid for the stored values. */
	positions: ArrayLike<number>;

	/** 27 floats per probe. */
	sh: ArrayLike<number>;

	/** 4 indices per tetrahedron (omit for a volume whose reader builds its own interpolator, e.g. a planar one). */
	tetrahedra?: ArrayLike<number>;

	/** 4 per tetrahedron; required with `tetrahedra`. */
	neighbors?: ArrayLike<number>;

	/** Name per probe. */
	names?: readonly string[];

	/** Role per probe; default 'fill'. */
	roles?: readonly BakedProbeRole[];

	/** Named groups of probes. */
	zones?: readonly { name: string; probes: ArrayLike<number>; bounds?: ArrayLike<number> }[];

	/** min x, y, z, max x, y, z; default the positions' box. */
	bounds?: ArrayLike<number>;

	/** Capture settings. */
	capture?: BakedCapture;

	/** Free-form text. */
	metadata?: string;

	/** 81 floats per probe (layout of {@link BakedVolumeData.gradients}); omit or null for plain probes. */
	gradients?: ArrayLike<number> | null;

	/** How the SH were fitted; omit or null when they are the captured ones. */
	fit?: BakedFit | null;

}

/** Options of {@link encodeBakedVolume}. */
export interface EncodeBakedVolumeOptions {

	/**
	 * Storage of the SH: `'float16'` halves the SH bytes (relative error ≤ 2^−11 for values above
	 * 6.1e−5; throws a `'float16-overflow'` error for values beyond ±65504) or `'float32'` (exact).
	 * Default `'float32'`.
	 */
	precision?: 'float16' | 'float32';

}

/** The JSON form of a baked volume (docs/format.md, "JSON form"): the binary sections as arrays. */
export interface BakedVolumeJSON {

	/** Always `BAKED_VOLUME_JSON_FORMAT` (bakedVolumeFormat.ts). */
	format: string;

	/** [ major, minor ]. */
	version: [ number, number ];

	/** Number of probes (checked against `positions` when read). */
	probeCount: number;

	/** Number of tetrahedra (checked against `tetrahedra` when read). */
	tetrahedronCount: number;

	/** x, y, z per probe. */
	positions: number[];

	/** 27 per probe, three.js `SphericalHarmonics3` order. */
	sh: number[];

	/** 4 probe indices per tetrahedron. */
	tetrahedra: number[];

	/** 4 per tetrahedron, −1 on the hull. */
	neighbors: number[];

	/** Name per probe. */
	names: string[];

	/** Role per probe. */
	roles: BakedProbeRole[];

	/** Zones; `bounds` flat, 6 numbers per box. */
	zones: { name: string; probes: number[]; bounds: number[] }[];

	/** min x, y, z, max x, y, z. */
	bounds: number[];

	/** Capture settings. */
	capture: BakedCapture;

	/** Free-form text. */
	metadata: string;

	/** 81 per probe (version ≥ 1.1; absent for plain probes). */
	gradients?: number[];

	/** How the SH were fitted (version ≥ 1.1; absent when not fitted). */
	fit?: BakedFit;

}
