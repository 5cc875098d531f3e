import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

/** The README heading whose first code block is the WebGPURenderer example. */
export const WEBGPU_HEADING = '## On WebGPURenderer';

/** The lines of README.md's WebGPURenderer example: the first fenced code block after {@link WEBGPU_HEADING}. */
export function readmeWebGPUExample( root: string ): string[] {

	const lines = readFileSync( resolve( root, 'README.md' ), 'utf8' ).split( '\n' );
	const heading = lines.indexOf( WEBGPU_HEADING );
	if ( heading < 0 ) throw new Error( `readmeWebGPUExample: README.md has no ${WEBGPU_HEADING}` );
	const open = lines.findIndex( ( line, i ) => i > heading && line.startsWith( '```' ) );
	const close = lines.findIndex( ( line, i ) => i > open && line.startsWith( '```' ) );
	const next = lines.findIndex( ( line, i ) => i > heading && line.startsWith( '## ' ) );
	if ( open < 0 || close < 0 || ( next >= 0 && open > next ) ) throw new Error( `readmeWebGPUExample: no code block under ${WEBGPU_HEADING}` );
	const block = lines.slice( open + 1, close );
	if ( ! block.some( ( line ) => line.includes( '\'three-capture-lighting/webgpu\'' ) ) ) throw new Error( 'readmeWebGPUExample: the block does not import three-capture-lighting/webgpu' );
	return block;

}

/** The block split into its import lines (first) and the rest. */
function split( root: string ): { imports: string[]; body: string[] } {

	const lines = readmeWebGPUExample( root );
	const body = lines.findIndex( ( line ) => ! line.startsWith( 'import ' ) && line.trim() !== '' );
	return { imports: lines.slice( 0, body ), body: lines.slice( body ) };

}

/**
 * The README's WebGPURenderer example as a TypeScript module for `tsc --strict`: its lines, with the
 * objects it takes from the app around it (scene, camera, character) declared after the imports —
 * typed with `three/webgpu`'s classes, as a WebGPURenderer app has them.
 */
export function readmeWebGPUModule( root: string ): string {

	const { imports, body } = split( root );
	const declarations = [
		'import type { Mesh, PerspectiveCamera, Scene } from \'three/webgpu\';',
		'declare const scene: Scene, camera: PerspectiveCamera, character: Mesh;',
	];
	return [ ...imports, ...declarations, '', ...body, 'export {};', '' ].join( '\n' );

}

/** What a wrong call against the webgpu entry's types looks like (a canvas where the renderer goes): must not type-check. */
export const WRONG_WEBGPU = [
	'import { LightProbeVolume, placeGrid } from \'three-capture-lighting/webgpu\';',
	'declare const scene: import( \'three/webgpu\' ).Scene;',
	'const volume = new LightProbeVolume( { positions: placeGrid( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 2, 2, 2 ] ) } );',
	'await volume.capture( document.createElement( \'canvas\' ), scene );',
	'export {};',
	'',
].join( '\n' );

/** The radiance of the furnace room's walls (linear, every channel). */
export const FURNACE_RADIANCE = 0.5;

/**
 * A page module running the README's WebGPURenderer example verbatim but for one option: its imports,
 * then the app the example takes for granted — a closed box of radiance {@link FURNACE_RADIANCE}
 * (unlit `MeshBasicMaterial`, `BackSide`) around a white `MeshLambertMaterial` sphere, the character —
 * then the example's lines, the renderer getting `forceWebGL` from `?backend=webgl2`. After the
 * example's animation loop has drawn five frames, it stops the loop and draws one frame into a
 * HalfFloat target, reads the sphere's centre and a wall, removes the sphere from the volume and reads
 * its centre again; `window.result` gets the three pixels (linear RGB), or `{ error }`. On the WebGPU
 * backend, the loop's frames go into the target too (headless Chromium loses a WebGPU device that
 * presents to a canvas, docs/webgpu.md).
 */
export function readmeWebGPUPage( root: string ): string {

	const { imports, body } = split( root );
	const construct = /new THREE\.WebGPURenderer\( \{ /g;
	const code = body.join( '\n' );
	if ( ( code.match( construct ) ?? [] ).length !== 1 ) throw new Error( 'readmeWebGPUPage: the example does not construct one `new THREE.WebGPURenderer( { … } )`' );
	const app = [
		'const fail = ( error ) => { window.result = { error: String( error?.stack ?? error?.message ?? error ) }; };',
		'window.addEventListener( \'error\', ( event ) => fail( event.error ?? event.message ) );',
		'window.addEventListener( \'unhandledrejection\', ( event ) => fail( event.reason ) );',
		'const FORCE_WEBGL = new URLSearchParams( location.search ).get( \'backend\' ) === \'webgl2\';',
		'const scene = new THREE.Scene();',
		`const walls = new THREE.MeshBasicMaterial( { color: new THREE.Color( ${FURNACE_RADIANCE}, ${FURNACE_RADIANCE}, ${FURNACE_RADIANCE} ), side: THREE.BackSide } );`,
		'const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 4 ), walls );',
		'room.position.y = 1.5;',
		'scene.add( room );',
		'const character = new THREE.Mesh( new THREE.SphereGeometry( 0.3, 32, 16 ), new THREE.MeshLambertMaterial( { color: 0xffffff } ) );',
		'character.position.set( 0, 1.5, 0 );',
		'scene.add( character );',
		'const camera = new THREE.PerspectiveCamera( 50, 1, 0.1, 20 );',
		'camera.position.set( 0, 1.5, 1.5 );',
		'camera.lookAt( 0, 1.5, 0 );',
	];
	const after = [
		'const target = new THREE.RenderTarget( 64, 64, { type: THREE.HalfFloatType } );',
		'const draw = renderer.render.bind( renderer );',
		'let frames = 0;',
		'renderer.render = ( s, c ) => {',
		'	frames ++;',
		'	if ( ! renderer.backend.isWebGPUBackend ) return draw( s, c );',
		'	renderer.setRenderTarget( target ); draw( s, c ); renderer.setRenderTarget( null );',
		'};',
		'while ( frames < 5 ) await new Promise( ( resolve ) => setTimeout( resolve, 20 ) );',
		'renderer.setAnimationLoop( null );',
		'const read = async ( x, y ) => {',
		'	volume.update();',
		'	renderer.setRenderTarget( target ); draw( scene, camera ); renderer.setRenderTarget( null );',
		'	const data = await renderer.readRenderTargetPixelsAsync( target, x, y, 1, 1 );',
		'	return Array.from( data.slice( 0, 3 ), ( h ) => THREE.DataUtils.fromHalfFloat( h ) );',
		'};',
		'const sphere = await read( 32, 32 ), wall = await read( 2, 2 );',
		'const lighting = volume.getLighting( character );',
		'volume.remove( character );',
		'const unlit = await read( 32, 32 );',
		'window.result = { backend: renderer.backend.isWebGPUBackend ? \'webgpu\' : \'webgl2\', frames, lighting, sphere, wall, unlit };',
	];
	return [ ...imports, '', ...app, '', code.replace( construct, 'new THREE.WebGPURenderer( { forceWebGL: FORCE_WEBGL, ' ), '', ...after, '' ].join( '\n' );

}
