import { describe, expect, it } from 'vitest';
import { DegenerateInputError } from '../../src/index.js';
import { tetrahedralize } from '../../src/math.js';
import { checkDelaunay, type DelaunayReport } from '../helpers/delaunayChecks.js';
import { gridPoints, integerSpherePoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/** Everything a valid Delaunay tetrahedralization of the convex hull must satisfy. */
function expectValid( report: DelaunayReport, expectedVolume?: number ): void {

	expect( report.tetrahedra ).toBeGreaterThan( 0 );
	expect( report.nonPositive, 'flat or inverted tetrahedra' ).toBe( 0 );
	expect( report.asymmetricNeighbors, 'neighbour links not symmetric' ).toBe( 0 );
	expect( report.mismatchedFaces, 'neighbours that do not share the face' ).toBe( 0 );
	expect( report.unusedPoints, 'input points missing from the mesh' ).toBe( 0 );
	expect( report.hullViolations, 'boundary faces that are not convex-hull faces' ).toBe( 0 );
	expect( report.emptySphereViolations, 'points strictly inside a circumsphere' ).toBe( 0 );
	// Positive cells with symmetric face links, a convex boundary and equal volumes: the cells tile the hull once.
	expect( Math.abs( report.volumeSum - report.hullVolume ) ).toBeLessThanOrEqual( 1e-9 * report.hullVolume );
	if ( expectedVolume !== undefined ) {

		expect( Math.abs( report.volumeSum - expectedVolume ) ).toBeLessThanOrEqual( 1e-9 * expectedVolume );

	}

}

function run( points: Float64Array ): DelaunayReport {

	const { tetrahedra, neighbors, duplicates } = tetrahedralize( points );
	const skip = new Set<number>();
	for ( let i = 0; i < duplicates.length; i += 2 ) skip.add( duplicates[ i ] );
	return checkDelaunay( points, tetrahedra, neighbors, skip );

}

describe( 'tetrahedralize: random point sets (brute-force Delaunay and tiling checks)', () => {

	for ( const seed of [ 1, 2, 3 ] ) {

		it( `300 uniform points, seed ${seed}`, () => expectValid( run( randomPoints( 300, seed ) ) ) );

	}

	it( '5,000 uniform points', () => expectValid( run( randomPoints( 5000, 7 ) ) ) );

	it( 'two clusters 1e4 apart (each 0.01 wide)', () => {

		// Separated along x only: along a diagonal the test's own float volume sums would cancel
		// catastrophically (terms of 1e12 for cells of 1e-4), not the mesh.
		const random = seededRandom( 11 );
		const points = new Float64Array( 3 * 400 );
		for ( let i = 0; i < 400; i ++ ) {

			for ( let a = 0; a < 3; a ++ ) points[ 3 * i + a ] = random() * 0.01;
			if ( i >= 200 ) points[ 3 * i ] += 1e4;

		}

		expectValid( run( points ) );

	} );

} );

describe( 'tetrahedralize: degenerate layouts (co-spherical, co-planar subsets)', () => {

	// On a grid every cube's 8 corners are co-spherical: each cell must be split into 5 or 6
	// tetrahedra and nothing else, and the cells tile the box exactly.
	const grids: [ number, number, number, number ][] = [ [ 4, 4, 4, 0.1 ], [ 12, 6, 6, 0.1 ], [ 12, 6, 6, 1 ], [ 20, 20, 20, 0.1 ] ];
	for ( const [ nx, ny, nz, spacing ] of grids ) {

		it( `${nx}x${ny}x${nz} grid, spacing ${spacing}`, () => {

			const report = run( gridPoints( nx, ny, nz, spacing ) );
			const boxes = ( nx - 1 ) * ( ny - 1 ) * ( nz - 1 );
			expectValid( report, boxes * spacing ** 3 );
			expect( report.tetrahedra ).toBeGreaterThanOrEqual( 5 * boxes );
			expect( report.tetrahedra ).toBeLessThanOrEqual( 6 * boxes );

		} );

	}

	it( 'all 30 integer points on the sphere of radius 3 (exactly co-spherical) plus its centre', () => {

		const sphere = integerSpherePoints( 3 );
		const points = Float64Array.from( [ ...sphere, 0, 0, 0 ] );
		expectValid( run( points ) );

	} );

	it( 'the 102 integer points on the sphere of radius 9 alone (every tetrahedron has the same circumsphere)', () => {

		const points = integerSpherePoints( 9 );
		expect( points.length / 3 ).toBe( 102 );
		expectValid( run( points ) );

	} );

	it( 'a dense plane of 400 grid points with 20 random points above and below', () => {

		const plane = gridPoints( 20, 20, 1, 0.05 );
		const random = seededRandom( 5 );
		const extra: number[] = [];
		for ( let i = 0; i < 20; i ++ ) extra.push( random(), random(), ( random() - 0.5 ) * 0.5 );
		expectValid( run( Float64Array.from( [ ...plane, ...extra ] ) ) );

	} );

	it( 'points on the faces and edges of a cube (many coplanar hull points)', () => {

		const out: number[] = [];
		for ( let i = 0; i <= 6; i ++ ) for ( let j = 0; j <= 6; j ++ ) for ( let k = 0; k <= 6; k ++ ) {

			if ( i === 0 || i === 6 || j === 0 || j === 6 || k === 0 || k === 6 ) out.push( i / 6, j / 6, k / 6 );

		}

		out.push( 0.5, 0.5, 0.5 );
		expectValid( run( Float64Array.from( out ) ), 1 );

	} );

	it( 'gives the same mesh whatever the insertion seed (perturbation decides ties by position, not order)', () => {

		const points = gridPoints( 5, 4, 3, 0.1 );
		const canonical = ( seed: number ) => {

			const { tetrahedra } = tetrahedralize( points, { seed } );
			const cells: string[] = [];
			for ( let t = 0; t < tetrahedra.length; t += 4 ) cells.push( Array.from( tetrahedra.subarray( t, t + 4 ) ).sort( ( a, b ) => a - b ).join( ',' ) );
			return cells.sort().join( ';' );

		};

		expect( canonical( 2 ) ).toBe( canonical( 1 ) );
		expect( canonical( 99 ) ).toBe( canonical( 1 ) );

	} );

} );

describe( 'tetrahedralize: duplicates and bad input', () => {

	it( 'merges exact and near duplicates and reports them', () => {

		const points = Array.from( gridPoints( 3, 3, 3, 1 ) );
		points.push( 1, 1, 1 ); // exact duplicate of point 13
		points.push( 2, 2, 2 + 1e-12 ); // within tolerance of point 26
		const { tetrahedra, neighbors, duplicates } = tetrahedralize( points );
		expect( Array.from( duplicates ) ).toEqual( [ 27, 13, 28, 26 ] );
		const report = checkDelaunay( Float64Array.from( points ), tetrahedra, neighbors, new Set( [ 27, 28 ] ) );
		expectValid( report, 8 );
		expect( Array.from( tetrahedra ).some( ( v ) => v === 27 || v === 28 ) ).toBe( false );

	} );

	it( 'keeps points that are close but beyond the tolerance', () => {

		const points = Array.from( gridPoints( 3, 3, 3, 1 ) );
		points.push( 1, 1, 1 + 1e-6 );
		const { duplicates, tetrahedra } = tetrahedralize( points );
		expect( duplicates.length ).toBe( 0 );
		expect( Array.from( tetrahedra ) ).toContain( 27 );

	} );

	it( 'rejects fewer than 4 points', () => {

		expect( () => tetrahedralize( [ 0, 0, 0, 1, 0, 0, 0, 1, 0 ] ) ).toThrow( /at least 4 points/ );
		expect( () => tetrahedralize( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0 ] ) ).toThrow( /only 3 distinct points/ );

	} );

	it( 'rejects coplanar and collinear sets with a DegenerateInputError naming the reason', () => {

		const floor = gridPoints( 5, 1, 5, 1 ); // y = 0 everywhere
		expect( () => tetrahedralize( floor ) ).toThrow( DegenerateInputError );
		try {

			tetrahedralize( floor );

		} catch ( error ) {

			expect( ( error as DegenerateInputError ).reason ).toBe( 'coplanar' );
			expect( ( error as Error ).message ).toMatch( /one plane/ );

		}

		const line = gridPoints( 6, 1, 1, 1 );
		expect( () => tetrahedralize( line ) ).toThrow( /one line/ );

	} );

	it( 'rejects NaN, Infinity and ragged arrays naming the argument', () => {

		expect( () => tetrahedralize( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NaN ] ) ).toThrow( /tetrahedralize: points\[11\] is NaN/ );
		expect( () => tetrahedralize( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, Infinity, 1 ] ) ).toThrow( /points\[10\] is Infinity/ );
		expect( () => tetrahedralize( [ 0, 0, 0, 1, 0 ] ) ).toThrow( /multiple of 3/ );
		expect( () => tetrahedralize( null as unknown as number[] ) ).toThrow( /points must be an array/ );

	} );

} );

describe( 'tetrahedralize: options are checked where they enter', () => {

	const cube = gridPoints( 2, 2, 2, 1 );

	it( 'rejects a NaN, negative, infinite or non-number tolerance, naming the API and the option', () => {

		expect( () => tetrahedralize( cube, { duplicateTolerance: NaN } ) )
			.toThrow( new RangeError( 'tetrahedralize: options.duplicateTolerance must be a finite number ≥ 0, got NaN.' ) );
		expect( () => tetrahedralize( cube, { duplicateTolerance: - 1e-9 } ) ).toThrow( RangeError );
		expect( () => tetrahedralize( cube, { duplicateTolerance: Infinity } ) ).toThrow( /^tetrahedralize: options.duplicateTolerance must be a finite number ≥ 0, got Infinity/ );
		expect( () => tetrahedralize( cube, { planarTolerance: - 1 } ) ).toThrow( /^tetrahedralize: options.planarTolerance must be a finite number ≥ 0, got -1/ );
		expect( () => tetrahedralize( cube, { planarTolerance: '1e-9' as unknown as number } ) ).toThrow( TypeError );
		expect( () => tetrahedralize( cube, { duplicateTolerance: '0' as unknown as number } ) ).toThrow( /got the string "0"/ );
		expect( () => tetrahedralize( cube, { seed: NaN } ) ).toThrow( /^tetrahedralize: options.seed must be a finite number, got NaN/ );
		expect( () => tetrahedralize( cube, null as unknown as object ) ).toThrow( new TypeError( 'tetrahedralize: options must be an object, got null.' ) );
		expect( () => tetrahedralize( cube, [] as unknown as object ) ).toThrow( /^tetrahedralize: options must be an object/ );

	} );

	it( 'a tolerance of 0 keeps distinct points however close, merges exact duplicates, and never returns a flat tetrahedron', () => {

		const points = Float64Array.from( [ ...cube, 1, 1, 1, 1, 1, 1 + 1e-15, 0.5, 0.5, 0.5 ] );
		const { tetrahedra, neighbors, duplicates } = tetrahedralize( points, { duplicateTolerance: 0, planarTolerance: 0 } );
		expect( Array.from( duplicates ) ).toEqual( [ 8, 7 ] );
		expectValid( checkDelaunay( points, tetrahedra, neighbors, new Set( [ 8 ] ) ), 1 );
		expect( Array.from( tetrahedra ) ).toContain( 9 );

	} );

	it( 'a planar tolerance of 0 rejects only exactly coplanar or collinear sets', () => {

		const flat = gridPoints( 3, 3, 1, 1 );
		expect( () => tetrahedralize( flat, { planarTolerance: 0 } ) ).toThrow( expect.objectContaining( { reason: 'coplanar' } ) );
		expect( () => tetrahedralize( gridPoints( 5, 1, 1, 1 ), { planarTolerance: 0 } ) ).toThrow( expect.objectContaining( { reason: 'collinear' } ) );
		// 1e-300 above the plane, beside a point of it: distinct only without tolerances, and then a volume.
		const almost = Float64Array.from( [ ...flat, 1, 1, 1e-300 ] ), exact = { duplicateTolerance: 0, planarTolerance: 0 };
		const { tetrahedra, neighbors } = tetrahedralize( almost, exact );
		expectValid( checkDelaunay( almost, tetrahedra, neighbors ) );
		expect( () => tetrahedralize( almost, { duplicateTolerance: 0 } ) ).toThrow( expect.objectContaining( { reason: 'coplanar' } ) );

	} );

} );

describe( 'the brute-force checker itself catches broken meshes', () => {

	const points = randomPoints( 60, 4 );
	const good = tetrahedralize( points );

	it( 'flags an inverted tetrahedron, a broken neighbour link, a missing cell', () => {

		const inverted = good.tetrahedra.slice();
		[ inverted[ 0 ], inverted[ 1 ] ] = [ inverted[ 1 ], inverted[ 0 ] ];
		expect( checkDelaunay( points, inverted, good.neighbors ).nonPositive ).toBe( 1 );

		const unlinked = good.neighbors.slice();
		const i = unlinked.findIndex( ( u ) => u >= 0 );
		unlinked[ i ] = - 1;
		const report = checkDelaunay( points, good.tetrahedra, unlinked );
		expect( report.asymmetricNeighbors + report.hullViolations ).toBeGreaterThan( 0 );

		const dropped = checkDelaunay( points, good.tetrahedra.slice( 4 ), good.neighbors.slice( 4 ) );
		expect( Math.abs( dropped.volumeSum - dropped.hullVolume ) ).toBeGreaterThan( 1e-9 );

	} );

	it( 'flags a non-Delaunay flip (a point strictly inside a circumsphere)', () => {

		// A triangular bipyramid (triangle 0-1-2, apexes 3 and 4) has two splits: two tetrahedra
		// sharing the triangle, or three around the apex edge 3–4. In general position exactly one
		// is Delaunay, so the one tetrahedralize did not choose must break the empty-sphere rule.
		const bipyramid = Float64Array.from( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1, 0.3, 0.3, - 0.1 ] );
		const delaunay = tetrahedralize( bipyramid );
		expectValid( checkDelaunay( bipyramid, delaunay.tetrahedra, delaunay.neighbors ) );
		const chosen = delaunay.tetrahedra.length / 4;
		expect( [ 2, 3 ] ).toContain( chosen );
		const other = chosen === 2
			? Uint32Array.from( [ 0, 1, 4, 3, 1, 2, 4, 3, 2, 0, 4, 3 ] )
			: Uint32Array.from( [ 0, 1, 2, 3, 0, 1, 2, 4 ] );
		const none = new Int32Array( other.length ).fill( - 1 );
		for ( let t = 0; t < other.length / 4; t ++ ) {

			const one = other.subarray( 4 * t, 4 * t + 4 );
			if ( checkDelaunay( bipyramid, one, none.subarray( 0, 4 ) ).nonPositive > 0 ) [ one[ 0 ], one[ 1 ] ] = [ one[ 1 ], one[ 0 ] ];

		}

		const report = checkDelaunay( bipyramid, other, none );
		expect( report.nonPositive ).toBe( 0 );
		expect( report.emptySphereViolations ).toBeGreaterThan( 0 );

	} );

} );
