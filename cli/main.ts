#!/usr/bin/env node
/**
 * `capture-lighting`: bakes a light probe volume from a scene file and a probe layout, headless
 * (`bake`), or checks a baked volume file (`inspect`). See `capture-lighting --help`.
 *
 * Exit codes: 0 ok, 1 failure at run time (or an invalid volume file, or a warning under --strict), 2
 * bad usage or input.
 * Every error is one line starting with "capture-lighting: ".
 */

import { USAGE, parseArguments } from './args.js';
import { CliError } from './errors.js';

/**
 * Runs the CLI with the given arguments.
 * @param argv `process.argv.slice( 2 )`.
 * @returns The exit code.
 */
async function main( argv: readonly string[] ): Promise<number> {

	try {

		const command = parseArguments( argv );
		if ( command.command === 'help' ) {

			process.stdout.write( USAGE + '\n' );
			return 0;

		}

		if ( command.command === 'inspect' ) {

			const { inspect } = await import( './inspect.js' );
			inspect( command.file, { strict: command.strict } );
			return 0;

		}

		const { bake } = await import( './bake.js' );
		await bake( command.options );
		return 0;

	} catch ( error ) {

		if ( error instanceof CliError ) {

			process.stderr.write( `capture-lighting: ${error.message}\n` );
			return error.exitCode;

		}

		process.stderr.write( `capture-lighting: unexpected error: ${( error as Error ).stack ?? String( error )}\n` );
		return 1;

	}

}

process.exitCode = await main( process.argv.slice( 2 ) );
