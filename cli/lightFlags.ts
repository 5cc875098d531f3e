import type { BakeLight, Vec3 } from './bakePage/protocol.js';
import { CliError } from './errors.js';

/*
 * The light flags of `capture-lighting bake`: --sun, --point and --spot, each a comma-separated
 * list of fields, the first ones required. Every message names the flag, the syntax and the value.
 */

/** The syntax of each light flag, as `--help` and the messages show it. */
export const LIGHT_FLAG_SYNTAX = {
	'--sun': 'x,y,z[,intensity[,#rrggbb]]',
	'--point': 'x,y,z[,intensity[,#rrggbb[,distance]]]',
	'--spot': 'x,y,z,tx,ty,tz[,intensity[,#rrggbb[,angle°[,penumbra[,distance]]]]]',
} as const;

/** The defaults of the light flags and of the layout's "lights" (three's own, but --sun's intensity). */
export const LIGHT_DEFAULTS = {
	sunIntensity: 3,
	intensity: 1,
	color: 0xffffff,
	distance: 0,
	decay: 2,
	angle: 60,
	penumbra: 0,
} as const;

/** `--sun x,y,z[,intensity[,#rrggbb]]`: a directional light from direction x,y,z (towards the sun). */
export function parseSunFlag( text: string ): BakeLight {

	const flag = '--sun';
	const fields = splitFields( text );
	if ( fields.length < 3 || fields.length > 5 || fields.slice( 0, 4 ).some( ( field ) => ! isNumber( field ) ) ) {

		throw new CliError( `--sun must be x,y,z or x,y,z,intensity or x,y,z,intensity,#rrggbb (finite numbers), got "${text}".` );

	}

	const direction = vector( fields, 0 );
	if ( direction[ 0 ] === 0 && direction[ 1 ] === 0 && direction[ 2 ] === 0 ) throw new CliError( '--sun direction must not be 0,0,0.' );
	return {
		type: 'directional', direction,
		intensity: intensity( flag, text, fields[ 3 ], LIGHT_DEFAULTS.sunIntensity ),
		color: color( flag, text, fields[ 4 ] ),
		source: 'flags',
	};

}

/** `--point x,y,z[,intensity[,#rrggbb[,distance]]]`: a point light at x,y,z. */
export function parsePointFlag( text: string ): BakeLight {

	const flag = '--point';
	const fields = splitFields( text );
	expectFields( flag, text, fields, 3, 6, [ 0, 1, 2, 3, 5 ] );
	return {
		type: 'point', position: vector( fields, 0 ),
		intensity: intensity( flag, text, fields[ 3 ], LIGHT_DEFAULTS.intensity ),
		color: color( flag, text, fields[ 4 ] ),
		distance: nonNegative( flag, text, 'distance', fields[ 5 ], LIGHT_DEFAULTS.distance ),
		decay: LIGHT_DEFAULTS.decay,
		source: 'flags',
	};

}

/** `--spot x,y,z,tx,ty,tz[,intensity[,#rrggbb[,angle°[,penumbra[,distance]]]]]`: a spot light at x,y,z aiming at tx,ty,tz. */
export function parseSpotFlag( text: string ): BakeLight {

	const flag = '--spot';
	const fields = splitFields( text );
	expectFields( flag, text, fields, 6, 11, [ 0, 1, 2, 3, 4, 5, 6, 8, 9, 10 ] );
	const position = vector( fields, 0 ), target = vector( fields, 3 );
	if ( position.every( ( v, i ) => v === target[ i ] ) ) throw new CliError( `--spot "${text}": the target tx,ty,tz is the light's position; it must aim somewhere.` );
	const angle = fields[ 8 ] === undefined ? LIGHT_DEFAULTS.angle : Number( fields[ 8 ] );
	if ( ! ( angle > 0 && angle <= 90 ) ) throw new CliError( `--spot "${text}": angle° must be in (0, 90] degrees (the cone's half angle), got ${fields[ 8 ]}.` );
	const penumbra = fields[ 9 ] === undefined ? LIGHT_DEFAULTS.penumbra : Number( fields[ 9 ] );
	if ( ! ( penumbra >= 0 && penumbra <= 1 ) ) throw new CliError( `--spot "${text}": penumbra must be in [0, 1], got ${fields[ 9 ]}.` );
	return {
		type: 'spot', position, target,
		intensity: intensity( flag, text, fields[ 6 ], LIGHT_DEFAULTS.intensity ),
		color: color( flag, text, fields[ 7 ] ),
		distance: nonNegative( flag, text, 'distance', fields[ 10 ], LIGHT_DEFAULTS.distance ),
		decay: LIGHT_DEFAULTS.decay,
		angle, penumbra,
		source: 'flags',
	};

}

/** An sRGB `#rrggbb` colour as a hex number, or undefined when `text` is not one. */
export function parseHexColor( text: string ): number | undefined {

	const hex = /^#([0-9a-f]{6})$/i.exec( text );
	return hex ? parseInt( hex[ 1 ], 16 ) : undefined;

}

function splitFields( text: string ): string[] {

	return text.split( ',' ).map( ( field ) => field.trim() );

}

function isNumber( field: string ): boolean {

	return field !== '' && Number.isFinite( Number( field ) );

}

/** Checks the field count and that the fields at `numeric` (when given) are finite numbers. */
function expectFields(
	flag: keyof typeof LIGHT_FLAG_SYNTAX, text: string, fields: string[], min: number, max: number, numeric: number[],
): void {

	const syntax = `${flag} must be ${LIGHT_FLAG_SYNTAX[ flag ]}`;
	if ( fields.length < min || fields.length > max ) {

		throw new CliError( `${syntax} (${min} to ${max} fields), got ${fields.length} field${fields.length === 1 ? '' : 's'} in "${text}".` );

	}

	const bad = numeric.find( ( i ) => i < fields.length && ! isNumber( fields[ i ] ) );
	if ( bad !== undefined ) throw new CliError( `${syntax}; field ${bad + 1} of "${text}" is "${fields[ bad ]}", not a finite number.` );

}

function vector( fields: string[], first: number ): Vec3 {

	return [ Number( fields[ first ] ), Number( fields[ first + 1 ] ), Number( fields[ first + 2 ] ) ];

}

function intensity( flag: string, text: string, field: string | undefined, fallback: number ): number {

	return nonNegative( flag, text, 'intensity', field, fallback );

}

function nonNegative( flag: string, text: string, name: string, field: string | undefined, fallback: number ): number {

	if ( field === undefined ) return fallback;
	const value = Number( field );
	if ( ! ( value >= 0 ) ) throw new CliError( `${flag} "${text}": ${name} must be ≥ 0, got ${field}.` );
	return value;

}

function color( flag: string, text: string, field: string | undefined ): number {

	if ( field === undefined ) return LIGHT_DEFAULTS.color;
	const value = parseHexColor( field );
	if ( value === undefined ) throw new CliError( `${flag} "${text}": the colour must be #rrggbb (sRGB), got "${field}".` );
	return value;

}
