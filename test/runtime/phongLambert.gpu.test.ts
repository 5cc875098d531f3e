/**
 * Probe light on `MeshPhongMaterial` (what OBJLoader and MTLLoader make), `MeshLambertMaterial`
 * and `MeshToonMaterial`, on a real GL context (headless-gl, WebGL2).
 *
 * The oracle is three.js's own `LightProbe`: its SH term goes into the same `irradiance` sum of
 * lights_fragment_begin that the patch adds to, and each of these materials hands that sum to its
 * own Lambertian RE_IndirectDiffuse. So a mesh lit by the volume alone must render exactly as the
 * same material lit by a `LightProbe` holding the blended SH; "1/255" is one step of the 8-bit
 * sRGB output per channel (float evaluation order only moves values across rounding edges).
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/phongLambert.gpu.test.ts`.
 */

import * as path from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { captureBounces } from '../../src/runtime/captureBounces.js';
import { getProbeVolumeUniforms } from '../../src/runtime/patchMaterial.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import {
	OUTPUT_DIR, averageColor, compareImages, diffImage, disposeMesh, projectToImage, renderToImage, writePNG, type Image8,
} from '../helpers/gpuScenes.js';

const SIZE = 128;
const ctx = await createHeadlessRenderer( SIZE, SIZE );
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

/** The sky of volume.gpu.test.ts: irradiance in (0.2, 2.5) for every normal, all bands and channels used. */
const SKY: number[] = [
	1.5, 1.35, 1.2, 0.45, 0.52, 0.75, 0.3, 0.1, - 0.15, - 0.38, 0.15, 0.3,
	0.15, - 0.08, 0.08, 0.08, 0.15, - 0.08, - 0.15, 0.08, 0.15, 0.12, - 0.09, 0.06, 0.18, 0.0, - 0.12,
];

/** Probes around everything the sphere tests render (an irregular double tetrahedron). */
const WIDE_POSITIONS = [ - 10, - 8, - 9, 11, - 9, - 8, 0, 12, - 10, 1, - 1, 12, - 2, 10, 9 ];

function repeatSH( sh: readonly number[], count: number ): Float32Array {

	const result = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) result.set( sh, 27 * i );
	return result;

}

function lightProbe( sh: readonly number[] ): THREE.LightProbe {

	return new THREE.LightProbe( new THREE.SphericalHarmonics3().fromArray( [ ...sh ] ) );

}

function camera( position: THREE.Vector3Like, target: THREE.Vector3Like = { x: 0, y: 0, z: 0 }, fov = 45 ): THREE.PerspectiveCamera {

	const result = new THREE.PerspectiveCamera( fov, 1, 0.05, 100 );
	result.position.set( position.x, position.y, position.z );
	result.lookAt( target.x, target.y, target.z );
	result.updateMatrixWorld();
	return result;

}

/** Pixels covered by something (not the black clear colour). */
function covered( image: Image8 ): number {

	let n = 0;
	for ( let p = 0; p < image.width * image.height; p ++ ) {

		if ( image.data[ 4 * p ] + image.data[ 4 * p + 1 ] + image.data[ 4 * p + 2 ] > 0 ) n ++;

	}

	return n;

}

/** Six spheres: Phong (plain, coloured with a strong highlight, flat-shaded), Lambert (two), Toon. */
function makeMaterials(): THREE.Material[] {

	return [
		new THREE.MeshPhongMaterial( { color: 0xffffff, specular: 0x111111, shininess: 30 } ),
		new THREE.MeshPhongMaterial( { color: 0xff8844, specular: 0x666666, shininess: 100, emissive: 0x101010 } ),
		new THREE.MeshPhongMaterial( { color: 0x88ccff, flatShading: true } ),
		new THREE.MeshLambertMaterial( { color: 0xffffff } ),
		new THREE.MeshLambertMaterial( { color: 0x44ff88 } ),
		new THREE.MeshToonMaterial( { color: 0xcccccc } ),
	];

}

function makeSpheres( materials: THREE.Material[], geometry: THREE.BufferGeometry ): THREE.Mesh[] {

	return materials.map( ( material, i ) => {

		const mesh = new THREE.Mesh( geometry, material );
		mesh.position.set( ( i % 3 - 1 ) * 1.1, ( Math.floor( i / 3 ) - 0.5 ) * 1.1, 0 );
		return mesh;

	} );

}

/** SH(x, z) of the floor tests (largeObjects.gpu.test.ts): a linear field, red towards +x, blue towards +z. */
function fieldSH( x: number, z: number ): number[] {

	const sh = new Array<number>( 27 ).fill( 0 );
	sh[ 0 ] = 1.1 + 0.045 * x; sh[ 1 ] = 1.1; sh[ 2 ] = 1.1 + 0.045 * z;
	sh[ 3 ] = 0.25; sh[ 4 ] = 0.3 + 0.012 * x; sh[ 5 ] = 0.25;
	sh[ 18 ] = 0.08; sh[ 19 ] = - 0.05 + 0.004 * z; sh[ 20 ] = 0.06;
	sh[ 24 ] = 0.05; sh[ 25 ] = 0.02; sh[ 26 ] = - 0.04;
	return sh;

}

/** Probes on two levels around the 20 × 20 floor, each holding fieldSH at its position. */
function fieldVolume(): LightProbeVolume {

	const positions: number[] = [];
	for ( const x of [ - 12, 12 ] ) for ( const y of [ - 2, 4 ] ) for ( const z of [ - 12, 12 ] ) positions.push( x, y, z );
	for ( let i = 0; i < 20; i ++ ) {

		positions.push( 9 * Math.sin( 3.1 * i + 1 ), 1 + 2 * Math.sin( 5.3 * i ), 9 * Math.cos( 2.3 * i + 0.5 ) );

	}

	const sh: number[] = [];
	for ( let i = 0; i < positions.length / 3; i ++ ) sh.push( ...fieldSH( positions[ 3 * i ], positions[ 3 * i + 2 ] ) );
	return new LightProbeVolume( { positions, sh } );

}

const FLOOR_MATERIALS = {
	phong: () => new THREE.MeshPhongMaterial( { color: 0xffffff } ),
	lambert: () => new THREE.MeshLambertMaterial( { color: 0xffffff } ),
	toon: () => new THREE.MeshToonMaterial( { color: 0xffffff } ),
};

type FloorKind = keyof typeof FLOOR_MATERIALS;

/** The floor, [−10, 10]² at y = 0, facing up, two triangles. */
function floorMesh( kind: FloorKind ): THREE.Mesh {

	return new THREE.Mesh( new THREE.PlaneGeometry( 20, 20 ).rotateX( - Math.PI / 2 ), FLOOR_MATERIALS[ kind ]() );

}

/** Floor sample points, inside pixels (not on the diagonal edge). */
const POINTS = [ [ - 8, - 8 ], [ 8, - 8 ], [ - 8, 8 ], [ 8, 8 ], [ 0.4, 0 ], [ - 4.3, 6.1 ], [ 5.7, - 2.2 ] ];

describe.skipIf( ! ctx.renderer )( `Phong, Lambert and Toon materials lit by probes (headless-gl)${SKIPPED}`, () => {

	const renderer = ctx.renderer as THREE.WebGLRenderer;
	const gl = ctx.gl as WebGL2RenderingContext;

	afterAll( () => ctx.dispose() );

	/** Renders both scenes and compares them; on failure the images go to test/output/phongLambert-<name>.*.png. */
	function compareScenes( name: string, actualScene: THREE.Scene, expectedScene: THREE.Scene, view: THREE.Camera, tolerance: number ) {

		const actual = renderToImage( renderer, gl, actualScene, view );
		const expected = renderToImage( renderer, gl, expectedScene, view );
		const result = compareImages( actual, expected, tolerance );
		let message = '';
		if ( result.count > 0 ) {

			for ( const [ suffix, image ] of [ [ 'actual', actual ], [ 'expected', expected ], [ 'diff', diffImage( actual, expected ) ] ] as const ) {

				writePNG( path.join( OUTPUT_DIR, `phongLambert-${name}.${suffix}.png` ), image );

			}

			message = `${result.count} pixels differ by > ${tolerance}/255 (max ${result.max} at ${result.at}); images in test/output/phongLambert-${name}.*.png`;

		}

		return { actual, expected, ...result, message };

	}

	describe( 'object mode: the same image as three\'s LightProbe', () => {

		it( 'per pixel: 3 Phong, 2 Lambert and 1 Toon sphere lit by a volume whose probes all carry SKY look as lit by LightProbe( SKY ) (≤ 1/255)', () => {

			// With every probe = SKY the blend is SKY, and E(n) = nᵀMn is what the LightProbe adds,
			// at the same place (`irradiance`, before RE_IndirectDiffuse) in the same world space.
			// Phong's highlight and Toon's gradient act on direct light only: none here. Unpatched
			// spheres would be black (no light at all): the reference is far from that.
			const geometry = new THREE.SphereGeometry( 0.5, 64, 32 );
			const materials = makeMaterials();
			const references = materials.map( ( material ) => material.clone() );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const volumeScene = new THREE.Scene(), referenceScene = new THREE.Scene();
			for ( const mesh of makeSpheres( materials, geometry ) ) {

				volumeScene.add( mesh );
				volume.add( mesh );

			}

			referenceScene.add( ...makeSpheres( references, geometry ), lightProbe( SKY ) );
			volume.update();
			const result = compareScenes( 'pixel', volumeScene, referenceScene, camera( { x: 0.3, y: 0.8, z: 4.5 } ), 1 );
			volume.dispose();
			geometry.dispose();
			for ( const material of [ ...materials, ...references ] ) material.dispose();

			expect( result.count, result.message ).toBe( 0 );
			expect( covered( result.expected ) ).toBeGreaterThan( 0.25 * SIZE * SIZE );
			expect( gl.getError() ).toBe( gl.NO_ERROR );

		} );

		it( 'a blend: a Phong and a Lambert sphere halfway between a red and a blue probe look as lit by a LightProbe with their average (≤ 1/255), not by either probe', () => {

			// The bipyramid of volume.gpu.test.ts: the origin is on the edge p0–p1 of its
			// tetrahedralization, so the weights are (½, ½) and the blend is (RED + BLUE) / 2; the
			// ring probes are bright green and must get no weight.
			const positions = [ - 0.3, 0, 0, 0.3, 0, 0, 0, 1, 0, 0, - 0.5, 0.866, 0, - 0.5, - 0.866 ];
			const RED = SKY.map( ( v, i ) => i % 3 === 0 ? v * 1.6 : v * 0.4 );
			const BLUE = SKY.map( ( v, i ) => i % 3 === 2 ? v * 1.4 : v * 0.3 ).map( ( v, i ) => i >= 3 && i < 12 ? - v : v );
			const GREEN = SKY.map( ( v, i ) => i % 3 === 1 ? v * 5 : 0 );
			const AVERAGE = RED.map( ( v, i ) => ( v + BLUE[ i ] ) / 2 );
			const view = camera( { x: 0.4, y: 0.6, z: 1.8 } );
			const geometry = new THREE.SphereGeometry( 0.5, 64, 32 );
			for ( const make of [ () => new THREE.MeshPhongMaterial( { shininess: 50 } ), () => new THREE.MeshLambertMaterial() ] ) {

				const volume = new LightProbeVolume( { positions, sh: [ ...RED, ...BLUE, ...GREEN, ...GREEN, ...GREEN ] } );
				const material = make(), reference = material.clone();
				const mesh = new THREE.Mesh( geometry, material );
				volume.add( mesh );
				volume.update();
				const name = `blend-${material.type}`;
				const probeScene = ( sh: number[] ) => new THREE.Scene().add( new THREE.Mesh( geometry, reference ), lightProbe( sh ) );
				const result = compareScenes( name, new THREE.Scene().add( mesh ), probeScene( AVERAGE ), view, 1 );
				const onlyRed = renderToImage( renderer, gl, probeScene( RED ), view );
				volume.dispose();
				material.dispose();
				reference.dispose();
				expect( result.count, `${material.type}: ${result.message}` ).toBe( 0 );
				expect( compareImages( result.actual, onlyRed ).max, material.type ).toBeGreaterThan( 20 );

			}

			geometry.dispose();

		} );

		it( 'with direct lights: probe + lights = LightProbe + the same lights (≤ 1/255); probeVolumeDirectScale = 0 leaves the probe light alone, Phong\'s highlight gone (≤ 1/255)', () => {

			// The direct scale multiplies reflectedLight.directDiffuse and .directSpecular after the
			// lights loop: 0 must give exactly the LightProbe-only image, for Phong's specular too.
			const lights = () => {

				const sun = new THREE.DirectionalLight( 0xffffff, 2 );
				sun.position.set( 2, 3, 4 );
				const lamp = new THREE.PointLight( 0xffaa66, 3, 0, 2 );
				lamp.position.set( - 1.5, 0.5, 1.5 );
				return [ sun, sun.target, lamp ];

			};

			const geometry = new THREE.SphereGeometry( 0.5, 64, 32 );
			const materials = makeMaterials();
			const references = materials.map( ( material ) => material.clone() );
			const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
			const spheres = makeSpheres( materials, geometry );
			for ( const mesh of spheres ) volume.add( mesh );
			volume.update();
			const view = camera( { x: 0.3, y: 0.8, z: 4.5 } );
			const litScene = new THREE.Scene().add( ...spheres, ...lights() );
			const withLights = compareScenes( 'direct', litScene, new THREE.Scene().add( ...makeSpheres( references, geometry ), lightProbe( SKY ), ...lights() ), view, 1 );
			for ( const mesh of spheres ) volume.getUniforms( mesh )!.probeVolumeDirectScale.value = 0;
			const probeOnly = compareScenes( 'direct-scale-0', litScene, new THREE.Scene().add( ...makeSpheres( references, geometry ), lightProbe( SKY ) ), view, 1 );
			volume.dispose();
			geometry.dispose();
			for ( const material of [ ...materials, ...references ] ) material.dispose();

			expect( withLights.count, withLights.message ).toBe( 0 );
			expect( probeOnly.count, probeOnly.message ).toBe( 0 );
			// The lights are really there: they change the picture a lot.
			expect( compareImages( withLights.actual, probeOnly.actual ).max ).toBeGreaterThan( 40 );

		} );

		it( 'per vertex (perVertex: true) on a finely tessellated Phong and Lambert sphere: within 2/255 of the per-pixel LightProbe', () => {

			// E is interpolated linearly across 128 × 64 triangles (≈ 6e-4 error in linear light,
			// see volume.gpu.test.ts), under one 8-bit step plus a rounding edge.
			const geometry = new THREE.SphereGeometry( 0.6, 128, 64 );
			const view = camera( { x: 0, y: 0.5, z: 2.2 } );
			for ( const material of [ new THREE.MeshPhongMaterial(), new THREE.MeshLambertMaterial() ] ) {

				const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
				const reference = material.clone();
				const mesh = new THREE.Mesh( geometry, material );
				volume.add( mesh, { perVertex: true } );
				volume.update();
				const result = compareScenes( `vertex-${material.type}`, new THREE.Scene().add( mesh ), new THREE.Scene().add( new THREE.Mesh( geometry, reference ), lightProbe( SKY ) ), view, 2 );
				volume.dispose();
				material.dispose();
				reference.dispose();
				expect( result.count, `${material.type}: ${result.message}` ).toBe( 0 );

			}

			geometry.dispose();

		} );

	} );

	describe( 'large objects: a 20 × 20 floor under a linear field, seen from above', () => {

		const top = new THREE.OrthographicCamera( - 10, 10, 10, - 10, 0.1, 50 );
		top.position.set( 0, 20, 0 );
		top.up.set( 0, 0, - 1 );
		top.lookAt( 0, 0, 0 );
		top.updateMatrixWorld();

		const pixel = ( image: Image8, x: number, z: number ) => {

			const [ u, v ] = projectToImage( new THREE.Vector3( x, 0, z ), top, image.width, image.height );
			const p = Math.floor( v ) * image.width + Math.floor( u );
			return [ image.data[ 4 * p ], image.data[ 4 * p + 1 ], image.data[ 4 * p + 2 ] ];

		};

		/** What three renders at (x, z) for the same kind of floor lit by a LightProbe holding SH(x, z). */
		const references = new Map<string, number[]>();
		const expected = ( kind: FloorKind, x: number, z: number ) => {

			const key = `${kind} ${x} ${z}`;
			if ( ! references.has( key ) ) {

				const floor = floorMesh( kind );
				const image = renderToImage( renderer, gl, new THREE.Scene().add( floor, lightProbe( fieldSH( x, z ) ) ), top );
				references.set( key, pixel( image, x, z ) );
				disposeMesh( floor );

			}

			return references.get( key )!;

		};

		const worstAgainstReference = ( kind: FloorKind, image: Image8 ) => {

			let worst = 0;
			for ( const [ x, z ] of POINTS ) {

				const actual = pixel( image, x, z ), want = expected( kind, x, z );
				for ( let c = 0; c < 3; c ++ ) worst = Math.max( worst, Math.abs( actual[ c ] - want[ c ] ) );

			}

			return worst;

		};

		for ( const kind of Object.keys( FLOOR_MATERIALS ) as FloorKind[] ) {

			it( `${kind}: vertex mode (irradiance and SH) and texture mode follow the gradient within 2/255 of LightProbe( SH there ); object mode does not`, () => {

				// A linear field is exact per vertex (linear across each triangle at a constant
				// normal) and under trilinear filtering of the texture's grid nodes.
				expect( expected( kind, 8, - 8 )[ 0 ] - expected( kind, - 8, - 8 )[ 0 ], 'the field is a real gradient' ).toBeGreaterThan( 30 );
				const modes = [ { mode: 'vertex' }, { mode: 'vertex', vertexOutput: 'sh' }, { mode: 'texture' }, { mode: 'object' } ] as const;
				const worst: number[] = [];
				for ( const options of modes ) {

					const volume = fieldVolume();
					const floor = floorMesh( kind );
					const original = floor.material;
					volume.add( floor, options );
					volume.update();
					const image = renderToImage( renderer, gl, new THREE.Scene().add( floor ), top );
					worst.push( worstAgainstReference( kind, image ) );
					if ( worst[ worst.length - 1 ] > 2 && options.mode !== 'object' ) {

						writePNG( path.join( OUTPUT_DIR, `phongLambert-floor-${kind}-${options.mode}.png` ), image );

					}

					volume.dispose();
					expect( floor.material ).toBe( original ); // restored
					disposeMesh( floor );

				}

				expect( worst.slice( 0, 3 ).every( ( w ) => w <= 2 ), `worst vertex, vertex sh, texture, object: ${worst}` ).toBe( true );
				expect( worst[ 3 ], 'one blend for the whole floor misses the gradient' ).toBeGreaterThan( 20 );

			} );

		}

	} );

	/**
	 * A room as OBJLoader + MTLLoader give one: every surface a `MeshPhongMaterial`, the bulb a
	 * `MeshBasicMaterial`. The only light shines straight up from below, so the ceiling (facing
	 * down) is lit and the floor and walls (N·L ≤ 0) get no direct light at all: whatever light they
	 * show is the ceiling's, bounced through the probes.
	 */
	function objRoom() {

		const scene = new THREE.Scene();
		const phong = ( color: number ) => {

			const material = new THREE.MeshPhongMaterial();
			material.color.setHex( color );
			return material;

		};

		const floor = new THREE.Mesh( new THREE.PlaneGeometry( 8, 8 ).rotateX( - Math.PI / 2 ), phong( 0xcccccc ) ); // two triangles
		floor.name = 'floor';
		const ceiling = new THREE.Mesh( new THREE.PlaneGeometry( 8, 8 ).rotateX( Math.PI / 2 ), phong( 0xffffff ) );
		ceiling.position.y = 3;
		ceiling.name = 'ceiling';
		const backWall = new THREE.Mesh( new THREE.PlaneGeometry( 8, 3, 32, 12 ), phong( 0xcc2020 ) ); // 0.35 m triangles
		backWall.position.set( 0, 1.5, - 4 );
		backWall.name = 'backWall';
		const crate = new THREE.Mesh( new THREE.BoxGeometry( 0.6, 0.6, 0.6 ), phong( 0x20cc20 ) );
		crate.position.set( - 1, 0.3, 1 );
		crate.name = 'crate';
		const bulb = new THREE.Mesh( new THREE.SphereGeometry( 0.1 ), new THREE.MeshBasicMaterial( { color: 0xffffff } ) );
		bulb.position.set( 0, 2.8, 0 );
		bulb.name = 'bulb';
		const light = new THREE.DirectionalLight( 0xffffff, 3 );
		light.position.set( 0, - 10, 0 ); // from below: only the ceiling faces it
		scene.add( floor, ceiling, backWall, crate, bulb, light, light.target );
		scene.updateMatrixWorld( true );
		const meshes = [ floor, ceiling, backWall, crate, bulb ];
		return { scene, floor, ceiling, backWall, crate, bulb, meshes, dispose: () => meshes.forEach( disposeMesh ) };

	}

	function roomProbes(): number[] {

		const positions: number[] = [];
		for ( const x of [ - 3, - 1, 1, 3 ] ) {

			for ( const y of [ 0.5, 2.5 ] ) for ( const z of [ - 3, - 1, 1, 3 ] ) positions.push( x, y, z );

		}

		return positions;

	}

	it( 'an OBJ-like room of Phong materials: add( scene ) lights floor (texture), back wall (vertex) and crate (object), black before the capture, lit after; the Basic bulb is left alone without a warning', async () => {

		const view = camera( { x: 0, y: 1.6, z: 3.5 }, { x: 0, y: 0.6, z: - 4 }, 70 );
		const r = objRoom();
		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		const bulbMaterial = r.bulb.material;
		const volume = new LightProbeVolume( { positions: roomProbes() } );
		volume.add( r.scene );
		expect( volume.getLighting( r.floor ) ).toBe( 'texture' );
		expect( volume.getLighting( r.backWall ) ).toBe( 'vertex' );
		expect( volume.getLighting( r.crate ) ).toBe( 'object' );
		expect( volume.getLighting( r.bulb ) ).toBeNull();
		expect( r.bulb.material ).toBe( bulbMaterial );
		expect( warn ).not.toHaveBeenCalled();
		warn.mockRestore();

		const dark = renderToImage( renderer, gl, r.scene, view ); // probes all zero: no light on floor or wall
		await volume.capture( renderer, r.scene, { resolution: 16 } );
		volume.update();
		const lit = renderToImage( renderer, gl, r.scene, view );
		writePNG( path.join( OUTPUT_DIR, 'phongLambert-objRoom-lit.png' ), lit );
		const at = ( point: THREE.Vector3 ) => projectToImage( point, view, SIZE, SIZE );
		const places = {
			floor: at( new THREE.Vector3( 1.5, 0, - 1 ) ),
			wall: at( new THREE.Vector3( 1.5, 1.2, - 4 ) ),
			crate: at( new THREE.Vector3( - 1, 0.3, 1.3 ) ), // its front face
		};
		const show = ( c: number[] ) => c.map( Math.round ).join( ', ' );
		for ( const [ name, [ x, y ] ] of Object.entries( places ) ) {

			const before = averageColor( dark, x, y, 2 ), after = averageColor( lit, x, y, 2 );
			const message = `${name} at (${x.toFixed( 0 )}, ${y.toFixed( 0 )}): before ${show( before )}, after ${show( after )}`;
			expect( Math.max( ...before ), message ).toBeLessThan( 1 );
			expect( Math.max( ...after ), message ).toBeGreaterThan( 20 );

		}

		// The wall's own colour shows: red, lit by white bounce light.
		const wall = averageColor( lit, places.wall[ 0 ], places.wall[ 1 ], 2 );
		expect( wall[ 0 ], `wall ${show( wall )}` ).toBeGreaterThan( 1.5 * Math.max( wall[ 1 ], wall[ 2 ] ) );
		volume.dispose();
		r.dispose();

	} );

	it( 'bounces on the Phong room without add( scene ): captureBounces lights every Phong mesh (not the bulb) and pass 1 adds light to pass 0', async () => {

		// Before Phong took probe light, the default static meshes of this room were none and the
		// bounce pass captured exactly pass 0 again.
		const r = objRoom();
		const volume = new LightProbeVolume( { positions: roomProbes() } );
		const result = await captureBounces( volume, renderer, r.scene, { bounces: 1, resolution: 16 } );
		const lit = new Set( result.staticMeshes );
		expect( [ r.floor, r.ceiling, r.backWall, r.crate ].every( ( mesh ) => lit.has( mesh ) ) ).toBe( true );
		expect( lit.has( r.bulb ) ).toBe( false );
		const [ pass0, pass1 ] = result.passes.map( ( pass ) => pass.meanL00[ 0 ] + pass.meanL00[ 1 ] + pass.meanL00[ 2 ] );
		expect( pass0 ).toBeGreaterThan( 0 );
		expect( pass1, `mean L00 sums: pass 0 ${pass0}, pass 1 ${pass1}` ).toBeGreaterThan( 1.05 * pass0 );
		// Everything is restored: no material of the room is left patched.
		for ( const mesh of r.meshes ) expect( getProbeVolumeUniforms( mesh.material as THREE.Material ) ).toBeNull();
		volume.dispose();
		r.dispose();

	} );

	it( 'program sharing: 4 meshes sharing one Phong material and 4 with their own Lambert materials, lit by add( scene ), add one program per material type, yet keep their own uniforms', () => {

		// Each mesh is its own 'object' entry; the shared Phong material is patched in place for
		// the first and cloned for the others (uniforms live on the material). Clones and
		// originals of one type and variant have one program cache key.
		const scene = new THREE.Scene();
		const box = new THREE.Mesh( new THREE.BoxGeometry( 0.2, 0.2, 0.2 ), new THREE.MeshBasicMaterial( { color: 0x808080 } ) );
		box.position.set( 0, - 1.2, 0 );
		scene.add( box );
		const view = camera( { x: 0, y: 0, z: 6 } );
		renderToImage( renderer, gl, scene, view );
		const before = renderer.info.programs!.length;

		const geometry = new THREE.SphereGeometry( 0.25, 32, 16 );
		const shared = new THREE.MeshPhongMaterial( { color: 0xffffff } );
		const meshes: THREE.Mesh[] = [];
		for ( let i = 0; i < 8; i ++ ) {

			const mesh = new THREE.Mesh( geometry, i < 4 ? shared : new THREE.MeshLambertMaterial( { color: 0xffffff } ) );
			mesh.position.set( ( i % 4 - 1.5 ) * 0.7, i < 4 ? 0.4 : - 0.3, 0 );
			scene.add( mesh );
			meshes.push( mesh );

		}

		const volume = new LightProbeVolume( { positions: WIDE_POSITIONS, sh: repeatSH( SKY, 5 ) } );
		volume.add( scene );
		volume.update();
		const image = renderToImage( renderer, gl, scene, view );
		const added = renderer.info.programs!.length - before;
		const uniforms = new Set( meshes.map( ( mesh ) => getProbeVolumeUniforms( mesh.material as THREE.Material ) ) );
		const types = new Set( meshes.map( ( mesh ) => ( mesh.material as THREE.Material ).type ) );
		const centres = meshes.map( ( mesh ) => averageColor( image, ...projectToImage( mesh.position, view, SIZE, SIZE ), 1 ) );
		volume.dispose();
		expect( meshes.slice( 0, 4 ).every( ( mesh ) => mesh.material === shared ) ).toBe( true ); // restored
		for ( const mesh of meshes ) {

			if ( mesh.material !== shared ) ( mesh.material as THREE.Material ).dispose();

		}

		shared.dispose();
		geometry.dispose();
		disposeMesh( box );

		expect( added, 'programs added' ).toBe( 2 );
		expect( uniforms.size ).toBe( 8 );
		expect( uniforms.has( null ) ).toBe( false );
		expect( [ ...types ].sort() ).toEqual( [ 'MeshLambertMaterial', 'MeshPhongMaterial' ] );
		for ( const colour of centres ) expect( Math.min( ...colour ), 'every sphere is lit' ).toBeGreaterThan( 60 );

	} );

} );
