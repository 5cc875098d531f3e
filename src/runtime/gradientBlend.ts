import { blendGradientSH } from '../interpolation/blendGradientSH.js';
import { blendSH } from '../interpolation/blendSH.js';

/**
 * The probes' SH blended at (x, y, z) with the given weights: gradient probes (`gradients` not null) by the gradient
 * formula ({@link blendGradientSH}) at that point, plain probes by `blendSH` — the one choice every blend site of the
 * runtime makes. Allocation-free.
 * @param positions x, y, z per probe; read only with gradients.
 * @returns `out`.
 */
export function blendProbes<T extends Float32Array | Float64Array>(
	indices: ArrayLike<number>, weights: ArrayLike<number>, count: number, sh: Float32Array,
	gradients: Float32Array | null | undefined, positions: ArrayLike<number> | undefined, x: number, y: number, z: number, out: T,
): T {

	if ( gradients === null || gradients === undefined ) return blendSH( indices, weights, sh, out, count );
	return blendGradientSH( indices, weights, sh, gradients, positions!, x, y, z, out, count );

}
