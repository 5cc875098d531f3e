/**
 * Large objects on a real GL context (headless-gl, WebGL2): a 20 × 20 floor under a probe field
 * whose SH is a linear function of x and z, seen from straight above by an orthographic camera.
 *
 * Truth, independent of the code under test: at a point p of the floor, the pixel must be what
 * three.js renders for the same floor lit by a plain `LightProbe` holding the analytic SH(p). The
 * object mode (one SH per object) gives one colour everywhere; the vertex and texture modes must
 * follow the gradient — a linear field is reproduced exactly by per-vertex sampling (linear across
 * triangles at a constant normal) and by trilinear filtering of grid nodes.
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/largeObjects.gpu.test.ts`.
 */

import * as path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { ProbeVertexLighting } from '../../src/runtime/ProbeVertexLighting.js';
import { ProbeTextureLighting } from '../../src/runtime/ProbeTextureLighting.js';
import { ProbeVolumeTexture } from '../../src/runtime/ProbeVolumeTexture.js';
import { toLightProbeGrid } from '../../src/runtime/toLightProbeGrid.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { FLOOR_POINTS, floorMesh, floorPixel, topCamera } from '../helpers/floorScene.js';
import { OUTPUT_DIR, compareImages, renderToImage, writePNG, type Image8 } from '../helpers/gpuScenes.js';

const SIZE = 64;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** SH(x, z): bright red towards +x, blue towards +z, green from above; a little L2 everywhere. */
function fieldSH( x: number, z: number ): number[] {

	const sh = new Array<number>( 27 ).fill( 0 );
	sh[ 0 ] = 1.1 + 0.045 * x; sh[ 1 ] = 1.1; sh[ 2 ] = 1.1 + 0.045 * z; // L00
	sh[ 3 ] = 0.25; sh[ 4 ] = 0.3 + 0.012 * x; sh[ 5 ] = 0.25; // L1−1 (y)
	sh[ 18 ] = 0.08; sh[ 19 ] = - 0.05 + 0.004 * z; sh[ 20 ] = 0.06; // L20
	sh[ 24 ] = 0.05; sh[ 25 ] = 0.02; sh[ 26 ] = - 0.04; // L22
	return sh;

}

/** Probes on two levels around the floor, corners plus irregular interior points. */
function fieldVolume(): LightProbeVolume {

	const positions: number[] = [];
	for ( const x of [ - 12, 12 ] ) for ( const y of [ - 2, 4 ] ) for ( const z of [ - 12, 12 ] ) positions.push( x, y, z );
	for ( let i = 0; i < 20; i ++ ) positions.push( 9 * Math.sin( 3.1 * i + 1 ), 1 + 2 * Math.sin( 5.3 * i ), 9 * Math.cos( 2.3 * i + 0.5 ) );
	const sh: number[] = [];
	for ( let i = 0; i < positions.length / 3; i ++ ) sh.push( ...fieldSH( positions[ 3 * i ], positions[ 3 * i + 2 ] ) );
	return new LightProbeVolume( { positions, sh } );

}

describe.skipIf( ! ctx.renderer )( `large objects on a real GL context (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;
	const camera = topCamera();

	afterAll( () => ctx.dispose() );

	/** What three renders at (x, z) for the floor lit by a LightProbe holding SH(x, z). */
	const reference = new Map<string, number[]>();
	function expected( x: number, z: number ): number[] {

		const key = `${x},${z}`;
		if ( ! reference.has( key ) ) {

			const scene = new THREE.Scene();
			const floor = floorMesh();
			scene.add( floor, new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( fieldSH( x, z ) ) ) );
			reference.set( key, floorPixel( renderToImage( renderer, gl, scene, camera ), camera, x, z ) );
			floor.geometry.dispose();
			( floor.material as THREE.Material ).dispose();

		}

		return reference.get( key )!;

	}

	function render( floor: THREE.Object3D, extra?: THREE.Object3D ): Image8 {

		const scene = new THREE.Scene();
		scene.add( floor );
		if ( extra ) scene.add( extra );
		return renderToImage( renderer, gl, scene, camera );

	}

	/** Largest channel difference between the image and the LightProbe references at FLOOR_POINTS. */
	function worstAgainstReference( image: Image8 ): number {

		let worst = 0;
		for ( const [ x, z ] of FLOOR_POINTS ) {

			const actual = floorPixel( image, camera, x, z ), want = expected( x, z );
			for ( let c = 0; c < 3; c ++ ) worst = Math.max( worst, Math.abs( actual[ c ] - want[ c ] ) );

		}

		return worst;

	}

	it( 'the references themselves differ across the floor by > 30/255 in red and blue (the field is a real gradient)', () => {

		expect( expected( 8, - 8 )[ 0 ] - expected( - 8, - 8 )[ 0 ] ).toBeGreaterThan( 30 );
		expect( expected( - 8, 8 )[ 2 ] - expected( - 8, - 8 )[ 2 ] ).toBeGreaterThan( 30 );

	} );

	it( 'object mode (LightProbeVolume.add): one colour over the whole floor — the issue this feature fixes', () => {

		const volume = fieldVolume();
		const floor = floorMesh();
		volume.add( floor );
		const image = render( floor );
		const colours = FLOOR_POINTS.map( ( [ x, z ] ) => floorPixel( image, camera, x, z ) );
		for ( const colour of colours ) for ( let c = 0; c < 3; c ++ ) expect( Math.abs( colour[ c ] - colours[ 0 ][ c ] ) ).toBeLessThanOrEqual( 1 );
		expect( worstAgainstReference( image ) ).toBeGreaterThan( 20 );
		volume.dispose();

	} );

	for ( const output of [ 'irradiance', 'sh' ] as const ) {

		it( `vertex mode, output '${output}', a two-triangle floor: every sample point within 2/255 of three's LightProbe with the SH there`, () => {

			const volume = fieldVolume();
			const floor = floorMesh();
			const lighting = new ProbeVertexLighting( floor, volume, { output } );
			const image = render( floor );
			const worst = worstAgainstReference( image );
			if ( worst > 2 ) writePNG( path.join( OUTPUT_DIR, `largeObjects.vertex-${output}.png` ), image );
			expect( worst ).toBeLessThanOrEqual( 2 );
			lighting.dispose();
			floor.geometry.dispose();

		} );

	}

	for ( const mode of [ 'vertex', 'texture' ] as const ) {

		it( `LightProbeVolume.add( floor, { mode: '${mode}' } ): the gradient within 2/255, update() follows a move, remove() restores the material`, () => {

			const volume = fieldVolume();
			const floor = floorMesh();
			const material = floor.material;
			volume.add( floor, { mode } );
			volume.update();
			expect( floor.material ).not.toBe( material );
			expect( worstAgainstReference( render( floor ) ) ).toBeLessThanOrEqual( 2 );
			// Moved 3 units along x: the light must follow the field, not stay baked at the old place.
			floor.position.x = 3;
			floor.updateMatrixWorld();
			volume.update();
			const moved = render( floor );
			const want = expected( 5, 0 ), got = floorPixel( moved, camera, 5, 0 );
			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( got[ c ] - want[ c ] ) ).toBeLessThanOrEqual( 2 );
			volume.remove( floor );
			expect( floor.material ).toBe( material );
			floor.geometry.dispose();

		} );

	}

	it( 'LightProbeVolume.capture: a floor added in vertex mode stays in the probes\' view, seen as built (its probe light off); an object-mode visitor is hidden', async () => {

		// A red emissive floor under one probe: the probe sees red from below only if the floor is
		// captured; its own probe light (a huge intensity here) must not leak into what it sees.
		const scene = new THREE.Scene();
		const floor = new THREE.Mesh( new THREE.PlaneGeometry( 20, 20 ).rotateX( - Math.PI / 2 ), new THREE.MeshStandardMaterial( { color: 0xffffff, emissive: 0xff0000, roughness: 1 } ) );
		scene.add( floor );
		const positions = [ - 1, 1, - 1, 1, 1, - 1, - 1, 1, 1, 1, 3, 1 ];
		const sh = new Array( 4 * 27 ).fill( 0 ).map( ( _, k ) => ( k % 27 === 1 ? 50 : 0 ) ); // bright green ambient
		const volume = new LightProbeVolume( { positions, sh } );
		volume.add( floor, { mode: 'vertex' } );
		await volume.capture( renderer, scene, { resolution: 8, type: THREE.FloatType } );
		const l00 = volume.sh.slice( 0, 3 );
		expect( l00[ 0 ] ).toBeGreaterThan( 0.5 ); // red floor seen
		expect( l00[ 1 ] ).toBeLessThan( 1e-3 ); // not its green probe light
		const lighting = volume.getUniforms( floor )!;
		expect( lighting.probeVolumeIntensity.value ).toBe( 1 ); // restored after the capture
		volume.remove( floor );
		volume.add( floor ); // now a visitor: hidden from captures
		await volume.capture( renderer, scene, { resolution: 8, type: THREE.FloatType } );
		expect( volume.sh[ 0 ] ).toBe( 0 );
		volume.dispose();
		floor.geometry.dispose();

	} );

	it( 'texture mode (half-float 3D texture, hardware trilinear): every sample point within 2/255 of the reference', () => {

		const volume = fieldVolume();
		const floor = floorMesh();
		const lighting = new ProbeTextureLighting( floor, volume, { resolution: [ 8, 2, 8 ] } );
		const image = render( floor );
		const worst = worstAgainstReference( image );
		if ( worst > 2 ) writePNG( path.join( OUTPUT_DIR, 'largeObjects.texture.png' ), image );
		expect( worst ).toBeLessThanOrEqual( 2 );
		// Moving the floor moves the texture with it: the light is the field's at the new place.
		floor.position.x = 2;
		lighting.update();
		const moved = render( floor );
		const want = expected( 5.7, - 2.2 ), got = floorPixel( moved, camera, 5.7, - 2.2 );
		for ( let c = 0; c < 3; c ++ ) expect( Math.abs( got[ c ] - want[ c ] ) ).toBeLessThanOrEqual( 2 );
		lighting.dispose();

	} );

	it( 'texture mode, float texels: rendered only where OES_texture_float_linear exists (else it samples black)', () => {

		const linear = renderer.extensions.has( 'OES_texture_float_linear' );
		const volume = fieldVolume();
		const floor = floorMesh();
		const lighting = new ProbeTextureLighting( floor, volume, { resolution: [ 8, 2, 8 ], type: 'float' } );
		const image = render( floor );
		if ( linear ) expect( worstAgainstReference( image ) ).toBeLessThanOrEqual( 2 );
		else console.warn( 'largeObjects: this GL has no OES_texture_float_linear; float texels not rendered' );
		lighting.dispose();

	} );

	it( 'three\'s own light-probe-grid path (toLightProbeGrid, unpatched material) renders the same floor as our texture path, within 2/255', () => {

		const volume = fieldVolume();
		const ours = floorMesh();
		const lighting = new ProbeTextureLighting( ours, volume, { resolution: [ 8, 2, 8 ] } );
		const oursImage = render( ours );

		const plain = floorMesh();
		const texture = new ProbeVolumeTexture( volume, new THREE.Box3().setFromObject( plain ), { resolution: [ 8, 2, 8 ] } );
		const grid = toLightProbeGrid( texture );
		const threeImage = render( plain, grid );
		const result = compareImages( oursImage, threeImage, 2 );
		if ( result.count > 0 ) {

			writePNG( path.join( OUTPUT_DIR, 'largeObjects.grid.ours.png' ), oursImage );
			writePNG( path.join( OUTPUT_DIR, 'largeObjects.grid.three.png' ), threeImage );

		}

		expect( result.count, `max ${result.max} at ${result.at}` ).toBe( 0 );
		expect( worstAgainstReference( threeImage ) ).toBeLessThanOrEqual( 2 );
		lighting.dispose();
		texture.dispose();
		grid.dispose();

	} );

	it( 'a mesh with zero normals (normalize → NaN on the GPU) gets the direction-free part of the probe light, not NaN/black — vertex SH and texture modes (the object mode, like three\'s LightProbe, has no guard: it would cost its frame time)', () => {

		// Probes holding L00 only: E is the same for every normal, so the direction-free fallback
		// must render what a mesh with proper normals renders.
		const positions = [ - 12, - 2, - 12, 12, - 2, - 12, - 12, 4, 12, 12, 4, 12, 0, 1, 0, - 12, 4, - 12 ];
		const sh = new Array( 27 * 6 ).fill( 0 ).map( ( _, k ) => ( k % 27 < 3 ? 1.2 + 0.3 * ( k % 27 ) : 0 ) );
		const reference = floorMesh();
		const volume = new LightProbeVolume( { positions, sh } );
		volume.add( reference );
		volume.update();
		const want = floorPixel( render( reference ), camera, 0, 0 );
		volume.remove( reference );
		expect( Math.max( ...want ) ).toBeGreaterThan( 40 );
		for ( const mode of [ 'vertex', 'texture' ] as const ) {

			const floor = floorMesh();
			( floor.geometry.getAttribute( 'normal' ).array as Float32Array ).fill( 0 );
			volume.add( floor, { mode, vertexOutput: 'sh' } );
			volume.update();
			const got = floorPixel( render( floor ), camera, 0, 0 );
			// Measured (with the guard in the object mode too, since removed): 152/168/182 against
			// 156/173/188, and black (0/0/0) without it. The few percent left are three's own
			// normal-dependent terms (its energy compensation uses dot( normal, view ), here NaN).
			for ( let c = 0; c < 3; c ++ ) expect( Math.abs( got[ c ] - want[ c ] ), `${mode} mode, channel ${c}` ).toBeLessThanOrEqual( 0.05 * want[ c ] );
			volume.remove( floor );
			floor.geometry.dispose();

		}

		reference.geometry.dispose();

	} );

	it( 'two objects in the same mode share one program (texture, vertex irradiance, vertex SH)', () => {

		const volume = fieldVolume();
		const setups: [ string, ( mesh: THREE.Mesh ) => { dispose(): void } ][] = [
			[ 'texture', ( mesh ) => new ProbeTextureLighting( mesh, volume, { resolution: 4 } ) ],
			[ 'vertex irradiance', ( mesh ) => new ProbeVertexLighting( mesh, volume ) ],
			[ 'vertex sh', ( mesh ) => new ProbeVertexLighting( mesh, volume, { output: 'sh' } ) ],
		];
		for ( const [ name, make ] of setups ) {

			const a = floorMesh(), b = floorMesh();
			b.position.z = 30;
			const la = make( a ), lb = make( b );
			const before = renderer.info.programs!.length;
			render( a ); render( b );
			expect( renderer.info.programs!.length - before, name ).toBe( 1 );
			la.dispose(); lb.dispose();

		}

	} );

} );
