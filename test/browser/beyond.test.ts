import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import type { Page } from 'puppeteer-core';
import { ASSETS, browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';
import { readPNG, writePNG } from '../helpers/images.js';

/*
 * The demo toggles of the features beyond the paper (issue 6), in a real browser: each page loads
 * with them without errors, and each changes the picture the way it should. Screenshots go to
 * test/output/beyond/ for a look; the assertions are on measured pixels, not goldens.
 */

const SIZE = { width: 480, height: 270 };
const FIXED = 'resolution=16&hide=gui&probes=0&tonemapping=none';

interface Demo { ready: boolean; error: string; probes: number; cells: number; leakingCells?: number }
type Image = { width: number; height: number; data: Uint8Array };

async function openDemo( session: BrowserSession, path: string ): Promise<{ page: Page; errors: string[]; demo: Demo }> {

	const { page, errors } = await session.open( path, SIZE );
	await page.waitForFunction( 'window.__demo !== undefined && ( window.__demo.ready || window.__demo.error !== "" )', { timeout: 240_000 } );
	const demo = await page.evaluate( 'window.__demo' ) as Demo;
	return { page, errors, demo };

}

async function shot( page: Page, name: string ): Promise<Image> {

	const image = readPNG( Buffer.from( await page.screenshot( { type: 'png' } ) ) );
	mkdirSync( 'test/output/beyond', { recursive: true } );
	writePNG( `test/output/beyond/${name}.png`, image.width, image.height, image.data );
	return image;

}

/** sRGB byte → linear. */
const linear = ( v: number ) => { const c = v / 255; return c <= 0.04045 ? c / 12.92 : ( ( c + 0.055 ) / 1.055 ) ** 2.4; };

/** Mean linear RGB over a box [ left, top, right, bottom ] (CSS px = image px here). */
function meanRGB( image: Image, [ left, top, right, bottom ]: number[] ): number[] {

	const sum = [ 0, 0, 0 ];
	let count = 0;
	for ( let y = Math.max( 0, Math.floor( top ) ); y < Math.min( image.height, Math.ceil( bottom ) ); y ++ ) {

		for ( let x = Math.max( 0, Math.floor( left ) ); x < Math.min( image.width, Math.ceil( right ) ); x ++ ) {

			const i = 4 * ( y * image.width + x );
			for ( let c = 0; c < 3; c ++ ) sum[ c ] += linear( image.data[ i + c ] );
			count ++;

		}

	}

	return sum.map( ( s ) => s / count );

}

/** Screen box (CSS px) of half-size `r` around a world point, through the page's camera. */
async function screenBoxAt( page: Page, [ x, y, z ]: number[], r: number ): Promise<number[]> {

	const [ sx, sy ] = await page.evaluate( `( () => {
		const app = window.__demoApp, p = app.camera.position.clone().set( ${x}, ${y}, ${z} ).project( app.camera );
		const rect = app.renderer.domElement.getBoundingClientRect();
		return [ ( p.x + 1 ) / 2 * rect.width, ( 1 - p.y ) / 2 * rect.height ];
	} )()` ) as number[];
	return [ sx - r, sy - r, sx + r, sy + r ];

}

const hasSponza = existsSync( `${ASSETS}/sponza/sponza.obj` );

describe.skipIf( browserSkipReason !== '' )( `demo toggles beyond the paper, in Chromium${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser(); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	it( 'basic: guard, outer cells/nearest face, de-ringing, non-negative and bounces load without errors; one bounce brightens the indirect light on the ball', async () => {

		// A white ball in the room, indirect light only: a bounce adds the light that walls lit by
		// the probes send back, so the ball must get brighter (the Basic room's walls are bright).
		const query = `${FIXED}&t=4&view=indirect%20only&character=0&ball=0.6,0.8,0.4`;
		const plain = await openDemo( session, `examples/basic.html?${query}` );
		expect( plain.demo.error ).toBe( '' );
		const box = await plain.page.evaluate( 'window.__demoApp.ballScreenBox()' ) as number[];
		const inner = [ box[ 0 ] + 0.3 * ( box[ 2 ] - box[ 0 ] ), box[ 1 ] + 0.3 * ( box[ 3 ] - box[ 1 ] ), box[ 2 ] - 0.3 * ( box[ 2 ] - box[ 0 ] ), box[ 3 ] - 0.3 * ( box[ 3 ] - box[ 1 ] ) ];
		const before = meanRGB( await shot( plain.page, 'basic-plain' ), inner );
		await plain.page.close();

		const all = await openDemo( session, `examples/basic.html?${query}&guard=1&outside=nearest&deringing=0.1&nonnegative=1&bounces=1` );
		expect( all.demo.error ).toBe( '' );
		expect( all.errors ).toEqual( [] );
		expect( all.demo.leakingCells ).toBeGreaterThanOrEqual( 0 );
		await all.page.close();

		const bounced = await openDemo( session, `examples/basic.html?${query}&bounces=1` );
		expect( bounced.demo.error ).toBe( '' );
		const after = meanRGB( await shot( bounced.page, 'basic-bounce1' ), inner );
		await bounced.page.close();
		const luminance = ( c: number[] ) => 0.2126 * c[ 0 ] + 0.7152 * c[ 1 ] + 0.0722 * c[ 2 ];
		expect( luminance( after ) ).toBeGreaterThan( 1.05 * luminance( before ) );

	} );

	it( 'basic: dragging a probe updates the tetrahedralization in place and captures that probe alone; adding one too', async () => {

		const { page, demo } = await openDemo( session, `examples/basic.html?${FIXED}&t=4` );
		expect( demo.error ).toBe( '' );
		const result = await page.evaluate( `( async () => {
			const app = window.__demoApp, before = app.volume.positions[ 6 ], counts = [];
			app.params.edit = true;
			app.select( 2 );
			app.markers.children.find( ( m ) => m.userData.probe === 2 ).position.x += 0.2;
			const capture = app.volume.capture.bind( app.volume );
			app.volume.capture = ( r, s, o ) => { counts.push( o.indices ? o.indices.length : app.volume.count ); return capture( r, s, o ); };
			await app.moveSelectedProbe();
			const moved = app.volume.positions[ 6 ] - before, incremental = app.volume.interpolator.dynamic != null;
			const probes = app.volume.count;
			await app.addProbe();
			return { moved, incremental, counts, probes, after: app.volume.count, cells: app.volume.interpolator.cellCount, error: window.__demo.error };
		} )()` ) as { moved: number; incremental: boolean; counts: number[]; probes: number; after: number; cells: number; error: string };
		await page.close();
		expect( result.error ).toBe( '' );
		expect( result.moved ).toBeCloseTo( 0.2, 6 );
		expect( result.incremental ).toBe( true );
		expect( result.counts ).toEqual( [ 1, 1 ] ); // the moved probe, then the added one
		expect( result.after ).toBe( result.probes + 1 );
		expect( result.cells ).toBeGreaterThan( 0 );

	} );

	it( 'basic: a baked volume exported from the page and loaded back with ?volume= (no capture) draws the same picture', async () => {

		const captured = await openDemo( session, `examples/basic.html?${FIXED}&t=4` );
		expect( captured.demo.error ).toBe( '' );
		// The page's volume written by LightProbeVolumeExporter (from the dev server's sources), as the panel's "export baked volume" does.
		const bytes = await captured.page.evaluate( `( async () => {
			const { LightProbeVolumeExporter } = await import( '/src/runtime/LightProbeVolumeExporter.ts' );
			const file = new LightProbeVolumeExporter().parse( window.__demoApp.activeVolume, { precision: 'float16' } );
			return Array.from( new Uint8Array( file ) );
		} )()` ) as number[];
		const before = await shot( captured.page, 'basic-captured' );
		await captured.page.close();
		writeFileSync( 'test/output/beyond/basic.lpv', Uint8Array.from( bytes ) );

		const loaded = await openDemo( session, `examples/basic.html?${FIXED}&t=4&volume=/test/output/beyond/basic.lpv` );
		expect( loaded.demo.error ).toBe( '' );
		expect( loaded.errors ).toEqual( [] );
		expect( loaded.demo.probes ).toBe( captured.demo.probes );
		expect( loaded.demo.cells ).toBe( captured.demo.cells );
		const report = await loaded.page.evaluate( 'window.__demo' ) as { captureMs: number; loadMs: number };
		expect( report.captureMs ).toBe( 0 ); // nothing captured
		expect( report.loadMs ).toBeGreaterThan( 0 );
		const after = await shot( loaded.page, 'basic-baked' );
		await loaded.page.close();
		// float16 SH: a channel may move by a unit here and there, no more.
		let worst = 0;
		for ( let i = 0; i < before.data.length; i ++ ) if ( i % 4 !== 3 ) worst = Math.max( worst, Math.abs( before.data[ i ] - after.data[ i ] ) );
		expect( worst ).toBeLessThanOrEqual( 2 );

	} );

	it( 'two rooms: the probe light at a point in the blue room 0.5 m from the wall holds red from the other room; with zones or the guard toggled on, none', async () => {

		// What the page's volume hands an object there (volume.sample: the same zone and guard logic
		// as update()). Red can only come from room A's probes: room B's panel and spot are pure blue.
		// The screenshots (ball at that point, indirect light only) are for a look.
		const query = `${FIXED}&t=0&view=indirect%20only&character=0&ball=0.5,1,0`;
		const redShare: Record<string, number> = {};
		for ( const [ name, extra ] of [ [ 'neither', '' ], [ 'zones', '&zones=1' ], [ 'guard', '&guard=1' ] ] ) {

			const { page, demo, errors } = await openDemo( session, `examples/tworooms.html?${query}${extra}` );
			expect( demo.error ).toBe( '' );
			expect( errors ).toEqual( [] );
			await shot( page, `tworooms-${name}` );
			const l00 = await page.evaluate( 'Array.from( window.__demoApp.activeVolume.sample( [ 0.5, 1, 0 ] ).slice( 0, 3 ) )' ) as number[];
			redShare[ name ] = l00[ 0 ] / ( l00[ 0 ] + l00[ 2 ] );
			await page.close();

		}

		// With neither fix part of the weight is on room A's probes (0.18 measured before the rooms
		// were relit on 2026-12-02, not measured since); 0 with either.
		expect( redShare.neither ).toBeGreaterThan( 0.1 );
		expect( redShare.zones ).toBeLessThan( 0.05 );
		expect( redShare.guard ).toBeLessThan( 0.05 );

	} );

	it.skipIf( ! hasSponza )( `sponza: the floor lit per vertex or per pixel from nearby probes is warm like the courtyard; lit as one object it takes the sky-lit air's colour${hasSponza ? '' : ' — SKIPPED: Sponza assets missing (see README "Assets")'}`, async () => {

		// Indirect light only, so the floor shows the probe light alone. Lit as one object, the floors
		// (ground + gallery, one mesh) sample the probes at their bounding-box centre, 5.6 m up in the
		// open courtyard, where the sky dominates: bluish. Per vertex / per texel, each part of the
		// floor takes the probes near it, which see the sunlit, warm courtyard: a lower blue/red ratio.
		const ratios: Record<string, number> = {};
		for ( const floor of [ 'object', 'vertex', 'texture' ] ) {

			const { page, demo, errors } = await openDemo( session, `examples/sponza.html?${FIXED}&t=4&view=indirect%20only&character=0&floor=${floor}` );
			expect( demo.error ).toBe( '' );
			expect( errors ).toEqual( [] );
			const image = await shot( page, `sponza-floor-${floor}` );
			const rgb = meanRGB( image, await screenBoxAt( page, [ - 6, 0, 0 ], 12 ) );
			ratios[ floor ] = rgb[ 2 ] / rgb[ 0 ];
			await page.close();

		}

		expect( ratios.vertex ).toBeLessThan( 0.8 * ratios.object );
		expect( ratios.texture ).toBeLessThan( 0.8 * ratios.object );

	} );

} );
