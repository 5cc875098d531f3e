import * as THREE from 'three';
import type { ProbeRole } from 'three-capture-lighting';
import data from './kyoto.json';

/** A panorama used by the Kyoto page: a real photo file, or a copy derived from one. */
export interface KyotoPanorama {

	id: string;
	/** Short text shown beside the probes that use it. */
	label: string;
	/** 'photo': a real photograph; 'derived': computed from a photo; 'dropped': a file the user dropped. */
	kind: 'photo' | 'derived' | 'dropped';
	/** Path under the asset folder (photos). */
	file?: string;
	/** The photo a derived panorama is computed from, its turn about the vertical (degrees) and linear RGB gain. */
	source?: string;
	yaw?: number;
	gain?: number[];
	note: string;

}

/** A probe on the map: ground position (x, z), the panorama it was captured from, its role. */
export interface KyotoProbe {

	name: string;
	at: number[];
	panorama: string;
	role: ProbeRole;

}

export interface KyotoLayout {

	name: string;
	probes: KyotoProbe[];
	grid?: { min: number[]; max: number[]; counts: number[] };

}

/** The stored scene: probe height, panoramas and the two layouts (the paper's 5x4 grid and 12 arbitrary). */
export const kyoto = data as { about: string; height: number; panoramas: KyotoPanorama[]; layouts: KyotoLayout[] };

/** Map extent in scene units (x: west–east, z: north–south; −z is north). */
export const MAP_SIZE = { width: 44, depth: 34 };

/** The character's walk, a closed loop inside both layouts' triangulations. */
export const kyotoPath = new THREE.CatmullRomCurve3( [
	[ - 8, - 9 ], [ 6, - 9 ], [ 12, - 4 ], [ 12, 5 ], [ 6, 10 ], [ - 6, 10 ], [ - 13, 4 ], [ - 13, - 4 ],
].map( ( [ x, z ] ) => new THREE.Vector3( x, 0, z ) ), true, 'centripetal' );

/**
 * A flat street map drawn on a canvas: a grid of blocks with fine lanes, a park, a temple
 * ground, and a river with bridges on the east side. Procedural — not Kyoto's real streets.
 */
export function createKyotoMap(): THREE.Mesh {

	const scale = 24; // pixels per unit
	const canvas = document.createElement( 'canvas' );
	canvas.width = MAP_SIZE.width * scale;
	canvas.height = MAP_SIZE.depth * scale;
	const g = canvas.getContext( '2d' )!;
	const X = ( x: number ) => ( x + MAP_SIZE.width / 2 ) * scale, Z = ( z: number ) => ( z + MAP_SIZE.depth / 2 ) * scale;
	const rect = ( x0: number, z0: number, x1: number, z1: number, color: string ) => {

		g.fillStyle = color; g.fillRect( X( x0 ), Z( z0 ), ( x1 - x0 ) * scale, ( z1 - z0 ) * scale );

	};

	rect( - 22, - 17, 22, 17, '#e7dfd0' );
	let seed = 7;
	const random = () => ( seed = ( seed * 16807 ) % 2147483647 ) / 2147483647;
	for ( let x = - 22; x < 22; x += 0.9 ) for ( let z = - 17; z < 17; z += 0.9 ) if ( random() < 0.55 ) rect( x + 0.1, z + 0.1, x + 0.1 + 0.4 + random() * 0.35, z + 0.1 + 0.4 + random() * 0.35, '#d6cbb8' );
	rect( - 15.3, - 11.3, - 8.7, - 4.7, '#b7d59b' ); // park
	for ( let i = 0; i < 40; i ++ ) { g.fillStyle = '#8fbf72'; g.beginPath(); g.arc( X( - 15 + random() * 6 ), Z( - 11 + random() * 6 ), scale * 0.35, 0, 2 * Math.PI ); g.fill(); }
	rect( - 7.3, 4.7, - 0.7, 11.3, '#e9d3c3' ); // temple ground
	rect( - 5, 6.5, - 3, 9.5, '#b5533c' );
	rect( 14, - 17, 18, 17, '#9cc3e0' ); // river
	rect( 13.2, - 17, 14, 17, '#c7dcb4' ); rect( 18, - 17, 18.8, 17, '#c7dcb4' );
	const street = ( x0: number, z0: number, x1: number, z1: number, width: number ) => {

		g.strokeStyle = '#ffffff'; g.lineWidth = width * scale; g.beginPath(); g.moveTo( X( x0 ), Z( z0 ) ); g.lineTo( X( x1 ), Z( z1 ) ); g.stroke();

	};

	for ( const x of [ - 20, - 12, - 4, 4 ] ) street( x, - 17, x, 17, 0.4 ); // lanes
	for ( const z of [ - 16, - 8, 0, 8, 16 ] ) { street( - 22, z, 13.2, z, 0.4 ); street( 18.8, z, 22, z, 0.4 ); }
	for ( const x of [ - 16, - 8, 0, 8 ] ) street( x, - 17, x, 17, x === 0 ? 1.6 : 1.1 ); // streets
	street( 12.6, - 17, 12.6, 17, 1.1 ); street( 19.4, - 17, 19.4, 17, 1.1 );
	for ( const z of [ - 12, - 4, 4, 12 ] ) street( - 22, z, 22, z, z === - 4 ? 1.6 : 1.1 ); // and bridges
	g.fillStyle = '#5d6f80'; g.font = `${scale}px system-ui, sans-serif`;
	g.fillText( 'N ↑', X( - 21.2 ), Z( - 15.6 ) );
	g.fillText( 'procedural map', X( - 21.2 ), Z( 16.4 ) );
	g.save(); g.translate( X( 16.3 ), Z( 9 ) ); g.rotate( - Math.PI / 2 ); g.fillText( 'river', 0, 0 ); g.restore();

	const texture = new THREE.CanvasTexture( canvas );
	texture.colorSpace = THREE.SRGBColorSpace;
	texture.anisotropy = 4;
	const mesh = new THREE.Mesh(
		new THREE.PlaneGeometry( MAP_SIZE.width, MAP_SIZE.depth ),
		new THREE.MeshBasicMaterial( { map: texture, toneMapped: false } )
	);
	mesh.rotation.x = - Math.PI / 2; // the canvas top edge is north (−z)
	mesh.name = 'map';
	return mesh;

}

/**
 * A panorama computed from a loaded one (three's `HDRLoader` output, half or full float RGBA): the
 * columns shifted by `yaw / 360` of the width — the same place turned about the vertical — and
 * each channel multiplied by `gain` (linear RGB). Nothing is clamped.
 */
export function derivePanorama( source: THREE.DataTexture, yaw: number, gain: number[] = [ 1, 1, 1 ] ): THREE.DataTexture {

	const { width, height, data } = source.image as { width: number; height: number; data: Uint16Array | Float32Array };
	const half = source.type === THREE.HalfFloatType;
	const out = new ( data.constructor as { new ( n: number ): Uint16Array | Float32Array } )( data.length );
	const shift = ( ( Math.round( yaw / 360 * width ) % width ) + width ) % width;
	const plain = gain.every( ( value ) => value === 1 );
	for ( let y = 0; y < height; y ++ ) {

		for ( let x = 0; x < width; x ++ ) {

			const from = 4 * ( y * width + x ), to = 4 * ( y * width + ( x + shift ) % width );
			for ( let c = 0; c < 3; c ++ ) {

				const value = data[ from + c ];
				out[ to + c ] = plain ? value :
					half ? THREE.DataUtils.toHalfFloat( THREE.DataUtils.fromHalfFloat( value ) * gain[ c ] ) : value * gain[ c ];

			}

			out[ to + 3 ] = data[ from + 3 ];

		}

	}

	const texture = new THREE.DataTexture( out, width, height, THREE.RGBAFormat, source.type );
	texture.flipY = source.flipY;
	texture.colorSpace = source.colorSpace;
	texture.minFilter = source.minFilter;
	texture.magFilter = source.magFilter;
	texture.generateMipmaps = false;
	texture.mapping = THREE.EquirectangularReflectionMapping;
	texture.needsUpdate = true;
	return texture;

}
