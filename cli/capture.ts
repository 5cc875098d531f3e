import { createReadStream, existsSync, statSync } from 'node:fs';
import { basename, dirname, extname, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { IncomingMessage, ServerResponse } from 'node:http';
import type { Browser } from 'puppeteer-core';
import type { Plugin, ViteDevServer } from 'vite';
import { CliError } from './errors.js';
import { PROGRESS_FUNCTION, type BakePageApi, type BakeRequest, type BakeResult } from './bakePage/protocol.js';

/** Chromium's flags: WebGL2 on SwiftShader (the CPU), no sandbox (containers), no network chatter. */
export const CHROMIUM_ARGS = [ '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run' ];

/** What {@link captureInBrowser} needs besides the request's capture settings. */
export interface BrowserCaptureOptions {

	/** The scene file on disk. */
	scene: string;

	/** An equirectangular .hdr sky on disk, if any. */
	skyFile: string | null;

	/** Chromium's executable. */
	browser: string;

	/** Progress of each stage ('loading', 'capturing'). */
	onProgress?: ( stage: string, done: number, total: number ) => void;

}

/**
 * Runs the capture in headless Chromium: a Vite dev server serves the bake page (cli/bakePage/,
 * compiled on the fly with the library's sources) and the scene file's folder, as it is on disk,
 * at /__scene/ (and the sky's folder at /__sky/), so an .mtl, .bin or texture next to the scene
 * loads by its relative name.
 * @param request Everything but the URLs, which are filled in here.
 * @throws {CliError} exit code 2 when Chromium is missing; 1 when the page fails (its message included).
 */
export async function captureInBrowser( request: Omit<BakeRequest, 'sceneUrl' | 'sky'> & { sky: { color: [ number, number, number ] } | null }, options: BrowserCaptureOptions ): Promise<BakeResult> {

	if ( ! existsSync( options.browser ) ) throw new CliError( `Chromium not found at ${options.browser}; install it (apt install chromium) or pass --browser <path> (or set CHROME_PATH).` );
	const root = findRoot();
	const sceneFolder = dirname( resolve( options.scene ) );
	const skyFolder = options.skyFile ? dirname( resolve( options.skyFile ) ) : null;

	const { createServer } = await import( 'vite' );
	const { default: puppeteer } = await import( 'puppeteer-core' );
	const server: ViteDevServer = await createServer( {
		configFile: false,
		root,
		logLevel: 'error',
		plugins: [ folderPlugin( '/__scene', sceneFolder ), ...( skyFolder ? [ folderPlugin( '/__sky', skyFolder ) ] : [] ) ],
		resolve: { alias: { 'three-capture-lighting': resolve( root, 'src/index.ts' ), '@scenes': resolve( root, 'scenes' ) } },
		// No watching or HMR: an edit elsewhere must not reload the page mid-bake.
		server: { host: '127.0.0.1', port: 0, hmr: false, watch: null },
		optimizeDeps: { noDiscovery: true, include: [] },
	} );

	let browser: Browser | null = null;
	try {

		await server.listen();
		const baseUrl = server.resolvedUrls!.local[ 0 ];
		try {

			browser = await puppeteer.launch( { executablePath: options.browser, headless: true, args: CHROMIUM_ARGS, protocolTimeout: 24 * 3_600_000 } );

		} catch ( error ) {

			throw new CliError( `could not start Chromium at ${options.browser}: ${( error as Error ).message.split( '\n' )[ 0 ]}`, 1 );

		}

		const page = await browser.newPage();
		const errors: string[] = [];
		page.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
		page.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( message.text() ); } );
		await page.exposeFunction( PROGRESS_FUNCTION, ( stage: string, done: number, total: number ) => options.onProgress?.( stage, done, total ) );
		await page.goto( baseUrl + 'cli/bakePage/index.html', { waitUntil: 'load' } );
		await page.waitForFunction( () => ( window as unknown as { bakeReady?: boolean } ).bakeReady === true, { timeout: 120_000 } ).catch( ( error ) => {

			throw new CliError( `the bake page did not start in Chromium: ${errors.join( ' | ' ) || ( error as Error ).message}`, 1 );

		} );

		const full: BakeRequest = {
			...request,
			sceneUrl: `${baseUrl}__scene/${encodeURIComponent( basename( options.scene ) )}`,
			sky: options.skyFile ? { hdrUrl: `${baseUrl}__sky/${encodeURIComponent( basename( options.skyFile ) )}` } : request.sky,
		};
		try {

			return await page.evaluate( ( r: BakeRequest ) => ( window as unknown as { bake: BakePageApi } ).bake.run( r ), full );

		} catch ( error ) {

			const message = ( error as Error ).message.split( '\n' )[ 0 ];
			throw new CliError( `the capture failed in Chromium: ${message}${errors.length ? ` (page errors: ${errors.join( ' | ' )})` : ''}`, 1 );

		}

	} finally {

		await browser?.close().catch( () => undefined );
		await server.close().catch( () => undefined );

	}

}

/** The repository (or installed package) root: the nearest folder up with cli/bakePage/index.html, from source or from dist/cli. */
function findRoot(): string {

	let folder = dirname( fileURLToPath( import.meta.url ) );
	for ( let i = 0; i < 5; i ++ ) {

		if ( existsSync( resolve( folder, 'cli/bakePage/index.html' ) ) ) return folder;
		folder = dirname( folder );

	}

	throw new CliError( `cannot find the bake page (cli/bakePage/index.html) above ${dirname( fileURLToPath( import.meta.url ) )}.`, 1 );

}

const TYPES: Record<string, string> = {
	'.gltf': 'model/gltf+json', '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream', '.obj': 'text/plain', '.mtl': 'text/plain',
	'.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.webp': 'image/webp', '.ktx2': 'image/ktx2', '.hdr': 'application/octet-stream',
};

/** Serves the files of `folder` (and its subfolders) at `route`, raw, as they are on disk. */
function folderPlugin( route: string, folder: string ): Plugin {

	return {
		name: `capture-lighting-folder${route.replace( /\//g, '-' )}`,
		configureServer( server ) {

			server.middlewares.use( route, ( request: IncomingMessage, response: ServerResponse ) => {

				let path: string;
				try {

					path = decodeURIComponent( ( request.url ?? '/' ).split( '?' )[ 0 ] );

				} catch {

					path = '';

				}

				const file = resolve( folder, '.' + path );
				if ( ! path || ! file.startsWith( folder + sep ) || ! existsSync( file ) || ! statSync( file ).isFile() ) {

					response.statusCode = 404;
					response.end( `not found: ${path} (in ${folder})` );
					return;

				}

				response.setHeader( 'Content-Type', TYPES[ extname( file ).toLowerCase() ] ?? 'application/octet-stream' );
				createReadStream( file ).pipe( response );

			} );

		},
	};

}
