import { describe, expect, it } from 'vitest';
import { BakedVolumeError, encodeBakedVolume, decodeBakedVolume, type BakedVolumeData } from '../../src/io/index.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { makeVolume, independentCheck, fixChecksum, fourCC } from './helpers.js';

/*
 * Random mutations of valid files. Every decode must either throw a BakedVolumeError or return
 * data that passes the brute-force check of helpers.ts; no other error type (a RangeError from a
 * huge allocation, a TypeError from a bad index) and no hang. With the checksum left as it is,
 * almost every mutation is caught by it, and whatever still decodes must equal the original (the
 * only unchecked bytes are the magic, the version and the checksum field); so the same mutations
 * run again with the checksum recomputed, which sends them through the structural checks.
 */

// BAKED_FUZZ_CASES=100000 BAKED_FUZZ_SEED=7 npx vitest run test/io/fuzz.test.ts for a longer search.
const CASES = Number( process.env.BAKED_FUZZ_CASES ?? 6000 );
const SEED = Number( process.env.BAKED_FUZZ_SEED ?? 0 );

const sources = [
	{ data: makeVolume( 12, 2 ), precision: 'float32' as const },
	{ data: makeVolume( 85, 3 ), precision: 'float16' as const },
	{ data: makeVolume( 200, 4, false ), precision: 'float32' as const },
	{ data: makeVolume( 30, 5 ), precision: 'float16' as const },
];
const files = sources.map( ( { data, precision } ) => new Uint8Array( encodeBakedVolume( data, { precision } ) ) );
const originals = files.map( ( bytes ) => decodeBakedVolume( bytes.slice().buffer ) );

/** Section data ranges of a valid file, for mutations aimed at structure (indices, links, counts). */
function sectionsOf( bytes: Uint8Array ): Map<number, [ number, number ]> {

	const view = new DataView( bytes.buffer );
	const map = new Map<number, [ number, number ]>();
	for ( let s = 0; s < view.getUint32( 40, true ); s ++ ) map.set( view.getUint32( 64 + 16 * s, true ), [ view.getUint32( 72 + 16 * s, true ), view.getUint32( 76 + 16 * s, true ) ] );
	return map;

}

const layouts = files.map( sectionsOf );
const EXTREME_U32 = [ 0xFFFFFFFF, 0x80000000, 0x7FFFFFFF, 0, 1, 0xFFFFFFF8, 0x10000, 0x0FFFFFFF ];
const EXTREME_F64 = [ NaN, Infinity, - Infinity, - 0, 1e308, - 1e308, 5e-324 ];

const OPS = [ 'bit flips', 'extreme u32', 'extreme f64', 'truncation', 'section table edit', 'header count edit', 'splice', 'byte run', 'index nudge' ] as const;

function mutate( random: () => number, source: number ): { bytes: Uint8Array; op: string } {

	const original = files[ source ];
	let bytes = original.slice();
	const view = new DataView( bytes.buffer );
	const int = ( n: number ): number => Math.floor( random() * n );
	const op = OPS[ int( OPS.length ) ];
	switch ( op ) {

		case 'bit flips': {

			for ( let k = 1 + int( 4 ); k > 0; k -- ) bytes[ int( bytes.length ) ] ^= 1 << int( 8 );
			break;

		}

		case 'extreme u32': {

			view.setUint32( 4 * int( bytes.length / 4 ), EXTREME_U32[ int( EXTREME_U32.length ) ], true );
			break;

		}

		case 'extreme f64': {

			view.setFloat64( 8 * int( bytes.length / 8 ), EXTREME_F64[ int( EXTREME_F64.length ) ], true );
			break;

		}

		case 'truncation': {

			bytes = bytes.slice( 0, int( bytes.length ) );
			break;

		}

		case 'section table edit': {

			const entry = 64 + 16 * int( view.getUint32( 40, true ) ) + 4 * int( 4 );
			const old = view.getUint32( entry, true );
			const choice = int( 3 );
			const value = choice === 0 ? EXTREME_U32[ int( EXTREME_U32.length ) ] : choice === 1 ? old + [ - 8, - 4, - 1, 1, 4, 8, 16 ][ int( 7 ) ] : view.getUint32( 64 + 16 * int( view.getUint32( 40, true ) ) + 4 * int( 4 ), true );
			view.setUint32( entry, value >>> 0, true );
			break;

		}

		case 'header count edit': {

			const field = 16 + 4 * int( 8 );
			const old = view.getUint32( field, true );
			view.setUint32( field, ( random() < 0.5 ? EXTREME_U32[ int( EXTREME_U32.length ) ] : old + [ - 2, - 1, 1, 2 ][ int( 4 ) ] ) >>> 0, true );
			break;

		}

		case 'splice': {

			const from = files[ int( files.length ) ];
			const length = 1 + int( 64 );
			const at = int( Math.max( 1, from.length - length ) );
			const to = int( Math.max( 1, bytes.length - length ) );
			bytes.set( from.subarray( at, Math.min( from.length, at + length ) ).subarray( 0, bytes.length - to ), to );
			break;

		}

		case 'byte run': {

			const fill = [ 0x00, 0xFF, 0x80, int( 256 ) ][ int( 4 ) ];
			const at = int( bytes.length );
			bytes.fill( fill, at, Math.min( bytes.length, at + 1 + int( 16 ) ) );
			break;

		}

		case 'index nudge': {

			const ids = [ 'TETS', 'NBRS', 'ZONE', 'NAME', 'ROLE', 'POS ' ].map( fourCC ).filter( ( id ) => layouts[ source ].has( id ) );
			const [ offset, length ] = layouts[ source ].get( ids[ int( ids.length ) ] )!;
			if ( length < 4 ) break;
			const at = offset + 4 * int( length / 4 );
			view.setInt32( at, view.getInt32( at, true ) + [ - 3, - 2, - 1, 1, 2, 3 ][ int( 6 ) ], true );
			break;

		}

	}

	return { bytes, op };

}

function sameData( a: BakedVolumeData, b: BakedVolumeData ): boolean {

	const arrays = ( d: BakedVolumeData ) => [ d.positions, d.sh, d.tetrahedra, d.neighbors, d.bounds ];
	const x = arrays( a ), y = arrays( b );
	for ( let k = 0; k < x.length; k ++ ) {

		if ( x[ k ].length !== y[ k ].length ) return false;
		for ( let i = 0; i < x[ k ].length; i ++ ) if ( ! Object.is( x[ k ][ i ], y[ k ][ i ] ) ) return false;

	}

	const rest = ( d: BakedVolumeData ) => JSON.stringify( [ d.names, d.roles, d.capture, d.metadata, d.zones.map( ( z ) => [ z.name, Array.from( z.probes ), Array.from( z.bounds ) ] ) ] );
	return rest( a ) === rest( b );

}

interface Tally { cases: number; decoded: number; codes: Record<string, number>; failures: string[]; slowest: number }

function run( cases: number, seed: number, recomputeChecksum: boolean ): Tally {

	const random = mulberry32( seed );
	const tally: Tally = { cases: 0, decoded: 0, codes: {}, failures: [], slowest: 0 };
	for ( let c = 0; c < cases; c ++ ) {

		const source = Math.floor( random() * files.length );
		const { bytes, op } = mutate( random, source );
		if ( recomputeChecksum ) fixChecksum( bytes );
		tally.cases ++;
		const start = performance.now();
		let data: BakedVolumeData | null = null;
		try {

			data = decodeBakedVolume( bytes );

		} catch ( error ) {

			if ( error instanceof BakedVolumeError ) tally.codes[ error.code ] = ( tally.codes[ error.code ] ?? 0 ) + 1;
			else tally.failures.push( `case ${c} (${op}): ${String( error )}` );

		}

		tally.slowest = Math.max( tally.slowest, performance.now() - start );
		if ( data === null ) continue;
		tally.decoded ++;
		const problem = independentCheck( data );
		if ( problem ) tally.failures.push( `case ${c} (${op}): decoded but invalid: ${problem}` );
		for ( const array of [ data.positions, data.sh, data.tetrahedra, data.neighbors ] ) {

			// No decoded array larger than a small multiple of the file (float16 SH doubles in size).
			if ( array.byteLength > 2 * bytes.length ) tally.failures.push( `case ${c} (${op}): ${array.byteLength}-byte array from a ${bytes.length}-byte file` );

		}

		if ( ! recomputeChecksum && ! sameData( data, originals[ source ] ) ) tally.failures.push( `case ${c} (${op}): the checksum passed but the data changed` );

	}

	return tally;

}

describe( 'baked volume loader fuzz', () => {

	it( '6,000 mutations with the stored checksum: each is rejected with a BakedVolumeError or decodes to exactly the original', () => {

		const tally = run( CASES, 101 + SEED, false );
		expect( tally.failures.slice( 0, 10 ) ).toEqual( [] );
		expect( tally.cases ).toBe( CASES );
		expect( tally.codes.checksum ).toBeGreaterThan( CASES / 2 );
		console.log( 'fuzz, checksum kept:', JSON.stringify( tally.codes ), `decoded ${tally.decoded}, slowest decode ${tally.slowest.toFixed( 1 )} ms` );

	} );

	it( '6,000 mutations with the checksum recomputed: each is rejected with a BakedVolumeError or decodes to data that passes the brute-force check; the structural checks all fire', () => {

		const tally = run( CASES, 202 + SEED, true );
		expect( tally.failures.slice( 0, 10 ) ).toEqual( [] );
		expect( tally.codes.checksum ?? 0 ).toBe( 0 );
		// The structural rules are what rejects these files: every class below must have fired.
		for ( const code of [ 'truncated', 'bad-magic', 'header', 'section', 'count', 'range', 'nan', 'orientation', 'neighbors' ] ) {

			expect( tally.codes[ code ] ?? 0, code ).toBeGreaterThan( 0 );

		}

		expect( tally.decoded ).toBeGreaterThan( 100 ); // harmless edits (SH values, names) still load
		console.log( 'fuzz, checksum recomputed:', JSON.stringify( tally.codes ), `decoded ${tally.decoded}, slowest decode ${tally.slowest.toFixed( 1 )} ms` );

	} );

} );
