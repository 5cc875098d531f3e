import type { GLTFExporterPlugin, GLTFWriter } from 'three/examples/jsm/exporters/GLTFExporter.js';
import { BakedVolumeError, encodeBakedVolume, type BakedVolumeInput, type EncodeBakedVolumeOptions } from '../io/index.js';
import { GLTF_LIGHT_PROBE_VOLUME_EXTENSION, type GLTFLightProbeVolumeEntry } from './GLTFLightProbeVolumeExtension.js';

// The parts of three's GLTFWriter the plugin uses; they are public fields of the JS class but not in its typings.
interface WriterInternals {

	json: { bufferViews?: unknown[]; extensions?: Record<string, unknown>; buffers?: unknown[] };
	byteOffset: number;
	processBuffer( buffer: ArrayBuffer ): number;
	extensionsUsed: Record<string, boolean>;

}

/**
 * GLTFExporter plugin writing light probe volumes into the file (binary .glb or .gltf with a data URI),
 * each as the baked binary file of docs/format.md.
 *
 * ```js
 * const volumes = [ { name: 'level', data: volume.toBakedData() } ];
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
	 * @param volumes The volumes to write, each `volume.toBakedData()` (a bare one is written with the name '').
	 * @param options Encoding options (SH precision), for every volume.
	 */
	constructor(
		writer: GLTFWriter, volumes: readonly GLTFLightProbeVolumeEntry<BakedVolumeInput>[] | BakedVolumeInput,
		options: EncodeBakedVolumeOptions = {},
	) {

		const where = 'GLTFLightProbeVolumeExporterPlugin';
		const candidate = writer as unknown as Partial<WriterInternals> | null;
		if ( ! candidate || typeof candidate !== 'object' || typeof candidate.processBuffer !== 'function' ) {

			throw new BakedVolumeError( 'argument', `${where}: writer must be the GLTFWriter that GLTFExporter passes to register()'s callback.` );

		}

		if ( volumes === null || typeof volumes !== 'object' ) throw new BakedVolumeError( 'argument', `${where}: volumes must be an array of { name, data } or one volume.` );
		if ( options === null || typeof options !== 'object' ) throw new BakedVolumeError( 'argument', `${where}: options must be an object.` );
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
