import type { Overlay } from './Overlay.js';

/**
 * The progress bar of a capture: probes done / total, the pass with bounces, and the time left,
 * estimated from the probes done so far; then, for a capture with `fit`, the fit points. Feed it
 * `LightProbeVolume.capture`'s `onProgress` and `captureBounces`' `onPass`.
 */
export class CaptureProgress {

	private readonly overlay: Overlay;
	private readonly what: string;
	private readonly passes: number;
	private pass = 0;
	/** Time and probes done (over all passes) at the first progress report: the estimate starts there. */
	private firstTime = 0;
	private firstDone = - 1;
	/** When the fit points' stage started (−1: not yet). */
	private fitStart = - 1;

	/**
	 * Shows an empty bar for a capture of `passes` passes (1 + bounces); `what` names it in the label
	 * (e.g. "at 32²").
	 */
	constructor( overlay: Overlay, what: string, passes = 1 ) {

		this.overlay = overlay;
		this.what = what;
		this.passes = passes;
		overlay.progress( `capturing the probes ${what}…`, 0 );

	}

	/**
	 * `onProgress( done, total, stage )` of the capture: `done` of the pass's `total` probes are
	 * captured, or (stage `'fit'`) `done` of its `total` fit points.
	 */
	probes( done: number, total: number, stage = 'probes' ): void {

		if ( stage === 'fit' ) {

			this.fitPoints( done, total );
			return;

		}

		const overall = this.pass * total + done, all = this.passes * total;
		const now = performance.now();
		// The first probe also compiles the shaders: the rate is measured from the first report on.
		if ( this.firstDone < 0 ) {

			this.firstDone = overall;
			this.firstTime = now;

		}

		const measured = overall - this.firstDone;
		const left = measured > 0 ? ( now - this.firstTime ) / measured * ( all - overall ) : NaN;
		const pass = this.passes > 1 ? `pass ${this.pass + 1} / ${this.passes}: ` : '';
		this.overlay.progress( `${pass}capturing probe ${done} / ${total} ${this.what} — ${formatTimeLeft( left )}`, overall / all );

	}

	/** The fit points' stage: its own bar and estimate (a point costs what a probe does). */
	private fitPoints( done: number, total: number ): void {

		const now = performance.now();
		if ( this.fitStart < 0 || done <= 1 ) this.fitStart = now;
		const left = done > 1 ? ( now - this.fitStart ) / ( done - 1 ) * ( total - done ) : NaN;
		this.overlay.progress( `capturing fit point ${done} / ${total} ${this.what} — ${formatTimeLeft( left )}`, done / total );

	}

	/** `onPass( pass )` of `captureBounces`: pass `pass` (0 = direct light) is done. */
	passDone( pass: number ): void {

		this.pass = pass + 1;

	}

	/** Hides the bar. */
	done(): void {

		this.overlay.progress( '', 1 );

	}

}

/** "about 12 s left", or "estimating the time left…" before a rate is measured. */
export function formatTimeLeft( ms: number ): string {

	if ( ! Number.isFinite( ms ) ) return 'estimating the time left…';
	const seconds = Math.max( 1, Math.round( ms / 1000 ) );
	if ( seconds < 90 ) return `about ${seconds} s left`;
	return `about ${Math.floor( seconds / 60 )} min ${String( seconds % 60 ).padStart( 2, '0' )} s left`;

}
