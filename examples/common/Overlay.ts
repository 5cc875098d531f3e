/** One line of a page's legend: its text and, optionally, the CSS colour of its ring swatch. */
export interface LegendEntry {

	text: string;
	swatch?: string;

}

/**
 * On-page status, progress bar, notices, errors and a legend: a demo must say what is wrong on
 * screen, not only in the console. The styles are in main.css (ids below).
 */
export class Overlay {

	/** Bottom left: the legend above the status text. */
	private readonly hud = element( 'hud' );
	private readonly legendElement = element( 'legend', this.hud );
	/** Hidden until set: an empty line would still take a gap in the hud's column. */
	private readonly rendererElement = hidden( element( 'renderer', this.hud ) );
	private readonly statusElement = element( 'status', this.hud );
	/** The progress block in the middle of the page: a label above a bar. */
	private readonly progressElement = element( 'progress' );
	private readonly label = element( 'progress-label', this.progressElement );
	private readonly bar = element( 'progress-bar', element( 'progress-track', this.progressElement ) );
	private readonly noticeElement = element( 'notice' );
	private readonly errorElement = element( 'error' );

	/**
	 * Which renderer and backend draw the page ('WebGPU', 'WebGPURenderer (WebGL2 backend)',
	 * 'WebGLRenderer'): a line above the status.
	 */
	renderer( text: string ): void {

		this.rendererElement.textContent = text;
		this.rendererElement.style.cssText = 'font: 12px ui-monospace, monospace; color: #8cf; text-shadow: 0 0 3px #000;';

	}

	/** The bottom-left status text. */
	status( text: string ): void {

		if ( this.statusElement.textContent !== text ) this.statusElement.textContent = text;

	}

	/** A progress bar (fraction 0..1) with a label; hidden at 1. */
	progress( text: string, fraction: number ): void {

		this.progressElement.style.display = fraction >= 1 ? 'none' : '';
		this.bar.style.width = `${( 100 * Math.max( 0, Math.min( 1, fraction ) ) ).toFixed( 1 )}%`;
		this.label.textContent = fraction >= 1 ? '' : text;

	}

	/** A non-fatal message, e.g. a missing asset replaced by a stand-in. */
	notice( text: string ): void {

		this.noticeElement.textContent = text;

	}

	/** A fatal message in the middle of the page ('' clears it). */
	error( text: string ): void {

		this.errorElement.textContent = text;

	}

	/**
	 * What the picture shows (bottom left, above the status): one line per entry, each with an optional
	 * CSS colour swatch. Shown with `hide=gui` too — it changes only when the page's state does.
	 */
	legend( entries: readonly LegendEntry[] ): void {

		this.legendElement.replaceChildren( ...entries.map( ( { text, swatch } ) => {

			const line = document.createElement( 'div' );
			if ( swatch ) {

				const mark = document.createElement( 'span' );
				mark.className = 'swatch';
				mark.style.borderColor = swatch;
				line.appendChild( mark );

			}

			line.appendChild( document.createTextNode( text ) );
			return line;

		} ) );

	}

}

function hidden( div: HTMLDivElement ): HTMLDivElement {

	div.style.display = 'none';
	return div;

}

function element( id: string, parent: HTMLElement = document.body ): HTMLDivElement {

	const div = document.createElement( 'div' );
	div.id = id;
	parent.appendChild( div );
	return div;

}
