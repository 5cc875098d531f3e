import type { Scene, WebGLRenderer } from 'three';
import { ProbeCapturer } from '../capture/ProbeCapturer.js';
import type { BakedCapture } from '../io/index.js';
import type { ProbeRole } from '../roles.js';
import { makeIrradianceNonNegative, windowSH } from '../sh/windowSH.js';
import { SH_FLOATS, assertArrayLike } from '../validate.js';
import { bakedCaptureSettings } from './bakedVolumeData.js';
import type { LightProbeVolumeCaptureOptions } from './LightProbeVolumeOptions.js';
import type { LitObject } from './litObjects.js';

/** The fields of a `LightProbeVolume` that {@link captureProbes} reads, and its `sh`, which it fills. */
export interface CapturedVolume {

	readonly positions: Float64Array;
	readonly sh: Float32Array;
	readonly roles: readonly ProbeRole[];
	readonly count: number;
	isProbeActive( index: number ): boolean;

}

/**
 * One capture of a volume's probes (`LightProbeVolume.capture` without bounces): the probes of
 * `options.indices` (default all live ones), in one pass per role with settings of its own, then
 * de-ringed or made non-negative. Objects lit in `'object'` mode (`hidden`) are hidden; large
 * objects stay visible with their probe light off. Captured probes leave `dirty`. On a lost
 * context the SH already held stay.
 * @returns The capture settings to store with a bake (`LightProbeVolume.captureSettings`).
 */
export async function captureProbes(
	volume: CapturedVolume, lit: readonly LitObject[], dirty: Set<number>,
	renderer: WebGLRenderer, scene: Scene, options: LightProbeVolumeCaptureOptions,
): Promise<BakedCapture> {

	const where = 'LightProbeVolume.capture';
	const indices = captureIndices( where, volume, options.indices );

	// Probes whose role has its own settings (paper 3.4: sky, bounce and reflection captures
	// want different ranges and layers) are captured in their own pass.
	const groups = new Map<string, number[]>();
	for ( const index of indices ) {

		const role = volume.roles[ index ];
		const key = options.roles?.[ role ] ? role : '';
		groups.set( key, [ ...( groups.get( key ) ?? [] ), index ] );

	}

	const deringing = options.deringing ?? 0;
	if ( ! ( deringing >= 0 && deringing <= 1 ) ) {

		throw new RangeError( `${where}: options.deringing must be in [0, 1], got ${options.deringing}.` );

	}

	const nonNegative = options.nonNegative === true;
	// Visitors are hidden; scenery lit by the probes (large objects) is seen as built: probe light off.
	const exclude = [ ...lit.filter( ( entry ) => entry.hidden ).map( ( entry ) => entry.object ), ...( options.exclude ?? [] ) ];
	const intensities: [ { value: number }, number ][] = [];
	for ( const entry of lit ) {

		if ( entry.hidden ) continue;
		const all = entry.large ? entry.large.map( ( lighting ) => lighting.uniforms ) : [ entry.uniforms ];
		for ( const uniforms of all ) intensities.push( [ uniforms.probeVolumeIntensity, uniforms.probeVolumeIntensity.value ] );

	}

	for ( const [ uniform ] of intensities ) uniform.value = 0;
	const total = indices.length;
	let done = 0;
	try {

		for ( const [ role, group ] of groups ) {

			const settings = { ...options, ...( role ? options.roles?.[ role as ProbeRole ] : {} ) };
			const positions = new Float64Array( 3 * group.length );
			group.forEach( ( index, k ) => positions.set( volume.positions.subarray( 3 * index, 3 * index + 3 ), 3 * k ) );
			const capturer = new ProbeCapturer( renderer, settings );
			try {

				const start = done;
				const captured = await capturer.capture( scene, positions, new Float32Array( SH_FLOATS * group.length ), {
					...settings, exclude, onProgress: options.onProgress && ( ( n ) => options.onProgress!( start + n, total ) ),
				} );
				if ( nonNegative ) makeIrradianceNonNegative( captured, deringing );
				else if ( deringing > 0 ) windowSH( captured, deringing, captured );
				group.forEach( ( index, k ) => {

					volume.sh.set( captured.subarray( SH_FLOATS * k, SH_FLOATS * ( k + 1 ) ), SH_FLOATS * index );
					dirty.delete( index );

				} );
				done += group.length;

			} finally {

				capturer.dispose();

			}

		}

	} finally {

		for ( const [ uniform, value ] of intensities ) uniform.value = value;

	}

	return bakedCaptureSettings( options );

}

/** `options.indices` checked (live probe ids), or every live probe. */
function captureIndices( where: string, volume: CapturedVolume, requested: ArrayLike<number> | undefined ): number[] {

	if ( requested === undefined ) {

		const indices: number[] = [];
		for ( let i = 0; i < volume.count; i ++ ) if ( volume.isProbeActive( i ) ) indices.push( i );
		return indices;

	}

	assertArrayLike( where, 'options.indices', requested );
	const indices = Array.from( requested );
	indices.forEach( ( index ) => {

		if ( ! Number.isInteger( index ) || index < 0 || index >= volume.count ) {

			throw new RangeError( `${where}: options.indices holds ${index}, not a probe index (0..${volume.count - 1}).` );

		}

		if ( ! volume.isProbeActive( index ) ) throw new RangeError( `${where}: options.indices holds ${index}, a removed probe.` );

	} );
	return indices;

}
