import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/index.js';
import { ProbeCapturer } from '../../src/capture.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';

const ctx = await createHeadlessRenderer( 16, 16 );

describe.skipIf( ! ctx.renderer )( `capture settings per probe role${ctx.skipReason ? ' — SKIPPED: ' + ctx.skipReason : ''}`, () => {

	afterAll( () => ctx.dispose() );

	it( 'overlapping captures on one ProbeCapturer: the second is refused with a clear error, the first completes', async () => {

		const scene = new THREE.Scene();
		scene.add( new THREE.Mesh( new THREE.BoxGeometry( 20, 20, 20 ), new THREE.MeshBasicMaterial( { color: 0xffffff, side: THREE.BackSide } ) ) );
		const capturer = new ProbeCapturer( ctx.renderer!, { resolution: 8 } );
		// Enough probes that the first capture yields to the event loop before it is done.
		const positions = new Float64Array( 3 * 400 ).map( ( _, i ) => ( i % 7 ) * 0.1 );
		const first = capturer.capture( scene, positions, new Float32Array( 27 * 400 ) );
		await expect( capturer.capture( scene, [ 0, 0, 0 ], new Float32Array( 27 ) ) ).rejects.toThrow( /already running/ );
		const sh = await first;
		expect( sh[ 27 * 399 ] ).toBeCloseTo( 2 * Math.sqrt( Math.PI ), 2 );
		await expect( capturer.capture( scene, [ 0, 0, 0 ], new Float32Array( 27 ) ) ).resolves.toBeInstanceOf( Float32Array );
		capturer.dispose();

	} );

	it( 'a role\'s own near/far and layers apply to its probes only; progress counts all probes', async () => {

		// A bright box 10 units around every probe. Probes whose role has far = 5 cannot see it
		// (black, SH 0); the others see it (L00 = 2√π · 1 for a constant radiance of 1).
		const scene = new THREE.Scene();
		scene.add( new THREE.Mesh( new THREE.BoxGeometry( 20, 20, 20 ), new THREE.MeshBasicMaterial( { color: 0xffffff, side: THREE.BackSide } ) ) );
		const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1 ];
		const volume = new LightProbeVolume( { positions, roles: [ 'sky', 'bounce', 'bounce', 'fill', 'sky' ] } );
		const progress: number[][] = [];
		await volume.capture( ctx.renderer!, scene, { resolution: 8, far: 100, roles: { bounce: { far: 5 } }, onProgress: ( done, total ) => progress.push( [ done, total ] ) } );
		const l00 = ( i: number ) => volume.sh[ 27 * i ];
		expect( l00( 1 ) ).toBe( 0 );
		expect( l00( 2 ) ).toBe( 0 );
		for ( const i of [ 0, 3, 4 ] ) expect( l00( i ) ).toBeCloseTo( 2 * Math.sqrt( Math.PI ), 2 );
		expect( progress.at( - 1 ) ).toEqual( [ 5, 5 ] );
		expect( progress.map( ( [ done ] ) => done ) ).toEqual( [ 1, 2, 3, 4, 5 ] );

		// Layers per role: the box on layer 3 is invisible to sky probes limited to layer 0.
		scene.children[ 0 ].layers.set( 3 );
		const skyLayers = new THREE.Layers(); // layer 0 only
		const other = new THREE.Layers(); other.set( 3 );
		await volume.capture( ctx.renderer!, scene, { resolution: 8, layers: other, roles: { sky: { layers: skyLayers } } } );
		expect( l00( 0 ) ).toBe( 0 );
		expect( l00( 1 ) ).toBeCloseTo( 2 * Math.sqrt( Math.PI ), 2 );

	} );

} );
