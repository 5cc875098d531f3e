import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';

/**
 * What the large-object lighting classes read: an interpolation structure and its probes' SH —
 * a `LightProbeVolume` is one as it is (`volume.interpolator`, `volume.sh`). They resample
 * whenever `sh`'s values change (e.g. after a recapture), so no notification is needed.
 */
export interface ProbeField {

	/** Turns a world position into probe indices and weights (tetrahedral, planar or grid). */
	readonly interpolator: ProbeInterpolator;

	/** 27 floats per probe, three.js `SphericalHarmonics3` layout, `interpolator.probeCount` probes. */
	readonly sh: Float32Array;

}

/** Checks a {@link ProbeField} argument; throws an Error naming `where` and the problem. */
export function assertProbeField( where: string, field: unknown ): asserts field is ProbeField {

	const candidate = field as Partial<ProbeField> | null | undefined;
	if ( ! candidate || typeof candidate !== 'object' ) throw new TypeError( `${where}: field must be { interpolator, sh } (e.g. a LightProbeVolume), got ${field === null ? 'null' : typeof field}.` );
	if ( typeof candidate.interpolator?.interpolate !== 'function' ) throw new TypeError( `${where}: field.interpolator must implement ProbeInterpolator (interpolate, weightCount, probeCount).` );
	if ( ! ( candidate.sh instanceof Float32Array ) ) throw new TypeError( `${where}: field.sh must be a Float32Array of 27 floats per probe.` );
	const probes = candidate.interpolator.probeCount;
	if ( candidate.sh.length !== 27 * probes ) throw new RangeError( `${where}: field.sh has length ${candidate.sh.length}, expected 27 × ${probes} probes = ${27 * probes}.` );
	if ( candidate.interpolator.weightCount > 8 ) throw new RangeError( `${where}: field.interpolator.weightCount ${candidate.interpolator.weightCount} exceeds 8.` );

}

/**
 * Whether `sh` differs from `copy` (length or any value); when it does, checks `sh` is finite and
 * returns a copy to keep (a new array only when the length changed), else null. Allocation-free
 * when nothing changed: meant for per-frame `update()` calls.
 */
export function trackSH( where: string, sh: Float32Array, copy: Float32Array | null ): Float32Array | null {

	if ( copy !== null && copy.length === sh.length ) {

		let i = 0;
		const n = sh.length;
		while ( i < n && ( sh[ i ] === copy[ i ] ) ) i ++;
		if ( i === n ) return null;

	}

	for ( let i = 0, n = sh.length; i < n; i ++ ) {

		if ( ! Number.isFinite( sh[ i ] ) ) throw new RangeError( `${where}: field.sh[${i}] is ${sh[ i ]}; probe SH must be finite.` );

	}

	const next = copy !== null && copy.length === sh.length ? copy : new Float32Array( sh.length );
	next.set( sh );
	return next;

}
