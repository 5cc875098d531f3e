import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const source = resolve( dirname( fileURLToPath( import.meta.url ) ), '../../src' );

/** Every module a file loads at run time, followed through relative imports (type-only imports are erased). */
function runtimeImports( file: string, seen = new Set<string>() ): Set<string> {

	if ( seen.has( file ) ) return seen;
	seen.add( file );
	const text = readFileSync( file, 'utf8' );
	for ( const match of text.matchAll( /^\s*(?:import|export)\s+(?!type\b)[^'";]*?from\s+'([^']+)'/gm ) ) {

		const specifier = match[ 1 ];
		if ( specifier.startsWith( '.' ) ) runtimeImports( resolve( dirname( file ), specifier.replace( /\.js$/, '.ts' ) ), seen );
		else seen.add( specifier );

	}

	return seen;

}

describe( 'placement module split', () => {

	// The math and geometry must run in plain Node (tools, workers, tests) without three.js; only
	// the glue that reads Object3D trees may load it.
	const pure = [ 'placeGrid', 'candidatesFromVertices', 'classifyPoints', 'irradianceError', 'reduceProbes' ];
	const glue = [ 'placeFromMeshes', 'findProbeLocators' ];

	for ( const name of pure ) {

		it( `${name} loads nothing from three, directly or through its imports`, () => {

			const imports = [ ...runtimeImports( resolve( source, 'placement', `${name}.ts` ) ) ];
			expect( imports.filter( ( i ) => i === 'three' || i.startsWith( 'three/' ) ) ).toEqual( [] );

		} );

	}

	it( 'the glue modules are the ones that use three (so the check above can tell them apart)', () => {

		for ( const name of glue ) expect( runtimeImports( resolve( source, 'placement', `${name}.ts` ) ).has( 'three' ) || name === 'placeFromMeshes' ).toBe( true );
		expect( runtimeImports( resolve( source, 'placement', 'placeFromMeshes.ts' ) ).has( 'three' ) ).toBe( true ); // through gatherWorldGeometry

	} );

} );
