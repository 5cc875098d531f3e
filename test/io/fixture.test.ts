import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { decodeBakedVolume, encodeBakedVolume, type BakedVolumeInput } from '../../src/io/index.js';

/*
 * A stored version-1.0 file, so that a change made symmetrically to the writer and the reader (which
 * round-trip tests cannot see) still fails here. fixtures/v1.0-tiny.lpv was generated once, at
 * commit 45d482b (before src/io/BakedVolume.ts was split), by
 *   encodeBakedVolume( INPUT, { precision: 'float16' } )
 * with INPUT as below (its tetrahedra and neighbours are what tetrahedralize( positions ) returned
 * then). Never regenerate it: a reader must keep reading the files already written. The expected
 * values are written out literally; the SH are float16 roundings of INPUT's.
 */

const FIXTURE = new URL( './fixtures/v1.0-tiny.lpv', import.meta.url );

/** SH input: 27 per probe, a fixed pattern in [−0.5, 0.5). */
const SH_INPUT = Array.from( { length: 5 * 27 }, ( _, i ) => ( ( i * 37 ) % 101 ) / 100 - 0.5 );

const INPUT: BakedVolumeInput = {
	positions: [ 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 1.5, 1.25, 1.75 ],
	sh: SH_INPUT,
	tetrahedra: [ 0, 2, 4, 1, 2, 0, 4, 3, 0, 3, 1, 4 ],
	neighbors: [ - 1, 2, - 1, 1, 2, - 1, - 1, 0, - 1, 0, 1, - 1 ],
	names: [ 'door', '', 'café', 'stair', 'roof' ],
	roles: [ 'fill', 'bounce', 'bleed', 'fill', 'sky' ],
	zones: [ { name: 'hall', probes: [ 0, 1, 4 ], bounds: [ - 1, - 1, - 1, 3, 3, 3 ] } ],
	capture: { resolution: 16, near: 0.05, far: 50, roles: { sky: { far: 500 } } },
	metadata: 'v1.0-tiny fixture',
};

function fixture(): Uint8Array {

	const file = readFileSync( FIXTURE );
	return new Uint8Array( file.buffer, file.byteOffset, file.byteLength );

}

describe( 'stored version-1.0 file (test/io/fixtures/v1.0-tiny.lpv)', () => {

	it( 'has the header and section table the format specifies', () => {

		const bytes = fixture();
		const view = new DataView( bytes.buffer, bytes.byteOffset, bytes.byteLength );
		expect( bytes.length ).toBe( 992 );
		expect( Array.from( bytes.subarray( 0, 8 ) ) ).toEqual( [ 0xAB, 0x4C, 0x50, 0x56, 0x0D, 0x0A, 0x1A, 0x0A ] );
		const header = [ 8, 10 ].map( ( at ) => view.getUint16( at, true ) )
			.concat( [ 12, 16, 20, 24, 28, 32, 36, 40, 44 ].map( ( at ) => view.getUint32( at, true ) ) );
		// major, minor, CRC-32, file length, header size, flags (SH float16), probes, tetrahedra, zones, sections, name bytes
		expect( header ).toEqual( [ 1, 0, 0x1C91D532, 992, 64, 1, 5, 3, 1, 10, 18 ] );
		const table: [ string, number, number, number ][] = [];
		for ( let s = 0; s < 10; s ++ ) {

			const at = 64 + 16 * s;
			const id = String.fromCharCode( ...bytes.subarray( at, at + 4 ) );
			table.push( [ id, view.getUint32( at + 4, true ), view.getUint32( at + 8, true ), view.getUint32( at + 12, true ) ] );

		}

		// id, flags (1 = required), offset, length
		expect( table ).toEqual( [
			[ 'POS ', 1, 224, 120 ], [ 'SH  ', 1, 344, 270 ], [ 'TETS', 1, 616, 48 ], [ 'NBRS', 1, 664, 48 ], [ 'ROLE', 1, 712, 5 ],
			[ 'NAME', 1, 720, 38 ], [ 'ZONE', 1, 760, 88 ], [ 'BNDS', 1, 848, 48 ], [ 'CAPT', 0, 896, 66 ], [ 'META', 0, 968, 17 ],
		] );

	} );

	it( 'decodes to the literal values it was written from', () => {

		const data = decodeBakedVolume( fixture() );
		expect( Array.from( data.positions ) ).toEqual( [ 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 1.5, 1.25, 1.75 ] );
		expect( Array.from( data.tetrahedra ) ).toEqual( [ 0, 2, 4, 1, 2, 0, 4, 3, 0, 3, 1, 4 ] );
		expect( Array.from( data.neighbors ) ).toEqual( [ - 1, 2, - 1, 1, 2, - 1, - 1, 0, - 1, 0, 1, - 1 ] );
		expect( data.names ).toEqual( [ 'door', '', 'café', 'stair', 'roof' ] );
		expect( data.roles ).toEqual( [ 'fill', 'bounce', 'bleed', 'fill', 'sky' ] );
		expect( data.zones.map( ( z ) => ( { name: z.name, probes: Array.from( z.probes ), bounds: Array.from( z.bounds ) } ) ) )
			.toEqual( [ { name: 'hall', probes: [ 0, 1, 4 ], bounds: [ - 1, - 1, - 1, 3, 3, 3 ] } ] );
		expect( Array.from( data.bounds ) ).toEqual( [ 0, 0, 0, 2, 2, 2 ] );
		expect( data.capture ).toEqual( { resolution: 16, near: 0.05, far: 50, roles: { sky: { far: 500 } } } );
		expect( data.metadata ).toBe( 'v1.0-tiny fixture' );
		// Version 1.0 has no GRAD or FITS: plain probes, SH as captured.
		expect( [ data.gradients, data.fit ] ).toEqual( [ null, null ] );

		expect( data.sh.length ).toBe( 135 );
		expect( Array.from( data.sh.subarray( 0, 9 ) ) ).toEqual( [
			- 0.5, - 0.1300048828125, 0.239990234375, - 0.39990234375, - 0.029998779296875, 0.340087890625,
			- 0.300048828125, 0.07000732421875, 0.43994140625,
		] );
		expect( Array.from( data.sh.subarray( 100, 105 ) ) )
			.toEqual( [ 0.1400146484375, - 0.5, - 0.1300048828125, 0.239990234375, - 0.39990234375 ] );
		expect( data.sh[ 15 ] ).toBe( 0 );
		expect( data.sh[ 134 ] ).toBe( - 0.409912109375 );
		// Every value is its input rounded to float16: 11 significant bits (|x| ≥ 2^−14 here, or 0).
		for ( let i = 0; i < 135; i ++ ) {

			const error = Math.abs( data.sh[ i ] - SH_INPUT[ i ] );
			expect( error, `sh[${i}]` ).toBeLessThanOrEqual( Math.abs( SH_INPUT[ i ] ) * 2 ** - 11 );

		}


	} );

	it( 'encoding the literal input gives the stored bytes exactly', () => {

		const encoded = new Uint8Array( encodeBakedVolume( INPUT, { precision: 'float16' } ) );
		const stored = fixture();
		expect( encoded.length ).toBe( stored.length );
		const first = encoded.findIndex( ( b, i ) => b !== stored[ i ] );
		expect( first, 'first differing byte' ).toBe( - 1 );

	} );

} );

/*
 * A stored version-1.1 file with gradient probes and a fit record. fixtures/v1.1-gradients-tiny.lpv
 * was generated once (issue 14) by encodeBakedVolume( INPUT_1_1, { precision: 'float16' } ) with
 * INPUT_1_1 as below; the gradients are multiples of 1/64 in [−0.75, 0.75], exact in float16, so the
 * decoded values are the input itself. Never regenerate it. The reader of version 1.0 (commit
 * 83c1299) loads it, skipping GRAD and FITS, with the same positions and SH.
 */

const FIXTURE_1_1 = new URL( './fixtures/v1.1-gradients-tiny.lpv', import.meta.url );

const GRADIENTS_INPUT = Array.from( { length: 5 * 81 }, ( _, i ) => ( ( i * 53 ) % 97 ) / 64 - 0.75 );

const FIT_INPUT = {
	samples: 64, gradients: true, lambda: 0.25, gradientLambda: 0.0625, crossValidationError: 0.0712, source: 'dense captures at spacing 0.5',
};

const INPUT_1_1: BakedVolumeInput = {
	positions: INPUT.positions, sh: SH_INPUT, tetrahedra: INPUT.tetrahedra, neighbors: INPUT.neighbors, roles: INPUT.roles,
	capture: { resolution: 16 }, metadata: 'v1.1-gradients-tiny fixture', gradients: GRADIENTS_INPUT, fit: FIT_INPUT,
};

describe( 'stored version-1.1 file with gradients and a fit record (test/io/fixtures/v1.1-gradients-tiny.lpv)', () => {

	const bytes = (): Uint8Array => {

		const file = readFileSync( FIXTURE_1_1 );
		return new Uint8Array( file.buffer, file.byteOffset, file.byteLength );

	};

	it( 'has version 1.1, the SH-float16 flag and GRAD (162 bytes per probe) and FITS as optional sections', () => {

		const b = bytes();
		const view = new DataView( b.buffer, b.byteOffset, b.byteLength );
		const header = [ 8, 10 ].map( ( at ) => view.getUint16( at, true ) )
			.concat( [ 12, 16, 20, 24, 28, 32, 36, 40, 44 ].map( ( at ) => view.getUint32( at, true ) ) );
		// major, minor, CRC-32, file length, header size, flags (SH and gradients float16), probes, tetrahedra, zones, sections, name bytes
		expect( header ).toEqual( [ 1, 1, 0xE59B0038, 1784, 64, 1, 5, 3, 0, 10, 0 ] );
		const table: [ string, number, number, number ][] = [];
		for ( let s = 0; s < 10; s ++ ) {

			const at = 64 + 16 * s;
			const id = String.fromCharCode( ...b.subarray( at, at + 4 ) );
			table.push( [ id, view.getUint32( at + 4, true ), view.getUint32( at + 8, true ), view.getUint32( at + 12, true ) ] );

		}

		expect( table ).toEqual( [
			[ 'POS ', 1, 224, 120 ], [ 'SH  ', 1, 344, 270 ], [ 'TETS', 1, 616, 48 ], [ 'NBRS', 1, 664, 48 ], [ 'ROLE', 1, 712, 5 ],
			[ 'BNDS', 1, 720, 48 ], [ 'CAPT', 0, 768, 17 ], [ 'META', 0, 792, 27 ], [ 'GRAD', 0, 824, 810 ], [ 'FITS', 0, 1640, 140 ],
		] );
		// Gradient 81·4 + 27·2 + 5 (probe 4, ∂/∂z of SH float 5) as float16 bits: (383·53) % 97 = 26 → 26/64 − 0.75 = −0.34375 = 0xB580.
		expect( view.getUint16( 824 + 2 * 383, true ) ).toBe( 0xB580 );
		expect( JSON.parse( new TextDecoder().decode( b.subarray( 1640, 1780 ) ) ) ).toEqual( FIT_INPUT );

	} );

	it( 'decodes to the literal gradients and fit record, with the SH of the 1.0 fixture', () => {

		const data = decodeBakedVolume( bytes() );
		expect( Array.from( data.gradients! ) ).toEqual( GRADIENTS_INPUT );
		expect( data.fit ).toEqual( FIT_INPUT );
		expect( Array.from( data.sh ) ).toEqual( Array.from( decodeBakedVolume( fixture() ).sh ) );
		expect( data.metadata ).toBe( 'v1.1-gradients-tiny fixture' );

	} );

	it( 'encoding the literal input gives the stored bytes exactly', () => {

		const encoded = new Uint8Array( encodeBakedVolume( INPUT_1_1, { precision: 'float16' } ) );
		const stored = bytes();
		expect( encoded.length ).toBe( stored.length );
		expect( encoded.findIndex( ( b, i ) => b !== stored[ i ] ), 'first differing byte' ).toBe( - 1 );

	} );

} );
