import { FileLoader, Loader, type LoadingManager } from 'three';
import {
	BAKED_VOLUME_MAGIC, BakedVolumeError, bakedVolumeFromJSON, decodeBakedVolume, type BakedVolumeData, type BakedVolumeJSON,
} from '../io/index.js';
import { assertOptionalFunction, describeValue } from '../validate.js';
import { assertBakedVolumeParameters, type BakedVolumeParameters } from './bakedVolumeData.js';
import { LightProbeVolume } from './LightProbeVolume.js';
import { renameBakedVolumeError } from './renameBakedVolumeError.js';

export type { BakedVolumeParameters } from './bakedVolumeData.js';

/** What {@link LightProbeVolumeLoader.parse} reads: a baked binary file, or the JSON form as text, bytes or object. */
export type LightProbeVolumeData = ArrayBuffer | ArrayBufferView | string | BakedVolumeJSON;

// Reused by every parse of JSON bytes; fatal, so invalid UTF-8 is an error instead of U+FFFD.
const utf8Decoder = new TextDecoder( 'utf-8', { fatal: true } );

/**
 * Loads baked light probe volumes (docs/format.md) as three.js loaders load models: the binary
 * file (`capture-lighting bake`, {@link LightProbeVolumeExporter}) or its JSON form, told apart
 * by their first bytes. The volume comes back ready to light objects: the stored
 * tetrahedralization is used as it is, nothing is captured.
 *
 * ```js
 * const volume = await new LightProbeVolumeLoader().loadAsync( 'level.lpv' );
 * volume.add( character );
 * ```
 *
 * Keeping the file format here, not in `LightProbeVolume`, keeps the codec out of the bundles of
 * games that capture at run time. A damaged, truncated or foreign file is a `BakedVolumeError`
 * whose message starts with `LightProbeVolumeLoader.parse:`; an HTTP failure (404 …) is an Error
 * starting with `LightProbeVolumeLoader.load:` that names the URL. In Node, read the file and
 * call {@link LightProbeVolumeLoader.parse}.
 */
export class LightProbeVolumeLoader extends Loader<LightProbeVolume> {

	/** More constructor parameters for every volume this loader makes, e.g. `occluders` (see `setParameters`). */
	parameters: BakedVolumeParameters = {};

	/**
	 * @param manager The loading manager (three's `DefaultLoadingManager` when omitted).
	 */
	constructor( manager?: LoadingManager ) {

		super( manager );

	}

	/**
	 * Sets the constructor parameters that `load()` and `parse()` add to what a file holds, such as
	 * `occluders` (the level's static geometry for the visibility guard) and `guard`.
	 * @param parameters Constructor parameters other than those a file gives (positions, SH, gradients, names, roles, zones, interpolator).
	 */
	setParameters( parameters: BakedVolumeParameters ): this {

		assertBakedVolumeParameters( 'LightProbeVolumeLoader.setParameters', parameters );
		this.parameters = parameters ?? {};
		return this;

	}

	/**
	 * Fetches a baked file (through three's `FileLoader`: `path`, `requestHeader`,
	 * `withCredentials` and the manager apply) and calls `onLoad` with the volume.
	 * @param url The file's URL, relative to `path`.
	 * @param onLoad Called with the volume.
	 * @param onProgress Called with the download's `ProgressEvent`s.
	 * @param onError Called with the error when the request or the file fails (else it is logged).
	 */
	override load(
		url: string, onLoad: ( volume: LightProbeVolume ) => void,
		onProgress?: ( event: ProgressEvent ) => void, onError?: ( error: unknown ) => void,
	): void {

		const where = 'LightProbeVolumeLoader.load';
		if ( typeof url !== 'string' ) throw new TypeError( `${where}: url must be a string, got ${describeValue( url )}.` );
		if ( typeof onLoad !== 'function' ) throw new TypeError( `${where}: onLoad must be a function, got ${describeValue( onLoad )}.` );
		assertOptionalFunction( where, 'onProgress', onProgress );
		assertOptionalFunction( where, 'onError', onError );
		const parameters = this.parameters;
		const resolved = this.manager.resolveURL( this.path + url ); // what FileLoader requests and reports to the manager
		const report = ( error: unknown ) => {

			if ( onError ) onError( error );
			else console.error( error );

		};

		const files = new FileLoader( this.manager );
		files.setPath( this.path ).setResponseType( 'arraybuffer' ).setRequestHeader( this.requestHeader ).setWithCredentials( this.withCredentials );
		files.priority = this.priority;
		files.cache = this.cache;
		files.load( url, ( data ) => {

			let volume: LightProbeVolume;
			try {

				volume = this.parseData( data, parameters, resolved );

			} catch ( error ) {

				// FileLoader has reported a success to the manager; the file itself failed.
				report( error );
				this.manager.itemError( resolved );
				return;

			}

			onLoad( volume );

		}, onProgress, ( error ) => report( requestError( where, resolved, error ) ) );

	}

	/**
	 * A volume from a baked file's bytes (the binary form, or the JSON form as UTF-8), the JSON
	 * text or the parsed JSON object — what `load()` calls on the downloaded bytes.
	 * @param data The file (an `ArrayBuffer`, a typed array such as a Node `Buffer`, a `DataView`), JSON text or JSON object.
	 * @param parameters Constructor parameters besides the file's, e.g. `{ occluders }`; default: `this.parameters`.
	 * @throws {BakedVolumeError} when the data is not a valid baked volume (code: what is wrong).
	 */
	parse( data: LightProbeVolumeData, parameters: BakedVolumeParameters = this.parameters ): LightProbeVolume {

		return this.parseData( data, parameters, null );

	}

	/** `parse`, with the URL the bytes came from for the messages (null when none). */
	private parseData( data: unknown, parameters: unknown, url: string | null ): LightProbeVolume {

		const where = 'LightProbeVolumeLoader.parse';
		assertBakedVolumeParameters( where, parameters );
		let baked: BakedVolumeData;
		try {

			baked = readBakedVolume( where, data );

		} catch ( error ) {

			throw renameBakedVolumeError( where, error, url === null ? '' : `"${url}": ` );

		}

		return LightProbeVolume.fromBakedData( baked, parameters );

	}

}

/** The decoded volume of any form `parse` takes, told apart by type and first bytes. */
function readBakedVolume( where: string, data: unknown ): BakedVolumeData {

	if ( typeof data === 'string' ) return readText( where, data.replace( /^\uFEFF/, '' ) );
	if ( data instanceof ArrayBuffer || ArrayBuffer.isView( data ) ) {

		const bytes = data instanceof ArrayBuffer
			? new Uint8Array( data ) : new Uint8Array( data.buffer, data.byteOffset, data.byteLength );
		// Not the binary magic: JSON (or a web page) when the first byte after a BOM and white space says so.
		let first = bytes[ 0 ] === 0xEF && bytes[ 1 ] === 0xBB && bytes[ 2 ] === 0xBF ? 3 : 0;
		while ( first < bytes.length && isWhiteSpace( bytes[ first ] ) ) first ++;
		const lead = bytes[ first ];
		if ( bytes[ 0 ] !== BAKED_VOLUME_MAGIC[ 0 ] && ( lead === 0x7B || lead === 0x3C ) ) {

			let text: string;
			try {

				text = utf8Decoder.decode( bytes );

			} catch {

				throw new BakedVolumeError( 'utf8', `${where}: the data starts like JSON text but is not valid UTF-8.` );

			}

			return readText( where, text );

		}

		return decodeBakedVolume( data );

	}

	if ( data !== null && typeof data === 'object' ) return bakedVolumeFromJSON( data );
	throw new BakedVolumeError( 'argument', `${where}: data must be a baked file (an ArrayBuffer or a typed array), `
		+ `its JSON text or its JSON object, got ${describeValue( data )}.` );

}

/** The JSON form's text, or the error for a web page where a volume was expected. */
function readText( where: string, text: string ): BakedVolumeData {

	if ( /^\s*</.test( text ) ) {

		throw new BakedVolumeError( 'bad-magic', `${where}: the data is an HTML or XML page, not a baked light probe volume `
			+ '(servers such as Vite\'s answer a missing file with a page: check the URL and that the file is served).' );

	}

	return bakedVolumeFromJSON( text );

}

/** JSON's white space: space, tab, line feed, carriage return. */
function isWhiteSpace( byte: number ): boolean {

	return byte === 0x20 || byte === 0x09 || byte === 0x0A || byte === 0x0D;

}

/** The error of a failed request: the URL, and the HTTP status when the server answered. */
function requestError( where: string, url: string, error: unknown ): Error {

	const status = ( error as { response?: { status?: unknown; statusText?: unknown } } | null )?.response;
	const reason = typeof status?.status === 'number'
		? `the server answered HTTP ${status.status}${status.statusText ? ` ${String( status.statusText )}` : ''}`
		: `the request failed (${( error as Error | null )?.message ?? String( error )})`;
	return new Error( `${where}: "${url}" could not be loaded: ${reason}.`, { cause: error } );

}
