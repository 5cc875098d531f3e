import { describe, expect, it } from 'vitest';
import {
	encodeBakedVolume, decodeBakedVolume, bakedVolumeToJSON, bakedVolumeFromJSON, validateBakedVolume,
	type BakedVolumeData, type BakedVolumeInput,
} from '../../src/io/index.js';
import { fromFloat16Bits } from '../../src/io/float16.js';
import { readFileSync } from 'node:fs';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { gridPoints } from '../helpers/pointSets.js';
import {
	makeVolume, independentCheck, readSections, writeSections, fourCC, referenceCRC32, expectError, edited, sectionOffset,
} from './helpers.js';

function expectSame( d: BakedVolumeData, input: BakedVolumeInput ): void {

	expect( Array.from( d.positions ) ).toEqual( Array.from( input.positions ) );
	expect( Array.from( d.tetrahedra ) ).toEqual( Array.from( input.tetrahedra ?? [] ) );
	expect( Array.from( d.neighbors ) ).toEqual( Array.from( input.neighbors ?? [] ) );
	expect( d.names ).toEqual( input.names ?? d.names.map( () => '' ) );
	expect( d.roles ).toEqual( input.roles ?? d.roles.map( () => 'fill' ) );
	expect( d.zones.map( ( z ) => ( { name: z.name, probes: Array.from( z.probes ), bounds: Array.from( z.bounds ) } ) ) ).toEqual(
		( input.zones ?? [] ).map( ( z ) => ( { name: z.name, probes: Array.from( z.probes ), bounds: Array.from( z.bounds ?? [] ) } ) ) );
	expect( Array.from( d.bounds ) ).toEqual( Array.from( input.bounds ?? d.bounds ) );
	expect( d.capture ).toEqual( input.capture ?? {} );
	expect( d.metadata ).toEqual( input.metadata ?? '' );

}

function tableEntry( buffer: ArrayBuffer, id: string ): number {

	const view = new DataView( buffer );
	for ( let s = 0; s < view.getUint32( 40, true ); s ++ ) if ( view.getUint32( 64 + 16 * s, true ) === fourCC( id ) ) return 64 + 16 * s;
	throw new Error( `no section ${id}` );

}

const volume = makeVolume( 40, 1 );
const file = encodeBakedVolume( volume );

describe( 'baked volume: round trips', () => {

	it( 'float32: every field decodes exactly, and the result passes the brute-force check', () => {

		const d = decodeBakedVolume( file );
		expectSame( d, volume );
		expect( Array.from( d.sh ) ).toEqual( Array.from( volume.sh ) );
		expect( independentCheck( d ) ).toBeNull();

	} );

	it( 'the header holds magic, version 1.0, the CRC-32 of bytes 16.., the counts, and 8-aligned sections (docs/format.md)', () => {

		const view = new DataView( file ), bytes = new Uint8Array( file );
		expect( Array.from( bytes.subarray( 0, 8 ) ) ).toEqual( [ 0xAB, 0x4C, 0x50, 0x56, 0x0D, 0x0A, 0x1A, 0x0A ] );
		expect( [ view.getUint16( 8, true ), view.getUint16( 10, true ) ] ).toEqual( [ 1, 0 ] );
		expect( view.getUint32( 12, true ) ).toBe( referenceCRC32( bytes, 16, file.byteLength ) );
		expect( view.getUint32( 16, true ) ).toBe( file.byteLength );
		expect( view.getUint32( 20, true ) ).toBe( 64 );
		expect( view.getUint32( 24, true ) ).toBe( 0 );
		expect( view.getUint32( 28, true ) ).toBe( 40 );
		expect( view.getUint32( 32, true ) ).toBe( volume.tetrahedra.length / 4 );
		expect( view.getUint32( 36, true ) ).toBe( 2 );
		const names = volume.names!.reduce( ( n, s ) => n + new TextEncoder().encode( s ).length, 0 );
		expect( view.getUint32( 44, true ) ).toBe( names );
		const { sections } = readSections( file );
		expect( sections.map( ( s ) => String.fromCharCode( ...new Uint8Array( new Uint32Array( [ s.id ] ).buffer ) ) ) ).toEqual( [ 'POS ', 'SH  ', 'TETS', 'NBRS', 'ROLE', 'NAME', 'ZONE', 'BNDS', 'CAPT', 'META' ] );
		for ( let s = 0; s < sections.length; s ++ ) expect( view.getUint32( 64 + 16 * s + 8, true ) % 8 ).toBe( 0 );
		// POS holds float64 x, y, z little-endian.
		expect( view.getFloat64( sectionOffset( file, 'POS ' ) + 8 * 4, true ) ).toBe( volume.positions[ 4 ] );

	} );

	it( 'float16: SH within half precision (relative 2^−11, absolute 2^−25 below 2^−14), everything else exact', () => {

		const input = { ...volume, sh: Float32Array.from( volume.sh ) };
		input.sh.set( [ 1e-7, - 3e-6, 6.1e-5, 65504, - 65504, 0, - 0 ], 0 ); // subnormals, the largest half, signed zeros
		const buffer = encodeBakedVolume( input, { precision: 'float16' } );
		expect( new DataView( buffer ).getUint32( 24, true ) ).toBe( 1 );
		expect( buffer.byteLength ).toBeLessThan( file.byteLength - 40 * 54 + 8 );
		const d = decodeBakedVolume( buffer );
		expectSame( d, input );
		for ( let i = 0; i < input.sh.length; i ++ ) {

			const v = input.sh[ i ], err = Math.abs( d.sh[ i ] - v );
			expect( err ).toBeLessThanOrEqual( Math.abs( v ) >= 2 ** - 14 ? Math.abs( v ) * 2 ** - 11 : 2 ** - 25 );

		}

		expect( d.sh[ 0 ] ).toBe( fromFloat16Bits( 2 ) ); // 1e-7 = 1.68 units of 2^−24 → 2 units
		expect( d.sh[ 3 ] ).toBe( 65504 );
		expect( Object.is( d.sh[ 6 ], - 0 ) ).toBe( true );

	} );

	it( 'float16 overflow: an SH value beyond ±65504 is an error naming the index (code float16-overflow), not a clamp', () => {

		const sh = Float32Array.from( volume.sh );
		sh[ 100 ] = 70000;
		expectError( 'float16-overflow', () => encodeBakedVolume( { ...volume, sh }, { precision: 'float16' } ), /sh\[100\] = 70000.*float32/ );
		expect( decodeBakedVolume( encodeBakedVolume( { ...volume, sh } ) ).sh[ 100 ] ).toBe( 70000 ); // float32 keeps it

	} );

	it( 'decodes from an aligned ArrayBuffer as views (no copy) and from a misaligned Node Buffer by copying, with equal results; trailing bytes are ignored', () => {

		const aligned = decodeBakedVolume( file );
		expect( aligned.positions.buffer ).toBe( file );
		expect( aligned.tetrahedra.buffer ).toBe( file );
		const host = new Uint8Array( file.byteLength + 5 );
		host.set( new Uint8Array( file ), 3 );
		const misaligned = decodeBakedVolume( Buffer.from( host.buffer, 3, file.byteLength + 2 ) );
		expect( misaligned.positions.buffer ).not.toBe( host.buffer );
		expectSame( misaligned, volume );
		expect( Array.from( misaligned.sh ) ).toEqual( Array.from( aligned.sh ) );

	} );

	it( 'a volume without tetrahedra (for a planar or grid interpolator), names, zones or capture settings round-trips with defaults', () => {

		const input = { positions: new Float32Array( [ 0, 0, 0, 1, 0, 0, 0, 0, 1 ] ), sh: new Float32Array( 81 ).fill( 0.5 ) };
		const d = decodeBakedVolume( encodeBakedVolume( input ) );
		expect( Array.from( d.positions ) ).toEqual( [ 0, 0, 0, 1, 0, 0, 0, 0, 1 ] );
		expect( d.tetrahedra.length ).toBe( 0 );
		expect( d.names ).toEqual( [ '', '', '' ] );
		expect( d.roles ).toEqual( [ 'fill', 'fill', 'fill' ] );
		expect( Array.from( d.bounds ) ).toEqual( [ 0, 0, 0, 1, 0, 1 ] ); // the positions' box
		expect( d.capture ).toEqual( {} );
		expect( d.zones ).toEqual( [] );

	} );

	it( 'a 6×5×4 grid (co-spherical everywhere, most probes on the hull) round-trips and passes the brute-force check', () => {

		const positions = gridPoints( 6, 5, 4, 0.1 );
		const { tetrahedra, neighbors } = tetrahedralize( positions );
		const d = decodeBakedVolume( encodeBakedVolume( { positions, sh: new Float32Array( 27 * 120 ), tetrahedra, neighbors } ) );
		expect( Array.from( d.tetrahedra ) ).toEqual( Array.from( tetrahedra ) );
		expect( independentCheck( d ) ).toBeNull();

	} );

	it( 'the JSON example of docs/format.md loads (with its SH filled in)', () => {

		const doc = readFileSync( new URL( '../../docs/format.md', import.meta.url ), 'utf8' );
		const block = /## JSON form[\s\S]*?```json\n([\s\S]*?)```/.exec( doc )![ 1 ];
		const json = JSON.parse( block );
		json.sh = new Array( 27 * json.probeCount ).fill( 0.5 );
		const d = bakedVolumeFromJSON( json );
		expect( d.roles[ 4 ] ).toBe( 'bounce' );
		expect( independentCheck( d ) ).toBeNull();

	} );

	it( 'JSON: stringify → parse → fromJSON gives the same data exactly (float64 positions, float32 SH)', () => {

		const json = bakedVolumeToJSON( volume );
		expect( json.format ).toBe( 'three-capture-lighting/baked-light-probe-volume' );
		expect( json.version ).toEqual( [ 1, 0 ] );
		expect( json.probeCount ).toBe( 40 );
		const d = bakedVolumeFromJSON( JSON.stringify( json ) );
		expectSame( d, volume );
		expect( Array.from( d.sh ) ).toEqual( Array.from( volume.sh ) );
		// The JSON form and the binary form carry the same data.
		expect( bakedVolumeToJSON( decodeBakedVolume( file ) ) ).toEqual( json );

	} );

	it( 'JSON: wrong format tag → bad-magic, newer major → version, later minor accepted, bad fields → their codes', () => {

		const json = bakedVolumeToJSON( volume );
		expectError( 'bad-magic', () => bakedVolumeFromJSON( { ...json, format: 'gltf' } ), /not a baked light probe volume/ );
		expectError( 'version', () => bakedVolumeFromJSON( { ...json, version: [ 2, 0 ] } ), /version 2\.0 is newer than this reader \(supports ≤ 1\.x\)/ );
		expect( bakedVolumeFromJSON( { ...json, version: [ 1, 9 ], futureField: 1 } ).positions.length ).toBe( 120 );
		expectError( 'json', () => bakedVolumeFromJSON( '{ "format": ' ) );
		expectError( 'nan', () => bakedVolumeFromJSON( { ...json, positions: json.positions.map( ( v, i ) => i === 7 ? null as unknown as number : v ) } ) ); // JSON.stringify( NaN ) is null
		expectError( 'range', () => bakedVolumeFromJSON( { ...json, tetrahedra: json.tetrahedra.map( ( v, i ) => i === 5 ? 1.5 : v ) } ), /tetrahedra\[5\]/ );
		expectError( 'count', () => bakedVolumeFromJSON( { ...json, probeCount: 41 } ) );
		expectError( 'range', () => bakedVolumeFromJSON( { ...json, roles: json.roles.map( ( r, i ) => i === 2 ? 'sun' as 'sky' : r ) } ), /roles\[2\] is "sun"/ );

	} );

	it( 'the encoder validates its input the same way (a file it writes always loads)', () => {

		const positions = Float64Array.from( volume.positions as Float64Array );
		positions[ 10 ] = NaN;
		expectError( 'nan', () => encodeBakedVolume( { ...volume, positions } ), /positions\[10\] is NaN/ );
		expectError( 'argument', () => encodeBakedVolume( volume, { precision: 'float8' as 'float16' } ) );
		expectError( 'count', () => encodeBakedVolume( { ...volume, neighbors: volume.neighbors.subarray( 4 ) } ) );
		expectError( 'utf8', () => validateBakedVolume( { ...volume, metadata: 'a\uD800b' } ) );

	} );

} );

describe( 'baked volume: each failure class, by name', () => {

	it( 'truncated: shorter than the magic, than the header, or than the declared length', () => {

		expectError( 'truncated', () => decodeBakedVolume( file.slice( 0, 5 ) ) );
		expectError( 'truncated', () => decodeBakedVolume( file.slice( 0, 40 ) ) );
		expectError( 'truncated', () => decodeBakedVolume( file.slice( 0, file.byteLength - 1 ) ), /truncated/ );
		expectError( 'truncated', () => decodeBakedVolume( new ArrayBuffer( 0 ) ) );

	} );

	it( 'bad-magic: a PNG, JSON text, or zeros give "not a baked light probe volume"', () => {

		const png = new Uint8Array( 100 );
		png.set( [ 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A ] );
		expectError( 'bad-magic', () => decodeBakedVolume( png ), /not a baked light probe volume/ );
		expectError( 'bad-magic', () => decodeBakedVolume( new TextEncoder().encode( JSON.stringify( bakedVolumeToJSON( volume ) ) ) ) );
		expectError( 'bad-magic', () => decodeBakedVolume( new ArrayBuffer( 200 ) ) );

	} );

	it( 'version: a newer major is refused with "version X.Y is newer than this reader"; a newer minor is read; an unknown required section is refused, an unknown optional one skipped', () => {

		expectError( 'version', () => decodeBakedVolume( edited( file, ( v ) => v.setUint16( 8, 2, true ) ) ), /version 2\.0 is newer than this reader \(supports ≤ 1\.x\)/ );
		expectError( 'version', () => decodeBakedVolume( edited( file, ( v ) => v.setUint16( 8, 0, true ) ) ) );
		expectSame( decodeBakedVolume( edited( file, ( v ) => v.setUint16( 10, 7, true ) ) ), volume );
		const { header, sections } = readSections( file );
		const extra = { id: fourCC( 'LMAP' ), flags: 0, bytes: new Uint8Array( [ 1, 2, 3 ] ) };
		expectSame( decodeBakedVolume( writeSections( header, [ extra, ...sections ] ) ), volume );
		expectError( 'version', () => decodeBakedVolume( writeSections( header, [ ...sections, { ...extra, flags: 1 } ] ) ), /'LMAP' is required but unknown/ );

	} );

	it( 'checksum: one flipped bit anywhere after byte 16 gives "corrupted"', () => {

		for ( const at of [ 20, 100, sectionOffset( file, 'SH  ' ) + 13, file.byteLength - 1 ] ) {

			const copy = new Uint8Array( file.slice( 0 ) );
			copy[ at ] ^= 4;
			expectError( 'checksum', () => decodeBakedVolume( copy ), /corrupted/ );

		}

	} );

	it( 'header: header size below 64 or misaligned, reserved flag bits, a file length shorter than the header', () => {

		expectError( 'header', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( 20, 60, true ) ) ) );
		expectError( 'header', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( 20, 68, true ) ) ) );
		expectError( 'header', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( 24, 2, true ) ) ), /reserved/ );

	} );

	it( 'section: misaligned, outside the file, overlapping, duplicated, missing', () => {

		const sh = tableEntry( file, 'SH  ' );
		expectError( 'section', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( sh + 8, v.getUint32( sh + 8, true ) + 4, true ) ) ), /multiple of 8/ );
		expectError( 'section', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( sh + 8, 0xFFFFFFF8, true ) ) ), /outside/ );
		expectError( 'section', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( sh + 8, sectionOffset( file, 'POS ' ) + 8, true ) ) ), /overlap/ );
		expectError( 'section', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( sh, fourCC( 'POS ' ), true ) ) ), /twice/ );
		const { header, sections } = readSections( file );
		expectError( 'section', () => decodeBakedVolume( writeSections( header, sections.filter( ( s ) => s.id !== fourCC( 'POS ' ) ) ) ), /'POS '.*missing/ );

	} );

	it( 'count: hostile counts (0xFFFFFFFF probes, tetrahedra, zones, sections, name bytes) are refused before any allocation', () => {

		for ( const [ offset, name ] of [ [ 28, 'probes' ], [ 32, 'tetrahedra' ], [ 36, 'zones' ], [ 40, 'sections' ], [ 44, 'name bytes' ] ] as const ) {

			const before = process.memoryUsage().arrayBuffers;
			const error = expectError( 'count', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( offset, 0xFFFFFFFF, true ) ) ) );
			expect( process.memoryUsage().arrayBuffers - before, name + ': ' + error.message ).toBeLessThan( 1e6 );

		}

		expectError( 'count', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( 28, 0, true ) ) ) );
		expectError( 'count', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( 28, 39, true ) ) ), /section 'POS ' is 960 bytes but the header's counts need 936/ );

	} );

	it( 'range: a tetrahedron vertex ≥ probe count, a neighbour ≥ tetrahedron count or itself, a role code > 3, a zone probe out of range', () => {

		const tets = sectionOffset( file, 'TETS' ), nbrs = sectionOffset( file, 'NBRS' );
		expectError( 'range', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( tets + 4 * 9, 40, true ) ) ), /tetrahedra\[9\] = 40/ );
		expectError( 'range', () => decodeBakedVolume( edited( file, ( v ) => v.setInt32( nbrs + 4 * 6, 99999, true ) ) ), /neighbors\[6\] = 99999/ );
		expectError( 'range', () => decodeBakedVolume( edited( file, ( v ) => v.setInt32( nbrs + 4 * 6, 1, true ) ) ), /neighbors\[6\] = 1/ );
		expectError( 'range', () => decodeBakedVolume( edited( file, ( v ) => v.setInt32( nbrs + 4 * 6, - 2, true ) ) ) );
		expectError( 'range', () => decodeBakedVolume( edited( file, ( _v, b ) => b[ sectionOffset( file, 'ROLE' ) + 3 ] = 4 ) ), /roles\[3\] has code 4/ );
		const zone = sectionOffset( file, 'ZONE' ); // name 'hall' padded to 8, then its probes
		expectError( 'range', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( zone + 16 + 8 + 4, 1000, true ) ) ), /zones\[0\]\.probes\[1\] = 1000/ );

	} );

	it( 'nan: NaN or Infinity in positions, float32 SH, float16 SH, bounds, zone boxes, capture settings — the field and index are named', () => {

		const pos = sectionOffset( file, 'POS ' ), sh = sectionOffset( file, 'SH  ' );
		expectError( 'nan', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat64( pos + 8 * 5, NaN, true ) ) ), /positions\[5\] is NaN/ );
		expectError( 'nan', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat32( sh + 4 * 30, - Infinity, true ) ) ), /sh\[30\] is -Infinity/ );
		const half = encodeBakedVolume( volume, { precision: 'float16' } );
		expectError( 'nan', () => decodeBakedVolume( edited( half, ( v ) => v.setUint16( sectionOffset( half, 'SH  ' ) + 2 * 8, 0x7E00, true ) ) ), /sh\[8\] is NaN/ );
		expectError( 'nan', () => decodeBakedVolume( edited( half, ( v ) => v.setUint16( sectionOffset( half, 'SH  ' ) + 2 * 9, 0xFC00, true ) ) ), /sh\[9\] is Infinity/ );
		expectError( 'nan', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat64( sectionOffset( file, 'BNDS' ) + 8, NaN, true ) ) ), /bounds\[1\] is NaN/ );
		const zone = sectionOffset( file, 'ZONE' ) + 16 + 8 + 32; // after 'hall' and its 7 probes (28 → 32 bytes)
		expectError( 'nan', () => decodeBakedVolume( edited( file, ( v ) => v.setFloat64( zone + 8 * 2, Infinity, true ) ) ), /zones\[0\]\.bounds\[2\] is Infinity/ );

	} );

	it( 'orientation: swapping two vertices of a tetrahedron (inverted) or repeating one (flat) is refused', () => {

		const tets = sectionOffset( file, 'TETS' );
		expectError( 'orientation', () => decodeBakedVolume( edited( file, ( v ) => {

			const a = v.getUint32( tets + 16 * 3, true );
			v.setUint32( tets + 16 * 3, v.getUint32( tets + 16 * 3 + 4, true ), true );
			v.setUint32( tets + 16 * 3 + 4, a, true );

		} ) ), /tetrahedron 3 .* not positively oriented/ );
		expectError( 'orientation', () => decodeBakedVolume( edited( file, ( v ) => v.setUint32( tets + 16 * 3, v.getUint32( tets + 16 * 3 + 4, true ), true ) ) ) );
		// Moving a probe across the face of its tetrahedra inverts them.
		const t = volume.tetrahedra, p = volume.positions as Float64Array;
		expectError( 'orientation', () => decodeBakedVolume( edited( file, ( v ) => {

			const [ a, b ] = [ t[ 0 ], t[ 1 ] ];
			for ( let k = 0; k < 3; k ++ ) v.setFloat64( sectionOffset( file, 'POS ' ) + 8 * ( 3 * a + k ), 2 * p[ 3 * b + k ] - p[ 3 * a + k ], true );

		} ) ) );

	} );

	it( 'neighbors: a link to a tetrahedron without the shared face, a one-sided link, a hull face inside the mesh', () => {

		const nbrs = sectionOffset( file, 'NBRS' );
		const T = volume.tetrahedra.length / 4;
		// Find an inner face t,i and a tetrahedron that is neither t nor its neighbour there.
		let f = 0;
		while ( volume.neighbors[ f ] < 0 ) f ++;
		const other = ( ( f >> 2 ) + 1 ) % T === volume.neighbors[ f ] ? ( ( f >> 2 ) + 2 ) % T : ( ( f >> 2 ) + 1 ) % T;
		expectError( 'neighbors', () => decodeBakedVolume( edited( file, ( v ) => v.setInt32( nbrs + 4 * f, other, true ) ) ) );
		expectError( 'neighbors', () => decodeBakedVolume( edited( file, ( v ) => v.setInt32( nbrs + 4 * f, - 1, true ) ) ) );

	} );

	it( 'neighbors: two tetrahedra on the same side of their shared face (overlapping, both positive) are refused', () => {

		// A hand-made pair: base triangle 0,1,2 and apexes 3 and 4 both above it.
		const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 2 ];
		const tetrahedra = [ 0, 1, 2, 3, 0, 1, 2, 4 ];
		const sh = new Float32Array( 5 * 27 );
		// A link across the wrong face (slot 0 is face 1,2,3, not in tetrahedron 1).
		expectError( 'neighbors', () => encodeBakedVolume( { positions, sh, tetrahedra, neighbors: [ 1, - 1, - 1, - 1, 0, - 1, - 1, - 1 ] } ), /does not contain the face/ );
		// The link across the shared face 0,1,2 (slot 3 in both).
		expectError( 'neighbors', () => encodeBakedVolume( { positions, sh, tetrahedra, neighbors: [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 0 ] } ), /same side/ );
		// The same two with the hull link on both: the shared face is a hull face twice.
		expectError( 'neighbors', () => encodeBakedVolume( { positions, sh, tetrahedra, neighbors: [ - 1, - 1, - 1, - 1, - 1, - 1, - 1, - 1 ] } ), /overlap/ );
		// Apex 4 below the base: a valid pair.
		const below = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, - 2 ];
		expect( independentCheck( decodeBakedVolume( encodeBakedVolume( { positions: below, sh, tetrahedra: [ 0, 1, 2, 3, 1, 0, 2, 4 ], neighbors: [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 0 ] } ) ) ) ).toBeNull();

	} );

	it( 'utf8: an invalid byte in a name, a zone name or the metadata', () => {

		const names = sectionOffset( file, 'NAME' ) + 4 * 40; // the blob after 40 end offsets; names[0] is ''
		expectError( 'utf8', () => decodeBakedVolume( edited( file, ( _v, b ) => b[ names + 2 ] = 0xFF ) ), /names\[1\] is not valid UTF-8/ );
		expectError( 'utf8', () => decodeBakedVolume( edited( file, ( _v, b ) => b[ sectionOffset( file, 'ZONE' ) + 16 ] = 0xC0 ) ), /zones\[0\]\.name/ );
		expectError( 'utf8', () => decodeBakedVolume( edited( file, ( _v, b ) => b[ sectionOffset( file, 'META' ) ] = 0xFE ) ), /metadata/ );

	} );

	it( 'json: malformed capture settings', () => {

		const capt = sectionOffset( file, 'CAPT' );
		expectError( 'json', () => decodeBakedVolume( edited( file, ( _v, b ) => b[ capt ] = 0x5B /* '[' */ ) ) );

	} );

	it( 'argument: not a buffer', () => {

		expectError( 'argument', () => decodeBakedVolume( null as unknown as ArrayBuffer ) );
		expectError( 'argument', () => decodeBakedVolume( 'LPV' as unknown as ArrayBuffer ) );

	} );

} );
