/** What the Kyoto page's panorama table shows of a panorama. */
export interface PanoramaRow {

	id: string;
	label: string;
	kind: string;
	/** Width × height of the image. */
	size: string;
	/** GPU projection to SH9, ms. */
	ms: number;
	/** Range of its irradiance E(n) over the sphere. */
	minE: number;
	maxE: number;

}

/**
 * The Kyoto page's panorama table, as text: per panorama its kind, size, projection time, irradiance
 * range and how many probes of the layout use it (`panoramaIds`, one per probe).
 */
export function panoramaTableText( rows: readonly PanoramaRow[], panoramaIds: readonly string[], warmupMs: number ): string {

	const uses = new Map<string, number>();
	for ( const id of panoramaIds ) uses.set( id, ( uses.get( id ) ?? 0 ) + 1 );
	const lines = rows.map( ( p ) => `${p.label.padEnd( 13 )}${p.kind.padEnd( 8 )}${p.size.padEnd( 9 )}${p.ms.toFixed( 0 ).padStart( 5 )} ms  `
		+ `E ${p.minE.toFixed( 2 ).padStart( 5 )}…${p.maxE.toFixed( 2 ).padEnd( 6 )} ×${uses.get( p.id ) ?? 0}`
		+ `${p.minE < 0 ? '  E<0: SH ringing (not clamped)' : ''}` );
	const total = rows.reduce( ( sum, p ) => sum + p.ms, 0 );
	return `panorama     kind    size      GPU→SH9  E(n) min…max   probes\n${lines.join( '\n' )}\n`
		+ `projection ${total.toFixed( 0 )} ms for ${rows.length} panoramas (+ ${warmupMs.toFixed( 0 )} ms shader warm-up)\n`
		+ 'photo: Potsdamer Platz, Berlin; Venice sunset (Poly Haven, CC0). Rings: see the legend.';

}
