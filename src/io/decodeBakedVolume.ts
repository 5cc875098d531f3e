import { checkZoneName, checkZoneProbes, type ProbeRole } from '../roles.js';
import { BakedVolumeError } from './BakedVolumeError.js';
import { crc32 } from './crc32.js';
import { float16Table } from './float16.js';
import {
	align8, BAKED_ROLES, BAKED_SECTION, BAKED_VOLUME_MAGIC, BAKED_VOLUME_VERSION_MAJOR,
	ENTRY_SIZE, FLAG_SH_FLOAT16, GRADIENT_FLOATS, HEADER_SIZE, KNOWN_SECTIONS, LITTLE_ENDIAN, SECTION_REQUIRED, sectionName,
} from './bakedVolumeFormat.js';
import {
	boxOf, checkBox, checkCapture, checkFinite, checkFit, checkGradients, checkPositions, checkSH, checkTetrahedralization,
	codecReject, fail,
} from './checks.js';
import type { BakedCapture, BakedVolumeData, BakedZone } from './bakedVolumeTypes.js';

/*
 * The binary reader. Loading is defensive: every count is checked against the section lengths, and
 * every section against the buffer, before anything proportional to a count is allocated; then
 * every value is checked (finite numbers, indices in range, positively oriented tetrahedra,
 * symmetric neighbour links that share a face and lie on opposite sides of it). All loops are
 * bounded by the buffer length, so no input can make the reader hang or allocate more than a small
 * multiple of the file.
 */

const utf8Decoder = new TextDecoder( 'utf-8', { fatal: true, ignoreBOM: true } );

type TypedCtor = Float64ArrayConstructor | Float32ArrayConstructor | Uint32ArrayConstructor | Int32ArrayConstructor
	| Uint16ArrayConstructor;

/**
 * A typed array over `length` elements at `at`: a view of the buffer when the platform is
 * little-endian and the address is aligned (no copy), else a copy read through the DataView.
 */
function readTyped<T extends TypedCtor>( Ctor: T, view: DataView, at: number, length: number ): InstanceType<T> {

	const size = Ctor.BYTES_PER_ELEMENT;
	const address = view.byteOffset + at;
	if ( LITTLE_ENDIAN && address % size === 0 ) return new Ctor( view.buffer as ArrayBuffer, address, length ) as InstanceType<T>;
	if ( LITTLE_ENDIAN ) return new Ctor( view.buffer.slice( address, address + size * length ) as ArrayBuffer ) as InstanceType<T>;
	const out = new Ctor( length ) as InstanceType<T>;
	for ( let i = 0; i < length; i ++ ) {

		const p = at + size * i;
		out[ i ] = Ctor === Float64Array ? view.getFloat64( p, true ) : Ctor === Float32Array ? view.getFloat32( p, true )
			: Ctor === Uint32Array ? view.getUint32( p, true ) : Ctor === Int32Array ? view.getInt32( p, true ) : view.getUint16( p, true );

	}

	return out;

}

/** UTF-8 text of `length` bytes at `at` ('utf8' when invalid). */
function readString( where: string, name: string, bytes: Uint8Array, at: number, length: number ): string {

	try {

		return utf8Decoder.decode( bytes.subarray( at, at + length ) );

	} catch {

		fail( 'utf8', where, `${name} is not valid UTF-8.` );

	}

}

/** The JSON value of `length` bytes of UTF-8 at `at` ('utf8', 'json' when invalid); `name` says what it is. */
function readJSON( where: string, name: string, bytes: Uint8Array, at: number, length: number ): unknown {

	const text = readString( where, name, bytes, at, length );
	try {

		return JSON.parse( text );

	} catch ( error ) {

		fail( 'json', where, `${name} is not valid JSON (${( error as Error ).message}).` );

	}

}

/**
 * `length` floats at `at`: float32 viewed in place where alignment allows (as {@link readTyped}),
 * float16 converted to float32, whose NaN and Infinity bit patterns are refused here ('nan').
 */
function readFloats( where: string, name: string, view: DataView, at: number, length: number, half: boolean ): Float32Array {

	if ( ! half ) return readTyped( Float32Array, view, at, length );
	const bits = readTyped( Uint16Array, view, at, length );
	const table = float16Table();
	const out = new Float32Array( length );
	for ( let i = 0; i < length; i ++ ) {

		if ( ( bits[ i ] & 0x7C00 ) === 0x7C00 ) fail( 'nan', where, `${name}[${i}] is ${bits[ i ] & 0x3FF ? 'NaN' : 'Infinity'} (float16 bits 0x${bits[ i ].toString( 16 )}); every value must be finite.` );
		out[ i ] = table[ bits[ i ] ];

	}

	return out;

}

/**
 * Reads a volume written by {@link encodeBakedVolume} (any 1.x minor version) and checks it
 * completely; see docs/format.md for the layout and the rules. Typed arrays in the result are views
 * of `buffer` where alignment allows (no copy): do not reuse the buffer while the data is in use.
 * Bytes after the declared file length are ignored.
 * @param buffer The file, or a view of it (e.g. a Node `Buffer` or a glTF bufferView).
 * @throws {BakedVolumeError} with `code` naming the failure class; never another error type.
 */
export function decodeBakedVolume( buffer: ArrayBuffer | ArrayBufferView ): BakedVolumeData {

	const where = 'decodeBakedVolume';
	let bytes: Uint8Array;
	if ( buffer instanceof ArrayBuffer ) bytes = new Uint8Array( buffer );
	else if ( ArrayBuffer.isView( buffer ) ) bytes = new Uint8Array( buffer.buffer, buffer.byteOffset, buffer.byteLength );
	else fail( 'argument', where, 'expected an ArrayBuffer or a typed array / DataView of the file.' );
	const view = new DataView( bytes.buffer, bytes.byteOffset, bytes.byteLength );
	const available = bytes.length;

	for ( let i = 0; i < 8; i ++ ) {

		if ( i >= available ) fail( 'truncated', where, `the buffer ends after ${available} bytes, inside the magic bytes.` );
		if ( bytes[ i ] !== BAKED_VOLUME_MAGIC[ i ] ) fail( 'bad-magic', where, 'not a baked light probe volume (the first 8 bytes are not the format\'s magic bytes AB 4C 50 56 0D 0A 1A 0A).' );

	}

	if ( available < HEADER_SIZE ) fail( 'truncated', where, `the buffer is ${available} bytes, shorter than the ${HEADER_SIZE}-byte header.` );
	const major = view.getUint16( 8, true ), minor = view.getUint16( 10, true );
	if ( major > BAKED_VOLUME_VERSION_MAJOR ) fail( 'version', where, `version ${major}.${minor} is newer than this reader (supports ≤ ${BAKED_VOLUME_VERSION_MAJOR}.x).` );
	if ( major < 1 ) fail( 'version', where, `version ${major}.${minor} is not a released version of the format (this reader supports 1.x).` );
	const fileLength = view.getUint32( 16, true );
	if ( fileLength > available ) fail( 'truncated', where, `the header declares ${fileLength} bytes but the buffer holds ${available}: the file is truncated.` );
	if ( fileLength < HEADER_SIZE ) fail( 'header', where, `the declared file length ${fileLength} is shorter than the header.` );
	const storedCRC = view.getUint32( 12, true );
	const computedCRC = crc32( bytes, 16, fileLength );
	if ( storedCRC !== computedCRC ) {

		fail( 'checksum', where, `corrupted: CRC-32 of bytes 16..${fileLength} is 0x${computedCRC.toString( 16 ).padStart( 8, '0' )}, the header says 0x${storedCRC.toString( 16 ).padStart( 8, '0' )}.` );

	}

	const headerSize = view.getUint32( 20, true );
	if ( headerSize < HEADER_SIZE || headerSize % 8 !== 0 || headerSize > fileLength ) fail( 'header', where, `header size ${headerSize} is not a multiple of 8 between ${HEADER_SIZE} and the file length ${fileLength}.` );
	const flags = view.getUint32( 24, true );
	if ( ( flags & ~ FLAG_SH_FLOAT16 ) !== 0 ) fail( 'header', where, `flags 0x${flags.toString( 16 )} set reserved bits (only bit 0, SH as float16, is defined in 1.x).` );
	const probeCount = view.getUint32( 28, true );
	const tetCount = view.getUint32( 32, true );
	const zoneCount = view.getUint32( 36, true );
	const sectionCount = view.getUint32( 40, true );
	const nameBytes = view.getUint32( 44, true );
	if ( sectionCount > ( fileLength - headerSize ) / ENTRY_SIZE ) fail( 'count', where, `sectionCount ${sectionCount} does not fit in the ${fileLength}-byte file.` );
	const tableEnd = headerSize + ENTRY_SIZE * sectionCount;

	// Section table: every section inside the file, after the table, 8-aligned, no overlap, no duplicate.
	const found = new Map<number, { offset: number; length: number }>();
	const spans: [ number, number, number ][] = [];
	for ( let s = 0; s < sectionCount; s ++ ) {

		const entry = headerSize + ENTRY_SIZE * s;
		const id = view.getUint32( entry, true ), sectionFlags = view.getUint32( entry + 4, true );
		const offset = view.getUint32( entry + 8, true ), length = view.getUint32( entry + 12, true );
		if ( offset % 8 !== 0 ) fail( 'section', where, `section ${sectionName( id )} starts at ${offset}, not a multiple of 8.` );
		if ( offset < tableEnd || offset + length > fileLength ) fail( 'section', where, `section ${sectionName( id )} (bytes ${offset}..${offset + length}) is outside the data area ${tableEnd}..${fileLength}.` );
		if ( found.has( id ) ) fail( 'section', where, `section ${sectionName( id )} appears twice.` );
		if ( ! KNOWN_SECTIONS.has( id ) && ( sectionFlags & SECTION_REQUIRED ) ) fail( 'version', where, `section ${sectionName( id )} is required but unknown to this reader (version ${major}.${minor} file).` );
		found.set( id, { offset, length } );
		spans.push( [ offset, offset + length, id ] );

	}

	spans.sort( ( a, b ) => a[ 0 ] - b[ 0 ] );
	for ( let s = 1; s < spans.length; s ++ ) {

		if ( spans[ s ][ 0 ] < spans[ s - 1 ][ 1 ] ) fail( 'section', where, `sections ${sectionName( spans[ s - 1 ][ 2 ] )} and ${sectionName( spans[ s ][ 2 ] )} overlap.` );

	}

	const section = ( id: number, expected: number | null, required: boolean, what: string ): { offset: number; length: number } | null => {

		const entry = found.get( id );
		if ( ! entry ) {

			if ( required ) fail( 'section', where, `the required section ${sectionName( id )} (${what}) is missing.` );
			return null;

		}

		if ( expected !== null && entry.length !== expected ) {

			fail( 'count', where, `section ${sectionName( id )} is ${entry.length} bytes but the header's counts need ${expected} (${what}).` );

		}

		return entry;

	};

	// Counts against section lengths before anything proportional to a count is allocated; the
	// sections are inside the file, so every allocation below is bounded by the file size.
	if ( probeCount < 1 ) fail( 'count', where, 'probeCount is 0; a volume has at least one probe.' );
	const half = ( flags & FLAG_SH_FLOAT16 ) !== 0;
	const pos = section( BAKED_SECTION.POSITIONS, 24 * probeCount, true, `${probeCount} probes × 3 float64` )!;
	const shs = section( BAKED_SECTION.SH, ( half ? 54 : 108 ) * probeCount, true, `${probeCount} probes × 27 ${half ? 'float16' : 'float32'}` )!;
	const tets = section( BAKED_SECTION.TETRAHEDRA, 16 * tetCount, tetCount > 0, `${tetCount} tetrahedra × 4 u32` );
	const nbrs = section( BAKED_SECTION.NEIGHBORS, 16 * tetCount, tetCount > 0, `${tetCount} tetrahedra × 4 i32` );
	const rls = section( BAKED_SECTION.ROLES, probeCount, false, `${probeCount} probes × u8` );
	const nms = section( BAKED_SECTION.NAMES, 4 * probeCount + nameBytes, false, `${probeCount} u32 ends + ${nameBytes} bytes of UTF-8` );
	if ( ! nms && nameBytes !== 0 ) fail( 'count', where, `the header declares ${nameBytes} bytes of names but there is no NAME section.` );
	const zns = section( BAKED_SECTION.ZONES, null, zoneCount > 0, `${zoneCount} zones` );
	if ( zns && zoneCount > zns.length / 16 ) fail( 'count', where, `zoneCount ${zoneCount} does not fit in the ${zns.length}-byte ZONE section.` );
	const bnd = section( BAKED_SECTION.BOUNDS, 48, false, '6 float64' );
	const cpt = section( BAKED_SECTION.CAPTURE, null, false, 'UTF-8 JSON' );
	const mta = section( BAKED_SECTION.METADATA, null, false, 'UTF-8 text' );
	const grd = section( BAKED_SECTION.GRADIENTS, ( half ? 162 : 324 ) * probeCount, false, `${probeCount} probes × 81 ${half ? 'float16' : 'float32'}` );
	const fts = section( BAKED_SECTION.FIT, null, false, 'UTF-8 JSON' );

	const positions = readTyped( Float64Array, view, pos.offset, 3 * probeCount );
	checkPositions( where, positions );

	const sh = readFloats( where, 'sh', view, shs.offset, 27 * probeCount, half );
	checkSH( where, 'sh', sh );

	let tetrahedra: Uint32Array = new Uint32Array( 0 ), neighbors: Int32Array = new Int32Array( 0 );
	if ( tetCount > 0 ) {

		const storedTetrahedra = readTyped( Uint32Array, view, tets!.offset, 4 * tetCount );
		const storedNeighbors = readTyped( Int32Array, view, nbrs!.offset, 4 * tetCount );
		( { tetrahedra, neighbors } = checkTetrahedralization( where, positions, storedTetrahedra, storedNeighbors ) );

	}

	const roles: ProbeRole[] = new Array( probeCount );
	for ( let i = 0; i < probeCount; i ++ ) {

		const code = rls ? bytes[ rls.offset + i ] : 3; // no ROLE section: fill
		if ( code >= BAKED_ROLES.length ) fail( 'range', where, `roles[${i}] has code ${code}; expected 0 (sky), 1 (bounce), 2 (bleed) or 3 (fill).` );
		roles[ i ] = BAKED_ROLES[ code ];

	}

	const names: string[] = new Array( probeCount );
	if ( nms ) {

		const blob = nms.offset + 4 * probeCount;
		let start = 0;
		for ( let i = 0; i < probeCount; i ++ ) {

			const end = view.getUint32( nms.offset + 4 * i, true );
			if ( end < start || end > nameBytes ) fail( 'range', where, `names: end offset ${i} is ${end}, outside ${start}..${nameBytes}.` );
			names[ i ] = readString( where, `names[${i}]`, bytes, blob + start, end - start );
			start = end;

		}

		if ( start !== nameBytes ) fail( 'count', where, `names use ${start} of the ${nameBytes} bytes the header declares.` );

	} else {

		names.fill( '' );

	}

	const zones: BakedZone[] = [];
	if ( zns ) {

		// The zone rules of src/roles.ts, which the runtime applies too: unique names, ≥ 1 probe each.
		const reject = codecReject( where ), seen = new Set<string>();

		let at = zns.offset;
		const end = zns.offset + zns.length;
		for ( let z = 0; z < zoneCount; z ++ ) {

			if ( at + 16 > end ) fail( 'count', where, `zone ${z}'s record starts beyond the ZONE section.` );
			const nameLength = view.getUint32( at, true ), count = view.getUint32( at + 4, true ), boxes = view.getUint32( at + 8, true );
			// Each size is checked against the bytes left before it is used, in float64 arithmetic (no overflow).
			const size = 16 + align8( nameLength ) + align8( 4 * count ) + 48 * boxes;
			if ( size > end - at ) fail( 'count', where, `zone ${z} declares ${nameLength} name bytes, ${count} probes and ${boxes} boxes: ${size} bytes, but ${end - at} are left in the ZONE section.` );
			at += 16;
			const name = checkZoneName( readString( where, `zones[${z}].name`, bytes, at, nameLength ), z, seen, reject );
			at += align8( nameLength );
			const probes = checkZoneProbes( readTyped( Uint32Array, view, at, count ), `zones[${z}].probes`, probeCount, reject );
			at += align8( 4 * count );
			const zoneBounds = readTyped( Float64Array, view, at, 6 * boxes );
			checkFinite( where, `zones[${z}].bounds`, zoneBounds );
			for ( let b = 0; b < zoneBounds.length; b += 6 ) checkBox( where, `zones[${z}].bounds`, zoneBounds, b );
			at += 48 * boxes;
			zones.push( { name, probes, bounds: zoneBounds } );

		}

		if ( at !== end ) fail( 'count', where, `the ZONE section has ${end - at} bytes after its ${zoneCount} zones.` );

	}

	let bounds: Float64Array;
	if ( bnd ) {

		bounds = readTyped( Float64Array, view, bnd.offset, 6 );
		checkFinite( where, 'bounds', bounds );
		checkBox( where, 'bounds', bounds, 0 );

	} else {

		bounds = boxOf( positions );

	}

	const capture: BakedCapture = cpt ? checkCapture( where, readJSON( where, 'the capture settings section (CAPT)', bytes, cpt.offset, cpt.length ) ) : {};
	let gradients: Float32Array | null = null;
	if ( grd ) {

		gradients = readFloats( where, 'gradients', view, grd.offset, GRADIENT_FLOATS * probeCount, half );
		checkGradients( where, gradients, positions );

	}

	const fit = fts ? checkFit( where, readJSON( where, 'the fit record section (FITS)', bytes, fts.offset, fts.length ), gradients !== null ) : null;
	const metadata = mta ? readString( where, 'metadata', bytes, mta.offset, mta.length ) : '';
	return { positions, sh, tetrahedra, neighbors, names, roles, zones, bounds, capture, metadata, gradients, fit };

}
