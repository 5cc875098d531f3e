import { checkProbeNames, checkProbeRoles, checkZoneName, checkZoneProbes } from '../roles.js';
import {
	boxOf, checkBox, checkCapture, checkFinite, checkFit, checkGradients, checkPositions, checkSH, checkTetrahedralization, checkText,
	codecReject, fail, numbers,
} from './checks.js';
import { GRADIENT_FLOATS } from './bakedVolumeFormat.js';
import type { BakedVolumeData, BakedVolumeInput, BakedZone } from './bakedVolumeTypes.js';

/**
 * Checks a volume given as plain data (the encoders' input, the JSON form) and returns it in the
 * normalized {@link BakedVolumeData} shape (typed arrays, defaults filled in). Throws
 * {@link BakedVolumeError} naming the field and index of the first problem.
 * @param where Function name for messages.
 */
export function validateBakedVolume( input: BakedVolumeInput, where = 'validateBakedVolume' ): BakedVolumeData {

	if ( input === null || typeof input !== 'object' ) fail( 'argument', where, 'expected a volume { positions, sh, tetrahedra?, neighbors?, names?, roles?, zones?, bounds?, capture?, metadata?, gradients?, fit? }.' );
	const positionsIn = numbers( where, 'positions', input.positions, 3 );
	const probeCount = positionsIn.length / 3;
	if ( probeCount < 1 ) fail( 'count', where, 'positions holds no probe.' );
	checkPositions( where, positionsIn );
	const positions = positionsIn instanceof Float64Array ? positionsIn : Float64Array.from( positionsIn );

	const shIn = numbers( where, 'sh', input.sh, 27 );
	if ( shIn.length !== 27 * probeCount ) fail( 'count', where, `sh has ${shIn.length} values; ${probeCount} probes need 27 each (${27 * probeCount}).` );
	checkSH( where, 'sh', shIn );
	const sh = shIn instanceof Float32Array ? shIn : Float32Array.from( shIn );

	let tetrahedra: Uint32Array = new Uint32Array( 0 ), neighbors: Int32Array = new Int32Array( 0 );
	if ( input.tetrahedra !== undefined || input.neighbors !== undefined ) {

		const tetIn = numbers( where, 'tetrahedra', input.tetrahedra, 4 );
		const nbrIn = numbers( where, 'neighbors', input.neighbors, 4 );
		if ( nbrIn.length !== tetIn.length ) fail( 'count', where, `neighbors has ${nbrIn.length} entries; ${tetIn.length / 4} tetrahedra need 4 each (${tetIn.length}).` );
		( { tetrahedra, neighbors } = checkTetrahedralization( where, positions, tetIn, nbrIn ) );

	}

	// The rules of src/roles.ts, which the runtime applies too: a file written here always loads.
	const reject = codecReject( where );
	const names = checkProbeNames( input.names, probeCount, reject );
	const roles = checkProbeRoles( input.roles, probeCount, reject );
	const zones: BakedZone[] = [];
	if ( input.zones !== undefined ) {

		if ( ! Array.isArray( input.zones ) ) fail( 'argument', where, 'zones must be an array of { name, probes, bounds? }.' );
		const seen = new Set<string>();
		for ( let z = 0; z < input.zones.length; z ++ ) {

			const zone = input.zones[ z ];
			if ( zone === null || typeof zone !== 'object' ) fail( 'argument', where, `zones[${z}] must be an object { name, probes, bounds? }.` );
			const name = checkZoneName( zone.name, z, seen, reject );
			const probes = checkZoneProbes( zone.probes, `zones[${z}].probes`, probeCount, reject );
			const bounds = zone.bounds === undefined ? [] : numbers( where, `zones[${z}].bounds`, zone.bounds, 6 );
			checkFinite( where, `zones[${z}].bounds`, bounds );
			for ( let b = 0; b < bounds.length; b += 6 ) checkBox( where, `zones[${z}].bounds`, bounds, b );
			zones.push( { name, probes, bounds: bounds instanceof Float64Array ? bounds : Float64Array.from( bounds ) } );

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

	let gradients: Float32Array | null = null;
	if ( input.gradients !== undefined && input.gradients !== null ) {

		const g = numbers( where, 'gradients', input.gradients, GRADIENT_FLOATS );
		if ( g.length !== GRADIENT_FLOATS * probeCount ) {

			fail( 'count', where, `gradients has ${g.length} values; ${probeCount} probes need ${GRADIENT_FLOATS} each (${GRADIENT_FLOATS * probeCount}).` );

		}

		// Checked as stored (float32): the bound is not a float32 value, so rounding could cross it.
		gradients = g instanceof Float32Array ? g : Float32Array.from( g );
		checkGradients( where, gradients, positions );

	}

	const fit = checkFit( where, input.fit, gradients !== null );
	return { positions, sh, tetrahedra, neighbors, names, roles, zones, bounds, capture, metadata, gradients, fit };

}
