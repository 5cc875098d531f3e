#!/usr/bin/env node
// Runs the Vitest suite. GPU tests need an X display for headless-gl: when none is set and
// xvfb-run exists (scripts/setup.sh installs it), the suite runs under a virtual one; without it,
// the GPU tests skip and say why.
import { spawnSync } from 'node:child_process';

const args = [ 'vitest', 'run', ...process.argv.slice( 2 ) ];
const hasXvfb = spawnSync( 'sh', [ '-c', 'command -v xvfb-run' ] ).status === 0;
const command = ! process.env.DISPLAY && hasXvfb
	? [ 'xvfb-run', [ '-a', '-s', '-screen 0 1280x1024x24', 'npx', ...args ] ]
	: [ 'npx', args ];
const result = spawnSync( command[ 0 ], command[ 1 ], { stdio: 'inherit' } );
process.exit( result.status ?? 1 );
