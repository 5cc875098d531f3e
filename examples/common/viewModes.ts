import type * as THREE from 'three';
import { type LightProbeVolume } from 'three-capture-lighting';
import { irradianceMatrices } from 'three-capture-lighting/math';
import type { ViewMode } from './queryParameters.js';

/**
 * A sky/ground hemisphere as irradiance matrices, for the paper's "direct + hemisphere" comparison
 * view: sky (0.6, 0.7, 0.9) above, ground (0.3, 0.25, 0.2) below, in SH bands 0 and 1.
 */
export function hemisphereMatrices(): Float32Array {

	const sh = new Float32Array( 27 );
	const sky = [ 0.6, 0.7, 0.9 ], ground = [ 0.3, 0.25, 0.2 ];
	for ( let c = 0; c < 3; c ++ ) {

		sh[ c ] = ( sky[ c ] + ground[ c ] ) * Math.sqrt( Math.PI );
		sh[ 3 + c ] = ( sky[ c ] - ground[ c ] ) * Math.sqrt( 3 * Math.PI ) / 2;

	}

	const matrices = new Float32Array( 48 );
	irradianceMatrices( sh, matrices );
	return matrices;

}

/**
 * After `volume.update()`: the view mode on the objects the volume lights — "indirect only" turns
 * their direct light off, "direct + hemisphere" replaces the probe light by `hemisphere`.
 */
export function applyViewMode(
	volume: LightProbeVolume, objects: readonly THREE.Object3D[], view: ViewMode, hemisphere: Float32Array,
): void {

	for ( const object of objects ) {

		const uniforms = volume.getUniforms( object );
		if ( ! uniforms ) continue;
		uniforms.probeVolumeDirectScale.value = view === 'indirect only' ? 0 : 1;
		if ( view === 'direct + hemisphere' ) uniforms.probeVolumeMatrices.value.set( hemisphere );

	}

}
