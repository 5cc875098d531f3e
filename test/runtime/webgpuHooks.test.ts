/**
 * The main entry alone (no `three-capture-lighting/webgpu` import, so no hooks installed): each
 * WebGPU path gives a named Error that says to import 'three-capture-lighting/webgpu', and the
 * failed call changes nothing. three/webgpu is imported here only to make real node materials;
 * the library itself never loads it (test/layers.test.ts).
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { MeshStandardNodeMaterial } from 'three/webgpu';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeHelper } from '../../src/runtime/LightProbeVolumeHelper.js';
import { nodeMaterialShading, probeUniformsOf } from '../../src/runtime/nodeMaterialHooks.js';
import { webGPUCapture } from '../../src/capture/captureBackends.js';
import { helperMaterials } from '../../src/runtime/helperHooks.js';

const ENTRY = '\'three-capture-lighting/webgpu\'';

function smallVolume(): LightProbeVolume {

	const positions: number[] = [];
	for ( let x = 0; x < 2; x ++ ) for ( let y = 0; y < 2; y ++ ) for ( let z = 0; z < 2; z ++ ) positions.push( x, y, z );
	positions.push( 0.5, 0.5, 0.5 );
	const sh = new Float32Array( 27 * 9 );
	for ( let i = 0; i < sh.length; i ++ ) sh[ i ] = 0.3 + 0.1 * Math.sin( i );
	return new LightProbeVolume( { positions, sh } );

}

/** A stand-in for a WebGPURenderer: only the flag the library checks, so any deeper use would crash. */
function fakeWebGPURenderer(): object {

	return { isWebGPURenderer: true, domElement: {}, capabilities: {}, init: async () => undefined, render() {}, setRenderTarget() {} };

}

describe( 'main entry without the webgpu hooks', () => {

	it( 'has no hooks installed', () => {

		expect( nodeMaterialShading() ).toBeNull();
		expect( webGPUCapture() ).toBeNull();
		expect( helperMaterials() ).toBeNull();

	} );

	it( 'add() of a node-material mesh names the webgpu entry and leaves material and volume untouched', () => {

		const volume = smallVolume();
		const material = new MeshStandardNodeMaterial();
		const before = { version: material.version, keys: Object.keys( material ).sort(), colorNode: material.colorNode };
		const mesh = new THREE.Mesh( new THREE.BoxGeometry(), material );
		const sh = volume.sh.slice();
		let error: unknown;
		try {

			volume.add( mesh );

		} catch ( e ) {

			error = e;

		}

		expect( error ).toBeInstanceOf( Error );
		const message = ( error as Error ).message;
		expect( message.startsWith( 'LightProbeVolume.add:' ) ).toBe( true );
		expect( message ).toContain( ENTRY );
		expect( message ).toContain( 'MeshStandardNodeMaterial' );
		expect( material.version ).toBe( before.version );
		expect( Object.keys( material ).sort() ).toEqual( before.keys );
		expect( material.colorNode ).toBe( before.colorNode );
		expect( probeUniformsOf( material ) ).toBeNull();
		expect( mesh.material ).toBe( material );
		expect( volume.getLighting( mesh ) ).toBeNull();
		expect( Array.from( volume.sh ) ).toEqual( Array.from( sh ) );

	} );

	it( 'capture() with a WebGPURenderer names the webgpu entry and leaves the volume as it was', async () => {

		const volume = smallVolume();
		const sh = volume.sh.slice();
		const positions = Array.from( volume.positions );
		const scene = new THREE.Scene();
		scene.add( new THREE.Mesh( new THREE.BoxGeometry(), new THREE.MeshStandardMaterial() ) );
		const error = await volume.capture( fakeWebGPURenderer() as never, scene ).then( () => null, ( e: unknown ) => e );
		expect( error ).toBeInstanceOf( Error );
		expect( error ).not.toBeInstanceOf( TypeError );
		const message = ( error as Error ).message;
		expect( message.startsWith( 'LightProbeVolume.capture:' ) ).toBe( true );
		expect( message ).toContain( ENTRY );
		expect( Array.from( volume.sh ) ).toEqual( Array.from( sh ) );
		expect( Array.from( volume.positions ) ).toEqual( positions );

	} );

	it( 'fromScene() with a WebGPURenderer names the webgpu entry', async () => {

		const scene = new THREE.Scene();
		scene.add( new THREE.Mesh( new THREE.BoxGeometry( 4, 4, 4 ), new THREE.MeshStandardMaterial( { side: THREE.BackSide } ) ) );
		const error = await LightProbeVolume.fromScene( fakeWebGPURenderer() as never, scene, { budget: 8, resolution: 8 } )
			.then( () => null, ( e: unknown ) => e );
		expect( error ).toBeInstanceOf( Error );
		expect( error ).not.toBeInstanceOf( TypeError );
		expect( ( error as Error ).message ).toContain( ENTRY );

	} );

	it( 'LightProbeVolumeHelper drawn by a WebGPURenderer names the webgpu entry', () => {

		const volume = smallVolume();
		const helper = new LightProbeVolumeHelper( volume );
		const mesh = helper.probes;
		const count = mesh.count;
		const camera = new THREE.PerspectiveCamera();
		let error: unknown;
		try {

			const material = mesh.material as THREE.Material;
			mesh.onBeforeRender( fakeWebGPURenderer() as never, new THREE.Scene(), camera, mesh.geometry, material, null as never );

		} catch ( e ) {

			error = e;

		}

		expect( error ).toBeInstanceOf( Error );
		expect( error ).not.toBeInstanceOf( TypeError );
		expect( ( error as Error ).message.startsWith( 'LightProbeVolumeHelper:' ) ).toBe( true );
		expect( ( error as Error ).message ).toContain( ENTRY );
		expect( mesh.count ).toBe( count );
		helper.dispose();

	} );

} );
