#!/usr/bin/env node
// Serves the example pages with Vite and prints the URL (the Basic scene is the default page).
//
//   npm start                 serve until Ctrl+C
//   npm start -- --check      (or CI=true) open the Basic page in headless Chromium, wait until it
//                             has rendered, save a screenshot to test/output/basic.png, and exit:
//                             non-zero on a page error, a console error, or a blank frame.
//
// Chromium comes from cli/chromium.ts (CHROME_PATH, else CHROMIUM_PATH, else /usr/bin/chromium),
// loaded through tsx since this file is plain Node.
import { createServer } from 'vite';
import { mkdirSync } from 'node:fs';

const check = process.argv.includes( '--check' ) || process.env.CI === 'true';

const server = await createServer( { configFile: new URL( '../vite.config.ts', import.meta.url ).pathname, logLevel: check ? 'warn' : 'info' } );
await server.listen();
const base = server.resolvedUrls.local[ 0 ];
const url = `${base}basic.html`;

if ( ! check ) {

	console.log( `\n  three-capture-lighting examples: ${base}\n  Basic scene:                     ${url}\n` );

} else {

	const code = await checkPage( url ).catch( ( error ) => {

		console.error( `start --check: ${error.message}` );
		return 1;

	} );
	await server.close();
	process.exit( code );

}

async function checkPage( pageUrl ) {

	const { tsImport } = await import( 'tsx/esm/api' );
	const { launchChromium } = await tsImport( '../cli/chromium.ts', import.meta.url );
	const browser = await launchChromium();

	try {

		const page = await browser.newPage();
		await page.setViewport( { width: 960, height: 540 } );
		const errors = [];
		page.on( 'pageerror', ( error ) => errors.push( error.message ) );
		page.on( 'console', ( message ) => { if ( message.type() === 'error' ) errors.push( message.text() ); } );
		await page.goto( pageUrl, { waitUntil: 'load' } );
		await page.waitForFunction( () => window.__demo?.ready === true || ( window.__demo?.error ?? '' ) !== '', { timeout: 120_000 } );
		const demo = await page.evaluate( () => ( { ...window.__demo, frameMs: undefined } ) );
		if ( demo.error ) errors.push( `the page shows: ${demo.error}` );

		// A rendered room has several distinct colours; a blank canvas has one.
		const distinct = await page.evaluate( () => {

			const canvas = document.querySelector( 'canvas' );
			const probe = document.createElement( 'canvas' );
			probe.width = 64; probe.height = 36;
			const context = probe.getContext( '2d' );
			context.drawImage( canvas, 0, 0, 64, 36 );
			const data = context.getImageData( 0, 0, 64, 36 ).data;
			const colours = new Set();
			for ( let i = 0; i < data.length; i += 4 ) {

				colours.add( ( data[ i ] >> 4 ) << 8 | ( data[ i + 1 ] >> 4 ) << 4 | ( data[ i + 2 ] >> 4 ) );

			}

			return colours.size;

		} );

		mkdirSync( 'test/output', { recursive: true } );
		await page.screenshot( { path: 'test/output/basic.png' } );
		const status = await page.$eval( '#status', ( element ) => element.textContent );
		console.log( `start --check: ${pageUrl} rendered (${distinct} distinct colours; ${demo.probes} probes, ${demo.cells} cells, capture ${Math.round( demo.captureMs )} ms, character: ${demo.character}); screenshot test/output/basic.png` );
		void status;
		if ( errors.length > 0 ) throw new Error( `the page reported errors:\n  ${errors.join( '\n  ' )}` );
		if ( distinct < 8 ) throw new Error( `the frame looks blank (${distinct} distinct colours)` );
		return 0;

	} finally {

		await browser.close();

	}

}
