import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { parseArguments, USAGE, type BakeOptions } from '../../cli/args.js';
import { CliError } from '../../cli/errors.js';
import { parseLayoutLights } from '../../cli/layoutLights.js';
import { CAPTURE_SCENE_DEFAULTS } from '../../src/capture/captureSceneDefaults.js';
import { CORNELL_PROBES, runCli, writeCornellOBJ, writeLayout } from './fixtures.js';

// The light flags, the layout's "lights", the scene-preparation and SH flags and the defaults,
// parsed without a browser. A few runs of the real CLI show that bad input is one line, exit 2.

const NO_BROWSER = { CHROME_PATH: '/nonexistent/chromium' };
const base = [ 'bake', 's.glb', '--probes', 'p.json', '--out', 'v.bin' ];

function bakeOptions( ...args: string[] ): BakeOptions {

	const command = parseArguments( [ ...base, ...args ], {} );
	if ( command.command !== 'bake' ) throw new Error( 'not a bake' );
	return command.options;

}

function parseError( run: () => unknown ): string {

	try {

		run();

	} catch ( error ) {

		expect( error ).toBeInstanceOf( CliError );
		expect( ( error as CliError ).exitCode ).toBe( 2 );
		return ( error as Error ).message;

	}

	throw new Error( 'expected a CliError' );

}

let dir = '';
beforeAll( () => { dir = mkdtempSync( join( tmpdir(), 'capture-lighting-lights-' ) ); } );
afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

describe( 'capture-lighting bake: light flags', () => {

	it( '--point, --spot and --sun are repeatable, with three\'s defaults (intensity 1, white, no cut-off, decay 2, 60°), --sun 3', () => {

		const options = bakeOptions( '--point', '0.2,2.1,0.3,12,#fff2e0', '--point', '-1,2,0', '--sun', '0,1,0', '--sun', '1,1,0,5,#ff8000',
			'--spot', '0,3,0,0,0,0,20,#ffffff,30,0.5,8', '--spot', '1,2,1,1,0,1' );
		expect( options.lights ).toEqual( [
			{ type: 'directional', direction: [ 0, 1, 0 ], intensity: 3, color: 0xffffff, source: 'flags' },
			{ type: 'directional', direction: [ 1, 1, 0 ], intensity: 5, color: 0xff8000, source: 'flags' },
			{ type: 'point', position: [ 0.2, 2.1, 0.3 ], intensity: 12, color: 0xfff2e0, distance: 0, decay: 2, source: 'flags' },
			{ type: 'point', position: [ - 1, 2, 0 ], intensity: 1, color: 0xffffff, distance: 0, decay: 2, source: 'flags' },
			{
				type: 'spot', position: [ 0, 3, 0 ], target: [ 0, 0, 0 ], intensity: 20, color: 0xffffff, distance: 8, decay: 2,
				angle: 30, penumbra: 0.5, source: 'flags',
			},
			{
				type: 'spot', position: [ 1, 2, 1 ], target: [ 1, 0, 1 ], intensity: 1, color: 0xffffff, distance: 0, decay: 2,
				angle: 60, penumbra: 0, source: 'flags',
			},
		] );

	} );

	it( 'bad light specs name the flag, its syntax and the bad field', () => {

		const cases: [ string[], RegExp ][] = [
			[ [ '--point', '1,2' ], /^--point must be x,y,z\[,intensity\[,#rrggbb\[,distance\]\]\] \(3 to 6 fields\), got 2 fields in "1,2"\.$/ ],
			[ [ '--point', '1,2,3,4,#ffffff,5,6' ], /^--point must be .* \(3 to 6 fields\), got 7 fields/ ],
			[ [ '--point', '1,x,3' ], /^--point must be x,y,z.*; field 2 of "1,x,3" is "x", not a finite number\.$/ ],
			[ [ '--point', '1,2,3,-4' ], /^--point "1,2,3,-4": intensity must be ≥ 0, got -4\.$/ ],
			[ [ '--point', '1,2,3,4,red' ], /^--point "1,2,3,4,red": the colour must be #rrggbb \(sRGB\), got "red"\.$/ ],
			[ [ '--point', '1,2,3,4,#fff,1' ], /the colour must be #rrggbb/ ],
			[ [ '--point', '1,2,3,4,#ffffff,-1' ], /^--point "1,2,3,4,#ffffff,-1": distance must be ≥ 0, got -1\.$/ ],
			[ [ '--spot', '0,3,0' ], /^--spot must be x,y,z,tx,ty,tz\[,intensity\[,#rrggbb\[,angle°\[,penumbra\[,distance\]\]\]\]\] \(6 to 11 fields\), got 3 fields/ ],
			[ [ '--spot', '0,3,0,0,3,0' ], /^--spot "0,3,0,0,3,0": the target tx,ty,tz is the light's position; it must aim somewhere\.$/ ],
			[ [ '--spot', '0,3,0,0,0,0,1,#ffffff,120' ], /^--spot ".*": angle° must be in \(0, 90\] degrees \(the cone's half angle\), got 120\.$/ ],
			[ [ '--spot', '0,3,0,0,0,0,1,#ffffff,0' ], /angle° must be in \(0, 90\]/ ],
			[ [ '--spot', '0,3,0,0,0,0,1,#ffffff,30,2' ], /^--spot ".*": penumbra must be in \[0, 1\], got 2\.$/ ],
			[ [ '--sun', '1,2' ], /^--sun must be x,y,z or x,y,z,intensity or x,y,z,intensity,#rrggbb \(finite numbers\), got "1,2"\.$/ ],
			[ [ '--sun', '0,0,0' ], /^--sun direction must not be 0,0,0\.$/ ],
			[ [ '--sun', '0,1,0,1,blue' ], /^--sun "0,1,0,1,blue": the colour must be #rrggbb/ ],
			[ [ '--point' ], /^option --point needs a value/ ],
		];
		for ( const [ args, message ] of cases ) expect( parseError( () => bakeOptions( ...args ) ), args.join( ' ' ) ).toMatch( message );

	} );

	it( 'defaults are the API\'s: resolution 32 (LightProbeVolume.capture), precision float32 (toArrayBuffer); prepareCaptureScene\'s defaults; no deringing', () => {

		const options = bakeOptions();
		expect( options.resolution ).toBe( 32 );
		expect( options.precision ).toBe( 'float32' );
		expect( options.prepare ).toEqual( { ...CAPTURE_SCENE_DEFAULTS } );
		expect( [ options.deringing, options.nonNegative, options.strict, options.lights ] ).toEqual( [ 0, false, false, [] ] );
		expect( USAGE ).toContain( '--resolution <n>         cube face size in texels, 1..256 (default 32, as LightProbeVolume.capture)' );
		expect( USAGE ).toMatch( /SH precision of the binary format \(default float32, as toArrayBuffer;/ );

	} );

	it( 'scene-preparation, SH and strict flags; bad values and contradictions exit 2', () => {

		const options = bakeOptions( '--shadow-map-size', '512', '--shadow-bias', '-0.002', '--no-shadow-fit', '--double-sided-shadows',
			'--deringing', '0.15', '--non-negative', '--strict' );
		const prepare = { shadows: true, shadowMapSize: 512, shadowBias: - 0.002, fitShadowCameras: false, doubleSidedShadows: true };
		expect( options.prepare ).toEqual( prepare );
		expect( [ options.deringing, options.nonNegative, options.strict ] ).toEqual( [ 0.15, true, true ] );
		expect( bakeOptions( '--no-shadows' ).prepare.shadows ).toBe( false );
		const contradiction = parseError( () => bakeOptions( '--no-shadows', '--shadow-map-size', '512' ) );
		expect( contradiction ).toBe( '--shadow-map-size has no effect with --no-shadows; give one or the other.' );
		expect( parseError( () => bakeOptions( '--shadow-map-size', '0' ) ) ).toBe( '--shadow-map-size must be an integer from 1 to 16384, got "0".' );
		expect( parseError( () => bakeOptions( '--shadow-bias', 'abc' ) ) ).toBe( '--shadow-bias must be a finite number, got "abc".' );
		expect( parseError( () => bakeOptions( '--deringing', '1.5' ) ) ).toBe( '--deringing must be a window strength in [0, 1], got 1.5.' );
		expect( parseError( () => bakeOptions( '--strict=yes' ) ) ).toBe( 'option --strict takes no value, got "--strict=yes".' );
		expect( parseError( () => bakeOptions( '--deringing', '0.1', '--deringing', '0.2' ) ) ).toBe( 'option --deringing is given twice.' );

	} );

	it( '--help documents every flag, the lights, the scene preparation and what turns each change off', () => {

		for ( const text of [
			'--point x,y,z[,intensity[,#rrggbb[,distance]]]', '--spot x,y,z,tx,ty,tz[,intensity[,#rrggbb[,angle°[,penumbra[,distance]]]]]',
			'--sun x,y,z[,intensity[,#rrggbb]]', '--ambient', '--no-shadows', '--shadow-map-size', '--shadow-bias', '--no-shadow-fit',
			'--double-sided-shadows', '--deringing', '--non-negative', '--strict', 'KHR_lights_punctual', 'emissive', 'prepareCaptureScene',
			'"lights"', `(default ${CAPTURE_SCENE_DEFAULTS.shadowMapSize})`, `(default ${CAPTURE_SCENE_DEFAULTS.shadowBias})`,
		] ) expect( USAGE ).toContain( text );
		for ( const line of USAGE.split( '\n' ) ) expect( line.length, line ).toBeLessThanOrEqual( 120 );

	} );

} );

describe( 'capture-lighting bake: the layout\'s "lights"', () => {

	const file = 'layout.json';

	it( 'point, spot and directional lights with the flags\' defaults', () => {

		expect( parseLayoutLights( file, [
			{ type: 'point', position: [ 0.2, 2.1, 0.3 ], intensity: 12, color: '#fff2e0' },
			{ type: 'spot', position: [ 0, 3, 0 ], target: [ 0, 0, 1 ], angle: 45, penumbra: 0.2, decay: 1, distance: 10 },
			{ type: 'spot', position: [ 0, 3, 0 ] },
			{ type: 'directional', direction: [ - 1, 2, 0.5 ] },
		] ) ).toEqual( [
			{ type: 'point', position: [ 0.2, 2.1, 0.3 ], intensity: 12, color: 0xfff2e0, distance: 0, decay: 2, source: 'layout' },
			{ type: 'spot', position: [ 0, 3, 0 ], target: [ 0, 0, 1 ], intensity: 1, color: 0xffffff, distance: 10, decay: 1, angle: 45, penumbra: 0.2, source: 'layout' },
			{ type: 'spot', position: [ 0, 3, 0 ], target: [ 0, 0, 0 ], intensity: 1, color: 0xffffff, distance: 0, decay: 2, angle: 60, penumbra: 0, source: 'layout' },
			{ type: 'directional', direction: [ - 1, 2, 0.5 ], intensity: 3, color: 0xffffff, source: 'layout' },
		] );
		expect( parseLayoutLights( file, undefined ) ).toEqual( [] );
		expect( parseLayoutLights( file, [] ) ).toEqual( [] );

	} );

	it( 'bad entries name the file, the light and what was expected', () => {

		const cases: [ unknown, string ][] = [
			[ { type: 'point' }, 'probe layout layout.json: "lights" must be an array of { "type", "position" | "direction", … }.' ],
			[ [ 3 ], 'probe layout layout.json: lights[0] must be an object { "type", … }.' ],
			[ [ { type: 'area', position: [ 0, 0, 0 ] } ], 'probe layout layout.json: lights[0] has "type" "area"; expected "point", "spot" or "directional".' ],
			[ [ { type: 'point' } ], 'probe layout layout.json: lights[0] (point) has no "position"; expected [x, y, z].' ],
			[ [ { type: 'point', position: [ 0, 1 ] } ], 'probe layout layout.json: lights[0] (point): "position" is [0,1]; expected [x, y, z] (3 finite numbers).' ],
			[ [ { type: 'point', postion: [ 0, 1, 2 ] } ],
				'probe layout layout.json: lights[0] (point) has the key "postion", which a point light does not take; expected type, position, intensity, color, distance, decay.' ],
			[ [ { type: 'directional', direction: [ 0, 1, 0 ], distance: 3 } ],
				'probe layout layout.json: lights[0] (directional) has the key "distance", which a directional light does not take; expected type, direction, intensity, color.' ],
			[ [ { type: 'directional', direction: [ 0, 0, 0 ] } ], 'probe layout layout.json: lights[0] (directional): "direction" must not be [0, 0, 0].' ],
			[ [ { type: 'point', position: [ 0, 1, 2 ] }, { type: 'point', position: [ 0, 1, 2 ], intensity: - 1 } ],
				'probe layout layout.json: lights[1] (point): "intensity" is -1; expected a finite number ≥ 0.' ],
			[ [ { type: 'point', position: [ 0, 1, 2 ], color: 'white' } ], 'probe layout layout.json: lights[0] (point): "color" is "white"; expected "#rrggbb" (sRGB).' ],
			[ [ { type: 'spot', position: [ 0, 0, 0 ] } ], 'probe layout layout.json: lights[0] (spot): "target" is the light\'s "position"; it must aim somewhere.' ],
			[ [ { type: 'spot', position: [ 0, 3, 0 ], angle: 100 } ], 'probe layout layout.json: lights[0] (spot): "angle" is 100; expected the cone\'s half angle in degrees, in (0, 90].' ],
			[ [ { type: 'spot', position: [ 0, 3, 0 ], penumbra: 1.5 } ], 'probe layout layout.json: lights[0] (spot): "penumbra" is 1.5; expected a number in [0, 1].' ],
		];
		for ( const [ value, message ] of cases ) expect( parseError( () => parseLayoutLights( file, value ) ) ).toBe( message );

	} );

	it( 'the real CLI: a bad light flag or layout light is one line on stderr, exit 2, before any browser starts', () => {

		const scene = writeCornellOBJ( dir, { mtl: true } );
		const good = writeLayout( dir, 'good.json', CORNELL_PROBES );
		const bad = writeLayout( dir, 'bad-lights.json', { ...CORNELL_PROBES, lights: [ { type: 'point', position: [ 0, 2, 'x' ] } ] } );
		const out = join( dir, 'v.bin' );
		for ( const [ args, message ] of [
			[ [ '--probes', good, '--point', '0,2' ], /^capture-lighting: --point must be x,y,z\[,intensity\[,#rrggbb\[,distance\]\]\] \(3 to 6 fields\), got 2 fields in "0,2"\.\n$/ ],
			[ [ '--probes', good, '--spot', '0,2,0,1,0,0,1,#ffffff,95' ], /^capture-lighting: --spot "0,2,0,1,0,0,1,#ffffff,95": angle° must be in \(0, 90\] degrees/ ],
			[ [ '--probes', bad ], /^capture-lighting: probe layout .*bad-lights\.json: lights\[0\] \(point\): "position" is \[0,2,"x"\]; expected \[x, y, z\] \(3 finite numbers\)\.\n$/ ],
		] as const ) {

			const run = runCli( [ 'bake', scene, '--out', out, ...args ], NO_BROWSER );
			expect( run.stderr ).toMatch( message );
			expect( run.stderr.trim().split( '\n' ) ).toHaveLength( 1 );
			expect( run.code ).toBe( 2 );
			expect( run.stdout ).toBe( '' );

		}

	} );

} );
