import type { ProbeRole } from '../roles.js';
import { BAKED_VOLUME_JSON_FORMAT, BAKED_VOLUME_VERSION_MAJOR, bakedVolumeMinorVersion } from './bakedVolumeFormat.js';
import { fail } from './checks.js';
import { validateBakedVolume } from './validateBakedVolume.js';
import type { BakedCapture, BakedFit, BakedVolumeData, BakedVolumeInput, BakedVolumeJSON } from './bakedVolumeTypes.js';

/* The JSON form of a baked volume (docs/format.md, "JSON form"): the binary sections as arrays. */

/**
 * The JSON form of a volume: a plain object for `JSON.stringify` (numbers print so that they read
 * back exactly, so the round trip is lossless). Validates the input like {@link encodeBakedVolume};
 * version 1.1 with `gradients` or `fit`, else 1.0.
 */
export function bakedVolumeToJSON( input: BakedVolumeInput ): BakedVolumeJSON {

	const data = validateBakedVolume( input, 'bakedVolumeToJSON' );
	const json: BakedVolumeJSON = {
		format: BAKED_VOLUME_JSON_FORMAT,
		version: [ BAKED_VOLUME_VERSION_MAJOR, bakedVolumeMinorVersion( data ) ],
		probeCount: data.positions.length / 3,
		tetrahedronCount: data.tetrahedra.length / 4,
		positions: Array.from( data.positions ),
		sh: Array.from( data.sh ),
		tetrahedra: Array.from( data.tetrahedra ),
		neighbors: Array.from( data.neighbors ),
		names: data.names.slice(),
		roles: data.roles.slice(),
		zones: data.zones.map( ( zone ) => ( { name: zone.name, probes: Array.from( zone.probes ), bounds: Array.from( zone.bounds ) } ) ),
		bounds: Array.from( data.bounds ),
		capture: JSON.parse( JSON.stringify( data.capture ) ),
		metadata: data.metadata,
	};
	if ( data.gradients ) json.gradients = Array.from( data.gradients );
	if ( data.fit ) json.fit = { ...data.fit };
	return json;

}

/**
 * Reads the JSON form (an object, or its text) with the same checks as the binary reader.
 * Members a 1.x writer may add later are ignored.
 * @throws {BakedVolumeError}
 */
export function bakedVolumeFromJSON( json: unknown ): BakedVolumeData {

	const where = 'bakedVolumeFromJSON';
	let value = json;
	if ( typeof value === 'string' ) {

		try {

			value = JSON.parse( value );

		} catch ( error ) {

			fail( 'json', where, `not valid JSON (${( error as Error ).message}).` );

		}

	}

	if ( value === null || typeof value !== 'object' || Array.isArray( value ) ) fail( 'json', where, 'expected a JSON object.' );
	const o = value as Record<string, unknown>;
	if ( o.format !== BAKED_VOLUME_JSON_FORMAT ) fail( 'bad-magic', where, `not a baked light probe volume (format is ${JSON.stringify( o.format ) ?? 'missing'}, expected "${BAKED_VOLUME_JSON_FORMAT}").` );
	const version = o.version;
	if ( ! Array.isArray( version ) || version.length !== 2 || ! version.every( ( v ) => Number.isInteger( v ) && v >= 0 ) ) fail( 'version', where, 'version must be [ major, minor ].' );
	if ( version[ 0 ] > BAKED_VOLUME_VERSION_MAJOR ) fail( 'version', where, `version ${version[ 0 ]}.${version[ 1 ]} is newer than this reader (supports ≤ ${BAKED_VOLUME_VERSION_MAJOR}.x).` );
	if ( version[ 0 ] < 1 ) fail( 'version', where, `version ${version[ 0 ]}.${version[ 1 ]} is not a released version of the format (this reader supports 1.x).` );
	const data = validateBakedVolume( {
		positions: o.positions as number[],
		sh: o.sh as number[],
		tetrahedra: o.tetrahedra as number[] | undefined,
		neighbors: o.neighbors as number[] | undefined,
		names: o.names as string[] | undefined,
		roles: o.roles as ProbeRole[] | undefined,
		zones: o.zones as BakedVolumeInput[ 'zones' ],
		bounds: o.bounds as number[] | undefined,
		capture: o.capture as BakedCapture | undefined,
		metadata: o.metadata as string | undefined,
		gradients: o.gradients as number[] | undefined,
		fit: o.fit as BakedFit | undefined,
	}, where );
	if ( o.probeCount !== undefined && o.probeCount !== data.positions.length / 3 ) fail( 'count', where, `probeCount is ${o.probeCount} but positions holds ${data.positions.length / 3} probes.` );
	if ( o.tetrahedronCount !== undefined && o.tetrahedronCount !== data.tetrahedra.length / 4 ) fail( 'count', where, `tetrahedronCount is ${o.tetrahedronCount} but tetrahedra holds ${data.tetrahedra.length / 4}.` );
	return data;

}
