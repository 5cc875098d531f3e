import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import {
	bakedVolumeFromJSON, bakedVolumeToJSON, decodeBakedVolume, encodeBakedVolume, validateBakedVolume, type BakedFit, type BakedVolumeInput,
} from '../../src/io/index.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { edited, expectError, fourCC, makeVolume, readSections, referenceCRC32, sectionOffset, writeSections } from './helpers.js';

/*
 * Gradient probes and the fit record in the baked format (docs/format.md, "GRAD" and "FITS", version
 * 1.1): the round trips, what a reader that does not know the sections sees, and each malformed
 * case by its error code. Expected layouts are read with the test helpers, written from the document.
 */

const PROBES = 30;

/** 81 seeded values per probe in [−2, 2): the gradient layout is opaque to the codec, any finite values do. */
function randomGradients( probes: number, seed: number ): Float32Array {

	const random = mulberry32( seed );
	return Float32Array.from( { length: 81 * probes }, () => 4 * random() - 2 );

}

const FIT: BakedFit = { samples: 1596, gradients: true, lambda: 0.03125, gradientLambda: 0.5, crossValidationError: 0.109, source: 'dense captures at spacing 0.5 — hall ✓' };
const plain = makeVolume( PROBES, 21 );
const GRADIENTS = randomGradients( PROBES, 22 );
const volume: BakedVolumeInput = { ...plain, gradients: GRADIENTS, fit: FIT };
const file = encodeBakedVolume( volume );

/** The section ids of a file in table order, as their four characters. */
function sectionIds( buffer: ArrayBuffer ): string[] {

	return readSections( buffer ).sections.map( ( s ) => String.fromCharCode( ...new Uint8Array( new Uint32Array( [ s.id ] ).buffer ) ) );

}

describe( 'baked format 1.1: gradients and the fit record round-trip', () => {

	it( 'float32: version 1.1, GRAD (324 bytes per probe, optional) and FITS (UTF-8 JSON, optional) after the 1.0 sections; bitwise', () => {

		const view = new DataView( file );
		expect( [ view.getUint16( 8, true ), view.getUint16( 10, true ) ] ).toEqual( [ 1, 1 ] );
		expect( view.getUint32( 12, true ) ).toBe( referenceCRC32( new Uint8Array( file ), 16, file.byteLength ) );
		expect( sectionIds( file ) ).toEqual( [ 'POS ', 'SH  ', 'TETS', 'NBRS', 'ROLE', 'NAME', 'ZONE', 'BNDS', 'CAPT', 'META', 'GRAD', 'FITS' ] );
		const { sections } = readSections( file );
		const grad = sections.find( ( s ) => s.id === fourCC( 'GRAD' ) )!, fits = sections.find( ( s ) => s.id === fourCC( 'FITS' ) )!;
		expect( [ grad.flags, grad.bytes.length ] ).toEqual( [ 0, 324 * PROBES ] );
		expect( fits.flags ).toBe( 0 );
		// gradients[ 81 i + 27 a + k ] little-endian float32 at 4 × that index.
		const stored = new DataView( grad.bytes.buffer );
		for ( const index of [ 0, 80, 81 * 7 + 27 * 2 + 26, 81 * PROBES - 1 ] ) {

			expect( stored.getFloat32( 4 * index, true ) ).toBe( GRADIENTS[ index ] );

		}

		expect( JSON.parse( new TextDecoder().decode( fits.bytes ) ) ).toEqual( FIT );

		const d = decodeBakedVolume( file );
		expect( d.gradients ).toBeInstanceOf( Float32Array );
		expect( Array.from( d.gradients! ) ).toEqual( Array.from( GRADIENTS ) );
		expect( d.fit ).toEqual( FIT );
		expect( Array.from( d.sh ) ).toEqual( Array.from( plain.sh ) );

	} );

	it( 'float32 gradients are a view of an aligned buffer (no copy), like the SH', () => {

		const d = decodeBakedVolume( file );
		expect( d.gradients!.buffer ).toBe( file );
		expect( d.gradients!.byteOffset ).toBe( sectionOffset( file, 'GRAD' ) );
		expect( d.sh.buffer ).toBe( file );

	} );

	it( 'float16: header flag bit 0 covers the gradients too (162 bytes per probe), each within half precision', () => {

		const gradients = Float32Array.from( GRADIENTS );
		gradients.set( [ 1e-7, - 3e-6, 6.1e-5, 65504, - 65504, 0 ], 0 ); // subnormals, the largest half, zero
		const half = encodeBakedVolume( { ...volume, gradients }, { precision: 'float16' } );
		expect( new DataView( half ).getUint32( 24, true ) ).toBe( 1 );
		expect( readSections( half ).sections.find( ( s ) => s.id === fourCC( 'GRAD' ) )!.bytes.length ).toBe( 162 * PROBES );
		const d = decodeBakedVolume( half );
		for ( let i = 0; i < gradients.length; i ++ ) {

			const v = gradients[ i ], error = Math.abs( d.gradients![ i ] - v );
			expect( error, `gradients[${i}]` ).toBeLessThanOrEqual( Math.abs( v ) >= 2 ** - 14 ? Math.abs( v ) * 2 ** - 11 : 2 ** - 25 );

		}

		expect( d.gradients![ 3 ] ).toBe( 65504 );
		expect( d.fit ).toEqual( FIT );

	} );

	it( 'float16 overflow of a gradient is an error naming it (float16-overflow), not a clamp', () => {

		const gradients = Float32Array.from( GRADIENTS );
		gradients[ 500 ] = - 70000;
		expectError( 'float16-overflow', () => encodeBakedVolume( { ...volume, gradients }, { precision: 'float16' } ), /gradients\[500\] = -70000.*float32/ );

	} );

	it( 'without gradients and fit: version 1.0, no GRAD or FITS, decoded as null; a fit of plain probes alone is 1.1 with FITS only', () => {

		const bare = encodeBakedVolume( plain );
		expect( new DataView( bare ).getUint16( 10, true ) ).toBe( 0 );
		expect( sectionIds( bare ) ).not.toContain( 'GRAD' );
		const d = decodeBakedVolume( bare );
		expect( [ d.gradients, d.fit ] ).toEqual( [ null, null ] );
		expect( new Uint8Array( encodeBakedVolume( { ...plain, gradients: null, fit: null } ) ) ).toEqual( new Uint8Array( bare ) );

		const plainFit: BakedFit = { samples: 748, gradients: false, lambda: 2, gradientLambda: 0, crossValidationError: null };
		const fitted = encodeBakedVolume( { ...plain, fit: plainFit } );
		expect( new DataView( fitted ).getUint16( 10, true ) ).toBe( 1 );
		expect( sectionIds( fitted ).slice( - 2 ) ).toEqual( [ 'META', 'FITS' ] );
		const f = decodeBakedVolume( fitted );
		expect( f.gradients ).toBeNull();
		expect( f.fit ).toEqual( plainFit );

	} );

	it( 'a reader that does not know GRAD and FITS (a 1.0 reader) skips them: the same ids renamed load as the plain volume', () => {

		// docs/format.md: a reader skips unknown sections not marked required; the ids are renamed
		// to ones this reader does not know either, with their flags kept.
		const { header, sections } = readSections( file );
		const renamed = sections.map( ( s ) => s.id === fourCC( 'GRAD' ) ? { ...s, id: fourCC( 'GRA?' ) } : s.id === fourCC( 'FITS' ) ? { ...s, id: fourCC( 'FIT?' ) } : s );
		const d = decodeBakedVolume( writeSections( header, renamed ) );
		expect( [ d.gradients, d.fit ] ).toEqual( [ null, null ] );
		expect( Array.from( d.sh ) ).toEqual( Array.from( plain.sh ) );
		expect( Array.from( d.tetrahedra ) ).toEqual( Array.from( plain.tetrahedra ) );

	} );

	it( 'JSON: gradients and fit exactly through JSON.stringify, version [ 1, 1 ]; without them neither member and [ 1, 0 ]', () => {

		const json = bakedVolumeToJSON( volume );
		expect( json.version ).toEqual( [ 1, 1 ] );
		expect( json.gradients ).toHaveLength( 81 * PROBES );
		const d = bakedVolumeFromJSON( JSON.stringify( json ) );
		expect( Array.from( d.gradients! ) ).toEqual( Array.from( GRADIENTS ) );
		expect( d.fit ).toEqual( FIT );
		// The JSON form and the binary form carry the same data.
		expect( bakedVolumeToJSON( decodeBakedVolume( file ) ) ).toEqual( json );

		const bare = bakedVolumeToJSON( plain );
		expect( bare.version ).toEqual( [ 1, 0 ] );
		expect( 'gradients' in bare || 'fit' in bare ).toBe( false );
		const b = bakedVolumeFromJSON( bare );
		expect( [ b.gradients, b.fit ] ).toEqual( [ null, null ] );

	} );

	it( 'fit record members other than the six are dropped; source is optional', () => {

		const { source: _source, ...noSource } = FIT;
		const d = decodeBakedVolume( encodeBakedVolume( { ...volume, fit: { ...noSource, future: 1 } as BakedFit } ) );
		expect( d.fit ).toEqual( noSource );

	} );

} );

describe( 'baked format 1.1: malformed gradients and fit records, by name', () => {

	it( 'GRAD of the wrong length (for the probe count or for float16) → count', () => {

		const { header, sections } = readSections( file );
		const short = sections.map( ( s ) => s.id === fourCC( 'GRAD' ) ? { ...s, bytes: s.bytes.subarray( 0, 324 * ( PROBES - 1 ) ) } : s );
		expectError( 'count', () => decodeBakedVolume( writeSections( header, short ) ), /section 'GRAD' is 9396 bytes but the header's counts need 9720/ );
		// The same bytes under the float16 flag: 162 per probe were expected.
		expectError( 'count', () => decodeBakedVolume( edited( encodeBakedVolume( volume, { precision: 'float16' } ), ( v ) => v.setUint32( 24, 0, true ) ) ), /'SH  '/ );
		const halfHeader = header.slice();
		new DataView( halfHeader.buffer ).setUint32( 24, 1, true );
		const halfSH = sections.map( ( s ) => s.id === fourCC( 'SH  ' ) ? { ...s, bytes: s.bytes.subarray( 0, 54 * PROBES ) } : s );
		expectError( 'count', () => decodeBakedVolume( writeSections( halfHeader, halfSH ) ), /section 'GRAD' is 9720 bytes but the header's counts need 4860 \(30 probes × 81 float16\)/ );

	} );

	it( 'NaN or Infinity in float32 and float16 gradients → nan naming the index; beyond ±1e30 → range', () => {

		const grad = sectionOffset( file, 'GRAD' );
		expectError( 'nan', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat32( grad + 4 * 77, NaN, true ) ) ), /gradients\[77\] is NaN/ );
		expectError( 'nan', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat32( grad + 4 * 78, Infinity, true ) ) ), /gradients\[78\] is Infinity/ );
		expectError( 'range', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat32( grad + 4 * 79, - 3e38, true ) ) ), /gradients\[79\] is -3/ );
		const half = encodeBakedVolume( volume, { precision: 'float16' } ), halfGrad = sectionOffset( half, 'GRAD' );
		expectError( 'nan', () => decodeBakedVolume( edited( half, ( v ) => v.setUint16( halfGrad + 2 * 5, 0x7E00, true ) ) ), /gradients\[5\] is NaN/ );
		expectError( 'nan', () => decodeBakedVolume( edited( half, ( v ) => v.setUint16( halfGrad + 2 * 6, 0xFC00, true ) ) ), /gradients\[6\] is Infinity/ );

	} );

	it( 'the gradient bound is 1e30 over the probes\' bounding-box diagonal (the runtime\'s), checked on the float32 values; scale-free', () => {

		// Unit tetrahedron corners scaled by s: the box is s × s × s, its diagonal s·√3.
		const at = ( s: number ) => [ 0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s ];
		const sh = new Float32Array( 4 * 27 );
		const limit = ( s: number ) => Math.fround( 1e30 ) / ( s * Math.sqrt( 3 ) );
		const withGradient = ( s: number, v: number ) => ( { positions: at( s ), sh, gradients: new Float32Array( 4 * 81 ).fill( v ) } );
		for ( const s of [ 1e-6, 1, 1e6 ] ) {

			// float32 steps are 2^−23 relative: 1 − 1e−6 of the bound is inside it after rounding, 1 + 1e−6 outside.
			const inside = Math.fround( limit( s ) * ( 1 - 1e-6 ) ), outside = limit( s ) * ( 1 + 1e-6 );
			expect( decodeBakedVolume( encodeBakedVolume( withGradient( s, - inside ) ) ).gradients![ 0 ] ).toBe( - inside );
			expectError( 'range', () => encodeBakedVolume( withGradient( s, outside ) ), /gradients\[0\] is .*within ±.*bounding-box diagonal/ );

		}

		// A float64 gradient exactly at the bound whose float32 rounding is above it: refused (what is stored is checked).
		let scale = 1;
		while ( ! ( Math.fround( limit( scale ) ) > limit( scale ) ) ) scale ++;
		const atBound = { positions: at( scale ), sh, gradients: new Float64Array( 4 * 81 ).fill( limit( scale ) ) };
		expectError( 'range', () => encodeBakedVolume( atBound ), /gradients\[0\]/ );

		// A layout 1e6 times smaller takes gradients 1e6 times larger: 1e31 is valid at s = 1e-6 (bound 5.8e35).
		expect( decodeBakedVolume( encodeBakedVolume( withGradient( 1e-6, 1e31 ) ) ).gradients![ 5 ] ).toBe( Math.fround( 1e31 ) );

	} );

	it( 'a file cut inside GRAD → truncated; one flipped bit in GRAD or FITS → checksum (the CRC covers them)', () => {

		const grad = sectionOffset( file, 'GRAD' );
		expectError( 'truncated', () => decodeBakedVolume( file.slice( 0, grad + 100 ) ), /truncated/ );
		for ( const at of [ grad + 13, sectionOffset( file, 'FITS' ) + 3 ] ) {

			const copy = new Uint8Array( file.slice( 0 ) );
			copy[ at ] ^= 8;
			expectError( 'checksum', () => decodeBakedVolume( copy ), /corrupted/ );

		}

	} );

	it( 'FITS: not JSON → json; members of the wrong type, negative, non-integer samples → json / range; gradients: true without GRAD → count', () => {

		const { header, sections } = readSections( file );
		const withFit = ( text: string, keepGradients = true ): ArrayBuffer => writeSections( header, sections
			.filter( ( s ) => keepGradients || s.id !== fourCC( 'GRAD' ) )
			.map( ( s ) => s.id === fourCC( 'FITS' ) ? { ...s, bytes: new TextEncoder().encode( text ) } : s ) );
		const fit = ( change: Record<string, unknown> ) => JSON.stringify( { ...FIT, ...change } );
		expectError( 'json', () => decodeBakedVolume( withFit( '{ "samples": ' ) ), /fit record section \(FITS\) is not valid JSON/ );
		expectError( 'json', () => decodeBakedVolume( withFit( '[ 1 ]' ) ), /fit must be an object/ );
		expectError( 'json', () => decodeBakedVolume( withFit( fit( { lambda: '0.5' } ) ) ), /fit\.lambda is "0\.5"; expected a number ≥ 0/ );
		expectError( 'json', () => decodeBakedVolume( withFit( fit( { gradients: 1 } ) ) ), /fit\.gradients is 1; expected true or false/ );
		expectError( 'json', () => decodeBakedVolume( withFit( fit( { crossValidationError: undefined } ) ) ), /fit\.crossValidationError is undefined/ );
		expectError( 'json', () => decodeBakedVolume( withFit( fit( { source: 7 } ) ) ), /fit\.source/ );
		expectError( 'range', () => decodeBakedVolume( withFit( fit( { gradientLambda: - 1 } ) ) ), /fit\.gradientLambda is -1; expected ≥ 0/ );
		expectError( 'range', () => decodeBakedVolume( withFit( fit( { samples: 2.5 } ) ) ), /fit\.samples is 2\.5; expected an integer/ );
		expectError( 'count', () => decodeBakedVolume( withFit( fit( {} ), false ) ), /fit\.gradients is true but the volume holds no gradients/ );
		expectError( 'utf8', () => decodeBakedVolume( edited( file, ( _v, b ) => b[ sectionOffset( file, 'FITS' ) + 2 ] = 0xFF ) ), /fit record/ );
		// crossValidationError null (λ given) is valid.
		expect( decodeBakedVolume( withFit( fit( { crossValidationError: null } ) ) ).fit!.crossValidationError ).toBeNull();

	} );

	it( 'the encoder and the JSON reader check the same: gradients length, type, NaN (and JSON null), fit values', () => {

		expectError( 'count', () => encodeBakedVolume( { ...volume, gradients: GRADIENTS.subarray( 81 ) } ), /gradients has 2349 values; 30 probes need 81 each \(2430\)/ );
		expectError( 'count', () => encodeBakedVolume( { ...volume, gradients: new Float32Array( 80 ) } ), /gradients has length 80, not a multiple of 81/ );
		expectError( 'argument', () => encodeBakedVolume( { ...volume, gradients: 'none' as unknown as number[] } ), /gradients must be an array/ );
		const nan = Float64Array.from( GRADIENTS );
		nan[ 12 ] = NaN;
		expectError( 'nan', () => validateBakedVolume( { ...volume, gradients: nan } ), /gradients\[12\] is NaN/ );
		expectError( 'nan', () => encodeBakedVolume( { ...volume, fit: { ...FIT, lambda: NaN } } ), /fit\.lambda is NaN/ );
		expectError( 'utf8', () => encodeBakedVolume( { ...volume, fit: { ...FIT, source: 'a\uD800' } } ), /fit\.source/ );
		expectError( 'count', () => bakedVolumeToJSON( { ...plain, fit: FIT } ), /fit\.gradients is true/ );
		const json = bakedVolumeToJSON( volume );
		expectError( 'nan', () => bakedVolumeFromJSON( { ...json, gradients: json.gradients!.map( ( v, i ) => i === 9 ? null as unknown as number : v ) } ), /gradients\[9\] is null/ );
		expectError( 'count', () => bakedVolumeFromJSON( { ...json, gradients: json.gradients!.slice( 0, 81 ) } ), /gradients has 81 values/ );
		expectError( 'range', () => bakedVolumeFromJSON( { ...json, fit: { ...FIT, samples: - 1 } } ), /fit\.samples is -1/ );

	} );

} );

describe( 'baked format 1.1: docs/format.md', () => {

	it( 'the FITS example of docs/format.md is a valid fit record that round-trips', () => {

		const doc = readFileSync( new URL( '../../docs/format.md', import.meta.url ), 'utf8' );
		const example = JSON.parse( /\*\*FITS\*\* JSON[\s\S]*?```json\n([\s\S]*?)```/.exec( doc )![ 1 ] );
		expect( decodeBakedVolume( encodeBakedVolume( { ...volume, fit: example } ) ).fit ).toEqual( example );

	} );

} );
