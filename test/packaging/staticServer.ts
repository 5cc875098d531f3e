import { createServer, type Server } from 'node:http';
import { existsSync, readFileSync, statSync } from 'node:fs';
import { extname, join, normalize, sep } from 'node:path';
import type { AddressInfo } from 'node:net';

const TYPES: Record<string, string> = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json' };

/**
 * Serves a built page's folder on 127.0.0.1 (a secure context: WebGPU needs one), as any static host
 * would: files by path, `/` as index.html, 404 otherwise (204 for the favicon browsers ask for).
 */
export async function serveFolder( folder: string ): Promise<{ url: string; close(): Promise<void> }> {

	const root = normalize( folder ) + sep;
	const server: Server = createServer( ( request, response ) => {

		const pathname = decodeURIComponent( new URL( request.url ?? '/', 'http://127.0.0.1' ).pathname );
		const path = normalize( join( root, pathname.endsWith( '/' ) ? pathname + 'index.html' : pathname ) );
		if ( pathname === '/favicon.ico' ) return void response.writeHead( 204 ).end();
		if ( ! path.startsWith( root ) || ! existsSync( path ) || ! statSync( path ).isFile() ) return void response.writeHead( 404 ).end();
		response.writeHead( 200, { 'content-type': TYPES[ extname( path ) ] ?? 'application/octet-stream' } ).end( readFileSync( path ) );

	} );
	await new Promise<void>( ( resolve ) => server.listen( 0, '127.0.0.1', resolve ) );
	const { port } = server.address() as AddressInfo;
	return {
		url: `http://127.0.0.1:${port}/`,
		close: () => new Promise<void>( ( resolve ) => server.close( () => resolve() ) ),
	};

}
