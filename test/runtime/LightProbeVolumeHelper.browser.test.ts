/**
 * The demo pages draw their probes with LightProbeVolumeHelper (examples/common/ProbeMarkers.ts),
 * in a real browser (Chromium, WebGL2 on SwiftShader): the Basic page shows one sphere per probe,
 * the tetrahedra and the fox's cell, with no console errors; a click on a probe's ball selects
 * that probe for editing (the drag then moves it and its ball); the balls' centre pixels are the
 * captured probes' E(n)/π for the normal facing the camera, as in the headless-gl test. The
 * screenshot goes to test/output/LightProbeVolumeHelper/ for a look.
 */

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { mkdirSync } from 'node:fs';
import type { Page } from 'puppeteer-core';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';
import { readPNG, writePNG } from '../helpers/images.js';

const SIZE = { width: 480, height: 270 };

async function openBasic( session: BrowserSession ): Promise<{ page: Page; errors: string[] }> {

	// No tone mapping, so a ball's pixels are its probe's E(n)/π in sRGB, comparable with the SH.
	const { page, errors } = await session.open( 'examples/basic.html?resolution=16&hide=gui&t=4&tonemapping=none', SIZE );
	await page.waitForFunction( 'window.__demo !== undefined && ( window.__demo.ready || window.__demo.error !== "" )', { timeout: 240_000 } );
	expect( await page.evaluate( 'window.__demo.error' ) ).toBe( '' );
	return { page, errors };

}

/** Two animation frames: the page's loop has drawn what the last evaluate changed. */
async function frames( page: Page ): Promise<void> {

	await page.evaluate( 'new Promise( ( done ) => requestAnimationFrame( () => requestAnimationFrame( done ) ) )' );

}

describe.skipIf( browserSkipReason !== '' )( `the demo's probe markers are a LightProbeVolumeHelper, in Chromium${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	beforeAll( async () => { session = await startBrowser(); }, 60_000 );
	afterAll( async () => { await session?.close(); } );

	it( 'Basic: a sphere per probe, the tetrahedra, the fox\'s cell; a click on a ball selects its probe for dragging', async () => {

		const { page, errors } = await openBasic( session );
		await page.evaluate( 'window.__demoApp.params.showCells = true' );
		await frames( page );
		const state = await page.evaluate( `( () => {
			const app = window.__demoApp, helper = app.markers.parent.children.find( ( c ) => c.type === 'LightProbeVolumeHelper' );
			return {
				helpers: app.markers.parent.children.filter( ( c ) => c.type === 'LightProbeVolumeHelper' ).length,
				spheres: helper.probes.count, probes: app.volume.count, handles: app.markers.children.length,
				segments: helper.cells.geometry.getAttribute( 'position' ).count / 2, cellProbes: helper.cell.probeCount,
				cellSegments: helper.cell.geometry.drawRange.count / 2,
			};
		} )()` ) as Record<string, number>;
		const image = readPNG( Buffer.from( await page.screenshot( { type: 'png' } ) ) );
		mkdirSync( 'test/output/LightProbeVolumeHelper', { recursive: true } );
		writePNG( 'test/output/LightProbeVolumeHelper/basic.png', image.width, image.height, image.data );
		// Looked at (test/output/LightProbeVolumeHelper/basic.png): the red/blue/green room, 13 small
		// probe balls at the ceiling, floor corners, walls and front, the faint grey tetrahedra
		// between them and a yellow tetrahedron around the fox (feet on the floor, its cell's lower
		// vertex the floor-centre probe). The balls look warm grey, the ceiling one brightest: what
		// the camera sees of each is its side facing the room's white-lit middle; the side facing a
		// wall (red for the probe by the red wall: E(−x)/π = 139, 30, 24 in sRGB) faces away from it.
		// The last part of this test checks the pixels against the SH.
		expect( state.helpers ).toBe( 1 );
		expect( state.spheres ).toBe( state.probes );
		expect( state.handles ).toBe( state.probes );
		expect( state.segments ).toBeGreaterThan( state.probes );
		expect( state.cellProbes ).toBe( 4 ); // the fox is inside the probes' hull
		expect( state.cellSegments ).toBe( 6 );

		// Pick the probe nearest to the camera that is on screen; click the centre of its ball.
		const target = await page.evaluate( `( () => {
			const app = window.__demoApp, rect = app.renderer.domElement.getBoundingClientRect();
			let best = null;
			for ( const handle of app.markers.children ) {
				const p = handle.position.clone().project( app.camera );
				if ( Math.abs( p.x ) > 0.9 || Math.abs( p.y ) > 0.9 || p.z > 1 ) continue;
				const distance = handle.position.distanceTo( app.camera.position );
				if ( ! best || distance < best.distance ) best = { probe: handle.userData.probe, distance, x: rect.left + ( p.x + 1 ) / 2 * rect.width, y: rect.top + ( 1 - p.y ) / 2 * rect.height };
			}
			app.params.edit = true;
			return best;
		} )()` ) as { probe: number; x: number; y: number };
		expect( target ).not.toBeNull();
		await page.mouse.click( target.x, target.y );
		// The drag, as the gizmo does it: the selected marker moves, then moveSelectedProbe().
		const moved = await page.evaluate( `( async () => {
			const app = window.__demoApp, before = app.volume.positions[ 3 * ${target.probe} ];
			const marker = app.markers.children.find( ( m ) => m.userData.probe === ${target.probe} );
			marker.position.x += 0.1;
			await new Promise( ( done ) => requestAnimationFrame( () => requestAnimationFrame( done ) ) );
			const helper = app.markers.parent.children.find( ( c ) => c.type === 'LightProbeVolumeHelper' );
			const ballDuringDrag = helper.probes.instanceMatrix.array[ 16 * ${target.probe} + 12 ];
			await app.moveSelectedProbe();
			return { moved: app.volume.positions[ 3 * ${target.probe} ] - before, ballDuringDrag: ballDuringDrag - before };
		} )()` ) as { moved: number; ballDuringDrag: number };
		expect( moved.ballDuringDrag ).toBeCloseTo( 0.1, 5 ); // the ball followed the handle before the volume changed
		expect( moved.moved ).toBeCloseTo( 0.1, 6 ); // the clicked probe was the one selected, and moved

		// Centre pixels of five balls the camera sees unobstructed (ceiling, floor centre, the red-wall
		// and green-wall probes, the front one) against E(n)/π of their SH (three's basis constants),
		// n the ball's normal where the ray through that pixel's centre meets it. The balls are made
		// larger (0.45) for this, so that a pixel spans a small angle of the sphere; the probe is
		// deselected and the lines hidden, so that neither the transform gizmo nor an edge in front
		// of a ball is drawn over it.
		const colours = await page.evaluate( `( () => {
			const app = window.__demoApp, renderer = app.renderer, volume = app.volume, gl = renderer.getContext(), camera = app.camera;
			const helper = app.markers.parent.children.find( ( c ) => c.type === 'LightProbeVolumeHelper' );
			renderer.setAnimationLoop( null );
			app.select( - 1 );
			helper.size = 0.45;
			helper.tetrahedra = false;
			helper.highlight( null );
			let scene = app.markers; while ( scene.parent ) scene = scene.parent;
			renderer.setRenderTarget( null );
			renderer.render( scene, camera );
			const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight, r = helper.size;
			const srgb = ( a ) => 255 * ( a <= 0.0031308 ? 12.92 * a : 1.055 * Math.pow( a, 1 / 2.4 ) - 0.055 );
			return [ 0, 5, 6, 7, 9 ].map( ( i ) => {
				const centre = camera.position.clone().fromArray( volume.positions, 3 * i ), p = centre.clone().project( camera );
				const px = Math.floor( ( p.x + 1 ) / 2 * w ), py = Math.floor( ( p.y + 1 ) / 2 * h );
				const direction = camera.position.clone().set( ( px + 0.5 ) / w * 2 - 1, ( py + 0.5 ) / h * 2 - 1, 0.5 ).unproject( camera ).sub( camera.position ).normalize();
				const toCentre = centre.clone().sub( camera.position ), along = toCentre.dot( direction );
				const t = along - Math.sqrt( r * r - ( toCentre.lengthSq() - along * along ) );
				const [ x, y, z ] = camera.position.clone().addScaledVector( direction, t ).sub( centre ).normalize().toArray();
				const s = volume.sh.subarray( 27 * i );
				const expected = [ 0, 1, 2 ].map( ( c ) => srgb( Math.max( 0, s[ c ] * 0.886227
					+ 2 * 0.511664 * ( s[ 3 + c ] * y + s[ 6 + c ] * z + s[ 9 + c ] * x )
					+ 2 * 0.429043 * ( s[ 12 + c ] * x * y + s[ 15 + c ] * y * z + s[ 21 + c ] * x * z )
					+ s[ 18 + c ] * ( 0.743125 * z * z - 0.247708 ) + s[ 24 + c ] * 0.429043 * ( x * x - y * y ) ) / Math.PI ) );
				const pixel = new Uint8Array( 4 );
				gl.readPixels( px, py, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel );
				return { probe: i, actual: Array.from( pixel.subarray( 0, 3 ) ), expected };
			} );
		} )()` ) as { probe: number; actual: number[]; expected: number[] }[];
		for ( const { probe, actual, expected } of colours ) {

			const difference = Math.max( ...actual.map( ( v, c ) => Math.abs( v - expected[ c ] ) ) );
			expect( difference, `probe ${probe}: ${actual} vs ${expected.map( Math.round )}` ).toBeLessThanOrEqual( 2 );

		}

		expect( errors ).toEqual( [] );
		await page.close();

	} );

} );
