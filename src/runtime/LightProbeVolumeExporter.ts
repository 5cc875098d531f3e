import { bakedVolumeToJSON, encodeBakedVolume, type BakedVolumeInput, type BakedVolumeJSON } from '../io/index.js';
import { describeValue } from '../validate.js';
import type { LightProbeVolume } from './LightProbeVolume.js';
import { renameBakedVolumeError } from './renameBakedVolumeError.js';

/** Options of {@link LightProbeVolumeExporter.parse}. */
export interface LightProbeVolumeExporterOptions {

	/** `true` (default): the binary file as an `ArrayBuffer`; `false`: the JSON form as an object, for `JSON.stringify`. */
	binary?: boolean;

	/** SH of the binary file as `'float32'` (default, exact) or `'float16'` (half the SH bytes; binary only). */
	precision?: 'float16' | 'float32';

}

/** Options that make {@link LightProbeVolumeExporter.parse} write the binary file. */
export type LightProbeVolumeBinaryOptions = LightProbeVolumeExporterOptions & { binary?: true };

/** Options that make {@link LightProbeVolumeExporter.parse} return the JSON form (which has no SH precision). */
export type LightProbeVolumeJSONOptions = { binary: false; precision?: never };

const OPTION_NAMES = [ 'binary', 'precision' ];

/**
 * Writes a {@link LightProbeVolume} as a baked file (docs/format.md) for {@link LightProbeVolumeLoader}
 * or `capture-lighting inspect`, as three's exporters write scenes: the binary form (default) or
 * the JSON form. The file holds positions, SH, gradients (gradient probes), the tetrahedralization,
 * names, roles, zones, capture settings, the fit record (`fitSettings`) and metadata; probes
 * removed by `removeProbe()` are left out.
 *
 * ```js
 * const file = new LightProbeVolumeExporter().parse( volume, { precision: 'float16' } ); // ArrayBuffer
 * const json = new LightProbeVolumeExporter().parse( volume, { binary: false } );        // JSON.stringify( json )
 * ```
 */
export class LightProbeVolumeExporter {

	/**
	 * The volume as a baked file: an `ArrayBuffer` (binary, the default) or the JSON object.
	 * @param volume The volume to write.
	 * @param options `binary` (default true) and, for the binary form, `precision` (default `'float32'`).
	 * @throws {BakedVolumeError} when the volume cannot be written (`'float16-overflow'`: an SH or gradient value beyond ±65504
	 * in float16; `'count'`: `fitSettings.gradients` is true but the volume has no gradients).
	 */
	parse( volume: LightProbeVolume, options?: LightProbeVolumeBinaryOptions ): ArrayBuffer;
	parse( volume: LightProbeVolume, options: LightProbeVolumeJSONOptions ): BakedVolumeJSON;
	parse( volume: LightProbeVolume, options?: LightProbeVolumeExporterOptions ): ArrayBuffer | BakedVolumeJSON;
	parse( volume: LightProbeVolume, options: LightProbeVolumeExporterOptions = {} ): ArrayBuffer | BakedVolumeJSON {

		const where = 'LightProbeVolumeExporter.parse';
		const { binary, precision } = readOptions( where, options );
		if ( typeof ( volume as Partial<LightProbeVolume> | null )?.toBakedData !== 'function' ) {

			throw new TypeError( `${where}: volume must be a LightProbeVolume, got ${describeValue( volume )}.` );

		}

		const data: BakedVolumeInput = volume.toBakedData();
		try {

			return binary ? encodeBakedVolume( data, { precision } ) : bakedVolumeToJSON( data );

		} catch ( error ) {

			throw renameBakedVolumeError( where, error );

		}

	}

	/**
	 * {@link LightProbeVolumeExporter.parse} as a promise, as three's `GLTFExporter.parseAsync`:
	 * it resolves with the file and rejects with parse's error.
	 * @param volume The volume to write.
	 * @param options As for `parse`.
	 */
	parseAsync( volume: LightProbeVolume, options?: LightProbeVolumeBinaryOptions ): Promise<ArrayBuffer>;
	parseAsync( volume: LightProbeVolume, options: LightProbeVolumeJSONOptions ): Promise<BakedVolumeJSON>;
	parseAsync( volume: LightProbeVolume, options?: LightProbeVolumeExporterOptions ): Promise<ArrayBuffer | BakedVolumeJSON>;
	parseAsync( volume: LightProbeVolume, options?: LightProbeVolumeExporterOptions ): Promise<ArrayBuffer | BakedVolumeJSON> {

		return new Promise( ( resolve ) => resolve( this.parse( volume, options ) ) );

	}

}

/** The checked options with their defaults: only known members, `precision` for the binary form only. */
function readOptions( where: string, options: unknown ): Required<LightProbeVolumeExporterOptions> {

	if ( options === null || typeof options !== 'object' || Array.isArray( options ) ) {

		throw new TypeError( `${where}: options must be an object { binary?, precision? }, got ${describeValue( options )}.` );

	}

	const { binary = true, precision } = options as LightProbeVolumeExporterOptions;
	const unknown = Object.keys( options ).filter( ( name ) => ! OPTION_NAMES.includes( name ) );
	if ( unknown.length > 0 ) throw new TypeError( `${where}: unknown option ${unknown[ 0 ]}; the options are binary and precision.` );
	if ( typeof binary !== 'boolean' ) throw new TypeError( `${where}: options.binary must be true or false, got ${describeValue( binary )}.` );
	if ( precision !== undefined && precision !== 'float16' && precision !== 'float32' ) {

		throw new RangeError( `${where}: options.precision is ${describeValue( precision )}; expected 'float16' or 'float32'.` );

	}

	if ( precision !== undefined && ! binary ) {

		throw new RangeError( `${where}: options.precision applies to the binary file; the JSON form stores the SH values as they are.` );

	}

	return { binary, precision: precision ?? 'float32' };

}
