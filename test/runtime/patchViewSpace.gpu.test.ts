/**
 * The object mode evaluates the probe term for the view-space normal, with coefficients made per
 * draw from the camera (src/runtime/viewIrradiance.ts): images from cameras turned every way —
 * looking along each axis, rolled, under a rotated parent, two views of one ArrayCamera in one
 * render — compared with the same spheres lit by three's LightProbe, which evaluates the world
 * normal. headless-gl, WebGL2; "1/255" is one step of the 8-bit sRGB output.
 */

import * as path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { OUTPUT_DIR, compareImages, diffImage, renderToImage, writePNG, type Image8 } from '../helpers/gpuScenes.js';

const SIZE = 128;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** Light that differs along every axis and band: warm from −x, blue from above, green from +z. */
const SKY: number[] = [
	1.5, 1.35, 1.2, 0.45, 0.52, 0.75, 0.3, 0.1, - 0.15, - 0.38, 0.15, 0.3,
	0.15, - 0.08, 0.08, 0.08, 0.15, - 0.08, - 0.15, 0.08, 0.15, 0.12, - 0.09, 0.06, 0.18, 0.0, - 0.12,
];
const POSITIONS = [ - 10, - 8, - 9, 11, - 9, - 8, 0, 12, - 10, 1, - 1, 12, - 2, 10, 9 ];

function repeatSH( sh: readonly number[], count: number ): Float32Array {

	const result = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) result.set( sh, 27 * i );
	return result;

}

/** A camera at `position` looking at the origin with `up`, optionally under a parent. */
function camera( position: THREE.Vector3Like, up: THREE.Vector3Like = { x: 0, y: 1, z: 0 } ): THREE.PerspectiveCamera {

	const result = new THREE.PerspectiveCamera( 50, 1, 0.05, 100 );
	result.position.copy( position );
	result.up.copy( up );
	result.lookAt( 0, 0, 0 );
	result.updateMatrixWorld();
	return result;

}

describe.skipIf( ! ctx.renderer )( `object mode in view space = three's LightProbe in world space${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;
	afterAll( () => ctx.dispose() );

	/** Spheres lit by a volume of SKY probes (per pixel or per vertex) and the same lit by LightProbe( SKY ). */
	function scenes( perVertex: boolean ) {

		const geometry = new THREE.SphereGeometry( 0.45, perVertex ? 128 : 48, perVertex ? 64 : 24 );
		const materials = [
			new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } ),
			new THREE.MeshStandardMaterial( { color: 0xff9966, roughness: 0.5, metalness: 0.3 } ),
			new THREE.MeshPhongMaterial( { color: 0xccddff, shininess: 10 } ),
			new THREE.MeshLambertMaterial( { color: 0xffffff } ),
		];
		// At the corners of a tetrahedron: seen along any axis, the spheres do not hide each other.
		const corners = [ [ 0.5, 0.5, 0.5 ], [ - 0.5, - 0.5, 0.5 ], [ - 0.5, 0.5, - 0.5 ], [ 0.5, - 0.5, - 0.5 ] ];
		const place = ( mesh: THREE.Mesh, i: number ) => mesh.position.fromArray( corners[ i ] );
		const volume = new LightProbeVolume( { positions: POSITIONS, sh: repeatSH( SKY, 5 ) } );
		const lit = new THREE.Scene(), reference = new THREE.Scene();
		materials.forEach( ( material, i ) => {

			const mesh = new THREE.Mesh( geometry, material );
			place( mesh, i );
			lit.add( mesh );
			volume.add( mesh, { perVertex } );
			const twin = new THREE.Mesh( geometry, material.clone() );
			place( twin, i );
			reference.add( twin );

		} );
		reference.add( new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( SKY ) ) );
		volume.update();
		const dispose = () => {

			volume.dispose();
			geometry.dispose();
			const disposeMaterial = ( o: THREE.Object3D ) => ( ( o as THREE.Mesh ).material as THREE.Material | undefined )?.dispose();
			for ( const scene of [ lit, reference ] ) scene.traverse( disposeMaterial );

		};

		return { lit, reference, dispose };

	}

	function compare( name: string, lit: THREE.Scene, reference: THREE.Scene, view: THREE.Camera, tolerance: number ) {

		const actual = renderToImage( renderer, gl, lit, view ), expected = renderToImage( renderer, gl, reference, view );
		const result = compareImages( actual, expected, tolerance );
		let message = '';
		if ( result.count > 0 ) {

			const save = ( suffix: string, image: Image8 ) => writePNG( path.join( OUTPUT_DIR, `view-space-${name}.${suffix}.png` ), image );
			save( 'actual', actual );
			save( 'expected', expected );
			save( 'diff', diffImage( actual, expected ) );
			message = `${name}: ${result.count} pixels differ by > ${tolerance}/255 (max ${result.max}); images in test/output/view-space-${name}.*.png`;

		}

		let covered = 0;
		const data = expected.data;
		for ( let p = 0; p < SIZE * SIZE; p ++ ) if ( data[ 4 * p ] + data[ 4 * p + 1 ] + data[ 4 * p + 2 ] > 0 ) covered ++;
		return { ...result, message, covered };

	}

	// Each view sees the spheres from a side where a wrong rotation shows: the light's colours come
	// from fixed world directions (warm −x, blue +y, green +z), so evaluating the view-space normal
	// as if it were the world normal, or rotating it the wrong way (Rᵀ for R), paints the wrong
	// side in the wrong colour, many steps off. Equal light at every pixel is only float rounding
	// of two evaluation orders (the matrices' and the SH's): ≤ 1/255, as in volume.gpu.test.ts.
	const views: [ string, () => THREE.Camera ][] = [
		[ 'from +x', () => camera( { x: 3.2, y: 0, z: 0 } ) ],
		[ 'from below, up +z', () => camera( { x: 0, y: - 3.2, z: 0 }, { x: 0, y: 0, z: 1 } ) ],
		[ 'from behind (−z)', () => camera( { x: 0.4, y: 0.3, z: - 3.2 } ) ],
		[ 'oblique, rolled 70°', () => camera( { x: 1.9, y: 1.7, z: 1.9 }, { x: Math.sin( 1.2 ), y: Math.cos( 1.2 ), z: 0 } ) ],
		[ 'under a rotated parent', () => {

			const parent = new THREE.Group();
			parent.rotation.set( 0.7, - 1.9, 0.4 );
			const child = new THREE.PerspectiveCamera( 50, 1, 0.05, 100 );
			child.position.set( 0, 0, 3.2 );
			parent.add( child );
			parent.updateMatrixWorld( true );
			return child;

		} ],
	];

	it( 'per pixel: five views turned every way, each ≤ 1/255 of the LightProbe image', () => {

		const { lit, reference, dispose } = scenes( false );
		const results = views.map( ( [ name, make ] ) => ( { name, ...compare( name.replace( /\W+/g, '-' ), lit, reference, make(), 1 ) } ) );
		dispose();
		for ( const result of results ) {

			expect( result.count, result.message ).toBe( 0 );
			expect( result.covered, `${result.name}: spheres in view` ).toBeGreaterThan( 0.15 * SIZE * SIZE );

		}

		expect( gl.getError() ).toBe( gl.NO_ERROR );

	} );

	it( 'per vertex (perVertex: true, 128 × 64 spheres): the rolled and the parented views ≤ 2/255 of the per-pixel LightProbe', () => {

		// Per vertex, E is interpolated across triangles: ≈ 6e-4 in linear light on this sphere,
		// within one more rounding step (volume.gpu.test.ts) — wrong rotations are many steps off.
		const { lit, reference, dispose } = scenes( true );
		const results = [ views[ 3 ], views[ 4 ] ].map( ( [ name, make ] ) => compare( `vertex-${name.replace( /\W+/g, '-' )}`, lit, reference, make(), 2 ) );
		dispose();
		for ( const result of results ) expect( result.count, result.message ).toBe( 0 );

	} );

	it( 'one ArrayCamera, two differently turned views side by side in one render: each half ≤ 1/255 (the coefficients follow the camera of each draw)', () => {

		const { lit, reference, dispose } = scenes( false );
		const left = camera( { x: - 2.5, y: 1.5, z: 1.5 }, { x: 0.3, y: 1, z: 0 } ), right = camera( { x: 1.5, y: - 2, z: - 2.2 } );
		for ( const [ sub, x ] of [ [ left, 0 ], [ right, SIZE / 2 ] ] as const ) {

			sub.aspect = 0.5;
			sub.updateProjectionMatrix();
			( sub as THREE.PerspectiveCamera & { viewport: THREE.Vector4 } ).viewport = new THREE.Vector4( x, 0, SIZE / 2, SIZE );

		}

		const array = new THREE.ArrayCamera( [ left, right ] );
		array.updateMatrixWorld();
		const result = compare( 'array-camera', lit, reference, array, 1 );
		dispose();
		expect( result.count, result.message ).toBe( 0 );
		expect( result.covered ).toBeGreaterThan( 0.15 * SIZE * SIZE );

	} );

} );
