import { describe, expect, it } from 'vitest';
import {
	CHROMIUM_ARGS, DEFAULT_CHROMIUM, WEBGPU_ARG, checkChromium, chromiumArgs, importPuppeteer, launchChromium, resolveChromiumPath,
} from '../../cli/chromium.js';

// The launcher's rules, without starting a browser: the browser and CLI tests launch it.
describe( 'cli/chromium: which Chromium, with which flags', () => {

	it( 'the path: explicit, else CHROME_PATH, else CHROMIUM_PATH, else /usr/bin/chromium; empty values count as unset', () => {

		const both = { CHROME_PATH: '/a/chrome', CHROMIUM_PATH: '/b/chromium' };
		expect( resolveChromiumPath( '/x/chromium', both ) ).toEqual( { path: '/x/chromium', source: 'explicit' } );
		expect( resolveChromiumPath( undefined, both ) ).toEqual( { path: '/a/chrome', source: 'CHROME_PATH' } );
		const onlyChromium = { CHROMIUM_PATH: '/b/chromium' };
		expect( resolveChromiumPath( null, onlyChromium ) ).toEqual( { path: '/b/chromium', source: 'CHROMIUM_PATH' } );
		expect( resolveChromiumPath( undefined, {} ) ).toEqual( { path: DEFAULT_CHROMIUM, source: 'default' } );
		expect( DEFAULT_CHROMIUM ).toBe( '/usr/bin/chromium' );
		const emptyChrome = { CHROME_PATH: '', CHROMIUM_PATH: '/b/chromium' };
		expect( resolveChromiumPath( '', emptyChrome ) ).toEqual( { path: '/b/chromium', source: 'CHROMIUM_PATH' } );
		expect( resolveChromiumPath( '', { CHROME_PATH: '', CHROMIUM_PATH: '' } ).source ).toBe( 'default' );

	} );

	it( 'a missing executable is reported with its path and where it came from, never replaced by the next rule', () => {

		expect( checkChromium( process.execPath, 'explicit' ) ).toBe( '' );
		const missing = '/nonexistent/chromium';
		const start = new RegExp( '^Chromium not found at /nonexistent/chromium; '
			+ 'install it \\(apt install chromium\\) or pass --browser <path> \\(or set CHROME_PATH\\)\\. ' );
		expect( checkChromium( missing, 'explicit' ) ).toMatch( start );
		expect( checkChromium( missing, 'explicit' ) ).toMatch( /Tried the explicit path .*overrides CHROME_PATH and CHROMIUM_PATH\.$/ );
		expect( checkChromium( missing, 'CHROME_PATH' ) ).toMatch( /Tried \$CHROME_PATH/ );
		expect( checkChromium( missing, 'CHROMIUM_PATH' ) ).toMatch( /Tried \$CHROMIUM_PATH .*CHROME_PATH not set/ );
		expect( checkChromium( missing, 'default' ) ).toMatch( /Tried the default .*CHROME_PATH and CHROMIUM_PATH not set/ );
		expect( checkChromium( missing ) ).toMatch( /The path is --browser, else CHROME_PATH, else CHROMIUM_PATH, else \/usr\/bin\/chromium\.$/ );

	} );

	it( 'launchChromium rejects a missing executable before loading puppeteer, naming itself, even when CHROME_PATH exists', async () => {

		await expect( launchChromium( { browser: '/nonexistent/chromium', env: { CHROME_PATH: process.execPath } } ) )
			.rejects.toThrow( /^launchChromium: Chromium not found at \/nonexistent\/chromium; .*Tried the explicit path/ );
		await expect( launchChromium( { env: { CHROMIUM_PATH: '/nonexistent/b' } } ) )
			.rejects.toThrow( /^launchChromium: Chromium not found at \/nonexistent\/b; .*Tried \$CHROMIUM_PATH/ );

	} );

	it( 'flags: WebGL2 on SwiftShader without a sandbox, then WebGPU when asked, then the caller\'s', () => {

		const swiftShader = [ '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox' ];
		for ( const flag of swiftShader ) expect( CHROMIUM_ARGS ).toContain( flag );
		expect( chromiumArgs() ).toEqual( [ ...CHROMIUM_ARGS ] );
		expect( chromiumArgs() ).not.toContain( WEBGPU_ARG );
		expect( WEBGPU_ARG ).toBe( '--enable-unsafe-webgpu' );
		const extra = '--window-size=1280,720';
		expect( chromiumArgs( { webgpu: true, args: [ extra ] } ) ).toEqual( [ ...CHROMIUM_ARGS, WEBGPU_ARG, extra ] );

	} );

	it( 'importPuppeteer gives puppeteer-core\'s launcher (a dev dependency here)', async () => {

		expect( typeof ( await importPuppeteer() ).launch ).toBe( 'function' );

	} );

} );
