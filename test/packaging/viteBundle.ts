import { gzipSync } from 'node:zlib';
import { readFileSync } from 'node:fs';
import { resolve, sep } from 'node:path';
import type { Rollup } from 'vite';
import { libraryAliases } from '../../cli/libraryAliases.js';

/** What a production Vite build of one entry module gives. */
export interface ViteBundle {

	/** The minified chunk. */
	code: string;
	/** Its size in bytes, and gzipped (zlib's default level, as Vite's build report). */
	bytes: number;
	gzipBytes: number;
	/** The modules with code in the chunk (Rollup's renderedLength > 0), relative to the repository, '/'-separated. */
	modules: string[];
	/** The bare imports left in the chunk (the externals). */
	imports: string[];

}

/**
 * How the package's own modules are treated: by its package.json `sideEffects` claim applied to the
 * aliased sources ('package.json'), analysed by Rollup ('analysed'), or as Vite treats an installed
 * package ('installed': no aliases, the package resolved from `root`'s node_modules).
 */
export type SideEffectsMode = 'package.json' | 'analysed' | 'installed';

/**
 * Bundles `code` as an app entry with Vite's build API (minified, tree-shaken, nothing written),
 * `three-capture-lighting` and its subpaths resolved to the repository's `src/` by the same
 * aliases as the examples (or, with sideEffects 'installed', from `root`'s node_modules). `three`
 * is external unless `bundleThree`.
 * @param root The repository, or the project the package is installed in.
 */
export async function viteBundle(
	root: string, code: string, options: { bundleThree: boolean; sideEffects: SideEffectsMode },
): Promise<ViteBundle> {

	const { build } = await import( 'vite' );
	const src = resolve( root, 'src' ) + sep;
	const installed = options.sideEffects === 'installed';
	const claim = installed ? undefined : JSON.parse( readFileSync( resolve( root, 'package.json' ), 'utf8' ) ).sideEffects;
	// An installed package's modules get its package.json claim from the bundler; the aliased
	// sources would not, so the claim is applied here by hand, or left out to let Rollup analyse them.
	const moduleSideEffects = ( id: string ) => ! id.startsWith( src ) || ( options.sideEffects === 'analysed' ? true : claim !== false );
	const entry = '\0bundle-entry';
	const output = await build( {
		configFile: false,
		root,
		logLevel: 'silent',
		resolve: { alias: installed ? [] : libraryAliases( root ) },
		plugins: [ {
			name: 'bundle-entry',
			resolveId: ( id ) => ( id === 'bundle-entry' ? entry : null ),
			load: ( id ) => ( id === entry ? code : null ),
		} ],
		build: {
			write: false,
			minify: 'esbuild',
			reportCompressedSize: false,
			rollupOptions: {
				input: 'bundle-entry',
				external: options.bundleThree ? [] : [ /^three($|\/)/ ],
				treeshake: installed ? {} : { moduleSideEffects },
			},
		},
	} ) as Rollup.RollupOutput | Rollup.RollupOutput[];
	const chunks = ( Array.isArray( output ) ? output : [ output ] ).flatMap( ( o ) => o.output ).filter( ( o ): o is Rollup.OutputChunk => o.type === 'chunk' );
	// Code loaded on demand (the fit, fromScene) goes to other chunks: the entry chunk is what a page loads first.
	const entryChunks = chunks.filter( ( c ) => c.isEntry );
	if ( entryChunks.length !== 1 ) throw new Error( `viteBundle: expected one entry chunk, got ${entryChunks.length}` );
	const [ chunk ] = entryChunks;
	const modules = Object.entries( chunk.modules )
		.filter( ( [ , module ] ) => module.renderedLength > 0 )
		.map( ( [ id ] ) => ( id.startsWith( root ) ? id.slice( root.length ).replace( /^[\\/]/, '' ) : id ).split( sep ).join( '/' ) );
	return {
		code: chunk.code,
		bytes: Buffer.byteLength( chunk.code ),
		gzipBytes: gzipSync( chunk.code ).length,
		modules,
		imports: chunk.imports,
	};

}
