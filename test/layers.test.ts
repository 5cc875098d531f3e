import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

/*
 * The layers of src/: which folder may import which (imports run one way, from the three.js glue
 * down to the pure math), and which modules may load three.js. The pure folders must run in plain
 * Node (tools, workers, the CLI's codec) without three.js, directly or through their imports.
 */

const SOURCE = resolve( dirname( fileURLToPath( import.meta.url ) ), '../src' );

/** Layer → the layers its modules may import (besides their own). `root` is src/*.ts other than the entries. */
const ALLOWED: Record<string, readonly string[]> = {
	root: [],
	geometry: [ 'root' ],
	sh: [ 'root' ],
	tetrahedra: [ 'geometry', 'root' ],
	interpolation: [ 'tetrahedra', 'geometry', 'sh', 'root' ],
	io: [ 'tetrahedra', 'geometry', 'sh', 'root' ],
	fitting: [ 'interpolation', 'tetrahedra', 'geometry', 'sh', 'root' ],
	placement: [ 'fitting', 'interpolation', 'tetrahedra', 'geometry', 'sh', 'root' ],
	capture: [ 'sh', 'root' ],
	runtime: [ 'capture', 'io', 'placement', 'fitting', 'interpolation', 'tetrahedra', 'geometry', 'sh', 'root' ],
	gltf: [ 'io', 'root' ],
	// WebGPURenderer glue (three/webgpu, three/tsl), on top: the WebGL core reaches it only through hooks it installs.
	webgpu: [ 'runtime', 'capture', 'io', 'placement', 'fitting', 'interpolation', 'tetrahedra', 'geometry', 'sh', 'root' ],
};

/** The package entries: they only re-export, so they may import any layer. */
const ENTRIES = [ 'index.ts', 'math.ts', 'format.ts', 'capture.ts', 'lightProbeGrid.ts', 'webgpu.ts' ];

/** Folders that must not load three.js, and the three.js glue files allowed inside them. */
const PURE = [ 'root', 'geometry', 'sh', 'tetrahedra', 'interpolation', 'fitting', 'io', 'placement' ];
const GLUE_IN_PURE = [ 'geometry/gatherWorldGeometry.ts', 'placement/placeFromMeshes.ts', 'placement/findProbeLocators.ts' ];

function sourceFiles( folder: string ): string[] {

	return readdirSync( folder ).flatMap( ( name ) => {

		const path = resolve( folder, name );
		if ( statSync( path ).isDirectory() ) return sourceFiles( path );
		return name.endsWith( '.ts' ) ? [ path ] : [];

	} );

}

/** The layer of a file: its folder under src/, or `root`, or `entry`. */
function layerOf( file: string ): string {

	const path = relative( SOURCE, file ).replace( /\\/g, '/' );
	if ( ! path.includes( '/' ) ) return ENTRIES.includes( path ) ? 'entry' : 'root';
	return path.split( '/' )[ 0 ];

}

/** Import specifiers of a file; `runtimeOnly` leaves out `import type` / `export type` (erased by TypeScript). */
function importsOf( file: string, runtimeOnly: boolean ): string[] {

	const text = readFileSync( file, 'utf8' );
	const pattern = runtimeOnly
		? /^\s*(?:import|export)\s+(?!type\b)[^'";]*?from\s+'([^']+)'|^\s*import\s+'([^']+)'/gm
		: /^\s*(?:import|export)\s+[^'";]*?from\s+'([^']+)'|^\s*import\s+'([^']+)'/gm;
	return [ ...text.matchAll( pattern ) ].map( ( match ) => match[ 1 ] ?? match[ 2 ] );

}

function resolveImport( file: string, specifier: string ): string {

	return resolve( dirname( file ), specifier.replace( /\.js$/, '.ts' ) );

}

/** Every relative import that runs against the layers, as "from → to" lines. */
function layerViolations(
	files: readonly string[], allowed: Record<string, readonly string[]>, imports: ( file: string ) => string[]
): string[] {

	const violations: string[] = [];
	for ( const file of files ) {

		const from = layerOf( file );
		if ( from === 'entry' ) continue;
		if ( ! ( from in allowed ) ) {

			violations.push( `${relative( SOURCE, file )}: folder "${from}" is not a known layer (add it to ALLOWED)` );
			continue;

		}

		for ( const specifier of imports( file ) ) {

			if ( ! specifier.startsWith( '.' ) ) continue;
			const to = layerOf( resolveImport( file, specifier ) );
			if ( to !== from && ! allowed[ from ].includes( to ) ) violations.push( `${relative( SOURCE, file )} (${from}) imports ${specifier} (${to})` );

		}

	}

	return violations;

}

/** Every module a file loads at run time, followed through relative imports. */
function runtimeClosure( file: string, seen = new Set<string>() ): Set<string> {

	if ( seen.has( file ) ) return seen;
	seen.add( file );
	for ( const specifier of importsOf( file, true ) ) {

		if ( specifier.startsWith( '.' ) ) runtimeClosure( resolveImport( file, specifier ), seen );
		else seen.add( specifier );

	}

	return seen;

}

const loadsThree = ( file: string ): boolean => [ ...runtimeClosure( file ) ].some( ( i ) => i === 'three' || i.startsWith( 'three/' ) );

describe( 'layers of src/', () => {

	const files = sourceFiles( SOURCE );

	it( 'every folder is a known layer and no import (type imports included) runs against the layers', () => {

		expect( layerViolations( files, ALLOWED, ( file ) => importsOf( file, false ) ) ).toEqual( [] );

	} );

	it( 'the check catches a wrong-way import (interpolation → runtime) and an unknown folder', () => {

		const fake = ( path: string ): string => resolve( SOURCE, path );
		const graph: Record<string, string[]> = {
			[ fake( 'interpolation/A.ts' ) ]: [ '../runtime/B.js', '../tetrahedra/C.js' ],
			[ fake( 'newFolder/D.ts' ) ]: [],
		};
		expect( layerViolations( Object.keys( graph ), ALLOWED, ( file ) => graph[ file ] ) ).toEqual( [
			'interpolation/A.ts (interpolation) imports ../runtime/B.js (runtime)',
			'newFolder/D.ts: folder "newFolder" is not a known layer (add it to ALLOWED)',
		] );

	} );

	const pure = files.filter( ( file ) => PURE.includes( layerOf( file ) ) && ! GLUE_IN_PURE.includes( relative( SOURCE, file ).replace( /\\/g, '/' ) ) );

	it( `the pure folders (${PURE.join( ', ' )}) load no three.js, directly or through their imports`, () => {

		expect( pure.length ).toBeGreaterThan( 30 );
		expect( pure.filter( loadsThree ).map( ( file ) => relative( SOURCE, file ) ) ).toEqual( [] );

	} );

	it( 'the three.js glue files inside pure folders, and capture/runtime, do load three; gltf uses three\'s types (so the checks above can tell them apart)', () => {

		for ( const glue of GLUE_IN_PURE ) expect( loadsThree( resolve( SOURCE, glue ) ), glue ).toBe( true );
		for ( const layer of [ 'capture', 'runtime' ] ) {

			const inLayer = files.filter( ( file ) => layerOf( file ) === layer );
			expect( inLayer.length, layer ).toBeGreaterThan( 0 );
			expect( inLayer.some( loadsThree ), layer ).toBe( true );

		}

		const gltf = files.filter( ( file ) => layerOf( file ) === 'gltf' );
		expect( gltf.some( ( file ) => importsOf( file, false ).some( ( i ) => i.startsWith( 'three/' ) ) ) ).toBe( true );

	} );

	it( 'three\'s node system (three/webgpu, three/tsl) is loaded only by src/webgpu and its entry, never by the main entry', () => {

		const loadsNodes = ( file: string ): boolean => [ ...runtimeClosure( file ) ].some( ( i ) => i === 'three/webgpu' || i === 'three/tsl' );
		const outside = files.filter( ( file ) => layerOf( file ) !== 'webgpu' && layerOf( file ) !== 'entry' && importsOf( file, false ).some( ( i ) => i === 'three/webgpu' || i === 'three/tsl' ) );
		expect( outside.map( ( file ) => relative( SOURCE, file ) ) ).toEqual( [] );
		for ( const entry of ENTRIES.filter( ( name ) => name !== 'webgpu.ts' ) ) expect( loadsNodes( resolve( SOURCE, entry ) ), entry ).toBe( false );

	} );

	it( 'the pure core loads in plain Node without three.js installed in the module graph', async () => {

		// Importing the math entry must not evaluate three: a pure module that imported it would
		// still pass the static check if it did so through a dynamic import.
		const math = await import( '../src/math.js' );
		expect( typeof math.tetrahedralize ).toBe( 'function' );
		expect( loadsThree( resolve( SOURCE, 'math.ts' ) ) ).toBe( false );

	} );

} );
