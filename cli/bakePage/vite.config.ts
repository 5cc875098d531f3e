import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';
import { libraryAliases } from '../libraryAliases.js';

// `npm run build` bundles the bake page (with three and the library) into dist/cli/page/, so an
// installed `capture-lighting` serves it as plain files: no Vite at bake time.
const root = fileURLToPath( new URL( '../..', import.meta.url ) );

export default defineConfig( {
	root: resolve( root, 'cli/bakePage' ),
	base: './',
	logLevel: 'warn',
	resolve: {
		alias: libraryAliases( root ),
	},
	build: { outDir: resolve( root, 'dist/cli/page' ), emptyOutDir: true, chunkSizeWarningLimit: 2000 },
} );
