import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { assertArrayLike } from '../validate.js';

/** A box given by its corners, e.g. a three.js `Box3`. */
export interface BoxLike {

	min: { x: number; y: number; z: number };
	max: { x: number; y: number; z: number };

}

/** One lighting zone, as passed to `LightProbeVolume` (`zones`). */
export interface ProbeZoneDefinition {

	/** Unique, non-empty name, used by `volume.add( object, { zone: name } )`. */
	name: string;

	/**
	 * Indices of the volume's probes lighting this zone (at least 3, not all on one line; 4 not
	 * in one plane for a 3D zone — coplanar probes get a planar triangulation). A probe may belong
	 * to several zones, e.g. one in a doorway.
	 */
	probes: ArrayLike<number>;

	/**
	 * World-space box(es) of the zone: an object without an explicit zone whose anchor is inside
	 * one of them is lit by this zone (the first zone in the list that contains it wins). Without
	 * bounds the zone is used only by name.
	 */
	bounds?: BoxLike | readonly BoxLike[];

}

/** A zone ready for use: its probes and its own interpolator over them. */
export interface ProbeZone {

	/** The zone's name. */
	readonly name: string;

	/** The volume's probe indices of this zone; the interpolator's probe k is `probes[k]`. */
	readonly probes: Uint32Array;

	/** Tetrahedralization (or planar triangulation) of the zone's probes alone. */
	readonly interpolator: ProbeInterpolator;

	/** min x, y, z, max x, y, z per box (empty: no bounds). */
	readonly bounds: Float64Array;

}

/**
 * Lighting zones of a `LightProbeVolume`: named groups of probes, each with its own
 * tetrahedralization, so rooms separated by walls do not share cells — an object in one room
 * blends only that room's probes. Objects are assigned by name or by the zones' bounds.
 */
export class ProbeZones {

	/** The zones, in the order given (the order in which bounds are tested). */
	readonly zones: readonly ProbeZone[];

	/**
	 * @param definitions See {@link ProbeZoneDefinition}.
	 * @param positions The volume's probe positions, x, y, z per probe.
	 * @throws for a missing or duplicate name, an empty zone, probe indices that are not integers
	 * in range, malformed bounds, or zone probes that are fewer than 3 distinct or all on a line.
	 */
	constructor( definitions: readonly ProbeZoneDefinition[], positions: ArrayLike<number> ) {

		const where = 'LightProbeVolume';
		if ( ! Array.isArray( definitions ) ) throw new TypeError( `${where}: zones must be an array of { name, probes, bounds? }.` );
		const count = positions.length / 3;
		const names = new Set<string>();
		this.zones = definitions.map( ( definition, z ) => {

			if ( ! definition || typeof definition !== 'object' ) throw new TypeError( `${where}: zones[${z}] must be an object { name, probes, bounds? }.` );
			const name = definition.name;
			if ( typeof name !== 'string' || name.length === 0 ) throw new TypeError( `${where}: zones[${z}].name must be a non-empty string.` );
			if ( names.has( name ) ) throw new RangeError( `${where}: zone name "${name}" is used twice.` );
			names.add( name );
			assertArrayLike( where, `zones[${z}] ("${name}").probes`, definition.probes );
			if ( definition.probes.length === 0 ) throw new RangeError( `${where}: zone "${name}" has no probes.` );
			const probes = new Uint32Array( definition.probes.length );
			for ( let k = 0; k < probes.length; k ++ ) {

				const index = definition.probes[ k ];
				if ( ! Number.isInteger( index ) || index < 0 || index >= count ) throw new RangeError( `${where}: zone "${name}" probes[${k}] is ${index}, not a probe index (0..${count - 1}).` );
				probes[ k ] = index;

			}

			const local = new Float64Array( 3 * probes.length );
			probes.forEach( ( index, k ) => local.set( [ positions[ 3 * index ], positions[ 3 * index + 1 ], positions[ 3 * index + 2 ] ], 3 * k ) );
			let interpolator: ProbeInterpolator;
			try {

				interpolator = createProbeInterpolator( local );

			} catch ( error ) {

				throw new RangeError( `${where}: zone "${name}" cannot be interpolated (${probes.length} probes): ${( error as Error ).message}` );

			}

			return { name, probes, interpolator, bounds: boundsOf( name, definition.bounds ) };

		} );

	}

	/** The index of the zone with this name, or −1. */
	indexOf( name: string ): number {

		for ( let z = 0; z < this.zones.length; z ++ ) if ( this.zones[ z ].name === name ) return z;
		return - 1;

	}

	/** The first zone (index) one of whose boxes contains (x, y, z), boundary included; −1 when none. Allocation-free. */
	zoneAt( x: number, y: number, z: number ): number {

		for ( let i = 0, n = this.zones.length; i < n; i ++ ) {

			const b = this.zones[ i ].bounds;
			for ( let k = 0; k < b.length; k += 6 ) {

				if ( x >= b[ k ] && y >= b[ k + 1 ] && z >= b[ k + 2 ] && x <= b[ k + 3 ] && y <= b[ k + 4 ] && z <= b[ k + 5 ] ) return i;

			}

		}

		return - 1;

	}

}

/**
 * The index of the zone named `name`, for an option naming a zone.
 * @throws Error when there are no zones; RangeError, listing the zones, when none has that name.
 */
export function zoneIndexOf( where: string, zones: ProbeZones | null, name: string ): number {

	if ( zones === null ) throw new Error( `${where}: zone "${name}" given, but the volume has no zones.` );
	const index = zones.indexOf( name );
	if ( index < 0 ) {

		const names = zones.zones.map( ( zone ) => `"${zone.name}"` ).join( ', ' );
		throw new RangeError( `${where}: unknown zone "${name}"; the zones are ${names}.` );

	}

	return index;

}

function boundsOf( name: string, bounds: BoxLike | readonly BoxLike[] | undefined ): Float64Array {

	if ( bounds === undefined ) return new Float64Array( 0 );
	const boxes = Array.isArray( bounds ) ? bounds as readonly BoxLike[] : [ bounds as BoxLike ];
	const out = new Float64Array( 6 * boxes.length );
	boxes.forEach( ( box, i ) => {

		const values = [ box?.min?.x, box?.min?.y, box?.min?.z, box?.max?.x, box?.max?.y, box?.max?.z ];
		if ( ! values.every( ( v ) => typeof v === 'number' && Number.isFinite( v ) ) ) throw new TypeError( `LightProbeVolume: zone "${name}" bounds[${i}] must be a box { min: {x, y, z}, max: {x, y, z} } of finite numbers (e.g. a Box3).` );
		if ( values[ 0 ]! > values[ 3 ]! || values[ 1 ]! > values[ 4 ]! || values[ 2 ]! > values[ 5 ]! ) throw new RangeError( `LightProbeVolume: zone "${name}" bounds[${i}] has min > max (an empty box).` );
		out.set( values as number[], 6 * i );

	} );

	return out;

}
