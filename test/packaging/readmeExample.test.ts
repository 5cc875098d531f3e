import { describe, expect, it } from 'vitest';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Color } from 'three';
import { parseArguments } from '../../cli/args.js';
import { readLayout, tetrahedralizeLayout } from '../../cli/layout.js';
import { parseLayoutLights } from '../../cli/layoutLights.js';
import { createBasicRoom } from '../../scenes/basic.js';
import { EXAMPLE_BEGIN, minimalExample, readmeBlocks, readmeExample } from './readmeExample.js';

/*
 * The README's first example and examples/minimal.ts (run and checked in Chromium by
 * test/browser/minimal.test.ts) are the same code, so the README shows what is tested: the
 * README's block is import lines, comments, then minimal.ts's lines between "// README example"
 * and "// end", verbatim. The README's layout.json is read by the CLI's own layout reader and is
 * the Basic room's (scenes/basic.json, createBasicRoom's lamp), and its command lines parse.
 */

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );

describe( 'README.md\'s example is examples/minimal.ts\'s code', () => {

	it( 'the block ends with minimal.ts\'s example lines, verbatim', () => {

		const readme = readmeExample( ROOT ), { example } = minimalExample( ROOT );
		expect( example.length ).toBeGreaterThan( 5 );
		expect( example.some( ( line ) => line.includes( 'await volume.capture(' ) ) ).toBe( true );
		expect( readme.slice( readme.length - example.length ) ).toEqual( example );

	} );

	it( 'every line before them is an import of minimal.ts, a comment or blank', () => {

		const readme = readmeExample( ROOT ), { all, example } = minimalExample( ROOT );
		const head = readme.slice( 0, readme.length - example.length );
		const imports = head.filter( ( line ) => line.startsWith( 'import ' ) );
		expect( imports.length, 'the block imports the library' ).toBeGreaterThan( 0 );
		for ( const line of imports ) expect( all.slice( 0, all.indexOf( EXAMPLE_BEGIN ) ), 'an import minimal.ts does not have' ).toContain( line );
		expect( head.filter( ( line ) => ! line.startsWith( 'import ' ) && ! /^\s*(\/\/.*)?$/.test( line ) ) ).toEqual( [] );

	} );

	it( 'minimal.ts\'s library calls outside the example are only the test hook and the status line', () => {

		// A call on the volume outside the marked lines would be code the README does not show.
		const { all, example } = minimalExample( ROOT );
		const begin = all.indexOf( EXAMPLE_BEGIN );
		const outside = [ ...all.slice( 0, begin ), ...all.slice( begin + example.length + 2 ) ];
		const calls = outside.filter( ( line ) => /\bvolume\.\w+\s*\(/.test( line ) );
		expect( calls ).toEqual( [] );

	} );

} );

describe( 'README.md\'s baking section', () => {

	it( 'its layout.json is a valid CLI layout: the Basic room\'s 13 probes (scenes/basic.json) and its lamp (createBasicRoom)', () => {

		const block = readmeBlocks( ROOT ).find( ( b ) => b.lang === 'json' && b.text.includes( '"positions"' ) );
		expect( block, 'a ```json block with "positions"' ).toBeDefined();
		const dir = mkdtempSync( join( tmpdir(), 'readme-layout-' ) );
		try {

			const file = join( dir, 'layout.json' );
			writeFileSync( file, block!.text );
			const layout = readLayout( file );
			const basic = JSON.parse( readFileSync( resolve( ROOT, 'scenes/basic.json' ), 'utf8' ) );
			expect( Array.from( layout.positions ) ).toEqual( basic.positions );
			expect( layout.names ).toEqual( basic.names );
			expect( layout.roles ).toEqual( basic.roles );
			expect( tetrahedralizeLayout( file, layout ) ).not.toBeNull();

			const lights = parseLayoutLights( file, layout.lights );
			const { lamp } = createBasicRoom();
			expect( lights.length ).toBe( 1 );
			const light = lights[ 0 ];
			if ( light.type !== 'point' ) throw new Error( `expected a point light, got ${light.type}` );
			expect( light.position ).toEqual( lamp.position.toArray() );
			expect( light.intensity ).toBe( lamp.intensity );
			expect( light.decay ).toBe( lamp.decay );
			expect( new Color( light.color ).getHex() ).toBe( lamp.color.getHex() );

		} finally {

			rmSync( dir, { recursive: true, force: true } );

		}

	} );

	it( 'its capture-lighting command lines parse: bake (a binary file at the defaults, resolution 32, float32), inspect, --help', () => {

		const commands = readmeBlocks( ROOT ).filter( ( b ) => b.lang === 'sh' ).flatMap( ( b ) => b.text.split( '\n' ) )
			.map( ( line ) => line.replace( /#.*$/, '' ).trim() ).filter( ( line ) => line.startsWith( 'npx capture-lighting ' ) )
			.map( ( line ) => line.split( /\s+/ ).slice( 2 ) );
		expect( commands.map( ( argv ) => argv[ 0 ] ) ).toEqual( [ 'bake', 'inspect', '--help' ] );
		const [ bake, inspect, help ] = commands.map( ( argv ) => parseArguments( argv, {} ) );
		expect( bake ).toMatchObject( { command: 'bake', options: { scene: 'level.glb', probes: 'layout.json', out: 'level.lpv' } } );
		expect( bake ).toMatchObject( { options: { format: 'bin', resolution: 32, precision: 'float32' } } );
		expect( inspect ).toMatchObject( { command: 'inspect', file: 'level.lpv' } );
		expect( help ).toMatchObject( { command: 'help' } );

	} );

} );
