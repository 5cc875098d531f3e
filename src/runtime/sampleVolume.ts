/* `LightProbeVolume.sample`: the blend an object at a point would get, computed on demand. */
import { assertOptions } from '../validate.js';
import { blendProbes } from './gradientBlend.js';
import type { ProbePosition, SampleOptions } from './LightProbeVolumeOptions.js';
import type { ProbeWeighting } from './ProbeWeighting.js';
import { zoneIndexOf, type ProbeZones } from './ProbeZones.js';
import { assertSHTarget, readPosition } from './volumeArguments.js';

/** The fields of a `LightProbeVolume` that {@link sampleVolume} reads. */
export interface SampledVolume {

	readonly positions: Float64Array;
	readonly sh: Float32Array;
	readonly gradients: Float32Array | null;
	readonly zones: ProbeZones | null;

}

/**
 * Checks `sample`'s arguments (errors naming `where`), weighs the probes at `position` as for a registered object (its
 * zone or `options.zone`, the visibility guard tested afresh) and writes the blend (gradient formula included) into `target`.
 */
export function sampleVolume(
	where: string, volume: SampledVolume, weighting: ProbeWeighting, position: ProbePosition, target: Float32Array, options: SampleOptions,
): Float32Array {

	const [ x, y, z ] = readPosition( where, position );
	assertSHTarget( where, target );
	assertOptions( where, 'options', options );
	const zones = volume.zones;
	const zone = options.zone !== undefined ? zoneIndexOf( where, zones, options.zone ) : ( zones ? zones.zoneAt( x, y, z ) : - 1 );
	weighting.weigh( x, y, z, zone, - 1, null );
	const { indices, weights, count } = weighting;
	return blendProbes( indices, weights, count, volume.sh, volume.gradients, volume.positions, x, y, z, target );

}
