import { formatPercent, formatValue, listProbes, type ShStatistics } from './shStatistics.js';

/** What the bake knows about the scene's light sources (`inspect` has none of it). */
export interface BakeLightFacts {

	/** Light sources the captures saw: scene lights, `--sun` / `--point` / `--spot` / `--ambient`, layout lights, a `--sky`. */
	lights: number;

	/** Emissive materials in the scene. */
	emissive: number;

}

/**
 * The warnings of a bake or an inspected file, one sentence each with the count, the likely cause
 * and the fix: black probes, a scene with no light source, probes with negative irradiance. Empty
 * when there is nothing to warn about. `bake` prints them as `warning: …`; `--strict` makes any a failure.
 * @param stats The SH statistics ({@link shStatistics}).
 * @param facts The scene's light sources, when known (bake); without them the causes are guessed from the SH alone.
 */
export function bakeWarnings( stats: ShStatistics, facts?: BakeLightFacts ): string[] {

	const warnings: string[] = [];
	const black = `${stats.black} of ${stats.count} probes are black (L00 ≤ ${formatValue( stats.blackThreshold )} in every channel`
		+ `${listProbes( stats.blackProbes )})`;
	if ( facts !== undefined && facts.lights === 0 && facts.emissive === 0 ) {

		warnings.push( `the scene has no lights, no emissive materials and no --sky${stats.black > 0 ? `, so ${black}` : ''}: `
			+ 'pass --sun, --point, --spot, --ambient or --sky, add "lights" to the layout, or add lights to the scene file.' );

	} else if ( stats.black === stats.count ) {

		warnings.push( `${black}: no light reached any probe — the scene has no lights, emissive materials or sky the captures `
			+ 'could see; pass --sun, --point, --ambient or --sky, or add "lights" to the layout.' );

	} else if ( stats.black > 0 ) {

		warnings.push( `${black}: they are probably inside walls or closed objects, or in rooms no light reaches — `
			+ 'move them into open space, or add lights there (--point, or "lights" in the layout).' );

	}

	if ( stats.negative > 0 ) {

		warnings.push( `${stats.negative} of ${stats.count} probes have negative irradiance (E(n) down to ${formatPercent( stats.deepestRing )} `
			+ `of the probe's mean at probe ${stats.deepestRingProbe}, lowest E(n) ${formatValue( stats.lowestIrradiance )} at probe ${stats.lowestProbe}`
			+ `${listProbes( stats.negativeProbes )}): ringing — 9 SH coefficients cannot hold a small or sharp-edged bright light (a lamp, `
			+ 'an emissive panel, the sun) — so surfaces facing away from it shade darker than black; bake with --non-negative, or --deringing 0.1 '
			+ '(or stronger).' );

	}

	return warnings;

}
