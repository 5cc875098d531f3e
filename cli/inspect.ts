import { existsSync, readFileSync, statSync } from 'node:fs';
import { readVolume, type ReadVolume } from './codec.js';
import { CliError } from './errors.js';
import { formatBytes, formatTable } from './table.js';

/**
 * `capture-lighting inspect`: decodes and validates a baked volume (binary or JSON) with the codec
 * and prints its summary.
 * @param file The volume file.
 * @param log Where the summary goes (stdout).
 * @throws {CliError} exit code 2 for a missing file; 1 for a file the codec rejects (its message).
 */
export function inspect( file: string, log: ( text: string ) => void = ( text ) => process.stdout.write( text + '\n' ) ): ReadVolume {

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

	log( formatTable( summaryRows( file, bytes.length, volume ) ) );
	return volume;

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
		[ 'tetrahedra', String( data.tetrahedra.length / 4 ) ],
		[ 'zones', data.zones.length === 0 ? '0' : `${data.zones.length} (${data.zones.map( ( zone ) => `${zone.name}: ${zone.probes.length} probes` ).join( ', ' )})` ],
		[ 'roles', [ ...roleCounts ].map( ( [ role, n ] ) => `${role} ${n}` ).join( ', ' ) || '—' ],
		[ 'SH precision', precision === 'json' ? 'JSON decimal (float32 values)' : precision ],
		[ 'bounds', `(${number( b[ 0 ] )}, ${number( b[ 1 ] )}, ${number( b[ 2 ] )}) – (${number( b[ 3 ] )}, ${number( b[ 4 ] )}, ${number( b[ 5 ] )})` ],
		[ 'capture', capture.join( ', ' ) || 'unknown' ],
	];
	if ( data.metadata ) rows.push( [ 'metadata', data.metadata.length > 200 ? data.metadata.slice( 0, 200 ) + '…' : data.metadata ] );
	rows.push( [ 'size on disk', formatBytes( size ) ] );
	return rows;

}
