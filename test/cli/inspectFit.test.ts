import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { inspect } from '../../cli/inspect.js';
import { bakedVolumeToJSON, encodeBakedVolume, type BakedFit, type BakedVolumeInput } from '../../src/io/index.js';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { ROOM_PROBES } from './fixtures.js';

/*
 * `inspect` says whether a file holds gradient probes and how its SH were fitted (the GRAD and
 * FITS sections of docs/format.md, version 1.1); a file without them says so too.
 */

let dir = '';

beforeAll( () => {

	dir = mkdtempSync( join( tmpdir(), 'capture-lighting-inspect-fit-' ) );

} );

afterAll( () => rmSync( dir, { recursive: true, force: true } ) );

/** The room layout lit evenly (L00 = 1), as a volume the codec accepts. */
function roomVolume(): BakedVolumeInput {

	const positions = Float64Array.from( ROOM_PROBES.positions );
	const { tetrahedra, neighbors } = tetrahedralize( positions );
	const sh = new Float32Array( 27 * 10 );
	for ( let p = 0; p < 10; p ++ ) sh.fill( 1, 27 * p, 27 * p + 3 );
	return { positions, sh, tetrahedra, neighbors };

}

/** The summary rows of `inspect` on the file, by label. */
function rows( name: string, bytes: Uint8Array ): Map<string, string> {

	const file = join( dir, name );
	writeFileSync( file, bytes );
	const lines: string[] = [];
	inspect( file, { log: ( text ) => lines.push( text ), warn: () => {} } );
	const out = new Map<string, string>();
	for ( const line of lines.join( '\n' ).split( '\n' ) ) {

		const match = /^ {2}(\S(?:.*?\S)?) {2,}(.*)$/.exec( line );
		if ( match ) out.set( match[ 1 ], match[ 2 ] );

	}

	return out;

}

describe( 'capture-lighting inspect: gradients and fit record', () => {

	const fit: BakedFit = { samples: 1596, gradients: true, lambda: 0.03125, gradientLambda: 0.5, crossValidationError: 0.10904, source: 'dense captures at spacing 0.5' };

	it( 'a 1.1 file with gradients and a fit record: both rows say what is stored, in the SH precision', () => {

		const volume = { ...roomVolume(), gradients: new Float32Array( 81 * 10 ).fill( 0.25 ), fit };
		const half = rows( 'fitted.lpv', new Uint8Array( encodeBakedVolume( volume, { precision: 'float16' } ) ) );
		expect( half.get( 'gradients' ) ).toBe( 'stored (81 per probe, float16)' );
		expect( half.get( 'fit' ) ).toBe( 'least squares to 1596 samples, SH and gradients; λ 0.03125, gradient λ 0.5; '
			+ 'cross-validation error 10.9 % of the mean irradiance; samples: dense captures at spacing 0.5' );
		const json = rows( 'fitted.json', new TextEncoder().encode( JSON.stringify( bakedVolumeToJSON( volume ) ) ) );
		expect( json.get( 'gradients' ) ).toBe( 'stored (81 per probe, JSON decimal)' );

	} );

	it( 'a plain fit with λ given, and a file without either: what the rows say', () => {

		const given: BakedFit = { samples: 64, gradients: false, lambda: 2, gradientLambda: 0, crossValidationError: null };
		const plainFit = rows( 'plain-fit.lpv', new Uint8Array( encodeBakedVolume( { ...roomVolume(), fit: given } ) ) );
		expect( plainFit.get( 'gradients' ) ).toBe( 'none (plain probes)' );
		expect( plainFit.get( 'fit' ) ).toBe( 'least squares to 64 samples, SH only; λ 2; λ given (no cross-validation)' );
		const captured = rows( 'captured.lpv', new Uint8Array( encodeBakedVolume( roomVolume() ) ) );
		expect( captured.get( 'gradients' ) ).toBe( 'none (plain probes)' );
		expect( captured.get( 'fit' ) ).toBe( 'none (the SH are the captured ones)' );
		expect( captured.get( 'probes' ) ).toBe( '10' );

	} );

} );
