/**
 * The object mode's per-draw coefficients (src/runtime/viewIrradiance.ts): E of a view-space
 * normal from the world-space irradiance matrices and the camera, checked against three's own
 * SphericalHarmonics3.getIrradianceAt of the world normal (the LightProbe's formula, an
 * independent evaluation), and the hook that computes them in patchMaterial.
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { getProbeVolumeUniforms, patchMaterial, unpatchMaterial } from '../../src/runtime/patchMaterial.js';
import { VIEW_IRRADIANCE_FLOATS, viewIrradiance } from '../../src/runtime/viewIrradiance.js';
import { irradianceMatrices } from '../../src/sh/index.js';

/** Deterministic numbers in [ -1, 1 ). */
function random( seed: number ): () => number {

	let s = seed;
	return () => ( s = ( s * 16807 ) % 2147483647 ) / 1073741823.5 - 1;

}

/** What the shader computes from the 27 coefficients for the unit view-space normal v. */
function evaluate( c: Float32Array, v: THREE.Vector3 ): number[] {

	const basis = [ 1, v.x, v.y, v.z, v.x * v.x, v.y * v.y, v.x * v.y, v.x * v.z, v.y * v.z ];
	return [ 0, 1, 2 ].map( ( channel ) => basis.reduce( ( sum, b, k ) => sum + c[ 3 * k + channel ] * b, 0 ) );

}

/** A camera somewhere, looking somewhere, rolled about its axis. */
function randomCamera( next: () => number ): THREE.PerspectiveCamera {

	const camera = new THREE.PerspectiveCamera();
	camera.position.set( 5 * next(), 5 * next(), 5 * next() );
	camera.up.set( next(), next(), next() ).normalize();
	camera.lookAt( next(), next(), next() );
	camera.updateMatrixWorld();
	return camera;

}

describe( 'viewIrradiance: E of the view-space normal', () => {

	it( 'equals three\'s SphericalHarmonics3.getIrradianceAt of the world normal × intensity, for random SH, cameras (rolled) and normals', () => {

		// E(n) is a quadratic polynomial of the world normal n; the view-space normal is v = R n for
		// the camera's rotation R, so the polynomial of v is fixed by R and the SH. Twelve cameras
		// with every rotation axis, 200 normals each: a transposed R, a lost factor 2 on the mixed
		// terms or a wrong z² fold would be off by ~|SH| ≫ 1e-5. Every third view matrix is scaled by
		// 3 (three removes a camera's scale from it, a matrix set by hand may keep one): three's
		// shader normalises the world normal, so the scale must not change the light.
		const next = random( 7 );
		const world = new THREE.Vector3(), view = new THREE.Vector3(), expected = new THREE.Vector3();
		const sh = new THREE.SphericalHarmonics3();
		const out = new Float32Array( VIEW_IRRADIANCE_FLOATS );
		let worst = 0, scale = 0;
		for ( let trial = 0; trial < 12; trial ++ ) {

			const coefficients = Array.from( { length: 27 }, () => next() );
			sh.fromArray( coefficients );
			const intensity = 0.5 + 2 * Math.abs( next() );
			const camera = randomCamera( next );
			const matrix = camera.matrixWorldInverse.clone().premultiply( new THREE.Matrix4().makeScale( 3, 3, 3 ) );
			const viewMatrix = trial % 3 === 2 ? matrix : camera.matrixWorldInverse;
			viewIrradiance( irradianceMatrices( coefficients ), intensity, viewMatrix.elements, out );
			for ( let i = 0; i < 200; i ++ ) {

				world.set( next(), next(), next() ).normalize();
				view.copy( world ).transformDirection( camera.matrixWorldInverse );
				sh.getIrradianceAt( world, expected ).multiplyScalar( intensity );
				const actual = evaluate( out, view );
				worst = Math.max( worst, ...expected.toArray().map( ( e, c ) => Math.abs( actual[ c ] - e ) ) );
				scale = Math.max( scale, Math.abs( expected.x ), Math.abs( expected.y ), Math.abs( expected.z ) );

			}

		}

		expect( scale ).toBeGreaterThan( 0.5 ); // the light is not trivially small
		expect( worst ).toBeLessThan( 2e-5 * scale );

	} );

	it( 'takes a matrix that is not symmetric as its quadratic form: nᵀMn for any M', () => {

		const next = random( 11 );
		const matrices = Float32Array.from( { length: 48 }, () => next() );
		const camera = randomCamera( next );
		const out = new Float32Array( VIEW_IRRADIANCE_FLOATS );
		viewIrradiance( matrices, 1, camera.matrixWorldInverse.elements, out );
		const world = new THREE.Vector3(), view = new THREE.Vector3();
		let worst = 0;
		for ( let i = 0; i < 100; i ++ ) {

			world.set( next(), next(), next() ).normalize();
			view.copy( world ).transformDirection( camera.matrixWorldInverse );
			const n = new THREE.Vector4( world.x, world.y, world.z, 1 );
			const actual = evaluate( out, view );
			for ( let c = 0; c < 3; c ++ ) {

				const m = new THREE.Matrix4().fromArray( matrices, 16 * c );
				const expected = n.dot( n.clone().applyMatrix4( m ) );
				worst = Math.max( worst, Math.abs( actual[ c ] - expected ) );

			}

		}

		expect( worst ).toBeLessThan( 1e-5 );

	} );

} );

describe( 'patchMaterial: the per-draw hook', () => {

	it( 'source \'uniform\': onBeforeRender writes the coefficients for the drawing camera into the program\'s uniform, after a user hook set before patching; unpatch restores that hook', () => {

		const material = new THREE.MeshStandardMaterial();
		const calls: THREE.Camera[] = [];
		const userHook = ( _r: unknown, _s: unknown, camera: THREE.Camera ) => { calls.push( camera ); };
		material.onBeforeRender = userHook;
		const uniforms = patchMaterial( material, { intensity: 2 } );
		const sh = Array.from( { length: 27 }, ( _, i ) => Math.sin( i + 1 ) );
		irradianceMatrices( sh, uniforms.probeVolumeMatrices.value );

		const { vertexShader, fragmentShader } = THREE.ShaderLib.standard;
		const shader = { vertexShader, fragmentShader, uniforms: {} };
		material.onBeforeCompile( shader as unknown as THREE.WebGLProgramParametersWithUniforms, null as unknown as THREE.WebGLRenderer );
		const view = ( shader.uniforms as Record<string, { value: Float32Array }> ).probeVolumeViewIrradiance;
		expect( view.value ).toHaveLength( 27 );
		expect( shader.fragmentShader ).toContain( 'probeVolumeIrradiance( geometryNormal )' );

		const camera = randomCamera( random( 3 ) );
		const mesh = new THREE.Mesh( new THREE.SphereGeometry(), material );
		const renderer = null as unknown as THREE.WebGLRenderer;
		material.onBeforeRender( renderer, new THREE.Scene(), camera, mesh.geometry, mesh, null as unknown as THREE.Group );
		expect( calls ).toEqual( [ camera ] );
		const expected = new Float32Array( 27 );
		viewIrradiance( uniforms.probeVolumeMatrices.value, 2, camera.matrixWorldInverse.elements, expected );
		expect( Array.from( view.value ) ).toEqual( Array.from( expected ) );
		expect( expected.some( ( v ) => v !== 0 ) ).toBe( true );

		unpatchMaterial( material );
		expect( material.onBeforeRender ).toBe( userHook );
		expect( getProbeVolumeUniforms( material ) ).toBeNull();

	} );

	it( 'the other sources leave onBeforeRender alone', () => {

		const material = new THREE.MeshStandardMaterial();
		const hook = material.onBeforeRender;
		patchMaterial( material, { source: 'vertexSH' } );
		expect( material.onBeforeRender ).toBe( hook );
		unpatchMaterial( material );

	} );

} );
