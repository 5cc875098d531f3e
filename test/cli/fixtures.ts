/**
 * Scene and layout files for the CLI tests, written into a temporary folder: a closed OBJ + MTL
 * room with one red wall and an emissive ceiling, an empty glTF, and a glTF floor lit by a
 * KHR_lights_punctual directional light.
 */

import { spawnSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The room's box: x, z ∈ [−2, 2], y ∈ [0, 3]. The red wall is x = −2, the white wall opposite is x = +2. */
export const ROOM = { min: [ - 2, 0, - 2 ], max: [ 2, 3, 2 ] };

/**
 * Writes room.obj and room.mtl: six inward-facing quads (counter-clockwise seen from inside), each
 * with its own material: red wall at x = −2, emissive white ceiling, white elsewhere.
 */
export function writeRoom( folder: string ): string {

	const [ x0, y0, z0 ] = ROOM.min, [ x1, y1, z1 ] = ROOM.max;
	// Corners listed counter-clockwise as seen from outside the room; the faces below take them in
	// reverse, so every wall faces inwards (a camera inside sees the front sides).
	const quads: [ string, number[][] ][] = [
		[ 'red', [ [ x0, y0, z0 ], [ x0, y0, z1 ], [ x0, y1, z1 ], [ x0, y1, z0 ] ] ], // x = −2
		[ 'white', [ [ x1, y0, z0 ], [ x1, y1, z0 ], [ x1, y1, z1 ], [ x1, y0, z1 ] ] ], // x = +2
		[ 'white', [ [ x0, y0, z0 ], [ x1, y0, z0 ], [ x1, y0, z1 ], [ x0, y0, z1 ] ] ], // floor
		[ 'ceiling', [ [ x0, y1, z0 ], [ x0, y1, z1 ], [ x1, y1, z1 ], [ x1, y1, z0 ] ] ], // ceiling
		[ 'white', [ [ x0, y0, z0 ], [ x0, y1, z0 ], [ x1, y1, z0 ], [ x1, y0, z0 ] ] ], // z = −2
		[ 'white', [ [ x0, y0, z1 ], [ x1, y0, z1 ], [ x1, y1, z1 ], [ x0, y1, z1 ] ] ], // z = +2
	];
	const lines = [ 'mtllib room.mtl' ];
	quads.forEach( ( [ material, corners ], q ) => {

		lines.push( `o wall${q}`, `usemtl ${material}` );
		for ( const [ x, y, z ] of corners ) lines.push( `v ${x} ${y} ${z}` );
		const base = 4 * q + 1;
		lines.push( `f ${base} ${base + 3} ${base + 2}`, `f ${base} ${base + 2} ${base + 1}` );

	} );
	writeFileSync( join( folder, 'room.obj' ), lines.join( '\n' ) + '\n' );
	writeFileSync( join( folder, 'room.mtl' ), [
		'newmtl red', 'Kd 0.8 0.05 0.05', '',
		'newmtl white', 'Kd 0.8 0.8 0.8', '',
		'newmtl ceiling', 'Kd 0 0 0', 'Ke 1 1 1', '',
	].join( '\n' ) );
	return join( folder, 'room.obj' );

}

/** An empty glTF scene (no nodes): a capture sees only the sky. */
export function writeEmptyGLTF( folder: string ): string {

	const file = join( folder, 'empty.gltf' );
	writeFileSync( file, JSON.stringify( { asset: { version: '2.0' }, scene: 0, scenes: [ { nodes: [] } ] } ) );
	return file;

}

/**
 * A glTF with a white 10 × 10 floor at y = 0 (facing up) and a KHR_lights_punctual directional
 * light pointing straight down; the geometry is in a separate floor.bin next to it.
 */
export function writeLitFloorGLTF( folder: string ): string {

	const positions = new Float32Array( [ - 5, 0, - 5, - 5, 0, 5, 5, 0, 5, 5, 0, - 5 ] );
	const normals = new Float32Array( [ 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0 ] );
	const indices = new Uint16Array( [ 0, 1, 2, 0, 2, 3 ] );
	const bin = Buffer.concat( [ Buffer.from( positions.buffer ), Buffer.from( normals.buffer ), Buffer.from( indices.buffer ) ] );
	writeFileSync( join( folder, 'floor.bin' ), bin );
	const gltf = {
		asset: { version: '2.0' },
		extensionsUsed: [ 'KHR_lights_punctual' ],
		extensions: { KHR_lights_punctual: { lights: [ { type: 'directional', color: [ 1, 1, 1 ], intensity: 3 } ] } },
		scene: 0,
		scenes: [ { nodes: [ 0, 1 ] } ],
		nodes: [
			{ mesh: 0, name: 'floor' },
			// −90° about x turns the light's −z axis to −y: straight down.
			{ name: 'sun', rotation: [ - Math.SQRT1_2, 0, 0, Math.SQRT1_2 ], translation: [ 0, 4, 0 ], extensions: { KHR_lights_punctual: { light: 0 } } },
		],
		meshes: [ { primitives: [ { attributes: { POSITION: 0, NORMAL: 1 }, indices: 2, material: 0 } ] } ],
		materials: [ { pbrMetallicRoughness: { baseColorFactor: [ 1, 1, 1, 1 ], metallicFactor: 0, roughnessFactor: 1 } } ],
		buffers: [ { uri: 'floor.bin', byteLength: bin.length } ],
		bufferViews: [
			{ buffer: 0, byteOffset: 0, byteLength: 48 },
			{ buffer: 0, byteOffset: 48, byteLength: 48 },
			{ buffer: 0, byteOffset: 96, byteLength: 12 },
		],
		accessors: [
			{ bufferView: 0, componentType: 5126, count: 4, type: 'VEC3', min: [ - 5, 0, - 5 ], max: [ 5, 0, 5 ] },
			{ bufferView: 1, componentType: 5126, count: 4, type: 'VEC3' },
			{ bufferView: 2, componentType: 5123, count: 6, type: 'SCALAR' },
		],
	};
	const file = join( folder, 'floor.gltf' );
	writeFileSync( file, JSON.stringify( gltf ) );
	return file;

}

/** Writes a layout JSON file. */
export function writeLayout( folder: string, name: string, layout: unknown ): string {

	const file = join( folder, name );
	writeFileSync( file, typeof layout === 'string' ? layout : JSON.stringify( layout ) );
	return file;

}

/**
 * The room's 10 probes: the corners of an inner box (8), one by the red wall, one by the white
 * wall opposite (indices 8 and 9).
 */
export const ROOM_PROBES = {
	name: 'room test layout',
	positions: [
		- 1.2, 0.5, - 1.2, 1.2, 0.5, - 1.2, - 1.2, 0.5, 1.2, 1.2, 0.5, 1.2,
		- 1.2, 2.4, - 1.2, 1.2, 2.4, - 1.2, - 1.2, 2.4, 1.2, 1.2, 2.4, 1.2,
		- 1.7, 1.5, 0, 1.7, 1.5, 0,
	],
	names: [ 'a', 'b', 'c', 'd', 'e', 'f', 'g', 'h', 'by red wall', 'by white wall' ],
	roles: [ 'bounce', 'bounce', 'bounce', 'bounce', 'fill', 'fill', 'fill', 'fill', 'bleed', 'bleed' ],
};

/** What a CLI run printed and returned. */
export interface CliRun {

	code: number | null;
	stdout: string;
	stderr: string;

}

/** The repository root (the CLI runs from here). */
export const ROOT = fileURLToPath( new URL( '../..', import.meta.url ) );

/**
 * Runs `node --import tsx cli/main.ts …args` as a child process, as a user would run the CLI.
 * @param env Extra environment variables.
 */
export function runCli( args: string[], env: Record<string, string> = {} ): CliRun {

	const result = spawnSync( process.execPath, [ '--import', 'tsx', 'cli/main.ts', ...args ], {
		cwd: ROOT, encoding: 'utf8', env: { ...process.env, ...env }, timeout: 280_000,
	} );
	return { code: result.status, stdout: result.stdout, stderr: result.stderr };

}

/**
 * Writes a constant Radiance .hdr panorama (16 × 8, flat RGBE scanlines) of radiance
 * 128 · 2^(129 − 128) / 255 = 256 / 255 in every channel, as three's HDRLoader decodes it.
 * @returns The file and its radiance.
 */
export function writeConstantHDR( folder: string ): { file: string; radiance: number } {

	const width = 16, height = 8;
	const header = Buffer.from( `#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ${height} +X ${width}\n`, 'latin1' );
	const pixels = Buffer.alloc( 4 * width * height );
	for ( let i = 0; i < width * height; i ++ ) pixels.set( [ 128, 128, 128, 129 ], 4 * i );
	const file = join( folder, 'constant sky.hdr' );
	writeFileSync( file, Buffer.concat( [ header, pixels ] ) );
	return { file, radiance: 128 * 2 / 255 };

}
