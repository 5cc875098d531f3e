import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { bakedVolumeFromJSON, decodeBakedVolume } from '../../src/io/index.js';
import { checkChromium, resolveChromiumPath } from '../../cli/chromium.js';
import { ROOM_PROBES, ROOT, runCli, writeConstantHDR, writeEmptyGLTF, writeLayout, writeLitFloorGLTF, writeRoom } from './fixtures.js';

// End to end in headless Chromium (SwiftShader): few, small bakes at 8² and 16².
const CHROMIUM = resolveChromiumPath();
const missing = checkChromium( CHROMIUM.path, CHROMIUM.source );
const skipReason = missing ? `${missing} The CLI bake tests are skipped.` : '';
if ( skipReason ) console.warn( skipReason );
const ENV = { CHROME_PATH: CHROMIUM.path };

/** three's Y00 basis constant (SphericalHarmonics3). */
const Y00 = 0.282095;

/** sRGB → linear (what `Color.setRGB( …, SRGBColorSpace )` does to a --sky colour). */
const linear = ( c: number ) => c <= 0.04045 ? c / 12.92 : ( ( c + 0.055 ) / 1.055 ) ** 2.4;

let dir = '';

beforeAll( () => {

	dir = mkdtempSync( join( tmpdir(), 'capture-lighting-bake-' ) );

} );

afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

describe.skipIf( skipReason !== '' )( 'capture-lighting bake (headless Chromium)', () => {

	it( 'OBJ room with a red wall: exit 0, summary table, progress on stderr; inspect agrees; the probe by the red wall is redder', () => {

		const room = writeRoom( dir );
		const layout = writeLayout( dir, 'room.json', ROOM_PROBES );
		const out = join( dir, 'room.bin' );
		const run = runCli( [ 'bake', room, '--probes', layout, '--out', out, '--resolution', '8', '--ambient', '1' ], ENV );
		expect( run.code, run.stderr ).toBe( 0 );

		const expectedTetrahedra = tetrahedralize( ROOM_PROBES.positions ).tetrahedra.length / 4;
		const row = ( text: string, label: string ) => new RegExp( `^  ${label} +(.*)$`, 'm' ).exec( text )?.[ 1 ];
		expect( row( run.stdout, 'probes' ) ).toBe( '10' );
		expect( row( run.stdout, 'tetrahedra' ) ).toBe( String( expectedTetrahedra ) );
		expect( row( run.stdout, 'resolution' ) ).toBe( '8² per cube face' );
		expect( row( run.stdout, 'output' ) ).toBe( `${out} (bin, SH float32)` ); // the API's default precision
		expect( row( run.stdout, 'lights' ) ).toBe( '1 ambient light (flags); 1 emissive material' );
		expect( row( run.stdout, 'capture time' ) ).toMatch( /^\d+(\.\d)? m?s / );
		expect( row( run.stdout, 'size on disk' ) ).toContain( `${statSync( out ).size.toLocaleString( 'en-US' )} bytes` );
		// Not a terminal: progress as lines, the last one complete.
		expect( run.stderr ).toMatch( /^capturing 10 probes at 8²: 10\/10 100% [\d.]+ s$/m );
		expect( run.stderr ).not.toContain( '\r' );

		const inspected = runCli( [ 'inspect', out ] );
		expect( inspected.code, inspected.stderr ).toBe( 0 );
		expect( row( inspected.stdout, 'probes' ) ).toBe( '10' );
		expect( row( inspected.stdout, 'tetrahedra' ) ).toBe( String( expectedTetrahedra ) );
		expect( row( inspected.stdout, 'roles' ) ).toBe( 'bounce 4, fill 4, bleed 2' );
		expect( row( inspected.stdout, 'SH precision' ) ).toBe( 'float32' );
		expect( row( inspected.stdout, 'capture' ) ).toBe( 'resolution 8, near 0.05, far 1000, type half, solidAngle exact' );

		const volume = decodeBakedVolume( readFileSync( out ) );
		expect( Array.from( volume.positions ) ).toEqual( ROOM_PROBES.positions );
		expect( volume.names ).toEqual( ROOM_PROBES.names );
		// Probe 8 is 0.3 from the red wall (Kd 0.8, 0.05, 0.05), probe 9 as close to the white one
		// (Kd 0.8 everywhere) and the room is otherwise mirror-symmetric: red light is the same for
		// both, green much less by the red wall (the red wall fills half its view, a few % of 9's).
		const l00 = ( probe: number, channel: number ) => volume.sh[ 27 * probe + channel ];
		expect( l00( 8, 1 ) ).toBeGreaterThan( 0.1 ); // lit at all
		expect( l00( 8, 0 ) ).toBeCloseTo( l00( 9, 0 ), 2 );
		expect( l00( 8, 0 ) / l00( 8, 1 ) ).toBeGreaterThan( 1.15 * l00( 9, 0 ) / l00( 9, 1 ) );
		// The L1 x coefficient (index 3, x): red arrives from −x at probe 8, so its red-minus-green L1x is
		// negative there (more red from −x than from +x).
		expect( volume.sh[ 27 * 8 + 9 ] - volume.sh[ 27 * 8 + 10 ] ).toBeLessThan( 0 );

	} );

	it( 'empty glTF with --sky #808080 (JSON out): every probe sees constant radiance c = linear(128/255), L00 = 4π·0.282095·c, the rest 0', () => {

		const scene = writeEmptyGLTF( dir );
		const layout = writeLayout( dir, 'sky.json', { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, - 3, 2, 5 ] } );
		const out = join( dir, 'sky.json.out.json' );
		const run = runCli( [ 'bake', scene, '--probes', layout, '--out', out, '--resolution', '8', '--sky', '#808080', '--quiet' ], ENV );
		expect( run.code, run.stderr ).toBe( 0 );
		expect( run.stdout ).toBe( '' );
		expect( run.stderr ).toBe( '' );
		const volume = bakedVolumeFromJSON( readFileSync( out, 'utf8' ) );
		// Same constant as test/sh/projectCubeMapToSH.test.ts ("constant radiance c"); the exact
		// texel weights sum to 4π, so only the half-float capture (2⁻¹¹ relative) is off.
		const expected = 4 * Math.PI * Y00 * linear( 128 / 255 );
		for ( let probe = 0; probe < 6; probe ++ ) {

			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( volume.sh[ 27 * probe + c ] / expected - 1 ) ).toBeLessThan( 1e-3 );
			for ( let i = 3; i < 27; i ++ ) expect( Math.abs( volume.sh[ 27 * probe + i ] ) ).toBeLessThan( 1e-4 * expected );

		}

	} );

	it( 'empty glTF with a constant --sky .hdr panorama (its name has a space): L00 = 4π·0.282095·L', () => {

		const scene = writeEmptyGLTF( dir );
		const { file, radiance } = writeConstantHDR( dir );
		const layout = writeLayout( dir, 'hdr-probes.json', { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] } );
		const out = join( dir, 'hdr.bin' );
		const run = runCli( [ 'bake', scene, '--probes', layout, '--out', out, '--resolution', '8', '--sky', file, '--precision', 'float32', '--quiet' ], ENV );
		expect( run.code, run.stderr ).toBe( 0 );
		const volume = decodeBakedVolume( readFileSync( out ) );
		// The panorama is turned into a half-float cube map and captured in half floats: 2 × 2⁻¹¹.
		const expected = 4 * Math.PI * Y00 * radiance;
		for ( let probe = 0; probe < 4; probe ++ ) {

			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( volume.sh[ 27 * probe + c ] / expected - 1 ) ).toBeLessThan( 1.5e-3 );
			for ( let i = 3; i < 27; i ++ ) expect( Math.abs( volume.sh[ 27 * probe + i ] ) ).toBeLessThan( 1e-3 * expected );

		}

	} );

	it( 'glTF floor lit by a KHR_lights_punctual directional light (32², float32): L00 above the floor ≈ (3/π)·0.282095·Ω(floor), light from below', () => {

		const scene = writeLitFloorGLTF( dir );
		const layout = writeLayout( dir, 'floor-probes.json', { positions: [ 0, 1, 0, 1, 1, 1, - 1, 2, 0, 0, 1.5, - 1, 0.5, 3, 0.5 ] } );
		const out = join( dir, 'floor-volume.bin' );
		const run = runCli( [ 'bake', scene, '--probes', layout, '--out', out, '--resolution', '32', '--precision', 'float32', '--quiet' ], ENV );
		expect( run.code, run.stderr ).toBe( 0 );
		const volume = decodeBakedVolume( readFileSync( out ) );
		// A white Lambert floor under 3 lux of light straight down has radiance 3/π; from height h
		// above its centre, the 10 × 10 floor covers Ω = 4·asin( 25 / ( 25 + h² ) ).
		// MeshStandardMaterial scales its diffuse by ( 1 − F ) (F0 = 0.04) and adds a little
		// rough specular, so the capture lies a few % below pure Lambert: −1.4 % measured at 32² and
		// at 64² alike. (At 16² the floor's edge, 11° below the horizon, falls between texel rows
		// and L00 is 7.7 % low: a quadrature error, hence 32² here.)
		const omega = 4 * Math.asin( 25 / ( 25 + 1 ) );
		const lambert = 3 / Math.PI * Y00 * omega;
		const ratio = volume.sh[ 0 ] / lambert;
		expect( ratio ).toBeGreaterThan( 0.95 );
		expect( ratio ).toBeLessThan( 1.01 );
		for ( let probe = 0; probe < 5; probe ++ ) {

			expect( volume.sh[ 27 * probe ] ).toBeGreaterThan( 0.5 );
			// L1 y (coefficient 1): the light comes from the floor, below.
			expect( volume.sh[ 27 * probe + 3 ] ).toBeLessThan( - 0.3 * volume.sh[ 27 * probe ] );

		}

		// --sun 0,1,0,3 adds a second light equal to the glTF's (3, straight down): twice the light.
		const sunOut = join( dir, 'floor-sun.bin' );
		const sunRun = runCli( [ 'bake', scene, '--probes', layout, '--out', sunOut, '--resolution', '32', '--precision', 'float32', '--quiet', '--sun', '0,1,0,3' ], ENV );
		expect( sunRun.code, sunRun.stderr ).toBe( 0 );
		const sun = decodeBakedVolume( readFileSync( sunOut ) );
		for ( let i = 0; i < sun.sh.length; i ++ ) expect( sun.sh[ i ] ).toBeCloseTo( 2 * volume.sh[ i ], 2 );

	} );

	it( 'an OBJ of binary garbage (no triangles) or with a NaN vertex is bad input: exit 2, one line naming the file, no output', () => {

		const layout = writeLayout( dir, 'garbage-probes.json', { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] } );
		const garbage = join( dir, 'garbage.obj' );
		writeFileSync( garbage, Buffer.from( Array.from( { length: 4096 }, ( _, i ) => ( i * 7919 + 13 ) % 256 ) ) );
		const nanVertex = join( dir, 'nan-vertex.obj' );
		writeFileSync( nanVertex, 'v 0 0 0\nv 1 0 0\nv 0 NaN 1\nf 1 2 3\n' );
		for ( const [ scene, message ] of [
			[ garbage, /^capture-lighting: scene .*garbage\.obj has no triangles \(0 meshes\) and no --sky is given/ ],
			[ nanVertex, /^capture-lighting: scene .*nan-vertex\.obj has 1 vertices with a NaN or infinite coordinate/ ],
		] as const ) {

			const out = join( dir, 'garbage.bin' );
			const run = runCli( [ 'bake', scene, '--probes', layout, '--out', out, '--resolution', '8', '--quiet' ], ENV );
			expect( run.stderr ).toMatch( message );
			expect( run.stderr.trim().split( '\n' ) ).toHaveLength( 1 );
			expect( run.code ).toBe( 2 );
			expect( existsSync( out ) ).toBe( false );

		}

	} );

	it( 'a scene the browser cannot load exits 1 with the loader\'s message', () => {

		const broken = join( dir, 'broken.glb' );
		writeFileSync( broken, Buffer.concat( [ Buffer.from( 'glTF' ), Buffer.alloc( 16, 0xff ) ] ) );
		const layout = writeLayout( dir, 'broken-probes.json', { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] } );
		const run = runCli( [ 'bake', broken, '--probes', layout, '--out', join( dir, 'broken.bin' ), '--resolution', '8', '--quiet' ], ENV );
		expect( run.stderr ).toMatch( /^capture-lighting: the capture failed in Chromium: .+/ );
		expect( run.code ).toBe( 1 );
		expect( existsSync( join( dir, 'broken.bin' ) ) ).toBe( false );

	} );

} );

describe.skipIf( skipReason !== '' )( 'capture-lighting as an installed package runs it: compiled to JS, the bake page prebuilt and served as plain files (no Vite at bake time)', () => {

	// What `npm run build` makes, written under test/output so that `three` and puppeteer-core
	// resolve from the repository's node_modules, as from a package's.
	const out = join( ROOT, 'test/output/cli-dist' );

	it( 'builds, bakes the red-wall room from the compiled CLI, and gives the same SH as the CLI run from source', () => {

		rmSync( out, { recursive: true, force: true } );
		// The package's own build (library modules once, the CLI pointing at them, the prebuilt page).
		const build = spawnSync( process.execPath, [ 'scripts/build.mjs', '--out', out ], { cwd: ROOT, encoding: 'utf8' } );
		expect( build.status, build.stdout + build.stderr ).toBe( 0 );
		expect( existsSync( join( out, 'src' ) ), 'no second copy of the library under the CLI' ).toBe( false );

		const room = writeRoom( dir );
		const layout = writeLayout( dir, 'room-built.json', ROOM_PROBES );
		const fromSource = join( dir, 'room-source.bin' ), fromBuild = join( dir, 'room-built.bin' );
		const args = [ '--probes', layout, '--resolution', '8', '--precision', 'float32', '--ambient', '1', '--quiet' ];
		const source = runCli( [ 'bake', room, '--out', fromSource, ...args ], ENV );
		expect( source.code, source.stderr ).toBe( 0 );
		const built = spawnSync( process.execPath, [ join( out, 'cli/main.js' ), 'bake', room, '--out', fromBuild, ...args ], { cwd: dir, encoding: 'utf8', env: { ...process.env, ...ENV }, timeout: 120_000 } );
		expect( built.status, built.stderr ).toBe( 0 );
		const a = decodeBakedVolume( readFileSync( fromSource ) ), b = decodeBakedVolume( readFileSync( fromBuild ) );
		expect( b.sh.length ).toBe( a.sh.length );
		for ( let i = 0; i < a.sh.length; i ++ ) expect( b.sh[ i ] ).toBeCloseTo( a.sh[ i ], 5 );

	} );

} );
