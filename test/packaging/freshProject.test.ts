import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { spawnSync, type SpawnSyncReturns } from 'node:child_process';
import { readmeExampleModule } from './readmeExample.js';
import { viteBundle } from './viteBundle.js';

/*
 * The package as a user gets it: `npm run build`'s output (scripts/build.mjs, into a copy of the
 * package folder outside the repository), `npm pack`, and the tarball installed in a new project
 * with `three` and `@types/three` — what the README's install lines do. In that project: the
 * README's example type-checks with `tsc --strict` (and a wrong call does not), the main entry
 * loads in plain Node, `npx capture-lighting --help` and `inspect` run, and a Vite build of the
 * example's import keeps the CLI and the tools out. The tarball's sizes and the bundle's are
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

	it( 'the README\'s example type-checks with tsc --strict against the installed .d.ts (and @types/three), and a wrong call does not', () => {

		writeFileSync( join( app, 'example.ts' ), readmeExampleModule( ROOT ) );
		writeFileSync( join( app, 'wrong.ts' ), 'import { LightProbeVolume } from \'three-capture-lighting\';\nnew LightProbeVolume( { positions: \'0, 0, 0\' } );\n' );
		const compilerOptions = {
			strict: true, noEmit: true, target: 'ES2022', module: 'ESNext', moduleResolution: 'Bundler', lib: [ 'ES2022', 'DOM' ], types: [],
			skipLibCheck: false,
		};
		const tsc = resolve( ROOT, 'node_modules/typescript/bin/tsc' );
		writeFileSync( join( app, 'tsconfig.json' ), JSON.stringify( { compilerOptions, files: [ 'example.ts' ] } ) );
		expectOk( run( process.execPath, [ tsc, '-p', 'tsconfig.json' ], app ), 'tsc --strict on the README\'s example' );
		writeFileSync( join( app, 'tsconfig.wrong.json' ), JSON.stringify( { compilerOptions, files: [ 'wrong.ts' ] } ) );
		const wrong = run( process.execPath, [ tsc, '-p', 'tsconfig.wrong.json' ], app );
		expect( wrong.status ).not.toBe( 0 );
		expect( wrong.stdout ).toMatch( /wrong\.ts\(2,\d+\): error TS2322/ );

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

} );
