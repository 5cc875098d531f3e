import { existsSync, readFileSync, statSync } from 'node:fs';
import { DegenerateInputError, tetrahedralize, type Tetrahedralization } from '../src/tetrahedra/tetrahedralize.js';
import { BAKED_ROLES as ROLES, validateBakedVolume, type BakedProbeRole as ProbeRole } from '../src/io/index.js';
import { CliError } from './errors.js';
import { layoutShape, type LayoutShapeResult } from './layoutShape.js';

const AXES = [ 'x', 'y', 'z' ];

/** A validated probe layout (the JSON of scenes/*.json). */
export interface CliLayout {

	name: string;
	positions: Float64Array;
	names: string[];
	roles: ProbeRole[];
	/** Named groups of probes, passed to the volume as they are (the codec checks them). */
	zones: { name: string; probes: number[]; bounds?: number[] }[];
	/** The layout's "lights" value as written (unchecked here; cli/layoutLights.ts parses it), or undefined. */
	lights?: unknown;

}

/**
 * Reads and validates a probe layout file:
 * `{ name?, positions: number[], names?: string[], roles?: string[], zones?: [...], lights?: [...] }`.
 * Names default to '' (none), roles to "fill"; `lights` is passed through unchecked.
 * @param file Path of the JSON file (named in every message).
 * @throws {CliError} exit code 2: missing or unreadable file, bad JSON, a coordinate that is not a
 * finite number (naming the probe and axis), fewer than 4 probes, names/roles of the wrong length,
 * an unknown role.
 */
export function readLayout( file: string ): CliLayout {

	if ( ! existsSync( file ) ) throw new CliError( `probe layout ${file} not found.` );
	if ( ! statSync( file ).isFile() ) throw new CliError( `probe layout ${file} is not a file.` );
	let json: unknown;
	try {

		// A UTF-8 byte-order mark (Windows editors write one) is not part of the JSON text.
		json = JSON.parse( readFileSync( file, 'utf8' ).replace( /^\uFEFF/, '' ) );

	} catch ( error ) {

		const message = ( error as Error ).message;
		// The hint only where it applies: a bare NaN or Infinity where a number belongs.
		const hint = /\b(NaN|Infinity)\b/.test( readFileSync( file, 'utf8' ) ) ? '; NaN and Infinity cannot be written in JSON' : '';
		throw new CliError( `probe layout ${file} is not valid JSON (${message})${hint}.` );

	}

	if ( json === null || typeof json !== 'object' || Array.isArray( json ) ) throw new CliError( `probe layout ${file} must be a JSON object { "positions": [x, y, z, ...] }.` );
	const layout = json as Record<string, unknown>;
	const raw = layout.positions;
	if ( ! Array.isArray( raw ) ) throw new CliError( `probe layout ${file} has no "positions" array.` );
	if ( raw.length % 3 !== 0 ) throw new CliError( `probe layout ${file}: "positions" must hold x, y, z per probe (a multiple of 3 numbers), got ${raw.length} numbers.` );
	const count = raw.length / 3;
	for ( let i = 0; i < raw.length; i ++ ) {

		const v = raw[ i ];
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) {

			throw new CliError( `probe layout ${file}: probe ${Math.floor( i / 3 )} has ${AXES[ i % 3 ]} = ${JSON.stringify( v )} (positions[${i}]); every coordinate must be a finite number.` );

		}

	}

	if ( count < 4 ) throw new CliError( `probe layout ${file} has ${count} probe${count === 1 ? '' : 's'}; a layout needs at least 4.` );

	const names = optionalList( file, layout, 'names', count, () => '' );
	names.forEach( ( name, i ) => {

		if ( typeof name !== 'string' ) throw new CliError( `probe layout ${file}: names[${i}] (probe ${i}) is ${JSON.stringify( name )}; names must be strings.` );

	} );
	const roles = optionalList( file, layout, 'roles', count, () => 'fill' );
	roles.forEach( ( role, i ) => {

		if ( ! ROLES.includes( role as ProbeRole ) ) throw new CliError( `probe layout ${file}: probe ${i} has the unknown role ${JSON.stringify( role )}; expected one of ${ROLES.join( ', ' )}.` );

	} );

	const zones = layout.zones ?? [];
	if ( ! Array.isArray( zones ) ) throw new CliError( `probe layout ${file}: "zones" must be an array of { name, probes, bounds? }.` );

	const name = typeof layout.name === 'string' ? layout.name : '';
	const result: CliLayout = {
		name, positions: Float64Array.from( raw as number[] ), names: names as string[], roles: roles as ProbeRole[], zones,
	};
	if ( layout.lights !== undefined ) result.lights = layout.lights;
	return result;

}

function optionalList(
	file: string, layout: Record<string, unknown>, key: string, count: number, fallback: ( i: number ) => string
): unknown[] {

	const value = layout[ key ];
	if ( value === undefined ) return Array.from( { length: count }, ( _, i ) => fallback( i ) );
	if ( ! Array.isArray( value ) ) throw new CliError( `probe layout ${file}: "${key}" must be an array.` );
	if ( value.length !== count ) throw new CliError( `probe layout ${file}: "${key}" has ${value.length} entries for ${count} probes.` );
	return value;

}

/**
 * Tetrahedralizes a validated layout, or returns null for one that spans no volume: probes in one
 * plane or on one line are stored without tetrahedra, and `LightProbeVolume` interpolates them in
 * their plane (`PlanarMesh`) or along their line, as it does for `new LightProbeVolume( { positions } )`.
 * @param file The layout's path, for the messages.
 * @returns The tetrahedralization, or null for a planar or collinear layout.
 * @throws {CliError} exit code 2: two probes at the same place (naming both; all probes at one
 * place is that too), a coordinate float64 cannot hold beside the layout's extent.
 */
export function tetrahedralizeLayout( file: string, layout: CliLayout ): Tetrahedralization | null {

	const p = layout.positions;
	let shape: LayoutShapeResult;
	try {

		shape = layoutShape( p );

	} catch ( error ) {

		if ( error instanceof DegenerateInputError ) throw new CliError( `probe layout ${file}: ${error.message}` );
		throw error;

	}

	const { duplicates } = shape;
	if ( duplicates.length > 0 ) {

		const a = duplicates[ 0 ], b = duplicates[ 1 ];
		const label = ( i: number ) => layout.names[ i ] ? `probe ${i} ("${layout.names[ i ]}")` : `probe ${i}`;
		const more = duplicates.length > 2 ? ` (and ${duplicates.length / 2 - 1} more duplicates)` : '';
		throw new CliError( `probe layout ${file}: ${label( a )} and ${label( b )} are at the same position (${p[ 3 * b ]}, ${p[ 3 * b + 1 ]}, `
			+ `${p[ 3 * b + 2 ]})${more}; remove one.` );

	}

	return shape.shape === 'volume' ? tetrahedralize( p ) : null;

}

/**
 * Runs the volume codec's own checks on everything but the SH (zeros here) before the capture, so a
 * layout the codec would reject (a bad zone, a name it cannot store) fails in milliseconds, not
 * after the bake. A null tetrahedralization (a planar or collinear layout) is checked as a volume
 * stored without tetrahedra.
 * @throws {CliError} exit code 2 with the codec's message.
 */
export function checkVolumeInput( file: string, layout: CliLayout, tetrahedralization: Tetrahedralization | null ): void {

	try {

		validateBakedVolume( {
			positions: layout.positions, sh: new Float32Array( 27 * layout.positions.length / 3 ),
			tetrahedra: tetrahedralization?.tetrahedra, neighbors: tetrahedralization?.neighbors,
			names: layout.names, roles: layout.roles, zones: layout.zones,
		}, 'capture-lighting' );

	} catch ( error ) {

		throw new CliError( `probe layout ${file}: ${( error as Error ).message.replace( /^capture-lighting: /, '' )}` );

	}

}
