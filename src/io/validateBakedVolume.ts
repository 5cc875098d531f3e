import { isProbeRole, PROBE_ROLES, type ProbeRole } from '../roles.js';
import { boxOf, checkBox, checkCapture, checkFinite, checkTetrahedralization, checkText, fail, numbers } from './checks.js';
import type { BakedVolumeData, BakedVolumeInput, BakedZone } from './bakedVolumeTypes.js';

/**
 * Checks a volume given as plain data (the encoders' input, the JSON form) and returns it in the
 * normalized {@link BakedVolumeData} shape (typed arrays, defaults filled in). Throws
 * {@link BakedVolumeError} naming the field and index of the first problem.
 * @param where Function name for messages.
 */
export function validateBakedVolume( input: BakedVolumeInput, where = 'validateBakedVolume' ): BakedVolumeData {

	if ( input === null || typeof input !== 'object' ) fail( 'argument', where, 'expected a volume { positions, sh, tetrahedra?, neighbors?, names?, roles?, zones?, bounds?, capture?, metadata? }.' );
	const positionsIn = numbers( where, 'positions', input.positions, 3 );
	const probeCount = positionsIn.length / 3;
	if ( probeCount < 1 ) fail( 'count', where, 'positions holds no probe.' );
	checkFinite( where, 'positions', positionsIn );
	const positions = positionsIn instanceof Float64Array ? positionsIn : Float64Array.from( positionsIn );

	const shIn = numbers( where, 'sh', input.sh, 27 );
	if ( shIn.length !== 27 * probeCount ) fail( 'count', where, `sh has ${shIn.length} values; ${probeCount} probes need 27 each (${27 * probeCount}).` );
	checkFinite( where, 'sh', shIn );
	const sh = shIn instanceof Float32Array ? shIn : Float32Array.from( shIn );
	// Float32 storage: a finite float64 beyond ±3.4e38 would become Infinity.
	if ( ! ( shIn instanceof Float32Array ) ) checkFinite( where, 'sh (as float32)', sh );

	let tetrahedra: Uint32Array = new Uint32Array( 0 ), neighbors: Int32Array = new Int32Array( 0 );
	if ( input.tetrahedra !== undefined || input.neighbors !== undefined ) {

		const tetIn = numbers( where, 'tetrahedra', input.tetrahedra, 4 );
		const nbrIn = numbers( where, 'neighbors', input.neighbors, 4 );
		if ( nbrIn.length !== tetIn.length ) fail( 'count', where, `neighbors has ${nbrIn.length} entries; ${tetIn.length / 4} tetrahedra need 4 each (${tetIn.length}).` );
		( { tetrahedra, neighbors } = checkTetrahedralization( where, positions, tetIn, nbrIn ) );

	}

	const names: string[] = [];
	if ( input.names !== undefined ) {

		if ( ! Array.isArray( input.names ) ) fail( 'argument', where, 'names must be an array of strings.' );
		if ( input.names.length !== probeCount ) fail( 'count', where, `names has ${input.names.length} entries for ${probeCount} probes.` );
		for ( let i = 0; i < probeCount; i ++ ) {

			const name = input.names[ i ];
			if ( typeof name !== 'string' ) fail( 'argument', where, `names[${i}] is not a string.` );
			checkText( where, `names[${i}]`, name );
			names.push( name );

		}

	} else {

		for ( let i = 0; i < probeCount; i ++ ) names.push( '' );

	}

	const roles: ProbeRole[] = [];
	if ( input.roles !== undefined ) {

		if ( ! Array.isArray( input.roles ) ) fail( 'argument', where, 'roles must be an array of strings.' );
		if ( input.roles.length !== probeCount ) fail( 'count', where, `roles has ${input.roles.length} entries for ${probeCount} probes.` );
		for ( let i = 0; i < probeCount; i ++ ) {

			const role = input.roles[ i ];
			if ( ! isProbeRole( role ) ) fail( 'range', where, `roles[${i}] is ${JSON.stringify( role ) ?? String( role )}; expected one of ${PROBE_ROLES.join( ', ' )}.` );
			roles.push( role );

		}

	} else {

		for ( let i = 0; i < probeCount; i ++ ) roles.push( 'fill' );

	}

	const zones: BakedZone[] = [];
	if ( input.zones !== undefined ) {

		if ( ! Array.isArray( input.zones ) ) fail( 'argument', where, 'zones must be an array of { name, probes, bounds? }.' );
		for ( let z = 0; z < input.zones.length; z ++ ) {

			const zone = input.zones[ z ];
			if ( zone === null || typeof zone !== 'object' ) fail( 'argument', where, `zones[${z}] must be an object { name, probes, bounds? }.` );
			if ( typeof zone.name !== 'string' ) fail( 'argument', where, `zones[${z}].name must be a string.` );
			checkText( where, `zones[${z}].name`, zone.name );
			const probes = numbers( where, `zones[${z}].probes`, zone.probes, 1 );
			for ( let i = 0; i < probes.length; i ++ ) {

				const p = probes[ i ];
				if ( ! ( p >= 0 && p < probeCount && p === Math.floor( p ) ) ) fail( 'range', where, `zones[${z}].probes[${i}] = ${p} is not a probe index (0..${probeCount - 1}).` );

			}

			const bounds = zone.bounds === undefined ? [] : numbers( where, `zones[${z}].bounds`, zone.bounds, 6 );
			checkFinite( where, `zones[${z}].bounds`, bounds );
			for ( let b = 0; b < bounds.length; b += 6 ) checkBox( where, `zones[${z}].bounds`, bounds, b );
			zones.push( {
				name: zone.name,
				probes: probes instanceof Uint32Array ? probes : Uint32Array.from( probes ),
				bounds: bounds instanceof Float64Array ? bounds : Float64Array.from( bounds ),
			} );

		}

	}

	let bounds: Float64Array;
	if ( input.bounds !== undefined ) {

		const b = numbers( where, 'bounds', input.bounds, 6 );
		if ( b.length !== 6 ) fail( 'count', where, `bounds must hold 6 numbers (min x, y, z, max x, y, z), got ${b.length}.` );
		checkFinite( where, 'bounds', b );
		checkBox( where, 'bounds', b, 0 );
		bounds = b instanceof Float64Array ? b : Float64Array.from( b );

	} else {

		bounds = boxOf( positions );

	}

	const capture = checkCapture( where, input.capture );
	const metadata = input.metadata ?? '';
	if ( typeof metadata !== 'string' ) fail( 'argument', where, 'metadata must be a string.' );
	checkText( where, 'metadata', metadata );

	return { positions, sh, tetrahedra, neighbors, names, roles, zones, bounds, capture, metadata };

}
