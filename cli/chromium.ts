/**
 * Headless Chromium for everything here that renders in a browser: `capture-lighting bake`,
 * `npm start -- --check`, the experiment and the bounce measurement, the capture benchmark and the
 * browser tests. Chromium (Debian's, or any Chrome) is driven by puppeteer-core, an optional peer
 * dependency, with WebGL2 on SwiftShader (the CPU) unless the machine gives Chromium a GPU.
 *
 * The executable is the first of these that is set (an empty value counts as unset): an explicit
 * path (`--browser`, the `browser` option), else $CHROME_PATH, else $CHROMIUM_PATH, else
 * /usr/bin/chromium. It is used even when it does not exist, so a wrong setting is reported, not
 * skipped: the error names the path and where it came from.
 */

import { existsSync } from 'node:fs';
import type { Browser, LaunchOptions, Viewport } from 'puppeteer-core';

/** Debian's Chromium: the path when no explicit one, CHROME_PATH or CHROMIUM_PATH is given. */
export const DEFAULT_CHROMIUM = '/usr/bin/chromium';

/** Chromium's flags: WebGL2 on SwiftShader (the CPU), no sandbox (containers), no network chatter. */
export const CHROMIUM_ARGS: readonly string[] = [
	'--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
	'--disable-background-networking', '--disable-component-update', '--no-first-run',
];

/** The flag that {@link ChromiumLaunchOptions.webgpu} adds: WebGPU, which Chromium on Linux keeps behind it. */
export const WEBGPU_ARG = '--enable-unsafe-webgpu';

/** Where a Chromium path came from: the explicit path, an environment variable, or the default. */
export type ChromiumPathSource = 'explicit' | 'CHROME_PATH' | 'CHROMIUM_PATH' | 'default';

/** A Chromium executable and where its path came from. */
export interface ChromiumPath {

	/** The executable's path (not checked). */
	path: string;

	/** Which rule gave it. */
	source: ChromiumPathSource;

}

/** Environment variables, as in `process.env`. */
export type Environment = Record<string, string | undefined>;

/**
 * The Chromium path by the module's rule: `explicit`, else CHROME_PATH, else CHROMIUM_PATH, else
 * /usr/bin/chromium (empty values count as unset). Pure: the file is not looked at.
 * @param explicit A path given by the caller (`--browser`), or undefined / null / ''.
 * @param env The environment to read (default `process.env`).
 */
export function resolveChromiumPath( explicit?: string | null, env: Environment = process.env ): ChromiumPath {

	if ( explicit ) return { path: explicit, source: 'explicit' };
	if ( env.CHROME_PATH ) return { path: env.CHROME_PATH, source: 'CHROME_PATH' };
	if ( env.CHROMIUM_PATH ) return { path: env.CHROMIUM_PATH, source: 'CHROMIUM_PATH' };
	return { path: DEFAULT_CHROMIUM, source: 'default' };

}

const TRIED: Record<ChromiumPathSource, string> = {
	explicit: 'the explicit path (--browser, the browser option), which overrides CHROME_PATH and CHROMIUM_PATH',
	CHROME_PATH: '$CHROME_PATH (no explicit path given)',
	CHROMIUM_PATH: '$CHROMIUM_PATH (no explicit path given, CHROME_PATH not set)',
	default: 'the default (no explicit path given, CHROME_PATH and CHROMIUM_PATH not set)',
};

/**
 * Why Chromium cannot be started from `path`: '' when the file exists, else a message naming the
 * path, its source (when given) and how to get Chromium. Callers prefix their own name.
 * @param path The executable, as from {@link resolveChromiumPath}.
 * @param source Where `path` came from; without it the message states the whole rule.
 */
export function checkChromium( path: string, source?: ChromiumPathSource ): string {

	if ( existsSync( path ) ) return '';
	const rule = source ? `Tried ${TRIED[ source ]}.`
		: `The path is --browser, else CHROME_PATH, else CHROMIUM_PATH, else ${DEFAULT_CHROMIUM}.`;
	return `Chromium not found at ${path}; install it (apt install chromium) or pass --browser <path> (or set CHROME_PATH). ${rule}`;

}

/** What {@link chromiumArgs} adds to {@link CHROMIUM_ARGS}. */
export interface ChromiumFlagOptions {

	/** Also enable WebGPU ({@link WEBGPU_ARG}); default false. */
	webgpu?: boolean;

	/** More flags, after the shared ones (a caller's extras). */
	args?: readonly string[];

}

/** The command-line flags of a launch: {@link CHROMIUM_ARGS}, then WebGPU's, then the caller's. */
export function chromiumArgs( options: ChromiumFlagOptions = {} ): string[] {

	return [ ...CHROMIUM_ARGS, ...( options.webgpu ? [ WEBGPU_ARG ] : [] ), ...( options.args ?? [] ) ];

}

/**
 * puppeteer-core's entry, or an Error when it is not installed (it is an optional peer dependency).
 * @param caller Who needs it; the message starts with it, e.g. "capture-lighting bake drives Chromium …".
 */
export async function importPuppeteer( caller = 'importPuppeteer' ): Promise<typeof import( 'puppeteer-core' )[ 'default' ]> {

	try {

		return ( await import( 'puppeteer-core' ) ).default;

	} catch {

		throw new Error( `${caller} drives Chromium through puppeteer-core, which is not installed: npm install puppeteer-core` );

	}

}

/** What {@link launchChromium} takes: the executable, the flags, and puppeteer's per-caller settings. */
export interface ChromiumLaunchOptions extends ChromiumFlagOptions {

	/** The executable; when absent or '', CHROME_PATH, else CHROMIUM_PATH, else /usr/bin/chromium. */
	browser?: string | null;

	/** The environment the path is read from (default `process.env`). */
	env?: Environment;

	/** How long one call into a page may take, in ms (default puppeteer's 180 s). */
	protocolTimeout?: number;

	/** Every new page's viewport (default puppeteer's 800 × 600; null: the window's size). */
	defaultViewport?: Viewport | null;

}

/**
 * Starts headless Chromium: finds the executable by the module's rule, then launches it with
 * {@link chromiumArgs}. Errors of puppeteer's own launch are passed on as they are.
 * @throws {Error} "launchChromium: Chromium not found at …" when the executable does not exist,
 * "launchChromium drives Chromium through puppeteer-core, which is not installed …" without puppeteer-core.
 */
export async function launchChromium( options: ChromiumLaunchOptions = {} ): Promise<Browser> {

	const { path, source } = resolveChromiumPath( options.browser, options.env );
	const problem = checkChromium( path, source );
	if ( problem ) throw new Error( `launchChromium: ${problem}` );
	const puppeteer = await importPuppeteer( 'launchChromium' );
	const launch: LaunchOptions = { executablePath: path, headless: true, args: chromiumArgs( options ) };
	if ( options.protocolTimeout !== undefined ) launch.protocolTimeout = options.protocolTimeout;
	if ( options.defaultViewport !== undefined ) launch.defaultViewport = options.defaultViewport;
	return puppeteer.launch( launch );

}
