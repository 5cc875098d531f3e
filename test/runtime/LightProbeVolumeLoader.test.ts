import { createServer, type IncomingHttpHeaders, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { LoadingManager } from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeExporter } from '../../src/runtime/LightProbeVolumeExporter.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { BakedVolumeError, bakedVolumeToJSON, decodeBakedVolume, encodeBakedVolume } from '../../src/io/index.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { randomVolume as createRandomVolume } from '../helpers/randomVolume.js';
import { installGLTFNodeStubs } from '../io/gltfNodeStubs.js';

/*
 * LightProbeVolumeLoader / LightProbeVolumeExporter: the baked-file I/O outside LightProbeVolume,
 * as three's loaders and exporters. Truth: the codec's own output for the same data (test/io pins
 * the codec to docs/format.md), the original volume's samples, and a guard case whose blend is
 * known analytically. load() runs against a real HTTP server on 127.0.0.1.
 */

// Node 20 has fetch but no ProgressEvent, which three's FileLoader creates per chunk (without it a load never ends).
installGLTFNodeStubs();

const randomVolume = ( count: number, seed: number ): LightProbeVolume => createRandomVolume( count, seed, 'loader test' );

/** The loaded volume holds the original's data and lights every point as it does, within `tolerance` (relative). */
function expectSameVolume( loaded: LightProbeVolume, volume: LightProbeVolume, tolerance: number ): void {

	expect( loaded ).toBeInstanceOf( LightProbeVolume );
	expect( Array.from( loaded.positions ) ).toEqual( Array.from( volume.positions ) );
	expect( loaded.names ).toEqual( volume.names );
	expect( loaded.roles ).toEqual( volume.roles );
	const zones = ( v: LightProbeVolume ) => v.zones!.zones.map( ( z ) => [ z.name, Array.from( z.probes ), Array.from( z.bounds ) ] );
	expect( zones( loaded ) ).toEqual( zones( volume ) );
	expect( loaded.captureSettings ).toEqual( volume.captureSettings );
	expect( loaded.metadata ).toBe( volume.metadata );
	const tetrahedra = ( v: LightProbeVolume ) => Array.from( ( v.interpolator as TetrahedralMesh ).tetrahedra );
	expect( loaded.interpolator ).toBeInstanceOf( TetrahedralMesh );
	expect( tetrahedra( loaded ) ).toEqual( tetrahedra( volume ) );
	const random = mulberry32( 99 );
	const a = new Float32Array( 27 ), b = new Float32Array( 27 );
	for ( let k = 0; k < 200; k ++ ) {

		// Inside and outside the probes' hull, with and without a zone.
		const p = [ 14 * random() - 2, 14 * random() - 2, 14 * random() - 2 ];
		const zone = k % 3 === 0 ? { zone: 'west' } : undefined;
		volume.sample( p, a, zone );
		loaded.sample( p, b, zone );
		for ( let j = 0; j < 27; j ++ ) expect( Math.abs( a[ j ] - b[ j ] ), `sample ${k}, coefficient ${j}` ).toBeLessThanOrEqual( tolerance * ( 1 + Math.abs( a[ j ] ) ) );

	}

}

/** The error `call` throws (or its promise rejects with). */
async function caught( call: () => unknown ): Promise<Error> {

	try {

		await call();

	} catch ( error ) {

		return error as Error;

	}

	throw new Error( 'the call did not fail' );

}

const volume = randomVolume( 50, 1 );
const exporter = new LightProbeVolumeExporter();
const f32 = exporter.parse( volume );
const f16 = exporter.parse( volume, { precision: 'float16' } );
const json = exporter.parse( volume, { binary: false } );
const F16_TOLERANCE = 2 ** - 10;

/*
 * A volume with a wall: 8 probes at the corners of the cube [0, 2]³, red L00 = 1 + x (1 on the
 * left, 3 on the right), and the plane x = 1.5 as occluders. At x = 0.9 the tetrahedral blend of
 * this linear field is 1.9, the left probes' weights sum to 1 − x / 2 and the right ones' to x / 2
 * (barycentric weights reproduce linear functions), so a guard that scales blocked (right) probes
 * by b gives ( w·1 + b·(1 − w)·3 ) / ( w + b·(1 − w) ), w = 1 − x / 2.
 */
const wallVolume = new LightProbeVolume( {
	positions: [ 0, 0, 0, 2, 0, 0, 0, 2, 0, 2, 2, 0, 0, 0, 2, 2, 0, 2, 0, 2, 2, 2, 2, 2 ],
	sh: Float32Array.from( { length: 27 * 8 }, ( _, i ) => i % 27 === 0 ? 1 + 2 * ( ( i / 27 ) % 2 ) : 0 ),
} );
const wall = [ 1.5, - 10, - 10, 1.5, 10, - 10, 1.5, - 10, 10, 1.5, 10, - 10, 1.5, 10, 10, 1.5, - 10, 10 ];
const wallFile = exporter.parse( wallVolume );
const behindWall = [ 0.9, 0.7, 1.1 ];
function guardedRed( blockedWeight: number ): number {

	const w = 1 - behindWall[ 0 ] / 2;
	return ( w + blockedWeight * ( 1 - w ) * 3 ) / ( w + blockedWeight * ( 1 - w ) );

}

describe( 'LightProbeVolumeExporter', () => {

	it( 'binary float32 and float16: the bytes encodeBakedVolume writes for volume.toBakedData(); JSON: bakedVolumeToJSON\'s object', async () => {

		expect( f32 ).toBeInstanceOf( ArrayBuffer );
		expect( new Uint8Array( f32 ) ).toEqual( new Uint8Array( encodeBakedVolume( volume.toBakedData() ) ) );
		expect( new Uint8Array( f16 ) ).toEqual( new Uint8Array( encodeBakedVolume( volume.toBakedData(), { precision: 'float16' } ) ) );
		expect( new Uint8Array( exporter.parse( volume, { binary: true, precision: 'float32' } ) ) ).toEqual( new Uint8Array( f32 ) );
		// 108 → 54 bytes of SH per probe, the section padded to a multiple of 8 (docs/format.md).
		expect( f32.byteLength - f16.byteLength ).toBe( 50 * 108 - 8 * Math.ceil( 50 * 54 / 8 ) );
		expect( decodeBakedVolume( f16 ).sh ).not.toEqual( decodeBakedVolume( f32 ).sh ); // really rounded to float16
		expect( JSON.stringify( json ) ).toBe( JSON.stringify( bakedVolumeToJSON( volume.toBakedData() ) ) );
		expect( json.format ).toBe( 'three-capture-lighting/baked-light-probe-volume' );
		expect( new Uint8Array( await exporter.parseAsync( volume ) ) ).toEqual( new Uint8Array( f32 ) );
		expect( JSON.stringify( await exporter.parseAsync( volume, { binary: false } ) ) ).toBe( JSON.stringify( json ) );

	} );

	it( 'removed probes are left out of the file, as volume.toBakedData() leaves them out', () => {

		const edited = new LightProbeVolume( { positions: volume.positions, sh: volume.sh, names: volume.names } );
		edited.removeProbe( 7 );
		const loaded = new LightProbeVolumeLoader().parse( exporter.parse( edited ) );
		expect( loaded.count ).toBe( 49 );
		expect( loaded.names ).not.toContain( 'probe 7' );

	} );

	it.each( [
		[ 'no volume', [ null ], TypeError, /volume must be a LightProbeVolume, got null/ ],
		[ 'not a volume', [ { positions: [] } ], TypeError, /volume must be a LightProbeVolume, got object/ ],
		[ 'options null', [ volume, null ], TypeError, /options must be an object \{ binary\?, precision\? \}, got null/ ],
		[ 'options a string', [ volume, 'float16' ], TypeError, /options must be an object/ ],
		[ 'an unknown precision', [ volume, { precision: 'float8' } ], RangeError, /precision is the string "float8"; expected 'float16' or 'float32'/ ],
		[ 'binary not a boolean', [ volume, { binary: 'yes' } ], TypeError, /binary must be true or false, got the string "yes"/ ],
		[ 'a precision for JSON', [ volume, { binary: false, precision: 'float16' } ], RangeError, /precision applies to the binary file/ ],
		[ 'a misspelt option', [ volume, { precison: 'float16' } ], TypeError, /unknown option precison; the options are binary and precision/ ],
	] )( 'refuses %s with a named error (parse throws, parseAsync rejects)', async ( _, args, type, message ) => {

		const [ target, options ] = args as [ LightProbeVolume, never ];
		for ( const call of [ () => exporter.parse( target, options ), () => exporter.parseAsync( target, options ) ] ) {

			const error = await caught( call );
			expect( error ).toBeInstanceOf( type );
			expect( error.message ).toMatch( /^LightProbeVolumeExporter\.parse: / );
			expect( error.message ).toMatch( message );

		}

	} );

	it( 'an SH value beyond float16 is a BakedVolumeError float16-overflow naming the exporter; float32 writes it', async () => {

		const bright = new LightProbeVolume( { positions: wallVolume.positions, sh: wallVolume.sh.map( ( v, i ) => i === 27 ? 1e5 : v ) } );
		for ( const call of [ () => exporter.parse( bright, { precision: 'float16' } ), () => exporter.parseAsync( bright, { precision: 'float16' } ) ] ) {

			const error = await caught( call ) as BakedVolumeError;
			expect( error ).toBeInstanceOf( BakedVolumeError );
			expect( error.code ).toBe( 'float16-overflow' );
			expect( error.message ).toMatch( /^LightProbeVolumeExporter\.parse: sh\[27\] = 100000 is beyond the float16 range/ );
			expect( ( error.cause as Error ).message ).toMatch( /^encodeBakedVolume: / );

		}

		expect( decodeBakedVolume( exporter.parse( bright ) ).sh[ 27 ] ).toBe( 1e5 );

	} );

} );

describe( 'LightProbeVolumeLoader.parse', () => {

	const loader = new LightProbeVolumeLoader();

	it( 'reads the binary file (float32 exactly, float16 within half precision) from an ArrayBuffer, a view at an offset, a Node Buffer or a DataView', () => {

		expectSameVolume( loader.parse( f32 ), volume, 0 );
		expectSameVolume( loader.parse( f16 ), volume, F16_TOLERANCE );
		const padded = new Uint8Array( f32.byteLength + 16 );
		padded.set( new Uint8Array( f32 ), 8 );
		expectSameVolume( loader.parse( padded.subarray( 8, 8 + f32.byteLength ) ), volume, 0 );
		expectSameVolume( loader.parse( Buffer.from( f16 ) ), volume, F16_TOLERANCE );
		expectSameVolume( loader.parse( new DataView( f32 ) ), volume, 0 );
		// What the class did before the loader existed: decode, then fromBakedData.
		expectSameVolume( loader.parse( f32 ), LightProbeVolume.fromBakedData( decodeBakedVolume( f32 ) ), 0 );

	} );

	it( 'reads the JSON form as an object, as text (with a BOM and white space too) and as UTF-8 bytes, exactly', () => {

		const text = JSON.stringify( json );
		expectSameVolume( loader.parse( json ), volume, 0 );
		expectSameVolume( loader.parse( text ), volume, 0 );
		expectSameVolume( loader.parse( '\uFEFF\n  ' + text ), volume, 0 );
		expectSameVolume( loader.parse( new TextEncoder().encode( '\uFEFF\r\n\t' + JSON.stringify( json, null, 2 ) ) ), volume, 0 );
		expectSameVolume( loader.parse( new TextEncoder().encode( text ).buffer ), volume, 0 );

	} );

	it( 'passes the parameters through: occluders and guard options reach the volume (the guarded blend is the analytic one)', () => {

		const red = ( loaded: LightProbeVolume ) => loaded.sample( behindWall )[ 0 ];
		expect( red( loader.parse( wallFile ) ) ).toBeCloseTo( 1.9, 6 );
		expect( red( loader.parse( wallFile, { occluders: wall } ) ) ).toBeCloseTo( guardedRed( 0 ), 6 );
		expect( guardedRed( 0 ) ).toBe( 1 );
		const soft = loader.parse( wallFile, { occluders: wall, guard: { blockedWeight: 0.5 } } );
		expect( soft.visibilityGuard!.blockedWeight ).toBe( 0.5 );
		expect( red( soft ) ).toBeCloseTo( guardedRed( 0.5 ), 6 );
		const wallText = JSON.stringify( exporter.parse( wallVolume, { binary: false } ) );
		expect( red( loader.parse( wallText, { occluders: wall } ) ) ).toBeCloseTo( 1, 6 );
		// setParameters: the default of parse() (and of load(), below).
		const guarded = new LightProbeVolumeLoader().setParameters( { occluders: wall } );
		expect( red( guarded.parse( wallFile ) ) ).toBeCloseTo( 1, 6 );
		expect( red( guarded.parse( wallFile, {} ) ) ).toBeCloseTo( 1.9, 6 );

	} );

	it( 'refuses parameters that are not an object or that a file gives (they would be replaced silently)', async () => {

		for ( const [ parameters, message ] of [
			[ 'x', /^LightProbeVolumeLoader\.parse: parameters must be an object, got the string "x"/ ],
			[ null, /^LightProbeVolumeLoader\.parse: parameters must be an object, got null/ ],
			[ { positions: [ 0, 0, 0 ] }, /^LightProbeVolumeLoader\.parse: parameters\.positions \(an array of length 3\) comes from the baked file/ ],
			[ { zones: [] }, /^LightProbeVolumeLoader\.parse: parameters\.zones .* comes from the baked file/ ],
		] as const ) {

			const error = await caught( () => loader.parse( f32, parameters as never ) );
			expect( error ).toBeInstanceOf( TypeError );
			expect( error.message ).toMatch( message );

		}

		expect( () => new LightProbeVolumeLoader().setParameters( { sh: [] } as never ) ).toThrow( /^LightProbeVolumeLoader\.setParameters: parameters\.sh/ );
		// The constructor's own checks still apply to the values (here the guard's).
		expect( () => loader.parse( wallFile, { occluders: 5 as never } ) ).toThrow( /^VisibilityGuard: / );

	} );

	const damaged = new Uint8Array( f32.slice( 0 ) );
	damaged[ 300 ] ^= 0x10;
	const html = '<!doctype html>\n<html><head><title>Vite</title></head><body><div id="app"></div></body></html>';
	it.each( [
		[ 'a truncated file', f32.slice( 0, f32.byteLength - 9 ), 'truncated', /the header declares \d+ bytes but the buffer holds \d+: the file is truncated/ ],
		[ 'a corrupted byte', damaged, 'checksum', /^LightProbeVolumeLoader\.parse: corrupted: CRC-32/ ],
		[ 'an empty buffer', new ArrayBuffer( 0 ), 'truncated', /the buffer ends after 0 bytes/ ],
		[ 'another binary format (PNG)', Uint8Array.from( [ 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13 ] ), 'bad-magic', /not a baked light probe volume/ ],
		[ 'an HTML page as bytes', new TextEncoder().encode( html ), 'bad-magic', /the data is an HTML or XML page, not a baked light probe volume/ ],
		[ 'an HTML page as text', '\n' + html, 'bad-magic', /the data is an HTML or XML page/ ],
		[ 'malformed JSON text', '{"format": ', 'json', /^LightProbeVolumeLoader\.parse: not valid JSON/ ],
		[ 'malformed JSON bytes', new TextEncoder().encode( '{"format": ' ), 'json', /^LightProbeVolumeLoader\.parse: not valid JSON/ ],
		[ 'JSON bytes that are not UTF-8', Uint8Array.from( [ 0x7B, 0x22, 0xC3, 0x28, 0x22, 0x7D ] ), 'utf8', /starts like JSON text but is not valid UTF-8/ ],
		[ 'another JSON document', '{"format": "something else"}', 'bad-magic', /format is "something else"/ ],
		[ 'a JSON object of another kind', { format: 'glTF' }, 'bad-magic', /format is "glTF"/ ],
		[ 'a JSON array', [ 1, 2, 3 ], 'json', /expected a JSON object/ ],
		[ 'a number', 5, 'argument', /data must be a baked file \(an ArrayBuffer or a typed array\), its JSON text or its JSON object, got 5/ ],
		[ 'null', null, 'argument', /got null/ ],
	] )( '%s: a BakedVolumeError naming LightProbeVolumeLoader.parse, not a volume', ( _, data, code, message ) => {

		const error = ( () => {

			try {

				loader.parse( data as never );

			} catch ( thrown ) {

				return thrown as BakedVolumeError;

			}

			throw new Error( 'parse did not fail' );

		} )();
		expect( error ).toBeInstanceOf( BakedVolumeError );
		expect( error.code ).toBe( code );
		expect( error.message ).toMatch( /^LightProbeVolumeLoader\.parse: / );
		expect( error.message ).toMatch( message );
		expect( error.message ).not.toMatch( /decodeBakedVolume|bakedVolumeFromJSON/ );

	} );

} );

describe( 'LightProbeVolumeLoader.load over HTTP (a Node server on 127.0.0.1)', () => {

	const files: Record<string, { body: Uint8Array | string; type: string }> = {
		'/files/level.lpv': { body: new Uint8Array( f32 ), type: 'application/octet-stream' },
		'/files/level16.lpv': { body: new Uint8Array( f16 ), type: 'application/octet-stream' },
		'/files/level.json': { body: JSON.stringify( json ), type: 'application/json' },
		'/files/wall.lpv': { body: new Uint8Array( wallFile ), type: 'application/octet-stream' },
		// A file cut short on the server (an interrupted upload): the server sends what it has.
		'/files/truncated.lpv': { body: new Uint8Array( f32.slice( 0, 1000 ) ), type: 'application/octet-stream' },
		// What Vite's dev server answers for a file that is not there: its index page, with 200.
		'/files/spa.lpv': { body: '<!doctype html>\n<html><body><div id="app"></div></body></html>', type: 'text/html' },
	};
	let server: Server, base = '';
	const requests: { url: string; headers: IncomingHttpHeaders }[] = [];

	beforeAll( async () => {

		server = createServer( ( request, response ) => {

			requests.push( { url: request.url ?? '', headers: request.headers } );
			if ( request.url === '/files/dropped.lpv' ) {

				// The connection dies mid-transfer: half of the bytes the Content-Length announces.
				response.writeHead( 200, { 'Content-Type': 'application/octet-stream', 'Content-Length': f32.byteLength } );
				response.write( new Uint8Array( f32.slice( 0, f32.byteLength / 2 ) ), () => response.destroy() );
				return;

			}

			const file = files[ request.url ?? '' ];
			if ( ! file ) {

				response.writeHead( 404, { 'Content-Type': 'text/html' } ).end( '<html><body>Cannot GET</body></html>' );
				return;

			}

			const body = typeof file.body === 'string' ? Buffer.from( file.body ) : file.body;
			response.writeHead( 200, { 'Content-Type': file.type, 'Content-Length': body.byteLength } ).end( body );

		} );
		await new Promise<void>( ( resolve ) => server.listen( 0, '127.0.0.1', resolve ) );
		base = `http://127.0.0.1:${( server.address() as AddressInfo ).port}/files/`;

	} );

	afterAll( () => new Promise<void>( ( resolve ) => server.close( () => resolve() ) ) );

	it( 'load(): path, request headers and progress apply; the volume is the one exported', async () => {

		const progress: { loaded: number; total: number; lengthComputable: boolean }[] = [];
		const loader = new LightProbeVolumeLoader().setPath( base ).setRequestHeader( { 'X-Level': 'hall' } );
		const loaded = await new Promise<LightProbeVolume>( ( resolve, reject ) => {

			loader.load( 'level.lpv', resolve, ( event ) => progress.push( event ), reject );

		} );
		expectSameVolume( loaded, volume, 0 );
		expect( requests.at( - 1 )!.url ).toBe( '/files/level.lpv' );
		expect( requests.at( - 1 )!.headers[ 'x-level' ] ).toBe( 'hall' );
		expect( progress.length ).toBeGreaterThan( 0 );
		expect( progress.at( - 1 ) ).toMatchObject( { loaded: f32.byteLength, total: f32.byteLength, lengthComputable: true } );

	} );

	it( 'loadAsync(): float16 and JSON files, told apart by their bytes whatever the URL says', async () => {

		const loader = new LightProbeVolumeLoader();
		expectSameVolume( await loader.loadAsync( base + 'level16.lpv' ), volume, F16_TOLERANCE );
		expectSameVolume( await loader.loadAsync( base + 'level.json' ), volume, 0 );

	} );

	it( 'parameters set on the loader reach the volumes it loads', async () => {

		const loaded = await new LightProbeVolumeLoader().setParameters( { occluders: wall, guard: { blockedWeight: 0.5 } } ).loadAsync( base + 'wall.lpv' );
		expect( loaded.sample( behindWall )[ 0 ] ).toBeCloseTo( guardedRed( 0.5 ), 6 );

	} );

	it( 'a 404 is an Error of LightProbeVolumeLoader.load naming the URL and the status, not a decode error of the page', async () => {

		const url = base + 'missing.lpv';
		const error = await caught( () => new LightProbeVolumeLoader().loadAsync( url ) );
		expect( error ).not.toBeInstanceOf( BakedVolumeError );
		expect( error.message ).toBe( `LightProbeVolumeLoader.load: "${url}" could not be loaded: the server answered HTTP 404 Not Found.` );
		expect( ( error.cause as { response: Response } ).response.status ).toBe( 404 );
		// load() with callbacks: onError gets the same error, onLoad is never called.
		const viaCallbacks = await new Promise<Error>( ( resolve, reject ) => {

			new LightProbeVolumeLoader().load( url, () => reject( new Error( 'onLoad called' ) ), undefined, ( e ) => resolve( e as Error ) );

		} );
		expect( viaCallbacks.message ).toBe( error.message );

	} );

	it( 'a truncated file is a BakedVolumeError "truncated" naming the URL; a page served for a missing file says so', async () => {

		const truncated = await caught( () => new LightProbeVolumeLoader().loadAsync( base + 'truncated.lpv' ) ) as BakedVolumeError;
		expect( truncated ).toBeInstanceOf( BakedVolumeError );
		expect( truncated.code ).toBe( 'truncated' );
		expect( truncated.message ).toBe( `LightProbeVolumeLoader.parse: "${base}truncated.lpv": the header declares ${f32.byteLength} bytes but the buffer holds 1000: the file is truncated.` );
		const page = await caught( () => new LightProbeVolumeLoader().loadAsync( base + 'spa.lpv' ) ) as BakedVolumeError;
		expect( page.code ).toBe( 'bad-magic' );
		expect( page.message ).toMatch( new RegExp( `^LightProbeVolumeLoader\\.parse: "${base}spa\\.lpv": the data is an HTML or XML page` ) );

	} );

	it( 'a connection that drops mid-transfer is an Error of LightProbeVolumeLoader.load naming the URL', async () => {

		const error = await caught( () => new LightProbeVolumeLoader().loadAsync( base + 'dropped.lpv' ) );
		expect( error ).not.toBeInstanceOf( BakedVolumeError );
		expect( error.message ).toMatch( new RegExp( `^LightProbeVolumeLoader\\.load: "${base}dropped\\.lpv" could not be loaded: the request failed \\(.+\\)\\.$` ) );

	} );

	it( 'the loading manager sees every item start and end, onError with the URL of each failure (HTTP or file), then onLoad once', async () => {

		const events: string[] = [];
		let finished: () => void = () => {};
		const allEnded = new Promise<void>( ( resolve ) => finished = resolve );
		const manager = new LoadingManager(
			() => { events.push( 'load' ); finished(); },
			( url, loaded, total ) => events.push( `progress ${url.slice( base.length )} ${loaded}/${total}` ),
			( url ) => events.push( `error ${url.slice( base.length )}` ),
		);
		manager.onStart = ( url ) => events.push( `start ${url.slice( base.length )}` );
		const loader = new LightProbeVolumeLoader( manager ).setPath( base );
		const outcomes = await Promise.allSettled( [ 'level.lpv', 'missing.lpv', 'truncated.lpv' ].map( ( name ) => loader.loadAsync( name ) ) );
		expect( outcomes.map( ( o ) => o.status ) ).toEqual( [ 'fulfilled', 'rejected', 'rejected' ] );
		await allEnded; // FileLoader ends an item after its callbacks ran
		expect( events[ 0 ] ).toBe( 'start level.lpv' );
		expect( events.filter( ( e ) => e.startsWith( 'error' ) ).sort() ).toEqual( [ 'error missing.lpv', 'error truncated.lpv' ] );
		expect( events.filter( ( e ) => e.startsWith( 'progress' ) ).map( ( e ) => e.split( ' ' )[ 2 ] ) ).toEqual( [ '1/3', '2/3', '3/3' ] );
		expect( events.at( - 1 ) ).toBe( 'load' );
		expect( events.filter( ( e ) => e === 'load' ) ).toHaveLength( 1 );
		// Each failure is reported before that item ends.
		for ( const name of [ 'missing.lpv', 'truncated.lpv' ] ) {

			expect( events.indexOf( `error ${name}` ) ).toBeLessThan( events.findIndex( ( e ) => e.startsWith( `progress ${name}` ) ) );

		}

	} );

	it( 'refuses a url that is not a string and callbacks that are not functions, before any request', () => {

		const loader = new LightProbeVolumeLoader();
		const before = requests.length;
		expect( () => loader.load( 5 as never, () => {} ) ).toThrow( /^LightProbeVolumeLoader\.load: url must be a string, got 5/ );
		expect( () => loader.load( base + 'level.lpv', null as never ) ).toThrow( /^LightProbeVolumeLoader\.load: onLoad must be a function/ );
		expect( () => loader.load( base + 'level.lpv', () => {}, 'x' as never ) ).toThrow( /^LightProbeVolumeLoader\.load: onProgress must be a function/ );
		expect( () => loader.load( base + 'level.lpv', () => {}, undefined, 1 as never ) ).toThrow( /^LightProbeVolumeLoader\.load: onError must be a function/ );
		expect( requests.length ).toBe( before );

	} );

} );
