import { Vector3, type Object3D } from 'three';
import { PROBE_ROLES, isProbeRole, type ProbeRole } from '../roles.js';


// "probe" at the start of the name, any case: probe, Probe_sky_01, PROBE.003, probeBounce2.
const LOCATOR_NAME = /^probe/i;

/** Result of {@link findProbeLocators}: parallel arrays, one entry per locator, in traversal order. */
export interface ProbeLocators {

	/** World position of each locator, x, y, z. */
	positions: Float64Array;

	/** Each locator's object name (may be empty for an unnamed object tagged by `userData.probe`). */
	names: string[];

	/** Each locator's role: from `userData.probe.role`, else from its name, else `'fill'`. */
	roles: ProbeRole[];

}

const _position = new Vector3();

/**
 * Finds the probe locators an artist placed in a DCC tool (paper 2.1): objects — typically
 * empties — under `root` (root included) that are named `probe…` (case-insensitive) or carry
 * `userData.probe`. glTF node `extras` arrive as `userData` through three's GLTFLoader, so a
 * Blender empty with the custom property `probe = { "role": "sky" }` (exported with "Include →
 * Custom Properties") or simply named `probe_sky_01` is found either way.
 *
 * - **Role**: `userData.probe.role` (or `userData.probe` given as a role string) wins; else the
 *   first word of the name that is a role (`probe_sky_01`, `Probe-Bounce`, `probeBleed2` → sky,
 *   bounce, bleed); else `'fill'`. A role in `userData` that is not one of sky, bounce, bleed,
 *   fill throws, naming the object — a typo silently turning into a fill probe would be hard to find.
 * - `userData.probe === false` excludes an object even when its name starts with `probe`.
 * - The descendants of a locator are not searched: GLTFLoader names the meshes of a
 *   multi-primitive node after it (`probe_sky_1`, …), and a locator's helper geometry is not
 *   another probe.
 * - Positions are world positions after `root.updateWorldMatrix( true, true )`.
 */
export function findProbeLocators( root: Object3D ): ProbeLocators {

	const where = 'findProbeLocators';
	if ( root === null || typeof root !== 'object' || ( root as Object3D ).isObject3D !== true ) {

		throw new TypeError( `${where}: root must be a three.js Object3D.` );

	}

	root.updateWorldMatrix( true, true );
	const positions: number[] = [], names: string[] = [], roles: ProbeRole[] = [];

	const visit = ( object: Object3D ): void => {

		const tag: unknown = object.userData?.probe;
		const named = LOCATOR_NAME.test( object.name );
		if ( tag !== false && ( named || ( tag !== undefined && tag !== null ) ) ) {

			object.getWorldPosition( _position );
			positions.push( _position.x, _position.y, _position.z );
			names.push( object.name );
			roles.push( roleFromTag( where, object, tag ) ?? roleFromName( object.name ) ?? 'fill' );
			return;

		}

		for ( const child of object.children ) visit( child );

	};

	visit( root );
	return { positions: Float64Array.from( positions ), names, roles };

}

/** The role given in `userData.probe` (`{ role }` or a role string), or undefined when none is given. */
function roleFromTag( where: string, object: Object3D, tag: unknown ): ProbeRole | undefined {

	let role: unknown;
	if ( typeof tag === 'string' ) role = tag;
	else if ( tag !== null && typeof tag === 'object' ) role = ( tag as { role?: unknown } ).role;
	if ( role === undefined || role === null || role === '' ) return undefined;
	const normalized = typeof role === 'string' ? role.trim().toLowerCase() : role;
	if ( ! isProbeRole( normalized ) ) {

		throw new RangeError( `${where}: object "${object.name}" has userData.probe role ${JSON.stringify( role )}; expected one of ${PROBE_ROLES.join( ', ' )}.` );

	}

	return normalized;

}

/** The first word of the name after "probe" that is a role: words split at non-letters and at camelCase humps. */
function roleFromName( name: string ): ProbeRole | undefined {

	const words = name.replace( LOCATOR_NAME, '' ).split( /[^A-Za-z]+|(?=[A-Z][a-z])/ );
	for ( const word of words ) {

		const lower = word.toLowerCase();
		if ( isProbeRole( lower ) ) return lower;

	}

	return undefined;

}
