import { defineConfig } from 'vitest/config';

export default defineConfig( {
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
