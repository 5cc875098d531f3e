import { orient3d } from 'robust-predicates';
import { expect } from 'vitest';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { BakedVolumeError, type BakedVolumeData, type BakedVolumeErrorCode, type BakedVolumeInput } from '../../src/io/index.js';

/*
 * Test-side helpers written from docs/format.md, not from the codec: a bitwise CRC-32, a section
 * table reader and writer, and a brute-force validity check of decoded data; and the expectations
 * the codec tests share.
 */

/** Bit-at-a-time CRC-32 (IEEE), the textbook definition. */
export function referenceCRC32( bytes: Uint8Array, start = 0, end = bytes.length ): number {

	let c = 0xFFFFFFFF;
	for ( let i = start; i < end; i ++ ) {

		c ^= bytes[ i ];
		for ( let k = 0; k < 8; k ++ ) c = c & 1 ? ( c >>> 1 ) ^ 0xEDB88320 : c >>> 1;

	}

	return ( c ^ 0xFFFFFFFF ) >>> 0;

}

const CRC_TABLE = Uint32Array.from( { length: 256 }, ( _, n ) => {

	let c = n;
	for ( let k = 0; k < 8; k ++ ) c = c & 1 ? ( c >>> 1 ) ^ 0xEDB88320 : c >>> 1;
	return c >>> 0;

} );

/** Byte-at-a-time table CRC-32 (the same function as referenceCRC32, fast enough for the fuzz loop). */
export function tableCRC32( bytes: Uint8Array, start = 0, end = bytes.length ): number {

	let c = 0xFFFFFFFF;
	for ( let i = start; i < end; i ++ ) c = CRC_TABLE[ ( c ^ bytes[ i ] ) & 0xFF ] ^ ( c >>> 8 );
	return ( c ^ 0xFFFFFFFF ) >>> 0;

}

/** Writes a valid checksum (bytes 12..15 = CRC-32 of bytes 16..fileLength, clamped to the buffer). */
export function fixChecksum( bytes: Uint8Array ): Uint8Array {

	if ( bytes.length < 20 ) return bytes;
	const view = new DataView( bytes.buffer, bytes.byteOffset, bytes.byteLength );
	const end = Math.min( view.getUint32( 16, true ), bytes.length );
	if ( end < 16 ) return bytes;
	view.setUint32( 12, tableCRC32( bytes, 16, end ), true );
	return bytes;

}

export const fourCC = ( s: string ): number => ( s.charCodeAt( 0 ) | ( s.charCodeAt( 1 ) << 8 ) | ( s.charCodeAt( 2 ) << 16 ) | ( s.charCodeAt( 3 ) << 24 ) ) >>> 0;

export interface RawSection { id: number; flags: number; bytes: Uint8Array }

/** Header fields and sections of a file, read per docs/format.md (trusting a valid file). */
export function readSections( buffer: ArrayBuffer ): { header: Uint8Array; sections: RawSection[] } {

	const view = new DataView( buffer );
	const headerSize = view.getUint32( 20, true ), count = view.getUint32( 40, true );
	const sections: RawSection[] = [];
	for ( let s = 0; s < count; s ++ ) {

		const e = headerSize + 16 * s;
		const offset = view.getUint32( e + 8, true ), length = view.getUint32( e + 12, true );
		sections.push( { id: view.getUint32( e, true ), flags: view.getUint32( e + 4, true ), bytes: new Uint8Array( buffer.slice( offset, offset + length ) ) } );

	}

	return { header: new Uint8Array( buffer.slice( 0, headerSize ) ), sections };

}

/** Lays out a file per docs/format.md: header (copied, counts kept), table, 8-aligned sections, checksum. */
export function writeSections( header: Uint8Array, sections: RawSection[] ): ArrayBuffer {

	const headerSize = header.length;
	let offset = ( headerSize + 16 * sections.length + 7 ) & ~ 7;
	const offsets = sections.map( ( s ) => {

		const at = offset;
		offset = ( offset + s.bytes.length + 7 ) & ~ 7;
		return at;

	} );
	const buffer = new ArrayBuffer( offset );
	const bytes = new Uint8Array( buffer ), view = new DataView( buffer );
	bytes.set( header, 0 );
	view.setUint32( 16, offset, true );
	view.setUint32( 20, headerSize, true );
	view.setUint32( 40, sections.length, true );
	sections.forEach( ( s, i ) => {

		const e = headerSize + 16 * i;
		view.setUint32( e, s.id, true );
		view.setUint32( e + 4, s.flags, true );
		view.setUint32( e + 8, offsets[ i ], true );
		view.setUint32( e + 12, s.bytes.length, true );
		bytes.set( s.bytes, offsets[ i ] );

	} );
	fixChecksum( bytes );
	return buffer;

}

/** A random volume of n probes in a 10 m box, tetrahedralized, with names, roles, zones, capture and metadata. */
export function makeVolume( n: number, seed: number, extras = true ): BakedVolumeInput & { tetrahedra: Uint32Array; neighbors: Int32Array } {

	const random = mulberry32( seed );
	const positions = new Float64Array( 3 * n );
	for ( let i = 0; i < positions.length; i ++ ) positions[ i ] = 10 * random() - 5;
	const sh = new Float32Array( 27 * n );
	for ( let i = 0; i < sh.length; i ++ ) sh[ i ] = 4 * random() - 1;
	const { tetrahedra, neighbors } = tetrahedralize( positions );
	if ( ! extras ) return { positions, sh, tetrahedra, neighbors };
	const roles = [ 'sky', 'bounce', 'bleed', 'fill' ] as const;
	return {
		positions, sh, tetrahedra, neighbors,
		names: Array.from( { length: n }, ( _, i ) => i % 3 === 0 ? '' : `probe ${i} — hall ✓` ),
		roles: Array.from( { length: n }, ( _, i ) => roles[ i % 4 ] ),
		zones: [
			{ name: 'hall', probes: Uint32Array.from( { length: Math.min( n, 7 ) }, ( _, i ) => i ), bounds: [ - 5, - 5, - 5, 0, 5, 5, 0, - 5, - 5, 5, 5, 5 ] },
			{ name: '', probes: [ n - 1 ] },
		],
		bounds: [ - 6, - 6, - 6, 6, 6, 6 ],
		capture: { resolution: 32, near: 0.05, far: 500, type: 'half', solidAngle: 'exact', roles: { sky: { far: 5000 }, bounce: { far: 20 } } },
		metadata: `seed ${seed}`,
	};

}

/** The volume with seeded gradients (81 per probe in [−1, 1)) and a fit record (version 1.1 sections). */
export function withGradients<T extends BakedVolumeInput>( volume: T, seed: number ): T {

	const random = mulberry32( seed );
	const gradients = Float32Array.from( { length: 27 * volume.positions.length }, () => 2 * random() - 1 );
	const fit = { samples: 500, gradients: true, lambda: 0.25, gradientLambda: 0.5, crossValidationError: 0.08, source: `seed ${seed}` };
	return { ...volume, gradients, fit };

}

const ROLES = new Set( [ 'sky', 'bounce', 'bleed', 'fill' ] );

/**
 * Brute-force validity of decoded data: lengths, finiteness, index ranges, positive orientation
 * (robust-predicates directly), and neighbours re-derived from a face map: every face shared by
 * exactly two tetrahedra which point at each other with their apexes on opposite sides, every
 * other face on the hull (−1). Returns the first problem, or null.
 */
export function independentCheck( d: BakedVolumeData ): string | null {

	const n = d.positions.length / 3;
	if ( ! Number.isInteger( n ) || n < 1 ) return 'positions length';
	if ( d.sh.length !== 27 * n ) return 'sh length';
	// docs/format.md: |coordinate| ≤ 1e18, |SH value| ≤ 1e30 (as float32 rounds it), names UTF-8, zone names unique, zones not empty.
	for ( const v of d.positions ) if ( ! ( Math.abs( v ) <= 1e18 ) ) return 'positions finite and within ±1e18';
	for ( const v of d.sh ) if ( ! ( Math.abs( v ) <= Math.fround( 1e30 ) ) ) return 'sh finite and within ±1e30';
	const utf8 = ( text: string ) => new TextDecoder( 'utf-8', { fatal: true } ).decode( new TextEncoder().encode( text ) ) === text;
	if ( d.names.length !== n || d.names.some( ( s ) => typeof s !== 'string' || ! utf8( s ) ) ) return 'names';
	if ( new Set( d.zones.map( ( zone ) => zone.name ) ).size !== d.zones.length ) return 'zone names unique';
	if ( d.zones.some( ( zone ) => zone.probes.length === 0 || ! utf8( zone.name ) ) ) return 'zones hold a probe';
	if ( d.roles.length !== n || d.roles.some( ( r ) => ! ROLES.has( r ) ) ) return 'roles';
	if ( d.bounds.length !== 6 || [ 0, 1, 2 ].some( ( k ) => ! ( d.bounds[ k ] <= d.bounds[ k + 3 ] ) ) || ! d.bounds.every( Number.isFinite ) ) return 'bounds';
	for ( const zone of d.zones ) {

		if ( typeof zone.name !== 'string' ) return 'zone name';
		for ( const p of zone.probes ) if ( ! ( p < n ) ) return 'zone probe';
		if ( zone.bounds.length % 6 !== 0 || ! zone.bounds.every( Number.isFinite ) ) return 'zone bounds';
		for ( let b = 0; b < zone.bounds.length; b += 6 ) if ( [ 0, 1, 2 ].some( ( k ) => ! ( zone.bounds[ b + k ] <= zone.bounds[ b + k + 3 ] ) ) ) return 'zone box';

	}

	// docs/format.md (1.1): gradients null or 81 per probe, finite, within 1e30 / the positions' box diagonal; a valid fit record.
	if ( d.gradients !== null ) {

		if ( d.gradients.length !== 81 * n ) return 'gradients length';
		const low = [ 0, 1, 2 ].map( ( k ) => Math.min( ...d.positions.filter( ( _, i ) => i % 3 === k ) ) );
		const high = [ 0, 1, 2 ].map( ( k ) => Math.max( ...d.positions.filter( ( _, i ) => i % 3 === k ) ) );
		const diagonal = Math.hypot( high[ 0 ] - low[ 0 ], high[ 1 ] - low[ 1 ], high[ 2 ] - low[ 2 ] );
		const bound = diagonal > 0 ? Math.min( Math.fround( 1e30 ) / diagonal, 3.4028234663852886e38 ) : 3.4028234663852886e38;
		for ( const v of d.gradients ) if ( ! ( Math.abs( v ) <= bound ) ) return 'gradients finite and within the bound';

	}

	if ( d.fit !== null ) {

		const f = d.fit;
		if ( ! Number.isInteger( f.samples ) || f.samples < 0 || typeof f.gradients !== 'boolean' ) return 'fit samples, gradients';
		if ( ! ( f.lambda >= 0 && f.gradientLambda >= 0 && Number.isFinite( f.lambda ) && Number.isFinite( f.gradientLambda ) ) ) return 'fit λ';
		if ( f.crossValidationError !== null && ! ( f.crossValidationError >= 0 && Number.isFinite( f.crossValidationError ) ) ) return 'fit error';
		if ( f.gradients && d.gradients === null ) return 'fit claims gradients';

	}

	const T = d.tetrahedra.length / 4, p = d.positions;
	if ( ! Number.isInteger( T ) || d.neighbors.length !== 4 * T ) return 'tetrahedra length';
	for ( const v of d.tetrahedra ) if ( ! ( v < n ) ) return 'tetrahedron vertex';
	const sign = ( a: number, b: number, c: number, e: number ): number => - orient3d(
		p[ 3 * a ], p[ 3 * a + 1 ], p[ 3 * a + 2 ], p[ 3 * b ], p[ 3 * b + 1 ], p[ 3 * b + 2 ],
		p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ], p[ 3 * e ], p[ 3 * e + 1 ], p[ 3 * e + 2 ] );
	// Faces keyed by their sorted vertex triple (a number: n ≤ 2^17 keeps it exact).
	const faces = new Map<number, number[]>();
	for ( let t = 0; t < T; t ++ ) {

		const v = d.tetrahedra.subarray( 4 * t, 4 * t + 4 );
		if ( ! ( sign( v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ] ) > 0 ) ) return `orientation of ${t}`;
		for ( let i = 0; i < 4; i ++ ) {

			const f = [ v[ ( i + 1 ) % 4 ], v[ ( i + 2 ) % 4 ], v[ ( i + 3 ) % 4 ] ].sort( ( a, b ) => a - b );
			const key = ( f[ 0 ] * n + f[ 1 ] ) * n + f[ 2 ];
			const list = faces.get( key );
			if ( list ) list.push( 4 * t + i ); else faces.set( key, [ 4 * t + i ] );

		}

	}

	for ( const [ key, list ] of faces ) {

		if ( list.length > 2 ) return `face ${key} in ${list.length} tetrahedra`;
		if ( list.length === 1 ) {

			if ( d.neighbors[ list[ 0 ] ] !== - 1 ) return `hull face ${key} has neighbour ${d.neighbors[ list[ 0 ] ]}`;
			continue;

		}

		const t = list[ 0 ] >> 2, i = list[ 0 ] & 3, u = list[ 1 ] >> 2, j = list[ 1 ] & 3;
		if ( d.neighbors[ 4 * t + i ] !== u || d.neighbors[ 4 * u + j ] !== t ) return `face ${key}: links ${d.neighbors[ 4 * t + i ]}, ${d.neighbors[ 4 * u + j ]}`;
		// u's apex replacing t's apex must give a negatively oriented tetrahedron (the other side).
		const v = Array.from( d.tetrahedra.subarray( 4 * t, 4 * t + 4 ) );
		v[ i ] = d.tetrahedra[ 4 * u + j ];
		if ( ! ( sign( v[ 0 ], v[ 1 ], v[ 2 ], v[ 3 ] ) < 0 ) ) return `face ${key}: apexes on one side`;

	}

	return null;

}

/** Runs `run`, expects a BakedVolumeError of `code` (and a message matching `message`), and returns it. */
export function expectError( code: BakedVolumeErrorCode, run: () => unknown, message?: RegExp ): BakedVolumeError {

	let caught: unknown = null;
	try {

		run();

	} catch ( error ) {

		caught = error;

	}

	expect( caught, `expected a BakedVolumeError '${code}'` ).toBeInstanceOf( BakedVolumeError );
	const error = caught as BakedVolumeError;
	expect( error.code, error.message ).toBe( code );
	if ( message ) expect( error.message ).toMatch( message );
	return error;

}

/** Edits a valid file: `edit` gets a DataView over a copy; the checksum is then made valid again. */
export function edited( buffer: ArrayBuffer, edit: ( view: DataView, bytes: Uint8Array ) => void ): ArrayBuffer {

	const copy = buffer.slice( 0 );
	edit( new DataView( copy ), new Uint8Array( copy ) );
	fixChecksum( new Uint8Array( copy ) );
	return copy;

}

/** Byte offset of a section's data in a valid file. */
export function sectionOffset( buffer: ArrayBuffer, id: string ): number {

	const view = new DataView( buffer );
	for ( let s = 0; s < view.getUint32( 40, true ); s ++ ) if ( view.getUint32( 64 + 16 * s, true ) === fourCC( id ) ) return view.getUint32( 64 + 16 * s + 8, true );
	throw new Error( `no section ${id}` );

}
