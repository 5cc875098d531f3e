/**
 * LightProbeVolumeHelper on a real GL context (headless-gl, WebGL2): the colour of every probe
 * sphere against three's own SphericalHarmonics3 (and against three's LightProbeHelper drawing the
 * same SH), the wireframe and highlight on screen, captures that do not see the helper, and
 * disposal back to the renderer's baseline (memory counters, programs and live GL buffers).
 *
 * Images are rendered to the default framebuffer (sRGB output, as on a page) and read back as
 * RGBA8; "1/255" means one step of that 8-bit value per channel.
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/LightProbeVolumeHelper.gpu.test.ts`.
 */

import * as path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeHelper } from 'three/addons/helpers/LightProbeHelper.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeHelper } from '../../src/runtime/LightProbeVolumeHelper.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { OUTPUT_DIR, projectToImage, renderToImage, writePNG, type Image8 } from '../helpers/gpuScenes.js';

const SIZE = 256;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** Radiance per unit SH coefficient: a white diffuse surface shows E / π, E = 0.886227 L00 + 1.023328 L1·n + … */
const L0 = Math.PI / 0.886227, L1 = Math.PI / ( 2 * 0.511664 ), L2 = Math.PI / ( 2 * 0.429043 );

/**
 * SH9 of a probe from the radiance it gives a white ball: `base` the direction-free part (L00) and
 * optional terms along y, z, x (band 1) and xy (band 2), each as the RGB radiance it adds at n = 1.
 */
function probeSH( base: number[], terms: { y?: number[]; z?: number[]; x?: number[]; xy?: number[] } = {} ): number[] {

	const sh = new Array( 27 ).fill( 0 );
	for ( let c = 0; c < 3; c ++ ) {

		sh[ c ] = base[ c ] * L0;
		sh[ 3 + c ] = ( terms.y?.[ c ] ?? 0 ) * L1;
		sh[ 6 + c ] = ( terms.z?.[ c ] ?? 0 ) * L1;
		sh[ 9 + c ] = ( terms.x?.[ c ] ?? 0 ) * L1;
		sh[ 12 + c ] = ( terms.xy?.[ c ] ?? 0 ) * L2;

	}

	return sh;

}

/** The 2×2×2 volume: a cube of side 2 centred at the origin, probe i at (±1, ±1, ±1), x fastest. */
const CUBE = [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 1, - 1, 1, 1, - 1, - 1, - 1, 1, 1, - 1, 1, - 1, 1, 1, 1, 1, 1 ];

/** Known light per probe: pure colours, and gradients in every band-1 direction and in band 2. */
const CUBE_SH = [
	probeSH( [ 0.8, 0, 0 ] ), // 0: pure red
	probeSH( [ 0, 0, 0.8 ] ), // 1: pure blue
	probeSH( [ 0.4, 0.4, 0.4 ], { y: [ 0.35, 0.35, 0.35 ] } ), // 2: grey, much brighter from above (+y)
	probeSH( [ 0, 0.6, 0 ] ), // 3: pure green
	probeSH( [ 0.45, 0.45, 0.45 ], { x: [ 0.3, 0.1, - 0.2 ] } ), // 4: warm towards +x, cool towards −x
	probeSH( [ 0.5, 0.5, 0.1 ], { xy: [ 0.2, 0.2, 0 ] } ), // 5: yellow, band-2 xy lobes
	probeSH( [ 0.1, 0.5, 0.5 ], { z: [ 0.1, 0.3, 0.3 ] } ), // 6: cyan, brighter towards +z
	probeSH( [ 0.6, 0, 0.6 ] ), // 7: magenta
].flat();

/** An orthographic camera 10 units from the origin along `direction`: every sphere's centre pixel faces it. */
function orthographic( direction: THREE.Vector3, halfSize = 2.3 ): THREE.OrthographicCamera {

	const camera = new THREE.OrthographicCamera( - halfSize, halfSize, halfSize, - halfSize, 0.1, 30 );
	camera.position.copy( direction ).normalize().multiplyScalar( 10 );
	camera.lookAt( 0, 0, 0 );
	camera.updateMatrixWorld();
	return camera;

}

/** The pixel (top-down) holding a world point's projection, and the offset of that pixel's centre from the point in the view plane. */
function pixelAt( point: THREE.Vector3, camera: THREE.OrthographicCamera ): { x: number; y: number; offset: THREE.Vector3 } {

	const [ fx, fy ] = projectToImage( point, camera, SIZE, SIZE );
	const x = Math.floor( fx ), y = Math.floor( fy );
	const right = new THREE.Vector3().setFromMatrixColumn( camera.matrixWorld, 0 );
	const up = new THREE.Vector3().setFromMatrixColumn( camera.matrixWorld, 1 );
	const worldPerPixel = ( camera.right - camera.left ) / SIZE;
	const offset = right.multiplyScalar( ( x + 0.5 - fx ) * worldPerPixel ).addScaledVector( up, - ( y + 0.5 - fy ) * worldPerPixel );
	return { x, y, offset };

}

/** The sphere's normal seen through a view-plane offset from its centre (orthographic: towards the camera, tilted by the offset). */
function normalThrough( offset: THREE.Vector3, radius: number, camera: THREE.Camera ): THREE.Vector3 {

	const back = new THREE.Vector3().setFromMatrixColumn( camera.matrixWorld, 2 );
	const tangent = offset.clone().divideScalar( radius );
	return tangent.addScaledVector( back, Math.sqrt( 1 - tangent.lengthSq() ) ).normalize();

}

/** What three's SphericalHarmonics3 says a white ball shows for normal n, as 8-bit sRGB: E(n) / π, clamped at 0. */
function expectedColor( sh: ArrayLike<number>, probe: number, normal: THREE.Vector3 ): number[] {

	const harmonics = new THREE.SphericalHarmonics3().fromArray( Array.from( sh ).slice( 27 * probe, 27 * probe + 27 ) );
	const e = harmonics.getIrradianceAt( normal, new THREE.Vector3() ).multiplyScalar( 1 / Math.PI ).max( new THREE.Vector3() );
	const srgb = new THREE.Color().setRGB( e.x, e.y, e.z, THREE.LinearSRGBColorSpace ).getRGB( { r: 0, g: 0, b: 0 }, THREE.SRGBColorSpace );
	return [ srgb.r * 255, srgb.g * 255, srgb.b * 255 ];

}

function pixel( image: Image8, x: number, y: number ): number[] {

	const p = 4 * ( y * image.width + x );
	return [ image.data[ p ], image.data[ p + 1 ], image.data[ p + 2 ] ];

}

function largestDifference( a: number[], b: number[] ): number {

	return Math.max( ...a.map( ( v, c ) => Math.abs( v - b[ c ] ) ) );

}

function cubeVolume(): LightProbeVolume {

	return new LightProbeVolume( { positions: CUBE, sh: CUBE_SH } );

}

describe.skipIf( ! ctx.renderer )( `LightProbeVolumeHelper on a real GL context (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;
	// Seen from above, right and front, so that all eight spheres show and none hides another.
	const view = orthographic( new THREE.Vector3( 0.9, 0.55, 1.3 ) );
	const RADIUS = 0.3;

	afterAll( () => ctx.dispose() );

	it( 'the 2×2×2 screenshot: every sphere\'s centre pixel is E(n)/π of its own SH for the normal facing the camera (three\'s SphericalHarmonics3), within 2/255', () => {

		const volume = cubeVolume();
		const helper = new LightProbeVolumeHelper( volume, RADIUS );
		const scene = new THREE.Scene().add( helper );
		const image = renderToImage( renderer, gl, scene, view );
		writePNG( path.join( OUTPUT_DIR, 'LightProbeVolumeHelper/cube.png' ), image );
		// Looked at (test/output/LightProbeVolumeHelper/cube.png, 256², seen from +x +y +z): eight
		// balls at the corners of a faint grey wireframe cube (its 12 edges and the diagonals of its
		// split into tetrahedra), each one flat colour except the gradients: red (probe 0, the far
		// corner, seen in the middle), blue (1, right), green (3, upper right) and magenta (7, the
		// near top corner) flat; the grey one (2, top) bright on top and dark underneath; probe 4
		// (lower left) tan on its +x side and bluish on its −x side; the cyan one (6, upper left)
		// lighter on the side facing +z; the yellow one (5, bottom) lighter and darker in the
		// quadrants of its xy lobes. That is each probe's light on the ball at its own position;
		// the numbers below check it pixel by pixel.
		for ( let i = 0; i < 8; i ++ ) {

			const centre = new THREE.Vector3().fromArray( CUBE, 3 * i );
			const { x, y, offset } = pixelAt( centre, view );
			const expected = expectedColor( CUBE_SH, i, normalThrough( offset, RADIUS, view ) );
			const actual = pixel( image, x, y );
			expect( largestDifference( actual, expected ), `probe ${i} at pixel ${x}, ${y}: ${actual} vs ${expected.map( Math.round )}` ).toBeLessThanOrEqual( 2 );

		}

		// The +y probe: a pixel half a radius above its centre on screen is brighter than one below,
		// each the colour its own normal gives.
		const up = new THREE.Vector3().setFromMatrixColumn( view.matrixWorld, 1 );
		const centre = new THREE.Vector3().fromArray( CUBE, 6 );
		const values = [ 0.5, - 0.5 ].map( ( s ) => {

			const { x, y, offset } = pixelAt( centre.clone().addScaledVector( up, s * RADIUS ), view );
			offset.addScaledVector( up, s * RADIUS );
			return { actual: pixel( image, x, y ), expected: expectedColor( CUBE_SH, 2, normalThrough( offset, RADIUS, view ) ) };

		} );
		expect( values[ 0 ].actual[ 0 ] ).toBeGreaterThan( values[ 1 ].actual[ 0 ] + 40 ); // 0.66 vs 0.37 in linear radiance
		for ( const { actual, expected } of values ) expect( largestDifference( actual, expected ), `${actual} vs ${expected}` ).toBeLessThanOrEqual( 2 );
		helper.dispose();

	} );

	it( 'looks like three\'s LightProbeHelper: the same SH as LightProbes give the same centre pixels (no tone mapping), within 1/255', () => {

		const volume = cubeVolume();
		const helper = new LightProbeVolumeHelper( volume, RADIUS );
		helper.tetrahedra = false;
		const ours = renderToImage( renderer, gl, new THREE.Scene().add( helper ), view );
		const reference = new THREE.Scene();
		const references: LightProbeHelper[] = [];
		for ( let i = 0; i < 8; i ++ ) {

			const probe = new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( CUBE_SH.slice( 27 * i, 27 * i + 27 ) ) );
			probe.position.fromArray( CUBE, 3 * i );
			const probeHelper = new LightProbeHelper( probe, RADIUS );
			references.push( probeHelper );
			reference.add( probeHelper );

		}

		const theirs = renderToImage( renderer, gl, reference, view );
		writePNG( path.join( OUTPUT_DIR, 'LightProbeVolumeHelper/three-LightProbeHelper.png' ), theirs );
		for ( let i = 0; i < 8; i ++ ) {

			const { x, y } = pixelAt( new THREE.Vector3().fromArray( CUBE, 3 * i ), view );
			expect( largestDifference( pixel( ours, x, y ), pixel( theirs, x, y ) ), `probe ${i}` ).toBeLessThanOrEqual( 1 );

		}

		for ( const probeHelper of references ) probeHelper.dispose();
		helper.dispose();

	} );

	it( 'update() after new SH (same probe count): the next render shows them (the buffers are updated in place)', () => {

		const volume = cubeVolume();
		const helper = new LightProbeVolumeHelper( volume, RADIUS );
		helper.tetrahedra = false;
		const scene = new THREE.Scene().add( helper );
		const { x, y, offset } = pixelAt( new THREE.Vector3().fromArray( CUBE, 0 ), view );
		const red = expectedColor( CUBE_SH, 0, normalThrough( offset, RADIUS, view ) ); // as captured first
		expect( largestDifference( pixel( renderToImage( renderer, gl, scene, view ), x, y ), red ) ).toBeLessThanOrEqual( 2 );
		const green = probeSH( [ 0, 0.5, 0 ], { y: [ 0, 0.2, 0 ] } );
		volume.sh.set( green, 0 ); // probe 0 captured again, say
		helper.update();
		const expected = expectedColor( green, 0, normalThrough( offset, RADIUS, view ) );
		expect( largestDifference( pixel( renderToImage( renderer, gl, scene, view ), x, y ), expected ) ).toBeLessThanOrEqual( 2 );
		helper.dispose();

	} );

	it( 'the highlight is drawn in yellow over the cell\'s edges, the wireframe faint grey', () => {

		const volume = cubeVolume();
		const helper = new LightProbeVolumeHelper( volume, 0.1 );
		const scene = new THREE.Scene().add( helper );
		const point = new THREE.Vector3( 0.3, - 0.2, 0.1 );
		helper.highlight( point );
		const image = renderToImage( renderer, gl, scene, view );
		writePNG( path.join( OUTPUT_DIR, 'LightProbeVolumeHelper/highlight.png' ), image );
		const cell = helper.cell;
		expect( cell.probeCount ).toBe( 4 );
		// The midpoint of each highlighted edge is yellow on screen (its line is drawn there, on top:
		// nothing else is in front of it at radius 0.1).
		const probes = Array.from( cell.cellProbes.subarray( 0, 4 ) );
		let yellow = 0;
		for ( let a = 0; a < 4; a ++ ) for ( let b = a + 1; b < 4; b ++ ) {

			const end = new THREE.Vector3().fromArray( CUBE, 3 * probes[ b ] );
			const middle = new THREE.Vector3().fromArray( CUBE, 3 * probes[ a ] ).lerp( end, 0.5 );
			const [ fx, fy ] = projectToImage( middle, view, SIZE, SIZE );
			let found = false;
			for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

				const [ r, g, bl ] = pixel( image, Math.floor( fx ) + dx, Math.floor( fy ) + dy );
				if ( r > 200 && g > 200 && bl < 60 ) found = true;

			}

			if ( found ) yellow ++;

		}

		expect( yellow ).toBe( 6 );
		helper.dispose();

	} );

	it( 'captures do not see the helper: the same SH with it in the scene as without (and different when its cube-camera skip is removed)', async () => {

		// A dim room (an inward box) and, far from the two captured probes, the helper's bright
		// spheres of a second volume whose probes glow white.
		const walls = new THREE.MeshBasicMaterial( { color: 0x202020, side: THREE.BackSide } );
		const room = new THREE.Mesh( new THREE.BoxGeometry( 12, 12, 12 ), walls );
		const scene = new THREE.Scene().add( room );
		const glowing = new LightProbeVolume( { positions: CUBE, sh: Array.from( { length: 8 }, () => probeSH( [ 3, 3, 3 ] ) ).flat() } );
		const helper = new LightProbeVolumeHelper( glowing, 0.9 );
		const capture = async () => {

			const volume = new LightProbeVolume( { positions: [ - 3, 0, 0, 3, 0, 0.5, 0, 3, 0, 0, 0, 3 ] } );
			await volume.capture( renderer, scene, { resolution: 16 } );
			return Array.from( volume.sh );

		};

		const without = await capture();
		scene.add( helper );
		const withHelper = await capture();
		expect( withHelper ).toEqual( without );
		// The control: the same spheres drawn by cube cameras change the SH a lot.
		const skip = helper.probes.onBeforeRender;
		helper.probes.onBeforeRender = () => {};
		const seen = await capture();
		helper.probes.onBeforeRender = skip;
		expect( seen[ 0 ] ).toBeGreaterThan( without[ 0 ] * 1.5 );
		// And the main camera still draws the spheres after the captures.
		const image = renderToImage( renderer, gl, scene, view );
		const { x, y } = pixelAt( new THREE.Vector3().fromArray( CUBE, 21 ), view );
		expect( pixel( image, x, y )[ 0 ] ).toBeGreaterThan( 200 );
		helper.dispose();
		room.geometry.dispose();
		room.material.dispose();

	} );

	it( 'dispose(): renderer.info.memory, the program count and the live GL buffers return to where they were, after edits that grow the buffers', () => {

		const live = { buffers: 0 };
		const createBuffer = gl.createBuffer.bind( gl ), deleteBuffer = gl.deleteBuffer.bind( gl );
		gl.createBuffer = () => { live.buffers ++; return createBuffer(); };
		gl.deleteBuffer = ( buffer ) => { if ( buffer ) live.buffers --; deleteBuffer( buffer ); };
		try {

			const scene = new THREE.Scene();
			const box = new THREE.Mesh( new THREE.BoxGeometry( 1, 1, 1 ), new THREE.MeshBasicMaterial( { color: 0x808080 } ) );
			scene.add( box );
			renderToImage( renderer, gl, scene, view );
			const baseline = { ...renderer.info.memory, programs: renderer.info.programs!.length, buffers: live.buffers };

			for ( let cycle = 0; cycle < 5; cycle ++ ) {

				const volume = cubeVolume();
				const helper = new LightProbeVolumeHelper( volume );
				helper.highlight( new THREE.Vector3( 0.2, 0.1, - 0.3 ) );
				scene.add( helper );
				renderToImage( renderer, gl, scene, view );
				// Edits: the instance buffers grow (8 → 16 slots), the wireframe is rebuilt, a probe is removed.
				for ( let k = 0; k < 3; k ++ ) volume.addProbe( [ 0.3 * k - 0.4, 0.5, 0.2 * k ] );
				volume.removeProbe( 0 );
				helper.update();
				renderToImage( renderer, gl, scene, view );
				expect( renderer.info.memory.geometries ).toBe( baseline.geometries + 3 );
				scene.remove( helper );
				helper.dispose();

			}

			renderToImage( renderer, gl, scene, view );
			const after = { ...renderer.info.memory, programs: renderer.info.programs!.length, buffers: live.buffers };
			box.geometry.dispose();
			box.material.dispose();
			expect( after ).toEqual( baseline );

		} finally {

			gl.createBuffer = createBuffer;
			gl.deleteBuffer = deleteBuffer;

		}

	} );

} );
