import { Box3, Vector3 } from 'three';
import { texture3D, uniform } from 'three/tsl';
import { boundsOf } from '../../geometry/boundsOf.js';
import type { LightProbeVolume } from '../../runtime/LightProbeVolume.js';
import { assertUsableProbeField } from '../../runtime/ProbeField.js';
import { checkVolumeTextureOptions, ProbeVolumeTexture, type BoundsLike, type ProbeVolumeTextureOptions } from '../../runtime/ProbeVolumeTexture.js';
import { assertOptions, describeValue } from '../../validate.js';
import { atlasIrradiance } from '../shading/packedSHIrradiance.js';

// TSL's typings model each node class; the graph is built from untyped chains.
type TSLNode = any;

/** Options of {@link ProbeVolumeIrradiance}: the resampling texture's, plus its box and a scale. */
export interface ProbeVolumeIrradianceOptions extends ProbeVolumeTextureOptions {

	/**
	 * The world box to resample the volume over: the meshes to bake, e.g.
	 * `new Box3().setFromObject( level )`. Default: the probes' box grown by one probe spacing.
	 */
	bounds?: BoundsLike;

	/** Scale of the light, as `volume.add( object, { intensity } )`. Default 1. */
	intensity?: number;

}

/**
 * The volume's irradiance E(n) as a TSL node, for three's `LightMapper` (WebGPU only): the field
 * `volume.add()` lights objects with, outer cells included, resampled into a
 * {@link ProbeVolumeTexture} and evaluated as the texture mode does. Units are those of three's
 * light maps and light probes (irradiance, not divided by π), so a lightmapped wall and a
 * probe-lit object at the same place get the same light.
 *
 * ```js
 * const source = new ProbeVolumeIrradiance( renderer, volume, { bounds: new Box3().setFromObject( room ) } );
 * const lightMapper = new LightMapper( renderer, 512, source.irradiance );
 * lightMapper.addObjects( meshes ); // with uv1, e.g. from unwrapUVs
 * lightMapper.update( 16 );
 * ```
 */
export class ProbeVolumeIrradiance {

	/** The resampled volume (its `texture` is what the node reads). */
	readonly volumeTexture: ProbeVolumeTexture;

	/**
	 * `( position, normal ) => vec3 node`: E(n) at a world position and world normal, to pass to
	 * `LightMapper` as its irradiance function (the sample index is not needed). Outside `bounds`
	 * the light is that of the box's nearest point (the texture is clamped there, unlike the
	 * volume's outer cells). The normal is used as given, as `SphericalHarmonics3.getIrradianceAt`
	 * uses it (LightMapper passes unit normals): a zero normal gives the constant term, no NaN.
	 */
	readonly irradiance: ( position: TSLNode, normal: TSLNode ) => TSLNode;

	private readonly intensityNode: TSLNode;
	private disposed = false;

	/**
	 * @param renderer A `WebGPURenderer` (three's `LightMapper` runs only there).
	 * @param volume A captured `LightProbeVolume`.
	 * @param options See {@link ProbeVolumeIrradianceOptions}.
	 */
	constructor( renderer: unknown, volume: LightProbeVolume, options: ProbeVolumeIrradianceOptions = {} ) {

		const where = 'ProbeVolumeIrradiance';
		if ( ( renderer as { isWebGPURenderer?: boolean } | null )?.isWebGPURenderer !== true ) {

			throw new TypeError( `${where}: expected a WebGPURenderer (three's LightMapper is WebGPU-only), got ${describeValue( renderer )}.` );

		}

		const sh = ( volume as { sh?: unknown } | null )?.sh;
		if ( ! ( sh instanceof Float32Array ) || ( volume as { interpolator?: unknown } ).interpolator === undefined ) {

			throw new TypeError( `${where}: expected a LightProbeVolume, got ${describeValue( volume )}.` );

		}

		assertUsableProbeField( where, volume );
		if ( ! sh.some( ( v ) => v !== 0 ) ) throw new Error( `${where}: the volume has no light yet; call volume.capture( renderer, scene ) first.` );
		// Checked here so that bad options and bounds name this class, not the texture it makes.
		assertOptions( where, 'options', options );
		checkVolumeTextureOptions( where, options );
		if ( options.bounds !== undefined ) checkBounds( where, options.bounds );
		const intensity = options.intensity ?? 1;
		if ( typeof intensity !== 'number' || ! Number.isFinite( intensity ) || intensity < 0 ) {

			throw new RangeError( `${where}: options.intensity must be a finite number ≥ 0, got ${describeValue( intensity )}.` );

		}

		const { bounds, intensity: _, ...textureOptions } = options;
		this.volumeTexture = new ProbeVolumeTexture( volume, bounds ?? probeBounds( volume ), textureOptions );
		this.intensityNode = uniform( intensity );
		const atlas = texture3D( this.volumeTexture.texture );
		const grid = this.volumeTexture;
		const min = uniform( grid.min ), max = uniform( grid.max ), res = uniform( grid.resolution );
		this.irradiance = ( position, normal ) => {

			if ( this.disposed ) throw new Error( 'ProbeVolumeIrradiance.irradiance: called after dispose().' );
			return atlasIrradiance( atlas, min, max, res, position, normal ).mul( this.intensityNode );

		};

	}

	/** Scale of the light; change it, then re-bake (`lightMapper.reset()`, `update()`). */
	get intensity(): number {

		return this.intensityNode.value;

	}

	set intensity( value: number ) {

		if ( this.disposed ) throw new Error( 'ProbeVolumeIrradiance.intensity: set after dispose().' );
		if ( typeof value !== 'number' || ! Number.isFinite( value ) || value < 0 ) {

			throw new RangeError( `ProbeVolumeIrradiance.intensity: expected a finite number ≥ 0, got ${describeValue( value )}.` );

		}

		this.intensityNode.value = value;

	}

	/** Resamples the volume after a capture or probe edit (then re-bake the light map). */
	update(): void {

		const where = 'ProbeVolumeIrradiance.update';
		if ( this.disposed ) throw new Error( `${where}: called after dispose().` );
		// The texture would check too, under its own name; nothing is written when this throws.
		assertUsableProbeField( where, this.volumeTexture.field );
		this.volumeTexture.resample();

	}

	/** Frees the resampling texture; the object is unusable afterwards (a second call does nothing). */
	dispose(): void {

		this.disposed = true;
		this.volumeTexture.dispose();

	}

}

/** The probes' box grown by one probe spacing, so walls just outside the hull are covered. */
function probeBounds( volume: LightProbeVolume ): Box3 {

	const b = boundsOf( volume.positions );
	return new Box3( new Vector3( b[ 0 ], b[ 1 ], b[ 2 ] ), new Vector3( b[ 3 ], b[ 4 ], b[ 5 ] ) ).expandByScalar( volume.probeSpacing );

}

/** Bounds must be { min, max } with finite corners, min ≤ max on every axis and not a single point. */
function checkBounds( where: string, bounds: unknown ): void {

	const b = bounds as BoundsLike | null;
	const corners = b?.min && b?.max ? [ b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z ] : null;
	if ( corners === null || corners.some( ( v ) => typeof v !== 'number' || ! Number.isFinite( v ) ) ) {

		throw new RangeError( `${where}: options.bounds must be { min, max } with finite x, y, z (e.g. a Box3 of the meshes; an empty Box3 has infinite corners), got ${describeValue( bounds )}.` );

	}

	const size = [ corners[ 3 ] - corners[ 0 ], corners[ 4 ] - corners[ 1 ], corners[ 5 ] - corners[ 2 ] ];
	if ( size.some( ( s ) => s < 0 ) ) throw new RangeError( `${where}: options.bounds.min must not exceed options.bounds.max, got size (${size.join( ', ' )}).` );
	if ( ! size.some( ( s ) => s > 0 ) ) throw new RangeError( `${where}: options.bounds is a single point; there is nothing to resample over.` );

}
