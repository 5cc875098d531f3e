import type { BakeLight, Vec3 } from './bakePage/protocol.js';
import { CliError } from './errors.js';
import { LIGHT_DEFAULTS, parseHexColor } from './lightFlags.js';

/*
 * The "lights" array of a probe layout file: the lights a bake adds, next to the probes they are
 * placed for. The same lights as --sun / --point / --spot, with decay too.
 */

const KEYS: Record<BakeLight[ 'type' ], readonly string[]> = {
	directional: [ 'type', 'direction', 'intensity', 'color' ],
	point: [ 'type', 'position', 'intensity', 'color', 'distance', 'decay' ],
	spot: [ 'type', 'position', 'target', 'intensity', 'color', 'distance', 'decay', 'angle', 'penumbra' ],
};

/**
 * Parses and checks a layout's "lights" value (as `readLayout` passes it through):
 * `[ { "type": "point" | "spot" | "directional", "position" | "direction", "target"?, "intensity"?,
 * "color"?, "distance"?, "decay"?, "angle"?, "penumbra"? }, … ]`. Directional lights take a
 * `direction` towards the light, point and spot lights a `position`; a spot aims at `target`
 * (default the origin, as three's). Colours are "#rrggbb" (sRGB), `angle` the cone's half angle in
 * degrees. Defaults: intensity 3 (directional) or 1, white, distance 0 (no cut-off), decay 2
 * (physically based), angle 60, penumbra 0.
 * @param file The layout's path, for the messages.
 * @param value The "lights" value, or undefined (no lights).
 * @throws {CliError} exit code 2, naming the file, the light and what was expected.
 */
export function parseLayoutLights( file: string, value: unknown ): BakeLight[] {

	if ( value === undefined ) return [];
	if ( ! Array.isArray( value ) ) throw new CliError( `probe layout ${file}: "lights" must be an array of { "type", "position" | "direction", … }.` );
	return value.map( ( entry, i ) => parseLight( file, entry, i ) );

}

function parseLight( file: string, entry: unknown, index: number ): BakeLight {

	const at = `probe layout ${file}: lights[${index}]`;
	if ( entry === null || typeof entry !== 'object' || Array.isArray( entry ) ) throw new CliError( `${at} must be an object { "type", … }.` );
	const light = entry as Record<string, unknown>;
	const type = light.type;
	if ( type !== 'point' && type !== 'spot' && type !== 'directional' ) {

		throw new CliError( `${at} has "type" ${JSON.stringify( type )}; expected "point", "spot" or "directional".` );

	}

	const name = `${at} (${type})`;
	for ( const key of Object.keys( light ) ) {

		if ( ! KEYS[ type ].includes( key ) ) throw new CliError( `${name} has the key "${key}", which a ${type} light does not take; expected ${KEYS[ type ].join( ', ' )}.` );

	}

	const intensity = number( name, light, 'intensity', type === 'directional' ? LIGHT_DEFAULTS.sunIntensity : LIGHT_DEFAULTS.intensity, 0 );
	const color = colour( name, light.color );
	if ( type === 'directional' ) {

		const direction = vector( name, light, 'direction' );
		if ( direction.every( ( v ) => v === 0 ) ) throw new CliError( `${name}: "direction" must not be [0, 0, 0].` );
		return { type, direction, intensity, color, source: 'layout' };

	}

	const position = vector( name, light, 'position' );
	const distance = number( name, light, 'distance', LIGHT_DEFAULTS.distance, 0 );
	const decay = number( name, light, 'decay', LIGHT_DEFAULTS.decay, 0 );
	if ( type === 'point' ) return { type, position, intensity, color, distance, decay, source: 'layout' };

	const target: Vec3 = light.target === undefined ? [ 0, 0, 0 ] : vector( name, light, 'target' );
	if ( position.every( ( v, i ) => v === target[ i ] ) ) throw new CliError( `${name}: "target" is the light's "position"; it must aim somewhere.` );
	const angle = number( name, light, 'angle', LIGHT_DEFAULTS.angle, 0 );
	if ( ! ( angle > 0 && angle <= 90 ) ) throw new CliError( `${name}: "angle" is ${angle}; expected the cone's half angle in degrees, in (0, 90].` );
	const penumbra = number( name, light, 'penumbra', LIGHT_DEFAULTS.penumbra, 0 );
	if ( penumbra > 1 ) throw new CliError( `${name}: "penumbra" is ${penumbra}; expected a number in [0, 1].` );
	return { type, position, target, intensity, color, distance, decay, angle, penumbra, source: 'layout' };

}

function vector( name: string, light: Record<string, unknown>, key: string ): Vec3 {

	const value = light[ key ];
	if ( value === undefined ) throw new CliError( `${name} has no "${key}"; expected [x, y, z].` );
	if ( ! Array.isArray( value ) || value.length !== 3 || value.some( ( v ) => typeof v !== 'number' || ! Number.isFinite( v ) ) ) {

		throw new CliError( `${name}: "${key}" is ${JSON.stringify( value )}; expected [x, y, z] (3 finite numbers).` );

	}

	return [ value[ 0 ], value[ 1 ], value[ 2 ] ];

}

function number( name: string, light: Record<string, unknown>, key: string, fallback: number, min: number ): number {

	const value = light[ key ];
	if ( value === undefined ) return fallback;
	if ( typeof value !== 'number' || ! Number.isFinite( value ) || value < min ) {

		throw new CliError( `${name}: "${key}" is ${JSON.stringify( value )}; expected a finite number ≥ ${min}.` );

	}

	return value;

}

function colour( name: string, value: unknown ): number {

	if ( value === undefined ) return LIGHT_DEFAULTS.color;
	const hex = typeof value === 'string' ? parseHexColor( value ) : undefined;
	if ( hex === undefined ) throw new CliError( `${name}: "color" is ${JSON.stringify( value )}; expected "#rrggbb" (sRGB).` );
	return hex;

}
