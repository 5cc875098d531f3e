import { IRRADIANCE_C4 } from '../src/sh/SHBasis.js';
import { minIrradiance } from '../src/sh/minimumOverSphere.js';
import { SH_FLOATS, assertInteger, assertSH } from '../src/validate.js';

/*
 * What a bake's or a file's SH say about its light: L00 per channel, probes that are black, probes
 * whose irradiance goes negative. Pure (no three.js): `bake` runs it on the captured SH, `inspect` on
 * the decoded file.
 */

/**
 * A probe is black when L00 of each channel is at most this fraction of the brightest probe's
 * largest L00 (or 1e-6, whichever is larger).
 */
export const BLACK_FRACTION = 1e-3;

/** The absolute floor of the black threshold, in L00 units. */
export const BLACK_FLOOR = 1e-6;

/**
 * A probe counts as negative when its lowest irradiance is below −1/256 of its mean irradiance
 * (c4 · its largest L00, or c4 · the black threshold if larger): less is what float16 storage alone
 * leaves of a probe made non-negative (docs/cli.md).
 */
export const NEGATIVE_FRACTION = 1 / 256;

/** The SH statistics of a set of probes ({@link shStatistics}). */
export interface ShStatistics {

	/** Probes counted. */
	count: number;

	/** L00 per channel (R, G, B) over the probes: smallest, median, largest. */
	l00: { min: [ number, number, number ]; median: [ number, number, number ]; max: [ number, number, number ] };

	/** L00 at or below which (in every channel) a probe is black. */
	blackThreshold: number;

	/** Number of black probes. */
	black: number;

	/** Indices of the black probes, ascending. */
	blackProbes: number[];

	/** Number of probes whose irradiance E(n) is negative (beyond {@link NEGATIVE_FRACTION}) for some normal. */
	negative: number;

	/** Indices of those probes, ascending. */
	negativeProbes: number[];

	/** The lowest irradiance E(n) over every probe, channel and unit normal (exact; may be ≥ 0). */
	lowestIrradiance: number;

	/** The probe where {@link ShStatistics.lowestIrradiance} is. */
	lowestProbe: number;

	/** The lowest of each probe's lowest irradiance divided by its mean irradiance (the depth of the worst ring; may be ≥ 0). */
	deepestRing: number;

	/** The probe where {@link ShStatistics.deepestRing} is. */
	deepestRingProbe: number;

}

/**
 * Statistics of `count` probes' SH9 (27 floats each, three's `SphericalHarmonics3` order): L00 per
 * channel, black probes ({@link BLACK_FRACTION}) and probes with negative irradiance, found with the
 * exact minimum over the sphere (`minIrradiance`).
 * @param sh 27 · count finite floats.
 * @param count Probes, ≥ 1.
 * @throws {RangeError} for a count that is not an integer ≥ 1, an array of another length or a
 * non-finite value.
 */
export function shStatistics( sh: Float32Array, count: number ): ShStatistics {

	const where = 'shStatistics';
	assertInteger( where, 'count', count, 1 );
	assertSH( where, 'sh', sh, count );

	const l00: ShStatistics[ 'l00' ] = { min: [ 0, 0, 0 ], median: [ 0, 0, 0 ], max: [ 0, 0, 0 ] };
	const channel = new Float64Array( count );
	let brightest = - Infinity;
	for ( let c = 0; c < 3; c ++ ) {

		for ( let p = 0; p < count; p ++ ) channel[ p ] = sh[ SH_FLOATS * p + c ];
		channel.sort();
		l00.min[ c ] = channel[ 0 ];
		l00.max[ c ] = channel[ count - 1 ];
		const half = count >> 1;
		l00.median[ c ] = count % 2 === 1 ? channel[ half ] : 0.5 * ( channel[ half - 1 ] + channel[ half ] );
		brightest = Math.max( brightest, channel[ count - 1 ] );

	}

	const blackThreshold = Math.max( BLACK_FLOOR, BLACK_FRACTION * brightest );
	const blackProbes: number[] = [], negativeProbes: number[] = [];
	let lowestIrradiance = Infinity, lowestProbe = 0, deepestRing = Infinity, deepestRingProbe = 0;
	for ( let p = 0; p < count; p ++ ) {

		const o = SH_FLOATS * p;
		const largest = Math.max( sh[ o ], sh[ o + 1 ], sh[ o + 2 ] );
		if ( largest <= blackThreshold ) blackProbes.push( p );
		const lowest = minIrradiance( sh, o );
		if ( lowest < lowestIrradiance ) {

			lowestIrradiance = lowest;
			lowestProbe = p;

		}

		const ring = lowest / ( IRRADIANCE_C4 * Math.max( largest, blackThreshold ) );
		if ( ring < deepestRing ) {

			deepestRing = ring;
			deepestRingProbe = p;

		}

		if ( ring < - NEGATIVE_FRACTION ) negativeProbes.push( p );

	}

	return {
		count, l00, blackThreshold,
		black: blackProbes.length, blackProbes,
		negative: negativeProbes.length, negativeProbes,
		lowestIrradiance, lowestProbe, deepestRing, deepestRingProbe,
	};

}

/**
 * The statistics as [label, value] rows for the summary tables (cli/table.ts `formatTable`): L00
 * min / median / max per channel, black probes and negative-irradiance probes with their indices.
 */
export function formatShStatistics( stats: ShStatistics ): [ string, string ][] {

	const { l00 } = stats;
	const channels = [ 'R', 'G', 'B' ].map( ( name, c ) =>
		`${name} ${formatValue( l00.min[ c ] )} / ${formatValue( l00.median[ c ] )} / ${formatValue( l00.max[ c ] )}` );
	const share = stats.blackThreshold > BLACK_FLOOR ? `, 1/${Math.round( 1 / BLACK_FRACTION )} of the brightest` : '';
	return [
		[ 'L00 min/median/max', channels.join( ', ' ) ],
		[ 'black probes', `${countOf( stats.black, stats.count )} (L00 ≤ ${formatValue( stats.blackThreshold )} in every channel${share}`
			+ `${listProbes( stats.blackProbes )})` ],
		[ 'negative irradiance', `${countOf( stats.negative, stats.count )} (E(n) below −1/${Math.round( 1 / NEGATIVE_FRACTION )} of the probe's mean for some `
			+ `normal n${listProbes( stats.negativeProbes )}; lowest E(n) ${formatValue( stats.lowestIrradiance )} at probe ${stats.lowestProbe}, `
			+ `lowest E(n)/mean ${formatPercent( stats.deepestRing )} at probe ${stats.deepestRingProbe})` ],
	];

}

/** "3 of 64". */
function countOf( part: number, whole: number ): string {

	return `${part} of ${whole}`;

}

/** "; probes 1, 4, 9 …" for up to 8 indices, or '' for none. */
export function listProbes( probes: readonly number[] ): string {

	if ( probes.length === 0 ) return '';
	const shown = probes.slice( 0, 8 ).join( ', ' );
	return `; probe${probes.length === 1 ? '' : 's'} ${shown}${probes.length > 8 ? ` and ${probes.length - 8} more` : ''}`;

}

/** A ratio as a percentage to 2 significant digits: "-1.7 %". */
export function formatPercent( ratio: number ): string {

	return `${Number( ( 100 * ratio ).toPrecision( 2 ) )} %`;

}

/** A value to 4 significant digits, without an exponent for ordinary magnitudes. */
export function formatValue( value: number ): string {

	if ( value === 0 ) return '0';
	const magnitude = Math.abs( value );
	if ( magnitude >= 1e-3 && magnitude < 1e6 ) return String( Number( value.toPrecision( 4 ) ) );
	return value.toExponential( 3 ).replace( /\.?0+e/, 'e' );

}
