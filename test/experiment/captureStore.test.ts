import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { CaptureSource } from '../../scripts/experiment/CaptureSource.js';
import { CaptureStore, decodeBase64, encodeBase64 } from '../../scripts/experiment/captureStore.js';
import type { ExperimentSession } from '../../scripts/experiment/browser.js';
import type { LoadedScene } from '../../scripts/experiment/page.js';

const folder = mkdtempSync( join( tmpdir(), 'captures-' ) );
afterAll( () => rmSync( folder, { recursive: true, force: true } ) );

const SETTINGS = { resolution: 32, near: 0.02, far: 20 };
const SCENE: LoadedScene = {
	hand: { name: 'hand', positions: [ 0, 1, 0 ] }, grid: { min: [ - 1, 0, - 1 ], max: [ 1, 2, 1 ], counts: [ 2, 2, 2 ] },
	triangles: encodeBase64( new Float32Array( 9 ) ), sides: encodeBase64( new Int8Array( 1 ) ), info: { renderer: 'test' },
};

/** SH of a probe: its x, y, z repeated (each probe's own, so a wrong slice shows). */
function shOf( positions: ArrayLike<number> ): Float32Array {

	const sh = new Float32Array( 9 * positions.length );
	for ( let i = 0; i < sh.length; i ++ ) sh[ i ] = positions[ 3 * Math.floor( i / 27 ) + ( i % 3 ) ] + i % 27;
	return sh;

}

/** A browser stand-in that counts its captures. */
function fakeSession(): ExperimentSession & { captures: number; loads: number } {

	const session = {
		browserVersion: 'Fake/1', captures: 0, loads: 0,
		async load() {

			session.loads ++;
			return SCENE;

		},
		async vertexCandidates() {

			return new Float32Array( 0 );

		},
		async capture( positions: ArrayLike<number> ) {

			session.captures ++;
			return { sh: shOf( positions ), ms: positions.length };

		},
		async rasterize() {},
		async close() {},
	};
	return session;

}

describe( 'experiment: saved captures', () => {

	it( 'finds a capture by its exact positions and settings, or as the start of a longer one', () => {

		const store = new CaptureStore( 'basic' );
		const long = [ 0.1, 0.2, 0.3, 1 / 3, 2, 3, 4, 5, 6 ];
		store.add( 'fit points', SETTINGS, long, shOf( long ), 90 );
		const prefix = store.find( long.slice( 0, 6 ), SETTINGS )!;
		expect( prefix.prefix ).toBe( true );
		expect( prefix.ms ).toBeCloseTo( 60, 12 );
		expect( Array.from( prefix.sh ) ).toEqual( Array.from( shOf( long ).subarray( 0, 54 ) ) );
		expect( store.find( long, SETTINGS )!.prefix ).toBe( false );
		// Positions must match to the last bit, settings exactly.
		expect( store.find( [ 0.1, 0.2, 0.3 + 1e-16 ], SETTINGS ) ).toBe( null );
		expect( store.find( [ 0.1, 0.2, 0.30000000000000004 ], SETTINGS ) ).toBe( null );
		expect( store.find( long.slice( 3 ), SETTINGS ) ).toBe( null );
		expect( store.find( long, { ...SETTINGS, resolution: 16 } ) ).toBe( null );
		expect( store.find( [ ...long, 7, 8, 9 ], SETTINGS ) ).toBe( null );

	} );

	it( 'writes and reads back every capture bit for bit, and refuses another scene\'s file', () => {

		const file = join( folder, 'basic.captures.json' );
		const store = new CaptureStore( 'basic' );
		store.scene = SCENE;
		store.browser = 'Fake/1';
		const positions = [ Math.PI, - 1e-300, 1e300, 0.1, 0.2, 0.3 ];
		store.add( 'truth', SETTINGS, positions, shOf( positions ), 12.5 );
		store.write( file );
		const back = CaptureStore.read( file, 'basic' );
		expect( back.scene ).toEqual( SCENE );
		expect( back.browser ).toBe( 'Fake/1' );
		expect( back.captures ).toHaveLength( 1 );
		expect( Array.from( back.captures[ 0 ].positions ) ).toEqual( positions );
		expect( Array.from( back.find( positions, SETTINGS )!.sh ) ).toEqual( Array.from( shOf( positions ) ) );
		expect( () => CaptureStore.read( file, 'sponza' ) ).toThrow( /holds captures of basic, not sponza/ );
		writeFileSync( join( folder, 'other.json' ), '{"format":"something else"}' );
		expect( () => CaptureStore.read( join( folder, 'other.json' ), 'basic' ) ).toThrow( /not a version 1 captures file/ );
		expect( CaptureStore.read( join( folder, 'missing.json' ), 'basic' ).captures ).toHaveLength( 0 );
		expect( Array.from( decodeBase64( encodeBase64( new Int8Array( [ - 1, 0, 1 ] ) ), Int8Array ) ) ).toEqual( [ - 1, 0, 1 ] );

	} );

	it( 'captures in the browser only what is not saved, starting it at the first such capture', async () => {

		const session = fakeSession();
		let starts = 0;
		const store = new CaptureStore( 'basic' );
		const source = new CaptureSource( store, { offline: false, log: () => {}, start: async () => { starts ++; return session; } } );
		const a = [ 0, 0, 0, 1, 1, 1 ];
		store.add( 'saved', SETTINGS, a, shOf( a ), 5 );
		expect( ( await source.capture( a, SETTINGS, 'a' ) ).saved ).toBe( true );
		expect( starts ).toBe( 0 );
		const b = [ 2, 2, 2 ];
		const first = await source.capture( b, SETTINGS, 'b' );
		expect( first.saved ).toBe( false );
		expect( Array.from( first.sh ) ).toEqual( Array.from( shOf( b ) ) );
		expect( ( await source.capture( b, SETTINGS, 'b again' ) ).saved ).toBe( true );
		expect( [ starts, session.loads, session.captures, source.newCaptures ] ).toEqual( [ 1, 1, 1, 1 ] );
		expect( await source.scene() ).toEqual( SCENE );
		expect( source.browserVersion ).toBe( 'Fake/1' );

	} );

	it( 'captures only the new points of a longer set whose start is saved, and keeps the longer one', async () => {

		const session = fakeSession();
		const store = new CaptureStore( 'basic' );
		const short = [ 0, 0, 0, 1, 1, 1 ], long = [ ...short, 2, 2, 2, 3, 3, 3, 4, 4, 4 ];
		store.add( 'fit points', SETTINGS, short, shOf( short ), 2 );
		let asked: number[] = [];
		const source = new CaptureSource( store, { offline: false, log: () => {}, start: async () => ( {
			...session, async capture( positions: ArrayLike<number> ) {

				asked = Array.from( positions );
				return { sh: shOf( positions ), ms: positions.length / 3 };

			},
		} ) } );
		const got = await source.capture( long, SETTINGS, 'fit points' );
		expect( asked ).toEqual( long.slice( 6 ) );
		expect( Array.from( got.sh ) ).toEqual( Array.from( shOf( long ) ) );
		expect( got.ms ).toBe( 5 );
		expect( store.captures ).toHaveLength( 1 );
		expect( store.find( short, SETTINGS )!.prefix ).toBe( true );

	} );

	it( 'offline, never starts the browser: a missing capture is an error, the plot is not drawn', async () => {

		const store = new CaptureStore( 'basic' );
		store.scene = SCENE;
		const source = new CaptureSource( store, { offline: true, log: () => {}, start: async () => { throw new Error( 'started the browser' ); } } );
		expect( await source.scene() ).toBe( SCENE );
		await expect( source.capture( [ 1, 2, 3 ], SETTINGS, 'fit points' ) ).rejects.toThrow( /--offline: the saved captures do not hold "fit points" \(1 probes\)/ );
		expect( await source.rasterize( '<svg/>', 10, 10, join( folder, 'x.png' ) ) ).toBe( false );

	} );

	it( 'refuses to mix new captures with saved ones of a scene that has changed since', async () => {

		const session = fakeSession();
		const store = new CaptureStore( 'basic' );
		store.scene = { ...SCENE, triangles: encodeBase64( new Float32Array( [ 1, 2, 3, 4, 5, 6, 7, 8, 9 ] ) ) };
		const source = new CaptureSource( store, { offline: false, log: () => {}, start: async () => session } );
		await expect( source.capture( [ 1, 2, 3 ], SETTINGS, 'x' ) ).rejects.toThrow( /differs from the one of the saved captures/ );
		expect( session.captures ).toBe( 0 );

	} );

} );
