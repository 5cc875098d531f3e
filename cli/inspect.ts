import { existsSync, readFileSync, statSync } from 'node:fs';
import { bakeWarnings } from './bakeWarnings.js';
import { readVolume, type ReadVolume } from './codec.js';
import { CliError } from './errors.js';
import type { BakedFit } from '../src/io/index.js';
import { layoutShape } from './layoutShape.js';
import { formatShStatistics, shStatistics } from './shStatistics.js';
import { formatBytes, formatTable } from './table.js';

/** Options of {@link inspect}. */
export interface InspectOptions {

	/** Fail (exit 1) when there is a warning, after printing the summary and the warnings. */
	strict?: boolean;

	/** Where the summary goes (default stdout). */
	log?: ( text: string ) => void;

	/** Where each `warning: …` line goes (default stderr). */
	warn?: ( text: string ) => void;

}

/** What {@link inspect} read and found. */
export interface InspectResult extends ReadVolume {

	/** The warnings printed (the SH alone: black probes, negative irradiance). */
	warnings: string[];

}

/**
 * `capture-lighting inspect`: decodes and validates a baked volume (binary or JSON) with the codec,
 * prints its summary with the SH statistics (`shStatistics`), and prints the bake's warnings that the
 * SH alone can show, as `warning: …` lines.
 * @param file The volume file.
 * @throws {CliError} exit code 2 for a missing file; 1 for a file the codec rejects (its message), or
 * for any warning under `strict`.
 */
export function inspect( file: string, options: InspectOptions = {} ): InspectResult {

	const {
		strict = false,
		log = ( text: string ) => process.stdout.write( text + '\n' ),
		warn = ( text: string ) => process.stderr.write( text + '\n' ),
	} = options;

	if ( ! existsSync( file ) ) throw new CliError( `volume ${file} not found.` );
	if ( ! statSync( file ).isFile() ) throw new CliError( `volume ${file} is not a file.` );
	// Node cannot read a file of 2 GiB or more into one buffer; no baked volume is that large.
	const size = statSync( file ).size;
	if ( size >= 2 ** 31 ) throw new CliError( `${file} is not a valid baked volume: it has ${size} bytes, more than the 2 GiB a volume file can have.`, 1 );
	const bytes = readFileSync( file );
	let volume: ReadVolume;
	try {

		volume = readVolume( bytes );

	} catch ( error ) {

		throw new CliError( `${file} is not a valid baked volume: ${( error as Error ).message}`, 1 );

	}

	const probes = volume.data.positions.length / 3;
	const stats = probes > 0 ? shStatistics( volume.data.sh, probes ) : null;
	const rows = summaryRows( file, bytes.length, volume );
	if ( stats ) rows.splice( rows.length - 1, 0, ...formatShStatistics( stats ) );
	log( formatTable( rows ) );
	const warnings = stats ? bakeWarnings( stats ) : [];
	for ( const warning of warnings ) warn( `warning: ${warning}` );
	if ( strict && warnings.length > 0 ) {

		throw new CliError( `${file}: ${warnings.length} warning${warnings.length === 1 ? '' : 's'} (see above) and --strict was given.`, 1 );

	}

	return { ...volume, warnings };

}

/** The rows of the inspect summary. */
export function summaryRows( file: string, size: number, { data, format, precision }: ReadVolume ): [ string, string ][] {

	const probes = data.positions.length / 3;
	const roleCounts = new Map<string, number>();
	for ( const role of data.roles ) roleCounts.set( role, ( roleCounts.get( role ) ?? 0 ) + 1 );
	const b = data.bounds;
	const number = ( v: number ) => String( Number( v.toPrecision( 6 ) ) );
	const capture = Object.entries( data.capture )
		.filter( ( [ key ] ) => key !== 'roles' )
		.map( ( [ key, value ] ) => `${key} ${value}` );
	for ( const [ role, settings ] of Object.entries( data.capture.roles ?? {} ) ) capture.push( `${role}: ${Object.entries( settings ?? {} ).map( ( [ k, v ] ) => `${k} ${v}` ).join( ', ' )}` );
	const rows: [ string, string ][] = [
		[ 'file', `${file} (${format === 'bin' ? 'binary' : 'JSON'}, valid)` ],
		[ 'probes', String( probes ) ],
		[ 'tetrahedra', tetrahedraRow( data.positions, data.tetrahedra.length / 4 ) ],
		[ 'zones', data.zones.length === 0 ? '0' : `${data.zones.length} (${data.zones.map( ( zone ) => `${zone.name}: ${zone.probes.length} probes` ).join( ', ' )})` ],
		[ 'roles', [ ...roleCounts ].map( ( [ role, n ] ) => `${role} ${n}` ).join( ', ' ) || '—' ],
		[ 'SH precision', precision === 'json' ? 'JSON decimal (float32 values)' : precision ],
		[ 'bounds', `(${number( b[ 0 ] )}, ${number( b[ 1 ] )}, ${number( b[ 2 ] )}) – (${number( b[ 3 ] )}, ${number( b[ 4 ] )}, ${number( b[ 5 ] )})` ],
		[ 'capture', capture.join( ', ' ) || 'unknown' ],
		[ 'gradients', data.gradients ? `stored (81 per probe, ${precision === 'json' ? 'JSON decimal' : precision})` : 'none (plain probes)' ],
		[ 'fit', fitRow( data.fit ) ],
	];
	if ( data.metadata ) rows.push( [ 'metadata', data.metadata.length > 200 ? data.metadata.slice( 0, 200 ) + '…' : data.metadata ] );
	rows.push( [ 'size on disk', formatBytes( size ) ] );
	return rows;

}

/** How the SH were fitted, from the file's fit record. */
function fitRow( fit: BakedFit | null ): string {

	if ( ! fit ) return 'none (the SH are the captured ones)';
	const number = ( v: number ) => String( Number( v.toPrecision( 4 ) ) );
	const parts = [
		`least squares to ${fit.samples} samples, ${fit.gradients ? 'SH and gradients' : 'SH only'}`,
		`λ ${number( fit.lambda )}${fit.gradients ? `, gradient λ ${number( fit.gradientLambda )}` : ''}`,
		fit.crossValidationError === null ? 'λ given (no cross-validation)'
			: `cross-validation error ${number( 100 * fit.crossValidationError )} % of the mean irradiance`,
	];
	if ( fit.source ) parts.push( `samples: ${fit.source.length > 200 ? fit.source.slice( 0, 200 ) + '…' : fit.source}` );
	return parts.join( '; ' );

}

/** The stored tetrahedra, or for none what the runtime builds from the positions. */
function tetrahedraRow( positions: Float64Array, tetrahedra: number ): string {

	if ( tetrahedra > 0 || positions.length === 0 ) return String( tetrahedra );
	const shape = layoutShape( positions ).shape;
	const built = shape === 'volume' ? 'tetrahedralizes them' : shape === 'plane' ? 'triangulates them in their plane'
		: shape === 'line' ? 'interpolates along their line' : 'uses that one probe\'s SH everywhere';
	const where = shape === 'volume' ? 'span a volume' : shape === 'plane' ? 'lie in one plane' : shape === 'line' ? 'lie on one line' : 'are at one point';
	return `0 (none stored: the probes ${where}; LightProbeVolume ${built} when it loads the file)`;

}
