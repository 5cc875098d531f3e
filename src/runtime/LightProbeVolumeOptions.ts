/*
 * The option types of `LightProbeVolume`: its constructor, capture (with bounces), sample, addProbe
 * and add.
 */
import type { Layers, Mesh, Object3D, Vector3 } from 'three';
import type { ProbeCaptureOptions, ProbeCaptureSettings } from '../capture/ProbeCapturer.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import type { TriangleBVH } from '../geometry/TriangleBVH.js';
import type { ProbeRole } from '../roles.js';
import type { CaptureProgressCallback } from './captureProbes.js';
import type { LightProbeVolumeFitOptions } from './fitVolume.js';
import type { ProbeZoneDefinition } from './ProbeZones.js';
import type { VisibilityGuard, VisibilityGuardOptions } from './VisibilityGuard.js';

export type { ProbeRole } from '../roles.js';

/** What `LightProbeVolume` accepts as occluders: a ready guard, a BVH, a triangle array, or static three.js objects. */
export type ProbeOccluders = VisibilityGuard | TriangleBVH | ArrayLike<number> | Object3D | readonly Object3D[];

/** Constructor argument of `LightProbeVolume`. */
export interface LightProbeVolumeParameters {

	/**
	 * Flat x, y, z per probe, each |coordinate| ≤ 1e18 (`POSITION_LIMIT`; docs/format.md). 4 not all
	 * in one plane give a 3D volume; coplanar probes a planar one; fewer than 3 distinct, or
	 * collinear ones, interpolate along their line.
	 */
	positions: ArrayLike<number>;

	/**
	 * 27 floats per probe, three.js `SphericalHarmonics3` layout, each |value| ≤ 1e30 (`SH_LIMIT`:
	 * blends and irradiance matrices then stay finite in float32); zeros (black) when omitted.
	 */
	sh?: ArrayLike<number>;

	/**
	 * Gradient probes: 81 floats per probe, `gradients[ 81·i + 27·a + k ]` = ∂(SH float k)/∂(axis a), e.g. fitted with
	 * `fitProbeSH`; each |value| ≤ 1e30 / the probes' bounding-box diagonal. Every blend is then
	 * Σ wᵢ · (cᵢ + Gᵢ · (q − pᵢ)) at its point q (see `LightProbeVolume.gradients`). Default: none, plain probes.
	 */
	gradients?: ArrayLike<number>;

	/** Optional name per probe: any strings UTF-8 can hold. */
	names?: readonly string[];

	/** Optional role per probe; default `'fill'`. */
	roles?: readonly ProbeRole[];

	/**
	 * How positions are turned into weights. Default: a `TetrahedralMesh` of the positions
	 * (a `PlanarMesh` when they are coplanar). Pass a `GridInterpolator` built over
	 * the same positions for the paper's trilinear baseline.
	 */
	interpolator?: ProbeInterpolator;

	/**
	 * Lighting zones: named groups of probes with their own tetrahedralization (e.g. one per room),
	 * so an object blends only its zone's probes and light does not leak through the walls between
	 * zones. Objects are assigned with `add( object, { zone } )` or by the zones' `bounds`; objects
	 * outside every zone's bounds use the whole volume. Each zone is tetrahedralized on its own
	 * (a planar triangulation when its probes are coplanar), whatever `interpolator` is. See
	 * {@link ProbeZoneDefinition}.
	 */
	zones?: readonly ProbeZoneDefinition[];

	/**
	 * Static geometry for the visibility guard (see `LightProbeVolume.setOccluders`): probes
	 * whose segment to an object passes through it do not light that object.
	 */
	occluders?: ProbeOccluders;

	/** Options of the visibility guard built from `occluders` (ignored when it is a `VisibilityGuard`). */
	guard?: VisibilityGuardOptions;

}

/** A world position as `LightProbeVolume.sample`, `moveProbe` and `addProbe` take it: `{ x, y, z }` (e.g. a `Vector3`) or `[ x, y, z ]`. */
export type ProbePosition = Vector3 | { x: number; y: number; z: number } | ArrayLike<number>;

/** Options of `LightProbeVolume.sample`. */
export interface SampleOptions {

	/** Sample this zone's probes; default: the zone whose bounds contain the position, else the whole volume. */
	zone?: string;

}

/**
 * The bounce options of `LightProbeVolume.capture` (and `captureBounces`): with `bounces` > 0 the
 * capture is repeated with the static meshes lit per vertex by the previous pass's probes.
 */
export interface LightProbeVolumeBounceOptions {

	/**
	 * Bounces of diffuse interreflection to add, 0..16: `bounces + 1` captures in all (see
	 * `captureBounces`). Default: none, one ordinary capture.
	 */
	bounces?: number;

	/**
	 * The static meshes lit by the previous pass's probes during the bounce passes. Default: every
	 * visible `Mesh` of the scene with a material that takes probe light (Standard, Physical, Phong,
	 * Lambert, Toon) that the capture would draw — not skinned or instanced, not inside an object
	 * registered with `volume.add()` or listed in `exclude`, not rejected by `filter`, on a layer
	 * the cube camera sees, and with no probe-patched material already (such a mesh has probe
	 * light of its own).
	 * The scenery this volume lights itself (what `add( scene )` registered, large objects) takes
	 * the previous pass's light through its own lighting instead.
	 */
	staticMeshes?: readonly Mesh[];

	/**
	 * Objects hidden during the bounce passes (pass ≥ 1) only: the scene's stand-ins for indirect
	 * light — an `AmbientLight` or `HemisphereLight` fill, a faint emissive "ambient" glow — which
	 * the computed bounces replace. Pass 0 is captured with them, as an ordinary capture would be.
	 * To have no stand-in in any pass, turn it off before calling (or use `exclude`).
	 */
	hideInBounces?: Iterable<Object3D>;

	/**
	 * What the static meshes' vertices store during the bounce passes (see
	 * `ProbeVertexLightingOptions.output`): `'irradiance'` (default, 12 bytes a vertex, normal and
	 * bump maps do not change the probe light) or `'sh'` (112 bytes a vertex, per-pixel normals).
	 * In Sibenik (bump-mapped stone) both give the same bounce (+78.6 % in the nave after one pass).
	 */
	output?: 'irradiance' | 'sh';

	/**
	 * Called after each pass with the pass number (0 = direct light only) and the SH of every probe
	 * after that pass — a staged array, overwritten by the next pass: copy it to keep it. The
	 * volume's own `sh` receive the last pass only when every pass is done (a capture is all or
	 * nothing). During the call the static meshes still carry the light that pass was captured
	 * with (none in pass 0); a throwing callback fails the capture.
	 */
	onPass?: ( pass: number, sh: Float32Array ) => void;

}

/** Options of `LightProbeVolume.capture`: capture settings plus per-call options, bounces and the fit. */
export interface LightProbeVolumeCaptureOptions
	extends ProbeCaptureSettings, Omit<ProbeCaptureOptions, 'exclude' | 'onProgress'>, LightProbeVolumeBounceOptions {

	/**
	 * Called after each probe with the number done and the total of its stage: `'probes'` (each
	 * pass), then `'fit'` (the fit points of `fit`).
	 */
	onProgress?: CaptureProgressCallback;

	/**
	 * Capture extra points after the probes (`samples`, or a grid at `spacing` over the probes' hull
	 * in open space) and fit the probes' SH — and with `gradients: true` a gradient per probe — so
	 * the blended field matches them (`fitProbeSH`; see {@link LightProbeVolumeFitOptions}); sets
	 * `sh`, `gradients` and `fitSettings`. Not taken with zones.
	 */
	fit?: LightProbeVolumeFitOptions;

	/**
	 * More objects to hide during the capture; objects lit as `'dynamic'` (`add( object )` in mode
	 * `'object'`, what `add( scene )` finds moving) are always hidden.
	 */
	exclude?: Iterable<Object3D>;

	/** Capture only these probes (e.g. the one an artist just moved); the others keep their SH. */
	indices?: ArrayLike<number>;

	/**
	 * Settings per probe role, over the common ones: e.g. `{ sky: { far: 5000 }, bounce: { far: 20 } }`
	 * (paper 3.4: sky, bounce and object-reflection captures need different ranges and layers).
	 */
	roles?: Partial<Record<ProbeRole, ProbeCaptureSettings & { layers?: Layers }>>;

	/**
	 * De-ringing window strength in [0, 1] applied to each captured probe (see `windowSHFactors`:
	 * 0 = none, 0.1 light, 1/3 strong blur). Default 0.
	 */
	deringing?: number;

	/**
	 * Guarantee that every captured probe's irradiance is ≥ 0 in every direction, by raising the
	 * de-ringing strength of the probes that need it (see `makeIrradianceNonNegative`); blends of
	 * such probes are then ≥ 0 too. Default false.
	 */
	nonNegative?: boolean;

}

/** Options of `LightProbeVolume.addProbe`. */
export interface AddProbeOptions {

	/** The new probe's name. Default ''. */
	name?: string;

	/** The new probe's role. Default `'fill'`. */
	role?: ProbeRole;

	/**
	 * Its SH (27 floats, each |value| ≤ 1e30), e.g. captured elsewhere; the probe is then not marked dirty. Default: the
	 * SH interpolated at its position from the probes around it before it was added (so the
	 * picture does not change until it is captured), and the probe is marked dirty.
	 */
	sh?: ArrayLike<number>;

}

/**
 * Options of `LightProbeVolume.add`. Probe light goes into `MeshStandardMaterial`,
 * `MeshPhysicalMaterial`, `MeshPhongMaterial` (what OBJLoader and MTLLoader make),
 * `MeshLambertMaterial` and `MeshToonMaterial`; other materials are left as they are.
 */
export interface AddOptions {

	/** Shade this object's irradiance per vertex instead of per pixel. Default false. */
	perVertex?: boolean;

	/** Probe light scale for this object's materials. Default 1. */
	intensity?: number;

	/**
	 * Where the object samples the probes, in its local frame. Default: the centre of its bounding
	 * box when added — a character's origin is usually at its feet, below the probes meant for it.
	 * Not taken in `'auto'` mode (each object samples at its own centre).
	 */
	anchor?: Vector3 | { x: number; y: number; z: number };

	/**
	 * The lighting zone (by name) that lights this object, whatever its position. Default: the zone
	 * whose bounds contain the object's anchor, re-checked every `update()`; outside all of them,
	 * the whole volume.
	 */
	zone?: string;

	/**
	 * How the object is lit:
	 * - `'object'` (default, except for a `Scene`): one blend of the probes at the object's anchor,
	 *   updated every frame — for characters, props, anything that moves.
	 * - `'vertex'`: the probe field sampled at every vertex (see `ProbeVertexLighting`) — for large
	 *   static or rarely moved meshes (floors, long walls) that one colour would flatten.
	 * - `'texture'`: the field resampled into a 3D SH texture over the object's bounds and read per
	 *   pixel (see `ProbeTextureLighting`) — for large objects whose tessellation is coarse.
	 * - `'auto'` (default for a `Scene`): a whole level — every mesh below the object not lit yet,
	 *   each in the mode that suits it (see {@link ProbeLighting}); `choose` and
	 *   `userData.probeLighting` override it per object. Meshes whose materials take no probe
	 *   light are skipped: unlit ones (`MeshBasicMaterial`, `MeshNormalMaterial`,
	 *   `MeshMatcapMaterial`) silently, those with their own shaders (`ShaderMaterial`, node
	 *   materials) with one `console.warn` per call that counts them (mark them `'none'` to
	 *   silence it).
	 *
	 * Vertex and texture modes sample the volume per vertex / texel, each point in the zone whose
	 * bounds hold it (or the `zone` given), without the visibility guard,
	 * and their objects stay visible in captures (they are scene, not visitors), their probe light
	 * switched off meanwhile so probes see them as built; capture's `bounces` adds their bounces.
	 */
	mode?: 'object' | 'vertex' | 'texture' | 'auto';

	/**
	 * `'auto'` mode: how to light an object below the root, asked for every object (groups too,
	 * parents before children) before its `userData.probeLighting` is read. Return a
	 * {@link ProbeLightingChoice} (a mark on a group lights the group as one object, as
	 * `add( group, { mode } )` would; `'none'` leaves it and everything below it unlit), or
	 * undefined to leave the choice to the mark or the automatic rule.
	 */
	choose?: ( object: Object3D ) => ProbeLightingChoice | undefined;

	/**
	 * Whether `capture()` hides the object. Default: true in `'object'` mode (a visitor must not
	 * light the probes it is lit by), false in the large-object modes (scenery). A static object lit
	 * in `'object'` mode (a statue) can pass false to stay in the probes' view. Not taken in
	 * `'auto'` mode, which hides what it lights as `'dynamic'` and nothing else.
	 */
	hideInCaptures?: boolean;

	/** `'vertex'` mode: store per-vertex irradiance (default) or per-vertex SH (normal maps respond). */
	vertexOutput?: 'irradiance' | 'sh';

	/** `'texture'` mode: world size of a texel (default: the longest side / 31). */
	texelSize?: number;

	/** `'texture'` mode: largest texel count per axis (default 64). */
	maxResolution?: number;

}

/**
 * How `add( scene )` (mode `'auto'`) lights an object, and what `LightProbeVolume.getLighting`
 * reports:
 * - `'dynamic'`: one blend per object, every frame, and hidden in captures (it must not light the
 *   probes it is lit by) — characters, vehicles, anything that moves. Chosen for skinned meshes
 *   and meshes below a `Bone`; a rig whose skinned meshes and bones share a root with nothing
 *   else below it is one object (one blend at its centre, as `add( character )` gives).
 * - `'object'`: one blend per object, part of the scenery: seen by captures, blended when added
 *   and again only when it moves or the probes change — props no longer than the probe spacing.
 * - `'vertex'`: the field per vertex — static meshes larger than the probe spacing whose
 *   triangles are at most half the spacing long.
 * - `'texture'`: the field per pixel from a 3D SH texture over the mesh — static meshes larger
 *   than the probe spacing, coarsely tessellated (a floor of two triangles).
 */
export type ProbeLighting = 'dynamic' | 'object' | 'vertex' | 'texture';

/**
 * A mark for `add( scene )`: in `object.userData.probeLighting` (a glTF node's `extras`, a DCC
 * custom property) or returned by the `choose` option. `'auto'` (or no mark) leaves the choice to
 * the automatic rule; `'none'` leaves the object and everything below it unlit.
 */
export type ProbeLightingChoice = ProbeLighting | 'auto' | 'none';
