/**
 * What bench/webgpuFrames.bench.ts and bench/webgpuCapture.bench.ts share: Chromium with WebGPU
 * (SwiftShader's adapter) and the repository's Vite server from test/helpers/browser.ts, one
 * bench/pages/webgpu.html page per backend, and typed calls into the page's `webgpuBench` API.
 */

import { startBrowser, browserSkipReason, type BrowserSession } from '../test/helpers/browser.js';
import type { WebGPUBenchApi } from './pages/webgpu.js';

type Page = import( 'puppeteer-core' ).Page;

/** One page on one WebGPURenderer backend, with its error messages. */
export interface WebGPUBenchPage {

	page: Page;
	errors: string[];
	call<K extends keyof WebGPUBenchApi>(
		name: K, ...args: Parameters<WebGPUBenchApi[ K ]>
	): Promise<Awaited<ReturnType<WebGPUBenchApi[ K ]>>>;

}

/** Starts the browser (throws with the reason when Chromium is missing). */
export async function startWebGPUBench(): Promise<BrowserSession> {

	if ( browserSkipReason ) throw new Error( `webgpu bench: ${browserSkipReason}` );
	return startBrowser( { webgpu: true } );

}

/** Opens bench/pages/webgpu.html on `backend` and waits for its renderer. */
export async function openWebGPUBench( session: BrowserSession, backend: 'webgpu' | 'webgl2' ): Promise<WebGPUBenchPage> {

	const { page, errors } = await session.open( `bench/pages/webgpu.html?backend=${backend}`, { width: 1280, height: 720 } );
	try {

		await page.waitForFunction( 'window.webgpuBenchReady === true || window.webgpuBenchError !== undefined', { timeout: 120_000 } );

	} catch ( error ) {

		throw new Error( `webgpu bench (${backend}): the page did not start (${( error as Error ).message}); page errors: ${errors.join( ' | ' ).slice( 0, 800 ) || 'none'}` );

	}

	const failed = await page.evaluate( 'window.webgpuBenchError' ) as string | undefined;
	if ( failed ) throw new Error( `webgpu bench (${backend}): ${failed}` );
	const call = ( name: string, ...args: unknown[] ) => page.evaluate( ( fn: string, fnArgs: unknown[] ) => {

		const api = ( window as unknown as { webgpuBench: Record<string, ( ...a: unknown[] ) => unknown> } ).webgpuBench;
		return api[ fn ]( ...fnArgs );

	}, name, args );
	return { page, errors, call: call as WebGPUBenchPage[ 'call' ] };

}
