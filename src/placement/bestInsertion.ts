import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import { blendRows, pointIrradianceError } from './irradianceError.js';

/** What {@link bestInsertion} reads: the dense set and its irradiance tables, as `reduceProbes` holds them. */
export interface InsertionContext {

	/** Positions of the points the error is measured at, x, y, z each: the dense candidates first, then any extra fit samples. */
	points: Float64Array;

	/** Per point, its irradiance at every normal (`irradianceAtNormals`), `stride` floats each. */
	truth: Float64Array;

	/** Floats per table row: 3 × the number of normals. */
	stride: number;

	/** The error's normaliser (`irradianceErrorScale`). */
	scale: number;

	/** Point indices along a Hilbert curve: the visiting order that keeps each point location short. */
	visitOrder: Uint32Array;

	/** Seeded rank per dense probe, for ties. */
	rank: Uint32Array;

	/** One weight per point (region of interest), or null: all count alike. */
	weights: Float64Array | null;

}

/**
 * Of the `trials` dense probes not in the subset with the largest (weighted) error `perPoint`, the
 * one whose insertion lowers the subset's (weighted) mean error over the points most (each trial: a
 * new tetrahedralization of the subset plus it, and one interpolation per point). Ties go to the
 * lower seeded rank. `reduceProbes`' `strategy: 'mean'`.
 * @param order The subset, dense indices.
 * @param selected Per dense probe: 1 when in the subset (its length is the number of dense probes).
 * @returns A dense index, or −1 when no probe is left out.
 */
export function bestInsertion(
	context: InsertionContext, order: readonly number[], selected: Uint8Array, perPoint: Float64Array, trials: number,
): number {

	const { points, rank, weights } = context, denseCount = selected.length;
	const candidates: number[] = [];
	for ( let p = 0; p < denseCount; p ++ ) if ( selected[ p ] === 0 ) candidates.push( p );
	const claim = ( p: number ): number => weights === null ? perPoint[ p ] : weights[ p ] * perPoint[ p ];
	candidates.sort( ( a, b ) => claim( b ) - claim( a ) || rank[ a ] - rank[ b ] );
	const subset = new Float64Array( 3 * ( order.length + 1 ) );
	order.forEach( ( i, s ) => subset.set( points.subarray( 3 * i, 3 * i + 3 ), 3 * s ) );
	const layout = [ ...order, - 1 ];
	let best = - 1, bestMean = Infinity;
	for ( const candidate of candidates.slice( 0, trials ) ) {

		subset.set( points.subarray( 3 * candidate, 3 * candidate + 3 ), 3 * order.length );
		layout[ order.length ] = candidate;
		const mean = meanError( context, subset, layout );
		if ( mean < bestMean || ( mean === bestMean && rank[ candidate ] < rank[ best ] ) ) {

			best = candidate;
			bestMean = mean;

		}

	}

	return best;

}

/** (Weighted) mean error over the points of the layout at `subset` (positions) / `layout` (dense indices). */
function meanError( context: InsertionContext, subset: Float64Array, layout: readonly number[] ): number {

	const { points, truth, stride, scale, visitOrder, weights: pointWeights } = context, count = points.length / 3, directions = stride / 3;
	const interpolator = createProbeInterpolator( subset );
	const indices = _indices, weights = _weights, row = rowOf( stride );
	let hint = - 1, sum = 0, total = 0;
	for ( let v = 0; v < count; v ++ ) {

		const p = visitOrder[ v ];
		const w = pointWeights === null ? 1 : pointWeights[ p ];
		total += w;
		if ( w === 0 ) continue;
		hint = interpolator.interpolate( points[ 3 * p ], points[ 3 * p + 1 ], points[ 3 * p + 2 ], indices, weights, hint );
		blendRows( truth, stride, layout, indices, weights, row );
		sum += w * pointIrradianceError( row, 0, truth, stride * p, directions, scale );

	}

	return pointWeights === null ? sum / count : sum / total;

}

// Scratch of `meanError` (the blend row grows to the largest stride seen).
const _indices = new Uint32Array( 4 ), _weights = new Float64Array( 4 );
let _row = new Float64Array( 78 );

function rowOf( stride: number ): Float64Array {

	if ( _row.length < stride ) _row = new Float64Array( stride );
	return _row;

}
