import { describe, expect, it } from 'vitest';
import { BakedVolumeError, LightProbeVolume } from '../../src/index.js';
import { GridInterpolator, PlanarMesh, TetrahedralMesh, tetrahedralize } from '../../src/math.js';
import { decodeBakedVolume } from '../../src/format.js';
import { LightProbeVolumeExporter } from '../../src/runtime/LightProbeVolumeExporter.js';
import { LightProbeVolumeLoader } from '../../src/runtime/LightProbeVolumeLoader.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { randomVolume as createRandomVolume } from '../helpers/randomVolume.js';

/*
 * LightProbeVolume ↔ baked files through LightProbeVolumeExporter / LightProbeVolumeLoader (the
 * codec itself is tested in test/io, the loader's forms and HTTP in LightProbeVolumeLoader.test.ts):
 * what a game loads must light objects exactly as the volume that was baked, without re-tetrahedralizing.
 */

const loader = new LightProbeVolumeLoader();
const exporter = new LightProbeVolumeExporter();

const randomVolume = ( count: number, seed: number ): LightProbeVolume => createRandomVolume( count, seed, 'test bake' );

function samplesEqual( a: LightProbeVolume, b: LightProbeVolume, tolerance: number ): void {

	const random = mulberry32( 99 );
	const sa = new Float32Array( 27 ), sb = new Float32Array( 27 );
	for ( let k = 0; k < 300; k ++ ) {

		// Inside and outside the probes' hull (outer cells), with and without zones.
		const p = [ 14 * random() - 2, 14 * random() - 2, 14 * random() - 2 ];
		const zone = k % 3 === 0 ? { zone: 'west' } : undefined;
		a.sample( p, sa, zone );
		b.sample( p, sb, zone );
		for ( let j = 0; j < 27; j ++ ) expect( Math.abs( sa[ j ] - sb[ j ] ), `sample ${k} coefficient ${j}` ).toBeLessThanOrEqual( tolerance * ( 1 + Math.abs( sa[ j ] ) ) );

	}

}

describe( 'LightProbeVolume baked files', () => {

	it( 'binary, float32: everything comes back, and objects are lit exactly as before', () => {

		const volume = randomVolume( 60, 1 );
		const loaded = loader.parse( exporter.parse( volume ) );
		expect( Array.from( loaded.positions ) ).toEqual( Array.from( volume.positions ) );
		expect( Array.from( loaded.sh ) ).toEqual( Array.from( volume.sh ) );
		expect( loaded.names ).toEqual( volume.names );
		expect( loaded.roles ).toEqual( volume.roles );
		expect( loaded.zones!.zones.map( ( z ) => [ z.name, Array.from( z.probes ), Array.from( z.bounds ) ] ) ).toEqual( volume.zones!.zones.map( ( z ) => [ z.name, Array.from( z.probes ), Array.from( z.bounds ) ] ) );
		expect( loaded.captureSettings ).toEqual( volume.captureSettings );
		expect( loaded.metadata ).toBe( 'test bake' );
		expect( loaded.interpolator ).toBeInstanceOf( TetrahedralMesh );
		expect( Array.from( ( loaded.interpolator as TetrahedralMesh ).tetrahedra ) ).toEqual( Array.from( ( volume.interpolator as TetrahedralMesh ).tetrahedra ) );
		samplesEqual( volume, loaded, 0 );

	} );

	it( 'binary, float16: smaller, and the light within half precision', () => {

		const volume = randomVolume( 60, 2 );
		const f32 = exporter.parse( volume ), f16 = exporter.parse( volume, { precision: 'float16' } );
		expect( f32.byteLength - f16.byteLength ).toBe( 60 * 27 * 2 );
		samplesEqual( volume, loader.parse( f16 ), 2 ** - 10 );

	} );

	it( 'JSON (object or text): the same volume', () => {

		const volume = randomVolume( 30, 3 );
		samplesEqual( volume, loader.parse( exporter.parse( volume, { binary: false } ) ), 0 );
		samplesEqual( volume, loader.parse( JSON.stringify( exporter.parse( volume, { binary: false } ) ) ), 0 );

	} );

	it( 'uses the stored tetrahedralization as it is: a reordered one comes back reordered, not rebuilt', () => {

		const volume = randomVolume( 40, 4 );
		const data = decodeBakedVolume( exporter.parse( volume ) );
		// Reverse the tetrahedra and remap the neighbour links: the same mesh, in an order
		// tetrahedralize() would not produce.
		const n = data.tetrahedra.length / 4;
		const tetrahedra = new Uint32Array( data.tetrahedra.length ), neighbors = new Int32Array( data.neighbors.length );
		for ( let t = 0; t < n; t ++ ) {

			for ( let i = 0; i < 4; i ++ ) {

				tetrahedra[ 4 * ( n - 1 - t ) + i ] = data.tetrahedra[ 4 * t + i ];
				const neighbor = data.neighbors[ 4 * t + i ];
				neighbors[ 4 * ( n - 1 - t ) + i ] = neighbor < 0 ? - 1 : n - 1 - neighbor;

			}

		}

		const loaded = LightProbeVolume.fromBakedData( { ...data, tetrahedra, neighbors } );
		expect( Array.from( ( loaded.interpolator as TetrahedralMesh ).tetrahedra ) ).toEqual( Array.from( tetrahedra ) );
		expect( Array.from( tetrahedralize( data.positions ).tetrahedra ) ).not.toEqual( Array.from( tetrahedra ) );
		samplesEqual( volume, loaded, 0 );

	} );

	it( 'a trilinear or planar volume is stored without tetrahedra and loads with the default interpolator', () => {

		const grid = new GridInterpolator( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 3, 3, 3 ] );
		const gridVolume = new LightProbeVolume( { positions: grid.positions, interpolator: grid } );
		expect( decodeBakedVolume( exporter.parse( gridVolume ) ).tetrahedra.length ).toBe( 0 );
		expect( loader.parse( exporter.parse( gridVolume ) ).interpolator ).toBeInstanceOf( TetrahedralMesh );
		const flat = new LightProbeVolume( { positions: [ 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0.5, 0, 2 ] } );
		expect( loader.parse( exporter.parse( flat ) ).interpolator ).toBeInstanceOf( PlanarMesh );

	} );

	it( 'a damaged file gives a BakedVolumeError naming the problem, never a volume', () => {

		const buffer = exporter.parse( randomVolume( 20, 5 ) );
		expect( () => loader.parse( buffer.slice( 0, buffer.byteLength - 9 ) ) ).toThrow( BakedVolumeError );
		const flipped = new Uint8Array( buffer.slice( 0 ) );
		flipped[ 200 ] ^= 0x10;
		expect( () => loader.parse( flipped ) ).toThrow( /corrupt/i );
		expect( () => loader.parse( '{"format": "something else"}' ) ).toThrow( BakedVolumeError );

	} );

} );

describe( 'LightProbeVolume baked files after incremental edits', () => {

	it( 'removed probes are left out (live probes renumbered), and the loaded volume lights objects as the edited one', () => {

		const volume = randomVolume( 40, 6 );
		// Zones cannot follow edits: a volume without them.
		const plain = new LightProbeVolume( { positions: volume.positions, sh: volume.sh, names: volume.names, roles: volume.roles } );
		plain.removeProbe( 3 );
		plain.moveProbe( 10, [ 5, 5, 5 ] );
		plain.removeProbe( 17 );
		const added = plain.addProbe( [ 1, 2, 3 ], { name: 'new', sh: new Float32Array( 27 ).fill( 0.5 ) } );
		const loaded = loader.parse( exporter.parse( plain ) );
		expect( loaded.count ).toBe( 39 );
		expect( loaded.names ).not.toContain( 'probe 3' );
		expect( loaded.names ).not.toContain( 'probe 17' );
		expect( loaded.names.at( - 1 ) ).toBe( 'new' );
		expect( added ).toBe( 40 );
		const random = mulberry32( 7 );
		const a = new Float32Array( 27 ), b = new Float32Array( 27 );
		for ( let k = 0; k < 200; k ++ ) {

			const p = [ 12 * random() - 1, 12 * random() - 1, 12 * random() - 1 ];
			plain.sample( p, a );
			loaded.sample( p, b );
			for ( let j = 0; j < 27; j ++ ) expect( b[ j ] ).toBeCloseTo( a[ j ], 6 );

		}

	} );

} );
