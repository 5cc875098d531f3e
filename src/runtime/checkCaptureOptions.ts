import type { Object3D } from 'three';
import { assertCaptureBackend } from '../capture/captureBackends.js';
import { assertScene, checkCaptureCall, checkCaptureSettings, checkLayers } from '../capture/captureSettings.js';
import { PROBE_ROLES, isProbeRole } from '../roles.js';
import { assertArrayLike, assertNumber, assertOptionalBoolean, assertOptions, describeValue } from '../validate.js';
import type { CapturedVolume } from './captureProbes.js';

/** What {@link checkCaptureOptions} reads once: the probes to capture and the objects to hide. */
export interface CheckedCapture {

	/** Live probe ids, `options.indices` or every live probe. */
	indices: number[];

	/** `options.exclude` as an array (it may be a one-shot iterable), or undefined. */
	exclude: Object3D[] | undefined;

}

/**
 * Checks everything `LightProbeVolume.capture` (and `captureBounces`) takes before anything is
 * captured: the common capture settings, each role's settings over them,
 * the per-call options, `deringing`, `nonNegative` and `indices` (live probe ids). The bounce
 * options are checked by `captureWithBounces`. Then the renderer (a WebGLRenderer, or a
 * WebGPURenderer with `three-capture-lighting/webgpu` imported) and the scene.
 * @throws TypeError / RangeError starting with `where`.
 */
export function checkCaptureOptions(
	where: string, volume: CapturedVolume, renderer: unknown, scene: unknown, options: unknown,
): CheckedCapture {

	assertOptions( where, 'options', options );
	const o = ( options ?? {} ) as Record<string, unknown>;
	checkCaptureSettings( where, 'options.', o );
	const { exclude } = checkCaptureCall( where, 'options.', o );
	if ( o.roles !== undefined ) {

		assertOptions( where, 'options.roles', o.roles );
		for ( const [ role, settings ] of Object.entries( o.roles as Record<string, unknown> ) ) {

			if ( ! isProbeRole( role ) ) throw new RangeError( `${where}: options.roles has the unknown role "${role}"; expected one of ${PROBE_ROLES.join( ', ' )}.` );
			if ( settings === undefined ) continue;
			assertOptions( where, `options.roles.${role}`, settings );
			checkCaptureSettings( where, `options.roles.${role}.`, { ...pick( o ), ...pick( settings as Record<string, unknown> ) } );
			checkLayers( where, `options.roles.${role}.layers`, ( settings as { layers?: unknown } ).layers );

		}

	}

	if ( o.deringing !== undefined ) {

		assertNumber( where, 'options.deringing', o.deringing );
		if ( ! ( o.deringing >= 0 && o.deringing <= 1 ) ) throw new RangeError( `${where}: options.deringing must be in [0, 1], got ${o.deringing}.` );

	}

	assertOptionalBoolean( where, 'options.nonNegative', o.nonNegative );
	const indices = captureIndices( where, volume, o.indices );
	assertCaptureBackend( where, renderer );
	assertScene( where, scene );
	return { indices, exclude };

}

/** The capture settings of an options object (undefined members left out, so they do not hide the common ones). */
function pick( o: Record<string, unknown> ): Record<string, unknown> {

	const out: Record<string, unknown> = {};
	for ( const key of [ 'resolution', 'near', 'far', 'type', 'solidAngle' ] ) if ( o[ key ] !== undefined ) out[ key ] = o[ key ];
	return out;

}

/** `options.indices` checked (live probe ids; a repeated one is captured once), or every live probe. */
function captureIndices( where: string, volume: CapturedVolume, requested: unknown ): number[] {

	if ( requested === undefined ) {

		const indices: number[] = [];
		for ( let i = 0; i < volume.count; i ++ ) if ( volume.isProbeActive( i ) ) indices.push( i );
		return indices;

	}

	assertArrayLike( where, 'options.indices', requested );
	const indices = new Set<number>();
	for ( const index of Array.from( requested as ArrayLike<unknown> ) ) {

		if ( typeof index !== 'number' || ! Number.isInteger( index ) || index < 0 || index >= volume.count ) {

			throw new RangeError( `${where}: options.indices holds ${describeValue( index )}, not a probe index (0..${volume.count - 1}).` );

		}

		if ( ! volume.isProbeActive( index ) ) throw new RangeError( `${where}: options.indices holds ${index}, a removed probe.` );
		indices.add( index );

	}

	return [ ...indices ];

}
