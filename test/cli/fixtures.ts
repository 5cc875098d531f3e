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

/**
 * scenes/basic.ts's room (the paper's Basic scene) as files: a 4 × 3 × 4 room (x, z ∈ [−2, 2],
 * y ∈ [0, 3]) with a red wall at x = −2, a green one at x = +2, a blue one at z = −2, grey floor,
 * ceiling and front wall, all single-sided quads facing inwards, and a closed light-grey block
 * standing on the floor (so shadows change what the probes see). Colours are the demo's sRGB hex
 * values. No light: the tests add basic.ts's lamp, {@link CORNELL_LAMP}.
 */
export const CORNELL_ROOM = {
	min: [ - 2, 0, - 2 ], max: [ 2, 3, 2 ],
	walls: [
		{ name: 'red', color: 0xd02020, normal: [ 1, 0, 0 ] },
		{ name: 'green', color: 0x30c030, normal: [ - 1, 0, 0 ] },
		{ name: 'ceiling', color: 0xaaaaaa, normal: [ 0, - 1, 0 ] },
		{ name: 'floor', color: 0x888888, normal: [ 0, 1, 0 ] },
		{ name: 'front', color: 0xcccccc, normal: [ 0, 0, - 1 ] },
		{ name: 'blue', color: 0x2040e0, normal: [ 0, 0, 1 ] },
	],
	block: { name: 'block', color: 0xcccccc, min: [ 0.3, 0, - 0.9 ], max: [ 1.1, 1.2, - 0.1 ] },
};

/** basic.ts's lamp: a warm point light of 12 cd under the ceiling, decay 2, no cut-off. */
export const CORNELL_LAMP = { position: [ 0.2, 2.1, 0.3 ], intensity: 12, color: 0xfff2e0 };

/** `--point` for {@link CORNELL_LAMP}. */
export const CORNELL_LAMP_FLAG = '0.2,2.1,0.3,12,#fff2e0';

/** Probes of the Cornell room: by the red, green and blue walls, above the floor, under the ceiling, beside the block. */
export const CORNELL_PROBES = {
	name: 'cornell test layout',
	positions: [ - 1.5, 1.5, 0, 1.5, 1.5, 0, 0, 1.5, - 1.5, 0, 0.3, 0.5, 0, 2.7, 0, 0.7, 0.4, 0.6, - 0.8, 0.8, 1.2 ],
	names: [ 'by red wall', 'by green wall', 'by blue wall', 'floor', 'ceiling', 'beside block', 'front left' ],
};

/** One quad: its material and four corners in counter-clockwise order seen from the side it faces. */
interface Quad { material: string; corners: number[][] }

/** The room's walls and the block's six faces as quads facing the given normals (walls inwards, block outwards). */
function cornellQuads(): Quad[] {

	const quads: Quad[] = [];
	const box = ( min: number[], max: number[], material: ( face: number ) => string, inwards: boolean ) => {

		for ( let axis = 0; axis < 3; axis ++ ) {

			for ( const side of [ 0, 1 ] ) {

				// The face at min (side 0) or max (side 1) of `axis`; its outward normal points along ∓/± axis.
				const u = ( axis + 1 ) % 3, v = ( axis + 2 ) % 3;
				const corner = ( a: number, b: number ) => {

					const p = [ 0, 0, 0 ];
					p[ axis ] = side ? max[ axis ] : min[ axis ];
					p[ u ] = a ? max[ u ] : min[ u ];
					p[ v ] = b ? max[ v ] : min[ v ];
					return p;

				};

				// ( u, v ) is right-handed with the axis, so this order faces +axis.
				let corners = [ corner( 0, 0 ), corner( 1, 0 ), corner( 1, 1 ), corner( 0, 1 ) ];
				const facesPlus = ( side === 1 ) !== inwards;
				if ( ! facesPlus ) corners = corners.reverse();
				quads.push( { material: material( 2 * axis + side ), corners } );

			}

		}

	};

	const { walls, block } = CORNELL_ROOM;
	// Faces in box order: −x, +x, −y, +y, −z, +z; walls by their normal (the wall at −x faces +x).
	const wallAt = ( face: number ) => walls.find( ( wall ) => wall.normal[ face >> 1 ] === ( face & 1 ? - 1 : 1 ) )!.name;
	box( CORNELL_ROOM.min, CORNELL_ROOM.max, wallAt, true );
	box( block.min, block.max, () => block.name, false );
	return quads;

}

/** sRGB components 0..1 of a hex colour. */
function srgb( hex: number ): number[] {

	return [ ( hex >> 16 & 255 ) / 255, ( hex >> 8 & 255 ) / 255, ( hex & 255 ) / 255 ];

}

const colorOf = ( name: string ) => name === 'block' ? CORNELL_ROOM.block.color : CORNELL_ROOM.walls.find( ( wall ) => wall.name === name )!.color;

/**
 * Writes the Cornell room as an OBJ: with `mtl`, cornell.obj + cornell.mtl (one Kd per surface,
 * no Ks or Ns, as an exporter writes a diffuse material); without, cornell-vc.obj with the same
 * colours as vertex colours (`v x y z r g b`) and no mtllib line. `emitter` (with `mtl`) adds a
 * 0.4 × 0.4 panel facing down just under the ceiling above the room's centre, with `Ke` = `emitter`
 * in every channel (cornell-emitter.obj): a small, bright source that rings in 9 SH coefficients.
 */
export function writeCornellOBJ( folder: string, { mtl, emitter = 0 }: { mtl: boolean; emitter?: number } ): string {

	const name = mtl ? ( emitter > 0 ? 'cornell-emitter' : 'cornell' ) : 'cornell-vc';
	const lines = mtl ? [ `mtllib ${name}.mtl` ] : [];
	const quads = cornellQuads();
	if ( emitter > 0 ) quads.push( { material: 'emitter', corners: [ [ - 0.2, 2.98, - 0.2 ], [ 0.2, 2.98, - 0.2 ], [ 0.2, 2.98, 0.2 ], [ - 0.2, 2.98, 0.2 ] ] } );
	quads.forEach( ( { material, corners }, q ) => {

		lines.push( `o ${material}${q}` );
		if ( mtl ) lines.push( `usemtl ${material}` );
		const color = mtl ? '' : ' ' + srgb( colorOf( material ) ).map( ( c ) => c.toFixed( 6 ) ).join( ' ' );
		for ( const [ x, y, z ] of corners ) lines.push( `v ${x} ${y} ${z}${color}` );
		const base = 4 * q + 1;
		lines.push( `f ${base} ${base + 1} ${base + 2}`, `f ${base} ${base + 2} ${base + 3}` );

	} );
	writeFileSync( join( folder, `${name}.obj` ), lines.join( '\n' ) + '\n' );
	if ( mtl ) {

		const materials = [ ...CORNELL_ROOM.walls, CORNELL_ROOM.block ];
		const text = materials.map( ( m ) => `newmtl ${m.name}\nKd ${srgb( m.color ).map( ( c ) => c.toFixed( 6 ) ).join( ' ' )}\n` );
		if ( emitter > 0 ) text.push( `newmtl emitter\nKd 0 0 0\nKe ${emitter} ${emitter} ${emitter}\n` );
		writeFileSync( join( folder, `${name}.mtl` ), text.join( '\n' ) );

	}

	return join( folder, `${name}.obj` );

}

/**
 * Writes the Cornell room as cornell.glb (hand-built binary glTF): one primitive per quad with a
 * rough dielectric material of the surface's colour (linear baseColorFactor), basic.ts's lamp as a
 * KHR_lights_punctual point light (intensity in candela, as three's), and a small emissive panel
 * under the ceiling (emissiveFactor, facing down) — the lamp's shade.
 */
export function writeCornellGLB( folder: string ): string {

	const linear = ( c: number ) => c <= 0.04045 ? c / 12.92 : ( ( c + 0.055 ) / 1.055 ) ** 2.4;
	const [ lx, , lz ] = CORNELL_LAMP.position;
	// Counter-clockwise seen from below: the panel faces down, into the room.
	const panel: Quad = { material: 'panel', corners: [ [ lx - 0.2, 2.95, lz - 0.2 ], [ lx + 0.2, 2.95, lz - 0.2 ], [ lx + 0.2, 2.95, lz + 0.2 ], [ lx - 0.2, 2.95, lz + 0.2 ] ] };
	const quads = [ ...cornellQuads(), panel ];
	const names = [ ...CORNELL_ROOM.walls.map( ( wall ) => wall.name ), 'block', 'panel' ];
	const chunks: Buffer[] = [];
	const bufferViews: object[] = [], accessors: object[] = [];
	let offset = 0;
	const view = ( data: Float32Array | Uint16Array ) => {

		const bytes = Buffer.from( data.buffer, data.byteOffset, data.byteLength );
		const padded = Buffer.concat( [ bytes, Buffer.alloc( ( 4 - bytes.length % 4 ) % 4 ) ] );
		bufferViews.push( { buffer: 0, byteOffset: offset, byteLength: bytes.length } );
		chunks.push( padded );
		offset += padded.length;
		return bufferViews.length - 1;

	};

	const meshes = quads.map( ( { material, corners } ) => {

		const [ a, b, c ] = corners;
		const e1 = [ 0, 1, 2 ].map( ( i ) => b[ i ] - a[ i ] ), e2 = [ 0, 1, 2 ].map( ( i ) => c[ i ] - a[ i ] );
		const n = [ e1[ 1 ] * e2[ 2 ] - e1[ 2 ] * e2[ 1 ], e1[ 2 ] * e2[ 0 ] - e1[ 0 ] * e2[ 2 ], e1[ 0 ] * e2[ 1 ] - e1[ 1 ] * e2[ 0 ] ];
		const length = Math.hypot( n[ 0 ], n[ 1 ], n[ 2 ] );
		const positions = new Float32Array( corners.flat() );
		const normals = new Float32Array( [ 0, 1, 2, 3 ].flatMap( () => n.map( ( v ) => v / length ) ) );
		const min = [ 0, 1, 2 ].map( ( i ) => Math.min( ...corners.map( ( p ) => p[ i ] ) ) );
		const max = [ 0, 1, 2 ].map( ( i ) => Math.max( ...corners.map( ( p ) => p[ i ] ) ) );
		accessors.push( { bufferView: view( positions ), componentType: 5126, count: 4, type: 'VEC3', min, max } );
		accessors.push( { bufferView: view( normals ), componentType: 5126, count: 4, type: 'VEC3' } );
		accessors.push( { bufferView: view( new Uint16Array( [ 0, 1, 2, 0, 2, 3 ] ) ), componentType: 5123, count: 6, type: 'SCALAR' } );
		const first = accessors.length - 3;
		const attributes = { POSITION: first, NORMAL: first + 1 };
		return { primitives: [ { attributes, indices: first + 2, material: names.indexOf( material ) } ] };

	} );
	const material = ( name: string ) => {

		if ( name === 'panel' ) return { name, pbrMetallicRoughness: { baseColorFactor: [ 0, 0, 0, 1 ], metallicFactor: 0 }, emissiveFactor: [ 1, 0.9, 0.8 ] };
		const baseColorFactor = [ ...srgb( colorOf( name ) ).map( linear ), 1 ];
		return { name, pbrMetallicRoughness: { baseColorFactor, metallicFactor: 0, roughnessFactor: 0.9 } };

	};

	const materials = names.map( material );
	const lampColor = srgb( CORNELL_LAMP.color ).map( linear );
	const json = {
		asset: { version: '2.0' },
		extensionsUsed: [ 'KHR_lights_punctual' ],
		extensions: { KHR_lights_punctual: { lights: [ { type: 'point', color: lampColor, intensity: CORNELL_LAMP.intensity } ] } },
		scene: 0,
		scenes: [ { nodes: [ ...meshes.map( ( _, i ) => i ), meshes.length ] } ],
		nodes: [
			...meshes.map( ( _, i ) => ( { mesh: i, name: `${quads[ i ].material}${i}` } ) ),
			{ name: 'lamp', translation: CORNELL_LAMP.position, extensions: { KHR_lights_punctual: { light: 0 } } },
		],
		meshes, materials, accessors, bufferViews,
		buffers: [ { byteLength: offset } ],
	};
	const jsonBytes = Buffer.from( JSON.stringify( json ) );
	const jsonChunk = Buffer.concat( [ jsonBytes, Buffer.alloc( ( 4 - jsonBytes.length % 4 ) % 4, 0x20 ) ] );
	const binChunk = Buffer.concat( chunks );
	const header = Buffer.alloc( 12 );
	header.write( 'glTF', 0, 'latin1' );
	header.writeUInt32LE( 2, 4 );
	header.writeUInt32LE( 12 + 8 + jsonChunk.length + 8 + binChunk.length, 8 );
	const chunkHeader = ( length: number, type: number ) => {

		const b = Buffer.alloc( 8 );
		b.writeUInt32LE( length, 0 );
		b.writeUInt32LE( type, 4 );
		return b;

	};

	const file = join( folder, 'cornell.glb' );
	const JSON_CHUNK = 0x4E4F534A, BIN_CHUNK = 0x004E4942;
	const parts = [ header, chunkHeader( jsonChunk.length, JSON_CHUNK ), jsonChunk, chunkHeader( binChunk.length, BIN_CHUNK ), binChunk ];
	writeFileSync( file, Buffer.concat( parts ) );
	return file;

}
