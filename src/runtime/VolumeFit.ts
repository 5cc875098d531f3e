import { fitProbeSH } from '../fitting/fitProbeSH.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import type { BakedFit } from '../io/index.js';
import { SH_FLOATS } from '../validate.js';

/** How a {@link VolumeFit} fits: the `fit` capture option's fitting settings, checked. */
export interface VolumeFitSettings {

	gradients: boolean;
	lambda: number | 'auto';
	gradientLambda: number | 'auto';
	nonNegative: boolean;

}

/** The probes a {@link VolumeFit} fits: the volume's interpolator and positions, and which ids are live. */
export interface FittedLayout {

	readonly interpolator: ProbeInterpolator;
	readonly positions: Float64Array;
	isProbeActive( index: number ): boolean;

}

/** What {@link VolumeFit.fit} gives: the fitted probes and the store that refits them after edits. */
export interface VolumeFitResult {

	/** 27 floats per probe id, fitted (removed probes zero). */
	sh: Float32Array;

	/** 81 floats per probe id, or null without gradients (removed probes zero). */
	gradients: Float32Array | null;

	/** The record for `volume.fitSettings` and baked files. */
	record: BakedFit;

	/** Weighted mean irradiance error of the fitted field over the samples. */
	fitError: number;

	/** The fit's store, for the next refit. */
	store: VolumeFit;

}

/**
 * The private store of a fitted `LightProbeVolume`: the fit samples (positions, captured SH,
 * weights), every probe's captured SH (the fit's regularisation targets — `volume.sh` holds the
 * fitted ones) and the settings, so that a capture of some probes (`recaptureDirty` after an edit)
 * refits the edited layout to the same samples. Immutable: each fit makes a new store, so a fit
 * that throws leaves the volume with its old one.
 *
 * The first fit chooses λ (by cross-validation unless given); refits reuse the chosen λ — a
 * property of the samples and the scene more than of one probe moved — so an edit costs one solve,
 * not a λ search, and their record's `crossValidationError` is null (not measured for the edited layout).
 */
export class VolumeFit {

	/** x, y, z per fit sample. */
	readonly samplePositions: Float64Array;

	/** 27 floats per fit sample: what was captured there. */
	readonly sampleSH: Float32Array;

	/** One weight per sample (a region of interest), or null: all 1. */
	readonly sampleWeights: Float64Array | null;

	/** 27 floats per probe id: the SH as captured, before fitting. */
	readonly captured: Float32Array;

	/** The fitting settings (λ as given: 'auto' or a number). */
	readonly settings: VolumeFitSettings;

	/** How the samples were made (the record's `source`). */
	readonly source: string;

	/** The record of the fit that made this store. */
	readonly record: BakedFit;

	/** Probe positions the store was fitted for (a copy): a layout that differs needs a refit. */
	private readonly fittedPositions: Float64Array;

	/** Live probe ids when fitted (1 each). */
	private readonly fittedActive: Uint8Array;

	private constructor(
		samples: { positions: Float64Array; sh: Float32Array; weights: Float64Array | null }, captured: Float32Array,
		settings: VolumeFitSettings, source: string, record: BakedFit, layout: FittedLayout,
	) {

		this.samplePositions = samples.positions;
		this.sampleSH = samples.sh;
		this.sampleWeights = samples.weights;
		this.captured = captured;
		this.settings = settings;
		this.source = source;
		this.record = record;
		this.fittedPositions = layout.positions.slice();
		this.fittedActive = activeFlags( layout );

	}

	/**
	 * Fits a layout's probes to samples: `fitProbeSH` over the volume's own interpolator (the
	 * runtime's weights, outer cells included), pulled toward `captured`; removed probes get zero SH
	 * and gradients.
	 * @param captured 27 floats per probe id: the captured SH (kept by the store; not copied).
	 * @throws the errors of `fitProbeSH` (named `fitProbeSH: …`).
	 */
	static fit(
		layout: FittedLayout, captured: Float32Array,
		samples: { positions: Float64Array; sh: Float32Array; weights: Float64Array | null },
		settings: VolumeFitSettings, source: string,
	): VolumeFitResult {

		return VolumeFit.fitLayout( layout, captured, samples, settings, settings, source );

	}

	/** Whether the layout's probes (positions, live ids) differ from those this store was fitted for. */
	isStale( layout: FittedLayout ): boolean {

		const positions = layout.positions;
		if ( positions.length !== this.fittedPositions.length ) return true;
		for ( let i = 0; i < positions.length; i ++ ) if ( positions[ i ] !== this.fittedPositions[ i ] ) return true;
		const active = activeFlags( layout );
		for ( let i = 0; i < active.length; i ++ ) if ( active[ i ] !== this.fittedActive[ i ] ) return true;
		return false;

	}

	/**
	 * Every probe's captured SH for a volume whose SH are `current` (27 floats per probe id): this
	 * store's, and `current`'s for probes added since (a new array).
	 */
	capturedOver( current: Float32Array ): Float32Array {

		const targets = current.slice();
		targets.set( this.captured.subarray( 0, Math.min( this.captured.length, current.length ) ) );
		return targets;

	}

	/**
	 * Refits an edited layout to this store's samples, with the λ chosen before: the captured SH
	 * are this store's, with `captured` (27 floats per entry of `indices`, e.g. a recapture of the
	 * moved and added probes) over them; probes added since and not captured take `current` (the
	 * volume's SH: what `addProbe` interpolated for them).
	 */
	refit(
		layout: FittedLayout, current: Float32Array, indices: readonly number[], captured: Float32Array,
	): VolumeFitResult {

		const targets = this.capturedOver( current );
		indices.forEach( ( index, k ) => targets.set( captured.subarray( SH_FLOATS * k, SH_FLOATS * ( k + 1 ) ), SH_FLOATS * index ) );
		const samples = { positions: this.samplePositions, sh: this.sampleSH, weights: this.sampleWeights };
		const chosen = { ...this.settings, lambda: this.record.lambda, gradientLambda: this.record.gradientLambda };
		const source = this.source.endsWith( REFIT_NOTE ) ? this.source : this.source + REFIT_NOTE;
		return VolumeFit.fitLayout( layout, targets, samples, this.settings, chosen, source );

	}

	/** {@link VolumeFit.fit} with the λ of `used` (the settings' own, or the chosen ones for a refit). */
	private static fitLayout(
		layout: FittedLayout, captured: Float32Array, samples: { positions: Float64Array; sh: Float32Array; weights: Float64Array | null },
		settings: VolumeFitSettings, used: VolumeFitSettings, source: string,
	): VolumeFitResult {

		const result = fitProbeSH( layout.interpolator, layout.positions, captured, {
			positions: samples.positions, sh: samples.sh, weights: samples.weights ?? undefined,
		}, { gradients: used.gradients, lambda: used.lambda, gradientLambda: used.gradientLambda, nonNegative: used.nonNegative } );
		const count = layout.positions.length / 3;
		for ( let i = 0; i < count; i ++ ) {

			if ( layout.isProbeActive( i ) ) continue;
			result.sh.fill( 0, SH_FLOATS * i, SH_FLOATS * ( i + 1 ) );
			result.gradients?.fill( 0, 3 * SH_FLOATS * i, 3 * SH_FLOATS * ( i + 1 ) );

		}

		const record: BakedFit = {
			samples: samples.positions.length / 3,
			gradients: settings.gradients,
			lambda: result.lambda,
			gradientLambda: result.gradientLambda,
			crossValidationError: result.crossValidationError,
			source,
		};
		const store = new VolumeFit( samples, captured, settings, source, record, layout );
		return { sh: result.sh, gradients: result.gradients, record, fitError: result.fitError, store };

	}

}

/** Appended to a refitted store's `source`. */
const REFIT_NOTE = '; refitted after probe edits';

function activeFlags( layout: FittedLayout ): Uint8Array {

	const count = layout.positions.length / 3;
	const active = new Uint8Array( count );
	for ( let i = 0; i < count; i ++ ) active[ i ] = layout.isProbeActive( i ) ? 1 : 0;
	return active;

}
