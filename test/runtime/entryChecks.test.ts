/**
 * Regression tests of issue 12's items on values checked where they enter (no GPU): SH beyond the
 * float32 range, far probes, null materials, JSON text, and the one set of rules the codec, the
 * CLI's inspect and the runtime share, so that every file the codec accepts loads.
 */

import { describe, expect, it, vi } from 'vitest';
import * as THREE from 'three';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeExporter } from '../../src/runtime/LightProbeVolumeExporter.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import {
	BakedVolumeError, bakedVolumeFromJSON, bakedVolumeToJSON, decodeBakedVolume, encodeBakedVolume, type BakedVolumeInput,
} from '../../src/io/index.js';
import { fixChecksum, fourCC, makeVolume, readSections, writeSections } from '../io/helpers.js';

const loader = new LightProbeVolumeLoader();
const exporter = new LightProbeVolumeExporter();

/** A 3 × 3 × 3 grid (27 probes) with SH = a linear field in L00 red and small values elsewhere. */
function grid( scale = 1, offset = 0 ): { positions: Float64Array; sh: Float32Array } {

	const positions = new Float64Array( 81 );
	let i = 0;
	for ( let x = 0; x < 3; x ++ ) for ( let y = 0; y < 3; y ++ ) for ( let z = 0; z < 3; z ++ ) {

		positions.set( [ offset + scale * x, offset + scale * y, offset + scale * z ], 3 * i ++ );

	}

	const sh = new Float32Array( 27 * 27 );
	for ( let p = 0; p < 27; p ++ ) for ( let k = 0; k < 27; k ++ ) sh[ 27 * p + k ] = k === 0 ? 1 + p : 0.01 * k;
	return { positions, sh };

}

function expectBaked( code: string, call: () => unknown, message: RegExp ): void {

	let error: unknown = null;
	try {

		call();

	} catch ( caught ) {

		error = caught;

	}

	expect( error ).toBeInstanceOf( BakedVolumeError );
	expect( ( error as BakedVolumeError ).code ).toBe( code );
	expect( ( error as Error ).message ).toMatch( message );

}

/** A binary file of `input` with one float written into a section at a byte offset, checksum fixed. */
function patched( input: BakedVolumeInput, id: string, at: number, write: ( view: DataView, at: number ) => void ): ArrayBuffer {

	const { header, sections } = readSections( encodeBakedVolume( input ) );
	const section = sections.find( ( s ) => s.id === fourCC( id ) )!;
	write( new DataView( section.bytes.buffer ), at );
	return writeSections( header, sections );

}

describe( 'values checked where they enter', () => {

	it( 'SH beyond ±1e30 (1e39 is Infinity in float32): the constructor, addProbe, the encoder and the decoder refuse them with named errors', () => {

		const { positions, sh } = grid();
		const big = Array.from( sh ), L00 = 0, L20 = 18;
		big[ 3 ] = 1e39;
		expect( () => new LightProbeVolume( { positions, sh: big } ) ).toThrow( /^LightProbeVolume: sh\[3\] is 1e\+39; probe SH values must be within ±1\.00e\+30/ );
		const bad = sh.slice();
		bad[ L00 ] = - 3.4e38;
		bad[ L20 ] = 3.4e38;
		expect( () => new LightProbeVolume( { positions, sh: bad } ) ).toThrow( RangeError );
		expectBaked( 'range', () => encodeBakedVolume( { positions, sh: bad } ), /^encodeBakedVolume: sh\[0\] is -3\.\d+e\+38; probe SH values must be within ±1\.00e\+30/ );
		expectBaked( 'range', () => bakedVolumeFromJSON( { ...bakedVolumeToJSON( { positions, sh } ), sh: Array.from( bad ) } ), /bakedVolumeFromJSON: sh\[0\]/ );
		// A file written by another writer: L00 = −3.4e38 and L20 = +3.4e38 in the SH section.
		const file = patched( { positions, sh }, 'SH  ', 0, ( view ) => {

			view.setFloat32( 4 * L00, - 3.4e38, true );
			view.setFloat32( 4 * L20, 3.4e38, true );

		} );
		expectBaked( 'range', () => decodeBakedVolume( file ), /^decodeBakedVolume: sh\[0\] is -3\.\d+e\+38/ );
		expectBaked( 'range', () => loader.parse( file ), /^LightProbeVolumeLoader\.parse: sh\[0\] is -3\.\d+e\+38/ );
		const volume = new LightProbeVolume( { positions, sh } );
		expect( () => volume.addProbe( [ 0.5, 0.5, 0.5 ], { sh: new Float32Array( 27 ).fill( 2e30 ) } ) ).toThrow( /^LightProbeVolume\.addProbe: options\.sh\[0\] is 2\.?\d*e\+30/ );
		// ±1e30 itself is accepted.
		expect( () => new LightProbeVolume( { positions, sh: sh.map( ( v, i ) => i === 5 ? - 1e30 : v ) } ) ).not.toThrow();

	} );

	it( 'update() never uploads a non-finite value: SH written into volume.sh directly give zero matrices and a RangeError naming the object and the probe', () => {

		const { positions, sh } = grid();
		const volume = new LightProbeVolume( { positions, sh } );
		const ball = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshStandardMaterial() );
		ball.name = 'ball';
		ball.position.set( 0.1, 0.1, 0.1 ); // probe 0 weighs most
		const other = new THREE.Mesh( new THREE.SphereGeometry( 0.2 ), new THREE.MeshStandardMaterial() );
		other.position.set( 1.5, 1.5, 1.5 );
		volume.add( ball ).add( other );
		const matrices = volume.getUniforms( ball )!.probeVolumeMatrices.value;
		const otherMatrices = volume.getUniforms( other )!.probeVolumeMatrices.value;
		expect( matrices.some( ( v ) => v !== 0 ) ).toBe( true );
		for ( const [ l00, l20 ] of [ [ - 3.4e38, 3.4e38 ], [ Infinity, 0 ], [ NaN, 0 ] ] ) {

			volume.sh[ 0 ] = l00; // probe 0 is a corner of the ball's cell
			volume.sh[ 18 ] = l20;
			const before = Array.from( otherMatrices );
			other.position.x += 0.01;
			expect( () => volume.update() ).toThrow( /^LightProbeVolume\.update: the blend for object "ball" is not finite \(probe 0 holds sh\[0\] = / );
			expect( Array.from( matrices ).every( ( v ) => v === 0 ), `${l00}: zero matrices` ).toBe( true );
			expect( Array.from( otherMatrices ).every( Number.isFinite ) ).toBe( true );
			expect( Array.from( otherMatrices ), 'the other object was updated' ).not.toEqual( before );
			volume.sh[ 0 ] = sh[ 0 ];
			volume.sh[ 18 ] = sh[ 18 ];
			volume.update();
			expect( matrices.some( ( v ) => v !== 0 ) ).toBe( true );

		}

		volume.dispose();

	} );

	it( 'probe coordinates beyond ±1e18 (1e154, 1e155: squares and determinants overflow) are refused with code range, not "hull is not convex"', () => {

		const { positions, sh } = grid();
		for ( const far of [ 1e154, 1e155, 1.5e18 ] ) {

			const moved = positions.slice();
			moved[ 4 ] = far;
			expectBaked( 'range', () => encodeBakedVolume( { positions: moved, sh } ), /^encodeBakedVolume: positions\[4\] is [\d.e+]+; probe coordinates must be within ±1e\+18/ );
			expect( () => new LightProbeVolume( { positions: moved, sh } ) ).toThrow( /^LightProbeVolume: positions\[4\] is .* within ±1e\+18/ );
			// Another writer's file: the tetrahedra of the unit grid, one position replaced.
			const file = patched( { ...makeTetrahedralized( positions ), sh }, 'POS ', 8 * 4, ( view, at ) => view.setFloat64( at, far, true ) );
			expectBaked( 'range', () => decodeBakedVolume( file ), /^decodeBakedVolume: positions\[4\] is .* within ±1e\+18/ );

		}

		// Inside the bound, values stay finite: a grid spanning 2e17.
		const huge = grid( 1e17, - 1e17 );
		const volume = loader.parse( exporter.parse( new LightProbeVolume( huge ) ) );
		for ( const p of [ [ 0, 0, 0 ], [ 3e17, - 5e17, 1e18 ], [ - 1e18, 1e18, - 1e18 ] ] ) {

			expect( Array.from( volume.sample( p ) ).every( Number.isFinite ), `sample( ${p} )` ).toBe( true );

		}

	} );

	it( 'add(): a mesh whose material array holds null or undefined is lit (those slots are drawn by nothing, as in three); intensity must be a finite number', () => {

		const { positions, sh } = grid();
		const volume = new LightProbeVolume( { positions, sh } );
		const standard = new THREE.MeshStandardMaterial();
		const mesh = new THREE.Mesh( new THREE.BoxGeometry(), [ null, undefined, standard ] as unknown as THREE.Material[] );
		mesh.position.set( 1, 1, 1 );
		volume.add( mesh );
		expect( volume.getUniforms( mesh ) ).not.toBe( null );
		expect( ( mesh.material as unknown[] )[ 2 ] ).toBe( standard );
		volume.remove( mesh );
		const single = new THREE.Mesh( new THREE.BoxGeometry() );
		( single as unknown as { material: null } ).material = null;
		expect( () => volume.add( single ) ).not.toThrow();
		expect( () => volume.add( new THREE.Mesh(), { intensity: '2' as never } ) ).toThrow( /^LightProbeVolume\.add: options\.intensity must be a finite number, got the string "2"/ );
		expect( () => volume.add( new THREE.Mesh(), { intensity: NaN } ) ).toThrow( /^LightProbeVolume\.add: options\.intensity must be a finite number, got NaN/ );

	} );

	it( 'names: [ 1, 2, 3, 4 ] is refused where it enters (the constructor, the encoder), not in the exporter', () => {

		const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ];
		expect( () => new LightProbeVolume( { positions, names: [ 1, 2, 3, 4 ] as never } ) ).toThrow( /^LightProbeVolume: names\[0\] is number 1; expected a string/ );
		expectBaked( 'argument', () => encodeBakedVolume( { positions, sh: new Float32Array( 108 ), names: [ 1, 2, 3, 4 ] as never } ), /^encodeBakedVolume: names\[0\] is number 1/ );

	} );

	it( 'LightProbeVolumeLoader.parse of malformed JSON text: a BakedVolumeError "json", as bakedVolumeFromJSON gives, not a raw SyntaxError', () => {

		expectBaked( 'json', () => loader.parse( '{"format": ' ), /^LightProbeVolumeLoader\.parse: not valid JSON/ );
		const text = JSON.stringify( exporter.parse( new LightProbeVolume( grid() ), { binary: false } ) );
		expect( loader.parse( text ).count ).toBe( 27 );

	} );

} );

/** Positions with their tetrahedralization, as the runtime writes it. */
function makeTetrahedralized( positions: Float64Array ): BakedVolumeInput {

	const data = new LightProbeVolume( { positions } ).toBakedData();
	return { positions, sh: data.sh, tetrahedra: data.tetrahedra, neighbors: data.neighbors };

}

describe( 'one set of rules for the codec, inspect and the runtime', () => {

	it( 'a zone named "" (and zones of one or two probes) written by encodeBakedVolume loads in the runtime, binary and JSON', () => {

		const { positions, sh } = grid();
		const input: BakedVolumeInput = {
			positions, sh, zones: [ { name: '', probes: [ 0, 1, 3, 9 ] }, { name: 'one', probes: [ 13 ] }, { name: 'two', probes: [ 0, 26 ] } ],
		};
		const file = encodeBakedVolume( input );
		expect( decodeBakedVolume( file ).zones.map( ( z ) => z.name ) ).toEqual( [ '', 'one', 'two' ] ); // what inspect reads
		const text = JSON.stringify( bakedVolumeToJSON( input ) );
		for ( const volume of [ loader.parse( file ), loader.parse( text ) ] ) {

			expect( volume.zones!.zones.map( ( z ) => z.name ) ).toEqual( [ '', 'one', 'two' ] );
			expect( volume.sample( [ 0, 0, 0 ], new Float32Array( 27 ), { zone: '' } )[ 0 ] ).toBeCloseTo( 1, 6 );
			expect( volume.sample( [ 9, 9, 9 ], new Float32Array( 27 ), { zone: 'one' } )[ 0 ] ).toBeCloseTo( 14, 6 );
			expect( volume.sample( [ 1, 1, 1 ], new Float32Array( 27 ), { zone: 'two' } )[ 0 ] ).toBeCloseTo( 14, 5 ); // halfway from 1 to 27

		}

	} );

	it( 'stored tetrahedra that do not fill the convex hull (which the format allows) load: the runtime rebuilds its tetrahedralization, with a warning', () => {

		const { positions, sh } = grid();
		const { tetrahedra, neighbors } = makeTetrahedralized( positions ) as unknown as { tetrahedra: Uint32Array; neighbors: Int32Array };
		// Drop a tetrahedron with a hull face: the rest is still a valid set of linked tetrahedra, with a dent.
		const ids = Array.from( { length: tetrahedra.length / 4 }, ( _, t ) => t );
		const dropped = ids.find( ( t ) => neighbors.subarray( 4 * t, 4 * t + 4 ).includes( - 1 ) )!;
		const kept = ids.filter( ( t ) => t !== dropped );
		const renumber = ( t: number ) => t < 0 || t === dropped ? - 1 : t - ( t > dropped ? 1 : 0 );
		const tets = Uint32Array.from( kept.flatMap( ( t ) => Array.from( tetrahedra.subarray( 4 * t, 4 * t + 4 ) ) ) );
		const links = Int32Array.from( kept.flatMap( ( t ) => Array.from( neighbors.subarray( 4 * t, 4 * t + 4 ), renumber ) ) );
		const file = encodeBakedVolume( { positions, sh, tetrahedra: tets, neighbors: links } ); // the codec accepts it
		const warn = vi.spyOn( console, 'warn' ).mockImplementation( () => {} );
		const volume = loader.parse( file );
		expect( warn ).toHaveBeenCalledTimes( 1 );
		expect( String( warn.mock.calls[ 0 ][ 0 ] ) ).toMatch( /^LightProbeVolume\.fromBakedData: the stored tetrahedra cannot be used .*rebuilt from the positions/ );
		warn.mockRestore();
		expect( volume.sample( [ 1, 1, 1 ] )[ 0 ] ).toBeCloseTo( 14, 5 );
		expect( volume.sample( [ 0.2, 0.1, 0.05 ] ).every( Number.isFinite ) ).toBe( true );

	} );

	it( 'every volume the test helpers write (names, roles, zones of one probe, capture settings) loads in the runtime', () => {

		for ( const [ n, seed ] of [ [ 12, 2 ], [ 85, 3 ], [ 30, 5 ] ] ) {

			const file = encodeBakedVolume( makeVolume( n, seed ) );
			const volume = loader.parse( file );
			expect( volume.count ).toBe( n );
			// The same data back, but for the volume's bounds box, which the runtime does not keep (it writes the probes' box).
			const plain = ( d: ReturnType<typeof decodeBakedVolume> ) => JSON.stringify(
				{ ...d, bounds: null }, ( _, v ) => ArrayBuffer.isView( v ) ? Array.from( v as Float64Array ) : v,
			);
			expect( plain( decodeBakedVolume( exporter.parse( volume ) ) ) ).toBe( plain( decodeBakedVolume( file ) ) );

		}

	} );

	it( 'zone names are unique and zones hold at least one probe, for the encoder and the decoder as for the runtime', () => {

		const { positions, sh } = grid();
		expectBaked( 'range', () => encodeBakedVolume( { positions, sh, zones: [ { name: 'a', probes: [ 0 ] }, { name: 'a', probes: [ 1 ] } ] } ), /^encodeBakedVolume: zones\[1\]\.name "a" is used by an earlier zone/ );
		expectBaked( 'count', () => encodeBakedVolume( { positions, sh, zones: [ { name: 'a', probes: [] } ] } ), /^encodeBakedVolume: zones\[0\]\.probes is empty/ );
		expect( () => new LightProbeVolume( { positions, sh, zones: [ { name: 'a', probes: [ 0 ] }, { name: 'a', probes: [ 1 ] } ] } ) ).toThrow( /^LightProbeVolume: zones\[1\]\.name "a" is used by an earlier zone/ );
		// Another writer's file with two zones called "ab": the second record's name bytes rewritten.
		const file = encodeBakedVolume( { positions, sh, zones: [ { name: 'ab', probes: [ 0 ] }, { name: 'cd', probes: [ 1 ] } ] } );
		const { header, sections } = readSections( file );
		const zone = sections.find( ( s ) => s.id === fourCC( 'ZONE' ) )!;
		const second = 16 + 8 + 8; // record 0: 16-byte head, name padded to 8, one probe padded to 8
		zone.bytes.set( [ 0x61, 0x62 ], second + 16 );
		expectBaked( 'range', () => decodeBakedVolume( writeSections( header, sections ) ), /^decodeBakedVolume: zones\[1\]\.name "ab" is used by an earlier zone/ );
		fixChecksum( new Uint8Array( file ) );

	} );

} );
