import { describe, expect, it } from 'vitest';
import { mkdirSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { viteBundle, type ViteBundle } from './viteBundle.js';

/*
 * What `import { LightProbeVolume } from 'three-capture-lighting'` costs a game built with Vite:
 * the modules Rollup keeps from a production build (minified, tree-shaken, three.js external —
 * the game ships three.js anyway), and that none of them belongs to the CLI, the placement tools,
 * the baked-file codec or the glTF plugins, which a game that captures at run time never calls.
 * The sizes are written to test/output/bundle-size.json (the README's figure comes from there).
 */

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );
const RUNTIME_ENTRY = 'import { LightProbeVolume } from \'three-capture-lighting\';\nconsole.log( LightProbeVolume );\n';

/** The baked-file codec's modules: encoder, decoder, their validation and the JSON form (src/io). */
const CODEC = [ 'encodeBakedVolume', 'decodeBakedVolume', 'validateBakedVolume', 'bakedVolumeJSON', 'checks', 'crc32', 'float16' ]
	.map( ( name ) => `src/io/${name}.ts` );

let runtime: Promise<ViteBundle> | null = null;
const runtimeBundle = () => ( runtime ??= viteBundle( ROOT, RUNTIME_ENTRY, { bundleThree: false, sideEffects: 'package.json' } ) );

describe( 'the runtime bundle: import { LightProbeVolume } from \'three-capture-lighting\' in a Vite production build', () => {

	it( 'holds LightProbeVolume and imports three.js instead of bundling it; sizes written to test/output/bundle-size.json', async () => {

		const bundle = await runtimeBundle();
		expect( bundle.modules ).toContain( 'src/runtime/LightProbeVolume.ts' );
		expect( bundle.modules.filter( ( id ) => id.includes( 'node_modules/three/' ) ) ).toEqual( [] );
		expect( bundle.imports ).toContain( 'three' );
		expect( bundle.code ).toContain( 'LightProbeVolume' ); // the class name survives minification (it names its errors)

		const withThree = await viteBundle( ROOT, RUNTIME_ENTRY, { bundleThree: true, sideEffects: 'package.json' } );
		expect( withThree.modules.some( ( id ) => id.includes( 'node_modules/three/' ) ) ).toBe( true );
		const sizes = {
			entry: RUNTIME_ENTRY.split( '\n' )[ 0 ],
			threeExternal: { bytes: bundle.bytes, gzipBytes: bundle.gzipBytes, modules: bundle.modules.length },
			withThree: { bytes: withThree.bytes, gzipBytes: withThree.gzipBytes, modules: withThree.modules.length },
			modules: bundle.modules,
		};
		mkdirSync( resolve( ROOT, 'test/output' ), { recursive: true } );
		writeFileSync( resolve( ROOT, 'test/output/bundle-size.json' ), JSON.stringify( sizes, null, '\t' ) + '\n' );
		console.log( `runtime bundle: ${bundle.bytes} B, ${bundle.gzipBytes} B gzip (three external); `
			+ `${withThree.bytes} B, ${withThree.gzipBytes} B gzip with three` );

	} );

	it( 'pulls in no module of the CLI (cli/), the placement tools (src/placement/) or the glTF plugins (src/gltf/)', async () => {

		const bundle = await runtimeBundle();
		expect( bundle.modules.filter( ( id ) => /^(cli\/|src\/placement\/|src\/gltf\/)/.test( id ) ) ).toEqual( [] );

	} );

	it( 'pulls in none of the baked-file codec (src/io encoder, decoder, validation, JSON)', async () => {

		const bundle = await runtimeBundle();
		const codec = bundle.modules.filter( ( id ) => CODEC.includes( id ) );
		expect(
			codec,
			'the codec is reached from LightProbeVolume: it stays in every game until toArrayBuffer/fromArrayBuffer/toJSON/fromJSON '
			+ 'leave the class for LightProbeVolumeExporter/LightProbeVolumeLoader (issue 13)',
		).toEqual( [] );

	} );

} );

describe( 'package.json "sideEffects": false is true to fact', () => {

	it( 'importing every entry for its side effects alone leaves nothing in the bundle when Rollup analyses the modules itself', async () => {

		// No claim: Rollup keeps every module-level statement it cannot prove free of side effects.
		// three.js is bundled so that Rollup can see into its constructors (module-level scratch
		// vectors and matrices are pure); an empty chunk means no module of the package needs to run.
		const entry = [ '', '/math', '/format', '/capture', '/lightProbeGrid' ].map( ( path ) => `import 'three-capture-lighting${path}';` ).join( '\n' );
		const bundle = await viteBundle( ROOT, entry, { bundleThree: true, sideEffects: 'analysed' } );
		expect( bundle.modules.filter( ( id ) => ! id.startsWith( '\0' ) ), bundle.code.slice( 0, 2000 ) ).toEqual( [] );
		expect( bundle.code.trim() ).toBe( '' );

	} );

	it( 'the analysis does keep a module-level statement with an effect (the check can fail)', async () => {

		const bundle = await viteBundle( ROOT, 'import { Vector3 } from \'three\';\nglobalThis.probe = new Vector3( 1, 2, 3 );\n',
			{ bundleThree: true, sideEffects: 'analysed' } );
		expect( bundle.code ).toContain( 'globalThis.probe' );

	} );

} );
