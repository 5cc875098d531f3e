/**
 * LightProbeVolume and patched materials on a real GL context (headless-gl, WebGL2): images
 * compared against three.js's own LightProbe, probe blending, the paper's Basic scene (with one
 * golden image), skinning, program sharing, material bookkeeping and GPU resource lifetime.
 *
 * Images are rendered to the default framebuffer (sRGB output, as on a page) and read back as
 * RGBA8; "1/255" below means one step of that 8-bit sRGB value per channel.
 *
 * Needs an X display for headless-gl: `node scripts/test.mjs test/runtime` runs it under xvfb-run.
 */

import * as fs from 'node:fs';
import * as path from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { getProbeVolumeUniforms, patchMaterial } from '../../src/runtime/patchMaterial.js';
import { evaluateIrradiance, irradianceMatrices } from '../../src/sh/index.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import {
	OUTPUT_DIR, REPO_ROOT, averageColor, compareImages, diffImage, disposeMesh, projectToImage, readPNG, renderToImage, writePNG,
	type Image8,
} from '../helpers/gpuScenes.js';

const SIZE = 128;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/**
 * A sky-like SH with real directional variation in all bands and channels: bluish from above
 * (+y), warm from −x, a little green from +z. Its irradiance stays in (0.2, 2.5) over all normals
 * (checked below), so a white diffuse surface (E/π) is neither black nor clipped in 8 bits.
 */
const SKY: number[] = [
	1.5, 1.35, 1.2, // L00
	0.45, 0.52, 0.75, // L1−1 (y)
	0.3, 0.1, - 0.15, // L10 (z)
	- 0.38, 0.15, 0.3, // L11 (x)
	0.15, - 0.08, 0.08, // L2−2
	0.08, 0.15, - 0.08, // L2−1
	- 0.15, 0.08, 0.15, // L20
	0.12, - 0.09, 0.06, // L21
	0.18, 0.0, - 0.12, // L22
];

/** `count` probes all carrying `sh`. */
function repeatSH( sh: ArrayLike<number>, count: number ): Float32Array {

	const result = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) result.set( Array.from( sh ), 27 * i );
	return result;

}

/** A probe layout around everything the tests render: a large irregular double tetrahedron. */
const WIDE_POSITIONS = [ - 10, - 8, - 9, 11, - 9, - 8, 0, 12, - 10, 1, - 1, 12, - 2, 10, 9 ];

function lightProbe( sh: ArrayLike<number> ): THREE.LightProbe {

	return new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( Array.from( sh ) ) );

}

function camera( position: THREE.Vector3Like, target: THREE.Vector3Like = { x: 0, y: 0, z: 0 }, fov = 45 ): THREE.PerspectiveCamera {

	const result = new THREE.PerspectiveCamera( fov, 1, 0.05, 100 );
	result.position.copy( position );
	result.lookAt( target.x, target.y, target.z );
	result.updateMatrixWorld();
	return result;

}

/** Pixels covered by something (not the black clear colour). */
function covered( image: Image8 ): number {

	let n = 0;
	for ( let p = 0; p < image.width * image.height; p ++ ) if ( image.data[ 4 * p ] + image.data[ 4 * p + 1 ] + image.data[ 4 * p + 2 ] > 0 ) n ++;
	return n;

}

function saveFailure( name: string, actual: Image8, expected: Image8 ): string {

	writePNG( path.join( OUTPUT_DIR, `${name}.actual.png` ), actual );
	writePNG( path.join( OUTPUT_DIR, `${name}.expected.png` ), expected );
	writePNG( path.join( OUTPUT_DIR, `${name}.diff.png` ), diffImage( actual, expected ) );
	return `images in test/output/${name}.{actual,expected,diff}.png`;

}

describe.skipIf( ! ctx.renderer )( `LightProbeVolume on a real GL context (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;

	afterAll( () => ctx.dispose() );

	/** Renders the volume-lit scene and the LightProbe-lit scene and compares them. */
	function compareWithLightProbe( name: string, volumeScene: THREE.Scene, referenceScene: THREE.Scene, view: THREE.Camera, tolerance: number ) {

		const actual = renderToImage( renderer, gl, volumeScene, view );
		const expected = renderToImage( renderer, gl, referenceScene, view );
		const result = compareImages( actual, expected, tolerance );
		const message = result.count > 0 ? `${result.count} pixels differ by > ${tolerance}/255 (max ${result.max} at ${result.at}); ${saveFailure( name, actual, expected )}` : '';
		return { actual, expected, ...result, message };

	}

	it( 'the SKY fixture is a sensible light: irradiance in (0.2, 2.5) for every normal', () => {

		let min = Infinity, max = - Infinity;
		for ( let i = 0; i < 2000; i ++ ) {

			const z = 2 * ( ( i + 0.5 ) / 2000 ) - 1, phi = i * 2.399963, r = Math.sqrt( 1 - z * z );
			const e = evaluateIrradiance( SKY, [ r * Math.cos( phi ), r * Math.sin( phi ), z ] );
			min = Math.min( min, ...e );
			max = Math.max( max, ...e );

		}

		expect( min ).toBeGreaterThan( 0.2 );
		expect( max ).toBeLessThan( 2.5 );

	} );

	describe( 'equivalence with three.js\'s LightProbe', () => {

		/** Six spheres: Standard and Physical, several roughness / metalness / colours / extras. */
		function makeMaterials(): THREE.MeshStandardMaterial[] {

			return [
				new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1, metalness: 0 } ),
				new THREE.MeshStandardMaterial( { color: 0xff8844, roughness: 0.3, metalness: 0.5 } ),
				new THREE.MeshStandardMaterial( { color: 0x88ccff, roughness: 0.6, metalness: 1 } ),
				new THREE.MeshPhysicalMaterial( { color: 0xffffff, roughness: 0.4, clearcoat: 1, clearcoatRoughness: 0.2 } ),
				new THREE.MeshPhysicalMaterial( { color: 0x44ff88, roughness: 0.8, sheen: 1, sheenColor: 0xff00ff, sheenRoughness: 0.5 } ),
				new THREE.MeshPhysicalMaterial( { color: 0xcccccc, roughness: 0.1, metalness: 0.2, ior: 1.8, specularIntensity: 0.5, iridescence: 0.5 } ),
			];

		}

		function makeSpheres( materials: THREE.Material[], geometry: THREE.BufferGeometry ): THREE.Mesh[] {

			return materials.map( ( material, i ) => {

				const mesh = new THREE.Mesh( geometry, material );
				mesh.position.set( ( i % 3 - 1 ) * 1.1, ( Math.floor( i / 3 ) - 0.5 ) * 1.1, 0 );
				return mesh;

			} );

		}

		it( 'per pixel: 3 MeshStandardMaterial + 3 MeshPhysicalMaterial spheres lit by a volume whose probes all carry SKY look exactly as lit by a LightProbe with SKY (≤ 1/255)', () => {

			// Why equal: with every probe = SKY and weights summing to 1, the blended SH is SKY
			// (to float rounding), and the patch adds nᵀMn = E(n) — the same irradiance three's
			// LightProbe adds (shGetIrradianceAt), at the same place (`irradiance` before
			// RE_IndirectDiffuse) and in the same world-normal space. Only float evaluation order
			// differs, which can move a value across an 8-bit rounding edge: hence 1/255. A
			// missing π, a transposed matrix, view- instead of world-space normals or a wrong
			// channel changes most pixels by ≫ 1/255.
			const geometry = new THREE.SphereGeometry( 0.5, 64, 32 );
			const materials = makeMaterials();
			const references = materials.map( ( m ) => m.clone() );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const volumeScene = new THREE.Scene(), referenceScene = new THREE.Scene();
			for ( const mesh of makeSpheres( materials, geometry ) ) { volumeScene.add( mesh ); volume.add( mesh ); }
			referenceScene.add( ...makeSpheres( references, geometry ), lightProbe( SKY ) );
			volume.update();

			const result = compareWithLightProbe( 'equivalence-pixel', volumeScene, referenceScene, camera( { x: 0.3, y: 0.8, z: 4.5 } ), 1 );
			volume.dispose();
			geometry.dispose();
			for ( const m of [ ...materials, ...references ] ) m.dispose();

			expect( result.count, result.message ).toBe( 0 );
			expect( covered( result.expected ) ).toBeGreaterThan( 0.25 * SIZE * SIZE ); // not an empty picture
			expect( gl.getError() ).toBe( gl.NO_ERROR );

		} );

		it( 'per vertex on a finely tessellated sphere (128×64) matches the per-pixel LightProbe within 2/255; on a coarse one (8×4) it visibly does not (the mode is really per vertex)', () => {

			// Per vertex, E(n) is evaluated at the vertices and interpolated linearly across each
			// triangle. E is quadratic in n, so the interpolation error is ≈ (edge angle)²/8 ·
			// |∂²E| ≈ (π/64)²/8 · 2 ≈ 6e-4 in linear light for 128×64, under one 8-bit sRGB step for
			// mid tones; 2/255 leaves room for the additional rounding edge. On an 8×4 sphere the
			// edges span 45° and the error is several steps.
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const view = camera( { x: 0, y: 0.5, z: 2.2 } );
			const results: { max: number; count: number; message: string }[] = [];
			for ( const [ widthSegments, heightSegments ] of [ [ 128, 64 ], [ 8, 4 ] ] ) {

				const geometry = new THREE.SphereGeometry( 0.6, widthSegments, heightSegments );
				const material = new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } );
				const reference = material.clone();
				const mesh = new THREE.Mesh( geometry, material );
				const volumeScene = new THREE.Scene().add( mesh );
				volume.add( mesh, { perVertex: true } );
				volume.update();
				const referenceScene = new THREE.Scene().add( new THREE.Mesh( geometry, reference ), lightProbe( SKY ) );
				results.push( compareWithLightProbe( `equivalence-vertex-${widthSegments}`, volumeScene, referenceScene, view, 2 ) );
				volume.remove( mesh );
				geometry.dispose();
				material.dispose();
				reference.dispose();

			}

			expect( results[ 0 ].count, results[ 0 ].message ).toBe( 0 );
			expect( results[ 0 ].max, 'fine sphere' ).toBeLessThanOrEqual( 2 );
			expect( results[ 1 ].max, 'coarse sphere' ).toBeGreaterThan( 4 );

		} );

	} );

	describe( 'blending between probes', () => {

		// A bipyramid: two probes 0.6 apart on the x axis and a ring of three around them. Its
		// Delaunay tetrahedralization has the three cells around the edge p0–p1 (the ring is far
		// out, so p0 and p1 are Delaunay neighbours), so the origin is on that edge, halfway.
		const positions = [ - 0.3, 0, 0, 0.3, 0, 0, 0, 1, 0, 0, - 0.5, 0.866, 0, - 0.5, - 0.866 ];
		const RED = SKY.map( ( v, i ) => i % 3 === 0 ? v * 1.6 : v * 0.4 );
		const BLUE = SKY.map( ( v, i ) => i % 3 === 2 ? v * 1.4 : v * 0.3 ).map( ( v, i ) => i >= 3 && i < 12 ? - v : v );
		const GREEN = SKY.map( ( v, i ) => i % 3 === 1 ? v * 5 : 0 ); // on the ring: must get zero weight
		const AVERAGE = RED.map( ( v, i ) => ( v + BLUE[ i ] ) / 2 );
		const sh = new Float32Array( [ ...RED, ...BLUE, ...GREEN, ...GREEN, ...GREEN ] );

		it( 'an object halfway between two probes gets their average: volume.sample, its uniforms = irradianceMatrices( average ), and its pixels = a LightProbe with the average (≤ 1/255)', () => {

			// Barycentric weights on the edge are (½, ½, 0, 0); blending is linear, so the object's
			// SH is (RED + BLUE) / 2 and its matrices those of that SH (irradianceMatrices is linear
			// too). The ring probes are bright green: any weight on them shows.
			const volume = new LightProbeVolume( { positions, sh } );
			const geometry = new THREE.SphereGeometry( 0.5, 64, 32 );
			const material = new THREE.MeshStandardMaterial( { roughness: 0.7 } );
			const reference = material.clone();
			const mesh = new THREE.Mesh( geometry, material );
			const volumeScene = new THREE.Scene().add( mesh );
			volume.add( mesh );
			volume.update();

			const sampled = volume.sample( new THREE.Vector3( 0, 0, 0 ) );
			for ( let i = 0; i < 27; i ++ ) expect( sampled[ i ] ).toBeCloseTo( AVERAGE[ i ], 6 );
			const matrices = volume.getUniforms( mesh )!.probeVolumeMatrices.value;
			const expectedMatrices = irradianceMatrices( AVERAGE );
			for ( let i = 0; i < 48; i ++ ) expect( matrices[ i ] ).toBeCloseTo( expectedMatrices[ i ], 6 );

			const referenceScene = new THREE.Scene().add( new THREE.Mesh( geometry, reference ), lightProbe( AVERAGE ) );
			const result = compareWithLightProbe( 'blend-halfway', volumeScene, referenceScene, camera( { x: 0.4, y: 0.6, z: 1.8 } ), 1 );
			// …and it is not simply one of the two probes.
			const onlyRed = renderToImage( renderer, gl, new THREE.Scene().add( new THREE.Mesh( geometry, reference ), lightProbe( RED ) ), camera( { x: 0.4, y: 0.6, z: 1.8 } ) );
			volume.dispose();
			geometry.dispose();
			material.dispose();
			reference.dispose();

			expect( result.count, result.message ).toBe( 0 );
			expect( compareImages( result.actual, onlyRed ).max ).toBeGreaterThan( 20 );

		} );

		it( 'moving the object along the edge moves its SH linearly (¼ of the way: ¾ RED + ¼ BLUE)', () => {

			const volume = new LightProbeVolume( { positions, sh } );
			const object = new THREE.Mesh( new THREE.SphereGeometry( 0.1 ), new THREE.MeshStandardMaterial() );
			volume.add( object );
			object.position.set( - 0.15, 0, 0 );
			volume.update();
			const expected = irradianceMatrices( RED.map( ( v, i ) => 0.75 * v + 0.25 * BLUE[ i ] ) );
			const actual = volume.getUniforms( object )!.probeVolumeMatrices.value;
			for ( let i = 0; i < 48; i ++ ) expect( actual[ i ] ).toBeCloseTo( expected[ i ], 6 );
			volume.dispose();
			disposeMesh( object );

		} );

	} );

	describe( 'the paper\'s Basic scene: a room with red, green and blue walls', () => {

		// Room x ∈ [−2, 2], y ∈ [0, 3], z ∈ [−2, 2]. Walls (MeshStandardMaterial, matte): −x red,
		// +x green, −z blue, floor, ceiling and +z white-grey. A point light under the ceiling
		// lights the walls; a white emissive panel on the ceiling is the visible lamp.
		// The camera stands near the +z wall looking towards −z: red wall on the LEFT of the
		// image, green on the RIGHT, blue at the back. A white matte sphere floats near the red
		// wall, left of centre; it is registered with the volume, so it is lit only by the probes
		// (plus the point light's direct term) and is hidden from the capture.
		const PROBES = [
			0, 2.8, 0, // sky
			- 1.7, 0.2, - 1.7, 1.7, 0.2, - 1.7, - 1.7, 0.2, 1.7, 1.7, 0.2, 1.7, 0, 0.2, 0, // bounce
			- 1.8, 1.3, 0, 1.8, 1.3, 0, 0, 1.3, - 1.8, // bleed: red, green, blue
			0, 1.5, 1.8, - 1.7, 2.7, - 1.7, 1.7, 2.7, 1.7, 1.7, 2.7, - 1.7, // fill
		];
		const ROLES = [ 'sky', 'bounce', 'bounce', 'bounce', 'bounce', 'bounce', 'bleed', 'bleed', 'bleed', 'fill', 'fill', 'fill', 'fill' ] as const;
		const SPHERE_CENTRE = new THREE.Vector3( - 1.25, 1.2, - 0.4 );
		const SPHERE_RADIUS = 0.4;

		/** The room, captured; `redWall: false` paints the −x wall grey like the floor (a control). */
		async function basicRoom( redWall = true ) {

			const scene = new THREE.Scene();
			const wall = ( color: number ) => new THREE.MeshStandardMaterial( { color, roughness: 1, side: THREE.BackSide } );
			// BoxGeometry groups: +x, −x, +y, −y, +z, −z.
			const walls = [ wall( 0x20c020 ), wall( redWall ? 0xd01818 : 0xbbbbbb ), wall( 0xeeeeee ), wall( 0xbbbbbb ), wall( 0xbbbbbb ), wall( 0x2030d0 ) ];
			const room = new THREE.Mesh( new THREE.BoxGeometry( 4, 3, 4 ), walls );
			room.position.set( 0, 1.5, 0 );
			const lamp = new THREE.Mesh( new THREE.PlaneGeometry( 1.2, 1.2 ), new THREE.MeshStandardMaterial( { color: 0x000000, emissive: 0xffffff, emissiveIntensity: 3 } ) );
			lamp.rotation.x = Math.PI / 2; // facing down
			lamp.position.set( 0, 2.98, 0 );
			const light = new THREE.PointLight( 0xffffff, 8, 0, 2 );
			light.position.set( 0, 2.9, 0 );
			const sphere = new THREE.Mesh( new THREE.SphereGeometry( SPHERE_RADIUS, 64, 32 ), new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } ) );
			sphere.position.copy( SPHERE_CENTRE );
			scene.add( room, lamp, light, sphere );

			const volume = new LightProbeVolume( { positions: PROBES, roles: [ ...ROLES ] } );
			volume.add( sphere );
			await volume.capture( renderer, scene, { resolution: 32 } );
			volume.update();
			const view = camera( { x: 0, y: 1.5, z: 1.9 }, { x: - 0.3, y: 1.2, z: - 2 }, 75 );
			return {
				scene, volume, sphere, light, view,
				dispose() {

					volume.dispose();
					disposeMesh( room );
					disposeMesh( lamp );
					disposeMesh( sphere );

				},
			};

		}

		it( 'capture sees the walls: the red-wall probe gets more red than green or blue, the green-wall probe more green, the blue-wall probe more blue', async () => {

			// Each "bleed" probe is 0.2 from its wall, which fills almost half its view.
			const room = await basicRoom();
			const sh = room.volume.sh;
			room.dispose();
			const l00 = ( probe: number ) => [ sh[ 27 * probe ], sh[ 27 * probe + 1 ], sh[ 27 * probe + 2 ] ];
			const [ red, green, blue ] = [ l00( 6 ), l00( 7 ), l00( 8 ) ];
			expect( red[ 0 ] ).toBeGreaterThan( 1.3 * Math.max( red[ 1 ], red[ 2 ] ) );
			expect( green[ 1 ] ).toBeGreaterThan( 1.3 * Math.max( green[ 0 ], green[ 2 ] ) );
			expect( blue[ 2 ] ).toBeGreaterThan( 1.3 * Math.max( blue[ 0 ], blue[ 1 ] ) );
			// The sky probe sees the lamp: more light from above than from below (L1−1 > 0).
			expect( sh[ 3 ] ).toBeGreaterThan( 0 );

		} );

		/** Probe-lit colour of the sphere's −x side (facing the red wall) and +x side, from pixels. */
		async function sphereSides( redWall: boolean ) {

			const room = await basicRoom( redWall );
			// The point light is switched off for this render so only the probe light (captured
			// with the light on) shades the sphere; the walls then render black, which does not
			// matter here.
			room.light.visible = false;
			const image = renderToImage( renderer, gl, room.scene, room.view );
			const [ cx, cy ] = projectToImage( SPHERE_CENTRE, room.view, SIZE, SIZE );
			const [ ex ] = projectToImage( SPHERE_CENTRE.clone().add( new THREE.Vector3( SPHERE_RADIUS, 0, 0 ) ), room.view, SIZE, SIZE );
			const radius = Math.abs( ex - cx );
			room.dispose();
			return {
				radius,
				left: averageColor( image, cx - 0.6 * radius, cy, 1 ), // −x side, facing the red wall
				right: averageColor( image, cx + 0.6 * radius, cy, 1 ), // +x side, facing the room
			};

		}

		const redness = ( c: number[] ) => c[ 0 ] / ( c[ 1 ] + c[ 2 ] );

		it( 'a white sphere near the red wall: the side facing the wall is redder, R/(G+B), than the opposite side, and redder than with the wall painted grey (probe light only, from pixels)', async () => {

			// Why: the probes next to the red wall captured red light arriving from −x, so the
			// blended E(n) for n = −x is red-heavy while for n = +x (facing the grey floor and
			// ceiling, the green wall far away) it is not. A mirrored x axis anywhere (capture,
			// projection, irradiance matrices, shader normal) would tint the wrong side. The
			// control with the red wall painted grey shows the tint comes from that wall: the
			// wall-facing side loses its red. Measured (llvmpipe): left (117, 103, 99), right
			// (116, 124, 118), grey-wall left (114, 117, 114): both ratios ≈ 1.2; the 1.1 thresholds
			// leave margin for other rasterizers.
			const red = await sphereSides( true );
			const grey = await sphereSides( false );
			const show = ( c: number[] ) => c.map( Math.round ).join( ', ' );
			const message = `red wall: left ${show( red.left )}, right ${show( red.right )}; grey wall: left ${show( grey.left )}`;
			expect( red.radius ).toBeGreaterThan( 5 ); // the sphere is really in view
			expect( red.left[ 0 ] + red.left[ 1 ] + red.left[ 2 ], message ).toBeGreaterThan( 60 ); // and lit
			expect( redness( red.left ), message ).toBeGreaterThan( 1.1 * redness( red.right ) );
			expect( redness( red.left ), message ).toBeGreaterThan( 1.1 * redness( grey.left ) );

		} );

		it( 'golden image test/golden/basic-room.png (128×128): red wall left, blue back, green right, lamp at the top, sphere left of centre with a warm wall-facing side', async () => {

			// What makes the golden right (looked at when it was made, enlarged): the wall on the
			// left of the image is red, the back wall blue, the wall on the right green (the view
			// looks down −z), the floor grey; the white lamp panel shows at the top centre with
			// the ceiling around it dark (the point light sits just under it, grazing the
			// ceiling). The sphere, left of centre in front of the red wall, is white on top where
			// the point light hits it directly, and its left, wall-facing edge is warm grey
			// (≈ 118, 91, 89) while its right edge is neutral (≈ 197, 202, 200) — the probe light
			// carrying the red wall's bleed, as the pixel test above checks numerically.
			// Comparison: ≤ 1 % of pixels may differ by more than 8/255 (other Mesa versions
			// rasterize and round slightly differently), else the actual, expected and a diff
			// image go to test/output/.
			const room = await basicRoom();
			const actual = renderToImage( renderer, gl, room.scene, room.view );
			room.dispose();

			const golden = path.join( REPO_ROOT, 'test/golden/basic-room.png' );
			if ( ! fs.existsSync( golden ) ) {

				writePNG( path.join( OUTPUT_DIR, 'basic-room.actual.png' ), actual );
				throw new Error( 'test/golden/basic-room.png is missing: the render is in test/output/basic-room.actual.png — look at it, and if it is right copy it to test/golden/basic-room.png.' );

			}

			const expected = readPNG( golden );
			const result = compareImages( actual, expected, 8 );
			const message = result.count > 0.01 * SIZE * SIZE ? `${result.count} pixels differ by > 8/255 (max ${result.max}); ${saveFailure( 'basic-room', actual, expected )}` : '';
			expect( result.count, message ).toBeLessThanOrEqual( 0.01 * SIZE * SIZE );

		} );

	} );

	describe( 'skinning, program sharing, instancing', () => {

		/** A cylinder along y with two bones; the upper half follows the upper bone. */
		function skinnedCylinder( material: THREE.Material ) {

			const geometry = new THREE.CylinderGeometry( 0.3, 0.3, 2, 64, 24 );
			const position = geometry.getAttribute( 'position' );
			const skinIndex: number[] = [], skinWeight: number[] = [];
			for ( let i = 0; i < position.count; i ++ ) {

				const w = THREE.MathUtils.clamp( ( position.getY( i ) + 0.2 ) / 0.4, 0, 1 );
				skinIndex.push( 0, 1, 0, 0 );
				skinWeight.push( 1 - w, w, 0, 0 );

			}

			geometry.setAttribute( 'skinIndex', new THREE.Uint16BufferAttribute( skinIndex, 4 ) );
			geometry.setAttribute( 'skinWeight', new THREE.Float32BufferAttribute( skinWeight, 4 ) );
			const root = new THREE.Bone(), upper = new THREE.Bone();
			root.position.y = - 1;
			upper.position.y = 1;
			root.add( upper );
			const mesh = new THREE.SkinnedMesh( geometry, material );
			mesh.add( root );
			mesh.bind( new THREE.Skeleton( [ root, upper ] ) );
			return { mesh, upper };

		}

		it( 'a SkinnedMesh with a moving bone is lit by the probes exactly like by a LightProbe, bent and straight (per pixel ≤ 1/255); per vertex compiles and is close (≤ 3/255)', () => {

			// Same argument as the sphere equivalence; a bent bone rotates the upper half's
			// normals, and the LightProbe reference uses the skinned normals, so a patch that
			// read unskinned normals would differ on the bent half.
			const errors = vi.spyOn( console, 'error' );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const view = camera( { x: 0.5, y: 0.3, z: 3.2 } );
			for ( const perVertex of [ false, true ] ) {

				const lit = skinnedCylinder( new THREE.MeshStandardMaterial( { roughness: 0.9 } ) );
				const reference = skinnedCylinder( new THREE.MeshStandardMaterial( { roughness: 0.9 } ) );
				const volumeScene = new THREE.Scene().add( lit.mesh );
				const referenceScene = new THREE.Scene().add( reference.mesh, lightProbe( SKY ) );
				volume.add( lit.mesh, { perVertex } );
				const images: Image8[] = [];
				for ( const angle of [ 0, 1.1 ] ) {

					lit.upper.rotation.z = reference.upper.rotation.z = angle;
					volume.update();
					const tolerance = perVertex ? 3 : 1;
					const result = compareWithLightProbe( `skinned-${perVertex ? 'vertex' : 'pixel'}-${angle}`, volumeScene, referenceScene, view, tolerance );
					expect( result.count, result.message ).toBe( 0 );
					expect( covered( result.actual ) ).toBeGreaterThan( 500 );
					images.push( result.actual );

				}

				// The bone really moved the mesh.
				expect( compareImages( images[ 0 ], images[ 1 ], 10 ).count ).toBeGreaterThan( 200 );
				volume.remove( lit.mesh );
				disposeMesh( lit.mesh );
				disposeMesh( reference.mesh );

			}

			volume.dispose();
			expect( errors ).not.toHaveBeenCalled();
			errors.mockRestore();
			expect( gl.getError() ).toBe( gl.NO_ERROR );

		} );

		it( '10 probe-lit spheres with their own materials share one shader program (+1 program at most), yet keep their own uniforms', () => {

			// Per-object data lives in uniforms; the patch's program cache key is the same for all
			// per-pixel patched MeshStandardMaterials. Intensities 0.1…1.0 per sphere must still
			// show as 10 different brightnesses (uniforms are per material, not per program).
			const scene = new THREE.Scene();
			const other = new THREE.Mesh( new THREE.BoxGeometry( 0.2, 0.2, 0.2 ), new THREE.MeshBasicMaterial( { color: 0x808080 } ) );
			other.position.set( 0, - 1.2, 0 );
			scene.add( other );
			const view = camera( { x: 0, y: 0, z: 6 } );
			renderToImage( renderer, gl, scene, view );
			const before = renderer.info.programs!.length;

			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const geometry = new THREE.SphereGeometry( 0.25, 32, 16 );
			const spheres: THREE.Mesh[] = [];
			for ( let i = 0; i < 10; i ++ ) {

				const sphere = new THREE.Mesh( geometry, new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } ) );
				sphere.position.set( ( i % 5 - 2 ) * 0.6, i < 5 ? 0.4 : - 0.3, 0 );
				scene.add( sphere );
				volume.add( sphere, { intensity: ( i + 1 ) / 10 } );
				spheres.push( sphere );

			}

			volume.update();
			const image = renderToImage( renderer, gl, scene, view );
			const after = renderer.info.programs!.length;
			const brightness = spheres.map( ( sphere ) => {

				const [ x, y ] = projectToImage( sphere.position, view, SIZE, SIZE );
				const c = averageColor( image, x, y, 1 );
				return c[ 0 ] + c[ 1 ] + c[ 2 ];

			} );
			volume.dispose();
			for ( const sphere of spheres ) ( sphere.material as THREE.Material ).dispose();
			geometry.dispose();
			disposeMesh( other );

			expect( after - before ).toBeLessThanOrEqual( 1 );
			for ( let i = 1; i < 10; i ++ ) expect( brightness[ i ], `sphere ${i} vs ${i - 1}: ${brightness}` ).toBeGreaterThan( brightness[ i - 1 ] + 3 );

		} );

		it( 'volume.add( instancedMesh ) does not throw and warns once (console.warn), however many are added', () => {

			const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const geometry = new THREE.BoxGeometry( 0.1, 0.1, 0.1 );
			const meshes = [ 0, 1, 2 ].map( () => new THREE.InstancedMesh( geometry, new THREE.MeshStandardMaterial(), 4 ) );
			for ( const mesh of meshes ) expect( () => volume.add( mesh ) ).not.toThrow();
			const otherVolume = new LightProbeVolume( { positions: WIDE_POSITIONS } );
			otherVolume.add( new THREE.Group().add( new THREE.InstancedMesh( geometry, new THREE.MeshStandardMaterial(), 2 ) ) );
			const instancingWarnings = warn.mock.calls.filter( ( args ) => String( args[ 0 ] ).includes( 'InstancedMesh' ) );
			warn.mockRestore();

			expect( instancingWarnings.length ).toBe( 1 );
			expect( getProbeVolumeUniforms( meshes[ 0 ].material as THREE.Material ) ).not.toBeNull(); // still lit, as one object
			volume.dispose();
			otherVolume.dispose();
			geometry.dispose();

		} );

	} );

	describe( 'material bookkeeping', () => {

		it( 'a material shared by two added objects is cloned for the second (own uniforms, own light); remove() restores the original and its unlit look', () => {

			// Probe 0 (at the first object) is red, probe 1 (at the second) blue, so the two
			// objects must render in different colours although they started with one material.
			const RED = SKY.map( ( v, i ) => i % 3 === 0 ? v : 0 );
			const BLUE = SKY.map( ( v, i ) => i % 3 === 2 ? v : 0 );
			const positions = [ - 0.8, 0, 0, 0.8, 0, 0, 0, 3, - 1, 0, - 3, - 1, 0, 0, 3 ];
			const volume = new LightProbeVolume( { positions, sh: [ ...RED, ...BLUE, ...SKY, ...SKY, ...SKY ] } );
			const shared = new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } );
			const originalHook = shared.onBeforeCompile;
			const geometry = new THREE.SphereGeometry( 0.35, 32, 16 );
			const a = new THREE.Mesh( geometry, shared ), b = new THREE.Mesh( geometry, shared );
			a.position.set( - 0.8, 0, 0 );
			b.position.set( 0.8, 0, 0 );
			const scene = new THREE.Scene().add( a, b );
			volume.add( a ).add( b );
			volume.update();

			expect( a.material ).toBe( shared );
			expect( b.material ).not.toBe( shared );
			expect( getProbeVolumeUniforms( b.material as THREE.Material ) ).toBe( volume.getUniforms( b ) );
			expect( getProbeVolumeUniforms( shared ) ).toBe( volume.getUniforms( a ) );
			expect( volume.getUniforms( a ) ).not.toBe( volume.getUniforms( b ) );

			const view = camera( { x: 0, y: 0, z: 3 } );
			const lit = renderToImage( renderer, gl, scene, view );
			const at = ( mesh: THREE.Mesh, image: Image8 ) => {

				const [ x, y ] = projectToImage( mesh.position, view, SIZE, SIZE );
				return averageColor( image, x, y, 1 );

			};

			const litA = at( a, lit ), litB = at( b, lit );
			expect( litA[ 0 ] ).toBeGreaterThan( litA[ 2 ] + 40 ); // a: red
			expect( litB[ 2 ] ).toBeGreaterThan( litB[ 0 ] + 40 ); // b: blue

			const clone = b.material as THREE.Material;
			const disposed = vi.fn();
			clone.addEventListener( 'dispose', disposed );
			volume.remove( b );
			expect( b.material ).toBe( shared );
			expect( disposed ).toHaveBeenCalledTimes( 1 ); // the clone was ours: freed
			volume.remove( a );
			expect( a.material ).toBe( shared );
			expect( getProbeVolumeUniforms( shared ) ).toBeNull();
			expect( shared.onBeforeCompile ).toBe( originalHook );
			expect( volume.getUniforms( a ) ).toBeNull();

			// No lights in the scene: once unpatched, both render black.
			const unlit = renderToImage( renderer, gl, scene, view );
			expect( at( a, unlit ) ).toEqual( [ 0, 0, 0 ] );
			expect( at( b, unlit ) ).toEqual( [ 0, 0, 0 ] );
			volume.dispose();
			geometry.dispose();
			shared.dispose();

		} );

		it( 'remove() then add() to another volume: the object is lit by the new volume\'s probes, not frozen at the old ones', () => {

			// Volume A is all red, volume B all blue; after A.remove( mesh ) and B.add( mesh ) the
			// sphere must render blue. FAILS as of writing (bug in src/runtime/patchMaterial.ts): it stays red: patchMaterial/unpatchMaterial only set
			// material.needsUpdate, and three keeps a per-material map from program cache key to
			// program; the re-patched material has the same key as after its first patch, so
			// three reuses that entry without calling onBeforeCompile again, and the material
			// keeps the uniform objects of its FIRST patch (volume A's, no longer updated).
			// Same volume: remove → move → add freezes the light at the old place the same way.
			const onlyChannel = ( channel: number ) => repeatSH( SKY.map( ( v, i ) => i % 3 === channel ? v : 0 ), 5 );
			const a = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: onlyChannel( 0 ) } );
			const b = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: onlyChannel( 2 ) } );
			const mesh = new THREE.Mesh( new THREE.SphereGeometry( 0.6, 32, 16 ), new THREE.MeshStandardMaterial( { roughness: 1 } ) );
			const scene = new THREE.Scene().add( mesh );
			const view = camera( { x: 0, y: 0, z: 3 } );
			const centre = () => averageColor( renderToImage( renderer, gl, scene, view ), SIZE / 2, SIZE / 2, 2 );

			a.add( mesh );
			const inA = centre();
			a.remove( mesh );
			const removed = centre();
			b.add( mesh );
			b.update();
			const inB = centre();
			b.dispose();
			a.dispose();
			disposeMesh( mesh );

			expect( inA[ 0 ] ).toBeGreaterThan( 100 );
			expect( inA[ 2 ] ).toBe( 0 );
			expect( removed ).toEqual( [ 0, 0, 0 ] );
			expect( inB[ 0 ], `after B.add the sphere is (${inB.map( Math.round )}), expected blue` ).toBe( 0 );
			expect( inB[ 2 ] ).toBeGreaterThan( 100 );

		} );

		it( 'user onBeforeCompile hooks still distinguish programs after patching: a red-tinting and a blue-tinting material stay red and blue', () => {

			// FAILS as of writing (bug in src/runtime/patchMaterial.ts, line 71).
			// patchMaterial documents that a user onBeforeCompile set before patching still runs.
			// three's default customProgramCacheKey is onBeforeCompile.toString(), so unpatched the
			// two hooks below give two programs. The patch's key is previousKey() + suffix, where
			// previousKey is the default method bound to the material — it now stringifies the
			// patch's own wrapper, identical for every patched material, so both materials get
			// one key, three compiles the first hook only, and the blue one renders red.
			const red = ( shader: THREE.WebGLProgramParametersWithUniforms ) => {

				shader.fragmentShader = shader.fragmentShader.replace( '#include <dithering_fragment>', '#include <dithering_fragment>\ngl_FragColor.rgb *= vec3( 1.0, 0.0, 0.0 );' );

			};

			const blue = ( shader: THREE.WebGLProgramParametersWithUniforms ) => {

				shader.fragmentShader = shader.fragmentShader.replace( '#include <dithering_fragment>', '#include <dithering_fragment>\ngl_FragColor.rgb *= vec3( 0.0, 0.0, 1.0 );' );

			};

			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const geometry = new THREE.SphereGeometry( 0.5, 32, 16 );
			const meshes = [ red, blue ].map( ( hook, i ) => {

				const material = new THREE.MeshStandardMaterial( { roughness: 1 } );
				material.onBeforeCompile = hook;
				const mesh = new THREE.Mesh( geometry, material );
				mesh.position.x = i === 0 ? - 0.6 : 0.6;
				return mesh;

			} );
			const scene = new THREE.Scene().add( ...meshes );
			for ( const mesh of meshes ) volume.add( mesh );
			volume.update();
			const view = camera( { x: 0, y: 0, z: 3 } );
			const image = renderToImage( renderer, gl, scene, view );
			const [ left, right ] = meshes.map( ( mesh ) => {

				const [ x, y ] = projectToImage( mesh.position, view, SIZE, SIZE );
				return averageColor( image, x, y, 1 );

			} );
			volume.dispose();
			geometry.dispose();
			for ( const mesh of meshes ) ( mesh.material as THREE.Material ).dispose();

			expect( left[ 0 ] ).toBeGreaterThan( 100 );
			expect( left[ 2 ] ).toBe( 0 );
			expect( right[ 0 ], `the blue-hooked sphere renders (${right.map( Math.round )})` ).toBe( 0 );
			expect( right[ 2 ] ).toBeGreaterThan( 100 );

		} );

		it( 'a material the user patched with patchMaterial is cloned on add(), and the user\'s uniforms are left alone', () => {

			const material = new THREE.MeshStandardMaterial();
			const userUniforms = patchMaterial( material );
			userUniforms.probeVolumeMatrices.value.fill( 0.25 );
			const mesh = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), material );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			volume.add( mesh );
			expect( mesh.material ).not.toBe( material );
			expect( getProbeVolumeUniforms( material ) ).toBe( userUniforms );
			expect( Array.from( userUniforms.probeVolumeMatrices.value ).every( ( v ) => v === 0.25 ) ).toBe( true );
			volume.remove( mesh );
			expect( mesh.material ).toBe( material );
			expect( getProbeVolumeUniforms( material ) ).toBe( userUniforms );
			mesh.geometry.dispose();
			material.dispose();

		} );

		it( 'update() writes into the same uniform arrays (no replacement) the matrices of volume.sample( world position ), also under a moving parent', () => {

			// Allocation is hard to assert in JS; replacing the arrays would be the visible
			// symptom (and would break three's uniform binding), so check identity and values.
			const sh = new Float32Array( 27 * 5 );
			for ( let i = 0; i < sh.length; i ++ ) sh[ i ] = Math.sin( 1.7 * i ) + ( i % 27 < 3 ? 2 : 0 );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh } );
			const parent = new THREE.Group();
			const mesh = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshStandardMaterial() );
			parent.add( mesh );
			volume.add( mesh );
			const uniforms = volume.getUniforms( mesh )!;
			const array = uniforms.probeVolumeMatrices.value;
			const world = new THREE.Vector3();
			for ( const [ px, py, pz, mx ] of [ [ 0, 0, 0, 0 ], [ 1, 2, - 1, 0.5 ], [ - 3, 0.5, 2, - 1 ], [ 4, - 2, 0, 2 ] ] ) {

				parent.position.set( px, py, pz );
				mesh.position.x = mx;
				volume.update();
				expect( uniforms.probeVolumeMatrices.value ).toBe( array );
				expect( volume.getUniforms( mesh ) ).toBe( uniforms );
				mesh.getWorldPosition( world );
				const expected = irradianceMatrices( volume.sample( world ) );
				for ( let i = 0; i < 48; i ++ ) expect( array[ i ] ).toBeCloseTo( expected[ i ], 6 );

			}

			volume.dispose();
			disposeMesh( mesh );

		} );

	} );

	describe( 'GPU resources and context', () => {

		it( 'dispose(): 50 create → capture → dispose cycles leave renderer.info.memory (geometries, textures) and the program count where they started', async () => {

			// LightProbeVolume.capture makes a ProbeCapturer (cube target, projection targets,
			// solid-angle texture, quad geometry, three materials) and disposes it; the baseline is
			// taken after one normal frame and one capture, so three's own lazily created
			// resources (and the scene's geometries) already exist.
			const scene = new THREE.Scene();
			const box = new THREE.Mesh( new THREE.BoxGeometry( 1, 1, 1 ), new THREE.MeshStandardMaterial( { emissive: 0x404040 } ) );
			box.position.set( 0, 0, - 2 );
			scene.add( box, new THREE.AmbientLight( 0xffffff, 0.5 ) );
			const view = camera( { x: 0, y: 0, z: 3 } );
			const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ];
			renderToImage( renderer, gl, scene, view );
			const warmUp = new LightProbeVolume( { positions } );
			await warmUp.capture( renderer, scene, { resolution: 8 } );
			warmUp.dispose();
			renderToImage( renderer, gl, scene, view );
			const baseline = { ...renderer.info.memory, programs: renderer.info.programs!.length };

			for ( let i = 0; i < 50; i ++ ) {

				const volume = new LightProbeVolume( { positions } );
				await volume.capture( renderer, scene, { resolution: 8 + ( i % 3 ) * 4 } );
				volume.dispose();

			}

			renderToImage( renderer, gl, scene, view );
			const after = { ...renderer.info.memory, programs: renderer.info.programs!.length };
			disposeMesh( box );
			expect( after ).toEqual( baseline );

		} );

		it( 'environment check: headless-gl still lacks WEBGL_lose_context, so context loss is tested in the browser suite (test/browser/contextLoss.test.ts)', () => {

			// ProbeCapturer.capture checks isContextLost() between probes and keeps the SH held
			// on loss; exercising that needs WEBGL_lose_context, which headless-gl lacks. If this
			// fails, headless-gl gained the extension: write the real test here.
			expect( gl.getExtension( 'WEBGL_lose_context' ) ).toBeNull();
			expect( gl.getSupportedExtensions() ).not.toContain( 'WEBGL_lose_context' );

		} );

	} );

} );
