import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';
import { libraryAliases } from './cli/libraryAliases.js';

const root = fileURLToPath( new URL( '.', import.meta.url ) );

export default defineConfig( {
	// `three-capture-lighting` and its subpaths resolve to src/, as in the demo pages (scenes/*.ts
	// import them): a fresh clone has no dist/ for the package's self-reference to find.
	resolve: { alias: libraryAliases( root ) },
	test: {
		include: [ 'test/**/*.test.ts' ],
		testTimeout: 300_000,
		// One file at a time: the GPU and browser suites each want both cores, and SwiftShader
		// under contention makes page loads slow enough to time out.
		fileParallelism: false,
		hookTimeout: 120_000,
		reporters: [ 'default' ],
	},
} );
