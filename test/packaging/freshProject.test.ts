import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { spawnSync, type SpawnSyncReturns } from 'node:child_process';
import type { Rollup } from 'vite';
import { readmeExampleModule } from './readmeExample.js';
import { FURNACE_RADIANCE, WRONG_WEBGPU, readmeWebGPUModule, readmeWebGPUPage } from './readmeWebGPU.js';
import { serveFolder } from './staticServer.js';
import { viteBundle } from './viteBundle.js';
import { checkChromium, launchChromium, resolveChromiumPath } from '../../cli/chromium.js';

/*
 * The package as a user gets it: `npm run build`'s output (scripts/build.mjs, into a copy of the
 * package folder outside the repository), `npm pack`, and the tarball installed in a new project
 * with `three` and `@types/three` — what the README's install lines do. In that project: the
 * README's example type-checks with `tsc --strict` (and a wrong call does not), the main entry
 * loads in plain Node, `npx capture-lighting --help` and `inspect` run, and a Vite build of the
 * example's import keeps the CLI and the tools out. The README's WebGPURenderer example too: it
 * type-checks, a Vite build of it as a page bundles `three-capture-lighting/webgpu` without the CLI,
 * and (with Chromium) the page runs it on the WebGL2 backend in a furnace room and reads the
 * character lit by the volume. The tarball's sizes and the bundle's are
 * written to test/output/fresh-project.json. Needs the npm registry (or its cache) for three,
 * @types/three and the package's two dependencies, and takes 40 s on an idle machine (a full build,
 * an install, tsc over all of @types/three) and minutes under load, so `npm test` skips it:
 * `npm run test:package` runs it.
 */

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );
const THREE_VERSION = JSON.parse( readFileSync( resolve( ROOT, 'node_modules/three/package.json' ), 'utf8' ) ).version;
const TYPES_VERSION = JSON.parse( readFileSync( resolve( ROOT, 'node_modules/@types/three/package.json' ), 'utf8' ) ).version;

interface PackedFile { path: string; size: number }
interface Packed { filename: string; size: number; unpackedSize: number; entryCount: number; files: PackedFile[] }

let work = '';
let packed: Packed;
let app = '';
let page = '';
let built = '';

function run( command: string, args: string[], cwd: string, timeout = 180_000 ): SpawnSyncReturns<string> {

	return spawnSync( command, args, { cwd, encoding: 'utf8', timeout, env: { ...process.env, npm_config_update_notifier: 'false' } } );

}

function expectOk( result: SpawnSyncReturns<string>, what: string ): void {

	expect( result.status, `${what} failed:\n${result.stdout}\n${result.stderr}${result.error ? '\n' + result.error.message : ''}` ).toBe( 0 );

}

const skipReason = process.env.CHECK_PACKAGE === '1' ? '' : 'run by npm run test:package (CHECK_PACKAGE=1)';

describe.skipIf( skipReason !== '' )( `a fresh project installs the packed package${skipReason ? ' — SKIPPED: ' + skipReason : ''}`, () => {

	beforeAll( () => {

		work = mkdtempSync( join( tmpdir(), 'three-capture-lighting-fresh-' ) );
		const folder = join( work, 'package' );
		mkdirSync( folder );
		for ( const name of [ 'package.json', 'README.md', 'LICENSE', 'docs' ] ) cpSync( resolve( ROOT, name ), join( folder, name ), { recursive: true } );
		expectOk( run( process.execPath, [ resolve( ROOT, 'scripts/build.mjs' ), '--out', join( folder, 'dist' ) ], ROOT ), 'scripts/build.mjs' );
		// --ignore-scripts: the copy has no scripts/ for package.json's prepack (the build just ran).
		const pack = run( 'npm', [ 'pack', folder, '--pack-destination', work, '--json', '--silent', '--ignore-scripts' ], work );
		expectOk( pack, 'npm pack' );
		packed = JSON.parse( pack.stdout )[ 0 ];

		app = join( work, 'app' );
		mkdirSync( app );
		writeFileSync( join( app, 'package.json' ), JSON.stringify( { name: 'fresh-app', private: true, type: 'module' } ) );
		expectOk( run( 'npm', [
			'install', '--prefer-offline', '--no-audit', '--no-fund', '--ignore-scripts',
			join( work, packed.filename ), `three@${THREE_VERSION}`, `@types/three@${TYPES_VERSION}`,
		], app ), 'npm install' );

	}, 300_000 );
	afterAll( () => { if ( work ) rmSync( work, { recursive: true, force: true } ); } );

	it( 'the tarball ships dist/ (each module once, no maps), the CLI with its prebuilt page, docs, README and LICENSE — no src/ or shaders/', () => {

		const paths = packed.files.map( ( file ) => file.path );
		for ( const path of [ 'package.json', 'README.md', 'LICENSE', 'dist/index.js', 'dist/index.d.ts', 'dist/cli/main.js', 'dist/cli/page/index.html' ] ) {

			expect( paths ).toContain( path );

		}

		expect( paths.filter( ( path ) => /^(src|shaders|dist\/src)\//.test( path ) || path.endsWith( '.map' ) || path.startsWith( 'docs/images/' ) ) ).toEqual( [] );
		expect( paths.filter( ( path ) => path.startsWith( 'dist/cli/' ) && ! path.startsWith( 'dist/cli/page/' ) && ! path.endsWith( '.js' ) ) ).toEqual( [] );
		// Every library module once: a CLI module reaching into src/ would have brought a second copy along.
		const libraryModules = paths.filter( ( path ) => path.startsWith( 'dist/' ) && ! path.startsWith( 'dist/cli/' ) && path.endsWith( '.js' ) );
		expect( libraryModules.length ).toBeGreaterThan( 50 );

	} );

	it( 'the README\'s examples (WebGLRenderer and WebGPURenderer) type-check with tsc --strict against the installed .d.ts (and @types/three), and wrong calls do not', () => {

		writeFileSync( join( app, 'example.ts' ), readmeExampleModule( ROOT ) );
		writeFileSync( join( app, 'webgpuExample.ts' ), readmeWebGPUModule( ROOT ) );
		writeFileSync( join( app, 'wrong.ts' ), 'import { LightProbeVolume } from \'three-capture-lighting\';\nnew LightProbeVolume( { positions: \'0, 0, 0\' } );\n' );
		writeFileSync( join( app, 'wrongWebGPU.ts' ), WRONG_WEBGPU );
		const compilerOptions = {
			strict: true, noEmit: true, target: 'ES2022', module: 'ESNext', moduleResolution: 'Bundler', lib: [ 'ES2022', 'DOM' ], types: [],
			skipLibCheck: false,
		};
		const tsc = resolve( ROOT, 'node_modules/typescript/bin/tsc' );
		// One tsc run per verdict: each reads all of @types/three, the slow part.
		writeFileSync( join( app, 'tsconfig.json' ), JSON.stringify( { compilerOptions, files: [ 'example.ts', 'webgpuExample.ts' ] } ) );
		expectOk( run( process.execPath, [ tsc, '-p', 'tsconfig.json' ], app ), 'tsc --strict on the README\'s examples' );
		writeFileSync( join( app, 'tsconfig.wrong.json' ), JSON.stringify( { compilerOptions, files: [ 'wrong.ts', 'wrongWebGPU.ts' ] } ) );
		const wrong = run( process.execPath, [ tsc, '-p', 'tsconfig.wrong.json' ], app );
		expect( wrong.status ).not.toBe( 0 );
		expect( wrong.stdout ).toMatch( /wrong\.ts\(2,\d+\): error TS2322/ );
		expect( wrong.stdout ).toMatch( /wrongWebGPU\.ts\(4,\d+\): error TS2345/ );
		expect( wrong.stdout.match( /error TS/g ) ).toHaveLength( 2 );

	} );

	it( 'the main entry loads in plain Node, and npx capture-lighting --help and inspect run from the installed package', () => {

		const script = [
			'import { writeFileSync } from \'node:fs\';',
			'import { LightProbeVolume } from \'three-capture-lighting\';',
			'import { encodeBakedVolume } from \'three-capture-lighting/format\';',
			'const volume = new LightProbeVolume( { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1 ], sh: new Float32Array( 135 ).fill( 0.25 ) } );',
			'writeFileSync( \'volume.bin\', new Uint8Array( encodeBakedVolume( volume.toBakedData() ) ) );',
			'console.log( volume.count );',
		].join( '\n' );
		writeFileSync( join( app, 'write.mjs' ), script );
		const write = run( process.execPath, [ 'write.mjs' ], app );
		expectOk( write, 'node write.mjs' );
		expect( write.stdout.trim() ).toBe( '5' );

		const help = run( 'npx', [ '--no-install', 'capture-lighting', '--help' ], app );
		expectOk( help, 'npx capture-lighting --help' );
		expect( help.stdout ).toMatch( /^Usage:\n {2}capture-lighting bake / );
		const inspect = run( 'npx', [ '--no-install', 'capture-lighting', 'inspect', 'volume.bin' ], app );
		expectOk( inspect, 'npx capture-lighting inspect volume.bin' );
		expect( inspect.stdout ).toMatch( /\b5\b/ );

	} );

	it( 'a Vite build of import { LightProbeVolume } from the installed package has no CLI, placement or glTF module; sizes in test/output/fresh-project.json', async () => {

		const entry = 'import { LightProbeVolume } from \'three-capture-lighting\';\nconsole.log( LightProbeVolume );\n';
		const bundle = await viteBundle( app, entry, { bundleThree: false, sideEffects: 'installed' } );
		const ours = bundle.modules.filter( ( id ) => id.includes( 'node_modules/three-capture-lighting/' ) );
		expect( ours.some( ( id ) => id.endsWith( 'dist/runtime/LightProbeVolume.js' ) ) ).toBe( true );
		expect( ours.filter( ( id ) => /dist\/(cli|placement|gltf)\//.test( id ) ) ).toEqual( [] );
		expect( bundle.imports ).toContain( 'three' );
		mkdirSync( resolve( ROOT, 'test/output' ), { recursive: true } );
		writeFileSync( resolve( ROOT, 'test/output/fresh-project.json' ), JSON.stringify( {
			tarball: { size: packed.size, unpackedSize: packed.unpackedSize, files: packed.entryCount },
			bundle: { entry: entry.split( '\n' )[ 0 ], threeExternal: true, bytes: bundle.bytes, gzipBytes: bundle.gzipBytes, modules: ours.length },
		}, null, '\t' ) + '\n' );

	} );

	it( 'a Vite build of the README\'s WebGPURenderer example as a page bundles three-capture-lighting/webgpu and three/webgpu, with no CLI or puppeteer module', async () => {

		page = join( app, 'webgpu-page' );
		mkdirSync( page, { recursive: true } );
		writeFileSync( join( page, 'index.html' ), '<!doctype html>\n<meta charset="utf-8">\n<script type="module" src="./main.js"></script>\n' );
		writeFileSync( join( page, 'main.js' ), readmeWebGPUPage( ROOT ) );
		const { build } = await import( 'vite' );
		const output = await build( {
			configFile: false, root: page, logLevel: 'silent',
			build: { outDir: join( page, 'dist' ), emptyOutDir: true, reportCompressedSize: false, chunkSizeWarningLimit: 4096 },
		} ) as Rollup.RollupOutput | Rollup.RollupOutput[];
		const chunks = ( Array.isArray( output ) ? output : [ output ] ).flatMap( ( o ) => o.output ).filter( ( o ): o is Rollup.OutputChunk => o.type === 'chunk' );
		const modules = chunks.flatMap( ( chunk ) => Object.entries( chunk.modules ).filter( ( [ , m ] ) => m.renderedLength > 0 ).map( ( [ id ] ) => id.split( sep ).join( '/' ) ) );
		const ours = modules.filter( ( id ) => id.includes( 'node_modules/three-capture-lighting/' ) );
		expect( ours.some( ( id ) => id.endsWith( 'dist/webgpu/installShading.js' ) ), 'the entry\'s shading installer' ).toBe( true );
		expect( ours.some( ( id ) => id.endsWith( 'dist/webgpu/installCapture.js' ) ), 'the entry\'s capture installer' ).toBe( true );
		expect( modules.some( ( id ) => id.includes( 'node_modules/three/build/three.webgpu.js' ) ) ).toBe( true );
		expect( ours.filter( ( id ) => /dist\/cli\//.test( id ) ) ).toEqual( [] );
		expect( modules.filter( ( id ) => id.includes( 'puppeteer' ) ) ).toEqual( [] );
		built = join( page, 'dist' );

	}, 300_000 );

	const chromium = resolveChromiumPath();
	const noChromium = checkChromium( chromium.path, chromium.source );
	it.skipIf( noChromium !== '' )( `the built page runs the README's WebGPURenderer example on the WebGL2 backend: the sphere added with volume.add() shows the furnace's radiance${noChromium ? ' — SKIPPED: ' + noChromium : ''}`, async () => {

		expect( built, 'the Vite build above' ).not.toBe( '' );
		const server = await serveFolder( built );
		const browser = await launchChromium( { browser: chromium.path, webgpu: true } );
		try {

			const tab = await browser.newPage();
			const errors: string[] = [];
			tab.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
			tab.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( message.text() ); } );
			await tab.goto( server.url + '?backend=webgl2', { waitUntil: 'load', timeout: 120_000 } );
			await tab.waitForFunction( 'window.result', { timeout: 240_000 } );
			const result = await tab.evaluate( 'window.result' ) as { error?: string; backend: string; frames: number; lighting: string; sphere: number[]; wall: number[]; unlit: number[] };
			expect( result.error ).toBeUndefined();
			expect( errors ).toEqual( [] );
			expect( result.backend ).toBe( 'webgl2' );
			expect( result.frames ).toBeGreaterThanOrEqual( 5 );
			expect( result.lighting ).toBe( 'dynamic' );
			// A white Lambertian surface inside a closed room of uniform radiance L reflects L (E = πL,
			// out = E / π): no light in the scene, so all of it is the volume's. Removed, it is black.
			for ( const c of [ 0, 1, 2 ] ) {

				expect( result.wall[ c ] ).toBeCloseTo( FURNACE_RADIANCE, 2 );
				expect( Math.abs( result.sphere[ c ] - FURNACE_RADIANCE ), `sphere ${result.sphere}` ).toBeLessThan( 2 / 255 );
				expect( result.unlit[ c ] ).toBeLessThan( 1 / 255 );

			}

		} finally {

			await browser.close();
			await server.close();

		}

	}, 300_000 );

} );
