import { defineConfig } from 'vite';
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';

// `npm run build` bundles the bake page (with three and the library) into dist/cli/page/, so an
// installed `capture-lighting` serves it as plain files: no Vite at bake time.
const root = fileURLToPath( new URL( '../..', import.meta.url ) );

export default defineConfig( {
	root: resolve( root, 'cli/bakePage' ),
	base: './',
	logLevel: 'warn',
	resolve: {
		alias: [
			// The package's entries: 'three-capture-lighting' and its subpaths (/math, /format, /capture, /lightProbeGrid).
			{ find: /^three-capture-lighting$/, replacement: resolve( root, 'src/index.ts' ) },
			{ find: /^three-capture-lighting\/(math|format|capture|lightProbeGrid)$/, replacement: resolve( root, 'src/$1.ts' ) },
			{ find: '@scenes', replacement: resolve( root, 'scenes' ) },
		],
	},
	build: { outDir: resolve( root, 'dist/cli/page' ), emptyOutDir: true, chunkSizeWarningLimit: 2000 },
} );
