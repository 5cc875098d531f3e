import { existsSync, readFileSync, statSync } from 'node:fs';
import { dirname, extname, resolve } from 'node:path';
import { CliError } from './errors.js';

/**
 * Checks a scene file before a browser is started, so bad input fails in milliseconds: it exists,
 * its extension is one the bake page loads, and the files it names beside it are there (an OBJ's
 * mtllib, a .gltf's buffers and images).
 * @returns Which loader reads it, and the absolute paths of the scene and the files it names (which
 * the output must not overwrite).
 * @throws {CliError} exit code 2, naming the file.
 */
export function checkScene( file: string ): { kind: 'gltf' | 'obj'; files: string[] } {

	if ( ! existsSync( file ) ) throw new CliError( `scene ${file} not found.` );
	if ( ! statSync( file ).isFile() ) throw new CliError( `scene ${file} is not a file.` );
	const extension = extname( file ).toLowerCase();
	if ( extension !== '.glb' && extension !== '.gltf' && extension !== '.obj' ) {

		throw new CliError( `scene ${file} has the extension "${extname( file ) || '(none)'}"; expected .glb, .gltf or .obj.` );

	}

	const folder = dirname( resolve( file ) );
	const files = [ resolve( file ) ];
	const missing = ( what: string, name: string ) => new CliError( `scene ${file} needs ${what} ${name}, which is not in ${folder}.` );

	if ( extension === '.obj' ) {

		const mtl = /^mtllib\s+(.+?)\s*$/m.exec( readFileSync( file, 'utf8' ) )?.[ 1 ];
		if ( mtl ) {

			if ( ! existsSync( resolve( folder, mtl ) ) ) throw missing( 'its material library', mtl );
			files.push( resolve( folder, mtl ) );

		}

		return { kind: 'obj', files };

	}

	if ( extension === '.gltf' ) {

		let json: { buffers?: { uri?: string }[]; images?: { uri?: string }[] };
		try {

			json = JSON.parse( readFileSync( file, 'utf8' ) );

		} catch ( error ) {

			throw new CliError( `scene ${file} is not valid glTF JSON (${( error as Error ).message}).` );

		}

		const uris = [ ...( json.buffers ?? [] ), ...( json.images ?? [] ) ].map( ( entry ) => entry?.uri ).filter( ( uri ): uri is string => typeof uri === 'string' && ! uri.startsWith( 'data:' ) );
		for ( const uri of uris ) {

			let path: string;
			try {

				path = decodeURIComponent( uri );

			} catch {

				path = uri;

			}

			if ( /^[a-z]+:\/\//i.test( uri ) ) continue;
			if ( ! existsSync( resolve( folder, path ) ) ) throw missing( 'the file', path );
			files.push( resolve( folder, path ) );

		}

	} else {

		const header = readFileSync( file ).subarray( 0, 4 ).toString( 'latin1' );
		if ( header !== 'glTF' ) throw new CliError( `scene ${file} is not a binary glTF file (it does not start with "glTF").` );

	}

	return { kind: 'gltf', files };

}
