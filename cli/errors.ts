/**
 * Errors the CLI reports without a stack trace: the message is printed after "capture-lighting: "
 * and the process exits with `exitCode` (2 for bad usage or input, 1 for a failure at run time).
 */
export class CliError extends Error {

	/** The process exit code: 2 bad usage or input, 1 run-time failure. */
	readonly exitCode: number;

	/**
	 * @param message What went wrong, naming the file or option.
	 * @param exitCode 2 (default) for bad usage or input, 1 for a run-time failure.
	 */
	constructor( message: string, exitCode = 2 ) {

		super( message );
		this.name = 'CliError';
		this.exitCode = exitCode;

	}

}
