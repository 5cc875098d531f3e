import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

/** The comment in README.md right before the example's code block. */
export const README_MARKER = '<!-- example: examples/minimal.ts -->';

/** The comments in examples/minimal.ts around the lines that are the README's. */
export const EXAMPLE_BEGIN = '// README example';
export const EXAMPLE_END = '// end';

/** The lines of README.md's example: the fenced code block after {@link README_MARKER}. */
export function readmeExample( root: string ): string[] {

	const lines = readFileSync( resolve( root, 'README.md' ), 'utf8' ).split( '\n' );
	const marker = lines.indexOf( README_MARKER );
	if ( marker < 0 ) throw new Error( `readmeExample: README.md has no ${README_MARKER}` );
	const open = lines.findIndex( ( line, i ) => i > marker && line.startsWith( '```' ) );
	const close = lines.findIndex( ( line, i ) => i > open && line.startsWith( '```' ) );
	if ( open !== marker + 1 || close < 0 ) throw new Error( `readmeExample: no code block right after ${README_MARKER}` );
	return lines.slice( open + 1, close );

}

/** The code blocks of README.md in order: their info string (`sh`, `js`, `json` …) and text. */
export function readmeBlocks( root: string ): { lang: string; text: string }[] {

	const blocks: { lang: string; text: string }[] = [];
	const pattern = /^```(\w*)\n([\s\S]*?)^```$/gm;
	const readme = readFileSync( resolve( root, 'README.md' ), 'utf8' );
	for ( let match = pattern.exec( readme ); match !== null; match = pattern.exec( readme ) ) {

		blocks.push( { lang: match[ 1 ], text: match[ 2 ] } );

	}

	return blocks;

}

/** examples/minimal.ts: all its lines, and those between {@link EXAMPLE_BEGIN} and {@link EXAMPLE_END}. */
export function minimalExample( root: string ): { all: string[]; example: string[] } {

	const all = readFileSync( resolve( root, 'examples/minimal.ts' ), 'utf8' ).split( '\n' );
	const begin = all.indexOf( EXAMPLE_BEGIN ), end = all.indexOf( EXAMPLE_END );
	if ( begin < 0 || end < begin ) throw new Error( `minimalExample: examples/minimal.ts has no ${EXAMPLE_BEGIN} … ${EXAMPLE_END} lines` );
	return { all, example: all.slice( begin + 1, end ) };

}

/**
 * The README's example as a TypeScript module for `tsc --strict`: its lines, with the objects it
 * takes from the app around it (renderer, scene, camera, character) declared after the imports.
 */
export function readmeExampleModule( root: string ): string {

	const lines = readmeExample( root );
	const body = lines.findIndex( ( line ) => ! line.startsWith( 'import ' ) && line.trim() !== '' );
	const declarations = [
		'import type { Mesh, PerspectiveCamera, Scene, WebGLRenderer } from \'three\';',
		'declare const renderer: WebGLRenderer, scene: Scene, camera: PerspectiveCamera, character: Mesh;',
	];
	return [ ...lines.slice( 0, body ), ...declarations, '', ...lines.slice( body ), 'export {};', '' ].join( '\n' );

}
