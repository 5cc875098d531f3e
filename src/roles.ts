/**
 * Probe roles and the per-probe name and role lists, shared by the runtime, placement and the
 * baked format (pure: no three.js).
 */

/** What a probe is for; capture settings can differ per role (e.g. a longer far plane for sky probes). */
export type ProbeRole = 'sky' | 'bounce' | 'bleed' | 'fill';

/** Every role, in the order the baked format stores them as codes 0..3. */
export const PROBE_ROLES: readonly ProbeRole[] = [ 'sky', 'bounce', 'bleed', 'fill' ];

/** The role probes get when none is given. */
export const DEFAULT_PROBE_ROLE: ProbeRole = 'fill';

/** Whether a value is one of {@link PROBE_ROLES}. */
export function isProbeRole( value: unknown ): value is ProbeRole {

	return typeof value === 'string' && ( PROBE_ROLES as readonly string[] ).includes( value );

}

/**
 * Reads an optional per-probe list of names: `undefined` gives `count` empty names. Throws a
 * `TypeError`/`RangeError` starting with `where` for a non-array, a wrong length or a non-string.
 */
export function readProbeNames( where: string, names: unknown, count: number ): string[] {

	if ( names === undefined ) return new Array<string>( count ).fill( '' );
	const list = readList( where, 'names', names, count );
	for ( let i = 0; i < count; i ++ ) {

		if ( typeof list[ i ] !== 'string' ) throw new TypeError( `${where}: names[${i}] is ${describe( list[ i ] )}; expected a string.` );

	}

	return list as string[];

}

/**
 * Reads an optional per-probe list of roles: `undefined` gives `count` × {@link DEFAULT_PROBE_ROLE}.
 * Throws a `TypeError`/`RangeError` starting with `where` for a non-array, a wrong length or an unknown role.
 */
export function readProbeRoles( where: string, roles: unknown, count: number ): ProbeRole[] {

	if ( roles === undefined ) return new Array<ProbeRole>( count ).fill( DEFAULT_PROBE_ROLE );
	const list = readList( where, 'roles', roles, count );
	for ( let i = 0; i < count; i ++ ) {

		if ( ! isProbeRole( list[ i ] ) ) throw new RangeError( `${where}: roles[${i}] is ${describe( list[ i ] )}; expected one of ${PROBE_ROLES.join( ', ' )}.` );

	}

	return list as ProbeRole[];

}

function readList( where: string, name: string, values: unknown, count: number ): unknown[] {

	if ( ! Array.isArray( values ) ) throw new TypeError( `${where}: ${name} must be an array with one entry per probe, got ${describe( values )}.` );
	if ( values.length !== count ) throw new RangeError( `${where}: ${name} must have one entry per probe (${count}), got ${values.length}.` );
	return Array.from( values );

}

function describe( value: unknown ): string {

	if ( typeof value === 'string' ) return JSON.stringify( value );
	if ( value === null ) return 'null';
	if ( Array.isArray( value ) ) return 'an array';
	return typeof value === 'object' ? 'an object' : `${typeof value} ${String( value )}`;

}
