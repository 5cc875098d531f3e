// Vite plugin: serves the third-party scene assets (Sponza, Sibenik, the Fox, panoramas) at
// /assets/ from the folder named by CAPTURE_LIGHTING_ASSETS, or ../shared/assets next to the
// repository. They are never copied into the repository; pages say so when the folder is missing.
import { createReadStream, existsSync, statSync } from 'node:fs';
import { extname, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath( new URL( '..', import.meta.url ) );

/** The asset folder: $CAPTURE_LIGHTING_ASSETS, else ../shared/assets beside the repository. */
export const assetsFolder = resolve( process.env.CAPTURE_LIGHTING_ASSETS ?? resolve( root, '../shared/assets' ) );

const TYPES = { '.obj': 'text/plain', '.mtl': 'text/plain', '.glb': 'model/gltf-binary', '.hdr': 'application/octet-stream', '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.json': 'application/json' };

export function assetsPlugin() {

	return {
		name: 'three-capture-lighting-assets',
		configureServer( server ) {

			server.middlewares.use( '/assets', ( request, response, next ) => {

				const path = decodeURIComponent( ( request.url ?? '/' ).split( '?' )[ 0 ] );
				const file = resolve( assetsFolder, '.' + path );
				if ( ! file.startsWith( assetsFolder + sep ) || ! existsSync( file ) || ! statSync( file ).isFile() ) {

					response.statusCode = 404;
					response.end( `asset not found: ${path} (asset folder: ${assetsFolder}; set CAPTURE_LIGHTING_ASSETS)` );
					return;

				}

				response.setHeader( 'Content-Type', TYPES[ extname( file ).toLowerCase() ] ?? 'application/octet-stream' );
				createReadStream( file ).pipe( response );
				void next;

			} );

		},
	};

}
