/**
 * The experiment's GPU: headless Chromium (WebGL2 on SwiftShader unless Chromium is given a GPU)
 * driven by puppeteer-core, serving scripts/experiment/page.html through a Vite dev server over
 * the repository — the same scene modules, loaders and asset route as the demo pages.
 */

import { existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Browser, Page } from 'puppeteer-core';
import type { ViteDevServer } from 'vite';
import { assetsPlugin } from '../assetsPlugin.mjs';
import type { CaptureRequest, ExperimentApi, LoadedScene } from './page.js';

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );

/** Chromium's path: $CHROMIUM_PATH or Debian's. */
export const CHROMIUM = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

export const CHROMIUM_ARGS = [ '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run' ];

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

export async function startSession( log: ( message: string ) => void ): Promise<ExperimentSession> {

	if ( ! existsSync( CHROMIUM ) ) throw new Error( `no Chromium at ${CHROMIUM}: run scripts/setup.sh, or set CHROMIUM_PATH` );
	const { createServer } = await import( 'vite' );
	const { default: puppeteer } = await import( 'puppeteer-core' );

	const server: ViteDevServer = await createServer( {
		configFile: false,
		root: ROOT,
		logLevel: 'error',
		plugins: [ assetsPlugin() ],
		resolve: { alias: { 'three-capture-lighting': resolve( ROOT, 'src/index.ts' ), '@scenes': resolve( ROOT, 'scenes' ) } },
		// No file watching or HMR: edits elsewhere in the repository must not reload the page mid-run.
		server: { host: '127.0.0.1', port: 0, hmr: false, watch: null },
		optimizeDeps: { noDiscovery: true, include: [] },
	} );
	await server.listen();
	const baseUrl = server.resolvedUrls!.local[ 0 ];

	let browser: Browser | null = null;
	try {

		browser = await puppeteer.launch( { executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS, protocolTimeout: 3_600_000 } );
		const page: Page = await browser.newPage();
		const errors: string[] = [];
		page.on( 'pageerror', ( error ) => errors.push( ( error as Error ).message ) );
		page.on( 'console', ( message ) => {

			const text = message.text();
			if ( text.startsWith( '[experiment]' ) ) log( text.slice( 13 ) );
			else if ( message.type() === 'error' ) errors.push( text );

		} );
		await page.goto( baseUrl + 'scripts/experiment/page.html', { waitUntil: 'load' } );
		await page.waitForFunction( () => ( window as unknown as { experimentReady?: boolean } ).experimentReady === true, { timeout: 120_000 } ).catch( ( error ) => {

			throw new Error( `the experiment page did not start: ${errors.join( ' | ' ) || ( error as Error ).message}` );

		} );

		const call = async <K extends keyof ExperimentApi>( name: K, ...args: Parameters<ExperimentApi[ K ]> ): Promise<Awaited<ReturnType<ExperimentApi[ K ]>>> => {

			try {

				return await page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

					const api = ( window as unknown as { experiment: Record<string, ( ...a: unknown[] ) => unknown> } ).experiment;
					return api[ fn ]( ...fnArgs );

				}, name, args as unknown[] ) as Awaited<ReturnType<ExperimentApi[ K ]>>;

			} catch ( error ) {

				throw new Error( `${name} failed in the page: ${( error as Error ).message}${errors.length ? ` (page errors: ${errors.join( ' | ' )})` : ''}` );

			}

		};

		const browserVersion = await browser.version();
		const session: ExperimentSession = {
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

				const plot = await browser!.newPage();
				try {

					await plot.setViewport( { width, height, deviceScaleFactor: 1 } );
					await plot.setContent( `<!DOCTYPE html><html><body style="margin:0;background:#fff">${svg}</body></html>` );
					await plot.screenshot( { path: file as `${string}.png`, clip: { x: 0, y: 0, width, height } } );

				} finally {

					await plot.close();

				}

			},
			async close() {

				await browser?.close().catch( () => undefined );
				await server.close().catch( () => undefined );

			},
		};
		return session;

	} catch ( error ) {

		await browser?.close().catch( () => undefined );
		await server.close().catch( () => undefined );
		throw error;

	}

}

/** Decodes a base64 string of a typed array's bytes. */
export function fromBase64<T extends Float32Array | Int8Array>( text: string, type: { new( buffer: ArrayBuffer ): T } ): T {

	const bytes = Buffer.from( text, 'base64' );
	const copy = new ArrayBuffer( bytes.length );
	new Uint8Array( copy ).set( bytes );
	return new type( copy );

}
