import { Box3, Vector3 } from 'three';
import { texture3D, uniform } from 'three/tsl';
import { boundsOf } from '../../geometry/boundsOf.js';
import type { LightProbeVolume } from '../../runtime/LightProbeVolume.js';
import { ProbeVolumeTexture, type BoundsLike, type ProbeVolumeTextureOptions } from '../../runtime/ProbeVolumeTexture.js';
import { describeValue } from '../../validate.js';
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
	 * `( position, normal ) => vec3 node`: E(n) at a world position and unit world normal, to pass
	 * to `LightMapper` as its irradiance function (the sample index is not needed).
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

		if ( ! sh.some( ( v ) => v !== 0 ) ) throw new Error( `${where}: the volume has no light yet; call volume.capture( renderer, scene ) first.` );
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

		if ( typeof value !== 'number' || ! Number.isFinite( value ) || value < 0 ) {

			throw new RangeError( `ProbeVolumeIrradiance.intensity: expected a finite number ≥ 0, got ${describeValue( value )}.` );

		}

		this.intensityNode.value = value;

	}

	/** Resamples the volume after a capture or probe edit (then re-bake the light map). */
	update(): void {

		if ( this.disposed ) throw new Error( 'ProbeVolumeIrradiance.update: called after dispose().' );
		this.volumeTexture.resample();

	}

	/** Frees the resampling texture. */
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
