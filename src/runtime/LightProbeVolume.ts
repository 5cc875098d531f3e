import type { Object3D, Scene, Vector3, WebGLRenderer } from 'three';
import type { CaptureRenderer } from '../capture/captureSettings.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import type { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import type { BakedCapture, BakedFit, BakedVolumeData, BakedVolumeInput } from '../io/index.js';
import type { ProbeRole } from '../roles.js';
import { SH_FLOATS, assertOptions } from '../validate.js';
import {
	assertBakedVolumeParameters, checkBakedData, parametersFromBakedData, toBakedVolumeInput, type BakedVolumeParameters,
} from './bakedVolumeData.js';
import { captureVolume } from './captureBounces.js';
import { CAPTURE_ACCESS, captureAccessOf, type CaptureAccess } from './captureProbes.js';
import type {
	AddOptions, AddProbeOptions, LightProbeVolumeCaptureOptions, LightProbeVolumeParameters, ProbeLighting, ProbeOccluders, ProbePosition,
	SampleOptions,
} from './LightProbeVolumeOptions.js';
import { assertObject3D } from './litObjects.js';
import { LitObjectRegistry } from './LitObjectRegistry.js';
import { ProbeEdits } from './ProbeEdits.js';
import { medianProbeSpacing } from './probeSpacing.js';
import { ProbeWeighting, defaultMoveThreshold, invalidateVisibility } from './ProbeWeighting.js';
import { ProbeZones } from './ProbeZones.js';
import { sampleVolume } from './sampleVolume.js';
import { assertRecaptureArguments, readVolumeParameters } from './volumeArguments.js';
import { VisibilityGuard, type VisibilityGuardOptions } from './VisibilityGuard.js';
import type { FromSceneOptions } from './volumeFromScene.js';
import type { ProbeVolumeUniforms } from './patchMaterial.js';

export type {
	AddOptions, AddProbeOptions, LightProbeVolumeBounceOptions, LightProbeVolumeCaptureOptions, LightProbeVolumeParameters,
	ProbeLighting, ProbeLightingChoice, ProbeOccluders, ProbePosition, ProbeRole, SampleOptions,
} from './LightProbeVolumeOptions.js';

/**
 * Light probes placed anywhere, captured from the scene and blended per object every frame —
 * the paper's pipeline in three.js. Probe positions are tetrahedralized (a planar triangulation
 * when they all lie in one plane); each registered object finds the cell around it, blends its
 * probes' SH with barycentric weights, and its patched material (Standard, Physical, Phong,
 * Lambert, Toon) shades E(n) = nᵀMn from them.
 *
 * ```js
 * const volume = new LightProbeVolume( { positions } );
 * volume.add( character );  // what moves first: hidden in captures, so it does not light its own probes
 * volume.add( scene );      // the level: every other mesh, each in the mode that suits it
 * await volume.capture( renderer, scene, { resolution: 32 } );
 * // each frame:
 * volume.update();
 * renderer.render( scene, camera );
 * ```
 *
 * Against light leaking through walls there are two tools, usable together: lighting `zones`
 * (each room blends only its own probes) and a visibility guard (`occluders` /
 * {@link LightProbeVolume.setOccluders}: a probe whose segment to the object passes through
 * static geometry gets weight 0 and the other weights are renormalised).
 *
 * Editing (level editors, live tools): {@link LightProbeVolume.moveProbe},
 * {@link LightProbeVolume.addProbe} and {@link LightProbeVolume.removeProbe} update the
 * tetrahedralization locally (the first edit turns the interpolator into an
 * `IncrementalTetrahedralMesh` — one full tetrahedralization — kept from then on), mark the moved or
 * added probe dirty, and {@link LightProbeVolume.recaptureDirty} captures only those. Probe ids
 * never shift: a removed probe keeps its slot (position, name, role; SH zeroed) and gets no
 * weight. `positions` and `sh` are replaced by edits (read them again; old references go stale).
 * Volumes with zones cannot be edited (create a new volume).
 */
export class LightProbeVolume {

	/**
	 * Probe positions, x, y, z per probe (one slot per probe id, removed ones included). Replaced by
	 * `moveProbe` / `addProbe` / `removeProbe` (a view of the incremental mesh's): read it again
	 * after an edit.
	 */
	positions: Float64Array;

	/**
	 * 27 floats per probe (three.js `SphericalHarmonics3` layout); `capture()` fills it. Replaced by
	 * `addProbe` (a view of a capacity-doubling store): read it again after adding a probe.
	 */
	sh: Float32Array;

	/**
	 * Gradient probes: 81 floats per probe, `gradients[ 81·i + 27·a + k ]` = ∂(SH float k)/∂(axis a) at probe i, and
	 * every blend (objects, vertices, texels, {@link LightProbeVolume.sample}) is Σ wᵢ · (cᵢ + Gᵢ · (q − pᵢ)) at its
	 * point q; null (default) for plain probes. Set it with {@link LightProbeVolume.setGradients}; values written in
	 * place are noticed like `sh`'s. Edits keep it in step (a moved or added probe's gradient is zero, a removed one's
	 * too) and replace it when adding a probe; a capture with `fit: { gradients: true }` sets it, a full capture
	 * without `fit` clears it.
	 */
	gradients: Float32Array | null;

	/**
	 * How the SH (and gradients) were fitted to extra captured points, stored in baked files; null when not fitted. A
	 * volume loaded with a record (`fromBakedData`) has no fit points to refit to: a capture of some of its probes sets it to null.
	 */
	fitSettings: BakedFit | null = null;

	/** Name per probe ('' when none was given); `addProbe` appends. */
	readonly names: string[];

	/** Role per probe; `addProbe` appends. */
	readonly roles: ProbeRole[];

	/**
	 * The tetrahedralization (or planar triangulation, or grid) that turns positions into weights.
	 * The first probe edit replaces a {@link TetrahedralMesh} by an incremental one.
	 */
	interpolator: ProbeInterpolator;

	/**
	 * Capture settings of the last {@link LightProbeVolume.capture} (or those read from a baked
	 * file): stored in baked files (`LightProbeVolumeExporter`) so a bake says how it was made.
	 */
	captureSettings: BakedCapture = {};

	/** Free-form text stored with baked files (e.g. the tool and scene of the bake). */
	metadata = '';

	/** The lighting zones, or null when none were given. */
	readonly zones: ProbeZones | null;

	private guard: VisibilityGuard | null = null;
	private readonly weighting: ProbeWeighting;
	private readonly edits: ProbeEdits;
	private readonly objects: LitObjectRegistry;
	/** {@link LightProbeVolume.probeSpacing}, or −1 until computed (again after an edit). */
	private spacing = - 1;

	/**
	 * @param parameters See {@link LightProbeVolumeParameters}.
	 */
	constructor( parameters: LightProbeVolumeParameters ) {

		const { positions, sh, gradients, names, roles, interpolator } = readVolumeParameters( 'LightProbeVolume', parameters );
		this.positions = positions;
		this.sh = sh;
		this.gradients = gradients;
		this.names = names;
		this.roles = roles;
		this.interpolator = interpolator;
		this.zones = parameters.zones !== undefined ? new ProbeZones( parameters.zones, this.positions ) : null;
		this.weighting = new ProbeWeighting( this, defaultMoveThreshold( positions ) );
		this.objects = new LitObjectRegistry( this, this.weighting );
		this.edits = new ProbeEdits( this, this.objects.lit );
		if ( parameters.occluders !== undefined ) this.setOccluders( parameters.occluders, parameters.guard );

	}

	/**
	 * Turns on the visibility guard (no light through walls): every object's blend, and
	 * {@link LightProbeVolume.sample}, tests the segment from the sampling point to each weighted
	 * probe against `occluders`; a blocked probe's weight is multiplied by
	 * `options.blockedWeight` (default 0) and the weights are renormalised. When every weighted
	 * probe is blocked, the nearest visible probe of the object's zone (or of the volume) is used
	 * alone, searching the 8 nearest; when none of them is visible either, the unguarded weights
	 * are kept. `update()` tests again only when an object has moved more than
	 * `options.moveThreshold` (default 1 % of the probes' bounding-box diagonal) or blends other
	 * probes than last time; between tests it reuses the result, without allocating.
	 *
	 * Occluders are static: pass the level's walls, floors and large props, built once in world
	 * space (objects are read where they are now); not the objects this volume lights.
	 * @param occluders A {@link VisibilityGuard}, a `TriangleBVH`, a flat triangle array (9
	 * floats per triangle), an `Object3D` or an array of them; null turns the guard off.
	 * @param options See {@link VisibilityGuardOptions} (ignored when `occluders` is a guard).
	 */
	setOccluders( occluders: ProbeOccluders | null, options?: VisibilityGuardOptions ): this {

		assertOptions( 'LightProbeVolume.setOccluders', 'options', options );
		if ( occluders === null ) this.guard = null;
		else this.guard = occluders instanceof VisibilityGuard ? occluders : new VisibilityGuard( occluders, options );
		for ( const entry of this.objects.lit ) invalidateVisibility( entry );
		this.objects.probesChanged();
		return this;

	}

	/** The visibility guard set by `occluders` / {@link LightProbeVolume.setOccluders}, or null. */
	get visibilityGuard(): VisibilityGuard | null {

		return this.guard;

	}

	/**
	 * Diagnostics: the tetrahedra of the volume's tetrahedralization (not the zones') with an edge
	 * through the occluders — where light leaks across geometry without the guard or zones.
	 * @throws when no occluders are set or the interpolator has no tetrahedra (grid, planar).
	 */
	findLeakingTetrahedra(): Uint32Array {

		const where = 'LightProbeVolume.findLeakingTetrahedra';
		if ( ! this.guard ) throw new Error( `${where}: no occluders; call setOccluders() first.` );
		const tetrahedra = ( this.interpolator as Partial<TetrahedralMesh> ).tetrahedra;
		if ( ! ( tetrahedra instanceof Uint32Array ) ) {

			throw new Error( `${where}: the volume's interpolator has no tetrahedra (a grid or a planar mesh).` );

		}

		return this.guard.findLeakingTetrahedra( this.positions, tetrahedra );

	}

	/** Number of probes. */
	get count(): number {

		return this.positions.length / 3;

	}

	/**
	 * The typical distance between probes: the median over live probes of the distance to the
	 * nearest other one (Infinity with fewer than two). `add( scene )` lights static meshes larger
	 * than this per vertex or per pixel. Computed when first read, again after a probe edit.
	 */
	get probeSpacing(): number {

		if ( this.spacing < 0 ) this.spacing = medianProbeSpacing( this.positions, ( i ) => this.isProbeActive( i ) );
		return this.spacing;

	}

	/**
	 * Captures every probe from the scene on the GPU and fills {@link LightProbeVolume.sh}.
	 * Objects lit as `'dynamic'` (`add( object )` in mode `'object'`, and what `add( scene )` found
	 * moving) are hidden while capturing, so add them before capturing — a character added later is
	 * captured into the probes it is then lit by; `options.exclude` hides more. Scenery lit by the
	 * volume (large objects, static props) stays in view with its probe light off. Shadow maps are
	 * drawn once per pass, not per cube face, and the renderer's shadow-map settings are restored.
	 * All or nothing: the results are staged and put into the volume (SH, dirty set,
	 * `captureSettings`) only when every probe and pass is done, so a capture that fails — a lost
	 * context, a throwing callback — changes nothing.
	 * With `options.bounces` = n, captures n + 1 times, adding a bounce of diffuse interreflection
	 * each time (as `captureBounces`, which also returns the statistics of each pass). With
	 * `options.fit`, captures extra points too and fits the SH (and gradients) to them; a later capture
	 * of some probes (`recaptureDirty` after an edit) refits, one of every probe without `fit` does not.
	 * `renderer`: a `WebGLRenderer`, or a `WebGPURenderer` with the library imported from
	 * `three-capture-lighting/webgpu` (awaits `renderer.init()` when needed).
	 */
	async capture( renderer: CaptureRenderer, scene: Scene, options: LightProbeVolumeCaptureOptions = {} ): Promise<this> {

		await captureVolume( 'LightProbeVolume.capture', this, renderer, scene, options );
		return this;

	}

	/**
	 * What a capture needs of the volume: its registered objects, the commit of a finished
	 * capture — SH and dirty set ({@link ProbeEdits.commitCapture}), then the capture settings — and its fit store.
	 */
	[ CAPTURE_ACCESS ](): CaptureAccess {

		return captureAccessOf( this, this.edits, this.objects.lit, () => this.objects.probesChanged() );

	}

	/**
	 * Captures only the dirty probes (moved or added since their last capture; see
	 * {@link LightProbeVolume.dirtyProbes}) and, for a fitted volume, refits the edited layout to the
	 * stored fit points; does nothing when there is neither. A volume loaded from a file keeps no fit points:
	 * its recaptured probes get captured SH and zero gradients, and `fitSettings` becomes null. Same options as
	 * {@link LightProbeVolume.capture}, without `indices`.
	 */
	async recaptureDirty(
		renderer: CaptureRenderer, scene: Scene, options: Omit<LightProbeVolumeCaptureOptions, 'indices'> = {},
	): Promise<this> {

		const where = 'LightProbeVolume.recaptureDirty';
		assertRecaptureArguments( where, renderer as WebGLRenderer, scene, options );
		await captureVolume( where, this, renderer, scene, { ...options, indices: this.dirtyProbes() } );
		return this;

	}

	/**
	 * The probes moved or added (without `sh`) since their last capture, ascending — e.g.
	 * `capture( renderer, scene, { indices: volume.dirtyProbes() } )`.
	 */
	dirtyProbes(): number[] {

		return this.edits.dirtyProbes();

	}

	/** Whether probe id `index` is in use (false for removed probes and out-of-range ids). */
	isProbeActive( index: number ): boolean {

		return this.edits.isActive( index );

	}

	/**
	 * Moves probe `index` to `position`: the tetrahedralization is updated locally (O(cells
	 * around the probe), plus O(hull) when the hull changed), and the probe is marked dirty — it
	 * keeps its SH until {@link LightProbeVolume.recaptureDirty} captures it at its new place.
	 * Objects keep their walk hints; visibility-guard caches are reset. `positions` is replaced.
	 * @param position `{ x, y, z }` (e.g. a `Vector3`) or `[ x, y, z ]`.
	 * @throws Error when the volume has zones or a non-tetrahedral interpolator (coplanar probes,
	 * a grid); RangeError for a removed or unknown index or a non-finite position;
	 * `DegenerateInputError` when the probe would coincide with another or make all probes
	 * coplanar. Nothing changes when it throws.
	 */
	moveProbe( index: number, position: ProbePosition ): this {

		this.edits.move( index, position );
		this.probesEdited();
		return this;

	}

	/**
	 * Adds a probe at `position` and returns its id (= the previous `count`; ids never shift). The
	 * tetrahedralization is updated locally; the probe's SH is `options.sh`, or else the SH
	 * interpolated at its position from the probes around it (so the picture does not flash black),
	 * and then it is marked dirty for {@link LightProbeVolume.recaptureDirty}. `positions` and `sh`
	 * are replaced (earlier references go stale); `names` and `roles` get one more entry.
	 * @throws as {@link LightProbeVolume.moveProbe}, and RangeError for a bad name, role or sh.
	 */
	addProbe( position: ProbePosition, options: AddProbeOptions = {} ): number {

		const index = this.edits.add( position, options );
		this.probesEdited();
		return index;

	}

	/**
	 * Removes probe `index`: the tetrahedralization is updated locally; the id stays (no other id
	 * shifts), in no tetrahedron any more, with its SH zeroed and its name and role kept. Needs no
	 * capture.
	 * @throws as {@link LightProbeVolume.moveProbe}; `DegenerateInputError` when fewer than 4
	 * probes, or only coplanar ones, would remain.
	 */
	removeProbe( index: number ): this {

		this.edits.remove( index );
		this.probesEdited();
		return this;

	}

	/**
	 * Makes the probes gradient probes (see {@link LightProbeVolume.gradients}) or, with null, plain ones again. The
	 * values are copied into a new array; a removed probe's gradient is kept at zero. All or nothing.
	 * @param gradients 81 × `count` finite numbers, each |value| ≤ 1e30 / the probes' bounding-box diagonal (so the
	 * gradient term across the layout stays within the SH limit); or null.
	 * @throws TypeError / RangeError for another length, a non-number, NaN or a value beyond the bound.
	 */
	setGradients( gradients: ArrayLike<number> | null ): this {

		this.edits.setGradients( 'LightProbeVolume.setGradients', gradients );
		this.objects.probesChanged();
		return this;

	}

	/**
	 * Everything a baked file holds: positions, SH, the tetrahedralization (when the interpolator
	 * is a {@link TetrahedralMesh}, so loading needs no re-tetrahedralization), names, roles, zones,
	 * bounds, capture settings, gradients, the fit record (`fitSettings`) and metadata. The arrays
	 * are the volume's own, not copies — except after `removeProbe()`, when the live probes are
	 * renumbered into new arrays.
	 */
	toBakedData(): BakedVolumeInput {

		return toBakedVolumeInput( this );

	}

	/**
	 * A volume from decoded baked data (as `decodeBakedVolume` or `bakedVolumeFromJSON` return it,
	 * having checked it): the stored tetrahedralization is used as it is, without checking it again;
	 * without one, the default interpolator is built.
	 * @param parameters More constructor parameters, e.g. `occluders`.
	 */
	static fromBakedData( data: BakedVolumeData, parameters: BakedVolumeParameters = {} ): LightProbeVolume {

		checkBakedData( 'LightProbeVolume.fromBakedData', data );
		assertBakedVolumeParameters( 'LightProbeVolume.fromBakedData', parameters );
		const volume = new LightProbeVolume( { ...parameters, ...parametersFromBakedData( data ) } );
		volume.captureSettings = data.capture;
		volume.metadata = data.metadata;
		volume.fitSettings = data.fit ?? null;
		return volume;

	}

	/**
	 * A ready volume for a level in one call: candidates in its open space, captured once, reduced to
	 * `options.budget` probes (or one per `options.spacing`³ of open space) and fitted to the
	 * candidates' captures, with progress per stage — see {@link FromSceneOptions}. Add the character
	 * and the scene to it afterwards, as to any volume.
	 */
	static async fromScene( renderer: CaptureRenderer, scene: Scene, options: FromSceneOptions ): Promise<LightProbeVolume> {

		const { volumeFromScene } = await import( './volumeFromScene.js' );
		return volumeFromScene( renderer, scene, options );

	}

	/**
	 * Writes the interpolated SH (27 floats) at a world position into `target` and returns it,
	 * with the same zone and visibility logic as a registered object (tested afresh, no cache),
	 * and the gradient formula at that position for gradient probes.
	 * @param position `{ x, y, z }` (e.g. a `Vector3`) or `[ x, y, z ]`.
	 * @param options `zone`: sample this zone by name instead of the one whose bounds contain the position.
	 */
	sample( position: ProbePosition, target: Float32Array = new Float32Array( SH_FLOATS ), options: SampleOptions = {} ): Float32Array {

		return sampleVolume( 'LightProbeVolume.sample', this, this.weighting, position, target, options );

	}

	/**
	 * Lights an object with this volume. A mesh or a group (a loaded character: all its meshes) is one object in
	 * `options.mode` (default `'object'`): its Standard, Physical, Phong, Lambert and Toon materials are patched (one
	 * shared with an object lit separately is cloned) and `update()` blends the probes at its world position every
	 * frame; an object with none of them is a TypeError. A `Scene` (or `mode: 'auto'`) is a level: every mesh below
	 * it not lit yet, each as it suits — see {@link ProbeLighting}; mark objects with `userData.probeLighting` or
	 * `options.choose`. Meshes with a `ShaderMaterial` or node material are left with one `console.warn` per call,
	 * unlit ones (`MeshBasicMaterial`) silently. Call it again after adding objects to the level; `add( object )`
	 * later takes over from what `add( scene )` chose for it.
	 *
	 * Add what moves (characters, vehicles) before `capture()`: only objects lit as `'dynamic'` when capturing are
	 * hidden from the probes. `add( scene )` finds skinned meshes and what hangs from bones; mark other movers `'dynamic'`.
	 */
	add( object: Object3D, options: AddOptions = {} ): this {

		this.objects.add( object, options );
		return this;

	}

	/**
	 * Stops lighting an object, or everything `add( object )` lit for a scene: materials restored,
	 * clones, textures and vertex attributes made by `add()` disposed.
	 */
	remove( object: Object3D ): this {

		this.objects.remove( object );
		return this;

	}

	/**
	 * How an object is lit — `'dynamic'`, `'object'`, `'vertex'` or `'texture'` (see
	 * {@link ProbeLighting}) — by its own registration or one covering it (a character's mesh), or
	 * null when this volume does not light it.
	 */
	getLighting( object: Object3D ): ProbeLighting | null {

		return this.objects.lightingOf( object );

	}

	/**
	 * The point where an object registered in `'object'` mode (or `'dynamic'`) samples the probes,
	 * in its local frame (its `anchor`), written into `target`; null for other objects.
	 */
	getAnchor( object: Object3D, target: Vector3 ): Vector3 | null {

		return this.objects.anchorOf( object, target );

	}

	/**
	 * The name of the zone that lit a registered object at the last `update()` (or `add()`), or
	 * null when it used the whole volume or is not registered.
	 */
	getZone( object: Object3D ): string | null {

		return this.objects.zoneOf( object );

	}

	/** The uniforms `update()` writes for a registered object, or null. */
	getUniforms( object: Object3D ): ProbeVolumeUniforms | null {

		assertObject3D( 'LightProbeVolume.getUniforms', object );
		return this.objects.find( object )?.uniforms ?? null;

	}

	/**
	 * Once per frame, before rendering: locates every dynamic object (walking from last frame's
	 * cell) in its zone or the whole volume, drops the probes it cannot see when occluders are set,
	 * blends its probes' SH and writes its irradiance matrices; scenery only when it moved or the
	 * probes changed. Allocation-free. An object whose blend is not finite (SH written into `sh`
	 * directly) gets zero matrices, and update() then throws a RangeError naming it and the probe.
	 */
	update(): void {

		this.objects.update( 'LightProbeVolume.update' );

	}

	/** Unregisters every object (restoring their materials). The volume holds no GPU resources of its own. */
	dispose(): void {

		this.objects.dispose();

	}

	/** After a probe edit: a new spacing, and static objects blend again. */
	private probesEdited(): void {

		this.spacing = - 1;
		this.objects.probesChanged();

	}

}
