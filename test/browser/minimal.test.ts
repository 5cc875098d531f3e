import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from 'puppeteer-core';
import { browserSkipReason, startBrowser, type BrowserSession } from '../helpers/browser.js';
import { compareWithGolden, readPNG } from '../helpers/images.js';

/*
 * examples/minimal.html — the README's example, whole — in Chromium (WebGL2 on SwiftShader), in
 * the Basic room (red wall at −x, green at +x, blue at −z, grey floor, ceiling and front, one warm
 * lamp). Colour bleeding is checked numerically on the probe-lit white ball, read back from the
 * drawing buffer at points of its surface whose normals are known:
 * - by the red wall, the side facing it is redder than the side facing the green wall, and by the
 *   green wall the reverse: the probes carry the direction the coloured light comes from;
 * - the ball by the red wall is redder than the ball by the green wall, on the same (front) normal:
 *   the blend follows the object (one global light probe would shade both alike);
 * - with the lamp off after the capture, no direct light is left (the room has no other light, and
 *   a point light inside a closed box leaves no wall in shadow), so whatever lights the walls then
 *   is the probes' light: every wall must be visibly lit, the red wall red; with the level taken
 *   out of the volume as well, the same pixels must be black, which shows the light came from the probes.
 * The lamp-side direct light is warm (more red than green or blue), so it works against the first
 * check on the ball by the red wall (its lamp side faces the green wall).
 *
 * Golden: docs/images/minimal.png, the README's picture, looked at before it was accepted. Both
 * halves show the room from the front (red wall left, blue at the back, green right, grey floor
 * and ceiling, the lamp's bulb in front of the blue wall) and the white ball on the floor by the
 * red wall. Left, the lamp alone: the ball is white on top and black underneath, the walls lit
 * only where the lamp reaches them. Right, the lamp and the probes: the ball's side towards the
 * red wall is red, its underside lit grey by the floor, and the walls, floor and ceiling are lifted
 * by the light bounced between them, each tinted by its neighbours.
 */

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );
const SIZE = { width: 480, height: 270 };

type RGB = [ number, number, number ];
type Image = { width: number; height: number; data: Uint8Array };

type Point = [ number, number, number ];

/**
 * In the page: stops the example's loop, poses the ball and the lamp, draws a frame, reads back
 * the mean RGB (0..255) of 5 × 5 pixels around each world point. `unlit` draws it with the level
 * (`remove( scene )`), or the level and the ball, taken out of the volume, then puts them back.
 */
async function probeFrame( page: Page, pose: { ball: Point; lamp: boolean; unlit?: 'level' | 'all' }, points: Point[] ): Promise<RGB[]> {

	return page.evaluate( ( pose, points ) => {

		type Vec = { x: number; y: number; set( x: number, y: number, z: number ): Vec; project( camera: unknown ): Vec; clone(): Vec };
		const m = ( window as unknown as { minimal: {
			renderer: { setAnimationLoop( f: null ): void; render( s: unknown, c: unknown ): void; getContext(): WebGL2RenderingContext };
			scene: { getObjectByName( name: string ): unknown }; camera: unknown; lamp: { visible: boolean };
			volume: { update(): void; remove( o: unknown ): void; add( o: unknown ): void; getLighting( o: unknown ): string | null };
			character: { position: Vec };
		} } ).minimal;
		m.renderer.setAnimationLoop( null );
		m.character.position.set( ...pose.ball );
		m.lamp.visible = pose.lamp;
		// remove( scene ) drops every entry add( scene ) made: the room's materials are restored.
		// Only what the page registered is registered again after.
		const readd = { level: m.volume.getLighting( m.scene.getObjectByName( 'room' ) ) !== null, ball: m.volume.getLighting( m.character ) !== null };
		if ( pose.unlit !== undefined ) m.volume.remove( m.scene );
		if ( pose.unlit === 'all' ) m.volume.remove( m.character );
		m.volume.update();
		m.renderer.render( m.scene, m.camera );
		const gl = m.renderer.getContext();
		const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
		const pixels = new Uint8Array( 5 * 5 * 4 );
		const result = points.map( ( [ x, y, z ] ) => {

			const p = m.character.position.clone().set( x, y, z ).project( m.camera );
			const px = Math.round( ( p.x + 1 ) / 2 * w ) - 2, py = Math.round( ( p.y + 1 ) / 2 * h ) - 2;
			gl.readPixels( px, py, 5, 5, gl.RGBA, gl.UNSIGNED_BYTE, pixels );
			const sum = [ 0, 0, 0 ];
			for ( let i = 0; i < 25; i ++ ) for ( let c = 0; c < 3; c ++ ) sum[ c ] += pixels[ 4 * i + c ] / 25;
			return sum;

		} );
		if ( pose.unlit === 'all' && readd.ball ) m.volume.add( m.character );
		if ( pose.unlit !== undefined && readd.level ) m.volume.add( m.scene );
		return result;

	}, pose, points ) as Promise<RGB[]>;

}

const redness = ( [ r, g, b ]: RGB ) => r / ( g + b + 1 );
const greenness = ( [ r, g, b ]: RGB ) => g / ( r + b + 1 );
const luminance = ( [ r, g, b ]: RGB ) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

/** Two images of one height, left and right, in one. */
function sideBySide( left: Image, right: Image ): Image {

	const width = left.width + right.width, data = new Uint8Array( 4 * width * left.height );
	for ( let y = 0; y < left.height; y ++ ) {

		data.set( left.data.subarray( 4 * y * left.width, 4 * ( y + 1 ) * left.width ), 4 * y * width );
		data.set( right.data.subarray( 4 * y * right.width, 4 * ( y + 1 ) * right.width ), 4 * ( y * width + left.width ) );

	}

	return { width, height: left.height, data };

}

/** A point on the ball's surface (radius 0.3) with normal `n` (normalised here). */
function onBall( center: number[], n: number[] ): Point {

	const length = Math.hypot( n[ 0 ], n[ 1 ], n[ 2 ] );
	return [ 0, 1, 2 ].map( ( i ) => center[ i ] + 0.3 * 0.97 * n[ i ] / length ) as Point;

}

describe.skipIf( browserSkipReason !== '' )( `examples/minimal.html in Chromium${browserSkipReason ? ' — SKIPPED: ' + browserSkipReason : ''}`, () => {

	let session: BrowserSession;
	let page: Page;
	let errors: string[];

	beforeAll( async () => {

		session = await startBrowser();
		( { page, errors } = await session.open( 'examples/minimal.html', SIZE ) );
		await page.waitForFunction( () => 'minimal' in window, { timeout: 180_000 } );

	}, 240_000 );
	afterAll( async () => { await session?.close(); } );

	it( 'loads without errors, captures the probes and draws the room as in the README\'s picture (golden)', async () => {

		expect( errors ).toEqual( [] );
		const status = await page.$eval( '#status', ( element ) => element.textContent );
		expect( status ).toBe( '64 probes captured' );
		// As the README says: the ball lit as a moving object, the room (one 4 × 3 × 4 box, larger than
		// the probe spacing) per texel or vertex.
		const lighting = await page.evaluate( () => {

			const m = ( window as unknown as { minimal: {
				scene: { getObjectByName( name: string ): unknown }; character: unknown;
				volume: { getLighting( o: unknown ): string | null };
			} } ).minimal;
			return { ball: m.volume.getLighting( m.character ), room: m.volume.getLighting( m.scene.getObjectByName( 'room' ) ) };

		} );
		expect( lighting.ball ).toBe( 'dynamic' );
		expect( [ 'texture', 'vertex' ] ).toContain( lighting.room );
		// The loop stopped (SwiftShader draws a few frames a second), the ball posed by the red wall, no
		// text; the lamp alone (nothing in the volume), then the lamp and the probes.
		await page.evaluate( () => document.querySelectorAll<HTMLElement>( '#info, #status' ).forEach( ( e ) => { e.style.display = 'none'; } ) );
		const ball: Point = [ - 1.1, 0.3, 0.7 ];
		const shot = async () => readPNG( Buffer.from( await page.screenshot( { type: 'png' } ) ) );
		await probeFrame( page, { ball, lamp: true, unlit: 'all' }, [] );
		const lampOnly = await shot();
		await probeFrame( page, { ball, lamp: true }, [] );
		const withProbes = await shot();
		const result = compareWithGolden( 'minimal', resolve( ROOT, 'docs/images/minimal.png' ), sideBySide( lampOnly, withProbes ) );
		expect( result.ok, result.message ).toBe( true );

	} );

	it( 'colour bleeding on the ball: by the red wall its side facing it is redder, by the green wall its side facing it greener', async () => {

		for ( const lamp of [ true, false ] ) {

			const byRed: Point = [ - 1.2, 0.8, 0 ], byGreen: Point = [ 1.2, 0.8, 0 ];
			// Normals towards the red wall, towards the green wall (both turned to the camera), and to the front.
			const sides = [ [ - 1, 0, 0.7 ], [ 1, 0, 0.7 ], [ 0, 0, 1 ] ];
			const atBall = ( center: Point ) => probeFrame( page, { ball: center, lamp }, sides.map( ( n ) => onBall( center, n ) ) );
			const [ redSide, greenSide, front ] = await atBall( byRed );
			const [ redSide2, greenSide2, front2 ] = await atBall( byGreen );
			const rounded = ( list: RGB[] ) => list.map( ( rgb ) => rgb.map( Math.round ).join( ',' ) ).join( ' | ' );
			const what = `lamp ${lamp ? 'on' : 'off'}: by the red wall ${rounded( [ redSide, greenSide, front ] )}; `
				+ `by the green wall ${rounded( [ redSide2, greenSide2, front2 ] )}`;
			for ( const rgb of [ redSide, greenSide, front, redSide2, greenSide2, front2 ] ) {

				expect( luminance( rgb ), what ).toBeGreaterThan( 10 );

			}

			expect( redness( redSide ), what ).toBeGreaterThan( 1.1 * redness( greenSide ) );
			expect( greenness( greenSide2 ), what ).toBeGreaterThan( 1.1 * greenness( redSide2 ) );
			expect( redness( front ), what ).toBeGreaterThan( 1.05 * redness( front2 ) );
			expect( greenness( front2 ), what ).toBeGreaterThan( 1.05 * greenness( front ) );

		}

	} );

	it( 'with the lamp off after the capture, every wall is still lit, by the probes alone (black once the level leaves the volume)', async () => {

		// Points on the walls in view (the room spans x, z ∈ [−2, 2], y ∈ [0, 3]), the ball out of the way.
		const walls: Record<string, Point> = {
			red: [ - 1.99, 1.2, - 0.8 ], green: [ 1.99, 1.2, - 0.8 ], blue: [ 0.6, 1.4, - 1.99 ],
			floor: [ - 0.6, 0.01, - 1 ], ceiling: [ - 0.8, 2.99, - 1.2 ],
		};
		const ball: Point = [ 0, 0.3, 1.8 ];
		const lit = await probeFrame( page, { ball, lamp: false }, Object.values( walls ) );
		const unlit = await probeFrame( page, { ball, lamp: false, unlit: 'level' }, Object.values( walls ) );
		const what = Object.keys( walls ).map( ( name, i ) => `${name}: ${lit[ i ].map( Math.round )} / ${unlit[ i ].map( Math.round )}` )
			.join( '; ' );
		for ( let i = 0; i < lit.length; i ++ ) {

			expect( luminance( lit[ i ] ), what ).toBeGreaterThan( 12 );
			expect( Math.max( ...unlit[ i ] ), what ).toBeLessThan( 1 );

		}

		expect( redness( lit[ 0 ] ), what ).toBeGreaterThan( 1.5 );
		expect( greenness( lit[ 1 ] ), what ).toBeGreaterThan( 1.5 );

	} );

} );
