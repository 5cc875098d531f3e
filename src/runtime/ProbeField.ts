import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { SH_LIMIT, firstBeyond } from '../validate.js';
import { GRADIENT_FLOATS, badGradientError, firstBadGradient } from './gradientProbes.js';

/**
 * What the large-object lighting classes read: an interpolation structure and its probes' SH —
 * a `LightProbeVolume` is one as it is (`volume.interpolator`, `volume.sh`, and for gradient probes
 * `volume.gradients`, `volume.positions`). They resample whenever the values of `sh` or `gradients`
 * change (e.g. after a recapture), so no notification is needed.
 */
export interface ProbeField {

	/** Turns a world position into probe indices and weights (tetrahedral, planar or grid). */
	readonly interpolator: ProbeInterpolator;

	/** 27 floats per probe, three.js `SphericalHarmonics3` layout, `interpolator.probeCount` probes. */
	readonly sh: Float32Array;

	/**
	 * Gradient probes: 81 floats per probe (`gradients[ 81·i + 27·a + k ]` = ∂(SH float k)/∂(axis a)), blended at each
	 * point by `blendGradientSH`; null or absent for plain probes. Needs `positions`.
	 */
	readonly gradients?: Float32Array | null;

	/** x, y, z per probe (`interpolator.probeCount` probes): where each probe's gradient is anchored. */
	readonly positions?: Float64Array;

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
	const gradients = candidate.gradients;
	if ( gradients === null || gradients === undefined ) return;
	if ( ! ( gradients instanceof Float32Array ) || gradients.length !== GRADIENT_FLOATS * probes ) {

		throw new RangeError( `${where}: field.gradients must be null or a Float32Array of 81 × ${probes} probes = ${GRADIENT_FLOATS * probes} floats.` );

	}

	if ( ! ( candidate.positions instanceof Float64Array ) || candidate.positions.length !== 3 * probes ) {

		throw new RangeError( `${where}: a field with gradients needs field.positions, a Float64Array of 3 × ${probes} probes = ${3 * probes} coordinates.` );

	}

}

/**
 * {@link assertProbeField}, and its SH finite and within ±`SH_LIMIT`, its gradients (if any) within `gradientLimit`: for
 * constructors, before they change anything.
 */
export function assertUsableProbeField( where: string, field: unknown ): asserts field is ProbeField {

	assertProbeField( where, field );
	const sh = field.sh, i = firstBeyond( sh, SH_LIMIT );
	if ( i >= 0 ) throw new RangeError( `${where}: field.sh[${i}] is ${sh[ i ]}; probe SH must be finite and within ±${SH_LIMIT.toPrecision( 3 )}.` );
	const gradients = field.gradients;
	const bad = gradients ? firstBadGradient( gradients, field.positions! ) : - 1;
	if ( bad >= 0 ) throw badGradientError( where, 'field.gradients', gradients!, bad, field.positions! );

}

/**
 * Whether `sh` differs from `copy` (length or any value); when it does, checks `sh` is finite and
 * within ±`SH_LIMIT` (so nothing non-finite is ever uploaded) and
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

	const i = firstBeyond( sh, SH_LIMIT );
	if ( i >= 0 ) throw new RangeError( `${where}: field.sh[${i}] is ${sh[ i ]}; probe SH must be finite and within ±${SH_LIMIT.toPrecision( 3 )}.` );

	const next = copy !== null && copy.length === sh.length ? copy : new Float32Array( sh.length );
	next.set( sh );
	return next;

}
