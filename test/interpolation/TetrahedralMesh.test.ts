import { describe, expect, it } from 'vitest';
import { orient3d } from 'robust-predicates';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { blendSH } from '../../src/interpolation/blendSH.js';
import { gridPoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/** A linear field: barycentric interpolation must reproduce it exactly. */
const linearField = ( x: number, y: number, z: number ): number => 0.3 + 1.7 * x - 2.1 * y + 0.9 * z;

/** Exact test that (x, y, z) is inside or on tetrahedron t (independent of the mesh's float matrices). */
function containsExactly( mesh: TetrahedralMesh, t: number, x: number, y: number, z: number ): boolean {

	const p = mesh.positions, v = Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ) );
	for ( let i = 0; i < 4; i ++ ) {

		const q = v.map( ( k ) => [ p[ 3 * k ], p[ 3 * k + 1 ], p[ 3 * k + 2 ] ] );
		q[ i ] = [ x, y, z ];
		// robust-predicates' orient3d is negative for det[b − a, c − a, d − a] > 0.
		const [ a, b, c, d ] = q;
		if ( orient3d( a[ 0 ], a[ 1 ], a[ 2 ], b[ 0 ], b[ 1 ], b[ 2 ], c[ 0 ], c[ 1 ], c[ 2 ], d[ 0 ], d[ 1 ], d[ 2 ] ) > 0 ) return false;

	}

	return true;

}

function insideHullExactly( mesh: TetrahedralMesh, x: number, y: number, z: number ): boolean {

	const p = mesh.positions, f = mesh.hullFaces;
	for ( let i = 0; i < f.length; i += 3 ) {

		const a = 3 * f[ i ], b = 3 * f[ i + 1 ], c = 3 * f[ i + 2 ];
		// Hull faces are counter-clockwise from outside: the point is outside when det[b−a, c−a, q−a] > 0.
		if ( orient3d(
			p[ a ], p[ a + 1 ], p[ a + 2 ], p[ b ], p[ b + 1 ], p[ b + 2 ], p[ c ], p[ c + 1 ], p[ c + 2 ], x, y, z
		) < 0 ) return false;

	}

	return true;

}

describe( 'TetrahedralMesh', () => {

	const positions = randomPoints( 500, 21 );
	const mesh = new TetrahedralMesh( positions );
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 );

	it( 'keeps positions, tetrahedra, neighbours and a 3x3 inverse per tetrahedron', () => {

		expect( mesh.probeCount ).toBe( 500 );
		expect( mesh.tetrahedra.length ).toBe( 4 * mesh.cellCount );
		expect( mesh.neighbors.length ).toBe( 4 * mesh.cellCount );
		expect( mesh.inverseMatrices.length ).toBe( 9 * mesh.cellCount );
		// The inverse must map each vertex to its unit barycentric vector.
		for ( let t = 0; t < mesh.cellCount; t += 37 ) {

			for ( let k = 0; k < 4; k ++ ) {

				const v = mesh.tetrahedra[ 4 * t + k ];
				const w = mesh.barycentric( t, positions[ 3 * v ], positions[ 3 * v + 1 ], positions[ 3 * v + 2 ], new Float64Array( 4 ) );
				for ( let j = 0; j < 4; j ++ ) expect( w[ j ] ).toBeCloseTo( j === k ? 1 : 0, 9 );

			}

		}

	} );

	it( 'weights are ≥ 0, sum to 1, and reproduce a linear field exactly (1e-9) inside the hull', () => {

		const f = linearField;
		const random = seededRandom( 3 );
		let hint = - 1, tested = 0;
		for ( let q = 0; q < 20000; q ++ ) {

			const x = random(), y = random(), z = random();
			if ( mesh.locate( x, y, z, hint ) < 0 ) continue;
			hint = mesh.interpolate( x, y, z, indices, weights, hint );
			let sum = 0, value = 0;
			for ( let k = 0; k < 4; k ++ ) {

				expect( weights[ k ] ).toBeGreaterThanOrEqual( 0 );
				sum += weights[ k ];
				const v = indices[ k ];
				value += weights[ k ] * f( positions[ 3 * v ], positions[ 3 * v + 1 ], positions[ 3 * v + 2 ] );

			}

			expect( Math.abs( sum - 1 ) ).toBeLessThan( 1e-12 );
			expect( Math.abs( value - f( x, y, z ) ) ).toBeLessThan( 1e-9 );
			tested ++;

		}

		expect( tested ).toBeGreaterThan( 15000 );

	} );

	it( 'is continuous across shared faces: both cells give the same weights on the face', () => {

		const random = seededRandom( 8 );
		const a = new Float64Array( 4 ), b = new Float64Array( 4 );
		let faces = 0;
		for ( let t = 0; t < mesh.cellCount; t ++ ) {

			for ( let i = 0; i < 4; i ++ ) {

				const u = mesh.neighbors[ 4 * t + i ];
				if ( u < t ) continue;
				// A random point of the shared face (the three vertices other than i).
				const face = [ 0, 1, 2, 3 ].filter( ( k ) => k !== i ).map( ( k ) => mesh.tetrahedra[ 4 * t + k ] );
				let r0 = random(), r1 = random();
				if ( r0 + r1 > 1 ) { r0 = 1 - r0; r1 = 1 - r1; }
				const r = [ r0, r1, 1 - r0 - r1 ];
				const point = [ 0, 1, 2 ].map( ( axis ) => r[ 0 ] * positions[ 3 * face[ 0 ] + axis ] +
					r[ 1 ] * positions[ 3 * face[ 1 ] + axis ] + r[ 2 ] * positions[ 3 * face[ 2 ] + axis ] );
				mesh.barycentric( t, point[ 0 ], point[ 1 ], point[ 2 ], a );
				mesh.barycentric( u, point[ 0 ], point[ 1 ], point[ 2 ], b );
				for ( const v of face ) {

					const ka = mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ).indexOf( v );
					const kb = mesh.tetrahedra.subarray( 4 * u, 4 * u + 4 ).indexOf( v );
					expect( Math.abs( a[ ka ] - b[ kb ] ) ).toBeLessThan( 1e-9 );

				}

				expect( Math.abs( a[ i ] ) ).toBeLessThan( 1e-9 ); // the off-face vertex has no say on the face
				faces ++;

			}

		}

		expect( faces ).toBeGreaterThan( 1000 );

	} );

	it( '100,000 random queries from random hints find the cell an exact test confirms', () => {

		const random = seededRandom( 77 );
		let inside = 0;
		for ( let q = 0; q < 100000; q ++ ) {

			// Some queries fall outside the hull on purpose.
			const x = random() * 1.2 - 0.1, y = random() * 1.2 - 0.1, z = random() * 1.2 - 0.1;
			const hint = Math.floor( random() * mesh.cellCount );
			const t = mesh.locate( x, y, z, hint );
			if ( t >= 0 ) {

				if ( ! containsExactly( mesh, t, x, y, z ) ) throw new Error( `locate(${x}, ${y}, ${z}) returned ${t}, which does not contain the point` );
				inside ++;

			} else if ( insideHullExactly( mesh, x, y, z ) ) {

				throw new Error( `locate(${x}, ${y}, ${z}) returned −1 for a point inside the hull` );

			}

		}

		expect( inside ).toBeGreaterThan( 40000 );
		expect( inside ).toBeLessThan( 100000 );

	} );

	it( 'agrees with a full scan of every tetrahedron (2,000 queries)', () => {

		const random = seededRandom( 78 );
		for ( let q = 0; q < 2000; q ++ ) {

			const x = random(), y = random(), z = random();
			let scan = - 1;
			for ( let t = 0; t < mesh.cellCount && scan < 0; t ++ ) if ( containsExactly( mesh, t, x, y, z ) ) scan = t;
			expect( mesh.locate( x, y, z, q % mesh.cellCount ) ).toBe( scan );

		}

	} );

	it( "outside the hull with { outside: 'nearestFace' }: weights of the nearest hull point, continuous along a path that leaves the hull", () => {

		const grid = new TetrahedralMesh( gridPoints( 3, 3, 3, 1 ), { outside: 'nearestFace' } ); // the cube [0, 2]³
		const f = ( x: number, y: number, z: number ) => x + 2 * y + 3 * z;
		const sample = ( x: number, y: number, z: number, hint: number ) => {

			const t = grid.interpolate( x, y, z, indices, weights, hint );
			let value = 0, sum = 0;
			for ( let k = 0; k < 4; k ++ ) {

				const v = indices[ k ];
				expect( weights[ k ] ).toBeGreaterThanOrEqual( 0 );
				sum += weights[ k ];
				value += weights[ k ] * f( grid.positions[ 3 * v ], grid.positions[ 3 * v + 1 ], grid.positions[ 3 * v + 2 ] );

			}

			expect( sum ).toBeCloseTo( 1, 12 );
			return { value, t };

		};

		// Walk from the centre out through the +x face and far beyond, in small steps.
		let previous = sample( 1, 0.7, 1.3, - 1 ), hint = previous.t;
		for ( let s = 1; s <= 4000; s ++ ) {

			const x = 1 + s * 0.001;
			const current = sample( x, 0.7, 1.3, hint );
			// f has gradient 1 in x inside and 0 outside: a step of 0.001 changes it by at most 0.001.
			expect( Math.abs( current.value - previous.value ) ).toBeLessThanOrEqual( 0.001 + 1e-12 );
			previous = current; hint = current.t;

		}

		// Far outside the field is the one at the nearest hull point (2, 0.7, 1.3).
		expect( previous.value ).toBeCloseTo( f( 2, 0.7, 1.3 ), 9 );
		expect( grid.locate( 5, 0.7, 1.3, - 1 ) ).toBe( - 1 );
		// Beyond a corner, the nearest point is the corner itself.
		expect( sample( 9, 9, 9, - 1 ).value ).toBeCloseTo( f( 2, 2, 2 ), 9 );

	} );

	it( 'blends SH with the interpolation weights', () => {

		const grid = new TetrahedralMesh( gridPoints( 2, 2, 2, 1 ) );
		const sh = new Float32Array( 27 * 8 );
		// linear in x
		for ( let v = 0; v < 8; v ++ ) for ( let i = 0; i < 27; i ++ ) sh[ 27 * v + i ] = grid.positions[ 3 * v ] * ( i + 1 );
		const out = new Float32Array( 27 );
		grid.interpolate( 0.25, 0.5, 0.5, indices, weights );
		blendSH( indices, weights, sh, out );
		for ( let i = 0; i < 27; i ++ ) expect( out[ i ] ).toBeCloseTo( 0.25 * ( i + 1 ), 5 );

	} );

	it( 'rejects bad arguments by name', () => {

		expect( () => new TetrahedralMesh( [ 0, 0, 0, 1, 0, 0, 0, NaN, 0, 0, 0, 1 ] ) ).toThrow( /TetrahedralMesh: positions\[7\] is NaN/ );
		expect( () => mesh.interpolateChecked( 0, NaN, 0, indices, weights ) ).toThrow( /y must be a finite number/ );
		expect( () => mesh.interpolateChecked( 0, 0, 0, new Uint32Array( 3 ), weights ) ).toThrow( /indices must have room for 4/ );
		expect( () => blendSH( [ 0, 9 ], [ 0.5, 0.5 ], new Float32Array( 27 * 2 ), new Float32Array( 27 ) ) ).toThrow( /indices\[1\] = 9 is not a probe/ );

	} );

} );
