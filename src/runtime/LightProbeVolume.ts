import { Box3, FloatType, Matrix4, Vector3 as Vector3Class, type Material, type Layers, type Mesh, type Object3D, type SkinnedMesh, type Scene, type Vector3, type WebGLRenderer } from 'three';
import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import { DynamicTetrahedralization } from '../tetrahedra/DynamicTetrahedralization.js';
import { bakedVolumeFromJSON, bakedVolumeToJSON, decodeBakedVolume, encodeBakedVolume, type BakedCapture, type BakedCaptureSettings, type BakedVolumeData, type BakedVolumeInput, type BakedVolumeJSON, type EncodeBakedVolumeOptions } from '../io/BakedVolume.js';
import type { PlanarMesh } from '../interpolation/PlanarMesh.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { blendSH } from '../interpolation/blendSH.js';
import { irradianceMatrices } from '../sh/irradiance.js';
import { makeIrradianceNonNegative, windowSH } from '../sh/windowSH.js';
import { ProbeCapturer, type ProbeCaptureOptions, type ProbeCaptureSettings } from '../capture/ProbeCapturer.js';
import { getProbeVolumeUniforms, patchMaterial, unpatchMaterial, type ProbeVolumeUniforms } from './patchMaterial.js';
import { ProbeVertexLighting } from './ProbeVertexLighting.js';
import { ProbeTextureLighting } from './ProbeTextureLighting.js';
import type { ProbeField } from './ProbeField.js';
import { SH_FLOATS, assertArrayLike, assertPoints, assertSH } from '../validate.js';
import { ProbeZones, type ProbeZoneDefinition } from './ProbeZones.js';
import { VisibilityGuard, type VisibilityGuardOptions } from './VisibilityGuard.js';
import type { TriangleBVH } from '../geometry/TriangleBVH.js';

/** What `LightProbeVolume` accepts as occluders: a ready guard, a BVH, a triangle array, or static three.js objects. */
export type ProbeOccluders = VisibilityGuard | TriangleBVH | ArrayLike<number> | Object3D | readonly Object3D[];

/** What a probe is for (paper 2.1.1): light from the sky, bounce from the ground, colour bleeding, or filling gaps. */
export type ProbeRole = 'sky' | 'bounce' | 'bleed' | 'fill';

const ROLES: readonly ProbeRole[] = [ 'sky', 'bounce', 'bleed', 'fill' ];

/** Constructor argument of {@link LightProbeVolume}. */
export interface LightProbeVolumeParameters {

	/** Flat x, y, z per probe (at least 3 probes; 4 not all in one plane for a 3D volume). */
	positions: ArrayLike<number>;

	/** 27 floats per probe, three.js `SphericalHarmonics3` layout; zeros (black) when omitted. */
	sh?: ArrayLike<number>;

	/** Optional name per probe. */
	names?: readonly string[];

	/** Optional role per probe; default `'fill'`. */
	roles?: readonly ProbeRole[];

	/**
	 * How positions are turned into weights. Default: a {@link TetrahedralMesh} of the positions
	 * (a {@link PlanarMesh} when they are coplanar). Pass a {@link GridInterpolator} built over
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
	 * Static geometry for the visibility guard (see {@link LightProbeVolume.setOccluders}): probes
	 * whose segment to an object passes through it do not light that object.
	 */
	occluders?: ProbeOccluders;

	/** Options of the visibility guard built from `occluders` (ignored when it is a `VisibilityGuard`). */
	guard?: VisibilityGuardOptions;

}

/** Options of {@link LightProbeVolume.sample}. */
export interface SampleOptions {

	/** Sample this zone's probes; default: the zone whose bounds contain the position, else the whole volume. */
	zone?: string;

}

/** Options of {@link LightProbeVolume.capture}: capture settings plus per-call options. */
export type LightProbeVolumeCaptureOptions = ProbeCaptureSettings & Omit<ProbeCaptureOptions, 'exclude'> & {

	/** More objects to hide during the capture; objects registered with `add()` are always hidden. */
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

};

/** Options of {@link LightProbeVolume.addProbe}. */
export interface AddProbeOptions {

	/** The new probe's name. Default ''. */
	name?: string;

	/** The new probe's role. Default `'fill'`. */
	role?: ProbeRole;

	/**
	 * Its SH (27 floats), e.g. captured elsewhere; the probe is then not marked dirty. Default: the
	 * SH interpolated at its position from the probes around it before it was added (so the
	 * picture does not change until it is captured), and the probe is marked dirty.
	 */
	sh?: ArrayLike<number>;

}

/** Options of {@link LightProbeVolume.add}. */
export interface AddOptions {

	/** Shade this object's irradiance per vertex instead of per pixel. Default false. */
	perVertex?: boolean;

	/** Probe light scale for this object's materials. Default 1. */
	intensity?: number;

	/**
	 * Where the object samples the probes, in its local frame. Default: the centre of its bounding
	 * box when added — a character's origin is usually at its feet, below the probes meant for it.
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
	 * - `'object'` (default): one blend of the probes at the object's anchor, updated every frame —
	 *   for characters, props, anything that moves.
	 * - `'vertex'`: the probe field sampled at every vertex (see `ProbeVertexLighting`) — for large
	 *   static or rarely moved meshes (floors, long walls) that one colour would flatten.
	 * - `'texture'`: the field resampled into a 3D SH texture over the object's bounds and read per
	 *   pixel (see `ProbeTextureLighting`) — for large objects whose tessellation is coarse.
	 *
	 * Vertex and texture modes sample the volume per vertex / texel, each point in the zone whose
	 * bounds hold it (or the `zone` given), without the visibility guard,
	 * and their objects stay visible in captures (they are scene, not visitors), their probe light
	 * switched off meanwhile so probes see them as built; `captureBounces` adds their bounces.
	 */
	mode?: 'object' | 'vertex' | 'texture';

	/**
	 * Whether `capture()` hides the object. Default: true in `'object'` mode (a visitor must not
	 * light the probes it is lit by), false in the large-object modes (scenery). A static object lit
	 * in `'object'` mode (a statue) can pass false to stay in the probes' view.
	 */
	hideInCaptures?: boolean;

	/** `'vertex'` mode: store per-vertex irradiance (default) or per-vertex SH (normal maps respond). */
	vertexOutput?: 'irradiance' | 'sh';

	/** `'texture'` mode: world size of a texel (default: the longest side / 31). */
	texelSize?: number;

	/** `'texture'` mode: largest texel count per axis (default 64). */
	maxResolution?: number;

}

interface Lit {

	object: Object3D;
	hint: number;
	sh: Float32Array;
	uniforms: ProbeVolumeUniforms;
	/** Meshes whose material was replaced by a patched clone, with the original to restore. */
	replaced: { mesh: Mesh; original: Material | Material[] }[];
	/** Materials patched in place (the user's, owned by this object alone). */
	patched: Material[];
	/** Patched clones made for this object (ours, disposed on remove). */
	clones: Material[];
	/** The point, in the object's local frame, where the probes are sampled. */
	anchor: Float64Array;
	/** The zone given to add(), or −1 for automatic assignment by bounds. */
	fixedZone: number;
	/** The zone used last update (−1: the whole volume); a change resets `hint`. */
	zone: number;
	/** Visibility cache: where the segments were last tested, to which probes, and the result. */
	guardPosition: Float64Array;
	guardIndices: Uint32Array;
	/** Bit k: slot k's probe was tested; its segment is blocked when bit k of `guardBlocked` is set. */
	guardTested: number;
	guardBlocked: number;
	guardValid: boolean;
	/** Nearest visible probe when every weighted probe is blocked: −2 not searched yet, −1 none. */
	guardFallback: number;
	/** Large-object modes: the per-vertex lightings (one per mesh) or the 3D-texture lighting. */
	large: ( ProbeVertexLighting | ProbeTextureLighting )[] | null;
	/** Hidden during `capture()`. */
	hidden: boolean;

}

const MAX_WEIGHTS = 8;
const _indices = new Uint32Array( MAX_WEIGHTS );
const _weights = new Float32Array( MAX_WEIGHTS );
const _sh = new Float32Array( SH_FLOATS );
/** How many (index, weight) pairs the last `weigh()` wrote. */
let _count = 0;
let _warnedInstancing = false;

/**
 * Light probes placed anywhere, captured from the scene and blended per object every frame —
 * the paper's pipeline in three.js. Probe positions are tetrahedralized (a planar triangulation
 * when they all lie in one plane); each registered object finds the cell around it, blends its
 * probes' SH with barycentric weights, and its patched `MeshStandardMaterial` shades
 * E(n) = nᵀMn from them.
 *
 * ```js
 * const volume = new LightProbeVolume( { positions } );
 * await volume.capture( renderer, scene, { resolution: 32 } );
 * volume.add( character );
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
 * tetrahedralization locally (the first edit turns the interpolator into an incremental
 * {@link TetrahedralMesh} — one full tetrahedralization — kept from then on), mark the moved or
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
	 * file): stored by {@link LightProbeVolume.toArrayBuffer} so a bake says how it was made.
	 */
	captureSettings: BakedCapture = {};

	/** Free-form text stored with baked files (e.g. the tool and scene of the bake). */
	metadata = '';

	/** The lighting zones, or null when none were given. */
	readonly zones: ProbeZones | null;

	private readonly lit: Lit[] = [];
	private guard: VisibilityGuard | null = null;
	/** Probes moved or added since they were last captured. */
	private readonly dirty = new Set<number>();
	/** Capacity-doubling store behind `sh` once a probe was added (null before). */
	private shStore: Float32Array | null = null;
	/** 1 % of the probes' bounding-box diagonal: the default re-test distance of the guard. */
	private readonly defaultMoveThreshold: number;

	/**
	 * @param parameters See {@link LightProbeVolumeParameters}.
	 */
	constructor( parameters: LightProbeVolumeParameters ) {

		if ( ! parameters || typeof parameters !== 'object' ) throw new TypeError( 'LightProbeVolume: expected { positions, sh?, names?, roles? }.' );
		const count = assertPoints( 'LightProbeVolume', 'positions', parameters.positions, 1 );
		this.positions = Float64Array.from( parameters.positions );
		this.sh = new Float32Array( SH_FLOATS * count );
		if ( parameters.sh !== undefined ) {

			assertSH( 'LightProbeVolume', 'sh', parameters.sh, count );
			this.sh.set( parameters.sh );

		}

		this.names = listOf( 'names', parameters.names, count, '' );
		this.roles = listOf( 'roles', parameters.roles, count, 'fill' as ProbeRole );
		this.roles.forEach( ( role, i ) => {

			if ( ! ROLES.includes( role ) ) throw new RangeError( `LightProbeVolume: roles[${i}] is "${role}"; expected one of ${ROLES.join( ', ' )}.` );

		} );

		if ( parameters.interpolator !== undefined ) {

			const interpolator = parameters.interpolator;
			if ( typeof interpolator?.interpolate !== 'function' ) throw new TypeError( 'LightProbeVolume: interpolator must implement ProbeInterpolator (interpolate, weightCount, probeCount).' );
			if ( interpolator.probeCount !== count ) throw new RangeError( `LightProbeVolume: interpolator indexes ${interpolator.probeCount} probes but positions has ${count}.` );
			if ( interpolator.weightCount > MAX_WEIGHTS ) throw new RangeError( `LightProbeVolume: interpolator.weightCount ${interpolator.weightCount} exceeds ${MAX_WEIGHTS}.` );
			this.interpolator = interpolator;

		} else {

			this.interpolator = createProbeInterpolator( this.positions ) as TetrahedralMesh | PlanarMesh;

		}

		this.zones = parameters.zones !== undefined ? new ProbeZones( parameters.zones, this.positions ) : null;
		const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
		for ( let i = 0; i < this.positions.length; i ++ ) {

			min[ i % 3 ] = Math.min( min[ i % 3 ], this.positions[ i ] );
			max[ i % 3 ] = Math.max( max[ i % 3 ], this.positions[ i ] );

		}

		this.defaultMoveThreshold = 0.01 * Math.hypot( max[ 0 ] - min[ 0 ], max[ 1 ] - min[ 1 ], max[ 2 ] - min[ 2 ] );
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

		if ( occluders === null ) this.guard = null;
		else this.guard = occluders instanceof VisibilityGuard ? occluders : new VisibilityGuard( occluders, options );
		for ( const entry of this.lit ) { entry.guardValid = false; entry.guardFallback = - 2; }
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
		if ( ! ( tetrahedra instanceof Uint32Array ) ) throw new Error( `${where}: the volume's interpolator has no tetrahedra (a grid or a planar mesh).` );
		return this.guard.findLeakingTetrahedra( this.positions, tetrahedra );

	}

	/** Number of probes. */
	get count(): number {

		return this.positions.length / 3;

	}

	/**
	 * Captures every probe from the scene on the GPU and fills {@link LightProbeVolume.sh}.
	 * Registered objects are hidden while capturing. On a lost context the SH already held stay.
	 */
	async capture( renderer: WebGLRenderer, scene: Scene, options: LightProbeVolumeCaptureOptions = {} ): Promise<this> {

		const where = 'LightProbeVolume.capture';
		let indices: number[];
		if ( options.indices !== undefined ) {

			assertArrayLike( where, 'options.indices', options.indices );
			indices = Array.from( options.indices );
			indices.forEach( ( index ) => {

				if ( ! Number.isInteger( index ) || index < 0 || index >= this.count ) throw new RangeError( `${where}: options.indices holds ${index}, not a probe index (0..${this.count - 1}).` );
				if ( ! this.isProbeActive( index ) ) throw new RangeError( `${where}: options.indices holds ${index}, a removed probe.` );

			} );

		} else {

			indices = [];
			for ( let i = 0; i < this.count; i ++ ) if ( this.isProbeActive( i ) ) indices.push( i );

		}

		// Probes whose role has its own settings (paper 3.4: sky, bounce and reflection captures
		// want different ranges and layers) are captured in their own pass.
		const groups = new Map<string, number[]>();
		for ( const index of indices ) {

			const role = this.roles[ index ];
			const key = options.roles?.[ role ] ? role : '';
			groups.set( key, [ ...( groups.get( key ) ?? [] ), index ] );

		}

		const deringing = options.deringing ?? 0;
		if ( ! ( deringing >= 0 && deringing <= 1 ) ) throw new RangeError( `${where}: options.deringing must be in [0, 1], got ${options.deringing}.` );
		const nonNegative = options.nonNegative === true;
		// Visitors are hidden; scenery lit by the probes (large objects) is seen as built: probe light off.
		const exclude = [ ...this.lit.filter( ( entry ) => entry.hidden ).map( ( entry ) => entry.object ), ...( options.exclude ?? [] ) ];
		const intensities: [ { value: number }, number ][] = [];
		for ( const entry of this.lit ) {

			if ( entry.hidden ) continue;
			const all = entry.large ? entry.large.map( ( lighting ) => lighting.uniforms ) : [ entry.uniforms ];
			for ( const uniforms of all ) intensities.push( [ uniforms.probeVolumeIntensity, uniforms.probeVolumeIntensity.value ] );

		}

		for ( const [ uniform ] of intensities ) uniform.value = 0;
		const total = indices.length;
		let done = 0;
		try {

			for ( const [ role, group ] of groups ) {

				const settings = { ...options, ...( role ? options.roles?.[ role as ProbeRole ] : {} ) };
				const positions = new Float64Array( 3 * group.length );
				group.forEach( ( index, k ) => positions.set( this.positions.subarray( 3 * index, 3 * index + 3 ), 3 * k ) );
				const capturer = new ProbeCapturer( renderer, settings );
				try {

					const start = done;
					const captured = await capturer.capture( scene, positions, new Float32Array( SH_FLOATS * group.length ), {
						...settings, exclude, onProgress: options.onProgress && ( ( n ) => options.onProgress!( start + n, total ) ),
					} );
					if ( nonNegative ) makeIrradianceNonNegative( captured, deringing );
					else if ( deringing > 0 ) windowSH( captured, deringing, captured );
					group.forEach( ( index, k ) => {

						this.sh.set( captured.subarray( SH_FLOATS * k, SH_FLOATS * ( k + 1 ) ), SH_FLOATS * index );
						this.dirty.delete( index );

					} );
					done += group.length;

				} finally {

					capturer.dispose();

				}

			}

		} finally {

			for ( const [ uniform, value ] of intensities ) uniform.value = value;

		}

		const roles: Partial<Record<ProbeRole, BakedCaptureSettings>> = {};
		for ( const role of ROLES ) if ( options.roles?.[ role ] ) roles[ role ] = bakedSettings( { ...options, ...options.roles[ role ] } );
		this.captureSettings = { ...bakedSettings( options ), ...( Object.keys( roles ).length > 0 ? { roles } : {} ) };
		return this;

	}

	/**
	 * Captures only the dirty probes (moved or added since their last capture; see
	 * {@link LightProbeVolume.dirtyProbes}); does nothing when there are none. Same options as
	 * {@link LightProbeVolume.capture}, without `indices`.
	 */
	async recaptureDirty( renderer: WebGLRenderer, scene: Scene, options: Omit<LightProbeVolumeCaptureOptions, 'indices'> = {} ): Promise<this> {

		const indices = this.dirtyProbes();
		if ( indices.length === 0 ) return this;
		return this.capture( renderer, scene, { ...options, indices } );

	}

	/**
	 * The probes moved or added (without `sh`) since their last capture, ascending — e.g.
	 * `capture( renderer, scene, { indices: volume.dirtyProbes() } )`.
	 */
	dirtyProbes(): number[] {

		return Array.from( this.dirty ).sort( ( a, b ) => a - b );

	}

	/** Whether probe id `index` is in use (false for removed probes and out-of-range ids). */
	isProbeActive( index: number ): boolean {

		const mesh = this.interpolator instanceof TetrahedralMesh && this.interpolator.dynamic !== null ? this.interpolator : null;
		if ( mesh !== null ) return mesh.isActive( index );
		return Number.isInteger( index ) && index >= 0 && index < this.count;

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
	moveProbe( index: number, position: Vector3 | { x: number; y: number; z: number } | ArrayLike<number> ): this {

		const where = 'LightProbeVolume.moveProbe';
		const [ x, y, z ] = readPosition( where, position );
		this.assertActiveProbe( where, index );
		const mesh = this.editableMesh( where );
		mesh.moveProbe( index, x, y, z );
		this.afterEdit( mesh );
		this.dirty.add( index );
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
	addProbe( position: Vector3 | { x: number; y: number; z: number } | ArrayLike<number>, options: AddProbeOptions = {} ): number {

		const where = 'LightProbeVolume.addProbe';
		const [ x, y, z ] = readPosition( where, position );
		const { name = '', role = 'fill', sh } = options;
		if ( typeof name !== 'string' ) throw new TypeError( `${where}: options.name must be a string, got ${typeof name}.` );
		if ( ! ROLES.includes( role ) ) throw new RangeError( `${where}: options.role is "${role}"; expected one of ${ROLES.join( ', ' )}.` );
		if ( sh !== undefined ) assertSH( where, 'options.sh', sh, 1 );
		const mesh = this.editableMesh( where );
		if ( sh === undefined ) {

			// Before the probe exists, so it does not weigh itself (its SH is still zero).
			mesh.interpolate( x, y, z, _indices, _weights, - 1 );
			blendSH( _indices, _weights, this.sh, _sh, mesh.weightCount );

		} else {

			_sh.set( sh );

		}

		const index = mesh.addProbe( x, y, z );
		const total = index + 1;
		if ( this.shStore === null || this.shStore.length < SH_FLOATS * total ) {

			const store = new Float32Array( SH_FLOATS * Math.max( 16, 2 * total ) );
			store.set( this.sh );
			this.shStore = store;

		}

		this.sh = this.shStore.subarray( 0, SH_FLOATS * total );
		this.sh.set( _sh, SH_FLOATS * index );
		this.names.push( name );
		this.roles.push( role );
		this.afterEdit( mesh );
		if ( sh === undefined ) this.dirty.add( index );
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

		const where = 'LightProbeVolume.removeProbe';
		this.assertActiveProbe( where, index );
		const mesh = this.editableMesh( where );
		mesh.removeProbe( index );
		this.sh.fill( 0, SH_FLOATS * index, SH_FLOATS * ( index + 1 ) );
		this.dirty.delete( index );
		this.afterEdit( mesh );
		return this;

	}

	private assertActiveProbe( where: string, index: number ): void {

		if ( ! this.isProbeActive( index ) ) throw new RangeError( `${where}: ${index} is not a probe of this volume (0..${this.count - 1}, not removed).` );

	}

	/**
	 * The incremental mesh edits go through: the volume's own once made incremental, else one built
	 * now over the current positions (a full tetrahedralization, once).
	 */
	private editableMesh( where: string ): TetrahedralMesh {

		if ( this.zones !== null ) throw new Error( `${where}: the volume has lighting zones, whose own tetrahedralizations are not edited; create a new LightProbeVolume with the edited positions.` );
		const current = this.interpolator;
		if ( ! ( current instanceof TetrahedralMesh ) ) throw new Error( `${where}: probes can be edited only with a tetrahedral interpolator; this volume's is a ${current.constructor?.name ?? 'custom interpolator'} (coplanar probes, or one passed in); create a new LightProbeVolume with the edited positions.` );
		if ( current.dynamic !== null ) return current;
		const mesh = TetrahedralMesh.fromDynamic( new DynamicTetrahedralization( this.positions ), { outside: current.outside } );
		this.interpolator = mesh;
		this.positions = mesh.positions;
		// Cell ids of the old mesh mean nothing in the new one.
		for ( const entry of this.lit ) if ( entry.zone < 0 ) entry.hint = - 1;
		return mesh;

	}

	/** After an edit: new positions, hints kept in range (any in-range hint is a valid walk start), guard caches reset. */
	private afterEdit( mesh: TetrahedralMesh ): void {

		this.positions = mesh.positions;
		const limit = mesh.cellCount + mesh.hullFaces.length / 3;
		for ( const entry of this.lit ) {

			if ( entry.zone < 0 && entry.hint >= limit ) entry.hint = - 1;
			entry.guardValid = false;
			entry.guardFallback = - 2;

		}

	}

	/**
	 * Everything a baked file holds: positions, SH, the tetrahedralization (when the interpolator
	 * is a {@link TetrahedralMesh}, so loading needs no re-tetrahedralization), names, roles, zones,
	 * bounds, capture settings and metadata. The arrays are the volume's own, not copies — except
	 * after `removeProbe()`, when the live probes are renumbered into new arrays.
	 */
	toBakedData(): BakedVolumeInput {

		const mesh = this.interpolator instanceof TetrahedralMesh ? this.interpolator : null;
		const count = this.count;
		let active = 0;
		for ( let i = 0; i < count; i ++ ) if ( this.isProbeActive( i ) ) active ++;
		if ( mesh && active < count ) {

			// Probes removed by removeProbe() leave empty id slots: the file holds the live probes
			// only, renumbered in order (tetrahedron ids and neighbour links do not change).
			const id = new Int32Array( count ).fill( - 1 ), keep: number[] = [];
			for ( let i = 0; i < count; i ++ ) if ( this.isProbeActive( i ) ) { id[ i ] = keep.length; keep.push( i ); }
			const positions = new Float64Array( 3 * active ), sh = new Float32Array( SH_FLOATS * active );
			keep.forEach( ( i, k ) => {

				positions.set( this.positions.subarray( 3 * i, 3 * i + 3 ), 3 * k );
				sh.set( this.sh.subarray( SH_FLOATS * i, SH_FLOATS * ( i + 1 ) ), SH_FLOATS * k );

			} );
			return {
				positions, sh, names: keep.map( ( i ) => this.names[ i ] ), roles: keep.map( ( i ) => this.roles[ i ] ),
				tetrahedra: mesh.tetrahedra.map( ( v ) => id[ v ] ), neighbors: mesh.neighbors,
				capture: this.captureSettings, metadata: this.metadata,
			};

		}

		return {
			positions: this.positions.subarray( 0, 3 * count ), sh: this.sh.subarray( 0, SH_FLOATS * count ), names: this.names, roles: this.roles,
			tetrahedra: mesh?.tetrahedra, neighbors: mesh?.neighbors,
			zones: this.zones?.zones.map( ( zone ) => ( { name: zone.name, probes: zone.probes, bounds: zone.bounds } ) ),
			capture: this.captureSettings, metadata: this.metadata,
		};

	}

	/**
	 * The volume as a baked binary file (little-endian, versioned; layout in docs/format.md).
	 * @param options `precision`: SH as `'float32'` (default, exact) or `'float16'` (smaller).
	 */
	toArrayBuffer( options?: EncodeBakedVolumeOptions ): ArrayBuffer {

		return encodeBakedVolume( this.toBakedData(), options );

	}

	/** The volume in the JSON form of the baked format (mirrors the binary; `JSON.stringify` it). */
	toJSON(): BakedVolumeJSON {

		return bakedVolumeToJSON( this.toBakedData() );

	}

	/**
	 * A volume from decoded baked data: the stored tetrahedralization is used as it is (checked in
	 * O(n)); without one, the default interpolator is built.
	 * @param parameters More constructor parameters, e.g. `occluders`.
	 */
	static fromBakedData( data: BakedVolumeData, parameters: Omit<LightProbeVolumeParameters, 'positions' | 'sh' | 'names' | 'roles' | 'zones' | 'interpolator'> = {} ): LightProbeVolume {

		const interpolator = data.tetrahedra.length > 0 ? TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, data.neighbors ) : undefined;
		const zones = data.zones.length > 0 ? data.zones.map( ( zone ) => ( { name: zone.name, probes: zone.probes, bounds: boxes( zone.bounds ) } ) ) : undefined;
		const volume = new LightProbeVolume( { ...parameters, positions: data.positions, sh: data.sh, names: data.names, roles: data.roles, zones, interpolator } );
		volume.captureSettings = data.capture;
		volume.metadata = data.metadata;
		return volume;

	}

	/**
	 * Loads a baked binary file written by {@link LightProbeVolume.toArrayBuffer} (or another
	 * writer of docs/format.md). A truncated, corrupted, newer-version or hostile file throws a
	 * `BakedVolumeError` naming the problem.
	 */
	static fromArrayBuffer( buffer: ArrayBuffer | ArrayBufferView, parameters?: Parameters<typeof LightProbeVolume.fromBakedData>[ 1 ] ): LightProbeVolume {

		return LightProbeVolume.fromBakedData( decodeBakedVolume( buffer ), parameters );

	}

	/** Loads the JSON form (an object or its text), with the same checks as {@link LightProbeVolume.fromArrayBuffer}. */
	static fromJSON( json: unknown, parameters?: Parameters<typeof LightProbeVolume.fromBakedData>[ 1 ] ): LightProbeVolume {

		return LightProbeVolume.fromBakedData( bakedVolumeFromJSON( typeof json === 'string' ? JSON.parse( json ) : json ), parameters );

	}

	/**
	 * Writes the interpolated SH (27 floats) at a world position into `target` and returns it,
	 * with the same zone and visibility logic as a registered object (tested afresh, no cache).
	 * @param position `{ x, y, z }` (e.g. a `Vector3`) or `[ x, y, z ]`.
	 * @param options `zone`: sample this zone by name instead of the one whose bounds contain the position.
	 */
	sample( position: Vector3 | { x: number; y: number; z: number } | ArrayLike<number>, target: Float32Array = new Float32Array( SH_FLOATS ), options: SampleOptions = {} ): Float32Array {

		const [ x, y, z ] = 'x' in position ? [ position.x, position.y, position.z ] : [ position[ 0 ], position[ 1 ], position[ 2 ] ];
		if ( ! Number.isFinite( x ) || ! Number.isFinite( y ) || ! Number.isFinite( z ) ) {

			throw new RangeError( `LightProbeVolume.sample: position must be three finite numbers, got (${x}, ${y}, ${z}).` );

		}

		const zone = options.zone !== undefined ? this.zoneIndex( 'LightProbeVolume.sample', options.zone ) : ( this.zones ? this.zones.zoneAt( x, y, z ) : - 1 );
		this.weigh( x, y, z, zone, - 1, null );
		return blendSH( _indices, _weights, this.sh, target, _count );

	}

	/**
	 * Lights an object (a mesh, or a group such as a loaded character: all its meshes) with this
	 * volume: its `MeshStandardMaterial`s are patched, and `update()` sets their irradiance from
	 * the probes around the object's world position. A material shared with an object lit
	 * separately is cloned for this one (uniforms are per material).
	 */
	add( object: Object3D, options: AddOptions = {} ): this {

		if ( ! object || ( object as { isObject3D?: boolean } ).isObject3D !== true ) throw new TypeError( 'LightProbeVolume.add: object must be a three.js Object3D.' );
		if ( this.lit.some( ( entry ) => entry.object === object ) ) return this;

		const fixedZone = options.zone !== undefined ? this.zoneIndex( 'LightProbeVolume.add', options.zone ) : - 1;
		const entry: Lit = {
			object, hint: - 1, sh: new Float32Array( SH_FLOATS ),
			uniforms: { probeVolumeMatrices: { value: new Float32Array( 48 ) }, probeVolumeIntensity: { value: options.intensity ?? 1 }, probeVolumeDirectScale: { value: 1 } },
			replaced: [], patched: [], clones: [], anchor: localBoundsCentre( object, options.anchor ),
			fixedZone, zone: - 1, guardPosition: new Float64Array( 3 ), guardIndices: new Uint32Array( MAX_WEIGHTS ),
			guardTested: 0, guardBlocked: 0, guardValid: false, guardFallback: - 2, large: null, hidden: true,
		};

		const mode = options.mode ?? 'object';
		entry.hidden = options.hideInCaptures ?? mode === 'object';
		if ( mode === 'vertex' || mode === 'texture' ) {

			entry.large = [];
			try {

				if ( mode === 'texture' ) {

					entry.large.push( new ProbeTextureLighting( object, this.zonedField( fixedZone ), { intensity: options.intensity, texelSize: options.texelSize, maxResolution: options.maxResolution } ) );

				} else {

					object.traverse( ( child ) => {

						if ( ( child as Mesh ).isMesh === true ) entry.large!.push( new ProbeVertexLighting( child as Mesh, this.zonedField( fixedZone ), { intensity: options.intensity, output: options.vertexOutput } ) );

					} );

				}

			} catch ( error ) {

				for ( const lighting of entry.large ) lighting.dispose();
				throw error;

			}

			entry.uniforms = entry.large[ 0 ]?.uniforms ?? entry.uniforms;
			this.lit.push( entry );
			return this;

		}

		if ( mode !== 'object' ) throw new RangeError( `LightProbeVolume.add: options.mode must be 'object', 'vertex' or 'texture', got ${String( mode )}.` );

		const owned = new Set<Material>();
		for ( const other of this.lit ) for ( const material of other.patched ) owned.add( material );

		object.traverse( ( child ) => {

			const mesh = child as Mesh & { isInstancedMesh?: boolean };
			if ( ( mesh as { isMesh?: boolean } ).isMesh !== true ) return;
			if ( mesh.isInstancedMesh === true && ! _warnedInstancing ) {

				_warnedInstancing = true;
				console.warn( 'LightProbeVolume.add: InstancedMesh is lit as one object, with the probes around its own origin; per-instance probe lighting is not supported yet.' );

			}

			const materials = Array.isArray( mesh.material ) ? mesh.material : [ mesh.material ];
			let replacement: Material[] | null = null;
			materials.forEach( ( material, i ) => {

				if ( ( material as { isMeshStandardMaterial?: boolean } ).isMeshStandardMaterial !== true ) return;
				// Uniforms live on the material: one lit by another object (or patched by the user)
				// gets a clone of its own.
				if ( owned.has( material ) || ( getProbeVolumeUniforms( material ) !== null && ! entry.patched.includes( material ) ) ) {

					const copy = material.clone();
					patchMaterial( copy, { perVertex: options.perVertex, uniforms: entry.uniforms } );
					replacement ??= materials.slice();
					replacement[ i ] = copy;
					entry.clones.push( copy );
					return;

				}

				if ( ! entry.patched.includes( material ) ) {

					patchMaterial( material, { perVertex: options.perVertex, uniforms: entry.uniforms } );
					entry.patched.push( material );

				}

			} );

			if ( replacement ) {

				entry.replaced.push( { mesh, original: mesh.material } );
				mesh.material = Array.isArray( mesh.material ) ? replacement : replacement[ 0 ];

			}

		} );

		this.lit.push( entry );
		this.updateEntry( entry );
		return this;

	}

	/** Stops lighting an object: its materials are restored (clones made by `add()` are disposed). */
	remove( object: Object3D ): this {

		const index = this.lit.findIndex( ( entry ) => entry.object === object );
		if ( index < 0 ) return this;
		const [ entry ] = this.lit.splice( index, 1 );
		for ( const lighting of entry.large ?? [] ) lighting.dispose();
		for ( const { mesh, original } of entry.replaced ) mesh.material = original;
		for ( const material of entry.patched ) unpatchMaterial( material );
		for ( const material of entry.clones ) material.dispose();
		return this;

	}

	/**
	 * The name of the zone that lit a registered object at the last `update()` (or `add()`), or
	 * null when it used the whole volume or is not registered.
	 */
	getZone( object: Object3D ): string | null {

		const entry = this.lit.find( ( candidate ) => candidate.object === object );
		return entry && entry.zone >= 0 && this.zones ? this.zones.zones[ entry.zone ].name : null;

	}

	/** The uniforms `update()` writes for a registered object, or null. */
	getUniforms( object: Object3D ): ProbeVolumeUniforms | null {

		return this.lit.find( ( entry ) => entry.object === object )?.uniforms ?? null;

	}

	/**
	 * Once per frame, before rendering: locates every registered object (walking from last
	 * frame's cell) in its zone or the whole volume, drops the probes it cannot see when
	 * occluders are set, blends its probes' SH and writes its irradiance matrices. Allocation-free.
	 */
	update(): void {

		for ( let i = 0, n = this.lit.length; i < n; i ++ ) this.updateEntry( this.lit[ i ] );

	}

	private updateEntry( entry: Lit ): void {

		if ( entry.large !== null ) {

			// Resample only when the object moved or the probes' SH changed (checked inside).
			for ( let i = 0; i < entry.large.length; i ++ ) entry.large[ i ].update();
			return;

		}

		const object = entry.object;
		object.updateWorldMatrix( true, false );
		const e = object.matrixWorld.elements, a = entry.anchor;
		const x = e[ 0 ] * a[ 0 ] + e[ 4 ] * a[ 1 ] + e[ 8 ] * a[ 2 ] + e[ 12 ];
		const y = e[ 1 ] * a[ 0 ] + e[ 5 ] * a[ 1 ] + e[ 9 ] * a[ 2 ] + e[ 13 ];
		const z = e[ 2 ] * a[ 0 ] + e[ 6 ] * a[ 1 ] + e[ 10 ] * a[ 2 ] + e[ 14 ];
		let zone = entry.fixedZone;
		if ( zone < 0 && this.zones !== null ) zone = this.zones.zoneAt( x, y, z );
		if ( zone !== entry.zone ) {

			// Cell indices belong to one interpolator: a hint from another zone's would be wrong.
			entry.zone = zone;
			entry.hint = - 1;

		}

		entry.hint = this.weigh( x, y, z, zone, entry.hint, entry );
		blendSH( _indices, _weights, this.sh, entry.sh, _count );
		irradianceMatrices( entry.sh, entry.uniforms.probeVolumeMatrices.value );

	}

	/**
	 * The field large objects sample: the whole volume without zones; with zones, each point (a
	 * vertex, a texel) interpolates the probes of the zone whose bounds hold it — or of `fixedZone`
	 * — so a floor running under a wall takes each room's light on its side. Not the visibility
	 * guard: vertices lie on surfaces, whose own triangles would block every segment.
	 */
	private zonedField( fixedZone: number ): ProbeField {

		if ( this.zones === null ) return this;
		const volume = this, zones = this.zones;
		let lastZone = - 2;
		const interpolator: ProbeInterpolator = {
			get probeCount() { return volume.count; },
			get cellCount() { return volume.interpolator.cellCount; },
			weightCount: Math.max( volume.interpolator.weightCount, ...zones.zones.map( ( zone ) => zone.interpolator.weightCount ) ),
			interpolate( x, y, z, indices, weights, hint = - 1 ) {

				const zone = fixedZone >= 0 ? fixedZone : zones.zoneAt( x, y, z );
				// Cell indices belong to one interpolator: a hint from another zone's would be wrong.
				if ( zone !== lastZone ) { hint = - 1; lastZone = zone; }
				hint = volume.weighZone( x, y, z, zone, hint );
				for ( let k = 0; k < this.weightCount; k ++ ) { indices[ k ] = k < _count ? _indices[ k ] : 0; weights[ k ] = k < _count ? _weights[ k ] : 0; }
				return hint;

			},
		};
		return { interpolator, get sh() { return volume.sh; } };

	}

	/**
	 * Writes the probes and weights for (x, y, z) into `_indices` / `_weights` (`_count` pairs):
	 * the zone's interpolator (indices mapped to the volume's probes) or the volume's, then the
	 * visibility guard. `entry` carries the guard's cache (null: test afresh).
	 * @returns The interpolator's cell, as the next hint.
	 */
	private weigh( x: number, y: number, z: number, zone: number, hint: number, entry: Lit | null ): number {

		hint = this.weighZone( x, y, z, zone, hint );
		if ( this.guard !== null ) this.applyGuard( this.guard, x, y, z, zone, entry );
		return hint;

	}

	/** {@link LightProbeVolume.weigh} without the visibility guard: the zone's (or volume's) weights. */
	private weighZone( x: number, y: number, z: number, zone: number, hint: number ): number {

		if ( zone >= 0 ) {

			const { interpolator, probes } = this.zones!.zones[ zone ];
			hint = interpolator.interpolate( x, y, z, _indices, _weights, hint );
			_count = interpolator.weightCount;
			for ( let k = 0; k < _count; k ++ ) _indices[ k ] = probes[ _indices[ k ] ];

		} else {

			hint = this.interpolator.interpolate( x, y, z, _indices, _weights, hint );
			_count = this.interpolator.weightCount;

		}

		return hint;

	}

	private applyGuard( guard: VisibilityGuard, x: number, y: number, z: number, zone: number, entry: Lit | null ): void {

		const count = _count, p = this.positions;
		let cached = false;
		if ( entry !== null && entry.guardValid ) {

			const threshold = guard.moveThreshold ?? this.defaultMoveThreshold;
			const dx = x - entry.guardPosition[ 0 ], dy = y - entry.guardPosition[ 1 ], dz = z - entry.guardPosition[ 2 ];
			cached = dx * dx + dy * dy + dz * dz <= threshold * threshold;
			for ( let k = 0; k < count && cached; k ++ ) {

				// A slot now weighted but not tested last time (or another probe) needs a new test.
				if ( entry.guardIndices[ k ] !== _indices[ k ] || ( _weights[ k ] > 0 && ( entry.guardTested & ( 1 << k ) ) === 0 ) ) cached = false;

			}

		}

		let blocked = 0;
		if ( cached ) {

			blocked = entry!.guardBlocked;

		} else {

			let tested = 0;
			for ( let k = 0; k < count; k ++ ) {

				if ( ! ( _weights[ k ] > 0 ) ) continue;
				tested |= 1 << k;
				const i = 3 * _indices[ k ];
				if ( guard.segmentBlocked( x, y, z, p[ i ], p[ i + 1 ], p[ i + 2 ] ) ) blocked |= 1 << k;

			}

			if ( entry !== null ) {

				entry.guardValid = true;
				entry.guardPosition[ 0 ] = x; entry.guardPosition[ 1 ] = y; entry.guardPosition[ 2 ] = z;
				entry.guardIndices.set( _indices );
				entry.guardTested = tested;
				entry.guardBlocked = blocked;
				entry.guardFallback = - 2;

			}

		}

		if ( guard.applyMask( blocked, _weights, count ) > 0 ) return;

		// Every weighted probe is behind geometry: the nearest visible one, alone.
		let fallback = entry !== null ? entry.guardFallback : - 2;
		if ( fallback === - 2 ) {

			fallback = guard.nearestVisible( x, y, z, p, zone >= 0 ? this.zones!.zones[ zone ].probes : null );
			if ( entry !== null ) entry.guardFallback = fallback;

		}

		if ( fallback < 0 ) return; // none visible nearby: keep the unguarded weights
		_indices[ 0 ] = fallback;
		_weights[ 0 ] = 1;
		for ( let k = 1; k < count; k ++ ) { _indices[ k ] = fallback; _weights[ k ] = 0; }

	}

	private zoneIndex( where: string, name: string ): number {

		if ( this.zones === null ) throw new Error( `${where}: zone "${name}" given, but the volume has no zones.` );
		const index = this.zones.indexOf( name );
		if ( index < 0 ) throw new RangeError( `${where}: unknown zone "${name}"; the zones are ${this.zones.zones.map( ( zone ) => `"${zone.name}"` ).join( ', ' )}.` );
		return index;

	}

	/** Unregisters every object (restoring their materials). The volume holds no GPU resources of its own. */
	dispose(): void {

		while ( this.lit.length > 0 ) this.remove( this.lit[ this.lit.length - 1 ].object );

	}

}

/** `{ x, y, z }` or `[ x, y, z ]` as three finite numbers. */
function readPosition( where: string, position: { x: number; y: number; z: number } | ArrayLike<number> ): [ number, number, number ] {

	if ( ! position || typeof position !== 'object' ) throw new TypeError( `${where}: position must be { x, y, z } or [ x, y, z ], got ${position === null ? 'null' : typeof position}.` );
	const [ x, y, z ] = 'x' in position ? [ position.x, position.y, position.z ] : [ position[ 0 ], position[ 1 ], position[ 2 ] ];
	if ( ! Number.isFinite( x ) || ! Number.isFinite( y ) || ! Number.isFinite( z ) ) throw new RangeError( `${where}: position must be three finite numbers, got (${x}, ${y}, ${z}).` );
	return [ x, y, z ];

}

/** The centre of an object's bounding box in its own frame (or the given anchor). */
function localBoundsCentre( object: Object3D, anchor?: { x: number; y: number; z: number } ): Float64Array {

	if ( anchor ) return Float64Array.of( anchor.x, anchor.y, anchor.z );
	object.updateWorldMatrix( true, true );
	// A skinned mesh's bounds follow its bones, whose matrices stay zero until the first render.
	object.traverse( ( child ) => ( child as SkinnedMesh ).skeleton?.update() );
	const box = new Box3().setFromObject( object );
	if ( box.isEmpty() ) return new Float64Array( 3 );
	const centre = box.getCenter( new Vector3Class() ).applyMatrix4( new Matrix4().copy( object.matrixWorld ).invert() );
	return Float64Array.of( centre.x, centre.y, centre.z );

}

function listOf<T>( name: string, values: readonly T[] | undefined, count: number, fallback: T ): T[] {

	if ( values === undefined ) return new Array<T>( count ).fill( fallback );
	assertArrayLike( 'LightProbeVolume', name, values as unknown );
	if ( values.length !== count ) throw new RangeError( `LightProbeVolume: ${name} must have one entry per probe (${count}), got ${values.length}.` );
	return Array.from( values );

}

/** The capture settings worth storing with a bake. */
function bakedSettings( settings: ProbeCaptureSettings ): BakedCaptureSettings {

	const out: BakedCaptureSettings = { resolution: settings.resolution ?? 32, near: settings.near ?? 0.05, far: settings.far ?? 1000, type: settings.type === FloatType ? 'float' : 'half' };
	// The format names the two normalised formulas only; 'paper-unnormalized' is left unstated.
	if ( settings.solidAngle === undefined || settings.solidAngle === 'exact' || settings.solidAngle === 'paper' ) out.solidAngle = settings.solidAngle ?? 'exact';
	return out;

}

/** Flat min/max boxes (6 numbers each) as `BoxLike`s. */
function boxes( flat: Float64Array ): { min: { x: number; y: number; z: number }; max: { x: number; y: number; z: number } }[] | undefined {

	if ( flat.length === 0 ) return undefined;
	const out = [];
	for ( let i = 0; i < flat.length; i += 6 ) out.push( { min: { x: flat[ i ], y: flat[ i + 1 ], z: flat[ i + 2 ] }, max: { x: flat[ i + 3 ], y: flat[ i + 4 ], z: flat[ i + 5 ] } } );
	return out;

}
