import { describe, expect, it } from 'vitest';
import { DegenerateInputError } from '../../src/index.js';
import { PlanarMesh, TetrahedralMesh, createProbeInterpolator } from '../../src/math.js';
import { seededRandom } from '../helpers/pointSets.js';

/** 30 random probes on a tilted plane through (1, 2, 3) spanned by two unit vectors. */
function tiltedPlane( seed: number ): { positions: Float64Array; u: number[]; v: number[] } {

	const u = [ Math.SQRT1_2, Math.SQRT1_2, 0 ], v = [ 0, 0.6, 0.8 ].map( ( c, i ) => c - 0.6 * Math.SQRT1_2 * u[ i ] );
	const length = Math.hypot( ...v );
	for ( let i = 0; i < 3; i ++ ) v[ i ] /= length;
	const random = seededRandom( seed );
	const positions = new Float64Array( 90 );
	for ( let k = 0; k < 30; k ++ ) {

		const a = 4 * random(), b = 4 * random();
		for ( let i = 0; i < 3; i ++ ) positions[ 3 * k + i ] = [ 1, 2, 3 ][ i ] + a * u[ i ] + b * v[ i ];

	}

	return { positions, u, v };

}

describe( 'PlanarMesh and createProbeInterpolator (coplanar layouts: a floor of probes, a photo map)', () => {

	const { positions, u, v } = tiltedPlane( 2 );
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 );

	it( 'createProbeInterpolator falls back to a PlanarMesh for coplanar probes, TetrahedralMesh otherwise', () => {

		expect( createProbeInterpolator( positions ) ).toBeInstanceOf( PlanarMesh );
		const lifted = Float64Array.from( [ ...positions, 0, 0, 10 ] );
		expect( createProbeInterpolator( lifted ) ).toBeInstanceOf( TetrahedralMesh );

	} );

	it( 'reproduces a field linear in the plane, ignores the offset along the normal', () => {

		const mesh = new PlanarMesh( positions );
		const n = [ u[ 1 ] * v[ 2 ] - u[ 2 ] * v[ 1 ], u[ 2 ] * v[ 0 ] - u[ 0 ] * v[ 2 ], u[ 0 ] * v[ 1 ] - u[ 1 ] * v[ 0 ] ];
		const f = ( x: number, y: number, z: number ) => 2 * x - y + 0.5 * z;
		const fInPlane = ( p: number[] ) => { // f of the point projected onto the plane
			const d = ( p[ 0 ] - 1 ) * n[ 0 ] + ( p[ 1 ] - 2 ) * n[ 1 ] + ( p[ 2 ] - 3 ) * n[ 2 ];
			return f( p[ 0 ] - d * n[ 0 ], p[ 1 ] - d * n[ 1 ], p[ 2 ] - d * n[ 2 ] );
		};
		// Random points inside the triangles, lifted off the plane along its normal.
		const random = seededRandom( 9 );
		let hint = - 1;
		for ( let q = 0; q < 2000; q ++ ) {

			const t = Math.floor( random() * mesh.cellCount );
			let r0 = random(), r1 = random();
			if ( r0 + r1 > 1 ) { r0 = 1 - r0; r1 = 1 - r1; }
			const r = [ r0, r1, 1 - r0 - r1 ];
			const off = ( random() - 0.5 ) * 3;
			const p = [ 0, 1, 2 ].map( ( i ) => r[ 0 ] * positions[ 3 * mesh.triangles[ 3 * t ] + i ] + r[ 1 ] * positions[ 3 * mesh.triangles[ 3 * t + 1 ] + i ] + r[ 2 ] * positions[ 3 * mesh.triangles[ 3 * t + 2 ] + i ] + off * n[ i ] );
			hint = mesh.interpolate( p[ 0 ], p[ 1 ], p[ 2 ], indices, weights, hint );
			let value = 0, sum = 0;
			for ( let k = 0; k < 4; k ++ ) {

				expect( weights[ k ] ).toBeGreaterThanOrEqual( 0 );
				sum += weights[ k ];
				value += weights[ k ] * f( positions[ 3 * indices[ k ] ], positions[ 3 * indices[ k ] + 1 ], positions[ 3 * indices[ k ] + 2 ] );

			}

			expect( weights[ 3 ] ).toBe( 0 );
			expect( sum ).toBeCloseTo( 1, 12 );
			expect( Math.abs( value - fInPlane( p ) ) ).toBeLessThan( 1e-9 );

		}

	} );

	it( 'outside the triangulated region: weights of the nearest boundary point', () => {

		const square = new PlanarMesh( [ 0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 0.5, 0, 0.5 ] ); // y = 0 plane
		square.interpolate( 3, 0, 0.25, indices, weights );
		const x = [ 0, 1, 2 ].reduce( ( s, k ) => s + weights[ k ] * square.positions[ 3 * indices[ k ] ], 0 );
		const z = [ 0, 1, 2 ].reduce( ( s, k ) => s + weights[ k ] * square.positions[ 3 * indices[ k ] + 2 ], 0 );
		expect( x ).toBeCloseTo( 1, 12 );
		expect( z ).toBeCloseTo( 0.25, 12 );

	} );

	it( 'a floor grid with one probe added inside triangulates without sliver triangles (exact plane axes)', () => {

		// 5x4 probes on y = 1.5 plus one inside: 21 points, 14 of them on the boundary, so a
		// triangulation has 2·21 − 2 − 14 = 26 triangles, none of zero area. Rotated plane axes
		// once bent the rows off their lines and delaunator added slivers along them.
		const positions: number[] = [];
		for ( let j = 0; j < 4; j ++ ) for ( let i = 0; i < 5; i ++ ) positions.push( i * 7.3 - 11, 1.5, j * 5.1 - 4 );
		positions.push( 0.37, 1.5, 1.2 );
		const mesh = new PlanarMesh( positions );
		expect( mesh.cellCount ).toBe( 26 );
		for ( let t = 0; t < mesh.cellCount; t ++ ) {

			const [ a, b, c ] = [ 0, 1, 2 ].map( ( k ) => mesh.triangles[ 3 * t + k ] );
			const area = Math.abs( ( positions[ 3 * b ] - positions[ 3 * a ] ) * ( positions[ 3 * c + 2 ] - positions[ 3 * a + 2 ] ) - ( positions[ 3 * c ] - positions[ 3 * a ] ) * ( positions[ 3 * b + 2 ] - positions[ 3 * a + 2 ] ) ) / 2;
			expect( area ).toBeGreaterThan( 1 );

		}

	} );

	it( 'interpolates the same at any scale (1e-300 … 1e300, 2^±1000): finite weights, the unit-scale ones', () => {

		const unit = new PlanarMesh( positions );
		const random = seededRandom( 17 ), queries: number[][] = [];
		for ( let q = 0; q < 300; q ++ ) queries.push( [ random() * 8 - 2, random() * 8 - 2, random() * 8 - 2 ] );
		const expected = queries.map( ( q ) => {

			const i = new Uint32Array( 4 ), w = new Float64Array( 4 );
			unit.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], i, w );
			return { i, w };

		} );
		for ( const s of [ 1e-300, 1e-200, 2 ** - 1000, 1e200, 1e300, 2 ** 1000 ] ) {

			const mesh = new PlanarMesh( positions.map( ( v ) => v * s ) );
			expect( mesh.cellCount ).toBe( unit.cellCount );
			queries.forEach( ( q, n ) => {

				mesh.interpolate( q[ 0 ] * s, q[ 1 ] * s, q[ 2 ] * s, indices, weights );
				expect( Array.from( weights ).every( Number.isFinite ), `${s}, query ${n}` ).toBe( true );
				// A field with one value per probe: the same weights on the same probes give the same blend.
				const value = ( i: ArrayLike<number>, w: ArrayLike<number> ) => w[ 0 ] * ( i[ 0 ] + 1 ) + w[ 1 ] * ( i[ 1 ] + 1 ) + w[ 2 ] * ( i[ 2 ] + 1 );
				expect( Math.abs( value( indices, weights ) - value( expected[ n ].i, expected[ n ].w ) ), `${s}, query ${n}` ).toBeLessThan( 1e-9 * 30 );

			} );

		}

	} );

	it( 'checks its tolerance where it enters (and createProbeInterpolator its options), naming itself', () => {

		expect( () => new PlanarMesh( positions, NaN ) ).toThrow( new RangeError( 'PlanarMesh: duplicateTolerance must be a finite number ≥ 0, got NaN.' ) );
		expect( () => new PlanarMesh( positions, - 1e-9 ) ).toThrow( RangeError );
		expect( () => new PlanarMesh( positions, '0' as unknown as number ) ).toThrow( TypeError );
		expect( () => createProbeInterpolator( positions, { duplicateTolerance: NaN } ) )
			.toThrow( /^createProbeInterpolator: options.duplicateTolerance must be a finite number ≥ 0, got NaN/ );
		expect( () => createProbeInterpolator( positions, { planarTolerance: - 1 } ) ).toThrow( /^createProbeInterpolator: options.planarTolerance/ );
		expect( () => createProbeInterpolator( positions, 'x' as unknown as object ) ).toThrow( /^createProbeInterpolator: options must be an object/ );

	} );

	it( 'rejects collinear and too few probes with a DegenerateInputError', () => {

		expect( () => createProbeInterpolator( [ 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3 ] ) ).toThrow( /one line/ );
		expect( () => createProbeInterpolator( [ 0, 0, 0, 1, 1, 1 ] ) ).toThrow( DegenerateInputError );

	} );

} );
