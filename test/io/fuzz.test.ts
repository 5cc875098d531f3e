import { beforeAll, describe, expect, it, vi } from 'vitest';
import { Object3D, Scene } from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import {
	BakedVolumeError, bakedVolumeFromJSON, bakedVolumeToJSON, encodeBakedVolume, decodeBakedVolume, type BakedVolumeData,
} from '../../src/io/index.js';
import { GLTFLightProbeVolumeExporterPlugin } from '../../src/gltf/GLTFLightProbeVolumeExporterPlugin.js';
import { GLTFLightProbeVolumeLoaderPlugin } from '../../src/gltf/GLTFLightProbeVolumeLoaderPlugin.js';
import { GLTF_LIGHT_PROBE_VOLUME_EXTENSION, type GLTFLightProbeVolumeEntry } from '../../src/gltf/GLTFLightProbeVolumeExtension.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { makeVolume, independentCheck, fixChecksum, fourCC, withGradients } from './helpers.js';
import { installGLTFNodeStubs } from './gltfNodeStubs.js';

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
	{ data: withGradients( makeVolume( 8, 6 ), 7 ), precision: 'float16' as const },
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

/*
 * The JSON form, mutated as text: every outcome of bakedVolumeFromJSON (on the text, and on
 * JSON.parse of it when that parses) is a BakedVolumeError or data that passes the brute-force
 * check, and LightProbeVolumeLoader.parse agrees — it loads every volume the codec accepts (finite
 * samples) and refuses the others with the codec's BakedVolumeError. (The loader also skips a
 * leading BOM, which JSON.parse refuses: for such a text the codec's verdict is that of the rest.)
 */

const JSON_CASES = Number( process.env.BAKED_FUZZ_JSON_CASES ?? 2500 );
const loader = new LightProbeVolumeLoader();
const jsonTexts = [ makeVolume( 12, 2 ), makeVolume( 20, 4, false ), makeVolume( 30, 5 ), withGradients( makeVolume( 6, 8 ), 9 ) ]
	.map( ( volume ) => JSON.stringify( bakedVolumeToJSON( volume ) ) );
const NUMBER = /-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?/g;
const STRING = /"(?:[^"\\]|\\.)*"/g;
const NUMBER_SWAPS = [ '1e400', '-1e400', '1e39', '3.4e38', '-3.4e38', '1e31', '1e155', '1e19', '-0', '0.5', '1.5', '-1', '4294967296', '2', '99999', 'null', '"7"', 'true', '[]', '{}' ];
const STRING_SWAPS = [ '""', '"sun"', '"\\ud800"', '"fill"', '"hall"', '1', 'null', '"half"', '"paper-unnormalized"', '"three-capture-lighting/baked-volume"', '[]' ];
const JUNK = [ ',', ']', '[', '{', '}', ':', '"', 'null', 'true', '-', '1e400', 'NaN', '0', '"x"', '\\u', '\uD800', '\uFEFF' ];
const JSON_OPS = [ 'delete span', 'insert junk', 'replace number', 'replace string', 'truncate', 'swap numbers' ] as const;

function tokens( text: string, pattern: RegExp ): [ number, number ][] {

	return Array.from( text.matchAll( pattern ), ( m ) => [ m.index!, m.index! + m[ 0 ].length ] );

}

const jsonTokens = jsonTexts.map( ( text ) => ( { numbers: tokens( text, NUMBER ), strings: tokens( text, STRING ) } ) );

function mutateText( random: () => number, source: number ): { text: string; op: string } {

	const text = jsonTexts[ source ], { numbers, strings } = jsonTokens[ source ];
	const int = ( n: number ): number => Math.floor( random() * n );
	const pick = <T>( list: readonly T[] ): T => list[ int( list.length ) ];
	const op = pick( JSON_OPS );
	const splice = ( [ from, to ]: [ number, number ], by: string ) => text.slice( 0, from ) + by + text.slice( to );
	switch ( op ) {

		case 'delete span': { const at = int( text.length ); return { text: splice( [ at, at + 1 + int( 20 ) ], '' ), op }; }
		case 'insert junk': { const at = int( text.length ); return { text: splice( [ at, at ], pick( JUNK ) ), op }; }
		case 'replace number': return { text: splice( pick( numbers ), pick( NUMBER_SWAPS ) ), op };
		case 'replace string': return { text: splice( pick( strings ), pick( STRING_SWAPS ) ), op };
		case 'truncate': return { text: text.slice( 0, int( text.length ) ), op };
		case 'swap numbers': {

			const a = int( numbers.length ), b = Math.min( numbers.length - 1, a + 1 + int( 8 ) );
			const [ x, y ] = [ numbers[ a ], numbers[ b ] ];
			const swapped = text.slice( 0, x[ 0 ] ) + text.slice( y[ 0 ], y[ 1 ] ) + text.slice( x[ 1 ], y[ 0 ] );
			return { text: swapped + text.slice( x[ 0 ], x[ 1 ] ) + text.slice( y[ 1 ] ), op };

		}

	}

}

/** 'ok' with the data, or the BakedVolumeError's code; anything else is a failure message. */
function readJSON( read: () => BakedVolumeData ): { data: BakedVolumeData | null; code: string | null; other: string | null } {

	try {

		return { data: read(), code: null, other: null };

	} catch ( error ) {

		if ( error instanceof BakedVolumeError ) return { data: null, code: error.code, other: null };
		return { data: null, code: null, other: String( error ) };

	}

}

describe( 'JSON form fuzz', () => {

	it( `${JSON_CASES} text mutations: bakedVolumeFromJSON gives a BakedVolumeError or valid data, and LightProbeVolumeLoader.parse loads exactly what the codec accepts`, () => {

		const random = mulberry32( 303 + SEED );
		const failures: string[] = [], codes: Record<string, number> = {};
		let decoded = 0;
		// Stored tetrahedra that do not fill the convex hull are rebuilt, with a warning (counted, not printed).
		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		for ( let c = 0; c < JSON_CASES; c ++ ) {

			const source = Math.floor( random() * jsonTexts.length );
			const { text, op } = mutateText( random, source );
			const fromText = readJSON( () => bakedVolumeFromJSON( text ) );
			let parsed: unknown, parses = true;
			try { parsed = JSON.parse( text ); } catch { parses = false; }
			const fromObject = parses ? readJSON( () => bakedVolumeFromJSON( parsed ) ) : { data: null, code: 'json', other: null };
			const where = `case ${c} (${op})`;
			if ( fromText.other || fromObject.other ) failures.push( `${where}: ${fromText.other ?? fromObject.other}` );
			if ( fromText.code !== fromObject.code ) failures.push( `${where}: text gives ${fromText.code}, the parsed object ${fromObject.code}` );
			if ( fromText.code ) codes[ fromText.code ] = ( codes[ fromText.code ] ?? 0 ) + 1;
			const accepted = text.startsWith( '\uFEFF' ) ? readJSON( () => bakedVolumeFromJSON( text.slice( 1 ) ) ) : fromText;
			let volume: LightProbeVolume | null = null;
			try {

				volume = loader.parse( text );

			} catch ( error ) {

				if ( accepted.data ) failures.push( `${where}: the codec accepts it but LightProbeVolumeLoader.parse throws ${String( error )}` );
				else if ( ! ( error instanceof BakedVolumeError ) ) failures.push( `${where}: LightProbeVolumeLoader.parse threw ${String( error )}` );

			}

			if ( ! accepted.data ) {

				if ( volume ) failures.push( `${where}: the codec refuses it (${accepted.code}) but LightProbeVolumeLoader.parse loads it` );
				continue;

			}

			decoded ++;
			const problem = independentCheck( accepted.data );
			if ( problem ) failures.push( `${where}: decoded but invalid: ${problem}` );
			for ( const p of [ [ 0, 0, 0 ], [ 9, - 7, 3 ] ] ) {

				if ( volume && ! volume.sample( p ).every( Number.isFinite ) ) failures.push( `${where}: sample( ${p} ) is not finite` );

			}

		}

		const rebuilt = warn.mock.calls.length;
		warn.mockRestore();
		expect( failures.slice( 0, 10 ) ).toEqual( [] );
		for ( const code of [ 'json', 'count', 'range', 'nan', 'argument', 'bad-magic' ] ) expect( codes[ code ] ?? 0, code ).toBeGreaterThan( 0 );
		expect( decoded ).toBeGreaterThan( JSON_CASES / 20 ); // harmless edits (an SH value, a name) still load
		console.log( 'JSON fuzz:', JSON.stringify( codes ), `decoded ${decoded}, of which ${rebuilt} rebuilt their tetrahedralization` );

	} );

} );

/*
 * glTF: the bufferViews, buffers and extension entries of a .gltf carrying two volumes (a scene
 * without meshes, so only the plugin reads the buffer), and the volume bytes in its data: URI,
 * mutated; every load resolves with volumes that pass the brute-force check and load in the
 * runtime, or rejects with a BakedVolumeError.
 */

const GLTF_CASES = Number( process.env.BAKED_FUZZ_GLTF_CASES ?? 300 );

type GLTFJSON = {
	bufferViews?: ( Record<string, unknown> | null )[]; buffers?: ( Record<string, unknown> | null )[];
	extensions?: Record<string, { volumes?: unknown } | null>;
};

async function exportGLTF(): Promise<GLTFJSON> {

	const scene = new Scene();
	scene.add( new Object3D() );
	const exporter = new GLTFExporter();
	const volumes = [ { name: 'hall', data: makeVolume( 12, 2 ) }, { name: '', data: makeVolume( 20, 4, false ) } ];
	exporter.register( ( writer ) => new GLTFLightProbeVolumeExporterPlugin( writer, volumes ) );
	return await exporter.parseAsync( scene, { binary: false } ) as GLTFJSON;

}

function mutateGLTF( random: () => number, base: GLTFJSON ): { json: GLTFJSON; op: string } {

	const json = structuredClone( base );
	const int = ( n: number ): number => Math.floor( random() * n );
	const pick = <T>( list: readonly T[] ): T => list[ int( list.length ) ];
	const set = ( target: Record<string, unknown>, key: string, value: unknown ) => {

		if ( value === undefined ) delete target[ key ]; else target[ key ] = value;

	};

	type Entry = { name?: unknown; bufferView?: unknown };
	const entries = ( json.extensions![ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ] as { volumes: Entry[] } ).volumes;
	const view = json.bufferViews![ entries[ int( entries.length ) ].bufferView as number ]!;
	const ops = [ 'view.buffer', 'view.byteOffset', 'view.byteLength', 'buffers', 'buffer uri', 'entry', 'extension', 'volume bytes', 'volume bytes, checksum fixed' ] as const;
	const op = pick( ops );
	switch ( op ) {

		case 'view.buffer': set( view, 'buffer', pick( [ 1, - 1, 0.5, '0', null, undefined, 1e9 ] ) ); break;
		case 'view.byteOffset': set( view, 'byteOffset', pick( [ - 8, 3, 1e9, '0', null, undefined, ( view.byteOffset as number ) + 8, ( view.byteOffset as number ) - 1 ] ) ); break;
		case 'view.byteLength': set( view, 'byteLength', pick( [ 0, 1, ( view.byteLength as number ) - 1, ( view.byteLength as number ) + 1, 1e9, null, undefined ] ) ); break;
		case 'buffers': json.buffers = pick( [ undefined, [], [ null ], [ { byteLength: 0 } ] ] as GLTFJSON[ 'buffers' ][] ); if ( json.buffers === undefined ) delete json.buffers; break;
		case 'buffer uri': {

			// A new relative URL each time: in Node, three's FileLoader keeps one that Request() refused as
			// "loading" forever, so a second load of the same one would never settle (browsers resolve it).
			const fresh = int( 1e9 );
			json.buffers![ 0 ]!.uri = pick( [ `missing-${fresh}.bin`, 'data:application/octet-stream;base64,', 'data:application/octet-stream;base64,@@@', fresh ] );
			break;

		}

		case 'entry': {

			const entry = entries[ int( entries.length ) ];
			if ( random() < 0.5 ) set( entry, 'bufferView', pick( [ - 1, 99, '0', null, 1.5, undefined ] ) );
			else set( entry, 'name', pick( [ 5, null, {} ] ) );
			break;

		}

		case 'extension': json.extensions![ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ] = pick( [ null, { volumes: {} }, { volumes: null }, {} ] ) as never; break;
		case 'volume bytes':
		case 'volume bytes, checksum fixed': {

			const uri = json.buffers![ 0 ]!.uri as string, comma = uri.indexOf( ',' ) + 1;
			const bytes = new Uint8Array( Buffer.from( uri.slice( comma ), 'base64' ) );
			const start = view.byteOffset as number, length = view.byteLength as number;
			const volume = bytes.subarray( start, start + length );
			const dv = new DataView( volume.buffer, volume.byteOffset, volume.byteLength );
			if ( random() < 0.5 ) for ( let k = 1 + int( 4 ); k > 0; k -- ) volume[ int( length ) ] ^= 1 << int( 8 );
			else dv.setUint32( 4 * int( length / 4 ), pick( EXTREME_U32 ), true );
			if ( op === 'volume bytes, checksum fixed' ) fixChecksum( volume );
			json.buffers![ 0 ]!.uri = uri.slice( 0, comma ) + Buffer.from( bytes ).toString( 'base64' );
			break;

		}

	}

	return { json, op };

}

describe( 'glTF fuzz', () => {

	beforeAll( installGLTFNodeStubs );

	it( `${GLTF_CASES} bufferView, buffer, extension and byte mutations through GLTFLoader and the plugin: valid volumes or a BakedVolumeError`, async () => {

		const base = await exportGLTF();
		const random = mulberry32( 404 + SEED );
		const failures: string[] = [], codes: Record<string, number> = {};
		let loaded = 0;
		for ( let c = 0; c < GLTF_CASES; c ++ ) {

			const { json, op } = mutateGLTF( random, base );
			const loader = new GLTFLoader();
			loader.register( ( parser ) => new GLTFLightProbeVolumeLoaderPlugin( parser ) );
			try {

				// A load that never settles is a failure too (not a hang of the suite).
				let timer: ReturnType<typeof setTimeout> | undefined;
				const gltf = await Promise.race( [
					loader.parseAsync( JSON.stringify( json ), '' ),
					new Promise<never>( ( _, reject ) => { timer = setTimeout( () => reject( new Error( 'the load did not settle in 5 s' ) ), 5000 ); } ),
				] ).finally( () => clearTimeout( timer ) );
				for ( const { data } of ( gltf.userData.lightProbeVolumes ?? [] ) as GLTFLightProbeVolumeEntry[] ) {

					const problem = independentCheck( data );
					if ( problem ) failures.push( `case ${c} (${op}): loaded but invalid: ${problem}` );
					else if ( ! LightProbeVolume.fromBakedData( data ).sample( [ 0, 0, 0 ] ).every( Number.isFinite ) ) failures.push( `case ${c} (${op}): sample not finite` );

				}

				loaded ++;

			} catch ( error ) {

				if ( error instanceof BakedVolumeError ) codes[ error.code ] = ( codes[ error.code ] ?? 0 ) + 1;
				else failures.push( `case ${c} (${op}): ${String( error )}${op === "buffer uri" ? ` [${String( json.buffers?.[ 0 ]?.uri ).slice( 0, 60 )}]` : ""}` );

			}

		}

		expect( failures.slice( 0, 10 ) ).toEqual( [] );
		for ( const code of [ 'range', 'json', 'truncated', 'checksum' ] ) expect( codes[ code ] ?? 0, code ).toBeGreaterThan( 0 );
		expect( loaded ).toBeGreaterThan( 0 );
		console.log( 'glTF fuzz:', JSON.stringify( codes ), `loaded ${loaded}` );

	} );

} );
