import { resolve } from 'node:path';
import type { Alias } from 'vite';

/** The package's subpath entries (`three-capture-lighting/<name>`), each built from src/<name>.ts. */
export const SUBPATH_ENTRIES: readonly string[] = [ 'math', 'format', 'capture', 'lightProbeGrid', 'webgpu' ];

/**
 * Vite aliases for a dev server over the repository at `root`: `three-capture-lighting` and its
 * subpaths resolve to the sources in src/, `@scenes` to scenes/ — what the examples, scenes and
 * test pages import, as vite.config.ts resolves them for `npm start`.
 * @param root The repository's folder.
 */
export function libraryAliases( root: string ): Alias[] {

	return [
		{ find: /^three-capture-lighting$/, replacement: resolve( root, 'src/index.ts' ) },
		{ find: new RegExp( `^three-capture-lighting/(${SUBPATH_ENTRIES.join( '|' )})$` ), replacement: resolve( root, 'src/$1.ts' ) },
		{ find: '@scenes', replacement: resolve( root, 'scenes' ) },
	];

}
