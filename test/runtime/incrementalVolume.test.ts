import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { IncrementalTetrahedralMesh } from '../../src/interpolation/IncrementalTetrahedralMesh.js';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { DegenerateInputError } from '../../src/tetrahedra/tetrahedralize.js';
import { randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * LightProbeVolume.moveProbe / addProbe / removeProbe (CPU side; the recapture is in
 * incrementalVolume.gpu.test.ts). Truth: a LightProbeVolume built from scratch on the active
 * probes with their SH — sample() and an object's irradiance uniforms must equal it.
 */

function randomSH( count: number, seed: number ): Float32Array {

	const random = seededRandom( seed );
	return Float32Array.from( { length: 27 * count }, () => random() * 2 - 0.5 );

}

/** A volume from scratch on `volume`'s active probes, and the map from its indices to `volume`'s ids. */
function fromScratch( volume: LightProbeVolume ): LightProbeVolume {

	const ids: number[] = [];
	for ( let i = 0; i < volume.count; i ++ ) if ( volume.isProbeActive( i ) ) ids.push( i );
	const positions = ids.flatMap( ( id ) => Array.from( volume.positions.subarray( 3 * id, 3 * id + 3 ) ) );
	const sh = new Float32Array( 27 * ids.length );
	ids.forEach( ( id, k ) => sh.set( volume.sh.subarray( 27 * id, 27 * id + 27 ), 27 * k ) );
	return new LightProbeVolume( { positions, sh } );

}

/** Largest difference of sample() from a volume built from scratch, at `count` points in and around [−2, 12]³. */
function sampleDifference( volume: LightProbeVolume, seed: number, count = 300 ): number {

	const scratch = fromScratch( volume ), random = seededRandom( seed );
	const a = new Float32Array( 27 ), b = new Float32Array( 27 );
	let worst = 0;
	for ( let n = 0; n < count; n ++ ) {

		const p = [ random() * 14 - 2, random() * 14 - 2, random() * 14 - 2 ];
		volume.sample( p, a );
		scratch.sample( p, b );
		for ( let k = 0; k < 27; k ++ ) worst = Math.max( worst, Math.abs( a[ k ] - b[ k ] ) );

	}

	return worst;

}

function litObject( x: number, y: number, z: number ): THREE.Mesh {

	const mesh = new THREE.Mesh( new THREE.BoxGeometry( 0.2, 0.2, 0.2 ), new THREE.MeshStandardMaterial() );
	mesh.position.set( x, y, z );
	return mesh;

}

describe( 'LightProbeVolume incremental edits', () => {

	it( 'moves, adds and removes give the same light as a volume built from scratch (sample and object uniforms)', () => {

		const volume = new LightProbeVolume( { positions: randomPoints( 40, 3, 10 ), sh: randomSH( 40, 4 ) } );
		expect( volume.interpolator ).toBeInstanceOf( TetrahedralMesh );
		expect( volume.interpolator ).not.toBeInstanceOf( IncrementalTetrahedralMesh );
		const objects = [ litObject( 5, 5, 5 ), litObject( 1, 9, 2 ), litObject( 11, - 1, 4 ) ];
		for ( const object of objects ) volume.add( object );
		const random = seededRandom( 9 );
		let adds = 0, removes = 0, moves = 0;
		for ( let step = 0; step < 40; step ++ ) {

			const active: number[] = [];
			for ( let i = 0; i < volume.count; i ++ ) if ( volume.isProbeActive( i ) ) active.push( i );
			const roll = random(), pick = active[ Math.floor( random() * active.length ) ];
			const position = [ random() * 11 - 0.5, random() * 11 - 0.5, random() * 11 - 0.5 ];
			if ( roll < 0.4 ) { volume.moveProbe( pick, position ); moves ++; }
			else if ( roll < 0.7 ) { volume.addProbe( { x: position[ 0 ], y: position[ 1 ], z: position[ 2 ] } ); adds ++; }
			else { volume.removeProbe( pick ); removes ++; }
			// Objects move too, so their hints are exercised across edits.
			objects[ step % 3 ].position.x += 0.3;
			volume.update();
			if ( step % 8 !== 7 ) continue;
			expect( sampleDifference( volume, step ) ).toBeLessThan( 1e-5 );
			const scratch = fromScratch( volume );
			for ( const object of objects ) {

				const twin = litObject( object.position.x, object.position.y, object.position.z );
				scratch.add( twin );
				const mine = volume.getUniforms( object )!.probeVolumeMatrices.value, theirs = scratch.getUniforms( twin )!.probeVolumeMatrices.value;
				for ( let k = 0; k < mine.length; k ++ ) expect( mine[ k ] ).toBeCloseTo( theirs[ k ], 4 );

			}

		}

		expect( Math.min( adds, removes, moves ) ).toBeGreaterThan( 5 );
		expect( volume.interpolator ).toBeInstanceOf( IncrementalTetrahedralMesh );
		expect( volume.count ).toBe( 40 + adds );
		expect( volume.sh.length ).toBe( 27 * volume.count );
		expect( volume.names.length ).toBe( volume.count );
		expect( volume.roles.length ).toBe( volume.count );
		expect( volume.interpolator.probeCount ).toBe( volume.count );

	} );

	it( 'addProbe: id = previous count, SH = the light interpolated there before it was added, dirty until captured; options.sh is used as given', () => {

		const volume = new LightProbeVolume( { positions: randomPoints( 20, 5, 10 ), sh: randomSH( 20, 6 ), names: Array.from( { length: 20 }, ( _, i ) => `p${i}` ) } );
		const at = [ 4, 5, 6 ];
		const before = volume.sample( at );
		const oldSH = volume.sh;
		const id = volume.addProbe( at, { name: 'new', role: 'bleed' } );
		expect( id ).toBe( 20 );
		expect( volume.sh ).not.toBe( oldSH );
		expect( Array.from( volume.sh.subarray( 27 * id, 27 * id + 27 ) ) ).toEqual( Array.from( before ) );
		// The picture does not change at the new probe (its SH is the blend it replaces).
		const after = volume.sample( at );
		for ( let k = 0; k < 27; k ++ ) expect( after[ k ] ).toBeCloseTo( before[ k ], 5 );
		expect( volume.names[ id ] ).toBe( 'new' );
		expect( volume.roles[ id ] ).toBe( 'bleed' );
		expect( Array.from( volume.positions.subarray( 3 * id, 3 * id + 3 ) ) ).toEqual( at );
		expect( volume.dirtyProbes() ).toEqual( [ id ] );

		const given = new Float32Array( 27 ).fill( 0.25 );
		const second = volume.addProbe( [ 1, 2, 3 ], { sh: given } );
		expect( Array.from( volume.sh.subarray( 27 * second, 27 * second + 27 ) ) ).toEqual( Array.from( given ) );
		expect( volume.dirtyProbes() ).toEqual( [ id ] );
		volume.moveProbe( 3, [ 5, 5, 5 ] );
		expect( volume.dirtyProbes() ).toEqual( [ 3, id ] );
		volume.removeProbe( id );
		expect( volume.dirtyProbes() ).toEqual( [ 3 ] );
		expect( Array.from( volume.sh.subarray( 27 * id, 27 * id + 27 ) ).every( ( v ) => v === 0 ) ).toBe( true );
		expect( volume.isProbeActive( id ) ).toBe( false );
		expect( volume.count ).toBe( 22 );

	} );

	it( 'bad edits throw clear errors and change nothing', async () => {

		const volume = new LightProbeVolume( { positions: randomPoints( 12, 7, 10 ) } );
		expect( () => volume.moveProbe( 12, [ 0, 0, 0 ] ) ).toThrow( /LightProbeVolume\.moveProbe: 12 is not a probe of this volume/ );
		expect( () => volume.moveProbe( 0, [ NaN, 0, 0 ] ) ).toThrow( /LightProbeVolume\.moveProbe: position must be three finite numbers/ );
		expect( () => volume.addProbe( [ 1, 1, 1 ], { role: 'sun' as never } ) ).toThrow( /options\.role is "sun"/ );
		expect( () => volume.addProbe( [ 1, 1, 1 ], { sh: [ 1, 2 ] } ) ).toThrow( /options\.sh must have length 27/ );
		const p = Array.from( volume.positions.subarray( 3, 6 ) );
		expect( () => volume.moveProbe( 0, p ) ).toThrow( DegenerateInputError );
		volume.removeProbe( 5 );
		expect( () => volume.removeProbe( 5 ) ).toThrow( /removeProbe: 5 is not a probe of this volume/ );
		await expect( volume.capture( {} as THREE.WebGLRenderer, new THREE.Scene(), { indices: [ 5 ] } ) ).rejects.toThrow( /options\.indices holds 5, a removed probe/ );
		// Down to probes 0..3 (ids 4 and 6..11 removed); a fifth removal would leave 3.
		for ( const i of [ 4, 6, 7, 8, 9, 10, 11 ] ) volume.removeProbe( i );
		expect( () => volume.removeProbe( 0 ) ).toThrow( DegenerateInputError );
		expect( volume.isProbeActive( 0 ) ).toBe( true );
		expect( sampleDifference( volume, 1 ) ).toBeLessThan( 1e-6 );

		const zoned = new LightProbeVolume( { positions: randomPoints( 12, 7, 10 ), zones: [ { name: 'a', probes: [ 0, 1, 2, 3, 4, 5 ] } ] } );
		expect( () => zoned.moveProbe( 0, [ 1, 1, 1 ] ) ).toThrow( /moveProbe: the volume has lighting zones.*create a new LightProbeVolume/ );
		const flat = new LightProbeVolume( { positions: [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 ] } );
		expect( () => flat.addProbe( [ 0.5, 0.5, 1 ] ) ).toThrow( /addProbe: probes can be edited only with a tetrahedral interpolator; this volume's is a PlanarMesh/ );

	} );

} );
