/**
 * Lighting zones without a GPU: a zone's blend equals a separate volume made of the zone's probes
 * alone (an independent construction), objects are assigned by name or by bounds (re-checked in
 * update()), the rest of the volume is unchanged, and bad zone definitions get clear errors.
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { irradianceMatrices } from '../../src/sh/index.js';
import { seededRandom } from '../helpers/pointSets.js';

/**
 * Two "rooms" of 8 probes (boxes x ∈ [−3, −1] and [1, 3], y, z ∈ [0, 2]) and a doorway probe at
 * (0, 1, 1) that belongs to both. SH: L00 red = 1 in the left room, L00 blue = 1 in the right
 * room, the doorway both at 0.5; L00 green = a linear field g(p) = 1 + 0.3x + 0.2y − 0.1z at
 * every probe (reproduced exactly inside any cell).
 */
function twoZones() {

	const positions: number[] = [];
	for ( const x of [ - 3, - 1, 1, 3 ] ) for ( const y of [ 0, 2 ] ) for ( const z of [ 0, 2 ] ) positions.push( x, y, z );
	positions.push( 0, 1, 1 );
	const count = positions.length / 3;
	const sh = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) {

		const [ x, y, z ] = positions.slice( 3 * i, 3 * i + 3 );
		sh[ 27 * i ] = x < 0 ? 1 : ( x > 0 ? 0 : 0.5 );
		sh[ 27 * i + 2 ] = x > 0 ? 1 : ( x < 0 ? 0 : 0.5 );
		sh[ 27 * i + 1 ] = g( x, y, z );
		for ( let k = 3; k < 27; k ++ ) sh[ 27 * i + k ] = Math.sin( 7 * i + k ); // something in every coefficient

	}

	const left = [ 0, 1, 2, 3, 4, 5, 6, 7, 16 ], right = [ 8, 9, 10, 11, 12, 13, 14, 15, 16 ];
	const leftBounds = new THREE.Box3( new THREE.Vector3( - 3.5, - 1, - 1 ), new THREE.Vector3( - 0.2, 3, 3 ) );
	const rightBounds = new THREE.Box3( new THREE.Vector3( 0.2, - 1, - 1 ), new THREE.Vector3( 3.5, 3, 3 ) );
	const zones = [
		{ name: 'left', probes: left, bounds: leftBounds },
		{ name: 'right', probes: right, bounds: [ rightBounds ] }, // a list of boxes works too
	];
	return { positions, sh, count, left, right, zones, leftBounds, rightBounds };

}

function g( x: number, y: number, z: number ): number {

	return 1 + 0.3 * x + 0.2 * y - 0.1 * z;

}

/** A volume made of some probes alone, in the given order. */
function subVolume( positions: number[], sh: Float32Array, probes: number[] ): LightProbeVolume {

	return new LightProbeVolume( {
		positions: probes.flatMap( ( i ) => positions.slice( 3 * i, 3 * i + 3 ) ),
		sh: probes.flatMap( ( i ) => Array.from( sh.subarray( 27 * i, 27 * i + 27 ) ) ),
	} );

}

function expectSH( actual: ArrayLike<number>, expected: ArrayLike<number>, digits = 6 ): void {

	for ( let k = 0; k < 27; k ++ ) expect( actual[ k ], `coefficient ${k}` ).toBeCloseTo( expected[ k ], digits );

}

function litSphere(): THREE.Mesh<THREE.SphereGeometry, THREE.MeshStandardMaterial> {

	return new THREE.Mesh( new THREE.SphereGeometry( 0.1 ), new THREE.MeshStandardMaterial() );

}

describe( 'LightProbeVolume zones', () => {

	it( 'sample() in a zone\'s bounds equals a separate volume of that zone\'s probes alone (300 points, every coefficient); outside all bounds, the volume without zones', () => {

		const { positions, sh, left, right, zones, leftBounds, rightBounds } = twoZones();
		const volume = new LightProbeVolume( { positions, sh, zones } );
		const plain = new LightProbeVolume( { positions, sh } );
		const leftOnly = subVolume( positions, sh, left ), rightOnly = subVolume( positions, sh, right );
		const random = seededRandom( 11 );
		let inLeft = 0, inRight = 0, outside = 0;
		for ( let i = 0; i < 300; i ++ ) {

			const p = [ 7 * random() - 3.5, 4 * random() - 1, 4 * random() - 1 ];
			const actual = volume.sample( p );
			if ( leftBounds.containsPoint( new THREE.Vector3( ...p ) ) ) { inLeft ++; expectSH( actual, leftOnly.sample( p ) ); }
			else if ( rightBounds.containsPoint( new THREE.Vector3( ...p ) ) ) { inRight ++; expectSH( actual, rightOnly.sample( p ) ); }
			else { outside ++; expectSH( actual, plain.sample( p ) ); }

		}

		expect( Math.min( inLeft, inRight, outside ) ).toBeGreaterThan( 10 );

	} );

	it( 'a zone keeps its own light: no blue in the left room, no red in the right one, even next to the other room; the linear green field is exact inside each zone\'s hull; without zones the rooms mix', () => {

		const { positions, sh, zones } = twoZones();
		const volume = new LightProbeVolume( { positions, sh, zones } );
		const plain = new LightProbeVolume( { positions, sh } );
		for ( const p of [ [ - 0.5, 1, 1 ], [ - 0.9, 0.3, 1.8 ], [ - 2, 1, 1 ] ] ) {

			expect( volume.sample( p )[ 2 ] ).toBeLessThanOrEqual( 0.5 + 1e-6 ); // at most the doorway's share
			expect( volume.sample( p )[ 1 ] ).toBeCloseTo( g( p[ 0 ], p[ 1 ], p[ 2 ] ), 5 );

		}

		expect( volume.sample( [ - 2, 1, 1 ] )[ 2 ] ).toBe( 0 ); // far from the doorway: none
		expect( volume.sample( [ 2, 1, 0.3 ] )[ 0 ] ).toBe( 0 );
		// The same points without zones: the cells between x = −1 and x = 1 blend both rooms.
		expect( plain.sample( [ - 0.5, 0.2, 0.2 ] )[ 2 ] ).toBeGreaterThan( 0.1 );

	} );

	it( 'add( object ): assigned by bounds and re-checked every update() as it moves (left → right → outside → left); uniforms = irradianceMatrices of the expected blend', () => {

		const { positions, sh, left, right, zones } = twoZones();
		const volume = new LightProbeVolume( { positions, sh, zones } );
		const plain = new LightProbeVolume( { positions, sh } );
		const leftOnly = subVolume( positions, sh, left ), rightOnly = subVolume( positions, sh, right );
		const sphere = litSphere();
		sphere.position.set( - 2, 1, 1 );
		volume.add( sphere );
		const matrices = volume.getUniforms( sphere )!.probeVolumeMatrices.value;
		const path: [ number[], string | null, LightProbeVolume ][] = [
			[ [ - 2, 1, 1 ], 'left', leftOnly ], [ [ 0.5, 1.5, 0.4 ], 'right', rightOnly ], [ [ 2.5, 0.1, 1.9 ], 'right', rightOnly ],
			[ [ 0, 1, 1 ], null, plain ], [ [ 6, 1, 1 ], null, plain ], [ [ - 0.3, 0.2, 0.2 ], 'left', leftOnly ],
		];
		for ( const [ p, zone, reference ] of path ) {

			sphere.position.set( p[ 0 ], p[ 1 ], p[ 2 ] );
			volume.update();
			expect( volume.getZone( sphere ), `at ${p}` ).toBe( zone );
			const expected = irradianceMatrices( reference.sample( p ), new Float32Array( 48 ) );
			for ( let k = 0; k < 48; k ++ ) expect( matrices[ k ], `at ${p}, matrix entry ${k}` ).toBeCloseTo( expected[ k ], 5 );

		}

		volume.dispose();
		sphere.geometry.dispose();
		sphere.material.dispose();

	} );

	it( 'add( object, { zone } ) pins the zone whatever the position; sample( p, target, { zone } ) does the same', () => {

		const { positions, sh, left, zones } = twoZones();
		const volume = new LightProbeVolume( { positions, sh, zones } );
		const leftOnly = subVolume( positions, sh, left );
		const sphere = litSphere();
		sphere.position.set( 2, 1, 1 ); // in the right room's bounds
		volume.add( sphere, { zone: 'left' } );
		expect( volume.getZone( sphere ) ).toBe( 'left' );
		const expected = leftOnly.sample( [ 2, 1, 1 ] );
		expect( expected[ 0 ] ).toBeGreaterThan( 0.4 ); // the left room's red, extrapolated: clearly not the right room's light
		const matrices = volume.getUniforms( sphere )!.probeVolumeMatrices.value;
		const expectedMatrices = irradianceMatrices( expected, new Float32Array( 48 ) );
		for ( let k = 0; k < 48; k ++ ) expect( matrices[ k ] ).toBeCloseTo( expectedMatrices[ k ], 5 );
		expectSH( volume.sample( [ 2, 1, 1 ], new Float32Array( 27 ), { zone: 'left' } ), expected );
		volume.dispose();
		sphere.geometry.dispose();
		sphere.material.dispose();

	} );

	it( 'a zone of coplanar probes gets a planar triangulation, like a volume of them alone', () => {

		const { positions, sh } = twoZones();
		// The left room's floor (y = 0) plus nothing else: 4 coplanar probes.
		const floor = [ 0, 1, 4, 5 ];
		const volume = new LightProbeVolume( { positions, sh, zones: [ { name: 'floor', probes: floor } ] } );
		const floorOnly = subVolume( positions, sh, floor );
		expect( floorOnly.interpolator.constructor.name ).toBe( 'PlanarMesh' );
		for ( const p of [ [ - 2, 0.5, 1 ], [ - 1.2, 1, 0.3 ] ] ) expectSH( volume.sample( p, new Float32Array( 27 ), { zone: 'floor' } ), floorOnly.sample( p ) );
		// No bounds: never chosen automatically.
		expectSH( volume.sample( [ - 2, 0.5, 1 ] ), new LightProbeVolume( { positions, sh } ).sample( [ - 2, 0.5, 1 ] ) );

	} );

	it( 'zones work with the visibility guard and with a volume that has neither (behaviour unchanged)', () => {

		const { positions, sh } = twoZones();
		const volume = new LightProbeVolume( { positions, sh } );
		expect( volume.zones ).toBe( null );
		expect( volume.visibilityGuard ).toBe( null );
		const sphere = litSphere();
		volume.add( sphere );
		expect( volume.getZone( sphere ) ).toBe( null );
		expect( volume.getZone( new THREE.Object3D() ) ).toBe( null );
		volume.dispose();
		sphere.geometry.dispose();
		sphere.material.dispose();

	} );

	it( 'large objects (vertex mode) take each vertex\'s zone: a floor under both rooms equals each room\'s own volume vertex by vertex; without zones red crosses the wall', () => {

		const { positions, sh, zones, left, right } = twoZones();
		// A 6 m strip at y = 1 inside both rooms' probe boxes, vertices every 0.1 m along x.
		const floor = () => new THREE.Mesh( new THREE.PlaneGeometry( 6, 0.5, 60, 1 ).rotateX( - Math.PI / 2 ).translate( 0, 1, 1 ), new THREE.MeshStandardMaterial() );
		const lightPerVertex = ( volume: LightProbeVolume ) => {

			const mesh = floor();
			volume.add( mesh, { mode: 'vertex', vertexOutput: 'sh' } );
			volume.update();
			return { data: ( mesh.geometry.getAttribute( 'probeSH0' ) as THREE.InterleavedBufferAttribute ).data.array as Float32Array, position: mesh.geometry.getAttribute( 'position' ) };

		};
		const zoned = lightPerVertex( new LightProbeVolume( { positions, sh, zones } ) );
		const plain = lightPerVertex( new LightProbeVolume( { positions, sh } ) );
		const leftAlone = subVolume( positions, sh, left ), rightAlone = subVolume( positions, sh, right );
		const expected = new Float32Array( 27 );
		let leak = 0, checked = 0;
		for ( let i = 0; i < zoned.position.count; i ++ ) {

			const x = zoned.position.getX( i ), y = zoned.position.getY( i ), z = zoned.position.getZ( i );
			// Between the zones' bounds (|x| < 0.2) a vertex belongs to no zone: the whole volume.
			if ( Math.abs( x ) < 0.2 ) continue;
			( x < 0 ? leftAlone : rightAlone ).sample( [ x, y, z ], expected );
			for ( let k = 0; k < 27; k ++ ) expect( zoned.data[ 28 * i + k ] ).toBeCloseTo( expected[ k ], 5 );
			if ( x > 0 ) leak = Math.max( leak, plain.data[ 28 * i ] ); // red right of the wall
			checked ++;

		}

		expect( checked ).toBeGreaterThan( 100 );
		expect( leak ).toBeGreaterThan( 0.1 );

	} );

	it( 'zones of one probe, two, or a row (a corridor) interpolate along their line: exact for a linear field on it, constant across it, the end probe beyond the ends', () => {

		const { positions, sh } = twoZones();
		// Probes 0, 4, 8, 12 are ( x, 0, 0 ) for x = −3, −1, 1, 3; probes 0, 1 are ( −3, 0, 0 ), ( −3, 0, 2 ).
		const volume = new LightProbeVolume( { positions, sh, zones: [
			{ name: 'row', probes: [ 12, 0, 8, 4 ] }, { name: 'pair', probes: [ 0, 1 ] }, { name: '', probes: [ 9 ] },
		] } );
		const green = ( p: number[], zone: string ) => volume.sample( p, new Float32Array( 27 ), { zone } )[ 1 ];
		for ( const x of [ - 3, - 2.5, - 1, 0, 0.3, 2.9 ] ) expect( green( [ x, 0, 0 ], 'row' ) ).toBeCloseTo( g( x, 0, 0 ), 6 );
		expect( green( [ 0.3, 5, - 7 ], 'row' ) ).toBeCloseTo( g( 0.3, 0, 0 ), 6 ); // constant across the line
		expect( green( [ 10, 0, 0 ], 'row' ) ).toBeCloseTo( g( 3, 0, 0 ), 6 ); // the end probe beyond the end
		expect( green( [ - 10, 1, 1 ], 'row' ) ).toBeCloseTo( g( - 3, 0, 0 ), 6 );
		for ( const z of [ 0, 0.5, 2 ] ) expect( green( [ - 3, 0, z ], 'pair' ) ).toBeCloseTo( g( - 3, 0, z ), 6 );
		expectSH( volume.sample( [ 5, 5, 5 ], new Float32Array( 27 ), { zone: '' } ), sh.subarray( 27 * 9, 27 * 10 ) );
		// A volume whose probes span no plane gets the same interpolation.
		const row = subVolume( positions, sh, [ 0, 4, 8, 12 ] );
		for ( const x of [ - 3, - 0.7, 1.2 ] ) expect( row.sample( [ x, 1, - 1 ] )[ 1 ] ).toBeCloseTo( g( x, 0, 0 ), 6 );
		expectSH( subVolume( positions, sh, [ 7 ] ).sample( [ 0, 0, 0 ] ), sh.subarray( 27 * 7, 27 * 8 ) );

	} );

	it( 'bad zones get errors naming LightProbeVolume, the zone and the problem', () => {

		const { positions, sh, zones } = twoZones();
		const make = ( z: unknown ) => () => new LightProbeVolume( { positions, sh, zones: z as never } );
		expect( make( { name: 'a' } ) ).toThrow( /LightProbeVolume: zones must be an array/ );
		expect( make( [ null ] ) ).toThrow( /zones\[0\] must be an object/ );
		// The zone rules of the baked format (src/roles.ts): any UTF-8 name, '' included, unique; ≥ 1 probe index.
		expect( make( [ { name: 3, probes: [ 0, 1, 2, 3 ] } ] ) ).toThrow( /LightProbeVolume: zones\[0\]\.name is number 3; expected a string/ );
		expect( make( [ { name: 'a\uD800', probes: [ 0, 1, 2, 3 ] } ] ) ).toThrow( /zones\[0\]\.name has a lone surrogate/ );
		expect( make( [ { name: 'a', probes: [ 0, 1, 2, 4 ] }, { name: 'a', probes: [ 0, 1, 2, 4 ] } ] ) ).toThrow( /zones\[1\]\.name "a" is used by an earlier zone/ );
		expect( make( [ { name: '', probes: [ 0, 1, 2, 4 ] }, { name: '', probes: [ 0, 1, 2, 4 ] } ] ) ).toThrow( /zones\[1\]\.name "" is used by an earlier zone/ );
		expect( make( [ { name: 'a', probes: [] } ] ) ).toThrow( /zones\[0\] \("a"\)\.probes is empty; a zone needs at least one probe/ );
		expect( make( [ { name: 'a' } ] ) ).toThrow( /zones\[0\] \("a"\)\.probes must be an array/ );
		expect( make( [ { name: 'a', probes: [ 0, 1, 2, 17 ] } ] ) ).toThrow( /zones\[0\] \("a"\)\.probes\[3\] = 17 is not a probe index \(0\.\.16\)/ );
		expect( make( [ { name: 'a', probes: [ 0, - 1, 2, 3 ] } ] ) ).toThrow( /probes\[1\] = -1 is not a probe index/ );
		expect( make( [ { name: 'a', probes: [ 0, 1.5, 2, 3 ] } ] ) ).toThrow( /probes\[1\] = 1\.5 is not a probe index/ );
		expect( make( [ { name: 'a', probes: [ 0, 1, 2, 4 ], bounds: { min: { x: 0, y: 0, z: NaN }, max: { x: 1, y: 1, z: 1 } } } ] ) ).toThrow( /zone "a" bounds\[0\] must be a box/ );
		expect( make( [ { name: 'a', probes: [ 0, 1, 2, 4 ], bounds: new THREE.Box3() } ] ) ).toThrow( /zone "a" bounds\[0\]/ ); // an empty Box3 (±Infinity)
		expect( make( [ { name: 'a', probes: [ 0, 1, 2, 4 ], bounds: { min: { x: 2, y: 0, z: 0 }, max: { x: 1, y: 1, z: 1 } } } ] ) ).toThrow( /min > max/ );

		const volume = new LightProbeVolume( { positions, sh, zones } );
		const sphere = litSphere();
		expect( () => volume.add( sphere, { zone: 'kitchen' } ) ).toThrow( /LightProbeVolume\.add: unknown zone "kitchen"; the zones are "left", "right"/ );
		expect( () => volume.sample( [ 0, 0, 0 ], new Float32Array( 27 ), { zone: 'kitchen' } ) ).toThrow( /LightProbeVolume\.sample: unknown zone "kitchen"/ );
		expect( () => new LightProbeVolume( { positions, sh } ).add( sphere, { zone: 'left' } ) ).toThrow( /LightProbeVolume\.add: zone "left" given, but the volume has no zones/ );
		expect( volume.getUniforms( sphere ) ).toBe( null ); // the failed add left nothing behind
		sphere.geometry.dispose();
		sphere.material.dispose();

	} );

} );
