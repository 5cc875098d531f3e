import { GRADIENT_FLOATS, badGradientError, firstBadGradient } from './gradientProbes.js';

/**
 * Notices when a field's gradients change — new values, a new length, gradients appearing or going (null) — as
 * `trackSH` does for its SH, so the lightings that resample a field do so for gradients too. Keeps a copy;
 * allocation-free while nothing changes (per-frame `update()` calls).
 */
export class GradientTracker {

	private copy: Float32Array | null = null;

	/**
	 * Whether `gradients` differ from what the last call saw. Changed gradients are checked first — 81 per probe of
	 * `positions`, finite and within `gradientLimit( positions )` — else a RangeError naming `where`, with nothing
	 * recorded (the next call checks again).
	 * @param gradients The field's gradients (81 per probe), or null / undefined for plain probes.
	 * @param positions The field's probe positions (for the bound).
	 * @param name How the messages name the gradients.
	 */
	changed(
		where: string, gradients: Float32Array | null | undefined, positions: ArrayLike<number> | undefined, name = 'field.gradients',
	): boolean {

		const copy = this.copy;
		if ( gradients === null || gradients === undefined ) {

			this.copy = null;
			return copy !== null;

		}

		if ( copy !== null && copy.length === gradients.length ) {

			let i = 0;
			const n = gradients.length;
			while ( i < n && gradients[ i ] === copy[ i ] ) i ++;
			if ( i === n ) return false;

		}

		const probes = ( positions?.length ?? 0 ) / 3;
		if ( gradients.length !== GRADIENT_FLOATS * probes ) {

			throw new RangeError( `${where}: ${name} has length ${gradients.length}; expected 81 × ${probes} probes = ${GRADIENT_FLOATS * probes}.` );

		}

		const bad = firstBadGradient( gradients, positions ?? [] );
		if ( bad >= 0 ) throw badGradientError( where, name, gradients, bad, positions ?? [] );
		const next = copy !== null && copy.length === gradients.length ? copy : new Float32Array( gradients.length );
		next.set( gradients );
		this.copy = next;
		return true;

	}

	/** Forgets what was seen: the next {@link GradientTracker.changed} with gradients reports a change. */
	reset(): void {

		this.copy = null;

	}

}
