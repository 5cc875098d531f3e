import { beforeAll, describe, expect, it } from 'vitest';
import { BoxGeometry, Mesh, MeshStandardMaterial, Object3D, Scene } from 'three';
import { GLTFExporter } from 'three/addons/exporters/GLTFExporter.js';
import { GLTFLoader, type GLTF } from 'three/addons/loaders/GLTFLoader.js';
import {
	GLTFLightProbeVolumeExporterPlugin, GLTFLightProbeVolumeLoaderPlugin, GLTF_LIGHT_PROBE_VOLUME_EXTENSION, type GLTFLightProbeVolumeEntry,
} from '../../src/index.js';
import { BakedVolumeError, decodeBakedVolume, type BakedVolumeInput } from '../../src/io/index.js';
import { makeVolume, independentCheck } from './helpers.js';
import { installGLTFNodeStubs } from './gltfNodeStubs.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';

beforeAll( installGLTFNodeStubs );

function tinyScene(): Scene {

	const scene = new Scene();
	scene.add( new Mesh( new BoxGeometry( 1, 2, 3 ), new MeshStandardMaterial( { color: 0x808080 } ) ) );
	return scene;

}

async function exportGLB( volumes: GLTFLightProbeVolumeEntry<BakedVolumeInput>[], precision: 'float16' | 'float32' ): Promise<ArrayBuffer> {

	const exporter = new GLTFExporter();
	exporter.register( ( writer ) => new GLTFLightProbeVolumeExporterPlugin( writer, volumes, { precision } ) );
	return await exporter.parseAsync( tinyScene(), { binary: true } ) as ArrayBuffer;

}

function load( data: ArrayBuffer | string ): Promise<GLTF> {

	const loader = new GLTFLoader();
	loader.register( ( parser ) => new GLTFLightProbeVolumeLoaderPlugin( parser ) );
	return loader.parseAsync( data, '' );

}

/** The JSON chunk of a .glb. */
function glbJSON( glb: ArrayBuffer ): Record<string, unknown> & { extensions: Record<string, { volumes: { name?: string; bufferView: number }[] }>; bufferViews: { byteOffset: number; byteLength: number }[] } {

	const view = new DataView( glb );
	const length = view.getUint32( 12, true );
	return JSON.parse( new TextDecoder().decode( new Uint8Array( glb, 20, length ) ) );

}

describe( 'glTF extension ' + GLTF_LIGHT_PROBE_VOLUME_EXTENSION, () => {

	const a = makeVolume( 30, 8 ), b = makeVolume( 12, 9, false );

	it( 'GLTFExporter → .glb → GLTFLoader returns both volumes, the mesh is intact, float32 exact', async () => {

		const glb = await exportGLB( [ { name: 'hall', data: a }, { name: '', data: b } ], 'float32' );
		const json = glbJSON( glb );
		expect( json.extensionsUsed ).toContain( GLTF_LIGHT_PROBE_VOLUME_EXTENSION );
		const entries = json.extensions[ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ].volumes;
		expect( entries ).toEqual( [ { name: 'hall', bufferView: expect.any( Number ) }, { bufferView: expect.any( Number ) } ] );
		for ( const entry of entries ) expect( json.bufferViews[ entry.bufferView ].byteOffset % 8 ).toBe( 0 );

		const gltf = await load( glb );
		expect( gltf.scene.children[ 0 ] ).toBeInstanceOf( Mesh );
		const volumes = gltf.userData.lightProbeVolumes as GLTFLightProbeVolumeEntry[];
		expect( volumes.map( ( v ) => v.name ) ).toEqual( [ 'hall', '' ] );
		expect( Array.from( volumes[ 0 ].data.positions ) ).toEqual( Array.from( a.positions ) );
		expect( Array.from( volumes[ 0 ].data.sh ) ).toEqual( Array.from( a.sh ) );
		expect( Array.from( volumes[ 0 ].data.tetrahedra ) ).toEqual( Array.from( a.tetrahedra ) );
		expect( volumes[ 0 ].data.names ).toEqual( a.names );
		expect( volumes[ 0 ].data.capture ).toEqual( a.capture );
		expect( Array.from( volumes[ 1 ].data.neighbors ) ).toEqual( Array.from( b.neighbors ) );
		expect( independentCheck( volumes[ 1 ].data ) ).toBeNull();

	} );

	it( 'float16 inside a .glb: SH within half precision', async () => {

		const gltf = await load( await exportGLB( [ { name: 'hall', data: a } ], 'float16' ) );
		const sh = ( gltf.userData.lightProbeVolumes as GLTFLightProbeVolumeEntry[] )[ 0 ].data.sh;
		for ( let i = 0; i < sh.length; i ++ ) expect( Math.abs( sh[ i ] - a.sh[ i ] ) ).toBeLessThanOrEqual( Math.max( Math.abs( a.sh[ i ] ) * 2 ** - 11, 2 ** - 25 ) );

	} );

	it( 'gradient probes and the fit record inside a .glb: float32 bitwise, float16 within half precision; a plain volume beside them stays plain', async () => {

		const random = mulberry32( 31 );
		const gradients = Float32Array.from( { length: 81 * 30 }, () => 6 * random() - 3 );
		const fit = { samples: 200, gradients: true, lambda: 0.5, gradientLambda: 0.125, crossValidationError: 0.06, source: 'test' };
		for ( const precision of [ 'float32', 'float16' ] as const ) {

			const gltf = await load( await exportGLB( [ { name: 'hall', data: { ...a, gradients, fit } }, { name: 'b', data: b } ], precision ) );
			const [ hall, plain ] = gltf.userData.lightProbeVolumes as GLTFLightProbeVolumeEntry[];
			expect( hall.data.fit ).toEqual( fit );
			expect( [ plain.data.gradients, plain.data.fit ] ).toEqual( [ null, null ] );
			const read = hall.data.gradients!;
			expect( read ).toHaveLength( gradients.length );
			if ( precision === 'float32' ) expect( Array.from( read ) ).toEqual( Array.from( gradients ) );
			// The float16 bound of docs/format.md ("SH precision"): relative 2^−11, absolute 2^−25 near 0.
			for ( let i = 0; i < read.length; i ++ ) {

				const bound = Math.max( Math.abs( gradients[ i ] ) * 2 ** - 11, 2 ** - 25 );
				expect( Math.abs( read[ i ] - gradients[ i ] ), `gradients[${i}], ${precision}` ).toBeLessThanOrEqual( bound );

			}


		}

	} );

	it( 'the bufferView bytes are exactly the binary format (readable without three.js)', async () => {

		const glb = await exportGLB( [ { name: 'hall', data: a } ], 'float32' );
		const json = glbJSON( glb );
		const jsonLength = new DataView( glb ).getUint32( 12, true );
		const binStart = 20 + jsonLength + 8;
		const { byteOffset, byteLength } = json.bufferViews[ json.extensions[ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ].volumes[ 0 ].bufferView ];
		const d = decodeBakedVolume( new Uint8Array( glb, binStart + byteOffset, byteLength ) );
		expect( Array.from( d.positions ) ).toEqual( Array.from( a.positions ) );

	} );

	it( 'a .gltf (JSON with a data: URI buffer) carries the volume too', async () => {

		const exporter = new GLTFExporter();
		exporter.register( ( writer ) => new GLTFLightProbeVolumeExporterPlugin( writer, a ) );
		const json = await exporter.parseAsync( tinyScene(), { binary: false } );
		const gltf = await load( JSON.stringify( json ) );
		expect( Array.from( ( gltf.userData.lightProbeVolumes as GLTFLightProbeVolumeEntry[] )[ 0 ].data.sh ) ).toEqual( Array.from( a.sh ) );

	} );

	it( 'a corrupted volume inside the .glb rejects the load with BakedVolumeError "corrupted"; a bad bufferView index with code range', async () => {

		const glb = await exportGLB( [ { name: 'hall', data: a } ], 'float32' );
		const json = glbJSON( glb );
		const jsonLength = new DataView( glb ).getUint32( 12, true );
		const { byteOffset } = json.bufferViews[ json.extensions[ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ].volumes[ 0 ].bufferView ];
		const corrupted = glb.slice( 0 );
		new Uint8Array( corrupted )[ 20 + jsonLength + 8 + byteOffset + 200 ] ^= 1;
		await expect( load( corrupted ) ).rejects.toThrow( /corrupted/ );
		await expect( load( corrupted ) ).rejects.toBeInstanceOf( BakedVolumeError );

		const bad = { asset: { version: '2.0' }, extensionsUsed: [ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ], extensions: { [ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ]: { volumes: [ { bufferView: 3 } ] } } };
		await expect( load( JSON.stringify( bad ) ) ).rejects.toMatchObject( { name: 'BakedVolumeError', code: 'range' } );

	} );

	it( 'a bufferView pointing to a missing buffer, or running past its buffer, or unreadable: a BakedVolumeError, not a TypeError from inside GLTFLoader', async () => {

		// A scene with no mesh: the volume's buffer is read by the plugin alone (a mesh's broken buffer is three's to report).
		const empty = new Scene();
		empty.add( new Object3D() );
		const exporter = new GLTFExporter();
		exporter.register( ( writer ) => new GLTFLightProbeVolumeExporterPlugin( writer, [ { name: 'hall', data: a } ] ) );
		const json = await exporter.parseAsync( empty, { binary: false } ) as {
			bufferViews: { buffer?: unknown; byteOffset?: unknown; byteLength?: unknown }[]; buffers?: { byteLength: number; uri: string }[];
			extensions: Record<string, { volumes: { bufferView: number }[] }>;
		};
		const view = json.extensions[ GLTF_LIGHT_PROBE_VOLUME_EXTENSION ].volumes[ 0 ].bufferView;
		const edited = ( edit: ( j: typeof json ) => void ) => {

			const copy = structuredClone( json );
			edit( copy );
			return load( JSON.stringify( copy ) );

		};

		const cases: [ ( j: typeof json ) => void, string, RegExp ][] = [
			[ ( j ) => { j.bufferViews[ view ].buffer = 5; }, 'range', /bufferViews\[\d+\]\.buffer is 5; expected a buffer index \(0\.\.0\)/ ],
			[ ( j ) => { delete j.buffers; }, 'range', /bufferViews\[\d+\]\.buffer is 0; expected a buffer index \(0\.\.-1\)/ ],
			[ ( j ) => { j.bufferViews[ view ].buffer = '0'; }, 'range', /buffer is "0"/ ],
			[ ( j ) => { j.bufferViews[ view ].byteOffset = - 8; }, 'json', /needs integer byteOffset ≥ 0/ ],
			[ ( j ) => { j.bufferViews[ view ].byteLength = 1e9; }, 'truncated', /runs past the end of buffers\[0\]/ ],
			[ ( j ) => { j.buffers![ 0 ].uri = 'missing.bin'; }, 'truncated', /could not be read/ ],
			[ ( j ) => { j.bufferViews[ view ] = null as never; }, 'json', /bufferViews\[\d+\] must be an object/ ],
		];
		for ( const [ edit, code, message ] of cases ) {

			const error = await edited( edit ).then( () => null, ( caught: unknown ) => caught );
			expect( error, String( message ) ).toBeInstanceOf( BakedVolumeError );
			expect( error ).toMatchObject( { code } );
			expect( ( error as Error ).message ).toMatch( /^GLTFLightProbeVolumeLoaderPlugin: volumes\[0\]/ );
			expect( ( error as Error ).message ).toMatch( message );

		}

	} );

	it( 'a file without the extension loads as before (no lightProbeVolumes)', async () => {

		const exporter = new GLTFExporter();
		const gltf = await load( await exporter.parseAsync( tinyScene(), { binary: true } ) as ArrayBuffer );
		expect( gltf.userData.lightProbeVolumes ).toBeUndefined();

	} );

} );
