import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer as createHttpServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { basename, dirname, extname, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { IncomingMessage, ServerResponse } from 'node:http';
import type { Browser } from 'puppeteer-core';
import type { Plugin, ViteDevServer } from 'vite';
import { checkChromium, importPuppeteer, launchChromium } from './chromium.js';
import { libraryAliases } from './libraryAliases.js';
import { CliError } from './errors.js';
import { PROGRESS_FUNCTION, type BakePageApi, type BakeRequest, type BakeResult } from './bakePage/protocol.js';

/** What {@link captureInBrowser} needs besides the request's capture settings. */
export interface BrowserCaptureOptions {

	/** The scene file on disk. */
	scene: string;

	/** An equirectangular .hdr sky on disk, if any. */
	skyFile: string | null;

	/** Chromium's executable (parseArguments resolves it: --browser, CHROME_PATH, CHROMIUM_PATH, /usr/bin/chromium). */
	browser: string;

	/** Progress of each stage ('loading', 'capturing'). */
	onProgress?: ( stage: string, done: number, total: number ) => void;

}

/**
 * Runs the capture in headless Chromium. The bake page is served as plain files when `npm run
 * build` bundled it (dist/cli/page/, what an installed package runs), else by a Vite dev server
 * that compiles cli/bakePage/ with the library's sources (running from the repository). The scene
 * file's folder is served as it is on disk at /__scene/ (and the sky's folder at /__sky/), so an
 * .mtl, .bin or texture next to the scene loads by its relative name.
 * @param request Everything but the URLs, which are filled in here.
 * @throws {CliError} exit code 2 when Chromium is missing; 1 when the page fails (its message included).
 */
export async function captureInBrowser( request: Omit<BakeRequest, 'sceneUrl' | 'sky'> & { sky: { color: [ number, number, number ] } | null }, options: BrowserCaptureOptions ): Promise<BakeResult> {

	const missing = checkChromium( options.browser );
	if ( missing ) throw new CliError( missing );
	const sceneFolder = dirname( resolve( options.scene ) );
	const skyFolder = options.skyFile ? dirname( resolve( options.skyFile ) ) : null;

	await importPuppeteer( 'capture-lighting bake' ).catch( ( error: Error ) => {

		throw new CliError( error.message );

	} );
	const folders: [ string, string ][] = [ [ '/__scene', sceneFolder ], ...( skyFolder ? [ [ '/__sky', skyFolder ] as [ string, string ] ] : [] ) ];
	const prebuilt = findPrebuiltPage();
	const server = prebuilt ? await startStaticServer( [ ...folders, [ '/__page', prebuilt ] ] ) : await startViteServer( findRoot(), folders );
	const pagePath = prebuilt ? '__page/index.html' : 'cli/bakePage/index.html';

	let browser: Browser | null = null;
	try {

		const baseUrl = server.baseUrl;
		try {

			browser = await launchChromium( { browser: options.browser, protocolTimeout: 24 * 3_600_000 } );

		} catch ( error ) {

			throw new CliError( `could not start Chromium at ${options.browser}: ${( error as Error ).message.split( '\n' )[ 0 ]}`, 1 );

		}

		const page = await browser.newPage();
		const errors: string[] = [];
		page.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
		page.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( message.text() ); } );
		const progress = ( stage: string, done: number, total: number ) => options.onProgress?.( stage, done, total );
		await page.exposeFunction( PROGRESS_FUNCTION, progress );
		await page.goto( baseUrl + pagePath, { waitUntil: 'load' } );
		const ready = () => ( window as unknown as { bakeReady?: boolean } ).bakeReady === true;
		await page.waitForFunction( ready, { timeout: 120_000 } ).catch( ( error ) => {

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

/** The bundled bake page next to the compiled CLI (dist/cli/page/), or null when running from source. */
function findPrebuiltPage(): string | null {

	const folder = resolve( dirname( fileURLToPath( import.meta.url ) ), 'page' );
	return import.meta.url.endsWith( '.js' ) && existsSync( resolve( folder, 'index.html' ) ) && existsSync( resolve( folder, 'assets' ) ) ? folder : null;

}

interface PageServer { baseUrl: string; close(): Promise<void> }

/** Plain files: each route serves its folder as it is on disk. */
async function startStaticServer( routes: [ string, string ][] ): Promise<PageServer> {

	const handlers = routes.map( ( [ route, folder ] ) => [ route, serveFolder( folder ) ] as const );
	const server: Server = createHttpServer( ( request, response ) => {

		const url = request.url ?? '/';
		for ( const [ route, handler ] of handlers ) {

			if ( url.startsWith( route + '/' ) ) {

				request.url = url.slice( route.length );
				handler( request, response );
				return;

			}

		}

		response.statusCode = 404;
		response.end( `not found: ${url}` );

	} );
	await new Promise<void>( ( done ) => server.listen( 0, '127.0.0.1', done ) );
	const { port } = server.address() as AddressInfo;
	return { baseUrl: `http://127.0.0.1:${port}/`, close: () => new Promise<void>( ( done ) => server.close( () => done() ) ) };

}

/** Vite compiles the page from source (repository checkouts, where dist/ may be stale or absent). */
async function startViteServer( root: string, folders: [ string, string ][] ): Promise<PageServer> {

	let vite: typeof import( 'vite' );
	try {

		vite = await import( 'vite' );

	} catch {

		throw new CliError( 'the bake page is not built (dist/cli/page/) and Vite is not installed to compile it: run npm run build in the package, or npm install vite', 1 );

	}

	const server: ViteDevServer = await vite.createServer( {
		configFile: false,
		root,
		logLevel: 'error',
		plugins: folders.map( ( [ route, folder ] ) => folderPlugin( route, folder ) ),
		resolve: { alias: libraryAliases( root ) },
		// No watching or HMR: an edit elsewhere must not reload the page mid-bake.
		server: { host: '127.0.0.1', port: 0, hmr: false, watch: null },
		optimizeDeps: { noDiscovery: true, include: [] },
	} );
	await server.listen();
	return { baseUrl: server.resolvedUrls!.local[ 0 ], close: () => server.close() };

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
	'.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css',
};

/** Serves the files of `folder` (and its subfolders) at `route` of the Vite server, raw, as they are on disk. */
function folderPlugin( route: string, folder: string ): Plugin {

	const serve = serveFolder( folder );
	return {
		name: `capture-lighting-folder${route.replace( /\//g, '-' )}`,
		configureServer( server ) {

			server.middlewares.use( route, serve );

		},
	};

}

/** A request handler for the files of `folder` (request.url relative to it); nothing outside it. */
function serveFolder( folder: string ): ( request: IncomingMessage, response: ServerResponse ) => void {

	return ( request, response ) => {

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

	};

}
