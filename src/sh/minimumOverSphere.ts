/**
 * The exact minimum over all directions of one probe's reconstructed irradiance or radiance:
 * the test the non-negative switch relies on, exposed for checks and diagnostics.
 */

import { SH_FLOATS, assertInteger, assertOutput } from '../validate.js';
import { SHSphereMinimum, type SphereQuantity } from './SHSphereMinimum.js';
import { assertProbeFinite, assertSHArray } from './deringingArguments.js';
import type { WritableArrayLike } from './irradiance.js';

// Reusable scratch: prepared and read within one call.
const sphereMinimum = new SHSphereMinimum();

/**
 * The exact minimum over all unit normals of the irradiance E(n) reconstructed from one probe's
 * SH9 (the quadratic form of {@link irradianceMatrices}, what the patched materials shade), per
 * colour channel. Never above the true minimum: rounding can only make it conservative.
 * @param sh SH array, 27 floats per probe.
 * @param shOffset Index of the probe's first float (default 0), e.g. 27·probeIndex.
 * @param perChannel Receives the R, G, B minima in entries 0..2 when given.
 * @param directions Receives, when given, a unit normal attaining each channel's minimum
 * (R's x, y, z, then G's, then B's: 9 floats).
 * @returns The smallest of the three channel minima.
 */
export function minIrradiance(
	sh: ArrayLike<number>, shOffset = 0, perChannel?: WritableArrayLike, directions?: WritableArrayLike,
): number {

	return minimumOf( 'minIrradiance', 'irradiance', sh, shOffset, perChannel, directions );

}

/**
 * The exact minimum over all directions of the radiance L(ω) reconstructed from one probe's SH9
 * (three's `SphericalHarmonics3.getAt`), per channel, as {@link minIrradiance}. Radiance rings more
 * than irradiance: it matters for SH drawn as a sky or a reflection.
 * @param sh SH array, 27 floats per probe.
 * @param shOffset Index of the probe's first float (default 0).
 * @param perChannel Receives the R, G, B minima in entries 0..2 when given.
 * @param directions Receives a unit direction attaining each channel's minimum (9 floats) when given.
 * @returns The smallest of the three channel minima.
 */
export function minRadiance(
	sh: ArrayLike<number>, shOffset = 0, perChannel?: WritableArrayLike, directions?: WritableArrayLike,
): number {

	return minimumOf( 'minRadiance', 'radiance', sh, shOffset, perChannel, directions );

}

function minimumOf(
	where: string, quantity: SphereQuantity, sh: ArrayLike<number>, shOffset: number,
	perChannel?: WritableArrayLike, directions?: WritableArrayLike,
): number {

	assertSHArray( where, sh );
	assertInteger( where, 'shOffset', shOffset, 0, sh.length - SH_FLOATS );
	assertProbeFinite( where, sh, shOffset );
	if ( perChannel !== undefined ) assertOutput( where, 'perChannel', perChannel, 3 );
	if ( directions !== undefined ) assertOutput( where, 'directions', directions, 9 );

	sphereMinimum.prepare( quantity, sh, shOffset );
	let smallest = Infinity;
	for ( let channel = 0; channel < 3; channel ++ ) {

		const value = sphereMinimum.channelMinimum( channel, 1, 1 );
		if ( perChannel !== undefined ) perChannel[ channel ] = value;
		if ( value < smallest ) smallest = value;
		if ( directions !== undefined ) sphereMinimum.writeDirection( channel, directions, 3 * channel );

	}

	return smallest;

}
