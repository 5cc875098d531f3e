import { describe, expect, it } from 'vitest';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { gridPoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/** A tetrahedralization's arrays, copied so each test may corrupt its own. */
function stored( positions: Float64Array ) {

	const { tetrahedra, neighbors, duplicates } = tetrahedralize( positions );
	return {
		positions: Float64Array.from( positions ), tetrahedra: Uint32Array.from( tetrahedra ), neighbors: Int32Array.from( neighbors ),
		duplicates
	};

}

/** Some interior face: tetrahedron t, slot i, neighbour u and u's slot j back to t. */
function interiorFace( tetrahedra: Uint32Array, neighbors: Int32Array ) {

	for ( let t = 0; ; t ++ ) for ( let i = 0; i < 4; i ++ ) {

		const u = neighbors[ 4 * t + i ];
		if ( u < 0 ) continue;
		for ( let j = 0; j < 4; j ++ ) if ( neighbors[ 4 * u + j ] === t ) return { t, i, u, j };

	}

}

describe( 'TetrahedralMesh.fromTetrahedralization', () => {

	it( 'a mesh from stored arrays interpolates exactly like one built from the positions (inside and outside, both modes)', () => {

		for ( const positions of [ randomPoints( 300, 17 ), gridPoints( 5, 4, 3, 0.5 ) ] ) {

			const data = stored( positions );
			for ( const outside of [ 'outerCells', 'nearestFace' ] as const ) {

				const built = new TetrahedralMesh( positions, { outside } );
				const loaded = TetrahedralMesh.fromTetrahedralization(
					data.positions, data.tetrahedra, data.neighbors, { outside, duplicates: data.duplicates }
				);
				// Plain arrays (e.g. parsed JSON) work too.
				const fromJSON = TetrahedralMesh.fromTetrahedralization(
					Array.from( data.positions ), Array.from( data.tetrahedra ), Array.from( data.neighbors ), { outside }
				);
				expect( loaded.tetrahedra ).toBe( data.tetrahedra ); // kept, not copied
				expect( loaded.neighbors ).toBe( data.neighbors );
				expect( Array.from( loaded.hullFaces ) ).toEqual( Array.from( built.hullFaces ) );
				expect( Array.from( loaded.outerCells.normals ) ).toEqual( Array.from( built.outerCells.normals ) );
				const a = new Float64Array( 4 ), b = new Float64Array( 4 ), c = new Float64Array( 4 );
				const ia = new Uint32Array( 4 ), ib = new Uint32Array( 4 ), ic = new Uint32Array( 4 );
				const random = seededRandom( 5 );
				let ha = - 1, hb = - 1, hc = - 1;
				for ( let q = 0; q < 5000; q ++ ) {

					const x = random() * 4 - 1.5, y = random() * 4 - 1.5, z = random() * 4 - 1.5;
					ha = built.interpolate( x, y, z, ia, a, ha );
					hb = loaded.interpolate( x, y, z, ib, b, hb );
					hc = fromJSON.interpolate( x, y, z, ic, c, hc );
					expect( hb ).toBe( ha );
					expect( hc ).toBe( ha );
					expect( Array.from( ib ) ).toEqual( Array.from( ia ) );
					expect( Array.from( b ) ).toEqual( Array.from( a ) );
					expect( Array.from( c ) ).toEqual( Array.from( a ) );

				}

			}

		}

	} );

	it( 'names each kind of corruption', () => {

		const base = stored( randomPoints( 60, 3 ) );
		const load = ( change: ( d: ReturnType<typeof stored> ) => void, options = {} ) => () => {

			const d = {
				positions: base.positions.slice(), tetrahedra: base.tetrahedra.slice(), neighbors: base.neighbors.slice(),
				duplicates: base.duplicates
			};
			change( d );
			return TetrahedralMesh.fromTetrahedralization( d.positions, d.tetrahedra, d.neighbors, options );

		};

		expect( load( () => {} ) ).not.toThrow();
		expect( load( ( d ) => { d.positions[ 10 ] = NaN; } ) ).toThrow( /fromTetrahedralization: positions\[10\] is NaN/ );
		expect( load( ( d ) => { d.positions = d.positions.subarray( 0, 10 ); } ) ).toThrow( /positions must hold x, y, z per point/ );
		expect( load( ( d ) => { d.tetrahedra = d.tetrahedra.subarray( 0, d.tetrahedra.length - 1 ); } ) ).toThrow( /tetrahedra must hold 4 indices per tetrahedron/ );
		expect( load( ( d ) => { d.neighbors = d.neighbors.subarray( 0, d.neighbors.length - 4 ); } ) ).toThrow( /neighbors must have one entry per tetrahedron face/ );
		expect( load( ( d ) => { d.tetrahedra[ 5 ] = 60; } ) ).toThrow( /tetrahedra\[5\] = 60 is not a probe index \(0..59\)/ );
		expect( load( ( d ) => { d.neighbors[ 6 ] = d.tetrahedra.length / 4; } ) ).toThrow( /neighbors\[6\] = \d+ is neither −1 nor a tetrahedron index/ );
		expect( load( ( d ) => { d.neighbors[ 6 ] = - 2; } ) ).toThrow( /neighbors\[6\] = -2 is neither −1 nor a tetrahedron index/ );
		expect( () => TetrahedralMesh.fromTetrahedralization( base.positions, [ 0, 1, 2, 3.5 ], [ - 1, - 1, - 1, - 1 ] ) ).toThrow( /tetrahedra\[3\] = 3.5 is not a probe index/ );

		// Not symmetric: t points to u, u points elsewhere (−1).
		const { t, i, u, j } = interiorFace( base.tetrahedra, base.neighbors );
		expect( load( ( d ) => { d.neighbors[ 4 * u + j ] = - 1; } ) ).toThrow( new RegExp( `neighbours are not symmetric: neighbors\\[${4 * t + i}\\] = ${u} but neighbors\\[${4 * u + j}\\] = -1, not ${t}` ) );
		// Not sharing the face: t points to a tetrahedron far away.
		const far = base.tetrahedra.length / 4 - 1 === t ? 0 : base.tetrahedra.length / 4 - 1;
		expect( load( ( d ) => { d.neighbors[ 4 * t + i ] = far; } ) ).toThrow( new RegExp( `neighbors\\[${4 * t + i}\\] = ${far}, but tetrahedron ${far} does not share the face opposite vertex ${i} of tetrahedron ${t}` ) );
		// Orientation: swapping two vertices (and their neighbour entries) keeps adjacency valid but inverts t.
		expect( load( ( d ) => {

			const k = 4 * t;
			[ d.tetrahedra[ k ], d.tetrahedra[ k + 1 ] ] = [ d.tetrahedra[ k + 1 ], d.tetrahedra[ k ] ];
			[ d.neighbors[ k ], d.neighbors[ k + 1 ] ] = [ d.neighbors[ k + 1 ], d.neighbors[ k ] ];

		} ) ).toThrow( new RegExp( `tetrahedron ${t} \\(probes .*\\) is not positively oriented` ) );
		// Both sides of an interior face marked as hull: symmetric, but the hull is then two surfaces.
		expect( load( ( d ) => { d.neighbors[ 4 * t + i ] = - 1; d.neighbors[ 4 * u + j ] = - 1; } ) ).toThrow( /hull faces form more than one closed surface/ );
		// A tetrahedron left out: the hull is closed but dented, no longer the convex hull.
		expect( load( ( d ) => {

			// Remove the last tetrahedron and mark its neighbours' faces towards it as hull.
			const last = d.tetrahedra.length / 4 - 1;
			for ( let k = 0; k < 4 * last; k ++ ) if ( d.neighbors[ k ] === last ) d.neighbors[ k ] = - 1;
			d.tetrahedra = d.tetrahedra.subarray( 0, 4 * last );
			d.neighbors = d.neighbors.subarray( 0, 4 * last );

		} ) ).toThrow( /fromTetrahedralization: the hull is not convex at edge \(\d+, \d+\)/ );
		expect( () => TetrahedralMesh.fromTetrahedralization( base.positions, base.tetrahedra, base.neighbors, { outside: 'far' as 'outerCells' } ) ).toThrow( /options.outside must be/ );

	} );

	it( 'trusted: skips validateTetrahedralization (data a decoder already checked), keeps the hull checks', () => {

		const data = stored( randomPoints( 200, 11 ) );
		const checked = TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, data.neighbors );
		const trusted = TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, data.neighbors, { trusted: true } );
		expect( Array.from( trusted.inverseMatrices ) ).toEqual( Array.from( checked.inverseMatrices ) );
		expect( Array.from( trusted.hullFaces ) ).toEqual( Array.from( checked.hullFaces ) );
		expect( Array.from( trusted.outerCells.normals ) ).toEqual( Array.from( checked.outerCells.normals ) );

		// An inner tetrahedron inverted (two vertices and their links swapped): refused unless trusted.
		const count = data.tetrahedra.length / 4;
		let t = 0;
		while ( t < count && [ 0, 1, 2, 3 ].some( ( i ) => data.neighbors[ 4 * t + i ] < 0 ) ) t ++;
		expect( t ).toBeLessThan( count );
		const tetrahedra = data.tetrahedra.slice(), neighbors = data.neighbors.slice();
		[ tetrahedra[ 4 * t ], tetrahedra[ 4 * t + 1 ] ] = [ tetrahedra[ 4 * t + 1 ], tetrahedra[ 4 * t ] ];
		[ neighbors[ 4 * t ], neighbors[ 4 * t + 1 ] ] = [ neighbors[ 4 * t + 1 ], neighbors[ 4 * t ] ];
		expect( () => TetrahedralMesh.fromTetrahedralization( data.positions, tetrahedra, neighbors ) ).toThrow( /is not positively oriented/ );
		expect( () => TetrahedralMesh.fromTetrahedralization( data.positions, tetrahedra, neighbors, { trusted: true } ) ).not.toThrow();

		// Indices out of range are RangeErrors; the hull's closed-surface check runs even when trusted.
		const bad = data.tetrahedra.slice();
		bad[ 5 ] = 200;
		expect( () => TetrahedralMesh.fromTetrahedralization( data.positions, bad, data.neighbors ) ).toThrow( RangeError );
		const face = interiorFace( data.tetrahedra, data.neighbors );
		const open = data.neighbors.slice();
		open[ 4 * face.t + face.i ] = - 1;
		open[ 4 * face.u + face.j ] = - 1;
		expect( () => TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, open, { trusted: true } ) )
			.toThrow( /hull faces form more than one closed surface/ );

	} );

	it( 'loads a 20,000-probe tetrahedralization (O(n) checks, no re-tetrahedralization)', () => {

		const positions = randomPoints( 20000, 9 );
		const data = stored( positions );
		const mesh = TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, data.neighbors );
		expect( mesh.cellCount ).toBe( data.tetrahedra.length / 4 );
		const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 );
		mesh.interpolate( 0.5, 0.5, 0.5, indices, weights );
		let x = 0;
		for ( let k = 0; k < 4; k ++ ) x += weights[ k ] * positions[ 3 * indices[ k ] ];
		expect( x ).toBeCloseTo( 0.5, 9 );

	} );

	it( 'misuse named (issue 12): a garbage duplicates option, and barycentric() of a tetrahedron index out of range, instead of NaN', () => {

		const positions = [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1 ];
		const mesh = new TetrahedralMesh( positions );
		const load = ( duplicates: unknown ) => () => TetrahedralMesh.fromTetrahedralization(
			positions, mesh.tetrahedra, mesh.neighbors, { duplicates: duplicates as number[] } );
		expect( load( 'garbage' ) ).toThrow( /fromTetrahedralization: options\.duplicates must be pairs/ );
		expect( load( [ 1 ] ) ).toThrow( /options\.duplicates must be pairs/ );
		expect( load( [ 1, 7 ] ) ).toThrow( /options\.duplicates\[1\] = 7 is not a probe index \(0\.\.4\)/ );
		expect( load( [ 1, - 1 ] ) ).toThrow( RangeError );
		expect( Array.from( TetrahedralMesh.fromTetrahedralization( positions, mesh.tetrahedra, mesh.neighbors, { duplicates: [ 4, 0 ] } ).duplicates ) ).toEqual( [ 4, 0 ] );
		const out = new Float64Array( 4 );
		for ( const t of [ - 1, 1.5, mesh.cellCount, NaN ] ) {

			expect( () => mesh.barycentric( t, 0.1, 0.1, 0.1, out ), String( t ) ).toThrow( /TetrahedralMesh\.barycentric: t = .* is not a tetrahedron index/ );

		}

		mesh.barycentric( 0, 0.1, 0.1, 0.1, out );
		expect( out.every( Number.isFinite ) ).toBe( true );

	} );

} );
