import type { GLTFExporterPlugin, GLTFWriter } from 'three/examples/jsm/exporters/GLTFExporter.js';
import type { GLTF, GLTFLoaderPlugin, GLTFParser } from 'three/examples/jsm/loaders/GLTFLoader.js';
import {
	BakedVolumeError, decodeBakedVolume, encodeBakedVolume, type BakedVolumeData, type BakedVolumeInput, type EncodeBakedVolumeOptions,
} from '../io/index.js';

/**
 * Name of the glTF extension that carries baked light probe volumes (docs/format.md, "glTF"):
 * a vendor extension of this library (prefix CBL, Capture Based Lighting; not registered with Khronos).
 * At the root: `extensions.CBL_light_probe_volume = { volumes: [ { name, bufferView } ] }`, each
 * bufferView holding one file in the binary format, positions in the glTF scene's world space.
 */
export const GLTF_LIGHT_PROBE_VOLUME_EXTENSION = 'CBL_light_probe_volume';

/** One volume to write into, or read from, a glTF file. */
export interface GLTFLightProbeVolumeEntry<T = BakedVolumeData> {

	/** Name of the volume in the file ('' when none). */
	name: string;

	/** The volume. */
	data: T;

}

// The parts of three's GLTFWriter the plugin uses; they are public fields of the JS class but not in its typings.
interface WriterInternals {

	json: { bufferViews?: unknown[]; extensions?: Record<string, unknown>; buffers?: unknown[] };
	byteOffset: number;
	processBuffer( buffer: ArrayBuffer ): number;
	extensionsUsed: Record<string, boolean>;

}

/**
 * GLTFExporter plugin writing light probe volumes into the file (binary .glb or .gltf with a data URI).
 *
 * ```js
 * const volumes = [ { name: 'level', data } ];
 * exporter.register( ( writer ) => new GLTFLightProbeVolumeExporterPlugin( writer, volumes, { precision: 'float16' } ) );
 * const glb = await exporter.parseAsync( scene, { binary: true } );
 * ```
 */
export class GLTFLightProbeVolumeExporterPlugin implements GLTFExporterPlugin {

	/** The extension name. */
	readonly name = GLTF_LIGHT_PROBE_VOLUME_EXTENSION;

	private readonly writer: WriterInternals;
	private readonly volumes: GLTFLightProbeVolumeEntry<BakedVolumeInput>[];
	private readonly options: EncodeBakedVolumeOptions;

	/**
	 * @param writer The GLTFWriter the exporter passes to `register`'s callback.
	 * @param volumes The volumes to write (a bare volume is written with the name '').
	 * @param options Encoding options (SH precision), for every volume.
	 */
	constructor(
		writer: GLTFWriter, volumes: readonly GLTFLightProbeVolumeEntry<BakedVolumeInput>[] | BakedVolumeInput,
		options: EncodeBakedVolumeOptions = {},
	) {

		this.writer = writer as unknown as WriterInternals;
		this.volumes = Array.isArray( volumes ) ? volumes.slice() : [ { name: '', data: volumes as BakedVolumeInput } ];
		this.options = options;
		this.volumes.forEach( ( entry, i ) => {

			if ( entry === null || typeof entry !== 'object' || typeof entry.name !== 'string' || entry.data === null || typeof entry.data !== 'object' ) {

				throw new BakedVolumeError( 'argument', `GLTFLightProbeVolumeExporterPlugin: volumes[${i}] must be { name: string, data: volume }.` );

			}

		} );

	}

	/** Called by GLTFExporter after the scene is written: appends one bufferView per volume. */
	afterParse(): void {

		if ( this.volumes.length === 0 ) return;
		const writer = this.writer;
		const json = writer.json;
		const entries = this.volumes.map( ( { name, data } ) => {

			const encoded = encodeBakedVolume( data, this.options );
			// The merged buffer keeps other views at 4-byte multiples; starting ours at a multiple of 8
			// lets a reader of the whole buffer view the float64 positions in place.
			const pad = ( 8 - ( writer.byteOffset % 8 ) ) % 8;
			if ( pad > 0 ) {

				writer.processBuffer( new ArrayBuffer( pad ) );
				writer.byteOffset += pad;

			}

			if ( ! json.bufferViews ) json.bufferViews = [];
			const bufferView = json.bufferViews.push( {
				buffer: writer.processBuffer( encoded ),
				byteOffset: writer.byteOffset,
				byteLength: encoded.byteLength,
			} ) - 1;
			writer.byteOffset += encoded.byteLength;
			return name ? { name, bufferView } : { bufferView };

		} );

		json.extensions = json.extensions ?? {};
		json.extensions[ this.name ] = { volumes: entries };
		writer.extensionsUsed[ this.name ] = true;

	}

}

/**
 * GLTFLoader plugin reading the volumes written by {@link GLTFLightProbeVolumeExporterPlugin}
 * (or any writer following docs/format.md) into `gltf.userData.lightProbeVolumes`, an array of
 * {@link GLTFLightProbeVolumeEntry}. A malformed extension or volume rejects the load with a
 * {@link BakedVolumeError}.
 *
 * ```js
 * loader.register( ( parser ) => new GLTFLightProbeVolumeLoaderPlugin( parser ) );
 * const gltf = await loader.parseAsync( glb, '' );
 * const { data } = gltf.userData.lightProbeVolumes[ 0 ];
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

		this.parser = parser;

	}

	/** Called by GLTFLoader once the scene is built: decodes every volume. */
	async afterRoot( result: GLTF ): Promise<void> {

		const where = 'GLTFLightProbeVolumeLoaderPlugin';
		const json = this.parser.json as { extensions?: Record<string, unknown>; bufferViews?: unknown[] };
		const extension = json.extensions?.[ this.name ];
		if ( extension === undefined ) return;
		const volumes = ( extension as { volumes?: unknown } )?.volumes;
		if ( ! Array.isArray( volumes ) ) throw new BakedVolumeError( 'json', `${where}: extensions.${this.name}.volumes must be an array.` );
		const viewCount = json.bufferViews?.length ?? 0;
		const loaded: GLTFLightProbeVolumeEntry[] = [];
		for ( let i = 0; i < volumes.length; i ++ ) {

			const entry = volumes[ i ] as { name?: unknown; bufferView?: unknown } | null;
			const bufferView = entry?.bufferView;
			if ( typeof bufferView !== 'number' || ! Number.isInteger( bufferView ) || bufferView < 0 || bufferView >= viewCount ) {

				throw new BakedVolumeError( 'range', `${where}: volumes[${i}].bufferView is ${JSON.stringify( bufferView )}; expected a bufferView index (0..${viewCount - 1}).` );

			}

			const name = entry?.name ?? '';
			if ( typeof name !== 'string' ) throw new BakedVolumeError( 'json', `${where}: volumes[${i}].name must be a string.` );
			const buffer = await this.parser.getDependency( 'bufferView', bufferView ) as ArrayBuffer;
			loaded.push( { name, data: decodeBakedVolume( buffer ) } );

		}

		result.userData = result.userData ?? {};
		result.userData.lightProbeVolumes = loaded;

	}

}
