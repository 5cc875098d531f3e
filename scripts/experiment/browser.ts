/**
 * The experiment's GPU: headless Chromium (cli/chromium.ts: WebGL2 on SwiftShader unless Chromium
 * is given a GPU) driven by puppeteer-core, serving scripts/experiment/page.html (and scripts/bounces/page.html)
 * through a Vite dev server over the repository — the same scene modules, loaders and asset route
 * as the demo pages.
 */

import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Browser, Page } from 'puppeteer-core';
import type { ViteDevServer } from 'vite';
import { launchChromium } from '../../cli/chromium.js';
import { libraryAliases } from '../../cli/libraryAliases.js';
import { assetsPlugin } from '../assetsPlugin.mjs';
import type { CaptureRequest, ExperimentApi, LoadedScene } from './page.js';

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );

/** A loaded experiment page. */
export interface ExperimentSession {

	browserVersion: string;
	load( scene: string ): Promise<LoadedScene>;
	vertexCandidates( options: { offset: number; minSpacing: number; bounds: { min: number[]; max: number[] } } ): Promise<Float32Array>;
	capture( positions: ArrayLike<number>, settings: CaptureRequest, label: string ): Promise<{ sh: Float32Array; ms: number }>;
	/** Renders an SVG string to a PNG file (the plot). */
	rasterize( svg: string, width: number, height: number, file: string ): Promise<void>;
	close(): Promise<void>;

}

/**
 * A script page open in headless Chromium: `scripts/<name>/page.html`, served by a Vite dev server
 * over the repository, whose API the page puts on `window[ name ]` (and `window[ name + 'Ready' ]`
 * once it is set up); its console lines starting with `[name]` are passed to `log`.
 */
export interface ScriptPage<Api> {

	browser: Browser;
	browserVersion: string;
	/** Calls `window[ name ][ method ]( ...args )` in the page; page errors are added to a failure's message. */
	call<K extends keyof Api>(
		method: K, ...args: Api[ K ] extends ( ...a: infer A ) => unknown ? A : never
	): Promise<Api[ K ] extends ( ...a: never[] ) => infer R ? Awaited<R> : never>;
	close(): Promise<void>;

}

/** Opens `scripts/<name>/page.html` (the experiment's and the bounce measurement's pages). */
export async function openScriptPage<Api>( name: string, log: ( message: string ) => void ): Promise<ScriptPage<Api>> {

	const { createServer } = await import( 'vite' );

	const server: ViteDevServer = await createServer( {
		configFile: false,
		root: ROOT,
		logLevel: 'error',
		plugins: [ assetsPlugin() ],
		resolve: { alias: libraryAliases( ROOT ) },
		// No file watching or HMR: edits elsewhere in the repository must not reload the page mid-run.
		server: { host: '127.0.0.1', port: 0, hmr: false, watch: null },
		optimizeDeps: { noDiscovery: true, include: [] },
	} );
	await server.listen();
	const baseUrl = server.resolvedUrls!.local[ 0 ];

	let browser: Browser | null = null;
	const close = async () => {

		await browser?.close().catch( () => undefined );
		await server.close().catch( () => undefined );

	};

	try {

		browser = await launchChromium( { protocolTimeout: 3_600_000 } );
		const page: Page = await browser.newPage();
		const errors: string[] = [];
		const prefix = `[${name}]`;
		page.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
		page.on( 'console', ( message ) => {

			const text = message.text();
			if ( text.startsWith( prefix ) ) log( text.slice( prefix.length + 1 ) );
			else if ( message.type() === 'error' ) errors.push( text );

		} );
		await page.goto( `${baseUrl}scripts/${name}/page.html`, { waitUntil: 'load' } );
		await page.waitForFunction( `window[ ${JSON.stringify( name + 'Ready' )} ] === true`, { timeout: 120_000 } ).catch( ( error ) => {

			throw new Error( `the ${name} page did not start: ${errors.join( ' | ' ) || ( error as Error ).message}` );

		} );

		const call = async ( method: PropertyKey, ...args: unknown[] ) => {

			try {

				return await page.evaluate( ( api: string, fn: string, fnArgs: unknown[] ) => {

					const target = ( window as unknown as Record<string, Record<string, ( ...a: unknown[] ) => unknown>> )[ api ];
					return target[ fn ]( ...fnArgs );

				}, name, String( method ), args );

			} catch ( error ) {

				throw new Error( `${String( method )} failed in the page: ${( error as Error ).message}${errors.length ? ` (page errors: ${errors.join( ' | ' )})` : ''}` );

			}

		};

		return { browser, browserVersion: await browser.version(), call: call as ScriptPage<Api>[ 'call' ], close };

	} catch ( error ) {

		await close();
		throw error;

	}

}

export async function startSession( log: ( message: string ) => void ): Promise<ExperimentSession> {

	const { browser, browserVersion, call, close } = await openScriptPage<ExperimentApi>( 'experiment', log );
	return {
		browserVersion,
		load: ( scene ) => call( 'load', scene, '/assets/' ),
		async vertexCandidates( options ) {

			return fromBase64( await call( 'vertexCandidates', options ), Float32Array );

		},
		async capture( positions, settings, label ) {

			const { sh, ms } = await call( 'capture', Array.from( positions ), settings, label );
			return { sh: fromBase64( sh, Float32Array ), ms };

		},
		async rasterize( svg, width, height, file ) {

			const plot = await browser.newPage();
			try {

				await plot.setViewport( { width, height, deviceScaleFactor: 1 } );
				await plot.setContent( `<!DOCTYPE html><html><body style="margin:0;background:#fff">${svg}</body></html>` );
				await plot.screenshot( { path: file as `${string}.png`, clip: { x: 0, y: 0, width, height } } );

			} finally {

				await plot.close();

			}

		},
		close,
	};

}

/** Decodes a base64 string of a typed array's bytes. */
export function fromBase64<T extends Float32Array | Int8Array>( text: string, type: { new( buffer: ArrayBuffer ): T } ): T {

	const bytes = Buffer.from( text, 'base64' );
	const copy = new ArrayBuffer( bytes.length );
	new Uint8Array( copy ).set( bytes );
	return new type( copy );

}
