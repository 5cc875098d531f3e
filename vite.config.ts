import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';
import { existsSync } from 'node:fs';
import { assetsPlugin } from './scripts/assetsPlugin.mjs';
import { libraryAliases } from './cli/libraryAliases.js';

const root = fileURLToPath( new URL( '.', import.meta.url ) );

// The examples import the library by its package name, as users do; here it resolves to src/.
export default defineConfig( {
	root: resolve( root, 'examples' ),
	plugins: [ assetsPlugin() ],
	resolve: {
		alias: libraryAliases( root ),
	},
	server: { host: '127.0.0.1', port: 5173, strictPort: false },
	optimizeDeps: { noDiscovery: true, include: [] },
	build: {
		outDir: resolve( root, 'dist-examples' ),
		emptyOutDir: true,
		rollupOptions: {
			input: Object.fromEntries( [ 'index', 'minimal', 'basic', 'sponza', 'sibenik', 'kyoto', 'tworooms', 'lightmapper' ]
				.map( ( name ) => [ name, resolve( root, `examples/${name}.html` ) ] )
				.filter( ( [ , path ] ) => existsSync( path ) ) ),
		},
	},
} );
