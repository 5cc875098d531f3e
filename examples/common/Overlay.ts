/**
 * On-page status, progress bar, notices and errors: a demo must say what is wrong on screen,
 * not only in the console.
 */
export class Overlay {

	private readonly statusElement = element( 'status', 'position:absolute;bottom:8px;left:8px;white-space:pre;font:12px/1.4 ui-monospace,monospace;color:#ddd;text-shadow:0 0 3px #000' );
	private readonly bar = element( 'progress', 'position:absolute;top:0;left:0;height:4px;width:0;background:#8cf;transition:width .1s' );
	private readonly label = element( 'progress-label', 'position:absolute;top:8px;left:50%;transform:translateX(-50%);font:13px system-ui,sans-serif;color:#8cf' );
	private readonly noticeElement = element( 'notice', 'position:absolute;bottom:8px;right:8px;max-width:40%;font:13px system-ui,sans-serif;color:#fc6;text-align:right' );
	private readonly errorElement = element( 'error', 'position:absolute;top:40%;left:10%;right:10%;text-align:center;font:16px system-ui,sans-serif;color:#f66;text-shadow:0 0 4px #000' );

	/** The bottom-left status text. */
	status( text: string ): void {

		if ( this.statusElement.textContent !== text ) this.statusElement.textContent = text;

	}

	/** A progress bar (fraction 0..1) with a label; done at 1. */
	progress( text: string, fraction: number ): void {

		this.bar.style.width = fraction >= 1 ? '0' : `${( 100 * fraction ).toFixed( 1 )}%`;
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

}

function element( id: string, style: string ): HTMLDivElement {

	const div = document.createElement( 'div' );
	div.id = id;
	div.style.cssText = style;
	div.style.pointerEvents = 'none';
	document.body.appendChild( div );
	return div;

}
