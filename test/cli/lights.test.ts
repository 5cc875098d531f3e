import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { checkChromium, resolveChromiumPath } from '../../cli/chromium.js';
import { decodeBakedVolume } from '../../src/io/index.js';
import { makeIrradianceNonNegative, windowSH } from '../../src/sh/windowSH.js';
import {
	CORNELL_LAMP, CORNELL_LAMP_FLAG, CORNELL_PROBES, runCli, writeCornellGLB, writeCornellOBJ, writeLayout, type CliRun,
} from './fixtures.js';

// capture-lighting bake end to end (headless Chromium, SwiftShader) on scenes/basic.ts's room:
// lights from flags, from the layout and from a glTF file, the warnings and --strict, and the SH
// post-processing. Small bakes: 7 probes at 8² (16² where a small emitter must cover texels).
const CHROMIUM = resolveChromiumPath();
const missing = checkChromium( CHROMIUM.path, CHROMIUM.source );
const skipReason = missing ? `${missing} The CLI light tests are skipped.` : '';
if ( skipReason ) console.warn( skipReason );
const ENV = { CHROME_PATH: CHROMIUM.path };

// Probe indices of CORNELL_PROBES.
const BY_RED = 0, BY_GREEN = 1, BY_BLUE = 2;

let dir = '';
let layout = '';
beforeAll( () => {

	dir = mkdtempSync( join( tmpdir(), 'capture-lighting-lights-' ) );
	layout = writeLayout( dir, 'cornell.json', CORNELL_PROBES );

} );
afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

type BakeRun = CliRun & { sh: Float32Array; metadata: Record<string, unknown> };

/** Runs the CLI's bake and reads the file it wrote (empty SH when there is none). */
function bake( scene: string, out: string, args: string[], probes = layout ): BakeRun {

	const run = runCli( [ 'bake', scene, '--probes', probes, '--out', out, ...args ], ENV );
	const file = existsSync( out ) ? decodeBakedVolume( readFileSync( out ) ) : null;
	return { ...run, sh: file?.sh ?? new Float32Array( 0 ), metadata: file ? JSON.parse( file.metadata ) : {} };

}

const row = ( text: string, label: string ) => new RegExp( `^  ${label} +(.*)$`, 'm' ).exec( text )?.[ 1 ];

/** L00 of a probe's channel, and its L1 x coefficient (three's order: index 3 is x) over its L00. */
const l00 = ( sh: Float32Array, probe: number, channel: number ) => sh[ 27 * probe + channel ];
const l1x = ( sh: Float32Array, probe: number, channel: number ) => sh[ 27 * probe + 9 + channel ] / l00( sh, probe, channel );

/**
 * Colour bleeding in the Basic room, from the walls' colours alone: by the red wall (−x) the
 * light is redder than by the green wall (+x) and the other way round, by the blue wall bluer than
 * by either; at the probe by the red wall, red comes more from −x than green does (its L1x over
 * L00 is lower), and at the probe by the green wall, green comes more from +x.
 */
function expectBleeding( sh: Float32Array ): void {

	const ratio = ( probe: number, a: number, b: number ) => l00( sh, probe, a ) / l00( sh, probe, b );
	expect( ratio( BY_RED, 0, 1 ) ).toBeGreaterThan( 1.2 * ratio( BY_GREEN, 0, 1 ) );
	expect( ratio( BY_GREEN, 1, 0 ) ).toBeGreaterThan( 1.2 * ratio( BY_RED, 1, 0 ) );
	expect( ratio( BY_BLUE, 2, 0 ) ).toBeGreaterThan( 1.2 * Math.max( ratio( BY_RED, 2, 0 ), ratio( BY_GREEN, 2, 0 ) ) );
	expect( l1x( sh, BY_RED, 0 ) ).toBeLessThan( l1x( sh, BY_RED, 1 ) );
	expect( l1x( sh, BY_GREEN, 1 ) ).toBeGreaterThan( l1x( sh, BY_GREEN, 0 ) );

}

/** Every probe lit in every channel (the room's darkest corner gets well above 0.1 from the 12 cd lamp). */
function expectLit( sh: Float32Array ): void {

	for ( let probe = 0; probe < sh.length / 27; probe ++ ) {

		for ( let c = 0; c < 3; c ++ ) expect( l00( sh, probe, c ), `probe ${probe} channel ${c}` ).toBeGreaterThan( 0.1 );

	}

}

describe.skipIf( skipReason !== '' )( 'capture-lighting bake: lights (headless Chromium)', () => {

	let fromFlag: Float32Array;

	it( 'the Basic room as OBJ + MTL with --point under the lamp, --strict: exit 0, no warning, "1 point light (flags)", lit, colour bleeding', () => {

		const scene = writeCornellOBJ( dir, { mtl: true } );
		const run = bake( scene, join( dir, 'flag.bin' ), [ '--resolution', '8', '--point', CORNELL_LAMP_FLAG, '--strict' ] );
		expect( run.code, run.stderr ).toBe( 0 );
		expect( run.stderr ).not.toContain( 'warning:' );
		expect( row( run.stdout, 'lights' ) ).toBe( '1 point light (flags); no emissive materials' );
		expect( row( run.stdout, 'shadows' ) ).toBe( '1 light, 12 meshes cast and receive (1024² maps, bias -0.0005, directional cameras fitted, shadow sides as given)' );
		expect( run.metadata.lights ).toEqual( [ { type: 'point', position: CORNELL_LAMP.position, intensity: 12, color: 0xfff2e0, distance: 0, decay: 2, source: 'flags' } ] );
		expectLit( run.sh );
		expectBleeding( run.sh );
		fromFlag = run.sh;

	} );

	it( 'the same light in the layout file gives the same SH, bit for bit; the summary says "(layout)"', () => {

		const scene = writeCornellOBJ( dir, { mtl: true } );
		const withLights = writeLayout( dir, 'cornell-lights.json', {
			...CORNELL_PROBES, lights: [ { type: 'point', position: CORNELL_LAMP.position, intensity: CORNELL_LAMP.intensity, color: '#fff2e0' } ],
		} );
		const run = bake( scene, join( dir, 'layout.bin' ), [ '--resolution', '8' ], withLights );
		expect( run.code, run.stderr ).toBe( 0 );
		expect( row( run.stdout, 'lights' ) ).toBe( '1 point light (layout); no emissive materials' );
		expect( Array.from( run.sh ) ).toEqual( Array.from( fromFlag ) );

	} );

	it( 'without an MTL (vertex colours, OBJLoader\'s default material): the same bleeding, and the MTL bake\'s SH within 1e-4 of L00', () => {

		// Both are MeshPhongMaterials with three's defaults; Kd and the vertex colours are the same
		// sRGB values, converted by the same ColorManagement call. Only where the colour enters the
		// shader differs (a uniform or an interpolated attribute): float rounding at most (measured: 0).
		const scene = writeCornellOBJ( dir, { mtl: false } );
		const run = bake( scene, join( dir, 'vc.bin' ), [ '--resolution', '8', '--point', CORNELL_LAMP_FLAG ] );
		expect( run.code, run.stderr ).toBe( 0 );
		expectBleeding( run.sh );
		for ( let i = 0; i < run.sh.length; i ++ ) {

			const scale = l00( fromFlag, Math.floor( i / 27 ), i % 3 );
			expect( Math.abs( run.sh[ i ] - fromFlag[ i ] ) / scale, `coefficient ${i}` ).toBeLessThan( 1e-4 );

		}

	} );

	it( 'the room as glTF: its KHR_lights_punctual point light and emissive panel are used — "1 point light (file); 1 emissive material"', () => {

		const scene = writeCornellGLB( dir );
		const run = bake( scene, join( dir, 'glb.bin' ), [ '--resolution', '8', '--quiet' ] );
		expect( run.code, run.stderr ).toBe( 0 );
		expect( run.stderr ).toBe( '' );
		expect( run.metadata.sceneLights ).toBe( '1 point light (file); 1 emissive material' );
		expectLit( run.sh );
		expectBleeding( run.sh );

	} );

	it( '--spot aimed at the red wall lights it; a layout sun above the closed room is shadowed by it, and leaks in with --no-shadows', () => {

		// The spot (30 cd, 25° half angle) from under the ceiling's centre at the red wall's middle:
		// the probe by the red wall sees a lit red patch, the one by the green wall only its bounce.
		const scene = writeCornellOBJ( dir, { mtl: true } );
		const spot = bake( scene, join( dir, 'spot.bin' ), [ '--resolution', '8', '--spot', '0,2.9,0,-2,1.5,0,30,#ffffff,25' ] );
		expect( spot.code, spot.stderr ).toBe( 0 );
		expect( row( spot.stdout, 'lights' ) ).toBe( '1 spot light (flags); no emissive materials' );
		expect( l00( spot.sh, BY_RED, 0 ) ).toBeGreaterThan( 2 * l00( spot.sh, BY_GREEN, 0 ) );

		// The sun shines from above and a little +z onto the room's outside. Without shadows it lights
		// the floor and walls inside (L00 0.19–0.63); with them, what gets in through the seams of the
		// single-sided quads is at most 0.96 % of that (measured), and five probes stay black.
		const withSun = writeLayout( dir, 'cornell-sun.json', {
			...CORNELL_PROBES, lights: [ { type: 'directional', direction: [ 0, 1, 0.2 ], intensity: 5 } ],
		} );
		const shadowed = bake( scene, join( dir, 'sun.bin' ), [ '--resolution', '8' ], withSun );
		expect( shadowed.code, shadowed.stderr ).toBe( 0 );
		expect( row( shadowed.stdout, 'lights' ) ).toBe( '1 directional light (layout); no emissive materials' );
		expect( shadowed.stderr ).toMatch( /^warning: 5 of 7 probes are black/m );
		const leaking = bake( scene, join( dir, 'sun-leak.bin' ), [ '--resolution', '8', '--no-shadows' ], withSun );
		expect( leaking.code, leaking.stderr ).toBe( 0 );
		expect( row( leaking.stdout, 'shadows' ) ).toBe( 'off (--no-shadows; 0 lights cast shadows as the file says)' );
		for ( let probe = 0; probe < 7; probe ++ ) {

			for ( let c = 0; c < 3; c ++ ) {

				expect( l00( leaking.sh, probe, c ) ).toBeGreaterThan( 0.1 );
				expect( l00( shadowed.sh, probe, c ), `probe ${probe} channel ${c}` ).toBeLessThan( 0.02 * l00( leaking.sh, probe, c ) );

			}

		}

	} );

	it( 'no light at all: the warning is printed (also with --quiet); --strict exits 1 and writes nothing', () => {

		const scene = writeCornellOBJ( dir, { mtl: true } );
		const out = join( dir, 'dark.bin' );
		const quiet = bake( scene, out, [ '--resolution', '8', '--quiet' ] );
		expect( quiet.code, quiet.stderr ).toBe( 0 );
		expect( quiet.stdout ).toBe( '' );
		expect( quiet.stderr ).toMatch( /^warning: the scene has no lights, no emissive materials and no --sky, so 7 of 7 probes are black/ );
		expect( Array.from( quiet.sh ).every( ( v ) => v === 0 ) ).toBe( true );
		rmSync( out );

		const strict = bake( scene, out, [ '--resolution', '8', '--strict' ] );
		expect( strict.stderr ).toMatch( /^warning: the scene has no lights/m );
		expect( strict.stderr ).toMatch( /^capture-lighting: 1 warning \(see above\) and --strict was given; .*dark\.bin was not written\.$/m );
		expect( strict.code ).toBe( 1 );
		expect( existsSync( out ) ).toBe( false );

	} );

	it( '--deringing and --non-negative change the SH exactly as windowSH and makeIrradianceNonNegative do, and are stored in the metadata', () => {

		// A dark room lit only by a 0.4 m panel of Ke 4 under the ceiling: its ring makes every
		// probe's irradiance negative somewhere (the warning says so), which --non-negative removes.
		const scene = writeCornellOBJ( dir, { mtl: true, emitter: 4 } );
		const args = [ '--resolution', '16' ];
		const plain = bake( scene, join( dir, 'ring.bin' ), args );
		expect( plain.code, plain.stderr ).toBe( 0 );
		expect( plain.stderr ).toMatch( /^warning: 7 of 7 probes have negative irradiance/m );
		expect( row( plain.stdout, 'SH' ) ).toBe( 'as captured (no --deringing, no --non-negative)' );

		const deringed = bake( scene, join( dir, 'ring-window.bin' ), [ ...args, '--deringing', '0.2' ] );
		expect( deringed.code, deringed.stderr ).toBe( 0 );
		expect( Array.from( deringed.sh ) ).toEqual( Array.from( windowSH( plain.sh, 0.2 ) ) );
		expect( deringed.metadata ).toMatchObject( { deringing: 0.2, nonNegative: false } );

		const nonNegative = bake( scene, join( dir, 'ring-positive.bin' ), [ ...args, '--non-negative' ] );
		expect( nonNegative.code, nonNegative.stderr ).toBe( 0 );
		expect( nonNegative.stderr ).not.toContain( 'negative irradiance' );
		const expected = Float32Array.from( plain.sh );
		expect( makeIrradianceNonNegative( expected ) ).toBe( 7 );
		expect( Array.from( nonNegative.sh ) ).toEqual( Array.from( expected ) );
		expect( row( nonNegative.stdout, 'SH' ) ).toBe( 'non-negative (7 probes windowed more)' );
		expect( nonNegative.metadata ).toMatchObject( { deringing: 0, nonNegative: true } );

	} );

} );
