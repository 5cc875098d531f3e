/** Where a {@link ProgressBar} writes: `process.stderr` or anything with the same shape. */
export interface ProgressStream {

	write( text: string ): unknown;
	isTTY?: boolean;
	columns?: number;

}

/** Options of {@link ProgressBar}. */
export interface ProgressBarOptions {

	/** Write nothing. Default false. */
	quiet?: boolean;

	/** Redraw one line in place (true) or print a line now and then (false). Default: `stream.isTTY`. */
	tty?: boolean;

	/** Clock in ms, for tests. Default `performance.now`. */
	now?: () => number;

}

/**
 * A progress bar on stderr. On a terminal it redraws one line in place (at most 10 times a second);
 * otherwise (a log file, CI) it prints a line at every 10 % step, so logs stay short.
 *
 * ```js
 * const bar = new ProgressBar( process.stderr );
 * bar.start( 'capturing' );
 * bar.update( 5, 12 );
 * bar.finish();
 * ```
 */
export class ProgressBar {

	private readonly stream: ProgressStream;
	private readonly quiet: boolean;
	private readonly tty: boolean;
	private readonly now: () => number;
	private label = '';
	private startTime = 0;
	private lastDraw = - Infinity;
	private lastStep = - 1;
	private drawn = false;

	/**
	 * @param stream Usually `process.stderr`.
	 * @param options See {@link ProgressBarOptions}.
	 */
	constructor( stream: ProgressStream, options: ProgressBarOptions = {} ) {

		this.stream = stream;
		this.quiet = options.quiet ?? false;
		this.tty = options.tty ?? stream.isTTY === true;
		this.now = options.now ?? ( () => performance.now() );

	}

	/** Starts a new stage: `label` heads the bar and its lines. */
	start( label: string ): void {

		this.finish();
		this.label = label;
		this.startTime = this.now();
		this.lastDraw = - Infinity;
		this.lastStep = - 1;

	}

	/** Reports `done` of `total` units. */
	update( done: number, total: number ): void {

		if ( this.quiet || total <= 0 ) return;
		const fraction = Math.min( 1, Math.max( 0, done / total ) );
		const seconds = ( this.now() - this.startTime ) / 1000;
		// Counts (probes) are shown; fractions (bytes loaded, normalised to 1) only as a percentage.
		const count = total > 1 && Number.isInteger( done ) ? ` ${done}/${total}` : '';
		if ( this.tty ) {

			const time = this.now();
			if ( done < total && time - this.lastDraw < 100 ) return;
			this.lastDraw = time;
			const width = Math.max( 10, Math.min( 40, ( this.stream.columns ?? 80 ) - this.label.length - 40 ) );
			const filled = Math.round( fraction * width );
			this.stream.write( `\r${this.label} [${'#'.repeat( filled )}${'-'.repeat( width - filled )}] ${( fraction * 100 ).toFixed( 0 ).padStart( 3 )}%${count} ${seconds.toFixed( 1 )} s\x1b[K` );
			this.drawn = true;

		} else {

			const step = Math.floor( fraction * 10 );
			if ( step === this.lastStep ) return;
			this.lastStep = step;
			this.stream.write( `${this.label}:${count} ${( fraction * 100 ).toFixed( 0 )}% ${seconds.toFixed( 1 )} s\n` );

		}

	}

	/** Ends the current bar (moves a terminal to the next line). */
	finish(): void {

		if ( this.drawn ) this.stream.write( '\n' );
		this.drawn = false;

	}

}
