import type { GLTF, GLTFLoaderPlugin, GLTFParser } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { BakedVolumeError, decodeBakedVolume, type BakedVolumeData } from '../io/index.js';
import { GLTF_LIGHT_PROBE_VOLUME_EXTENSION, type GLTFLightProbeVolumeEntry } from './GLTFLightProbeVolumeExtension.js';

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
