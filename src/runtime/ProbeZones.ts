import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { checkZoneName, checkZoneProbes, runtimeReject } from '../roles.js';
import { DegenerateInputError } from '../tetrahedra/tetrahedralize.js';
import { createVolumeInterpolator } from './createVolumeInterpolator.js';

/** A box given by its corners, e.g. a three.js `Box3`. */
export interface BoxLike {

	min: { x: number; y: number; z: number };
	max: { x: number; y: number; z: number };

}

/** One lighting zone, as passed to `LightProbeVolume` (`zones`). */
export interface ProbeZoneDefinition {

	/**
	 * Name, unique among the volume's zones ('' is a name like any other), used by
	 * `volume.add( object, { zone: name } )`; any string UTF-8 can hold.
	 */
	name: string;

	/**
	 * Indices of the volume's probes lighting this zone, at least one. 4 not in one plane give a
	 * tetrahedralization, coplanar probes a planar triangulation, and fewer than 3 distinct or
	 * collinear ones (a corridor) interpolate along their line. A probe may belong to several
	 * zones, e.g. one in a doorway.
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

	/** Tetrahedralization (or planar triangulation, or line) of the zone's probes alone. */
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
	 * @throws TypeError / RangeError for a non-string or duplicate name, a zone without probes,
	 * probe indices that are not integers in range, or malformed bounds (the rules of the baked
	 * format, src/roles.ts); DegenerateInputError when a zone's probes cannot be interpolated at all.
	 */
	constructor( definitions: readonly ProbeZoneDefinition[], positions: ArrayLike<number> ) {

		const where = 'LightProbeVolume';
		if ( ! Array.isArray( definitions ) ) throw new TypeError( `${where}: zones must be an array of { name, probes, bounds? }.` );
		const count = positions.length / 3;
		const reject = runtimeReject( where );
		const names = new Set<string>();
		this.zones = definitions.map( ( definition, z ) => {

			if ( ! definition || typeof definition !== 'object' ) throw new TypeError( `${where}: zones[${z}] must be an object { name, probes, bounds? }.` );
			const name = checkZoneName( definition.name, z, names, reject );
			const probes = checkZoneProbes( definition.probes, `zones[${z}] (${JSON.stringify( name )}).probes`, count, reject );
			const local = new Float64Array( 3 * probes.length );
			probes.forEach( ( index, k ) => {

				for ( let a = 0; a < 3; a ++ ) local[ 3 * k + a ] = positions[ 3 * index + a ];

			} );
			let interpolator: ProbeInterpolator;
			try {

				interpolator = createVolumeInterpolator( local );

			} catch ( error ) {

				if ( ! ( error instanceof DegenerateInputError ) ) throw error;
				const message = `${where}: zone ${JSON.stringify( name )} cannot be interpolated (${probes.length} probes): ${error.message}`;
				throw new DegenerateInputError( error.reason, message );

			}

			return { name, probes: Uint32Array.from( probes ), interpolator, bounds: boundsOf( name, definition.bounds ) };

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
export function zoneIndexOf( where: string, zones: ProbeZones | null, name: unknown ): number {

	if ( typeof name !== 'string' ) throw new TypeError( `${where}: options.zone must be a zone name (a string), got ${typeof name}.` );
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
