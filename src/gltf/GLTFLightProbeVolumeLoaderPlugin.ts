import type { GLTF, GLTFLoaderPlugin, GLTFParser } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { BakedVolumeError, decodeBakedVolume, type BakedVolumeData } from '../io/index.js';
import { GLTF_LIGHT_PROBE_VOLUME_EXTENSION, type GLTFLightProbeVolumeEntry } from './GLTFLightProbeVolumeExtension.js';

/**
 * GLTFLoader plugin reading the volumes written by {@link GLTFLightProbeVolumeExporterPlugin}
 * (or any writer following docs/format.md) into `gltf.userData.lightProbeVolumes`, an array of
 * {@link GLTFLightProbeVolumeEntry} whose `data` is decoded and checked baked data, ready for
 * `LightProbeVolume.fromBakedData`. A malformed extension or volume rejects the load with a
 * {@link BakedVolumeError}.
 *
 * ```js
 * loader.register( ( parser ) => new GLTFLightProbeVolumeLoaderPlugin( parser ) );
 * const gltf = await loader.loadAsync( 'level.glb' );
 * const volume = LightProbeVolume.fromBakedData( gltf.userData.lightProbeVolumes[ 0 ].data );
 * ```
 */
export class GLTFLightProbeVolumeLoaderPlugin implements GLTFLoaderPlugin {

	/** The extension name. */
	readonly name = GLTF_LIGHT_PROBE_VOLUME_EXTENSION;

	private readonly parser: GLTFParser;

	/**
	 * @param parser The GLTFParser the loader passes to `register`'s callback.
	 */
	constructor( parser: GLTFParser ) {

		const candidate = parser as { json?: unknown; getDependency?: unknown } | null;
		if ( ! candidate || typeof candidate.json !== 'object' || typeof candidate.getDependency !== 'function' ) {

			throw new BakedVolumeError( 'argument', 'GLTFLightProbeVolumeLoaderPlugin: parser must be the GLTFParser that GLTFLoader passes to register()\'s callback.' );

		}

		this.parser = parser;

	}

	/** Called by GLTFLoader once the scene is built: decodes every volume. */
	async afterRoot( result: GLTF ): Promise<void> {

		const where = 'GLTFLightProbeVolumeLoaderPlugin';
		const json = this.parser.json as { extensions?: Record<string, unknown>; bufferViews?: unknown[]; buffers?: unknown[] };
		const extension = json.extensions?.[ this.name ];
		if ( extension === undefined ) return;
		const volumes = ( extension as { volumes?: unknown } )?.volumes;
		if ( ! Array.isArray( volumes ) ) throw new BakedVolumeError( 'json', `${where}: extensions.${this.name}.volumes must be an array.` );
		const viewCount = Array.isArray( json.bufferViews ) ? json.bufferViews.length : 0;
		const loaded: GLTFLightProbeVolumeEntry[] = [];
		for ( let i = 0; i < volumes.length; i ++ ) {

			const entry = volumes[ i ] as { name?: unknown; bufferView?: unknown } | null;
			const bufferView = entry?.bufferView;
			if ( typeof bufferView !== 'number' || ! Number.isInteger( bufferView ) || bufferView < 0 || bufferView >= viewCount ) {

				throw new BakedVolumeError( 'range', `${where}: volumes[${i}].bufferView is ${JSON.stringify( bufferView )}; expected a bufferView index (0..${viewCount - 1}).` );

			}

			const name = entry?.name ?? '';
			if ( typeof name !== 'string' ) throw new BakedVolumeError( 'json', `${where}: volumes[${i}].name must be a string.` );
			checkBufferView( `${where}: volumes[${i}]`, json, bufferView );
			let buffer: ArrayBuffer;
			try {

				buffer = await this.parser.getDependency( 'bufferView', bufferView ) as ArrayBuffer;

			} catch ( error ) {

				// three's loader throws whatever a missing or unreadable buffer gives (TypeError, fetch errors).
				throw new BakedVolumeError( 'truncated', `${where}: volumes[${i}]: bufferView ${bufferView} could not be read (${( error as Error )?.message ?? error}).` );

			}

			if ( ! ( buffer instanceof ArrayBuffer ) ) throw new BakedVolumeError( 'truncated', `${where}: volumes[${i}]: bufferView ${bufferView} gave no bytes.` );
			loaded.push( { name, data: decodeBakedVolume( buffer ) } );

		}

		result.userData = result.userData ?? {};
		result.userData.lightProbeVolumes = loaded;

	}

}

/**
 * The glTF bufferView a volume points to, checked before three's loader reads it (three does not
 * check these, and fails deep inside with a TypeError): an object whose `buffer` is an index into
 * `buffers`, with integer `byteOffset` ≥ 0 and `byteLength` ≥ 0 that fit a known buffer length, and
 * a buffer whose `uri`, when it has one, is a non-empty string.
 */
function checkBufferView( where: string, json: { bufferViews?: unknown[]; buffers?: unknown[] }, index: number ): void {

	const view = json.bufferViews![ index ] as { buffer?: unknown; byteOffset?: unknown; byteLength?: unknown } | null;
	if ( view === null || typeof view !== 'object' ) throw new BakedVolumeError( 'json', `${where}: bufferViews[${index}] must be an object.` );
	const bufferCount = Array.isArray( json.buffers ) ? json.buffers.length : 0;
	const buffer = view.buffer, offset = view.byteOffset ?? 0, length = view.byteLength;
	if ( typeof buffer !== 'number' || ! Number.isInteger( buffer ) || buffer < 0 || buffer >= bufferCount ) {

		throw new BakedVolumeError( 'range', `${where}: bufferViews[${index}].buffer is ${JSON.stringify( buffer )}; expected a buffer index (0..${bufferCount - 1}).` );

	}

	const isSize = ( v: unknown ): v is number => typeof v === 'number' && Number.isInteger( v ) && v >= 0;
	if ( ! isSize( offset ) || ! isSize( length ) ) {

		throw new BakedVolumeError( 'json', `${where}: bufferViews[${index}] needs integer byteOffset ≥ 0 and byteLength ≥ 0, got ${JSON.stringify( offset )} and ${JSON.stringify( length )}.` );

	}

	const bufferDef = json.buffers![ buffer ] as { byteLength?: unknown; uri?: unknown } | null;
	if ( bufferDef === null || typeof bufferDef !== 'object' ) throw new BakedVolumeError( 'json', `${where}: buffers[${buffer}] must be an object.` );
	if ( bufferDef.uri !== undefined && ( typeof bufferDef.uri !== 'string' || bufferDef.uri === '' ) ) {

		throw new BakedVolumeError( 'json', `${where}: buffers[${buffer}].uri is ${JSON.stringify( bufferDef.uri )}; expected a URI string.` );

	}

	const size = bufferDef.byteLength;
	if ( isSize( size ) && offset + length > size ) {

		throw new BakedVolumeError( 'truncated', `${where}: bufferViews[${index}] (bytes ${offset}..${offset + length}) runs past the end of buffers[${buffer}] (${size} bytes).` );

	}

}
