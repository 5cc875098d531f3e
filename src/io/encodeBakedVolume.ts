import { crc32 } from './crc32.js';
import { toFloat16Bits, FLOAT16_MAX } from './float16.js';
import {
	align8, BAKED_ROLES, BAKED_SECTION, BAKED_VOLUME_MAGIC, BAKED_VOLUME_VERSION_MAJOR, bakedVolumeMinorVersion,
	ENTRY_SIZE, FLAG_SH_FLOAT16, HEADER_SIZE, LITTLE_ENDIAN, SECTION_REQUIRED,
} from './bakedVolumeFormat.js';
import { fail } from './checks.js';
import { validateBakedVolume } from './validateBakedVolume.js';
import type { BakedVolumeInput, EncodeBakedVolumeOptions } from './bakedVolumeTypes.js';

const utf8Encoder = new TextEncoder();

/**
 * Writes a volume in the binary format of docs/format.md (little-endian; version 1.1 when it holds
 * gradients or a fit record, else 1.0). Validates the input first (same rules as the reader), so a
 * written file always loads.
 * @throws {BakedVolumeError} on invalid input, on an SH or gradient value beyond ±65504 with
 * `'float16'` (code `'float16-overflow'`), or when the file would exceed 4 GiB.
 */
export function encodeBakedVolume( input: BakedVolumeInput, options: EncodeBakedVolumeOptions = {} ): ArrayBuffer {

	const where = 'encodeBakedVolume';
	if ( options === null || typeof options !== 'object' ) fail( 'argument', where, 'options must be an object { precision? }.' );
	const precision = options.precision ?? 'float32';
	if ( precision !== 'float16' && precision !== 'float32' ) fail( 'argument', where, `precision is ${JSON.stringify( precision )}; expected "float16" or "float32".` );
	const data = validateBakedVolume( input, where );
	const probeCount = data.positions.length / 3;
	const tetCount = data.tetrahedra.length / 4;

	// SH and gradients in the file's precision: float32 as they are, float16 converted (header flag bit 0).
	const sh = precision === 'float16' ? toFloat16( where, 'sh', data.sh ) : data.sh;
	// The gradient bound is ≥ 1e30 / (2e18·√3) ≈ 2.9e11 (positions within ±1e18), beyond float16's
	// range: float16 roundings never cross it.
	const gradients = data.gradients && precision === 'float16' ? toFloat16( where, 'gradients', data.gradients ) : data.gradients;
	const fitText = data.fit ? utf8Encoder.encode( JSON.stringify( data.fit ) ) : null;

	const roleBytes = new Uint8Array( probeCount );
	for ( let i = 0; i < probeCount; i ++ ) roleBytes[ i ] = BAKED_ROLES.indexOf( data.roles[ i ] );

	const encodedNames = data.names.map( ( name ) => utf8Encoder.encode( name ) );
	const nameBytes = encodedNames.reduce( ( sum, b ) => sum + b.length, 0 );
	const zoneNames = data.zones.map( ( zone ) => utf8Encoder.encode( zone.name ) );
	const captureText = Object.keys( data.capture ).length > 0 ? utf8Encoder.encode( JSON.stringify( data.capture ) ) : null;
	const metadataText = data.metadata.length > 0 ? utf8Encoder.encode( data.metadata ) : null;

	type Section = { id: number; required: boolean; length: number; write: ( view: DataView, bytes: Uint8Array, at: number ) => void };
	const sections: Section[] = [];
	const typed = ( id: number, array: ArrayBufferView, required = true ): Section => ( {
		id, required, length: array.byteLength,
		write: ( view, bytes, at ) => writeLE( view, bytes, at, array ),
	} );

	sections.push( typed( BAKED_SECTION.POSITIONS, data.positions ) );
	sections.push( typed( BAKED_SECTION.SH, sh ) );
	if ( tetCount > 0 ) {

		sections.push( typed( BAKED_SECTION.TETRAHEDRA, data.tetrahedra ) );
		sections.push( typed( BAKED_SECTION.NEIGHBORS, data.neighbors ) );

	}

	const blob = ( id: number, required: boolean, content: Uint8Array ): Section => ( {
		id, required, length: content.length,
		write: ( _view, bytes, at ) => bytes.set( content, at ),
	} );

	sections.push( blob( BAKED_SECTION.ROLES, true, roleBytes ) );
	if ( nameBytes > 0 ) {

		sections.push( { id: BAKED_SECTION.NAMES, required: true, length: 4 * probeCount + nameBytes, write: ( view, bytes, at ) => {

			let end = 0, blob = at + 4 * probeCount;
			encodedNames.forEach( ( b, i ) => {

				bytes.set( b, blob + end );
				end += b.length;
				view.setUint32( at + 4 * i, end, true );

			} );

		} } );

	}

	if ( data.zones.length > 0 ) {

		let length = 0;
		data.zones.forEach( ( zone, z ) => {

			length += 16 + align8( zoneNames[ z ].length ) + align8( 4 * zone.probes.length ) + 8 * zone.bounds.length;

		} );
		sections.push( { id: BAKED_SECTION.ZONES, required: true, length, write: ( view, bytes, at ) => {

			data.zones.forEach( ( zone, z ) => {

				const boxes = zone.bounds.length / 6;
				view.setUint32( at, zoneNames[ z ].length, true );
				view.setUint32( at + 4, zone.probes.length, true );
				view.setUint32( at + 8, boxes, true );
				at += 16;
				bytes.set( zoneNames[ z ], at );
				at += align8( zoneNames[ z ].length );
				for ( let i = 0; i < zone.probes.length; i ++ ) view.setUint32( at + 4 * i, zone.probes[ i ], true );
				at += align8( 4 * zone.probes.length );
				for ( let i = 0; i < zone.bounds.length; i ++ ) view.setFloat64( at + 8 * i, zone.bounds[ i ], true );
				at += 8 * zone.bounds.length;

			} );

		} } );

	}

	sections.push( typed( BAKED_SECTION.BOUNDS, data.bounds ) );
	if ( captureText ) sections.push( blob( BAKED_SECTION.CAPTURE, false, captureText ) );
	if ( metadataText ) sections.push( blob( BAKED_SECTION.METADATA, false, metadataText ) );
	// Optional (1.1): a 1.0 reader skips them and lights with the SH alone.
	if ( gradients ) sections.push( typed( BAKED_SECTION.GRADIENTS, gradients, false ) );
	if ( fitText ) sections.push( blob( BAKED_SECTION.FIT, false, fitText ) );

	let offset = align8( HEADER_SIZE + ENTRY_SIZE * sections.length );
	const offsets = sections.map( ( section ) => {

		const at = offset;
		offset = align8( offset + section.length );
		return at;

	} );
	const fileLength = offset;
	if ( fileLength > 0xFFFFFFFF ) fail( 'count', where, `the volume needs ${fileLength} bytes; the format's limit is 4 GiB.` );

	const buffer = new ArrayBuffer( fileLength );
	const view = new DataView( buffer );
	const bytes = new Uint8Array( buffer );
	bytes.set( BAKED_VOLUME_MAGIC, 0 );
	view.setUint16( 8, BAKED_VOLUME_VERSION_MAJOR, true );
	view.setUint16( 10, bakedVolumeMinorVersion( data ), true );
	view.setUint32( 16, fileLength, true );
	view.setUint32( 20, HEADER_SIZE, true );
	view.setUint32( 24, precision === 'float16' ? FLAG_SH_FLOAT16 : 0, true );
	view.setUint32( 28, probeCount, true );
	view.setUint32( 32, tetCount, true );
	view.setUint32( 36, data.zones.length, true );
	view.setUint32( 40, sections.length, true );
	view.setUint32( 44, nameBytes, true );
	sections.forEach( ( section, s ) => {

		const entry = HEADER_SIZE + ENTRY_SIZE * s;
		view.setUint32( entry, section.id, true );
		view.setUint32( entry + 4, section.required ? SECTION_REQUIRED : 0, true );
		view.setUint32( entry + 8, offsets[ s ], true );
		view.setUint32( entry + 12, section.length, true );
		section.write( view, bytes, offsets[ s ] );

	} );
	view.setUint32( 12, crc32( bytes, 16, fileLength ), true );
	return buffer;

}

/** Float16 bits of every value ('float16-overflow' naming `name` and the index for a value beyond ±65504). */
function toFloat16( where: string, name: string, values: Float32Array ): Uint16Array {

	const half = new Uint16Array( values.length );
	for ( let i = 0; i < half.length; i ++ ) {

		const h = toFloat16Bits( values[ i ] );
		if ( h < 0 ) fail( 'float16-overflow', where, `${name}[${i}] = ${values[ i ]} is beyond the float16 range (±${FLOAT16_MAX}); use { precision: 'float32' }.` );
		half[ i ] = h;

	}

	return half;

}

/** Copies a typed array's elements little-endian at `at`. */
function writeLE( view: DataView, bytes: Uint8Array, at: number, array: ArrayBufferView ): void {

	if ( LITTLE_ENDIAN ) {

		bytes.set( new Uint8Array( array.buffer, array.byteOffset, array.byteLength ), at );
		return;

	}

	if ( array instanceof Float64Array ) for ( let i = 0; i < array.length; i ++ ) view.setFloat64( at + 8 * i, array[ i ], true );
	else if ( array instanceof Float32Array ) for ( let i = 0; i < array.length; i ++ ) view.setFloat32( at + 4 * i, array[ i ], true );
	else if ( array instanceof Uint32Array ) for ( let i = 0; i < array.length; i ++ ) view.setUint32( at + 4 * i, array[ i ], true );
	else if ( array instanceof Int32Array ) for ( let i = 0; i < array.length; i ++ ) view.setInt32( at + 4 * i, array[ i ], true );
	else if ( array instanceof Uint16Array ) for ( let i = 0; i < array.length; i ++ ) view.setUint16( at + 2 * i, array[ i ], true );

}
