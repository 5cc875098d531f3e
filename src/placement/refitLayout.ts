import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import type { PlanarMesh } from '../interpolation/PlanarMesh.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import { fitProbeSHWithDesign, prepareFitSamples, type FitProbeSHResult, type PreparedFitSamples } from '../fitting/fitProbeSH.js';
import type { SampleDesign } from '../fitting/sampleDesign.js';
import {
	irradianceAtNormals, irradianceBasis, irradianceErrorScale, irradianceRow, summarizeErrors,
	type IrradianceErrorSummary,
} from './irradianceError.js';
import type { FitSettings, ReduceSettings } from './reduceOptions.js';
import { hilbertOrder } from './startingSet.js';

/** What every fit of one `reduceProbes` call shares: the fit set, its truth and weights, the objective. */
export interface RefitContext {

	where: string;

	/** Points of the fit set (dense candidates first), x, y, z each. */
	positions: Float64Array;

	/** Their captured SH, 27 each: the truth, and for candidates the SH a probe there is pulled toward. */
	sh: Float64Array;

	/** Dense candidates (the first points). */
	denseCount: number;

	/** One weight ≥ 0 per point (all 1 when none were given). */
	weights: Float64Array;

	/** The weights as `fitProbeSH` and the error summaries take them: undefined when all count alike. */
	givenWeights: Float64Array | undefined;

	/** Σ weights. */
	totalWeight: number;

	/** True irradiance of every point at every normal, `stride` floats each. */
	truth: Float64Array;

	/** 3 × the number of normals. */
	stride: number;

	/** The error's normals, as {@link irradianceBasis} factors. */
	basis: Float64Array;

	/** 1 / (K · Ē): the error's normaliser. */
	scale: number;

	/** Points along a Hilbert curve (short walks). */
	visitOrder: Uint32Array;

	/** The objective: gradients or not, non-negativity. */
	fit: FitSettings;

	/** The fit set as `fitProbeSH` takes it, checked and ordered once for every fit. */
	samples: PreparedFitSamples;

}

/** A subset fitted with `fitProbeSH`, and what its trials need: every point's weights and error. */
export interface FittedLayout {

	/** Dense index of each probe (local probe index = position here). */
	order: number[];

	/** Probe positions, 3 each. */
	positions: Float64Array;

	/** The interpolator the fit used (the runtime's: `createProbeInterpolator`). */
	interpolator: TetrahedralMesh | PlanarMesh;

	/** The fit. */
	result: FitProbeSHResult;

	/** Unknowns per probe (1, or 4 with gradients) × 27 floats: c, then h·∂c/∂x, h·∂c/∂y, h·∂c/∂z. */
	unknowns: Float64Array;

	/** Irradiance rows of the unknowns, `stride` rows per probe ({@link writeUnknownRows}). */
	rows: Float64Array;

	/** Unknowns per probe. */
	stride: number;

	/** h: the weighted RMS distance from a point to the probes that blend it (the gradient unknowns' unit). */
	lengthScale: number;

	/** Probes some point of positive weight reaches (the fit's n). */
	reached: number;

	/** Per point, 4 slots: the local probe (−1 for zero weight) and its weight. */
	slots: Int32Array;
	slotWeights: Float64Array;

	/** Per point: 1 when outside the probes' hull (outer cells). */
	outside: Uint8Array;

	/** Per point, the cell the interpolator returned for it (its hint: ≥ the tetrahedra count for an outer cell). */
	cells: Int32Array;

	/** Per local probe: 1 when it is a vertex of the hull. */
	hullVertex: Uint8Array;

	/** Every point's error under the fitted field. */
	errors: Float64Array;

	/** Weighted mean, p95 and max of `errors`. */
	summary: IrradianceErrorSummary;

	/** Per probe, the points of positive weight it blends: `adjacency[ adjacencyStart[ i ] … adjacencyStart[ i + 1 ] − 1 ]`. */
	adjacencyStart: Int32Array;
	adjacency: Int32Array;

}

/** The shared pieces of the fits of one `reduceProbes` call. */
export function createRefitContext( where: string, settings: ReduceSettings ): RefitContext {

	const { fitSet, normals, directions } = settings;
	const count = fitSet.positions.length / 3;
	const weights = fitSet.weights ?? new Float64Array( count ).fill( 1 );
	let totalWeight = 0;
	for ( let j = 0; j < count; j ++ ) totalWeight += weights[ j ];
	const truth = irradianceAtNormals( fitSet.sh, normals );
	const givenWeights = fitSet.weights ?? undefined;
	const { scale } = irradianceErrorScale( truth, directions, where, givenWeights );
	return {
		where, positions: fitSet.positions, sh: fitSet.sh, denseCount: fitSet.denseCount, weights, givenWeights, totalWeight,
		truth, stride: 3 * directions, basis: irradianceBasis( normals ), scale, visitOrder: hilbertOrder( fitSet.positions ),
		fit: settings.fit!, samples: prepareFitSamples( where, { positions: fitSet.positions, sh: fitSet.sh, weights: givenWeights } ),
	};

}

// Scratch of `fitLayout`: one point's slots and weights; of `predictedError`: its blending probes' row offsets and factors.
const _indices = new Uint32Array( 4 ), _weights = new Float64Array( 4 );
const _slotBase = new Int32Array( 4 ), _slotFactor = new Float64Array( 16 );

/**
 * Fits the layout `order` (dense indices) with `fitProbeSH` over the whole fit set and measures every
 * point's error under the fitted field, as the runtime would blend it.
 * @param lambda λ (or 'auto': cross-validation).
 * @param gradientLambda λ of the gradients (or 'auto'); ignored without gradients.
 */
export function fitLayout(
	context: RefitContext, order: readonly number[], lambda: number | 'auto', gradientLambda: number | 'auto',
): FittedLayout {

	const { positions: points, sh, weights, fit } = context;
	const size = order.length, count = weights.length, gradients = fit.gradients, stride = gradients ? 4 : 1;
	const positions = new Float64Array( 3 * size ), captured = new Float64Array( 27 * size );
	order.forEach( ( i, s ) => {

		positions.set( points.subarray( 3 * i, 3 * i + 3 ), 3 * s );
		captured.set( sh.subarray( 27 * i, 27 * i + 27 ), 27 * s );

	} );

	const interpolator = createProbeInterpolator( positions );
	// The fit's own error pass is skipped: every point's error is measured below, as the runtime blends it.
	const { result, design } = fitProbeSHWithDesign( interpolator, positions, captured, context.samples, {
		gradients, lambda, gradientLambda: gradients ? gradientLambda : 0, nonNegative: fit.nonNegative,
	} );

	// Every point's weights, as the fit and the runtime take them.
	const slots = new Int32Array( 4 * count ), slotWeights = new Float64Array( 4 * count ), outside = new Uint8Array( count );
	const cells = interpolator instanceof TetrahedralMesh ? interpolator.cellCount : Infinity;
	let hint = - 1, spread = 0;
	// The fit located every point already when it kept them all (no zero weights): read its design.
	const fromDesign = design.count === count && design.slots === 4;
	const pointCells = fromDesign ? design.cells : new Int32Array( count );
	if ( fromDesign ) slotsFromDesign( design, cells, slots, slotWeights, outside );
	for ( let v = 0; v < count && ! fromDesign; v ++ ) {

		const j = context.visitOrder[ v ];
		const x = points[ 3 * j ], y = points[ 3 * j + 1 ], z = points[ 3 * j + 2 ];
		_weights.fill( 0 );
		hint = interpolator.interpolate( x, y, z, _indices, _weights, hint );
		pointCells[ j ] = hint;
		outside[ j ] = hint >= cells ? 1 : 0;
		for ( let s = 0; s < 4; s ++ ) {

			const w = _weights[ s ], i = _indices[ s ];
			slots[ 4 * j + s ] = w === 0 ? - 1 : i;
			slotWeights[ 4 * j + s ] = w;
			if ( w === 0 || weights[ j ] === 0 ) continue;
			const dx = x - positions[ 3 * i ], dy = y - positions[ 3 * i + 1 ], dz = z - positions[ 3 * i + 2 ];
			spread += weights[ j ] * w * ( dx * dx + dy * dy + dz * dz );

		}

	}

	// h as fitProbeSH takes it, so a trial's gradient pull matches the fit's.
	const rms = Math.sqrt( spread / context.totalWeight );
	const lengthScale = fromDesign ? design.lengthScale : gradients && rms > 0 && Number.isFinite( rms ) ? rms : 1;
	const unknowns = new Float64Array( 27 * stride * size );
	for ( let i = 0; i < size; i ++ ) {

		for ( let k = 0; k < 27; k ++ ) unknowns[ 27 * stride * i + k ] = result.sh[ 27 * i + k ];
		if ( result.gradients === null ) continue;
		for ( let a = 0; a < 3; a ++ ) for ( let k = 0; k < 27; k ++ ) {

			unknowns[ 27 * ( stride * i + 1 + a ) + k ] = lengthScale * result.gradients[ 81 * i + 27 * a + k ];

		}

	}

	const rows = new Float64Array( context.stride * stride * size );
	for ( let i = 0; i < size; i ++ ) writeUnknownRows( context, unknowns, i, stride, rows );
	const errors = new Float64Array( count );
	for ( let j = 0; j < count; j ++ ) errors[ j ] = predictedError( context, j, slots, slotWeights, positions, rows, stride, lengthScale );
	const { adjacencyStart, adjacency, reached } = adjacencyOf( slots, weights, size );
	const hullVertex = new Uint8Array( size );
	if ( interpolator instanceof TetrahedralMesh ) for ( const i of interpolator.hullFaces ) hullVertex[ i ] = 1;
	else hullVertex.fill( 1 ); // a flat layout: every probe bounds it

	return {
		order: order.slice(), positions, interpolator, result, unknowns, rows, stride, lengthScale, reached,
		slots, slotWeights, outside, cells: pointCells, hullVertex, errors, summary: summarizeErrors( errors, context.givenWeights ),
		adjacencyStart, adjacency,
	};

}

/** Every point's 4 slots (layout probes, −1 for weight 0), weights and outside flag, read from the fit's design. */
function slotsFromDesign( design: SampleDesign, cells: number, slots: Int32Array, slotWeights: Float64Array, outside: Uint8Array ): void {

	const { probes, factors, stride, localToGlobal } = design;
	for ( let j = 0; j < design.count; j ++ ) {

		outside[ j ] = design.cells[ j ] >= cells ? 1 : 0;
		for ( let s = 0; s < 4; s ++ ) {

			const t = probes[ 4 * j + s ];
			slots[ 4 * j + s ] = t < 0 ? - 1 : localToGlobal[ t ];
			slotWeights[ 4 * j + s ] = t < 0 ? 0 : factors[ stride * ( 4 * j + s ) ];

		}

	}

}

/**
 * Writes the irradiance rows of probe i's unknowns (irradiance is linear in the SH, so a point's
 * predicted row is the same blend of these rows): `rows[ stride · rowStride · i + rowStride · a … ]`
 * for unknown a.
 */
export function writeUnknownRows(
	context: RefitContext, unknowns: ArrayLike<number>, i: number, stride: number, rows: Float64Array,
): void {

	for ( let a = 0; a < stride; a ++ ) {

		irradianceRow( unknowns, 27 * ( stride * i + a ), context.basis, rows, context.stride * ( stride * i + a ) );

	}

}

/**
 * Point j's error under the field Σ w · ( c + (h·G) · (q − p) / h ), with its 4 slots and weights given,
 * blended from the probes' unknown rows ({@link writeUnknownRows}; `probePositions` and `rows`
 * indexed by the slots' local probes).
 */
export function predictedError(
	context: RefitContext, j: number, slots: ArrayLike<number>, slotWeights: ArrayLike<number>, probePositions: ArrayLike<number>,
	rows: Float64Array, stride: number, lengthScale: number, slotOffset = 4 * j,
): number {

	const { positions, stride: rowStride } = context;
	const x = positions[ 3 * j ], y = positions[ 3 * j + 1 ], z = positions[ 3 * j + 2 ];

	// The blending probes, in slot order (the sums' order, so the result is the same to the bit); unused
	// ones get weight 0 and the first one's rows: they add ±0, which changes no error.
	const base = _slotBase, factor = _slotFactor;
	let n = 0;
	for ( let s = 0; s < 4; s ++ ) {

		const i = slots[ slotOffset + s ];
		if ( i < 0 ) continue;
		const w = slotWeights[ slotOffset + s ];
		base[ n ] = rowStride * stride * i;
		factor[ 4 * n ] = w;
		if ( stride !== 1 ) {

			factor[ 4 * n + 1 ] = w * ( x - probePositions[ 3 * i ] ) / lengthScale;
			factor[ 4 * n + 2 ] = w * ( y - probePositions[ 3 * i + 1 ] ) / lengthScale;
			factor[ 4 * n + 3 ] = w * ( z - probePositions[ 3 * i + 2 ] ) / lengthScale;

		}

		n ++;

	}

	if ( n === 0 ) base[ 0 ] = 0; // no probe blends it: the prediction is 0
	for ( let s = n; s < 4; s ++ ) {

		base[ s ] = base[ 0 ];
		factor.fill( 0, 4 * s, 4 * s + 4 );

	}

	const b0 = base[ 0 ], b1 = base[ 1 ], b2 = base[ 2 ], b3 = base[ 3 ];
	const w0 = factor[ 0 ], w1 = factor[ 4 ], w2 = factor[ 8 ], w3 = factor[ 12 ];
	const x0 = factor[ 1 ], x1 = factor[ 5 ], x2 = factor[ 9 ], x3 = factor[ 13 ];
	const y0 = factor[ 2 ], y1 = factor[ 6 ], y2 = factor[ 10 ], y3 = factor[ 14 ];
	const z0 = factor[ 3 ], z1 = factor[ 7 ], z2 = factor[ 11 ], z3 = factor[ 15 ];

	// The blended row minus the truth, its largest channel summed over the normals (pointIrradianceError, inlined).
	const truth = context.truth, t = rowStride * j;
	let sum = 0;
	if ( stride === 1 && n === 3 ) {

		// An outer cell's point: the fourth slot would add ±0, which changes no sum (it never starts at −0).
		for ( let k = 0; k < rowStride; k += 3 ) {

			const r = Math.abs( blend3( rows, k, b0, w0, b1, w1, b2, w2 ) - truth[ t + k ] );
			const g = Math.abs( blend3( rows, k + 1, b0, w0, b1, w1, b2, w2 ) - truth[ t + k + 1 ] );
			const b = Math.abs( blend3( rows, k + 2, b0, w0, b1, w1, b2, w2 ) - truth[ t + k + 2 ] );
			sum += r > g ? ( r > b ? r : b ) : ( g > b ? g : b );

		}

		return sum * context.scale;

	}

	if ( stride === 1 ) {

		for ( let k = 0; k < rowStride; k += 3 ) {

			const r = Math.abs( blend1( rows, k, b0, w0, b1, w1, b2, w2, b3, w3 ) - truth[ t + k ] );
			const g = Math.abs( blend1( rows, k + 1, b0, w0, b1, w1, b2, w2, b3, w3 ) - truth[ t + k + 1 ] );
			const b = Math.abs( blend1( rows, k + 2, b0, w0, b1, w1, b2, w2, b3, w3 ) - truth[ t + k + 2 ] );
			sum += r > g ? ( r > b ? r : b ) : ( g > b ? g : b );

		}

		return sum * context.scale;

	}

	for ( let k = 0; k < rowStride; k += 3 ) {

		let r = 0, g = 0, b = 0;
		r += blend4( rows, rowStride, k, b0, w0, x0, y0, z0 ); g += blend4( rows, rowStride, k + 1, b0, w0, x0, y0, z0 );
		b += blend4( rows, rowStride, k + 2, b0, w0, x0, y0, z0 );
		r += blend4( rows, rowStride, k, b1, w1, x1, y1, z1 ); g += blend4( rows, rowStride, k + 1, b1, w1, x1, y1, z1 );
		b += blend4( rows, rowStride, k + 2, b1, w1, x1, y1, z1 );
		r += blend4( rows, rowStride, k, b2, w2, x2, y2, z2 ); g += blend4( rows, rowStride, k + 1, b2, w2, x2, y2, z2 );
		b += blend4( rows, rowStride, k + 2, b2, w2, x2, y2, z2 );
		r += blend4( rows, rowStride, k, b3, w3, x3, y3, z3 ); g += blend4( rows, rowStride, k + 1, b3, w3, x3, y3, z3 );
		b += blend4( rows, rowStride, k + 2, b3, w3, x3, y3, z3 );
		r = Math.abs( r - truth[ t + k ] ); g = Math.abs( g - truth[ t + k + 1 ] ); b = Math.abs( b - truth[ t + k + 2 ] );
		sum += r > g ? ( r > b ? r : b ) : ( g > b ? g : b );

	}

	return sum * context.scale;

}

/** Σ over 4 probes of w · row[ k ], in that order from 0 (as the row was accumulated before). */
function blend1(
	rows: Float64Array, k: number, b0: number, w0: number, b1: number, w1: number, b2: number, w2: number, b3: number, w3: number,
): number {

	let v = 0;
	v += w0 * rows[ b0 + k ];
	v += w1 * rows[ b1 + k ];
	v += w2 * rows[ b2 + k ];
	v += w3 * rows[ b3 + k ];
	return v;

}

/** {@link blend1} of 3 probes. */
function blend3( rows: Float64Array, k: number, b0: number, w0: number, b1: number, w1: number, b2: number, w2: number ): number {

	let v = 0;
	v += w0 * rows[ b0 + k ];
	v += w1 * rows[ b1 + k ];
	v += w2 * rows[ b2 + k ];
	return v;

}

/** One probe's part of row entry k with gradients: w · c + fx · Gx + fy · Gy + fz · Gz, grouped left to right. */
function blend4( rows: Float64Array, rowStride: number, k: number, base: number, w: number, fx: number, fy: number, fz: number ): number {

	const gx = base + rowStride, gy = gx + rowStride, gz = gy + rowStride;
	return w * rows[ base + k ] + fx * rows[ gx + k ] + fy * rows[ gy + k ] + fz * rows[ gz + k ];

}

/** Per probe, the points of positive weight it blends (compressed rows), and how many probes have any. */
function adjacencyOf(
	slots: Int32Array, weights: Float64Array, size: number,
): { adjacencyStart: Int32Array; adjacency: Int32Array; reached: number } {

	const adjacencyStart = new Int32Array( size + 1 );
	for ( let j = 0; j < weights.length; j ++ ) {

		if ( weights[ j ] === 0 ) continue;
		for ( let s = 0; s < 4; s ++ ) if ( slots[ 4 * j + s ] >= 0 ) adjacencyStart[ slots[ 4 * j + s ] + 1 ] ++;

	}

	let reached = 0;
	for ( let i = 0; i < size; i ++ ) {

		if ( adjacencyStart[ i + 1 ] > 0 ) reached ++;
		adjacencyStart[ i + 1 ] += adjacencyStart[ i ];

	}

	const adjacency = new Int32Array( adjacencyStart[ size ] ), fill = adjacencyStart.slice( 0, size );
	for ( let j = 0; j < weights.length; j ++ ) {

		if ( weights[ j ] === 0 ) continue;
		for ( let s = 0; s < 4; s ++ ) if ( slots[ 4 * j + s ] >= 0 ) adjacency[ fill[ slots[ 4 * j + s ] ] ++ ] = j;

	}

	return { adjacencyStart, adjacency, reached };

}
