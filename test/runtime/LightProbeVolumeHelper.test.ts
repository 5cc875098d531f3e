/**
 * LightProbeVolumeHelper without a GPU: what it puts in its buffers. The wireframe holds each cell
 * edge once (checked against the edges listed from the cells and against Euler's formula), the
 * spheres sit at the probes with their SH, the highlight follows the cell an object or a point is
 * in (found here by brute force over all tetrahedra), `update()` follows probe edits, bad
 * arguments get named errors. Rendering, captures and disposal: LightProbeVolumeHelper.gpu.test.ts.
 */

import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { GridInterpolator } from '../../src/interpolation/GridInterpolator.js';
import type { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { LightProbeVolume } from '../../src/runtime/LightProbeVolume.js';
import { LightProbeVolumeHelper } from '../../src/runtime/LightProbeVolumeHelper.js';
import { randomPoints } from '../helpers/pointSets.js';

const CUBE = [ - 1, - 1, - 1, 1, - 1, - 1, - 1, 1, - 1, 1, 1, - 1, - 1, - 1, 1, 1, - 1, 1, - 1, 1, 1, 1, 1, 1 ];

/** Some SH in every coefficient, different per probe. */
function someSH( count: number ): Float32Array {

	return Float32Array.from( { length: 27 * count }, ( _, k ) => 0.5 + 0.4 * Math.sin( 1.7 * k ) );

}

/** The id of the probe at (x, y, z), within 1e-6. */
function probeAt( volume: LightProbeVolume, x: number, y: number, z: number ): number {

	const p = volume.positions;
	for ( let i = 0; i < volume.count; i ++ ) if ( Math.hypot( x - p[ 3 * i ], y - p[ 3 * i + 1 ], z - p[ 3 * i + 2 ] ) < 1e-6 ) return i;
	throw new Error( `no probe at ${x}, ${y}, ${z}` );

}

/** The segments a line geometry draws (its draw range) as sorted "a-b" keys of the probes at their ends. */
function segmentKeys( volume: LightProbeVolume, geometry: THREE.BufferGeometry ): string[] {

	const p = geometry.getAttribute( 'position' ), count = Math.min( p.count, geometry.drawRange.count );
	const keys: string[] = [];
	for ( let v = 0; v < count; v += 2 ) {

		const a = probeAt( volume, p.getX( v ), p.getY( v ), p.getZ( v ) );
		const b = probeAt( volume, p.getX( v + 1 ), p.getY( v + 1 ), p.getZ( v + 1 ) );
		keys.push( `${Math.min( a, b )}-${Math.max( a, b )}` );

	}

	return keys.sort();

}

/** The wireframe's segments as "a-b" keys. */
function wireframeEdges( helper: LightProbeVolumeHelper ): string[] {

	return segmentKeys( helper.volume, helper.cells.geometry );

}

/** The highlight's segments as "a-b" keys. */
function highlightedEdges( helper: LightProbeVolumeHelper ): string[] {

	return segmentKeys( helper.volume, helper.cell.geometry );

}

/** The edges of a list of cells with `size` vertices each (6 per tetrahedron, 3 per triangle), unique, sorted. */
function edgesOfCells( cells: ArrayLike<number>, size: number, map: ( i: number ) => number = ( i ) => i ): string[] {

	const keys = new Set<string>();
	for ( let c = 0; c < cells.length; c += size ) {

		for ( let i = 0; i < size; i ++ ) for ( let j = i + 1; j < size; j ++ ) {

			const a = map( cells[ c + i ] ), b = map( cells[ c + j ] );
			if ( a !== b ) keys.add( `${Math.min( a, b )}-${Math.max( a, b )}` );

		}

	}

	return [ ...keys ].sort();

}

/** Euler's formula for a tetrahedralized ball: V − E + F − T = 1, with F = (4T + hull triangles) / 2. */
function eulerEdgeCount( mesh: TetrahedralMesh, vertices: number ): number {

	const tetrahedra = mesh.tetrahedra.length / 4, hull = mesh.hullFaces.length / 3;
	return vertices + ( 4 * tetrahedra + hull ) / 2 - tetrahedra - 1;

}

function det3( a: number[], b: number[], c: number[] ): number {

	return a[ 0 ] * ( b[ 1 ] * c[ 2 ] - b[ 2 ] * c[ 1 ] ) - a[ 1 ] * ( b[ 0 ] * c[ 2 ] - b[ 2 ] * c[ 0 ] )
		+ a[ 2 ] * ( b[ 0 ] * c[ 1 ] - b[ 1 ] * c[ 0 ] );

}

/** The tetrahedron holding point q strictly inside, by brute force over all of them (signed volumes). */
function containingTetrahedron( mesh: TetrahedralMesh, q: number[] ): number[] {

	const p = ( i: number ) => Array.from( mesh.positions.subarray( 3 * i, 3 * i + 3 ) );
	const sub = ( a: number[], b: number[] ) => a.map( ( v, k ) => v - b[ k ] );
	for ( let t = 0; t < mesh.tetrahedra.length / 4; t ++ ) {

		const v = Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ) );
		const corners = v.map( p );
		const volume = ( k: number ) => {

			const c = corners.map( ( corner, j ) => ( j === k ? q : corner ) );
			return det3( sub( c[ 1 ], c[ 0 ] ), sub( c[ 2 ], c[ 0 ] ), sub( c[ 3 ], c[ 0 ] ) );

		};

		if ( [ 0, 1, 2, 3 ].every( ( k ) => volume( k ) > 0 ) ) return v;

	}

	throw new Error( `no tetrahedron holds ${q}` );

}

/** A lit object: a small box with a MeshStandardMaterial, at `position`. */
function box( position: number[] ): THREE.Mesh {

	const mesh = new THREE.Mesh( new THREE.BoxGeometry( 0.05, 0.05, 0.05 ), new THREE.MeshStandardMaterial() );
	mesh.position.fromArray( position );
	mesh.updateMatrixWorld();
	return mesh;

}

/** A frame: the volume samples its objects, then the renderer's scene.updateMatrixWorld() refreshes the helper. */
function frame( volume: LightProbeVolume, helper: LightProbeVolumeHelper ): void {

	volume.update();
	helper.updateMatrixWorld( true );

}

/** Instance i's translation and scale (the length of its first column: the matrices are a uniform scale and a translation). */
function instance( helper: LightProbeVolumeHelper, i: number ): { position: number[]; scale: number } {

	const e = helper.probes.instanceMatrix.array, o = 16 * i;
	return { position: [ e[ o + 12 ], e[ o + 13 ], e[ o + 14 ] ], scale: Math.hypot( e[ o ], e[ o + 1 ], e[ o + 2 ] ) };

}

describe( 'LightProbeVolumeHelper: the wireframe holds each cell edge once', () => {

	it( 'the 2×2×2 cube: the edges of its tetrahedra, as many as Euler\'s formula gives', () => {

		const volume = new LightProbeVolume( { positions: CUBE } );
		const helper = new LightProbeVolumeHelper( volume );
		const mesh = volume.interpolator as TetrahedralMesh;
		const edges = wireframeEdges( helper );
		expect( edges ).toEqual( edgesOfCells( mesh.tetrahedra, 4 ) );
		expect( new Set( edges ).size ).toBe( edges.length );
		expect( edges.length ).toBe( eulerEdgeCount( mesh, 8 ) );
		// A cube cut into tetrahedra has its 12 edges and one diagonal per face, and one inner diagonal when cut into 6.
		expect( edges.length === 18 || edges.length === 19 ).toBe( true );
		helper.dispose();

	} );

	it( '60 random probes: the edges of the Delaunay tetrahedra, Euler\'s count', () => {

		const volume = new LightProbeVolume( { positions: randomPoints( 60, 7, 4 ) } );
		const helper = new LightProbeVolumeHelper( volume );
		const mesh = volume.interpolator as TetrahedralMesh;
		const edges = wireframeEdges( helper );
		expect( edges ).toEqual( edgesOfCells( mesh.tetrahedra, 4 ) );
		expect( edges.length ).toBe( eulerEdgeCount( mesh, 60 ) );
		helper.dispose();

	} );

	it( 'a planar layout draws its triangles (V + T − 1 edges), a row of probes its segments, a grid its boxes', () => {

		// A square and its centre, in the plane y = 1: 4 triangles, 8 edges.
		const planar = new LightProbeVolume( { positions: [ 0, 1, 0, 2, 1, 0, 2, 1, 2, 0, 1, 2, 1, 1, 1 ] } );
		const flat = new LightProbeVolumeHelper( planar );
		const triangles = ( planar.interpolator as unknown as { triangles: Uint32Array } ).triangles;
		expect( wireframeEdges( flat ) ).toEqual( edgesOfCells( triangles, 3 ) );
		expect( wireframeEdges( flat ).length ).toBe( 5 + triangles.length / 3 - 1 );
		expect( wireframeEdges( flat ).length ).toBe( 8 );

		// Three probes on a line (given out of order): two segments, between neighbours along it.
		const line = new LightProbeVolumeHelper( new LightProbeVolume( { positions: [ 0, 0, 0, 2, 2, 2, 1, 1, 1 ] } ) );
		expect( wireframeEdges( line ) ).toEqual( [ '0-2', '1-2' ] );

		// A 3×2×2 grid (trilinear): (nx−1)·ny·nz + nx·(ny−1)·nz + nx·ny·(nz−1) = 8 + 6 + 6 edges, along the axes.
		const grid = new GridInterpolator( [ 0, 0, 0 ], [ 2, 1, 1 ], [ 3, 2, 2 ] );
		const boxes = new LightProbeVolumeHelper( new LightProbeVolume( { positions: grid.positions, interpolator: grid } ) );
		const edges = wireframeEdges( boxes );
		expect( edges.length ).toBe( 20 );
		for ( const key of edges ) {

			const [ a, b ] = key.split( '-' ).map( Number );
			const d = [ 0, 1, 2 ].map( ( k ) => Math.abs( grid.positions[ 3 * a + k ] - grid.positions[ 3 * b + k ] ) );
			expect( d.filter( ( v ) => v > 0 ).length, key ).toBe( 1 ); // along one axis
			expect( Math.max( ...d ), key ).toBeCloseTo( 1, 12 ); // to the next node

		}

		for ( const helper of [ flat, line, boxes ] ) helper.dispose();

	} );

	it( 'a volume with zones draws each zone\'s own cells, not the cells across them', () => {

		const positions: number[] = [];
		for ( const x of [ - 3, - 1, 1, 3 ] ) for ( const y of [ 0, 2 ] ) for ( const z of [ 0, 2 ] ) positions.push( x, y, z );
		const left = [ 0, 1, 2, 3, 4, 5, 6, 7 ], right = [ 8, 9, 10, 11, 12, 13, 14, 15 ];
		const volume = new LightProbeVolume( { positions, zones: [ { name: 'left', probes: left }, { name: 'right', probes: right } ] } );
		const helper = new LightProbeVolumeHelper( volume );
		const expected = volume.zones!.zones.flatMap( ( zone ) => {

			return edgesOfCells( ( zone.interpolator as TetrahedralMesh ).tetrahedra, 4, ( i ) => zone.probes[ i ] );

		} ).sort();
		expect( wireframeEdges( helper ) ).toEqual( expected );
		// No edge joins the rooms, though the volume's own tetrahedralization has such edges.
		const crossing = ( key: string ) => key.split( '-' ).map( Number ).filter( ( i ) => i < 8 ).length === 1;
		expect( wireframeEdges( helper ).some( crossing ) ).toBe( false );
		expect( edgesOfCells( ( volume.interpolator as TetrahedralMesh ).tetrahedra, 4 ).some( crossing ) ).toBe( true );
		helper.dispose();

	} );

} );

describe( 'LightProbeVolumeHelper: spheres', () => {

	it( 'one instance per probe at its position, radius `size` (default 0.15 × the median nearest-probe distance), its SH in the attributes', () => {

		const sh = someSH( 8 );
		const volume = new LightProbeVolume( { positions: CUBE, sh } );
		const helper = new LightProbeVolumeHelper( volume );
		expect( helper.size ).toBeCloseTo( 0.3, 12 ); // nearest neighbours 2 apart
		expect( helper.probes.count ).toBe( 8 );
		const attributes = [ 0, 1, 2, 3, 4, 5, 6 ].map( ( k ) => helper.probes.geometry.getAttribute( `probeSH${k}` ) );
		for ( let i = 0; i < 8; i ++ ) {

			const { position, scale } = instance( helper, i );
			expect( position ).toEqual( CUBE.slice( 3 * i, 3 * i + 3 ) );
			expect( scale ).toBeCloseTo( 0.3, 6 );
			const packed = attributes.flatMap( ( a ) => [ a.getX( i ), a.getY( i ), a.getZ( i ), a.getW( i ) ] ).slice( 0, 27 );
			expect( packed ).toEqual( Array.from( sh.subarray( 27 * i, 27 * i + 27 ) ) );

		}

		helper.size = 0.5;
		expect( instance( helper, 3 ).scale ).toBeCloseTo( 0.5, 6 );
		expect( new LightProbeVolumeHelper( volume, 0.2 ).size ).toBe( 0.2 );
		expect( new LightProbeVolumeHelper( new LightProbeVolume( { positions: [ 1, 2, 3 ] } ) ).size ).toBe( 1 ); // a single probe
		helper.dispose();

	} );

	it( 'a raycast at a sphere gives its probe id as instanceId; the lines do not answer raycasts', () => {

		const volume = new LightProbeVolume( { positions: CUBE } );
		const helper = new LightProbeVolumeHelper( volume, 0.3 );
		helper.updateMatrixWorld( true );
		const raycaster = new THREE.Raycaster( new THREE.Vector3( 1, 1, 10 ), new THREE.Vector3( 0, 0, - 1 ) );
		const hits = raycaster.intersectObject( helper, true );
		expect( hits.length ).toBeGreaterThan( 0 );
		expect( hits.every( ( hit ) => hit.object === helper.probes ) ).toBe( true );
		expect( hits[ 0 ].instanceId ).toBe( 7 ); // (1, 1, 1), the nearer of the two on that ray
		helper.dispose();

	} );

} );

describe( 'LightProbeVolumeHelper: the highlighted cell', () => {

	const positions = randomPoints( 40, 3, 4 ).map( ( v ) => v - 2 ); // in [−2, 2)³

	it( 'an object: the 6 edges of the tetrahedron holding its centre, found again after it moves; outside the hull a hull triangle', () => {

		const volume = new LightProbeVolume( { positions } );
		const mesh = volume.interpolator as TetrahedralMesh;
		const object = box( [ 0.1, 0.2, - 0.3 ] );
		volume.add( object );
		const helper = new LightProbeVolumeHelper( volume );
		helper.highlight( object );
		for ( const place of [ [ 0.1, 0.2, - 0.3 ], [ - 0.9, 0.4, 0.6 ], [ 0.7, - 0.8, 0.2 ] ] ) {

			object.position.fromArray( place );
			frame( volume, helper );
			const cell = containingTetrahedron( mesh, place );
			expect( highlightedEdges( helper ), `at ${place}` ).toEqual( edgesOfCells( cell, 4 ) );
			expect( highlightedEdges( helper ).length ).toBe( 6 );

		}

		// Far outside: the object extrapolates from an outer cell, drawn as its hull triangle.
		object.position.set( 30, 1, 2 );
		frame( volume, helper );
		const drawn = highlightedEdges( helper );
		expect( drawn.length ).toBe( 3 );
		const hull = mesh.hullFaces;
		const faces = Array.from( { length: hull.length / 3 }, ( _, f ) => edgesOfCells( hull.subarray( 3 * f, 3 * f + 3 ), 3 ) );
		expect( faces.some( ( face ) => face.join() === drawn.join() ) ).toBe( true );

		helper.highlight( null );
		helper.updateMatrixWorld( true );
		expect( helper.cell.geometry.drawRange.count ).toBe( 0 );
		helper.dispose();

	} );

	it( 'an object added with an anchor: the cell holding the anchor, not the bounding-box centre (getAnchor)', () => {

		const volume = new LightProbeVolume( { positions } );
		const mesh = volume.interpolator as TetrahedralMesh;
		const object = box( [ 0, 0, 0 ] );
		// Box centre at the origin, anchor 0.8 below it: two different cells of the cube.
		volume.add( object, { anchor: { x: 0.7, y: - 0.8, z: 0.2 } } );
		expect( volume.getAnchor( object, new THREE.Vector3() )?.toArray() ).toEqual( [ 0.7, - 0.8, 0.2 ] );
		expect( volume.getAnchor( new THREE.Object3D(), new THREE.Vector3() ) ).toBeNull();
		expect( containingTetrahedron( mesh, [ 0.7, - 0.8, 0.2 ] ).join() ).not.toBe( containingTetrahedron( mesh, [ 0, 0, 0 ] ).join() );
		const helper = new LightProbeVolumeHelper( volume );
		helper.highlight( object );
		frame( volume, helper );
		expect( highlightedEdges( helper ) ).toEqual( edgesOfCells( containingTetrahedron( mesh, [ 0.7, - 0.8, 0.2 ] ), 4 ) );
		helper.dispose();

	} );

	it( 'a Vector3 is followed by reference; an unchanged cell is not uploaded again (no per-frame upload)', () => {

		const volume = new LightProbeVolume( { positions } );
		const helper = new LightProbeVolumeHelper( volume );
		const point = new THREE.Vector3( 0.1, 0.2, - 0.3 );
		helper.highlight( point );
		helper.updateMatrixWorld( true );
		const attribute = helper.cell.geometry.getAttribute( 'position' ) as THREE.BufferAttribute;
		const version = attribute.version;
		for ( let i = 0; i < 5; i ++ ) helper.updateMatrixWorld( true );
		expect( attribute.version ).toBe( version );
		point.set( - 0.9, 0.4, 0.6 );
		helper.updateMatrixWorld( true );
		expect( attribute.version ).toBeGreaterThan( version );
		const mesh = volume.interpolator as TetrahedralMesh;
		expect( highlightedEdges( helper ) ).toEqual( edgesOfCells( containingTetrahedron( mesh, point.toArray() ), 4 ) );
		helper.highlight( [ 0.7, - 0.8, 0.2 ] );
		helper.updateMatrixWorld( true );
		expect( highlightedEdges( helper ) ).toEqual( edgesOfCells( containingTetrahedron( mesh, [ 0.7, - 0.8, 0.2 ] ), 4 ) );
		helper.dispose();

	} );

	it( 'zones: the cell of the zone the object is lit by; a grid: the box\'s 12 edges; a planar layout: the triangle', () => {

		const roomPositions: number[] = [];
		for ( const x of [ - 3, - 1, 1, 3 ] ) for ( const y of [ 0, 2 ] ) for ( const z of [ 0, 2 ] ) roomPositions.push( x, y, z );
		const right = [ 8, 9, 10, 11, 12, 13, 14, 15 ];
		const bounds = new THREE.Box3( new THREE.Vector3( 0.5, - 1, - 1 ), new THREE.Vector3( 3.5, 3, 3 ) );
		const zoned = new LightProbeVolume( { positions: roomPositions, zones: [ { name: 'left', probes: [ 0, 1, 2, 3, 4, 5, 6, 7 ] }, { name: 'right', probes: right, bounds } ] } );
		const object = box( [ 2.2, 0.7, 1.3 ] );
		zoned.add( object );
		const helper = new LightProbeVolumeHelper( zoned );
		helper.highlight( object );
		frame( zoned, helper );
		expect( zoned.getZone( object ) ).toBe( 'right' );
		const zone = zoned.zones!.zones[ 1 ];
		const local = containingTetrahedron( zone.interpolator as TetrahedralMesh, [ 2.2, 0.7, 1.3 ] );
		expect( highlightedEdges( helper ) ).toEqual( edgesOfCells( local, 4, ( i ) => zone.probes[ i ] ) );

		const grid = new GridInterpolator( [ 0, 0, 0 ], [ 2, 1, 1 ], [ 3, 2, 2 ] );
		const gridHelper = new LightProbeVolumeHelper( new LightProbeVolume( { positions: grid.positions, interpolator: grid } ) );
		gridHelper.highlight( [ 1.5, 0.5, 0.5 ] );
		gridHelper.updateMatrixWorld( true );
		// The box x ∈ [1, 2]: probes 1, 2, 4, 5, 7, 8, 10, 11 (x fastest), its 12 edges.
		const boxEdges = [ '1-2', '4-5', '7-8', '10-11', '1-4', '2-5', '7-10', '8-11', '1-7', '2-8', '4-10', '5-11' ];
		expect( highlightedEdges( gridHelper ) ).toEqual( boxEdges.sort() );

		const planar = new LightProbeVolume( { positions: [ 0, 1, 0, 2, 1, 0, 2, 1, 2, 0, 1, 2, 1, 1, 1 ] } );
		const planarHelper = new LightProbeVolumeHelper( planar );
		planarHelper.highlight( [ 1, 1.3, 0.4 ] ); // above the triangle (0, 1, 4) of the plane y = 1
		planarHelper.updateMatrixWorld( true );
		expect( highlightedEdges( planarHelper ) ).toEqual( [ '0-1', '0-4', '1-4' ] );
		for ( const h of [ helper, gridHelper, planarHelper ] ) h.dispose();

	} );

} );

describe( 'LightProbeVolumeHelper.update() after probe edits', () => {

	it( 'moveProbe, addProbe, removeProbe: spheres, SH, wireframe and the highlighted cell follow', () => {

		const positions = randomPoints( 30, 11, 4 ).map( ( v ) => v - 2 );
		const volume = new LightProbeVolume( { positions, sh: someSH( 30 ) } );
		const helper = new LightProbeVolumeHelper( volume, 0.1 );
		const point = new THREE.Vector3( 0.2, - 0.1, 0.3 );
		helper.highlight( point );
		helper.updateMatrixWorld( true );
		const check = ( label: string ) => {

			const mesh = volume.interpolator as TetrahedralMesh;
			expect( helper.probes.count, label ).toBe( volume.count );
			for ( let i = 0; i < volume.count; i ++ ) {

				const { position, scale } = instance( helper, i );
				expect( scale, `${label}: probe ${i}` ).toBeCloseTo( volume.isProbeActive( i ) ? 0.1 : 0, 6 );
				if ( ! volume.isProbeActive( i ) ) continue;
				for ( let k = 0; k < 3; k ++ ) expect( position[ k ] ).toBeCloseTo( volume.positions[ 3 * i + k ], 6 );

			}

			const attribute = helper.probes.geometry.getAttribute( 'probeSH0' );
			expect( attribute.getX( volume.count - 1 ) ).toBeCloseTo( volume.sh[ 27 * ( volume.count - 1 ) ], 6 );
			expect( wireframeEdges( helper ), label ).toEqual( edgesOfCells( mesh.tetrahedra, 4 ) );
			helper.updateMatrixWorld( true );
			expect( highlightedEdges( helper ), label ).toEqual( edgesOfCells( containingTetrahedron( mesh, point.toArray() ), 4 ) );

		};

		// Move a vertex of the highlighted cell: its spheres and edges must move too.
		const moved = helper.cell.cellProbes[ 0 ];
		volume.moveProbe( moved, Array.from( volume.positions.subarray( 3 * moved, 3 * moved + 3 ), ( v ) => 1.1 * v ) );
		helper.update();
		check( 'moveProbe' );
		for ( let k = 0; k < 5; k ++ ) volume.addProbe( [ 0.1 * k, 0.2 - 0.05 * k, 0.3 + 0.02 * k ] ); // 30 → 35 slots: the buffers grow
		helper.update();
		check( 'addProbe' );
		volume.removeProbe( 4 );
		helper.update();
		check( 'removeProbe' );
		expect( Math.abs( instance( helper, 4 ).scale ) ).toBe( 0 );
		expect( wireframeEdges( helper ).some( ( key ) => key.split( '-' ).includes( '4' ) ) ).toBe( false );
		helper.dispose();

	} );

} );

describe( 'LightProbeVolumeHelper: bad arguments', () => {

	it( 'name the API and what was expected; a failed call changes nothing', () => {

		expect( () => new LightProbeVolumeHelper( {} as LightProbeVolume ) ).toThrow( /^LightProbeVolumeHelper: volume must be a LightProbeVolume, got/ );
		expect( () => new LightProbeVolumeHelper( null as unknown as LightProbeVolume ) ).toThrow( TypeError );
		const volume = new LightProbeVolume( { positions: CUBE } );
		for ( const size of [ 0, - 1, NaN, Infinity, '1' ] ) {

			expect( () => new LightProbeVolumeHelper( volume, size as number ) ).toThrow( /^LightProbeVolumeHelper: size must be/ );

		}

		const helper = new LightProbeVolumeHelper( volume, 0.25 );
		expect( () => { helper.size = 0; } ).toThrow( RangeError );
		expect( helper.size ).toBe( 0.25 );
		expect( instance( helper, 0 ).scale ).toBeCloseTo( 0.25, 6 );
		const point = new THREE.Vector3( 0.1, 0.1, 0.1 );
		helper.highlight( point );
		helper.updateMatrixWorld( true );
		const before = highlightedEdges( helper );
		expect( () => helper.highlight( 5 as unknown as THREE.Vector3 ) ).toThrow( /^LightProbeVolumeHelper\.highlight: target must be an Object3D, \{ x, y, z \}, \[ x, y, z \] or null/ );
		expect( () => helper.highlight( { x: 1, y: NaN, z: 0 } ) ).toThrow( /^LightProbeVolumeHelper\.highlight: target must be three finite numbers/ );
		helper.updateMatrixWorld( true );
		expect( highlightedEdges( helper ) ).toEqual( before );
		// A followed position that becomes NaN later shows no cell rather than throwing during a render.
		point.x = NaN;
		helper.updateMatrixWorld( true );
		expect( helper.cell.geometry.drawRange.count ).toBe( 0 );
		helper.dispose();

	} );

} );
