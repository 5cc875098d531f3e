import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';
import type { ViteDevServer } from 'vite';
import type { Browser, Page } from 'puppeteer-core';
import { checkChromium, launchChromium, resolveChromiumPath } from '../../cli/chromium.js';
import { libraryAliases } from '../../cli/libraryAliases.js';
import { assetsPlugin, assetsFolder } from '../../scripts/assetsPlugin.mjs';

/** Where the third-party assets are looked for (CAPTURE_LIGHTING_ASSETS or ../shared/assets). */
export const ASSETS: string = assetsFolder;

/**
 * Browser tests: a Vite dev server over the repository (so both examples/ and test/browser/pages/
 * are reachable, with `three-capture-lighting` and its subpaths aliased to src/) and Chromium started by
 * cli/chromium.ts (WebGL2 on SwiftShader). `browserSkipReason` is set when Chromium is missing.
 */
const chromium = resolveChromiumPath();

/** Chromium's executable: CHROME_PATH, else CHROMIUM_PATH, else /usr/bin/chromium. */
export const CHROMIUM: string = chromium.path;

/** '' when Chromium exists, else why the browser tests are skipped. */
export const browserSkipReason: string = checkChromium( chromium.path, chromium.source );

const root = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );

export interface BrowserSession {

	browser: Browser;
	server: ViteDevServer;
	baseUrl: string;
	/** Opens a page, collecting console errors and page errors into `errors`. */
	open( path: string, size?: { width: number; height: number } ): Promise<{ page: Page; errors: string[] }>;
	close(): Promise<void>;

}

/** Options of {@link startBrowser}. */
export interface StartBrowserOptions {

	/** Launch Chromium with WebGPU enabled (SwiftShader's adapter; pages are served from 127.0.0.1, a secure context). Default false. */
	webgpu?: boolean;

}

export async function startBrowser( options: StartBrowserOptions = {} ): Promise<BrowserSession> {

	const { createServer } = await import( 'vite' );
	const server = await createServer( {
		configFile: false,
		root,
		logLevel: 'error',
		plugins: [ assetsPlugin() ],
		resolve: { alias: libraryAliases( root ) },
		// No hot reload and no file watching: an edit to src/ during a run must not reload a page mid-test.
		server: { host: '127.0.0.1', port: 0, hmr: false, watch: null, fs: { allow: [ root, resolve( root, '../shared' ) ] } },
		// No dependency pre-bundling: every dependency is plain ESM, and a re-optimisation found
		// mid-run would reload a page under test.
		optimizeDeps: { noDiscovery: true, include: [] },
	} );
	await server.listen();
	const baseUrl = server.resolvedUrls!.local[ 0 ];

	const browser = await launchChromium( { browser: CHROMIUM, webgpu: options.webgpu === true } );

	return {
		browser, server, baseUrl,
		async open( path, size = { width: 640, height: 360 } ) {

			const page = await browser.newPage();
			await page.setViewport( size );
			const errors: string[] = [];
			page.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
			page.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( message.text() ); } );
			// 120 s: the first page that imports three/webgpu waits for Vite to transform it cold.
			await page.goto( baseUrl + path.replace( /^\//, '' ), { waitUntil: 'load', timeout: 120_000 } );
			return { page, errors };

		},
		async close() {

			await browser.close();
			await server.close();

		},
	};

}
