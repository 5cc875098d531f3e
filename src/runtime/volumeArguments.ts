/* Argument readers shared by `LightProbeVolume`'s constructor, its methods and its probe edits. */
import type { Scene, WebGLRenderer } from 'three';
import { assertRenderer, assertScene } from '../capture/captureSettings.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { readProbeNames, readProbeRoles, type ProbeRole } from '../roles.js';
import { POSITION_LIMIT, SH_FLOATS, assertOptions, assertOutput, assertProbePositions, assertProbeSH } from '../validate.js';
import { createVolumeInterpolator } from './createVolumeInterpolator.js';
import { readGradients } from './gradientProbes.js';
import type { LightProbeVolumeCaptureOptions, LightProbeVolumeParameters, ProbePosition } from './LightProbeVolumeOptions.js';
import { assertInterpolator } from './ProbeWeighting.js';

/** The probes of `LightProbeVolume`'s constructor parameters, checked and copied (zones and occluders are read there). */
export interface VolumeProbes {

	count: number;
	positions: Float64Array;
	sh: Float32Array;
	gradients: Float32Array | null;
	names: string[];
	roles: ProbeRole[];
	interpolator: ProbeInterpolator;

}

/**
 * Reads the probes of a `LightProbeVolume`'s parameters — positions, SH (zeros when omitted), gradients (null when
 * omitted), names, roles, the interpolator (the default one when omitted) — and checks `guard`; throws before
 * anything is built.
 */
export function readVolumeParameters( where: string, parameters: LightProbeVolumeParameters ): VolumeProbes {

	if ( ! parameters || typeof parameters !== 'object' ) {

		throw new TypeError( `${where}: expected { positions, sh?, gradients?, names?, roles? }.` );

	}

	const count = assertProbePositions( where, 'positions', parameters.positions, 1 );
	const positions = Float64Array.from( parameters.positions );
	const sh = new Float32Array( SH_FLOATS * count );
	if ( parameters.sh !== undefined ) {

		assertProbeSH( where, 'sh', parameters.sh, count );
		sh.set( parameters.sh );

	}

	const gradients = parameters.gradients !== undefined ? readGradients( where, 'gradients', parameters.gradients, positions, count ) : null;
	const names = readProbeNames( where, parameters.names, count );
	const roles = readProbeRoles( where, parameters.roles, count );
	assertOptions( where, 'guard', parameters.guard );
	const interpolator = parameters.interpolator !== undefined
		? assertInterpolator( where, parameters.interpolator, count )
		: createVolumeInterpolator( positions );
	return { count, positions, sh, gradients, names, roles, interpolator };

}

/** The arguments of `LightProbeVolume.recaptureDirty`: a renderer, a scene and capture options without `indices`. */
export function assertRecaptureArguments( where: string, renderer: WebGLRenderer, scene: Scene, options: unknown ): void {

	assertRenderer( where, renderer );
	assertScene( where, scene );
	assertOptions( where, 'options', options );
	if ( options !== undefined && ( options as LightProbeVolumeCaptureOptions ).indices !== undefined ) {

		throw new TypeError( `${where}: options.indices is not taken (the dirty probes are captured); use capture().` );

	}

}

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
