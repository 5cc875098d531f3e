/**
 * Captures are all or nothing (headless-gl): a renderer whose render() throws on its Nth call —
 * in the first role pass, between role passes, in the second, in a bounce pass — makes capture(),
 * recaptureDirty() and captureBounces() reject, and every probe's SH, the dirty set and the
 * capture settings are exactly as before; registered objects are visible again with their probe
 * light back on. Then a capture that is left alone succeeds. (Chromium, with a lost context at the
 * same points: test/browser/atomicCapture.test.ts.)
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { captureBounces } from '../../src/runtime/captureBounces.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';

const ctx = await createHeadlessRenderer( 16, 16 );

/** A room (emissive, standard material: it takes bounces) and 8 probes, half of them with a role of their own. */
function setup() {

	const scene = new THREE.Scene();
	const material = new THREE.MeshStandardMaterial( { color: 0x808080, emissive: 0x204060, side: THREE.BackSide, roughness: 1 } );
	const room = new THREE.Mesh( new THREE.BoxGeometry( 10, 10, 10 ), material );
	scene.add( room );
	const positions = [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 1, - 1, 1, 1, - 1, - 1, - 1, 1, 1, - 1, 1, - 1, 1, 1, 1, 1, 1.2 ];
	const roles = [ 'sky', 'fill', 'sky', 'fill', 'sky', 'fill', 'sky', 'fill' ] as const;
	const volume = new LightProbeVolume( { positions, roles: [ ...roles ] } );
	const visitor = new THREE.Mesh( new THREE.SphereGeometry( 0.3 ), new THREE.MeshStandardMaterial() );
	scene.add( visitor );
	volume.add( visitor );
	const floorGeometry = new THREE.PlaneGeometry( 4, 4 ).rotateX( - Math.PI / 2 ).translate( 0, - 2, 0 );
	const floor = new THREE.Mesh( floorGeometry, new THREE.MeshStandardMaterial() );
	scene.add( floor );
	volume.add( floor, { mode: 'vertex' } ); // scenery: its probe light is switched off while capturing
	return { scene, room, material, volume, visitor, floor };

}

type Setup = ReturnType<typeof setup>;

function state( s: Setup ): string {

	return JSON.stringify( {
		sh: Array.from( s.volume.sh ), dirty: s.volume.dirtyProbes(), settings: s.volume.captureSettings,
		visitorVisible: s.visitor.visible, roomVisible: s.room.visible,
		intensities: [ s.visitor, s.floor ].map( ( object ) => s.volume.getUniforms( object )!.probeVolumeIntensity.value ),
		roomMaterial: s.room.material === s.material, roomAttributes: Object.keys( s.room.geometry.attributes ),
	} );

}

/** Makes the renderer's render() throw on its `failAt`-th call from now (0: never); returns a counter of the calls. */
function inject( renderer: THREE.WebGLRenderer, failAt: number ): { calls: number; restore(): void } {

	const original = renderer.render;
	const counter = {
		calls: 0,
		restore() { renderer.render = original; },
	};
	renderer.render = function ( scene, camera ) {

		counter.calls ++;
		if ( counter.calls === failAt ) throw new Error( `injected failure at render ${failAt}` );
		return original.call( this, scene, camera );

	};

	return counter;

}

describe.skipIf( ! ctx.renderer )( `captures are all or nothing${ctx.skipReason ? ' — SKIPPED: ' + ctx.skipReason : ''}`, () => {

	afterAll( () => ctx.dispose() );
	const renderer = ctx.renderer!;
	const options = { resolution: 8, far: 50, roles: { sky: { far: 40 } } };

	it( 'capture() failing anywhere in either role pass leaves SH, dirty set and capture settings as they were; left alone, it succeeds', async () => {

		const s = setup();
		await s.volume.capture( renderer, s.scene, { resolution: 8 } );
		s.volume.moveProbe( 7, [ 1, 1, 1.1 ] ); // dirty
		s.material.emissive.setHex( 0x603010 ); // a capture now gives other SH
		// How many render calls a whole capture makes, and where the second role pass starts.
		const count = inject( renderer, 0 );
		let secondPass = 0;
		const probe = new LightProbeVolume( { positions: Array.from( s.volume.positions ), roles: [ ...s.volume.roles ] } );
		await probe.capture( renderer, s.scene, { ...options, onProgress: ( done ) => { if ( done === 4 ) secondPass = count.calls; } } );
		count.restore();
		const total = count.calls;
		expect( secondPass ).toBeGreaterThan( 0 );
		expect( total ).toBeGreaterThan( secondPass );

		const before = state( s );
		const points = [ 1, Math.floor( secondPass / 2 ), secondPass, secondPass + 1, Math.floor( ( secondPass + total ) / 2 ), total ];
		for ( const failAt of points ) {

			const injected = inject( renderer, failAt );
			await expect( s.volume.capture( renderer, s.scene, options ), `failure at render ${failAt} of ${total}` ).rejects.toThrow( `injected failure at render ${failAt}` );
			injected.restore();
			expect( state( s ), `after a failure at render ${failAt} of ${total}` ).toBe( before );

		}

		// recaptureDirty too.
		const injected = inject( renderer, 3 );
		await expect( s.volume.recaptureDirty( renderer, s.scene, options ) ).rejects.toThrow( 'injected failure' );
		injected.restore();
		expect( state( s ) ).toBe( before );

		await s.volume.capture( renderer, s.scene, options );
		expect( Array.from( s.volume.sh ) ).not.toEqual( JSON.parse( before ).sh );
		expect( s.volume.dirtyProbes() ).toEqual( [] );
		expect( s.volume.captureSettings.roles?.sky?.far ).toBe( 40 );
		s.volume.dispose();

	} );

	it( 'captureBounces failing in pass 0, 1 or 2 leaves the volume as it was (no pass committed), and restores the scene', async () => {

		const s = setup();
		await s.volume.capture( renderer, s.scene, { resolution: 8 } );
		s.material.emissive.setHex( 0x406020 );
		const count = inject( renderer, 0 );
		const starts: number[] = [];
		const reference = await captureBounces( s.volume, renderer, s.scene, {
			...options, bounces: 2, staticMeshes: [ s.room ], onPass: () => starts.push( count.calls ),
		} );
		count.restore();
		expect( reference.passes.length ).toBe( 3 );
		const after = Array.from( s.volume.sh );
		s.material.emissive.setHex( 0x102030 );
		await s.volume.capture( renderer, s.scene, { resolution: 8 } );
		s.material.emissive.setHex( 0x406020 );
		const before = state( s );

		for ( const failAt of [ 2, starts[ 0 ] + 2, Math.floor( ( starts[ 0 ] + starts[ 1 ] ) / 2 ), starts[ 1 ] + 5, starts[ 2 ] - 1 ] ) {

			const injected = inject( renderer, failAt );
			await expect( captureBounces( s.volume, renderer, s.scene, { ...options, bounces: 2, staticMeshes: [ s.room ] } ) ).rejects.toThrow( 'injected failure' );
			injected.restore();
			expect( state( s ), `after a failure at render ${failAt} (passes start at 0, ${starts.join( ', ' )})` ).toBe( before );

		}

		await s.volume.capture( renderer, s.scene, { ...options, bounces: 2, staticMeshes: [ s.room ] } );
		expect( Array.from( s.volume.sh ) ).toEqual( after );
		s.volume.dispose();

	} );

} );
