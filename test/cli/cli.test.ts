import { mkdtempSync, readFileSync, rmSync, statSync, truncateSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { encodeBakedVolume, bakedVolumeToJSON } from '../../src/io/index.js';
import { ProgressBar } from '../../cli/progress.js';
import { parseArguments } from '../../cli/args.js';
import { readLayout } from '../../cli/layout.js';

import { ROOM_PROBES, runCli, writeLayout, writeLitFloorGLTF, writeRoom } from './fixtures.js';

// Every bad input must be rejected before a browser starts: these runs pass a Chromium path that
// does not exist, so a check that came too late would fail with the "Chromium not found" message
// instead of the one expected.
const NO_BROWSER = { CHROME_PATH: '/nonexistent/chromium' };

let dir = '';
let room = '', layout = '';

beforeAll( () => {

	dir = mkdtempSync( join( tmpdir(), 'capture-lighting-cli-' ) );
	room = writeRoom( dir );
	layout = writeLayout( dir, 'room.json', ROOM_PROBES );

} );

afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

/** Runs a bake with the room and layout unless overridden, expecting exit code 2 and `message`. */
function expectBadInput( args: string[], message: RegExp ): void {

	const run = runCli( args, NO_BROWSER );
	expect( run.stderr ).toMatch( /^capture-lighting: / );
	expect( run.stderr ).toMatch( message );
	expect( run.code, run.stderr ).toBe( 2 );
	expect( run.stdout ).toBe( '' );

}

describe( 'capture-lighting: usage', () => {

	it( '--help prints the usage with every option and exits 0', () => {

		const run = runCli( [ '--help' ] );
		expect( run.code ).toBe( 0 );
		const options = [
			'bake', 'inspect', '--probes', '--out', '--resolution', '--format', '--precision', '--near', '--far', '--sky', '--sun', '--point',
			'--spot', '--ambient', '--no-shadows', '--shadow-map-size', '--shadow-bias', '--deringing', '--non-negative', '--strict', '--browser',
			'--quiet', '--help',
		];
		for ( const option of options ) {

			expect( run.stdout ).toContain( option );

		}

	} );

	it( 'no command, an unknown command and an unknown option exit 2 naming the problem', () => {

		expectBadInput( [], /no command given/ );
		expectBadInput( [ 'cook', room ], /unknown command "cook"/ );
		expectBadInput( [ 'bake', room, '--probes', layout, '--out', join( dir, 'v.bin' ), '--bogus', '3' ], /unknown option --bogus/ );
		expectBadInput( [ 'bake', room, '--out', join( dir, 'v.bin' ) ], /needs --probes/ );
		expectBadInput( [ 'bake', room, '--probes', layout ], /needs --out/ );
		expectBadInput( [ 'inspect' ], /inspect takes one file/ );

	} );

	it( 'bad --resolution (0, 257, 1.5, abc), --format, --precision, --near/--far, --sky, --sun exit 2', () => {

		const base = [ 'bake', room, '--probes', layout, '--out', join( dir, 'v.bin' ) ];
		for ( const value of [ '0', '257', '1.5', 'abc' ] ) expectBadInput( [ ...base, '--resolution', value ], new RegExp( `--resolution must be an integer from 1 to 256, got "${value.replace( '.', '\\.' )}"` ) );
		expectBadInput( [ ...base, '--format', 'xml' ], /--format must be bin or json/ );
		expectBadInput( [ ...base, '--precision', 'float8' ], /--precision must be float16 or float32/ );
		expectBadInput( [ ...base, '--near', '2', '--far', '1' ], /need 0 < --near < --far/ );
		expectBadInput( [ ...base, '--sky', 'blue' ], /--sky must be a colour #rrggbb or a Radiance \.hdr file/ );
		expectBadInput( [ ...base, '--sun', '1,2' ], /--sun must be x,y,z or x,y,z,intensity/ );
		expectBadInput( [ ...base, '--sun', '0,0,0' ], /--sun direction must not be 0,0,0/ );

	} );

	it( 'parses negative numbers as values and takes the format from the --out extension', () => {

		const command = parseArguments( [ 'bake', 's.glb', '--probes', 'p.json', '--out', 'v.JSON', '--sun', '-1,2,-0.5,4', '--sky', '#ff8000', '--resolution=16' ], {} );
		expect( command.command ).toBe( 'bake' );
		if ( command.command !== 'bake' ) return;
		expect( command.options.format ).toBe( 'json' );
		expect( command.options.lights ).toMatchObject( [ { type: 'directional', direction: [ - 1, 2, - 0.5 ], intensity: 4 } ] );
		expect( command.options.sky ).toEqual( { color: [ 1, 128 / 255, 0 ] } );
		expect( command.options.resolution ).toBe( 16 );
		expect( command.options.browser ).toBe( '/usr/bin/chromium' );
		expect( parseArguments( [ 'bake', 's.glb', '--probes', 'p', '--out', 'v.bin' ], { CHROME_PATH: '/x/chrome' } ) ).toMatchObject( { options: { format: 'bin', precision: 'float32', resolution: 32, browser: '/x/chrome' } } );
		expect( parseArguments( [ 'inspect', '--strict', 'v.bin' ], {} ) ).toEqual( { command: 'inspect', file: 'v.bin', strict: true } );
		expect( parseArguments( [ 'inspect', 'v.bin' ], {} ) ).toEqual( { command: 'inspect', file: 'v.bin', strict: false } );

	} );

} );

describe( 'capture-lighting bake: bad input exits 2 before a browser starts', () => {

	it( 'missing scene, unknown extension, not a GLB, missing .mtl, missing glTF buffer', () => {

		const out = join( dir, 'v.bin' );
		expectBadInput( [ 'bake', join( dir, 'nothing.glb' ), '--probes', layout, '--out', out ], /scene .*nothing\.glb not found/ );
		writeFileSync( join( dir, 'scene.fbx' ), 'x' );
		expectBadInput( [ 'bake', join( dir, 'scene.fbx' ), '--probes', layout, '--out', out ], /scene .*scene\.fbx has the extension "\.fbx"; expected \.glb, \.gltf or \.obj/ );
		writeFileSync( join( dir, 'fake.glb' ), 'not a glb' );
		expectBadInput( [ 'bake', join( dir, 'fake.glb' ), '--probes', layout, '--out', out ], /fake\.glb is not a binary glTF file/ );
		writeFileSync( join( dir, 'lonely.obj' ), 'mtllib gone.mtl\nv 0 0 0\n' );
		expectBadInput( [ 'bake', join( dir, 'lonely.obj' ), '--probes', layout, '--out', out ], /lonely\.obj needs its material library gone\.mtl, which is not in / );
		const floor = writeLitFloorGLTF( dir );
		rmSync( join( dir, 'floor.bin' ) );
		expectBadInput( [ 'bake', floor, '--probes', layout, '--out', out ], /floor\.gltf needs the file floor\.bin/ );

	} );

	it( 'layout JSON: a UTF-8 byte-order mark is accepted; the NaN/Infinity hint appears only when the text has NaN or Infinity', () => {

		const withBOM = writeLayout( dir, 'bom.json', '\uFEFF' + JSON.stringify( ROOM_PROBES ) );
		expect( readFileSync( withBOM )[ 0 ] ).toBe( 0xEF );
		expect( readLayout( withBOM ).positions.length ).toBe( ROOM_PROBES.positions.length );
		const empty = writeLayout( dir, 'empty.json', '' );
		expect( () => readLayout( empty ) ).toThrow( /empty\.json is not valid JSON \([^)]*\)\.$/ );
		const nanText = writeLayout( dir, 'nan-hint.json', '{ "positions": [ 0, 0, Infinity ] }' );
		expect( () => readLayout( nanText ) ).toThrow( /nan-hint\.json is not valid JSON \(.*\); NaN and Infinity cannot be written in JSON\.$/ );

	} );

	it( 'layout: "lights" is passed through as written (cli/layoutLights.ts checks it); absent, it stays undefined', () => {

		const lights = [ { type: 'point', position: [ 0, 2, 0 ], color: '#ffffff', intensity: 5 }, 'not checked here' ];
		expect( readLayout( writeLayout( dir, 'lights.json', { ...ROOM_PROBES, lights } ) ).lights ).toEqual( lights );
		expect( readLayout( writeLayout( dir, 'lights-odd.json', { ...ROOM_PROBES, lights: 7 } ) ).lights ).toBe( 7 );
		expect( readLayout( layout ) ).not.toHaveProperty( 'lights' );

	} );

	it( 'layout: missing, NaN (null in JSON), literal NaN, < 4 probes, all at one point, duplicates (named or not), a bad zone, unknown role, names of the wrong length', () => {

		const out = join( dir, 'v.bin' );
		const bake = ( file: string ) => [ 'bake', room, '--probes', file, '--out', out ];
		expectBadInput( bake( join( dir, 'none.json' ) ), /probe layout .*none\.json not found/ );

		const nan = ROOM_PROBES.positions.slice() as number[];
		nan[ 3 * 5 + 1 ] = NaN; // JSON.stringify writes null
		expectBadInput( bake( writeLayout( dir, 'nan.json', { positions: nan } ) ), /nan\.json: probe 5 has y = null \(positions\[16\]\); every coordinate must be a finite number/ );
		expectBadInput( bake( writeLayout( dir, 'nan-text.json', '{ "positions": [ 0, 0, NaN ] }' ) ), /nan-text\.json is not valid JSON/ );
		expectBadInput( bake( writeLayout( dir, 'three.json', { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0 ] } ) ), /three\.json has 3 probes; a layout needs at least 4\.$/m );
		// Planar and collinear layouts are accepted (test/cli/planarLayout.test.ts); all probes at one place are duplicates.
		expectBadInput( bake( writeLayout( dir, 'point.json', { positions: [ 1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3 ] } ) ),
			/point\.json: probe 1 and probe 0 are at the same position \(1, 2, 3\) \(and 2 more duplicates\); remove one\./ );
		const duplicate = ROOM_PROBES.positions.slice();
		duplicate.splice( 3 * 7, 3, ...duplicate.slice( 3 * 2, 3 * 2 + 3 ) );
		expectBadInput( bake( writeLayout( dir, 'dup.json', { positions: duplicate } ) ), /dup\.json: probe 7 and probe 2 are at the same position \(-1\.2, 0\.5, 1\.2\)/ );
		expectBadInput( bake( writeLayout( dir, 'dup-named.json', { ...ROOM_PROBES, positions: duplicate } ) ), /dup-named\.json: probe 7 \("h"\) and probe 2 \("c"\) are at the same position/ );
		expectBadInput( bake( writeLayout( dir, 'zone.json', { ...ROOM_PROBES, zones: [ { name: 'hall', probes: [ 1, 12 ] } ] } ) ), /zone\.json: .*zones\[0\].*12/ );
		const roles = ROOM_PROBES.roles.slice();
		roles[ 4 ] = 'glow';
		expectBadInput( bake( writeLayout( dir, 'role.json', { ...ROOM_PROBES, roles } ) ), /role\.json: probe 4 has the unknown role "glow"; expected one of sky, bounce, bleed, fill/ );
		expectBadInput( bake( writeLayout( dir, 'names.json', { ...ROOM_PROBES, names: [ 'a' ] } ) ), /names\.json: "names" has 1 entries for 10 probes/ );

	} );

	it( '--out overwriting the scene\'s files or the layout, or in a missing folder; a missing --sky panorama', () => {

		expectBadInput( [ 'bake', room, '--probes', layout, '--out', join( dir, 'room.mtl' ) ], /would overwrite a file of the scene/ );
		expectBadInput( [ 'bake', room, '--probes', layout, '--out', layout ], /is the probe layout/ );
		expectBadInput( [ 'bake', room, '--probes', layout, '--out', join( dir, 'no/such/folder/v.bin' ) ], /--out: the folder .*no\/such\/folder .* does not exist/ );
		expectBadInput( [ 'bake', room, '--probes', layout, '--out', join( dir, 'v.bin' ), '--sky', join( dir, 'sky.hdr' ) ], /--sky: the panorama .*sky\.hdr was not found/ );

	} );

	it( 'valid input but no Chromium: exit 2 with how to get one, and no output file', () => {

		const out = join( dir, 'never.bin' );
		expectBadInput( [ 'bake', room, '--probes', layout, '--out', out ], /Chromium not found at \/nonexistent\/chromium; install it \(apt install chromium\) or pass --browser/ );
		expectBadInput( [ 'bake', room, '--probes', layout, '--out', out, '--browser', join( dir, 'chrome' ) ], /Chromium not found at .*chrome;/ );
		expect( () => statSync( out ) ).toThrow();

	} );

} );

describe( 'capture-lighting inspect (volumes written by the codec, no browser)', () => {

	/** A valid volume of the room layout, SH = probe index in every coefficient, one zone. */
	function volume() {

		const positions = Float64Array.from( ROOM_PROBES.positions );
		const { tetrahedra, neighbors } = tetrahedralize( positions );
		const sh = new Float32Array( 27 * 10 ).map( ( _, i ) => Math.floor( i / 27 ) );
		return {
			positions, sh, tetrahedra, neighbors, names: ROOM_PROBES.names, roles: ROOM_PROBES.roles as ( 'bounce' | 'fill' | 'bleed' )[],
			zones: [ { name: 'walls', probes: [ 8, 9 ] } ], capture: { resolution: 16, near: 0.1, far: 50 },
			count: tetrahedra.length / 4,
		};

	}

	it( 'prints probes, tetrahedra, zones, roles, precision, bounds, capture settings and size; exit 0', () => {

		const data = volume();
		const bin = join( dir, 'ok.bin' );
		writeFileSync( bin, new Uint8Array( encodeBakedVolume( data, { precision: 'float16' } ) ) );
		const run = runCli( [ 'inspect', bin ] );
		expect( run.code, run.stderr ).toBe( 0 );
		const row = ( label: string ) => new RegExp( `^  ${label} +(.*)$`, 'm' ).exec( run.stdout )?.[ 1 ];
		expect( row( 'probes' ) ).toBe( '10' );
		expect( row( 'tetrahedra' ) ).toBe( String( data.count ) );
		expect( row( 'zones' ) ).toBe( '1 (walls: 2 probes)' );
		expect( row( 'roles' ) ).toBe( 'bounce 4, fill 4, bleed 2' );
		expect( row( 'SH precision' ) ).toBe( 'float16' );
		expect( row( 'bounds' ) ).toBe( '(-1.7, 0.5, -1.2) – (1.7, 2.4, 1.2)' );
		expect( row( 'capture' ) ).toBe( 'resolution 16, near 0.1, far 50' );
		expect( row( 'size on disk' ) ).toContain( `${statSync( bin ).size.toLocaleString( 'en-US' )} bytes` );

		const json = join( dir, 'ok.json' );
		writeFileSync( json, JSON.stringify( bakedVolumeToJSON( data ) ) );
		const jsonRun = runCli( [ 'inspect', json ] );
		expect( jsonRun.code, jsonRun.stderr ).toBe( 0 );
		expect( jsonRun.stdout ).toMatch( /^ {2}file +.*ok\.json \(JSON, valid\)$/m );
		expect( jsonRun.stdout ).toMatch( /^ {2}tetrahedra +(\d+)$/m );

	} );

	it( 'a corrupted, truncated or foreign file exits 1 with the codec\'s message; a missing file exits 2', () => {

		const bytes = new Uint8Array( encodeBakedVolume( volume(), { precision: 'float32' } ) );
		const corrupted = bytes.slice();
		corrupted[ corrupted.length - 5 ] ^= 0x40;
		const files = {
			corrupted: [ corrupted, /corrupted\.bin is not a valid baked volume: decodeBakedVolume: corrupted: CRC-32 of bytes/ ],
			truncated: [ bytes.slice( 0, bytes.length - 8 ), /truncated\.bin is not a valid baked volume: decodeBakedVolume: .*truncated/ ],
			foreign: [ readFileSync( room ), /foreign\.bin is not a valid baked volume: decodeBakedVolume: not a baked light probe volume/ ],
		} as const;
		for ( const [ name, [ content, message ] ] of Object.entries( files ) ) {

			const file = join( dir, `${name}.bin` );
			writeFileSync( file, content );
			const run = runCli( [ 'inspect', file ] );
			expect( run.stderr ).toMatch( message );
			expect( run.code, run.stderr ).toBe( 1 );
			expect( run.stdout ).toBe( '' );

		}

		const badJSON = join( dir, 'bad.json' );
		const badTetrahedra = { tetrahedra: [ 0, 0, 0, 0 ], tetrahedronCount: 1, neighbors: [ - 1, - 1, - 1, - 1 ] };
		writeFileSync( badJSON, JSON.stringify( { ...bakedVolumeToJSON( volume() ), ...badTetrahedra } ) );
		const jsonRun = runCli( [ 'inspect', badJSON ] );
		expect( jsonRun.stderr ).toMatch( /bad\.json is not a valid baked volume: bakedVolumeFromJSON: / );
		expect( jsonRun.code ).toBe( 1 );

		// A file of 2 GiB or more cannot be read into one Node buffer: one line, exit 1 (a sparse
		// file, so the test writes no data).
		const huge = join( dir, 'huge.bin' );
		writeFileSync( huge, '' );
		truncateSync( huge, 2 ** 31 + 16 );
		const hugeRun = runCli( [ 'inspect', huge ] );
		expect( hugeRun.stderr ).toMatch( /^capture-lighting: .*huge\.bin is not a valid baked volume: it has 2147483664 bytes, more than the 2 GiB a volume file can have\.\n$/ );
		expect( hugeRun.code ).toBe( 1 );
		rmSync( huge );

		const missing = runCli( [ 'inspect', join( dir, 'missing.bin' ) ] );
		expect( missing.stderr ).toMatch( /^capture-lighting: volume .*missing\.bin not found/ );
		expect( missing.code ).toBe( 2 );

	} );

} );

describe( 'ProgressBar', () => {

	function capture( tty: boolean ) {

		let text = '', time = 0;
		const bar = new ProgressBar( { write: ( s: string ) => { text += s; }, isTTY: tty, columns: 100 }, { now: () => time } );
		bar.start( 'capturing' );
		for ( let i = 1; i <= 50; i ++ ) {

			time += 50;
			bar.update( i, 50 );

		}

		bar.finish();
		return text;

	}

	it( 'on a terminal: one line redrawn with \\r at most every 100 ms, ending at 100 % and a newline', () => {

		const text = capture( true );
		const draws = text.split( '\r' ).filter( Boolean );
		expect( draws.length ).toBe( 26 ); // every other update (100 ms apart) plus the last
		expect( draws[ draws.length - 1 ] ).toMatch( /^capturing \[#+\] 100% 50\/50 2\.5 s\x1b\[K\n$/ );
		expect( text.split( '\n' ).length ).toBe( 2 );

	} );

	it( 'elsewhere: a line at the first update and at each 10 % step, no carriage returns', () => {

		const text = capture( false );
		expect( text ).not.toContain( '\r' );
		const lines = text.trim().split( '\n' );
		expect( lines.length ).toBe( 11 ); // 2 % (the first update), 10 %, 20 %, … 100 %
		expect( lines[ 0 ] ).toBe( 'capturing: 1/50 2% 0.1 s' );
		expect( lines[ 1 ] ).toBe( 'capturing: 5/50 10% 0.3 s' );
		expect( lines[ 10 ] ).toBe( 'capturing: 50/50 100% 2.5 s' );

	} );

	it( 'quiet: nothing', () => {

		let text = '';
		const bar = new ProgressBar( { write: ( s: string ) => { text += s; }, isTTY: true }, { quiet: true } );
		bar.start( 'x' );
		bar.update( 1, 2 );
		bar.finish();
		expect( text ).toBe( '' );

	} );

} );

