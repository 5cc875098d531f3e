/**
 * captureBounces on a real GL context (headless-gl, WebGL2), against light that is known.
 *
 * The furnace: a closed, inward-facing room whose walls all emit Le and reflect diffusely with
 * albedo ρ; no lights. A probe anywhere inside sees the same radiance L in every direction, so its
 * SH is L00 = L·∫Y00 dω = L·√(4π) with every other coefficient 0, and the irradiance on a wall is
 * E = π·L00·Y00·√(4π)·… — three's getIrradianceAt gives E = 0.886227·L00 = π·L exactly.
 *
 * Three's convention, read from r187's lights_physical_pars_fragment (not assumed): the probe
 * irradiance is added to `irradiance` before lights_fragment_end (patchMaterial.ts puts it where a
 * LightProbe's term goes), and RE_IndirectDiffuse_Physical turns it into
 *   E · BRDF_Lambert( diffuseColor ) · ( 1 − FssEss − Fms·Ems ),  BRDF_Lambert = diffuseColor / π,
 * where the last factor takes the specular lobe's share (F0 = 0.04, F90 = 1 for a
 * MeshStandardMaterial; it depends on the view angle through the DFG table). No specular term
 * comes back from `irradiance` (that path reads `iblIrradiance`, an environment map's). With a
 * MeshPhysicalMaterial of specularIntensity 0 (F0 = F90 = 0) the factor is exactly 1, so a wall
 * sends out Le + ρ·E/π = Le + ρ·L, and pass k must capture L_k = Le·(1 + ρ + … + ρ^k).
 *
 * With a MeshStandardMaterial the reference is three itself: the same room lit by a `LightProbe`
 * holding the previous pass's SH — the per-vertex path must reproduce it — and the gain per bounce
 * lies a little below ρ (the specular share).
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/capture/bounces.gpu.test.ts`.
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { captureBounces } from '../../src/runtime/captureBounces.js';
import { ProbeCapturer } from '../../src/capture/ProbeCapturer.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { evaluateIrradiance } from '../../src/sh/index.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { disposeMesh, renderToImage } from '../helpers/gpuScenes.js';

const ctx = await createHeadlessRenderer( 32, 32 );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** ∫Y00 dω over the sphere: L00 of a uniform radiance 1 in three's basis. */
const UNIFORM_L00 = 4 * Math.PI * 0.282095;

/** Probes inside the rooms below (4 × 3 × 5 around the origin), not coplanar, off-centre. */
const PROBES = [ - 1, - 0.5, - 1.5, 1, - 0.5, - 1.5, 0, 0.8, 0, - 0.5, - 0.6, 1.5, 0.8, 0.3, 1.2 ];
const CAPTURE = { resolution: 16, near: 0.05, far: 100 };

const LE = 0.5;
const ALBEDO = [ 0.6, 0.4, 0.2 ];

/** The furnace room: an inward-facing box, 8–10 segments a side, one material. */
function furnace( material: THREE.Material ): THREE.Mesh {

	const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 5, 8, 6, 10 ), material );
	room.name = 'furnace';
	return room;

}

/** Lambertian wall (no specular lobe): F0 = F90 = 0. */
function lambertWall( albedo: readonly number[], emission: number ): THREE.MeshPhysicalMaterial {

	return new THREE.MeshPhysicalMaterial( {
		color: new THREE.Color( albedo[ 0 ], albedo[ 1 ], albedo[ 2 ] ), emissive: new THREE.Color( emission, emission, emission ),
		roughness: 1, metalness: 0, specularIntensity: 0, side: THREE.BackSide,
	} );

}

/** Largest |L00 − expected| / expected over probes and channels, and the largest |band ≥ 1| / L00. */
function furnaceErrors( sh: Float32Array, expected: readonly number[] ): { l00: number; higher: number } {

	let l00 = 0, higher = 0;
	for ( let p = 0; p < sh.length / 27; p ++ ) {

		for ( let c = 0; c < 3; c ++ ) {

			l00 = Math.max( l00, Math.abs( sh[ 27 * p + c ] - expected[ c ] ) / expected[ c ] );
			for ( let k = 1; k < 9; k ++ ) higher = Math.max( higher, Math.abs( sh[ 27 * p + 3 * k + c ] ) / expected[ c ] );

		}

	}

	return { l00, higher };

}

/** (R − G) / G of the irradiance a probe receives on a surface with normal n. */
function redness( sh: Float32Array, probe: number, normal: readonly number[] ): number {

	const e = evaluateIrradiance( sh, normal, new Float64Array( 3 ), 27 * probe );
	return ( e[ 0 ] - e[ 1 ] ) / e[ 1 ];

}

describe( 'captureBounces: bad input', () => {

	const volume = new LightProbeVolume( { positions: PROBES } );
	const renderer = null as unknown as THREE.WebGLRenderer;
	const scene = new THREE.Scene();

	it( 'bounces not an integer in 0..16: RangeError naming captureBounces and options.bounces', async () => {

		for ( const bounces of [ - 1, 1.5, 17, NaN ] ) await expect( captureBounces( volume, renderer, scene, { bounces } ) ).rejects.toThrow( /captureBounces: options\.bounces/ );
		await expect( captureBounces( volume, renderer, scene, undefined as never ) ).rejects.toThrow( /captureBounces: options/ );

	} );

	it( 'staticMeshes with a non-mesh, a mesh without a standard material, or a probe-patched one: a clear Error', async () => {

		await expect( captureBounces( volume, renderer, scene, { bounces: 1, staticMeshes: [ {} as THREE.Mesh ] } ) ).rejects.toThrow( /staticMeshes\[0\] is not a three\.js Mesh/ );
		const basic = new THREE.Mesh( new THREE.BoxGeometry(), new THREE.MeshBasicMaterial() );
		await expect( captureBounces( volume, renderer, scene, { bounces: 1, staticMeshes: [ basic ] } ) ).rejects.toThrow( /no MeshStandardMaterial/ );
		const lit = new THREE.Mesh( new THREE.BoxGeometry(), new THREE.MeshStandardMaterial() );
		volume.add( lit );
		await expect( captureBounces( volume, renderer, scene, { bounces: 1, staticMeshes: [ lit ] } ) ).rejects.toThrow( /probe light twice/ );
		volume.remove( lit );
		await expect( captureBounces( volume, renderer, scene, { bounces: 1, output: 'vertex' as never } ) ).rejects.toThrow( /options\.output/ );
		await expect( captureBounces( volume, renderer, scene, { bounces: 1, hideInBounces: [ 3 as never ] } ) ).rejects.toThrow( /hideInBounces\[0\]/ );

	} );

	it( 'volume.capture with options.bounces: the same checks, naming LightProbeVolume.capture', async () => {

		for ( const bounces of [ - 1, 1.5, 17, NaN ] ) await expect( volume.capture( renderer, scene, { bounces } ) ).rejects.toThrow( /LightProbeVolume\.capture: options\.bounces/ );
		await expect( volume.capture( renderer, scene, { bounces: 1, output: 'vertex' as never } ) ).rejects.toThrow( /LightProbeVolume\.capture: options\.output/ );

	} );

	it( 'a volume that is not one: TypeError', async () => {

		await expect( captureBounces( {} as LightProbeVolume, renderer, scene, { bounces: 1 } ) ).rejects.toThrow( /captureBounces: volume must be a LightProbeVolume/ );

	} );

} );

describe.skipIf( ! ctx.renderer )( `captureBounces on a real GL context (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;

	afterAll( () => ctx.dispose() );

	it( 'furnace, Lambertian walls (ρ = 0.6 / 0.4 / 0.2, Le = 0.5): pass k = Le·(1 + ρ + … + ρ^k) in L00 to 0.2 %, other bands < 0.1 % (HalfFloat targets)', async () => {

		const scene = new THREE.Scene();
		const room = furnace( lambertWall( ALBEDO, LE ) );
		scene.add( room );
		const volume = new LightProbeVolume( { positions: PROBES } );
		const passes: Float32Array[] = [];
		const result = await captureBounces( volume, renderer, scene, { bounces: 3, ...CAPTURE, onPass: ( _, sh ) => passes.push( sh.slice() ) } );

		expect( result.passes.map( ( pass ) => pass.pass ) ).toEqual( [ 0, 1, 2, 3 ] );
		expect( result.staticMeshes ).toEqual( [ room ] );
		expect( result.vertices ).toBe( room.geometry.getAttribute( 'position' ).count );
		for ( let k = 0; k <= 3; k ++ ) {

			const expected = ALBEDO.map( ( rho ) => UNIFORM_L00 * LE * ( 1 - rho ** ( k + 1 ) ) / ( 1 - rho ) );
			const { l00, higher } = furnaceErrors( passes[ k ], expected );
			// HalfFloat radiance is within 2^-11 = 0.05 % of the true value, the same bias on every
			// texel of a uniform scene; it enters each bounce again, so the error grows with k but
			// stays < 0.2 %. SH9 of a uniform environment is exact (the exact texel solid angles
			// sum to 4π), and a uniform field is reproduced exactly by per-vertex sampling.
			// Measured: 3e-7 (pass 0: Le = 0.5 is exact in half), 6.5e-4, 6.0e-4, 1.0e-3.
			expect( l00, `pass ${k}` ).toBeLessThan( 2e-3 );
			expect( higher, `pass ${k}` ).toBeLessThan( 1e-3 );
			for ( let c = 0; c < 3; c ++ ) expect( result.passes[ k ].meanL00[ c ] ).toBeCloseTo( expected[ c ], 2 );

		}

		// The last pass is what the volume holds.
		expect( Array.from( volume.sh ) ).toEqual( Array.from( passes[ 3 ] ) );
		disposeMesh( room );

	} );

	it( 'furnace, MeshStandardMaterial walls (roughness 1, metalness 0): each pass equals the same room lit by a three.js LightProbe with the previous pass\'s SH (0.3 %), and gains 0.9–0.995 × ρ per bounce (the specular share)', async () => {

		const material = new THREE.MeshStandardMaterial( {
			color: new THREE.Color( ...ALBEDO ), emissive: new THREE.Color( LE, LE, LE ), roughness: 1, metalness: 0, side: THREE.BackSide,
		} );
		const scene = new THREE.Scene();
		const room = furnace( material );
		scene.add( room );
		const volume = new LightProbeVolume( { positions: PROBES } );
		const passes: Float32Array[] = [];
		await captureBounces( volume, renderer, scene, { bounces: 2, ...CAPTURE, onPass: ( _, sh ) => passes.push( sh.slice() ) } );

		const capturer = new ProbeCapturer( renderer, CAPTURE );
		for ( let k = 1; k <= 2; k ++ ) {

			const probe = new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( Array.from( passes[ k - 1 ].subarray( 0, 27 ) ) ) );
			scene.add( probe );
			const reference = await capturer.capture( scene, PROBES, new Float32Array( PROBES.length * 9 ) );
			scene.remove( probe );
			const expected = [ 0, 1, 2 ].map( ( c ) => reference[ c ] );
			expect( furnaceErrors( passes[ k ], expected ).l00, `pass ${k}` ).toBeLessThan( 3e-3 );

		}

		capturer.dispose();
		// Gain of the first bounce over the light it reflects: ρ·(1 − specular share); measured
		// 0.979–0.981 of ρ (roughness 1, F0 = 0.04). Against the LightProbe: 2e-4, 4e-4.
		for ( let c = 0; c < 3; c ++ ) {

			const gain = ( passes[ 1 ][ c ] - passes[ 0 ][ c ] ) / passes[ 0 ][ c ] / ALBEDO[ c ];
			expect( gain ).toBeGreaterThan( 0.9 );
			expect( gain ).toBeLessThan( 0.995 );

		}

		disposeMesh( room );

	} );

	it( 'colour bleeding appears through bounces only: a white room with a red wall (−x) and a glowing ceiling — no red in pass 0, red after bounce 1, strongest by the red wall', async () => {

		const white = lambertWall( [ 0.8, 0.8, 0.8 ], 0 ), red = lambertWall( [ 0.8, 0.08, 0.08 ], 0 );
		const ceiling = lambertWall( [ 0.8, 0.8, 0.8 ], 1 );
		// BoxGeometry groups: +x, −x, +y, −y, +z, −z.
		const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 5, 8, 6, 10 ), [ white, red, ceiling, white, white, white ] );
		const scene = new THREE.Scene();
		scene.add( room );
		const byRed = 5, byWhite = 6;
		const positions = [ ...PROBES, - 1.7, 0, 0, 1.7, 0, 0 ];
		const volume = new LightProbeVolume( { positions } );
		const passes: Float32Array[] = [];
		await captureBounces( volume, renderer, scene, { bounces: 2, ...CAPTURE, onPass: ( _, sh ) => passes.push( sh.slice() ) } );

		const towardsRed = [ - 1, 0, 0 ];
		for ( let p = 0; p < positions.length / 3; p ++ ) {

			// Pass 0 sees only the white ceiling: grey everywhere (HalfFloat: same value per channel).
			expect( Math.abs( redness( passes[ 0 ], p, towardsRed ) ) ).toBeLessThan( 1e-3 );
			expect( Math.abs( redness( passes[ 0 ], p, [ 0, 1, 0 ] ) ) ).toBeLessThan( 1e-3 );

		}

		// After bounce 1 the red wall, lit by the probes, sends red light: the probe at the opposite
		// white wall receives it on a surface facing the red wall; the probe next to it far more
		// (measured: (R − G)/G = 0.029 and 1.01; pass 0: < 1e-3).
		const far1 = redness( passes[ 1 ], byWhite, towardsRed ), near1 = redness( passes[ 1 ], byRed, towardsRed );
		expect( far1 ).toBeGreaterThan( 0.01 );
		expect( near1 ).toBeGreaterThan( 2 * far1 );
		// Facing away from the red wall, the probe by the white wall gets less of it (0.007, SH9's
		// smoothing: that hemisphere sees only grey walls in pass 1).
		expect( redness( passes[ 1 ], byWhite, [ 1, 0, 0 ] ) ).toBeLessThan( far1 );
		// Bounce 2: the white walls now reflect reddened light too.
		expect( redness( passes[ 2 ], byWhite, [ 1, 0, 0 ] ) ).toBeGreaterThan( redness( passes[ 1 ], byWhite, [ 1, 0, 0 ] ) );
		disposeMesh( room );
		for ( const material of [ white, red, ceiling ] ) material.dispose();

	} );

	/** A scene with everything the default selection must sort out. */
	function restorationScene() {

		const scene = new THREE.Scene();
		const room = furnace( lambertWall( [ 0.5, 0.5, 0.5 ], 0.4 ) );
		const sharedGeometry = new THREE.BoxGeometry( 0.3, 0.3, 0.3 );
		const sharedMaterial = new THREE.MeshStandardMaterial( { color: 0x808080 } );
		const boxA = new THREE.Mesh( sharedGeometry, sharedMaterial ), boxB = new THREE.Mesh( sharedGeometry, sharedMaterial );
		boxA.position.set( - 1.2, - 1.2, 0 );
		boxB.position.set( 1.2, - 1.2, 0.5 );
		const basic = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshBasicMaterial( { color: 0xff0000 } ) );
		basic.position.set( 0, - 1, 2 );
		const character = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshStandardMaterial() );
		const fill = new THREE.AmbientLight( 0xffffff, 0.3 );
		scene.add( room, boxA, boxB, basic, character, fill );
		const meshes = [ room, boxA, boxB, basic, character ];
		const before = meshes.map( ( mesh ) => ( { mesh, geometry: mesh.geometry, material: mesh.material, attributes: Object.keys( mesh.geometry.attributes ).sort() } ) );
		const view = new THREE.PerspectiveCamera( 90, 1, 0.05, 20 );
		view.updateMatrixWorld();
		const volume = new LightProbeVolume( { positions: PROBES } );
		volume.add( character );
		const characterMaterial = character.material;
		const dispose = () => {

			volume.dispose();
			for ( const mesh of [ room, basic, character ] ) disposeMesh( mesh );
			sharedGeometry.dispose();
			sharedMaterial.dispose();

		};

		return { scene, room, boxA, boxB, basic, character, characterMaterial, fill, meshes, before, view, volume, dispose };

	}

	it( 'default static meshes and restoration: standard-material meshes only (not MeshBasic, not volume.add()ed), shared geometry handled, everything back by identity, hideInBounces hidden in passes ≥ 1 only, renderer.info.memory and programs back', async () => {

		const s = restorationScene();
		const render = () => renderToImage( renderer, gl, s.scene, s.view );
		// Warm-up with an ordinary capture: three's lazily made resources and the scene's programs
		// exist afterwards; the patched clones' program must not (it goes with the clones).
		render();
		await s.volume.capture( renderer, s.scene, { ...CAPTURE, resolution: 8 } );
		render();
		const baseline = { ...renderer.info.memory, programs: renderer.info.programs!.length };
		const state = { autoClear: renderer.autoClear, target: renderer.getRenderTarget(), toneMapping: renderer.toneMapping };

		const fillVisible: boolean[] = [];
		const litDuringPass: boolean[] = [];
		const result = await captureBounces( s.volume, renderer, s.scene, {
			bounces: 2, ...CAPTURE, hideInBounces: [ s.fill ],
			onPass: () => {

				fillVisible.push( s.fill.visible );
				litDuringPass.push( s.room.material !== s.before[ 0 ].material && s.boxA.geometry !== s.boxB.geometry && s.boxA.material !== s.boxB.material );

			},
		} );

		expect( new Set( result.staticMeshes ) ).toEqual( new Set( [ s.room, s.boxA, s.boxB ] ) );
		expect( fillVisible ).toEqual( [ true, false, false ] );
		expect( litDuringPass ).toEqual( [ false, true, true ] );
		expect( s.fill.visible ).toBe( true );
		for ( const { mesh, geometry, material, attributes } of s.before ) {

			expect( mesh.geometry ).toBe( geometry );
			expect( mesh.material ).toBe( material );
			expect( Object.keys( mesh.geometry.attributes ).sort() ).toEqual( attributes );

		}

		expect( s.character.material ).toBe( s.characterMaterial ); // still the volume's, still patched
		expect( s.volume.getUniforms( s.character ) ).not.toBeNull();
		expect( { autoClear: renderer.autoClear, target: renderer.getRenderTarget(), toneMapping: renderer.toneMapping } ).toEqual( state );

		for ( let i = 0; i < 3; i ++ ) await captureBounces( s.volume, renderer, s.scene, { bounces: 2, ...CAPTURE, resolution: 8 + 4 * i } );
		render();
		expect( { ...renderer.info.memory, programs: renderer.info.programs!.length } ).toEqual( baseline );
		s.dispose();

	} );

	it( 'a capture that throws in bounce pass 2: the error comes through, meshes, visibility and GPU memory are restored, the volume keeps what it had before (all or nothing)', async () => {

		const s = restorationScene();
		const render = () => renderToImage( renderer, gl, s.scene, s.view );
		render();
		await s.volume.capture( renderer, s.scene, { ...CAPTURE, resolution: 8 } );
		render();
		const baseline = { ...renderer.info.memory, programs: renderer.info.programs!.length };
		const before = { sh: Array.from( s.volume.sh ), settings: structuredClone( s.volume.captureSettings ), dirty: s.volume.dirtyProbes() };

		let pass = 0;
		const kept: Float32Array[] = [];
		const failing = captureBounces( s.volume, renderer, s.scene, {
			bounces: 3, ...CAPTURE, hideInBounces: [ s.fill ],
			onPass: ( done, sh ) => { pass = done + 1; kept.push( sh.slice() ); },
			onProgress: () => { if ( pass === 2 ) throw new Error( 'simulated failure' ); },
		} );
		await expect( failing ).rejects.toThrow( 'simulated failure' );
		expect( kept.length ).toBe( 2 );
		expect( Array.from( kept[ 1 ] ) ).not.toEqual( before.sh ); // pass 1 was captured, but only staged
		expect( Array.from( s.volume.sh ) ).toEqual( before.sh );
		expect( s.volume.captureSettings ).toEqual( before.settings );
		expect( s.volume.dirtyProbes() ).toEqual( before.dirty );
		expect( s.fill.visible ).toBe( true );
		for ( const { mesh, geometry, material, attributes } of s.before ) {

			expect( mesh.geometry ).toBe( geometry );
			expect( mesh.material ).toBe( material );
			expect( Object.keys( mesh.geometry.attributes ).sort() ).toEqual( attributes );

		}

		render();
		expect( { ...renderer.info.memory, programs: renderer.info.programs!.length } ).toEqual( baseline );
		s.dispose();

	} );

	it( 'volume.capture( renderer, scene, { bounces: 2 } ) is captureBounces with bounces: 2, bit for bit, and returns the volume', async () => {

		const scene = new THREE.Scene();
		const room = furnace( lambertWall( ALBEDO, LE ) );
		scene.add( room );
		const a = new LightProbeVolume( { positions: PROBES } ), b = new LightProbeVolume( { positions: PROBES } );
		const passes: number[] = [];
		expect( await a.capture( renderer, scene, { bounces: 2, ...CAPTURE, onPass: ( pass ) => passes.push( pass ) } ) ).toBe( a );
		await captureBounces( b, renderer, scene, { bounces: 2, ...CAPTURE } );
		expect( passes ).toEqual( [ 0, 1, 2 ] );
		expect( Array.from( a.sh ) ).toEqual( Array.from( b.sh ) );
		expect( a.captureSettings ).toEqual( b.captureSettings );
		disposeMesh( room );

	} );

	it( 'bounces: 0 is the ordinary capture, bit for bit', async () => {

		const scene = new THREE.Scene();
		const room = furnace( lambertWall( ALBEDO, LE ) );
		scene.add( room );
		const a = new LightProbeVolume( { positions: PROBES } ), b = new LightProbeVolume( { positions: PROBES } );
		const result = await captureBounces( a, renderer, scene, { bounces: 0, ...CAPTURE } );
		await b.capture( renderer, scene, CAPTURE );
		expect( result.passes.length ).toBe( 1 );
		expect( Array.from( a.sh ) ).toEqual( Array.from( b.sh ) );
		disposeMesh( room );

	} );

} );
