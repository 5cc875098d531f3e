import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { inspect } from '../../cli/inspect.js';
import { CliError } from '../../cli/errors.js';
import { encodeBakedVolume } from '../../src/io/index.js';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { ROOM_PROBES, runCli } from './fixtures.js';

/*
 * `inspect` on baked files whose SH are known: the room layout's 10 probes, probe 3 and 7 black
 * (all zeros), probe 5 ringing (L00 0.1, L10 1: E(−z) = c4·0.1 − 2·c2 = −0.9347), the rest lit
 * (L00 = 1 + probe/10 in every channel, nothing else), so the statistics are known by hand.
 */

const C2 = 0.511664, C4 = 0.886227;

let dir = '';

beforeAll( () => {

	dir = mkdtempSync( join( tmpdir(), 'capture-lighting-inspect-' ) );

} );

afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

/** The room volume with the SH above (or all lit when `clean`), written as float32 binary. */
function writeVolume( name: string, clean = false ): string {

	const positions = Float64Array.from( ROOM_PROBES.positions );
	const { tetrahedra, neighbors } = tetrahedralize( positions );
	const sh = new Float32Array( 27 * 10 );
	for ( let p = 0; p < 10; p ++ ) {

		for ( let c = 0; c < 3; c ++ ) {

			if ( ! clean && ( p === 3 || p === 7 ) ) continue;
			sh[ 27 * p + c ] = ! clean && p === 5 ? 0.1 : 1 + p / 10;
			if ( ! clean && p === 5 ) sh[ 27 * p + 6 + c ] = 1; // L10 (coefficient 2)

		}

	}

	const file = join( dir, name );
	writeFileSync( file, new Uint8Array( encodeBakedVolume( { positions, sh, tetrahedra, neighbors }, { precision: 'float32' } ) ) );
	return file;

}

describe( 'capture-lighting inspect: SH statistics and warnings', () => {

	it( 'prints L00 min / median / max, the black and negative probes, and the warnings on stderr; exit 0', () => {

		const file = writeVolume( 'mixed.bin' );
		const run = runCli( [ 'inspect', file ] );
		expect( run.code, run.stderr ).toBe( 0 );
		const row = ( label: string ) => new RegExp( `^  ${label.replace( /[()/]/g, '\\$&' )} +(.*)$`, 'm' ).exec( run.stdout )?.[ 1 ];
		// L00 over the 10 probes: 0, 0 (black), 0.1 (ringing), 1.0, 1.1, 1.2, 1.4, 1.6, 1.8, 1.9 → median (1.1 + 1.2) / 2.
		const channel = 'R 0 / 1.15 / 1.9';
		expect( row( 'L00 min/median/max' ) ).toBe( `${channel}, ${channel.replace( 'R', 'G' )}, ${channel.replace( 'R', 'B' )}` );
		// The brightest L00 is 1.9: black below 1.9e-3.
		expect( row( 'black probes' ) ).toBe( '2 of 10 (L00 ≤ 0.0019 in every channel, 1/1000 of the brightest; probes 3, 7)' );
		// Probe 5's lowest E over its mean: (c4·0.1 − 2·c2) / (c4·0.1) = −10.5 → "-1100 %".
		expect( row( 'negative irradiance' ) ).toBe( '1 of 10 (E(n) below −1/256 of the probe\'s mean for some normal n; probe 5; lowest E(n) '
			+ `${Number( ( C4 * 0.1 - 2 * C2 ).toPrecision( 4 ) )} at probe 5, lowest E(n)/mean -1100 % at probe 5)` );
		const warnings = run.stderr.trim().split( '\n' );
		expect( warnings ).toHaveLength( 2 );
		expect( warnings[ 0 ] ).toMatch( /^warning: 2 of 10 probes are black \(L00 ≤ 0\.0019 in every channel; probes 3, 7\): .*inside walls/ );
		expect( warnings[ 1 ] ).toMatch( new RegExp( /^warning: 1 of 10 probes have negative irradiance \(E\(n\) down to -1100 % of the probe's mean at probe 5, /
			.source + /lowest E\(n\) -0\.9347 at probe 5; probe 5\): .*--non-negative/.source ) );

	} );

	it( 'strict: the summary and the warnings, then a CliError with exit code 1; a clean file passes strict', () => {

		const lines: string[] = [], warnings: string[] = [];
		const options = { strict: true, log: ( text: string ) => lines.push( text ), warn: ( text: string ) => warnings.push( text ) };
		let error: unknown;
		try {

			inspect( writeVolume( 'strict.bin' ), options );

		} catch ( caught ) {

			error = caught;

		}

		expect( error ).toBeInstanceOf( CliError );
		expect( ( error as CliError ).exitCode ).toBe( 1 );
		expect( ( error as CliError ).message ).toMatch( /strict\.bin: 2 warnings \(see above\) and --strict was given\.$/ );
		expect( lines.join( '\n' ) ).toMatch( /black probes +2 of 10/ );
		expect( warnings ).toHaveLength( 2 );

		lines.length = 0;
		warnings.length = 0;
		const clean = inspect( writeVolume( 'clean.bin', true ), options );
		expect( clean.warnings ).toEqual( [] );
		expect( warnings ).toEqual( [] );
		expect( lines.join( '\n' ) ).toMatch( /black probes +0 of 10 \(L00 ≤ 0\.0019/ );
		expect( lines.join( '\n' ) ).toMatch( /negative irradiance +0 of 10 .*lowest E\(n\) 0\.8862 at probe 0, lowest E\(n\)\/mean 100 % at probe 0\)/ );

	} );

} );
