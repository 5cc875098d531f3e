/**
 * A two-column table, labels left-aligned and padded: the summaries of `bake` and `inspect`.
 * @param rows [label, value] pairs.
 */
export function formatTable( rows: ReadonlyArray<readonly [ string, string ]> ): string {

	const width = Math.max( 0, ...rows.map( ( [ label ] ) => label.length ) );
	return rows.map( ( [ label, value ] ) => `  ${label.padEnd( width )}  ${value}` ).join( '\n' );

}

/** A byte count as "12,345 bytes (12.1 KiB)". */
export function formatBytes( bytes: number ): string {

	const units = [ 'KiB', 'MiB', 'GiB' ];
	let value = bytes, unit = '';
	for ( const next of units ) {

		if ( value < 1024 ) break;
		value /= 1024;
		unit = next;

	}

	return unit ? `${bytes.toLocaleString( 'en-US' )} bytes (${value.toFixed( 1 )} ${unit})` : `${bytes} bytes`;

}

/** Milliseconds as "850 ms" or "12.3 s". */
export function formatDuration( ms: number ): string {

	return ms < 1000 ? `${Math.round( ms )} ms` : `${( ms / 1000 ).toFixed( 1 )} s`;

}
