import type { LegendEntry } from './Overlay.js';

/**
 * The Kyoto page's legend: what the rings round some probe balls, the magenta patches and the
 * orange triangle mean (the panorama table says it too, but the table is hidden with `hide=gui`
 * and on narrow pages). Only the lines for what is drawn.
 */
export function kyotoLegend( { probes, triangles }: { probes: boolean; triangles: boolean } ): LegendEntry[] {

	const entries: LegendEntry[] = [];
	if ( probes ) {

		entries.push(
			{ text: 'white ring: probe from a real photo (Berlin, Venice: not Kyoto)', swatch: '#ffffff' },
			{ text: 'no ring: a panorama derived from a photo (turned, tinted)' },
			{ text: 'cyan ring: a panorama you dropped on the map', swatch: '#66eeff' },
			{ text: 'magenta on a ball: irradiance < 0 (SH ringing, not clamped)', swatch: '#ff00ff' },
		);

	}

	if ( triangles ) entries.push( { text: 'orange: the fox\'s triangle of 3 probes', swatch: '#ff8000' } );
	return entries;

}
