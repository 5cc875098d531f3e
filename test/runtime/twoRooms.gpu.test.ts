/**
 * No light through walls, measured: scenes/twoRooms.ts (room A lit pure red, room B pure blue,
 * one probe grid spanning both, cells straddling the shared wall), captured on a real GL context
 * (headless-gl, 16² cube faces), then sampled in room B near the wall with neither zones nor
 * guard, with the visibility guard, with zones, and with both.
 *
 * Leak, defined: at points of room B 0.2 and 0.5 from the wall, the red channel of the irradiance
 * averaged over all normal directions (the mean of E(n) over the six axis normals, which for SH9
 * is exactly the spherical mean), divided by the same for room A's own light at the same height
 * and depth on A's side of the wall, where "room A's own" is a separate volume made of room A's
 * 8 probes alone (independent of the zone and guard code), read at its probe layer nearest the
 * wall (x = −1: measured there, not extrapolated, so the figure does not depend on how
 * TetrahedralMesh extrapolates outside the hull). Room B contains no red light source or
 * red surface and its lights cannot reach room A (see the scene), so every bit of red in room B
 * comes through the probes. The largest ratio over 18 points is the leak. (Not E for the normal
 * facing the wall alone: the shared wall's faces are unlit — each room's lamp hangs in front of
 * the shared wall and shines away from it — and E towards it is ≈ 0 in room A itself.)
 *
 * Needs an X display for headless-gl: `xvfb-run -a npx vitest run test/runtime/twoRooms.gpu.test.ts`.
 */

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { evaluateIrradiance, irradianceMatrices } from '../../src/sh/index.js';
import { createTwoRooms, type TwoRooms } from '../../scenes/twoRooms.js';
import { createHeadlessRenderer } from '../helpers/headlessGL.js';
import { averageColor, projectToImage, renderToImage } from '../helpers/gpuScenes.js';

const SIZE = 32;
const ctx = await createHeadlessRenderer( SIZE, SIZE );

const AXES = [ [ 1, 0, 0 ], [ - 1, 0, 0 ], [ 0, 1, 0 ], [ 0, - 1, 0 ], [ 0, 0, 1 ], [ 0, 0, - 1 ] ];

/** E(n) averaged over the six axis normals, RGB: the linear and quadratic SH terms cancel, leaving the spherical mean. */
function meanIrradiance( sh: ArrayLike<number> ): number[] {

	const sum = [ 0, 0, 0 ];
	for ( const n of AXES ) evaluateIrradiance( sh, n ).forEach( ( v, c ) => { sum[ c ] += v / 6; } );
	return sum;

}
const SKIPPED = ctx.renderer ? '' : ` — SKIPPED: ${ctx.skipReason}`;

describe.skipIf( ! ctx.renderer )( `two rooms sharing a wall: red room A, blue room B (headless-gl)${SKIPPED}`, () => {

	let rooms: TwoRooms;
	let sh: Float32Array;
	let roomAOnly: LightProbeVolume;
	let roomBOnly: LightProbeVolume;
	const measured: Record<string, number> = {};

	/** Sample points in room B (0.2 and 0.5 from the wall) and the reference points in room A (same y, z, at x = −1). */
	const points: { b: THREE.Vector3; a: THREE.Vector3 }[] = [];

	beforeAll( async () => {

		rooms = createTwoRooms();
		const capture = new LightProbeVolume( { positions: rooms.positions } );
		await capture.capture( ctx.renderer!, rooms.scene, { resolution: 16 } );
		sh = capture.sh;
		const only = ( probes: number[] ) => new LightProbeVolume( {
			positions: probes.flatMap( ( i ) => rooms.positions.slice( 3 * i, 3 * i + 3 ) ),
			sh: probes.flatMap( ( i ) => Array.from( sh.subarray( 27 * i, 27 * i + 27 ) ) ),
		} );
		roomAOnly = only( rooms.probesA );
		roomBOnly = only( rooms.probesB );
		for ( const distance of [ 0.2, 0.5 ] ) {

			const x = rooms.wallHalfThickness + distance;
			for ( const y of [ 1, 1.5, 2 ] ) for ( const z of [ - 1, 0, 1 ] ) points.push( { b: new THREE.Vector3( x, y, z ), a: new THREE.Vector3( - 1, y, z ) } );

		}

	} );

	afterAll( () => {

		console.log( `two rooms, red leak into room B near the wall (max over ${points.length} points): ${Object.entries( measured ).map( ( [ k, v ] ) => `${k} ${( 100 * v ).toFixed( 2 )} %` ).join( ', ' )}` );
		rooms?.dispose();
		ctx.dispose();

	} );

	/** Largest red ratio over the points, and room B's mean blue relative to room B's own. */
	function measure( volume: LightProbeVolume ) {

		let leak = 0, blue = 0, ownBlue = 0;
		for ( const { a, b } of points ) {

			const red = meanIrradiance( volume.sample( b ) )[ 0 ];
			const reference = meanIrradiance( roomAOnly.sample( a ) )[ 0 ];
			expect( reference ).toBeGreaterThan( 0.1 ); // room A really is lit red at the wall
			leak = Math.max( leak, red / reference );
			blue += meanIrradiance( volume.sample( b ) )[ 2 ];
			ownBlue += meanIrradiance( roomBOnly.sample( b ) )[ 2 ];

		}

		return { leak, blueRatio: blue / ownBlue };

	}

	it( 'the capture is what the scene says: room A probes red and not blue, room B probes blue and not red', () => {

		for ( const i of rooms.probesA ) {

			expect( sh[ 27 * i ], `probe ${i} L00 red` ).toBeGreaterThan( 0.1 );
			expect( sh[ 27 * i + 2 ], `probe ${i} L00 blue` ).toBeLessThan( 1e-3 * sh[ 27 * i ] );

		}

		for ( const i of rooms.probesB ) {

			expect( sh[ 27 * i + 2 ], `probe ${i} L00 blue` ).toBeGreaterThan( 0.1 );
			expect( sh[ 27 * i ], `probe ${i} L00 red` ).toBeLessThan( 1e-3 * sh[ 27 * i + 2 ] );

		}

	} );

	it( 'neither zones nor guard: the leak exists — room B near the wall gets well over 5 % of room A\'s red (the measure can fail)', () => {

		const volume = new LightProbeVolume( { positions: rooms.positions, sh } );
		const { leak } = measure( volume );
		measured[ 'neither' ] = leak;
		expect( leak ).toBeGreaterThan( 0.15 );

	} );

	it( 'visibility guard alone (occluders = the static meshes): < 5 % of room A\'s red, and room B keeps ≥ 90 % of its own blue', () => {

		const volume = new LightProbeVolume( { positions: rooms.positions, sh, occluders: rooms.statics } );
		const { leak, blueRatio } = measure( volume );
		measured[ 'guard' ] = leak;
		expect( leak ).toBeLessThan( 0.05 );
		expect( blueRatio ).toBeGreaterThan( 0.9 );
		// The cells between the two probe layers next to the wall are the leaking ones: each has
		// probes on both sides (every edge between the sides crosses the full-size wall).
		const mesh = volume.interpolator as unknown as { tetrahedra: Uint32Array };
		const straddling: number[] = [];
		for ( let t = 0; t < mesh.tetrahedra.length / 4; t ++ ) {

			const sides = new Set( Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ), ( i ) => rooms.positions[ 3 * i ] < 0 ) );
			if ( sides.size === 2 ) straddling.push( t );

		}

		expect( straddling.length ).toBeGreaterThan( 0 );
		expect( Array.from( volume.findLeakingTetrahedra() ) ).toEqual( straddling );

	} );

	it( 'zones alone (room A, room B by bounds): < 5 % of room A\'s red, and room B keeps ≥ 90 % of its own blue', () => {

		const volume = new LightProbeVolume( { positions: rooms.positions, sh, zones: rooms.zones } );
		const { leak, blueRatio } = measure( volume );
		measured[ 'zones' ] = leak;
		expect( leak ).toBeLessThan( 0.05 );
		expect( blueRatio ).toBeGreaterThan( 0.9 );

	} );

	it( 'zones and guard together: < 5 %', () => {

		const volume = new LightProbeVolume( { positions: rooms.positions, sh, zones: rooms.zones, occluders: rooms.statics } );
		const { leak } = measure( volume );
		measured[ 'zones + guard' ] = leak;
		expect( leak ).toBeLessThan( 0.05 );

	} );

	it( 'soft guard (blockedWeight 0.1): the leak is cut to about a tenth or less of the unguarded one', () => {

		const soft = measure( new LightProbeVolume( { positions: rooms.positions, sh, occluders: rooms.statics, guard: { blockedWeight: 0.1 } } ) ).leak;
		const none = measure( new LightProbeVolume( { positions: rooms.positions, sh } ) ).leak;
		measured[ 'soft guard 0.1' ] = soft;
		expect( soft ).toBeGreaterThan( 0 );
		expect( soft ).toBeLessThan( 0.15 * none );

	} );

	it( 'rendered: a white sphere in room B by the wall, lit by the probes and by the blue lamp of room B, has red in its pixels without zones and guard and none with either', () => {

		// The camera is under room B's ceiling looking down at the sphere, so the pixels at its
		// centre are the upward-facing side, which room A's probes light red from their panel.
		const sphere = new THREE.Mesh( new THREE.SphereGeometry( 0.25, 32, 16 ), new THREE.MeshStandardMaterial( { color: 0xffffff, roughness: 1 } ) );
		sphere.position.set( rooms.wallHalfThickness + 0.35, 1.4, 0 );
		rooms.scene.add( sphere );
		const view = new THREE.PerspectiveCamera( 40, 1, 0.05, 20 );
		view.position.set( sphere.position.x + 0.4, 2.8, 0.3 );
		view.lookAt( sphere.position );
		view.updateMatrixWorld();
		const [ px, py ] = projectToImage( sphere.position, view, SIZE, SIZE );
		const colour = ( parameters: ConstructorParameters<typeof LightProbeVolume>[ 0 ] ) => {

			const volume = new LightProbeVolume( parameters );
			volume.add( sphere );
			volume.update();
			const image = renderToImage( ctx.renderer!, ctx.gl!, rooms.scene, view );
			volume.dispose();
			return averageColor( image, px, py, 1 );

		};

		const base = { positions: rooms.positions, sh };
		const neither = colour( base ), guard = colour( { ...base, occluders: rooms.statics } ), zones = colour( { ...base, zones: rooms.zones } );
		rooms.scene.remove( sphere );
		sphere.geometry.dispose();
		sphere.material.dispose();
		const message = `sphere pixels (sRGB 0..255): neither ${neither.map( Math.round )}, guard ${guard.map( Math.round )}, zones ${zones.map( Math.round )}`;
		console.log( message );
		expect( neither[ 2 ], message ).toBeGreaterThan( 40 ); // lit (blue), really in view
		// The leak, visible: red measured (llvmpipe, 2026-12-02) 116 in sRGB with neither fix; with
		// the guard or zones it is exactly 0 (room B's probes and lamp hold no red at all).
		expect( neither[ 0 ], message ).toBeGreaterThan( 8 );
		for ( const c of [ guard, zones ] ) {

			expect( c[ 2 ], message ).toBeGreaterThan( 40 );
			expect( c[ 0 ], message ).toBeLessThanOrEqual( 1 );

		}

	} );

	it( 'a registered object in room B by the wall gets, from update(), the irradiance sample() gives (guard and zones), and without them the leaking one', () => {

		const sphere = new THREE.Mesh( new THREE.SphereGeometry( 0.15 ), new THREE.MeshStandardMaterial() );
		sphere.position.set( rooms.wallHalfThickness + 0.3, 1.4, 0.2 );
		const guarded = new LightProbeVolume( { positions: rooms.positions, sh, zones: rooms.zones, occluders: rooms.statics } );
		const plain = new LightProbeVolume( { positions: rooms.positions, sh } );
		const redOf = ( volume: LightProbeVolume ) => {

			volume.add( sphere );
			volume.update();
			const matrices = Array.from( volume.getUniforms( sphere )!.probeVolumeMatrices.value );
			const expected = Array.from( irradianceMatrices( volume.sample( sphere.position ), new Float32Array( 48 ) ) );
			expect( volume.getZone( sphere ) ).toBe( volume.zones ? 'B' : null );
			volume.remove( sphere );
			matrices.forEach( ( v, i ) => expect( v ).toBeCloseTo( expected[ i ], 6 ) );
			return meanIrradiance( volume.sample( sphere.position ) )[ 0 ];

		};

		const reference = meanIrradiance( roomAOnly.sample( [ - 1, 1.4, 0.2 ] ) )[ 0 ];
		expect( redOf( guarded ) / reference ).toBeLessThan( 0.05 );
		expect( redOf( plain ) / reference ).toBeGreaterThan( 0.15 );
		sphere.geometry.dispose();
		sphere.material.dispose();

	} );

} );
