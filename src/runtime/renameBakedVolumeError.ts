import { BakedVolumeError } from '../io/BakedVolumeError.js';

// The codec's functions, whose names start the messages of the errors they throw.
const CODEC_PREFIX = /^(?:decodeBakedVolume|encodeBakedVolume|bakedVolumeFromJSON|bakedVolumeToJSON|validateBakedVolume): /;

/**
 * A codec error as the error of the API the user called: a `BakedVolumeError` of the same code
 * whose message starts with `where` and `context` instead of the codec function's name (the
 * original is its `cause`). Any other error is returned as it is.
 * @param where The API's name, e.g. `'LightProbeVolumeLoader.parse'`.
 * @param error What the codec threw.
 * @param context Put after `where: `, e.g. the URL the bytes came from and a colon.
 */
export function renameBakedVolumeError( where: string, error: unknown, context = '' ): unknown {

	if ( ! ( error instanceof BakedVolumeError ) ) return error;
	const own = `${where}: `;
	const text = error.message.startsWith( own ) ? error.message.slice( own.length ) : error.message.replace( CODEC_PREFIX, '' );
	const renamed = new BakedVolumeError( error.code, `${own}${context}${text}` );
	renamed.cause = error;
	return renamed;

}
