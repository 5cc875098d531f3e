/**
 * Gradient probes on a real GL context (headless-gl, WebGL2): a 20 × 20 floor under a probe field whose SH is linear
 * in x, y and z, with every probe above the floor (the floor lies in the outer cells), seen from straight above.
 *
 * Truth, independent of the code under test: at a point p of the floor the pixel must be what three.js renders for
 * the floor lit by a plain `LightProbe` holding the analytic SH(p). Gradient probes (G = the field's gradient)
 * reproduce a linear field exactly anywhere, so vertex and texture modes must match within 2/255; the same probes
 * without gradients extrapolate from the hull's bottom face and miss by far more, so the check can fail.
 * Object mode: a ball below the probes must look like the same ball lit by a LightProbe holding SH(its centre).
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/gradientVolume.gpu.test.ts`.
 */

import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { FLOOR_POINTS, floorMesh, floorPixel, topCamera } from '../helpers/floorScene.js';
import { compareImages, renderToImage, type Image8 } from '../helpers/gpuScenes.js';

const SIZE = 64;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** The field's constant part and gradient: red towards +x, blue towards +z, all brighter upwards; a little L1, L2. */
const A = new Array<number>( 27 ).fill( 0 );
const B = new Array<number>( 81 ).fill( 0 ); // B[ 27·axis + k ]
A[ 0 ] = 1.0; A[ 1 ] = 0.9; A[ 2 ] = 1.0; A[ 3 ] = 0.25; A[ 4 ] = 0.3; A[ 5 ] = 0.25;
A[ 18 ] = 0.08; A[ 19 ] = - 0.05; A[ 20 ] = 0.06; A[ 24 ] = 0.05; A[ 25 ] = 0.02; A[ 26 ] = - 0.04;
B[ 0 ] = 0.04; B[ 4 ] = 0.01; // ∂/∂x
B[ 27 + 0 ] = 0.06; B[ 27 + 1 ] = 0.08; B[ 27 + 2 ] = 0.06; // ∂/∂y
B[ 54 + 2 ] = 0.04; B[ 54 + 19 ] = 0.004; // ∂/∂z

function fieldSH( x: number, y: number, z: number ): number[] {

	return A.map( ( a, k ) => a + B[ k ] * x + B[ 27 + k ] * y + B[ 54 + k ] * z );

}

/** Probes on two levels above the floor (y 2 … 5), corners plus irregular interior points; with or without gradients. */
function fieldVolume( gradients: boolean ): LightProbeVolume {

	const positions: number[] = [];
	for ( const x of [ - 12, 12 ] ) for ( const y of [ 2, 5 ] ) for ( const z of [ - 12, 12 ] ) positions.push( x, y, z );
	for ( let i = 0; i < 16; i ++ ) {

		positions.push( 9 * Math.sin( 3.1 * i + 1 ), 3.5 + 1.4 * Math.sin( 5.3 * i ), 9 * Math.cos( 2.3 * i + 0.5 ) );

	}

	const count = positions.length / 3, sh: number[] = [];
	for ( let i = 0; i < count; i ++ ) sh.push( ...fieldSH( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ] ) );
	const g = gradients ? Array.from( { length: count }, () => B ).flat() : undefined;
	return new LightProbeVolume( { positions, sh, gradients: g } );

}

describe.skipIf( ! ctx.renderer )( `gradient probes on a real GL context (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;
	const camera = topCamera();

	afterAll( () => ctx.dispose() );

	function render( ...objects: THREE.Object3D[] ): Image8 {

		const scene = new THREE.Scene();
		scene.add( ...objects );
		return renderToImage( renderer, gl, scene, camera );

	}

	/** What three renders at (x, 0, z) for the floor lit by a LightProbe holding SH(x, 0, z). */
	function expected( x: number, z: number ): number[] {

		const floor = floorMesh( 1 );
		const image = render( floor, new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( fieldSH( x, 0, z ) ) ) );
		floor.geometry.dispose();
		( floor.material as THREE.Material ).dispose();
		return floorPixel( image, camera, x, z );

	}

	const references = FLOOR_POINTS.map( ( [ x, z ] ) => expected( x, z ) );

	function worstAgainstReference( image: Image8 ): number {

		let worst = 0;
		FLOOR_POINTS.forEach( ( [ x, z ], i ) => {

			const actual = floorPixel( image, camera, x, z );
			for ( let c = 0; c < 3; c ++ ) worst = Math.max( worst, Math.abs( actual[ c ] - references[ i ][ c ] ) );

		} );
		return worst;

	}

	it( 'the references differ across the floor by > 30/255 in red and blue (the field is a real gradient)', () => {

		const at = ( x: number, z: number ) => references[ FLOOR_POINTS.findIndex( ( p ) => p[ 0 ] === x && p[ 1 ] === z ) ];
		expect( at( 8, - 8 )[ 0 ] - at( - 8, - 8 )[ 0 ] ).toBeGreaterThan( 30 );
		expect( at( - 8, 8 )[ 2 ] - at( - 8, - 8 )[ 2 ] ).toBeGreaterThan( 30 );

	} );

	for ( const mode of [ 'vertex', 'texture' ] as const ) {

		it( `add( floor, { mode: '${mode}' } ) below every probe: within 2/255 of the analytic field with gradients; plain probes miss by > 6/255`, () => {

			const errors: number[] = [];
			for ( const gradients of [ true, false ] ) {

				const volume = fieldVolume( gradients );
				const floor = floorMesh( 4 );
				volume.add( floor, { mode } );
				volume.update();
				errors.push( worstAgainstReference( render( floor ) ) );
				volume.dispose();
				floor.geometry.dispose();

			}

			expect( errors[ 0 ] ).toBeLessThanOrEqual( 2 );
			expect( errors[ 1 ] ).toBeGreaterThan( 6 );

		} );

	}

	it( 'object mode: a ball at (3, 0.5, −2), below the probes, looks like the ball lit by a LightProbe holding SH there (within 2/255)', () => {

		const ball = () => new THREE.Mesh( new THREE.SphereGeometry( 3, 48, 24 ), new THREE.MeshStandardMaterial( { roughness: 1 } ) );
		const centre = [ 3, 0.5, - 2 ] as const;
		const reference = ball();
		reference.position.set( ...centre );
		const probe = new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( fieldSH( ...centre ) ) );
		const want = render( reference, probe );
		const results: number[] = [];
		for ( const gradients of [ true, false ] ) {

			const volume = fieldVolume( gradients );
			const lit = ball();
			lit.position.set( ...centre );
			volume.add( lit );
			volume.update();
			results.push( compareImages( render( lit ), want ).max );
			volume.dispose();
			lit.geometry.dispose();

		}

		expect( results[ 0 ] ).toBeLessThanOrEqual( 2 );
		expect( results[ 1 ] ).toBeGreaterThan( 6 );
		reference.geometry.dispose();

	} );

} );
