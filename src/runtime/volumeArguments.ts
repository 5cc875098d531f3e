/* Argument readers shared by `LightProbeVolume`'s methods and its probe edits. */
import { POSITION_LIMIT, SH_FLOATS, assertOutput } from '../validate.js';
import type { ProbePosition } from './LightProbeVolumeOptions.js';

/**
 * A position argument (`{ x, y, z }`, e.g. a `Vector3`, or `[ x, y, z ]`) as three finite numbers
 * within ±{@link POSITION_LIMIT}. Throws a TypeError / RangeError starting with `where` and naming `name`.
 */
export function readPosition( where: string, position: ProbePosition | unknown, name = 'position' ): [ number, number, number ] {

	if ( ! position || typeof position !== 'object' ) {

		throw new TypeError( `${where}: ${name} must be { x, y, z } or [ x, y, z ], got ${position === null ? 'null' : typeof position}.` );

	}

	const p = position as { x?: unknown; y?: unknown; z?: unknown } & ArrayLike<unknown>;
	const xyz = 'x' in p ? [ p.x, p.y, p.z ] : [ p[ 0 ], p[ 1 ], p[ 2 ] ];
	for ( let a = 0; a < 3; a ++ ) {

		const v = xyz[ a ];
		if ( typeof v !== 'number' || ! ( Math.abs( v ) <= POSITION_LIMIT ) ) {

			throw new RangeError( `${where}: ${name} must be three finite numbers within ±${POSITION_LIMIT.toExponential()}, `
				+ `got (${xyz.map( ( c ) => typeof c === 'string' ? JSON.stringify( c ) : String( c ) ).join( ', ' )}).` );

		}

	}

	return xyz as [ number, number, number ];

}

/** A target for one probe's SH: a Float32Array (or Float64Array, plain array) with room for 27 values. */
export function assertSHTarget( where: string, target: unknown ): void {

	if ( ! ( target instanceof Float32Array || target instanceof Float64Array || Array.isArray( target ) ) ) {

		throw new TypeError( `${where}: target must be a Float32Array (or Float64Array, array) of ${SH_FLOATS} floats.` );

	}

	assertOutput( where, 'target', target, SH_FLOATS );

}
