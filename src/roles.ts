/**
 * Probe roles, and the rules for what a volume's probes and zones may be called and hold: one set
 * of rules for the runtime (`LightProbeVolume`), placement and the baked format, so that a file
 * the codec writes or accepts always loads (pure: no three.js). Each rule reports through a
 * {@link RuleReject} of its caller, which picks the error class: `TypeError`/`RangeError` in the
 * runtime, `BakedVolumeError` in the codec.
 */
import { isStorableText } from './validate.js';

/** What a probe is for; capture settings can differ per role (e.g. a longer far plane for sky probes). */
export type ProbeRole = 'sky' | 'bounce' | 'bleed' | 'fill';

/** Every role, in the order the baked format stores them as codes 0..3. */
export const PROBE_ROLES: readonly ProbeRole[] = [ 'sky', 'bounce', 'bleed', 'fill' ];

/** The role probes get when none is given. */
export const DEFAULT_PROBE_ROLE: ProbeRole = 'fill';

/**
 * Which rule a value broke: `'type'` (not an array, not a string), `'count'` (a wrong length, an
 * empty zone), `'range'` (an unknown role, an index out of range, a name used twice) or `'text'`
 * (a string with a lone surrogate, which has no UTF-8 form).
 */
export type RuleViolation = 'type' | 'count' | 'range' | 'text';

/** Throws the caller's error for a broken rule; `message` names the field (and index) and the problem. */
export type RuleReject = ( kind: RuleViolation, message: string ) => never;

/** Whether a value is one of {@link PROBE_ROLES}. */
export function isProbeRole( value: unknown ): value is ProbeRole {

	return typeof value === 'string' && ( PROBE_ROLES as readonly string[] ).includes( value );

}

/** The runtime's {@link RuleReject}: a `TypeError` (`'type'`) or `RangeError` whose message starts with `where`. */
export function runtimeReject( where: string ): RuleReject {

	return ( kind, message ) => {

		throw kind === 'type' ? new TypeError( `${where}: ${message}` ) : new RangeError( `${where}: ${message}` );

	};

}

/**
 * A probe or zone name: any string that UTF-8 can hold ('' included).
 * @param label The field for messages, e.g. `names[3]`.
 */
export function checkName( name: unknown, label: string, reject: RuleReject ): string {

	if ( typeof name !== 'string' ) reject( 'type', `${label} is ${describe( name )}; expected a string.` );
	if ( ! isStorableText( name ) ) reject( 'text', `${label} has a lone surrogate and cannot be stored as UTF-8.` );
	return name;

}

/** A probe role (one of {@link PROBE_ROLES}). */
export function checkRole( role: unknown, label: string, reject: RuleReject ): ProbeRole {

	if ( ! isProbeRole( role ) ) reject( 'range', `${label} is ${describe( role )}; expected one of ${PROBE_ROLES.join( ', ' )}.` );
	return role;

}

/** An optional per-probe list of names: `undefined` gives `count` empty names. */
export function checkProbeNames( names: unknown, count: number, reject: RuleReject ): string[] {

	if ( names === undefined ) return new Array<string>( count ).fill( '' );
	const list = readList( 'names', names, count, reject );
	for ( let i = 0; i < count; i ++ ) checkName( list[ i ], `names[${i}]`, reject );
	return list as string[];

}

/** An optional per-probe list of roles: `undefined` gives `count` × {@link DEFAULT_PROBE_ROLE}. */
export function checkProbeRoles( roles: unknown, count: number, reject: RuleReject ): ProbeRole[] {

	if ( roles === undefined ) return new Array<ProbeRole>( count ).fill( DEFAULT_PROBE_ROLE );
	const list = readList( 'roles', roles, count, reject );
	for ( let i = 0; i < count; i ++ ) checkRole( list[ i ], `roles[${i}]`, reject );
	return list as ProbeRole[];

}

/**
 * A zone's name: a name ({@link checkName}, '' included) that no earlier zone of the volume has;
 * it is added to `seen`.
 * @param z The zone's index, for messages.
 */
export function checkZoneName( name: unknown, z: number, seen: Set<string>, reject: RuleReject ): string {

	checkName( name, `zones[${z}].name`, reject );
	const text = name as string;
	if ( seen.has( text ) ) reject( 'range', `zones[${z}].name ${JSON.stringify( text )} is used by an earlier zone; zone names must be unique.` );
	seen.add( text );
	return text;

}

/**
 * A zone's probes: an array or typed array of at least one probe index, each an integer in
 * 0..probeCount − 1 (a probe may belong to several zones; within one, repeats are allowed).
 * @param label The field for messages, e.g. `zones[0].probes`.
 * @returns The indices as a `Uint32Array` (the input when it is one).
 */
export function checkZoneProbes( probes: unknown, label: string, probeCount: number, reject: RuleReject ): Uint32Array {

	const isList = Array.isArray( probes ) || ( ArrayBuffer.isView( probes ) && ! ( probes instanceof DataView ) );
	if ( ! isList ) reject( 'type', `${label} must be an array of probe indices, got ${describe( probes )}.` );
	const list = probes as ArrayLike<unknown>;
	if ( list.length === 0 ) reject( 'count', `${label} is empty; a zone needs at least one probe.` );
	for ( let i = 0; i < list.length; i ++ ) {

		const p = list[ i ];
		if ( typeof p !== 'number' || ! Number.isInteger( p ) || p < 0 || p >= probeCount ) {

			const value = typeof p === 'number' ? String( p ) : describe( p );
			reject( 'range', `${label}[${i}] = ${value} is not a probe index (0..${probeCount - 1}).` );

		}

	}

	return list instanceof Uint32Array ? list : Uint32Array.from( list as ArrayLike<number> );

}

/**
 * Reads an optional per-probe list of names: `undefined` gives `count` empty names. Throws a
 * `TypeError`/`RangeError` starting with `where` for a non-array, a wrong length, a non-string or
 * a string UTF-8 cannot hold.
 */
export function readProbeNames( where: string, names: unknown, count: number ): string[] {

	return checkProbeNames( names, count, runtimeReject( where ) );

}

/**
 * Reads an optional per-probe list of roles: `undefined` gives `count` × {@link DEFAULT_PROBE_ROLE}.
 * Throws a `TypeError`/`RangeError` starting with `where` for a non-array, a wrong length or an unknown role.
 */
export function readProbeRoles( where: string, roles: unknown, count: number ): ProbeRole[] {

	return checkProbeRoles( roles, count, runtimeReject( where ) );

}

function readList( name: string, values: unknown, count: number, reject: RuleReject ): unknown[] {

	if ( ! Array.isArray( values ) ) reject( 'type', `${name} must be an array with one entry per probe, got ${describe( values )}.` );
	const list = values as unknown[];
	if ( list.length !== count ) reject( 'count', `${name} must have one entry per probe (${count}), got ${list.length}.` );
	return Array.from( list );

}

function describe( value: unknown ): string {

	if ( typeof value === 'string' ) return JSON.stringify( value );
	if ( value === null ) return 'null';
	if ( Array.isArray( value ) ) return 'an array';
	return typeof value === 'object' ? 'an object' : `${typeof value} ${String( value )}`;

}
