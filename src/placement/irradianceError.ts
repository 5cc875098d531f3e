import { assertArrayLike, assertPoints, assertSH } from '../validate.js';
import { irradianceAt } from '../sh/irradiance.js';

/**
 * The 26 directions the error is measured in: from the centre of a 3×3×3 block of cubes to each of
 * its 26 neighbours, normalised — the 6 axes, the 12 edge diagonals and the 8 corner diagonals.
 * They sample the sphere evenly enough for order-2 SH irradiance (a quadratic in n) and include
 * the axis directions that floors and walls face.
 */
export const IRRADIANCE_ERROR_NORMALS: Float64Array = ( () => {

	const out: number[] = [];
	for ( let z = - 1; z <= 1; z ++ ) for ( let y = - 1; y <= 1; y ++ ) for ( let x = - 1; x <= 1; x ++ ) {

		if ( x === 0 && y === 0 && z === 0 ) continue;
		const length = Math.sqrt( x * x + y * y + z * z );
		out.push( x / length, y / length, z / length );

	}

	return Float64Array.from( out );

} )();

/** Summary of an irradiance error over points (see {@link irradianceError}). */
export interface IrradianceErrorSummary {

	/** Mean of the per-point errors. */
	mean: number;

	/** 95th percentile of the per-point errors (nearest rank). */
	p95: number;

	/** Largest per-point error. */
	max: number;

}

/** {@link IrradianceErrorSummary} plus the error of each point. */
export interface IrradianceErrorResult extends IrradianceErrorSummary {

	/** Error of each point, in point order. */
	perPoint: Float64Array;

	/** The normaliser: mean true irradiance over all points (weighted, with weights), normals and colour channels. */
	meanIrradiance: number;

}

/**
 * The one error measure of probe layouts in this library: how far predicted irradiance is from
 * the truth, relative to the scene's mean irradiance. For point p,
 *
 *     error_p = (1/K) Σ_k max_c | E_pred,c(p, n_k) − E_true,c(p, n_k) |  /  Ē
 *     Ē = mean over all points, all K normals and the 3 channels of E_true,c(p, n_k)
 *
 * with E(n) the Ramamoorthi–Hanrahan irradiance of the SH9 (`evaluateIrradiance`, what a
 * Lambertian surface facing n receives) and n_k the {@link IRRADIANCE_ERROR_NORMALS} by default.
 * Reported: mean, 95th percentile and max over points; 0.05 means "off by 5 % of the average
 * irradiance". With `weights` (e.g. a region of interest, `regionWeights`), the mean, the 95th
 * percentile and Ē are weighted and the max is over points of weight > 0: weights 1 inside a region
 * and 0 outside give exactly the error of the inside points alone.
 *
 * Why these choices:
 * - **Irradiance, not SH coefficients**: what a diffuse surface shows; coefficient differences
 *   weigh the L2 band (which irradiance attenuates to a quarter) as much as L0.
 * - **Max over RGB**: luminance weighting would count a blue error 10× less than a green one
 *   (0.07 vs 0.72), hiding exactly the colour bleeding the paper places probes for; the max
 *   catches a wrong tint in any channel.
 * - **One global normaliser Ē** (not each point's own brightness): a dark corner's error is judged
 *   against the scene's light level, as the eye sees it next to the lit parts, instead of blowing
 *   up as its own irradiance goes to 0.
 * - **Mean over normals**: an object shows all its sides; a single bad direction still counts
 *   1/26 per point and dominates `max`.
 *
 * `reduceProbes` uses exactly this measure (through {@link irradianceAtNormals} and
 * {@link irradianceErrorFromTables}).
 * @param predictedSH 27 floats per point, e.g. the layout's interpolation at each dense probe.
 * @param trueSH 27 floats per point, the same count: the captured truth.
 * @param normals Directions, x, y, z each, unit length (default {@link IRRADIANCE_ERROR_NORMALS}; `undefined` for the default).
 * @param weights One weight ≥ 0 per point, not all 0 (default: all count alike).
 */
export function irradianceError(
	predictedSH: ArrayLike<number>, trueSH: ArrayLike<number>, normals: ArrayLike<number> = IRRADIANCE_ERROR_NORMALS,
	weights?: ArrayLike<number>,
): IrradianceErrorResult {

	const where = 'irradianceError';
	const count = assertSH( where, 'trueSH', trueSH );
	assertSH( where, 'predictedSH', predictedSH, count );
	assertPoints( where, 'normals', normals, 1 );
	if ( weights !== undefined ) assertPointWeights( where, 'weights', weights, count );
	const truth = irradianceAtNormals( trueSH, normals );
	const predicted = irradianceAtNormals( predictedSH, normals );
	return irradianceErrorFromTables( predicted, truth, normals.length / 3, where, weights );

}

/**
 * Checks per-point weights: one finite number ≥ 0 per point, not all 0.
 * @param where Function name for messages.
 * @param name The argument's name for messages.
 * @param count The number of points.
 */
export function assertPointWeights( where: string, name: string, weights: unknown, count: number ): asserts weights is ArrayLike<number> {

	assertArrayLike( where, name, weights );
	if ( weights.length !== count ) throw new RangeError( `${where}: ${name} must have one weight per point (${count}), got length ${weights.length}.` );
	let sum = 0;
	for ( let p = 0; p < count; p ++ ) {

		const w = weights[ p ];
		if ( typeof w !== 'number' || ! ( w >= 0 ) || w === Infinity ) {

			throw new RangeError( `${where}: ${name}[${p}] is ${String( w )}; weights must be finite numbers ≥ 0.` );

		}

		sum += w;

	}

	if ( ! ( sum > 0 ) ) throw new RangeError( `${where}: ${name} are all 0; at least one point must count.` );

}

/**
 * Irradiance of every probe in every direction: `out[3 · (K · p + k) + c]` is channel c of
 * E(n_k) for probe p (K = number of normals). Irradiance is linear in the SH, so the table of a
 * blend is the same blend of the tables: `reduceProbes` interpolates these instead of SH.
 * @param sh 27 floats per probe.
 * @param normals Directions, x, y, z each.
 */
export function irradianceAtNormals( sh: ArrayLike<number>, normals: ArrayLike<number> ): Float64Array {

	const count = sh.length / 27, directions = normals.length / 3;
	const out = new Float64Array( 3 * directions * count );
	const basis = irradianceBasis( normals );
	for ( let p = 0; p < count; p ++ ) irradianceRow( sh, 27 * p, basis, out, 3 * directions * p );
	return out;

}

/**
 * The factor of each SH coefficient in the irradiance at each normal: `basis[ 9k + b ]` for
 * coefficient b at normal k, taken from `irradianceAt` itself (a unit coefficient gives its factor
 * exactly), so {@link irradianceRow} adds the same products in the same order as `evaluateIrradiance`.
 * @param normals Directions, x, y, z each.
 */
export function irradianceBasis( normals: ArrayLike<number> ): Float64Array {

	const directions = normals.length / 3;
	const basis = new Float64Array( 9 * directions ), unit = new Float64Array( 27 ), value = new Float64Array( 3 );
	for ( let k = 0; k < directions; k ++ ) {

		for ( let b = 0; b < 9; b ++ ) {

			unit.fill( 0 );
			unit[ 3 * b ] = 1;
			irradianceAt( unit, 0, normals[ 3 * k ], normals[ 3 * k + 1 ], normals[ 3 * k + 2 ], value, 0 );
			basis[ 9 * k + b ] = value[ 0 ];

		}

	}

	return basis;

}

/**
 * One SH's row of an irradiance table — `evaluateIrradiance` at each normal, the same numbers,
 * without its argument checks: `out[ outOffset + 3k + c ]` is channel c of E(n_k).
 * @param sh Holds the SH's 27 floats at `shOffset`.
 * @param basis {@link irradianceBasis} of the normals.
 */
export function irradianceRow( sh: ArrayLike<number>, shOffset: number, basis: Float64Array, out: Float64Array, outOffset: number ): void {

	for ( let k = 0, directions = basis.length / 9; k < directions; k ++ ) {

		const t = 9 * k;
		const b0 = basis[ t ], b1 = basis[ t + 1 ], b2 = basis[ t + 2 ], b3 = basis[ t + 3 ], b4 = basis[ t + 4 ];
		const b5 = basis[ t + 5 ], b6 = basis[ t + 6 ], b7 = basis[ t + 7 ], b8 = basis[ t + 8 ];
		for ( let c = 0; c < 3; c ++ ) {

			const s = shOffset + c;
			out[ outOffset + 3 * k + c ] = b0 * sh[ s ] + b1 * sh[ s + 3 ] + b2 * sh[ s + 6 ] + b3 * sh[ s + 9 ]
				+ b4 * sh[ s + 12 ] + b5 * sh[ s + 15 ] + b6 * sh[ s + 18 ] + b7 * sh[ s + 21 ] + b8 * sh[ s + 24 ];

		}

	}

}

/**
 * One point's predicted row of a per-probe table (e.g. {@link irradianceAtNormals}): the rows of the
 * probes an interpolator named, blended with its weights — `out = Σ_k weights[k] · row(layout[indices[k]])`,
 * zero weights skipped. Shared by `reduceProbes` and the experiment's selection, so both predict alike.
 * @param table `stride` floats per probe of the dense set.
 * @param layout Dense index of each layout probe (the interpolator's probe k is dense probe `layout[k]`).
 * @param indices Layout probe indices, as an interpolator wrote them; `weights` the same length.
 * @param out Receives the row (`stride` floats); returned.
 */
export function blendRows(
	table: ArrayLike<number>, stride: number, layout: ArrayLike<number>,
	indices: ArrayLike<number>, weights: ArrayLike<number>, out: Float64Array
): Float64Array {

	out.fill( 0, 0, stride );
	for ( let k = 0; k < weights.length; k ++ ) {

		const w = weights[ k ];
		if ( w === 0 ) continue;
		const source = stride * layout[ indices[ k ] ];
		for ( let j = 0; j < stride; j ++ ) out[ j ] += w * table[ source + j ];

	}

	return out;

}

/**
 * {@link irradianceError} from irradiance tables (as made by {@link irradianceAtNormals}): the
 * shared arithmetic, so every caller measures the same thing. `weights` (one per point, checked by
 * the caller) weight the summary and Ē as in {@link irradianceError}.
 * @param predicted Predicted irradiance table.
 * @param truth True irradiance table, same layout and length.
 * @param directions Number of normals K the tables were made with.
 * @param where Function name for error messages.
 */
export function irradianceErrorFromTables(
	predicted: ArrayLike<number>, truth: ArrayLike<number>, directions: number, where = 'irradianceErrorFromTables', weights?: ArrayLike<number>,
): IrradianceErrorResult {

	const { meanIrradiance, scale } = irradianceErrorScale( truth, directions, where, weights );
	const count = truth.length / ( 3 * directions );
	const perPoint = new Float64Array( count );
	for ( let p = 0; p < count; p ++ ) {

		perPoint[ p ] = pointIrradianceError( predicted, 3 * directions * p, truth, 3 * directions * p, directions, scale );

	}

	return { ...summarizeErrors( perPoint, weights ), perPoint, meanIrradiance };

}

/**
 * One point's error from its rows of two irradiance tables: Σ_k max_c |predicted − truth| · scale,
 * with `scale = 1 / (K · Ē)` (see {@link irradianceError}). Shared by every caller so the
 * arithmetic is the same everywhere.
 * @param predicted Table holding the point's predicted row at `predictedOffset` (3 · K floats).
 * @param truth Table holding its true row at `truthOffset`.
 * @param directions K, the number of normals.
 * @param scale 1 / (K · mean true irradiance).
 */
export function pointIrradianceError(
	predicted: ArrayLike<number>, predictedOffset: number, truth: ArrayLike<number>, truthOffset: number, directions: number, scale: number
): number {

	let sum = 0;
	for ( let k = 0; k < 3 * directions; k += 3 ) {

		const a = predictedOffset + k, b = truthOffset + k;
		const r = Math.abs( predicted[ a ] - truth[ b ] ), g = Math.abs( predicted[ a + 1 ] - truth[ b + 1 ] );
		const bl = Math.abs( predicted[ a + 2 ] - truth[ b + 2 ] );
		sum += r > g ? ( r > bl ? r : bl ) : ( g > bl ? g : bl );

	}

	return sum * scale;

}

/**
 * The normaliser of {@link irradianceError} for a true irradiance table: Ē, the mean of all its
 * entries (with `weights`, one per point: the weighted mean of the points' row means), and
 * `scale = 1 / (K · Ē)` for {@link pointIrradianceError}.
 * @throws RangeError when Ē ≤ 0 (all-black truth: a relative error means nothing).
 */
export function irradianceErrorScale(
	truth: ArrayLike<number>, directions: number, where = 'irradianceErrorScale', weights?: ArrayLike<number>,
): { meanIrradiance: number; scale: number } {

	const meanIrradiance = weights === undefined ? meanOf( truth ) : weightedRowMean( truth, 3 * directions, weights );
	if ( ! ( meanIrradiance > 0 ) ) {

		throw new RangeError( `${where}: the true irradiance averages ${meanIrradiance} over all points and normals; the relative error needs a positive mean (is the SH all black?).` );

	}

	return { meanIrradiance, scale: 1 / ( directions * meanIrradiance ) };

}

/**
 * Mean, 95th percentile (nearest rank) and max of per-point errors. With `weights` (one ≥ 0 per
 * point, not all 0): the weighted mean, the weighted nearest rank (the smallest error whose
 * cumulative weight, in ascending order, reaches 95 % of the total) and the max over points of
 * weight > 0.
 */
export function summarizeErrors( perPoint: ArrayLike<number>, weights?: ArrayLike<number> ): IrradianceErrorSummary {

	const count = perPoint.length;
	if ( count === 0 ) return { mean: 0, p95: 0, max: 0 };
	if ( weights !== undefined ) return summarizeWeighted( perPoint, weights );
	const sorted = Float64Array.from( perPoint ).sort();
	return { mean: meanOf( perPoint ), p95: sorted[ Math.ceil( 0.95 * count ) - 1 ], max: sorted[ count - 1 ] };

}

function summarizeWeighted( perPoint: ArrayLike<number>, weights: ArrayLike<number> ): IrradianceErrorSummary {

	const byError = Array.from( { length: perPoint.length }, ( _, p ) => p ).filter( ( p ) => weights[ p ] > 0 )
		.sort( ( a, b ) => perPoint[ a ] - perPoint[ b ] || a - b );
	let total = 0, sum = 0;
	for ( const p of byError ) {

		total += weights[ p ];
		sum += weights[ p ] * perPoint[ p ];

	}

	if ( byError.length === 0 ) return { mean: 0, p95: 0, max: 0 };
	// The rank's cumulative weight is compared with a small slack, so 20 equal weights reach 95 % at the 19th as counts do.
	const rank = 0.95 * total * ( 1 - 1e-12 );
	let cumulative = 0, p95 = perPoint[ byError[ byError.length - 1 ] ];
	for ( const p of byError ) {

		cumulative += weights[ p ];
		if ( cumulative >= rank ) {

			p95 = perPoint[ p ];
			break;

		}

	}

	return { mean: sum / total, p95, max: perPoint[ byError[ byError.length - 1 ] ] };

}

/** Σ_p w_p · mean( row p ) / Σ_p w_p over a table of `stride` floats per point. */
function weightedRowMean( table: ArrayLike<number>, stride: number, weights: ArrayLike<number> ): number {

	let sum = 0, total = 0;
	for ( let p = 0; p < weights.length; p ++ ) {

		const w = weights[ p ];
		if ( w === 0 ) continue;
		let row = 0;
		for ( let j = stride * p, end = j + stride; j < end; j ++ ) row += table[ j ];
		sum += w * row / stride;
		total += w;

	}

	return total > 0 ? sum / total : 0;

}

function meanOf( values: ArrayLike<number> ): number {

	let sum = 0;
	for ( let i = 0; i < values.length; i ++ ) sum += values[ i ];
	return values.length > 0 ? sum / values.length : 0;

}
