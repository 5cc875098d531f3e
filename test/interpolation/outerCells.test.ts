import { describe, expect, it } from 'vitest';
import { OuterCells } from '../../src/interpolation/OuterCells.js';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { gridPoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * Outer cells (extrapolation outside the hull). Truth used here, independent of OuterCells' cubic
 * solver: the defining geometry itself (a point equals Σ wᵢ (pᵢ + t nᵢ)), a root search by dense
 * sampling + bisection of det[b(t) − a(t), c(t) − a(t), q − a(t)] written out with vectors, the
 * inside weights on the hull, linear fields, brute force over every cell, and a jump detector
 * shown to catch a discontinuous interpolator.
 */

/** Two 5 × 5 layers of probes, 1 apart in x and y and 0.1 apart in z: a thin slab with sharp rims. */
function slabPoints(): Float64Array {

	const out: number[] = [];
	for ( let j = 0; j < 5; j ++ ) for ( let i = 0; i < 5; i ++ ) out.push( i, j, 0, i, j, 0.1 );
	return Float64Array.from( out );

}

/** Random points in a flat box [0, 1]² × [0, 0.05]: a flat-ish hull with sharp, irregular edges. */
function flatRandomPoints( n: number, seed: number ): Float64Array {

	const p = randomPoints( n, seed );
	for ( let i = 2; i < p.length; i += 3 ) p[ i ] *= 0.05;
	return p;

}

interface Case { name: string, mesh: TetrahedralMesh, min: number[], max: number[], extent: number }

function makeCase( name: string, positions: Float64Array ): Case {

	const mesh = new TetrahedralMesh( positions );
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < positions.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], positions[ i ] );
		max[ i % 3 ] = Math.max( max[ i % 3 ], positions[ i ] );

	}

	return { name, mesh, min, max, extent: Math.hypot( max[ 0 ] - min[ 0 ], max[ 1 ] - min[ 1 ], max[ 2 ] - min[ 2 ] ) };

}

const cases: Case[] = [
	makeCase( 'random cloud (200)', randomPoints( 200, 5 ) ),
	makeCase( 'random cloud (40)', randomPoints( 40, 11 ) ),
	makeCase( '4x4x4 grid', gridPoints( 4, 4, 4, 1 ) ),
	makeCase( 'thin slab (two 5x5 layers 0.1 apart)', slabPoints() ),
	makeCase( 'flat random box (100 points, 1 x 1 x 0.05)', flatRandomPoints( 100, 7 ) ),
];

/** A linear field of the probes' positions. */
const field = ( x: number, y: number, z: number ): number => 0.3 + 1.7 * x - 2.1 * y + 0.9 * z;

const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 );

/** Interpolated value of `field` and the new hint; checks weights ≥ 0, sum 1 on the way. */
function sample( mesh: TetrahedralMesh, x: number, y: number, z: number, hint: number ): { value: number, hint: number } {

	const next = mesh.interpolate( x, y, z, indices, weights, hint );
	let value = 0, sum = 0;
	const p = mesh.positions;
	for ( let k = 0; k < 4; k ++ ) {

		if ( ! ( weights[ k ] >= 0 ) ) throw new Error( `weight ${weights[ k ]} at (${x}, ${y}, ${z})` );
		sum += weights[ k ];
		const v = indices[ k ];
		value += weights[ k ] * field( p[ 3 * v ], p[ 3 * v + 1 ], p[ 3 * v + 2 ] );

	}

	if ( Math.abs( sum - 1 ) > 1e-12 ) throw new Error( `weights sum to ${sum} at (${x}, ${y}, ${z})` );
	return { value, hint: next };

}

/**
 * Walks the segment a → b in steps of `step` and returns the largest change between consecutive
 * samples that does not shrink when the step does (a jump): a large change is refined by bisection
 * 40 times towards where it happens; a steep but continuous change shrinks to nothing, a jump stays.
 */
function largestJump( value: ( x: number, y: number, z: number ) => number, a: number[], b: number[], step: number ): number {

	const length = Math.hypot( b[ 0 ] - a[ 0 ], b[ 1 ] - a[ 1 ], b[ 2 ] - a[ 2 ] );
	const n = Math.ceil( length / step );
	const at = ( s: number ) => value( a[ 0 ] + ( b[ 0 ] - a[ 0 ] ) * s, a[ 1 ] + ( b[ 1 ] - a[ 1 ] ) * s, a[ 2 ] + ( b[ 2 ] - a[ 2 ] ) * s );
	let jump = 0, previous = at( 0 );
	for ( let i = 1; i <= n; i ++ ) {

		const current = at( i / n );
		// The field's gradient is 2.9 and extrapolated weights change no faster than near the probes.
		if ( Math.abs( current - previous ) > 50 * step ) {

			let lo = ( i - 1 ) / n, hi = i / n, vLo = previous, vHi = current;
			for ( let r = 0; r < 40; r ++ ) {

				const mid = 0.5 * ( lo + hi ), vMid = at( mid );
				if ( Math.abs( vMid - vLo ) >= Math.abs( vHi - vMid ) ) { hi = mid; vHi = vMid; } else { lo = mid; vLo = vMid; }

			}

			// What is left after 40 halvings: ~0 for a steep continuous change, the jump's size for a jump.
			if ( Math.abs( vHi - vLo ) > 1e-9 ) jump = Math.max( jump, Math.abs( vHi - vLo ) );

		}

		previous = current;

	}

	return jump;

}

/** Smallest t ≥ 0 with q in the plane of hull face f moved along its vertex normals, by sampling and bisection (no cubic). */
function independentSolve( mesh: TetrahedralMesh, f: number, q: number[], tMax: number ): { t: number, w: number[] } | null {

	const p = mesh.positions, n = mesh.outerCells.normals;
	const v = [ 0, 1, 2 ].map( ( k ) => 3 * mesh.hullFaces[ 3 * f + k ] );
	const moved = ( t: number ) => v.map( ( i ) => [ 0, 1, 2 ].map( ( c ) => p[ i + c ] + t * n[ i + c ] ) );
	const sub = ( x: number[], y: number[] ) => x.map( ( xi, i ) => xi - y[ i ] );
	const cross = ( x: number[], y: number[] ) => [ x[ 1 ] * y[ 2 ] - x[ 2 ] * y[ 1 ], x[ 2 ] * y[ 0 ] - x[ 0 ] * y[ 2 ], x[ 0 ] * y[ 1 ] - x[ 1 ] * y[ 0 ] ];
	const dot = ( x: number[], y: number[] ) => x[ 0 ] * y[ 0 ] + x[ 1 ] * y[ 1 ] + x[ 2 ] * y[ 2 ];
	const det = ( t: number ) => { const [ a, b, c ] = moved( t ); return dot( cross( sub( b, a ), sub( c, a ) ), sub( q, a ) ); };
	// Samples: 0, then geometric from 1e-9 to tMax.
	let lo = 0, dLo = det( 0 ), hi = - 1;
	if ( dLo !== 0 ) {

		for ( let i = 0; i <= 4000; i ++ ) {

			const t = 1e-9 * Math.pow( tMax / 1e-9, i / 4000 ), d = det( t );
			if ( ( d < 0 ) !== ( dLo < 0 ) || d === 0 ) { hi = t; break; }
			lo = t; dLo = d;

		}

		if ( hi < 0 ) return null;
		for ( let i = 0; i < 200; i ++ ) {

			const mid = 0.5 * ( lo + hi ), d = det( mid );
			if ( ( d < 0 ) === ( dLo < 0 ) ) { lo = mid; dLo = d; } else hi = mid;

		}

	}

	const t = dLo === 0 ? lo : 0.5 * ( lo + hi );
	const [ a, b, c ] = moved( t );
	const normal = cross( sub( b, a ), sub( c, a ) ), nn = dot( normal, normal );
	const wb = dot( cross( sub( q, a ), sub( c, a ) ), normal ) / nn, wc = dot( cross( sub( b, a ), sub( q, a ) ), normal ) / nn;
	return { t, w: [ 1 - wb - wc, wb, wc ] };

}

/** A random point outside the hull, within `margin` extents of its bounding box. */
function randomOutside( c: Case, random: () => number, margin: number ): number[] {

	for ( ;; ) {

		const q = [ 0, 1, 2 ].map( ( k ) => c.min[ k ] - margin * c.extent + random() * ( c.max[ k ] - c.min[ k ] + 2 * margin * c.extent ) );
		if ( c.mesh.locate( q[ 0 ], q[ 1 ], q[ 2 ] ) < 0 ) return q;

	}

}

describe( 'TetrahedralMesh outer cells (outside the convex hull)', () => {

	it( 'vertex normals are the angle-weighted averages: face, edge and corner normals of a grid, whatever its triangulation', () => {

		const { mesh } = cases[ 2 ]; // the cube [0, 3]³
		const n = mesh.outerCells.normals, p = mesh.positions;
		let checked = 0;
		for ( let v = 0; v < mesh.probeCount; v ++ ) {

			const expected = [ 0, 1, 2 ].map( ( k ) => p[ 3 * v + k ] === 0 ? - 1 : p[ 3 * v + k ] === 3 ? 1 : 0 );
			const length = Math.hypot( ...expected );
			for ( let k = 0; k < 3; k ++ ) expect( n[ 3 * v + k ] ).toBeCloseTo( length === 0 ? 0 : expected[ k ] / length, 12 );
			checked ++;

		}

		expect( checked ).toBe( 64 );

	} );

	it( 'on the hull surface the outer-cell weights are the hull face\'s weights, equal to the inside weights (1e-9), and reproduce a linear field', () => {

		const random = seededRandom( 4 );
		const out = new Float64Array( 4 ), inside = new Float64Array( 4 ), insideIndices = new Uint32Array( 4 );
		for ( const c of cases ) {

			const { mesh } = c, p = mesh.positions, faces = mesh.hullFaces;
			for ( let f = 0; f < faces.length / 3; f ++ ) {

				for ( let r = 0; r < 5; r ++ ) {

					let u = random(), v = random();
					if ( u + v > 1 ) { u = 1 - u; v = 1 - v; }
					const b = [ 1 - u - v, u, v ];
					const q = [ 0, 1, 2 ].map( ( k ) => b[ 0 ] * p[ 3 * faces[ 3 * f ] + k ] + b[ 1 ] * p[ 3 * faces[ 3 * f + 1 ] + k ] + b[ 2 ] * p[ 3 * faces[ 3 * f + 2 ] + k ] );
					expect( mesh.outerCells.solve( f, q[ 0 ], q[ 1 ], q[ 2 ], out ) ).toBe( true );
					expect( out[ 0 ] ).toBeLessThan( 1e-9 * c.extent );
					for ( let k = 0; k < 3; k ++ ) expect( Math.abs( out[ 1 + k ] - b[ k ] ) ).toBeLessThan( 1e-9 );
					// The inside interpolation at the same point gives the same probes the same weights.
					const t = mesh.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], insideIndices, inside );
					expect( t ).toBeLessThan( mesh.cellCount );
					let value = 0;
					for ( let k = 0; k < 4; k ++ ) {

						const j = Array.from( faces.subarray( 3 * f, 3 * f + 3 ) ).indexOf( insideIndices[ k ] );
						expect( Math.abs( inside[ k ] - ( j < 0 ? 0 : out[ 1 + j ] ) ) ).toBeLessThan( 1e-9 );
						const w = insideIndices[ k ];
						value += inside[ k ] * field( p[ 3 * w ], p[ 3 * w + 1 ], p[ 3 * w + 2 ] );

					}

					expect( Math.abs( value - field( q[ 0 ], q[ 1 ], q[ 2 ] ) ) ).toBeLessThan( 1e-9 );
					// Just outside (1e-9 of the extent along the face normal), interpolate() says the same.
					const n = [ 0, 1, 2 ].map( ( k ) => mesh.outerCells.coefficients[ 12 * f + k ] * c.extent );
					const s = sample( mesh, q[ 0 ] + 1e-9 * c.extent * n[ 0 ], q[ 1 ] + 1e-9 * c.extent * n[ 1 ], q[ 2 ] + 1e-9 * c.extent * n[ 2 ], - 1 );
					expect( s.hint ).toBeGreaterThanOrEqual( mesh.cellCount );
					expect( Math.abs( s.value - value ) ).toBeLessThan( 1e-7 );

				}

			}

		}

	} );

	it( 'along the ray from a hull vertex along its normal, the weight is that vertex\'s alone, out to 1e6', () => {

		for ( const c of cases ) {

			const { mesh } = c, p = mesh.positions, n = mesh.outerCells.normals;
			const onHull = new Set( mesh.hullFaces );
			for ( const v of onHull ) {

				let hint = - 1;
				for ( const d of [ 1e-6, 0.01, 0.3, 1, 10, 1e6 ] ) {

					const dd = d * c.extent;
					hint = mesh.interpolate( p[ 3 * v ] + dd * n[ 3 * v ], p[ 3 * v + 1 ] + dd * n[ 3 * v + 1 ], p[ 3 * v + 2 ] + dd * n[ 3 * v + 2 ], indices, weights, hint );
					expect( hint ).toBeGreaterThanOrEqual( mesh.cellCount );
					const k = Array.from( indices ).indexOf( v );
					if ( k < 0 || Math.abs( weights[ k ] - 1 ) > 1e-9 ) throw new Error( `${c.name}: vertex ${v} at ${d} extents: indices ${indices}, weights ${weights}` );

				}

			}

		}

	} );

	it( 'the cell found by the walk solves the defining geometry: q = Σ wᵢ (pᵢ + t nᵢ), t the smallest such t ≥ 0 (independent root search)', () => {

		const random = seededRandom( 12 );
		for ( const c of cases ) {

			const { mesh } = c, p = mesh.positions, n = mesh.outerCells.normals, out = new Float64Array( 4 );
			for ( let i = 0; i < 150; i ++ ) {

				const q = randomOutside( c, random, i < 100 ? 0.5 : 5 );
				const hint = mesh.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], indices, weights );
				const f = hint - mesh.cellCount;
				expect( mesh.outerCells.solve( f, q[ 0 ], q[ 1 ], q[ 2 ], out ) ).toBe( true );
				const t = out[ 0 ];
				for ( let k = 0; k < 3; k ++ ) {

					let x = 0;
					for ( let j = 0; j < 3; j ++ ) { const v = 3 * mesh.hullFaces[ 3 * f + j ]; x += out[ 1 + j ] * ( p[ v + k ] + t * n[ v + k ] ); }
					expect( Math.abs( x - q[ k ] ) ).toBeLessThan( 1e-9 * c.extent );

				}

				const truth = independentSolve( mesh, f, q, 1e3 * c.extent );
				expect( truth ).not.toBeNull();
				expect( Math.abs( truth!.t - t ) ).toBeLessThan( 1e-7 * ( c.extent + t ) );
				for ( let k = 0; k < 3; k ++ ) expect( Math.abs( truth!.w[ k ] - weights[ k ] ) ).toBeLessThan( 1e-6 );

			}

		}

	} );

	it( 'continuity: random straight paths crossing the hull, sampled every 1e-3 of the extent, have no jumps (inside, across the hull, across outer cells)', () => {

		const random = seededRandom( 21 );
		const report: string[] = [];
		for ( const c of cases ) {

			const { mesh } = c;
			let hint = - 1, worst = 0;
			const value = ( x: number, y: number, z: number ) => { const s = sample( mesh, x, y, z, hint ); hint = s.hint; return s.value; };
			const centre = [ 0, 1, 2 ].map( ( k ) => 0.5 * ( c.min[ k ] + c.max[ k ] ) );
			for ( let path = 0; path < 100; path ++ ) {

				// From a point inside the bounding box to one up to 1.5 extents outside.
				const a = centre.map( ( m, k ) => m + ( random() - 0.5 ) * 0.6 * ( c.max[ k ] - c.min[ k ] ) );
				const direction = [ random() - 0.5, random() - 0.5, random() - 0.5 ], length = Math.hypot( ...direction );
				const b = a.map( ( m, k ) => m + direction[ k ] / length * 1.5 * c.extent );
				worst = Math.max( worst, largestJump( value, a, b, 1e-3 * c.extent ) );

			}

			report.push( `${c.name}: ${worst}` );

		}

		expect( report ).toEqual( cases.map( ( c ) => `${c.name}: 0` ) );

	} );

	it( 'the jump detector catches a discontinuous interpolator (nearest probe), so the continuity test can fail', () => {

		const { mesh } = cases[ 0 ], p = mesh.positions;
		const nearestProbe = ( x: number, y: number, z: number ) => {

			let best = 0, bestDistance = Infinity;
			for ( let v = 0; v < mesh.probeCount; v ++ ) {

				const d = ( p[ 3 * v ] - x ) ** 2 + ( p[ 3 * v + 1 ] - y ) ** 2 + ( p[ 3 * v + 2 ] - z ) ** 2;
				if ( d < bestDistance ) { bestDistance = d; best = v; }

			}

			return field( p[ 3 * best ], p[ 3 * best + 1 ], p[ 3 * best + 2 ] );

		};

		expect( largestJump( nearestProbe, [ 0.5, 0.5, 0.5 ], [ 2, 1.5, 0.5 ], 1e-3 ) ).toBeGreaterThan( 0.01 );

	} );

	it( 'far outside (1e6 and 1e300 extents away) weights are finite, ≥ 0, sum to 1, and converge to a limit', () => {

		const random = seededRandom( 31 );
		const limit = new Float64Array( 4 ), limitIndices = new Uint32Array( 4 );
		for ( const c of cases ) {

			const { mesh } = c;
			for ( let i = 0; i < 200; i ++ ) {

				const d = [ random() - 0.5, random() - 0.5, random() - 0.5 ], length = Math.hypot( ...d );
				for ( const r of [ 1e6, 1e300 ] ) {

					const s = r * c.extent / length;
					mesh.interpolate( d[ 0 ] * s, d[ 1 ] * s, d[ 2 ] * s, indices, weights );
					let sum = 0;
					for ( let k = 0; k < 4; k ++ ) { expect( weights[ k ] ).toBeGreaterThanOrEqual( 0 ); sum += weights[ k ]; }
					expect( Math.abs( sum - 1 ) ).toBeLessThan( 1e-12 );

				}

				// 1e6 and 2e6 away in the same direction: the same probes, weights within 1e-5.
				const s = 1e6 * c.extent / length;
				mesh.interpolate( d[ 0 ] * s, d[ 1 ] * s, d[ 2 ] * s, limitIndices, limit );
				mesh.interpolate( d[ 0 ] * 2 * s, d[ 1 ] * 2 * s, d[ 2 ] * 2 * s, indices, weights );
				for ( let k = 0; k < 4; k ++ ) {

					const j = Array.from( indices ).indexOf( limitIndices[ k ] );
					expect( Math.abs( ( j < 0 ? 0 : weights[ j ] ) - limit[ k ] ) ).toBeLessThan( 1e-5 );

				}

			}

		}

	} );

	it( 'the walk agrees with brute force over every outer cell for 10,000 random outside points; cells never overlap with different values', () => {

		const random = seededRandom( 41 );
		const out = new Float64Array( 4 ), nearest = new Float64Array( 4 ), nearestIndices = new Uint32Array( 4 );
		const counts: Record<string, { claimed: number, unclaimed: number }> = {};
		for ( let i = 0; i < 10000; i ++ ) {

			const c = cases[ i % cases.length ], { mesh } = c;
			const q = randomOutside( c, random, i % 2 === 0 ? 0.3 : 3 );
			// From a random hint (a tetrahedron, an outer cell or none), as a moving object would.
			const r = random();
			const hint = r < 0.3 ? - 1 : r < 0.6 ? Math.floor( random() * mesh.cellCount ) : mesh.cellCount + Math.floor( random() * mesh.outerCells.count );
			const result = mesh.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], indices, weights, hint );
			expect( result ).toBeGreaterThanOrEqual( mesh.cellCount );
			const claims: number[] = [];
			for ( let f = 0; f < mesh.outerCells.count; f ++ ) {

				if ( mesh.outerCells.solve( f, q[ 0 ], q[ 1 ], q[ 2 ], out ) && out[ 1 ] >= - 1e-10 && out[ 2 ] >= - 1e-10 && out[ 3 ] >= - 1e-10 ) claims.push( f );

			}

			const tally = counts[ c.name ] ??= { claimed: 0, unclaimed: 0 };
			if ( claims.length > 0 ) {

				tally.claimed ++;
				// Several claimants only on the quads and rays they share, where they agree: no overlaps.
				const values = claims.map( ( f ) => {

					mesh.outerCells.solve( f, q[ 0 ], q[ 1 ], q[ 2 ], out );
					let value = 0;
					for ( let k = 0; k < 3; k ++ ) { const v = 3 * mesh.hullFaces[ 3 * f + k ]; value += out[ 1 + k ] * field( mesh.positions[ v ], mesh.positions[ v + 1 ], mesh.positions[ v + 2 ] ); }
					return value;

				} );
				expect( Math.max( ...values ) - Math.min( ...values ) ).toBeLessThan( 1e-9 );
				const f = result - mesh.cellCount;
				if ( ! claims.includes( f ) ) throw new Error( `${c.name}: walk chose cell ${f} at ${q}, brute force finds ${claims}` );
				mesh.outerCells.solve( f, q[ 0 ], q[ 1 ], q[ 2 ], out );
				for ( let k = 0; k < 3; k ++ ) expect( Math.abs( weights[ k ] - Math.max( 0, out[ 1 + k ] ) ) ).toBeLessThan( 1e-9 );

			} else {

				// No cell's sweep reaches the point: the nearest hull point's weights answer.
				tally.unclaimed ++;
				const near = nearestFaceMesh( mesh );
				near.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], nearestIndices, nearest );
				for ( let k = 0; k < 3; k ++ ) expect( weights[ k ] ).toBe( nearest[ k ] );

			}

		}

		// On these sets the sweeps leave no gaps: the nearest-face fallback is never needed.
		expect( cases.map( ( c ) => `${c.name}: ${counts[ c.name ].claimed} claimed, ${counts[ c.name ].unclaimed} unclaimed` ) ).toEqual( cases.map( ( c ) => `${c.name}: 2000 claimed, 0 unclaimed` ) );

	} );

	it( 'differs from the nearest-face mode where it should: beyond the side of a cube, off the face normal', () => {

		const cube = gridPoints( 3, 3, 3, 1 ); // [0, 2]³
		const outer = new TetrahedralMesh( cube ), near = new TetrahedralMesh( cube, { outside: 'nearestFace' } );
		const f = ( x: number, y: number, z: number ) => x + 2 * y + 3 * z;
		const valueOf = ( mesh: TetrahedralMesh, x: number, y: number, z: number ) => {

			mesh.interpolate( x, y, z, indices, weights );
			let value = 0;
			for ( let k = 0; k < 4; k ++ ) value += weights[ k ] * f( cube[ 3 * indices[ k ] ], cube[ 3 * indices[ k ] + 1 ], cube[ 3 * indices[ k ] + 2 ] );
			return value;

		};

		// Nearest face: the value at the nearest hull point (2, 0.7, 1.3), whatever the distance.
		expect( valueOf( near, 5, 0.7, 1.3 ) ).toBeCloseTo( f( 2, 0.7, 1.3 ), 12 );
		// Outer cells: the rays of the probes at y = 0 lean towards −y, so far out the point sits
		// relatively nearer the y = 1 probes: the independent solver's value, not the nearest-face one.
		const q = [ 5, 0.7, 1.3 ];
		const hint = outer.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], indices, weights ) - outer.cellCount;
		const truth = independentSolve( outer, hint, q, 1e3 )!;
		let expected = 0;
		for ( let k = 0; k < 3; k ++ ) { const v = outer.hullFaces[ 3 * hint + k ]; expected += truth.w[ k ] * f( cube[ 3 * v ], cube[ 3 * v + 1 ], cube[ 3 * v + 2 ] ); }
		expect( valueOf( outer, 5, 0.7, 1.3 ) ).toBeCloseTo( expected, 9 );
		expect( Math.abs( expected - f( 2, 0.7, 1.3 ) ) ).toBeGreaterThan( 0.1 );
		// Both agree on the hull and along a vertex's own ray (the corner (2, 2, 2), normal (1, 1, 1)/√3).
		expect( valueOf( outer, 2, 0.7, 1.3 ) ).toBeCloseTo( valueOf( near, 2, 0.7, 1.3 ), 12 );
		expect( valueOf( outer, 7, 7, 7 ) ).toBeCloseTo( f( 2, 2, 2 ), 9 );
		expect( valueOf( near, 7, 7, 7 ) ).toBeCloseTo( f( 2, 2, 2 ), 9 );

	} );

	it( 'where no outer cell reaches a point, the nearest hull point\'s weights answer (fallback wiring, forced)', () => {

		const { mesh } = cases[ 0 ], near = nearestFaceMesh( mesh );
		const cells = mesh.outerCells as unknown as { locate: ( ...args: unknown[] ) => number };
		const locate = cells.locate;
		cells.locate = () => - 1;
		try {

			const expected = new Float64Array( 4 ), expectedIndices = new Uint32Array( 4 );
			const hint = mesh.interpolate( 1.7, 0.4, - 0.6, indices, weights );
			near.interpolate( 1.7, 0.4, - 0.6, expectedIndices, expected );
			expect( Array.from( indices ) ).toEqual( Array.from( expectedIndices ) );
			expect( Array.from( weights ) ).toEqual( Array.from( expected ) );
			expect( hint ).toBeGreaterThanOrEqual( mesh.cellCount );

		} finally {

			cells.locate = locate;

		}

	} );

	it( 'hints: an outer cell comes back as cellCount + face, and a hint from outside still finds the inside', () => {

		const { mesh } = cases[ 2 ];
		const outside = mesh.interpolate( 5, 1.5, 1.5, indices, weights );
		expect( outside ).toBeGreaterThanOrEqual( mesh.cellCount );
		expect( outside - mesh.cellCount ).toBeLessThan( mesh.outerCells.count );
		// Back inside with the outer hint: a tetrahedron, and locate accepts the outer hint too.
		const inside = mesh.interpolate( 2.9, 1.5, 1.5, indices, weights, outside );
		expect( inside ).toBeLessThan( mesh.cellCount );
		expect( mesh.locate( 2.9, 1.5, 1.5, outside ) ).toBe( inside );
		expect( mesh.locate( 5, 1.5, 1.5, outside ) ).toBe( - 1 );
		let value = 0;
		for ( let k = 0; k < 4; k ++ ) value += weights[ k ] * field( mesh.positions[ 3 * indices[ k ] ], mesh.positions[ 3 * indices[ k ] + 1 ], mesh.positions[ 3 * indices[ k ] + 2 ] );
		expect( value ).toBeCloseTo( field( 2.9, 1.5, 1.5 ), 9 );

	} );

	it( 'NaN or infinite coordinates throw, named, from interpolate and interpolateChecked; bad options are named', () => {

		const { mesh } = cases[ 0 ];
		expect( () => mesh.interpolate( 0, NaN, 0, indices, weights ) ).toThrow( /TetrahedralMesh.interpolate: y must be a finite number/ );
		expect( () => mesh.interpolate( Infinity, 0, 0, indices, weights ) ).toThrow( /TetrahedralMesh.interpolate: x must be a finite number/ );
		expect( () => mesh.interpolateChecked( 0, 0, NaN, indices, weights ) ).toThrow( /TetrahedralMesh.interpolate: z must be a finite number/ );
		expect( () => new TetrahedralMesh( randomPoints( 10, 1 ), { outside: 'clamp' as 'nearestFace' } ) ).toThrow( /options.outside must be 'outerCells' or 'nearestFace'/ );

	} );

} );

/** `p` with coordinate k multiplied by s[k]: a box flattened in one or two axes. */
function scaledPoints( p: Float64Array, s: number[] ): Float64Array {

	for ( let i = 0; i < p.length; i ++ ) p[ i ] *= s[ i % 3 ];
	return p;

}

/** n random points in the unit disc times [0, h] in z: a flat round hull whose rim is all sharp edges. */
function discPoints( n: number, seed: number, h: number ): Float64Array {

	const random = seededRandom( seed ), out: number[] = [];
	while ( out.length < 3 * n ) {

		const x = 2 * random() - 1, y = 2 * random() - 1;
		if ( x * x + y * y < 1 ) out.push( x, y, h * random() );

	}

	return Float64Array.from( out );

}

/** `p` rotated about z by 0.7 rad, then about x by 0.4 rad: flat layouts not aligned with the axes. */
function rotatedPoints( p: Float64Array ): Float64Array {

	const c = Math.cos( 0.7 ), s = Math.sin( 0.7 ), c2 = Math.cos( 0.4 ), s2 = Math.sin( 0.4 );
	for ( let i = 0; i < p.length; i += 3 ) {

		const x = p[ i ], y = p[ i + 1 ], z = p[ i + 2 ], x1 = c * x - s * y, y1 = s * x + c * y;
		p[ i ] = x1; p[ i + 1 ] = c2 * y1 - s2 * z; p[ i + 2 ] = s2 * y1 + c2 * z;

	}

	return p;

}

describe( 'outer cells tile the outside of flat hulls (no gaps, no overlaps)', () => {

	/*
	 * Layouts of the survey whose angle-weighted (then smoothed) normals left gaps between sweeps or
	 * cells overlapping with different weights before the Jacobian test of OuterCells (boxes
	 * flattened 20:1 and 100:1 in one or two axes, a rotated one, a disc 400:1; on the old normals
	 * the disc has gaps and overlaps here, the others folding cells and jumps along paths), plus a
	 * 200:1 box, a 40:1 disc and ordinary layouts that must stay tiled.
	 */
	const flat: Case[] = [
		makeCase( 'box 20:1 (100, seed 7201)', scaledPoints( randomPoints( 100, 7201 ), [ 1, 1, 1 / 20 ] ) ),
		makeCase( 'box 20:1 (100, seed 7203)', scaledPoints( randomPoints( 100, 7203 ), [ 1, 1, 1 / 20 ] ) ),
		makeCase( 'box 100:1 in two axes (100, seed 9002)', scaledPoints( randomPoints( 100, 9002 ), [ 1, 1 / 100, 1 / 100 ] ) ),
		makeCase( 'rotated box 100:1 (200)', rotatedPoints( scaledPoints( randomPoints( 200, 9100 ), [ 1, 1, 1 / 100 ] ) ) ),
		makeCase( 'disc 400:1 (200)', discPoints( 200, 70, 0.005 ) ),
		makeCase( 'disc 40:1 (200)', discPoints( 200, 70, 0.05 ) ),
		makeCase( 'box 200:1 (100, seed 9202)', scaledPoints( randomPoints( 100, 9202 ), [ 1, 1, 1 / 200 ] ) ),
		makeCase( 'random cloud (50)', randomPoints( 50, 5002 ) ),
		makeCase( '12x6x6 grid', gridPoints( 12, 6, 6, 1 ) ),
	];

	it( 'every outside point, 0.01 to 10 extents out, is in exactly one cell: the walk never falls back, brute force finds no second cell with other weights (22,500 points)', () => {

		const random = seededRandom( 77 );
		const out = new Float64Array( 4 ), found = new Float64Array( 4 );
		const report: string[] = [];
		for ( const c of flat ) {

			const cells = c.mesh.outerCells, faces = cells.faces, count = cells.count;
			let gaps = 0, overlaps = 0;
			for ( const margin of [ 0.01, 0.1, 0.5, 2, 10 ] ) {

				for ( let i = 0; i < 500; i ++ ) {

					const q = randomOutside( c, random, margin );
					const f = cells.locate( q[ 0 ], q[ 1 ], q[ 2 ], Math.floor( random() * count ), found );
					if ( f < 0 ) { gaps ++; continue; }
					for ( let g = 0; g < count; g ++ ) {

						if ( g === f || ! ( cells.solve( g, q[ 0 ], q[ 1 ], q[ 2 ], out ) && out[ 1 ] >= - 1e-10 && out[ 2 ] >= - 1e-10 && out[ 3 ] >= - 1e-10 ) ) continue;
						// A second claimant is fine only on a shared quad or ray, with the same weight per probe.
						let differs = false;
						for ( let k = 0; k < 3; k ++ ) {

							const j = Array.from( faces.subarray( 3 * f, 3 * f + 3 ) ).indexOf( faces[ 3 * g + k ] );
							if ( Math.abs( out[ 1 + k ] - ( j < 0 ? 0 : found[ 1 + j ] ) ) > 1e-7 ) differs = true;

						}

						if ( differs ) { overlaps ++; break; }

					}

				}

			}

			report.push( `${c.name}: ${gaps} gaps, ${overlaps} overlaps` );

		}

		expect( report ).toEqual( flat.map( ( c ) => `${c.name}: 0 gaps, 0 overlaps` ) );

	} );

	it( 'every hull vertex\'s ray leaves all its faces and no cell folds: N(t)·nᵢ > 0 for t up to 1e6 extents (sampled, independent of the build\'s quadratic test)', () => {

		const bad: string[] = [];
		for ( const c of flat ) {

			const { mesh } = c, p = mesh.positions, n = mesh.outerCells.normals, faces = mesh.hullFaces;
			for ( let f = 0; f < faces.length / 3; f ++ ) {

				const v = [ 0, 1, 2 ].map( ( k ) => 3 * faces[ 3 * f + k ] );
				for ( const t of [ 0, 1e-4, 1e-3, 0.01, 0.03, 0.1, 0.3, 1, 3, 10, 100, 1e4, 1e6 ].map( ( x ) => x * c.extent ) ) {

					const m = v.map( ( i ) => [ 0, 1, 2 ].map( ( k ) => p[ i + k ] + t * n[ i + k ] ) );
					const e1 = [ 0, 1, 2 ].map( ( k ) => m[ 1 ][ k ] - m[ 0 ][ k ] ), e2 = [ 0, 1, 2 ].map( ( k ) => m[ 2 ][ k ] - m[ 0 ][ k ] );
					const N = [ e1[ 1 ] * e2[ 2 ] - e1[ 2 ] * e2[ 1 ], e1[ 2 ] * e2[ 0 ] - e1[ 0 ] * e2[ 2 ], e1[ 0 ] * e2[ 1 ] - e1[ 1 ] * e2[ 0 ] ];
					for ( const i of v ) if ( ! ( N[ 0 ] * n[ i ] + N[ 1 ] * n[ i + 1 ] + N[ 2 ] * n[ i + 2 ] > 0 ) ) bad.push( `${c.name}: face ${f} at t = ${t}` );

				}

			}

		}

		expect( bad.slice( 0, 5 ) ).toEqual( [] );

	} );

	it( 'continuity on the flat layouts: random straight paths crossing the hull and rims, sampled every 1e-3 of the extent, have no jumps', () => {

		const random = seededRandom( 23 );
		const report: string[] = [];
		for ( const c of flat.slice( 0, 7 ) ) {

			const { mesh } = c;
			let hint = - 1, worst = 0;
			const value = ( x: number, y: number, z: number ) => { const s = sample( mesh, x, y, z, hint ); hint = s.hint; return s.value; };
			const centre = [ 0, 1, 2 ].map( ( k ) => 0.5 * ( c.min[ k ] + c.max[ k ] ) );
			for ( let path = 0; path < 40; path ++ ) {

				const a = centre.map( ( m, k ) => m + ( random() - 0.5 ) * 0.6 * ( c.max[ k ] - c.min[ k ] ) );
				const direction = [ random() - 0.5, random() - 0.5, random() - 0.5 ], length = Math.hypot( ...direction );
				const b = a.map( ( m, k ) => m + direction[ k ] / length * 1.5 * c.extent );
				worst = Math.max( worst, largestJump( value, a, b, 1e-3 * c.extent ) );
				// And a path just outside the flat side (0.01 extents beyond the thinnest axis of the
				// bounding box), parallel to it, across the rim and the cells swept by the rim's faces.
				const sizes = [ 0, 1, 2 ].map( ( k ) => c.max[ k ] - c.min[ k ] ), thin = sizes.indexOf( Math.min( ...sizes ) );
				const from = a.slice(), to = b.slice();
				from[ thin ] = to[ thin ] = c.max[ thin ] + 0.01 * c.extent;
				worst = Math.max( worst, largestJump( value, from, to, 1e-3 * c.extent ) );

			}

			report.push( `${c.name}: ${worst}` );

		}

		expect( report ).toEqual( flat.slice( 0, 7 ).map( ( c ) => `${c.name}: 0` ) );

	} );

	it( 'the jump detector sees the nearest-face fallback: forcing it on a band of outside points makes a jump on a path through the band', () => {

		const c = flat[ 0 ], { mesh } = c, cells = mesh.outerCells as unknown as { locate: ( ...args: unknown[] ) => number };
		const locate = cells.locate, x0 = c.max[ 0 ] + 0.2 * c.extent;
		// A fake gap: beyond x0 no cell claims the point (what a gap between sweeps did before).
		cells.locate = function ( this: unknown, ...args: unknown[] ) { return ( args[ 0 ] as number ) > x0 ? - 1 : locate.apply( this, args ); };
		try {

			let hint = - 1;
			const value = ( x: number, y: number, z: number ) => { const s = sample( mesh, x, y, z, hint ); hint = s.hint; return s.value; };
			// Off the rim's normals, where outer cells and the nearest face differ by ~0.18.
			const y = c.min[ 1 ] + 0.1, z = c.max[ 2 ] + 0.25;
			expect( largestJump( value, [ c.min[ 0 ], y, z ], [ c.max[ 0 ] + c.extent, y, z ], 1e-3 * c.extent ) ).toBeGreaterThan( 0.05 );
			// Unforced, the same path is continuous.
			cells.locate = locate;
			expect( largestJump( value, [ c.min[ 0 ], y, z ], [ c.max[ 0 ] + c.extent, y, z ], 1e-3 * c.extent ) ).toBe( 0 );

		} finally {

			cells.locate = locate;

		}

	} );

} );

const nearestFaceMeshes = new Map<TetrahedralMesh, TetrahedralMesh>();

/** The same probes with `outside: 'nearestFace'` (cached). */
function nearestFaceMesh( mesh: TetrahedralMesh ): TetrahedralMesh {

	let near = nearestFaceMeshes.get( mesh );
	if ( ! near ) nearestFaceMeshes.set( mesh, near = TetrahedralMesh.fromTetrahedralization( mesh.positions, mesh.tetrahedra, mesh.neighbors, { outside: 'nearestFace' } ) );
	return near;

}

describe( 'outer cells at any scale: finite weights, the same as at unit scale', () => {

	/** Hull triangles counter-clockwise from outside, as TetrahedralMesh derives them. */
	function hullFaces( tetrahedra: Uint32Array, neighbors: Int32Array ): Uint32Array {

		const faces: number[] = [];
		for ( let t = 0; t < tetrahedra.length / 4; t ++ ) {

			const [ v0, v1, v2, v3 ] = tetrahedra.subarray( 4 * t, 4 * t + 4 );
			if ( neighbors[ 4 * t ] === - 1 ) faces.push( v1, v2, v3 );
			if ( neighbors[ 4 * t + 1 ] === - 1 ) faces.push( v0, v3, v2 );
			if ( neighbors[ 4 * t + 2 ] === - 1 ) faces.push( v0, v1, v3 );
			if ( neighbors[ 4 * t + 3 ] === - 1 ) faces.push( v0, v2, v1 );

		}

		return Uint32Array.from( faces );

	}

	/** 300 query points 1.2 to 30 extents from the centre of the points' box, in every direction. */
	function outsideQueries( points: Float64Array ): number[][] {

		const { min, max, extent } = makeCase( '', points ), center = [ 0, 1, 2 ].map( ( a ) => ( min[ a ] + max[ a ] ) / 2 );
		const random = seededRandom( 31 ), out: number[][] = [];
		while ( out.length < 300 ) {

			const d = [ random() - 0.5, random() - 0.5, random() - 0.5 ], l = Math.hypot( ...d ), r = extent * ( 0.6 + 30 * random() ** 2 );
			if ( l > 0.1 ) out.push( d.map( ( c, a ) => center[ a ] + c / l * r ) );

		}

		return out;

	}

	const sets: [ string, Float64Array ][] = [
		[ 'random cloud (40)', randomPoints( 40, 11 ) ],
		[ '4x4x4 grid', gridPoints( 4, 4, 4, 1 ) ],
		[ 'flat random box', flatRandomPoints( 60, 7 ) ],
	];

	for ( const [ name, unit ] of sets ) {

		const { tetrahedra, neighbors } = tetrahedralize( unit );
		const faces = hullFaces( tetrahedra, neighbors );
		const reference = new OuterCells( unit, faces );
		const queries = outsideQueries( unit );
		const expected = queries.map( ( q ) => {

			const out = new Float64Array( 4 );
			return { cell: reference.locate( q[ 0 ], q[ 1 ], q[ 2 ], - 1, out ), out };

		} );

		it( `${name} × 2^k, k = −1000 … 1000: the same cells and weights, bit for bit`, () => {

			expect( expected.filter( ( e ) => e.cell >= 0 ).length ).toBeGreaterThan( 250 );

			for ( const k of [ - 1000, - 400, - 101, 101, 150, 500, 1000 ] ) {

				const points = unit.map( ( v ) => v * 2 ** k );
				const scaled = tetrahedralize( points );
				expect( Array.from( scaled.tetrahedra ) ).toEqual( Array.from( tetrahedra ) );
				const cells = new OuterCells( points, faces );
				const out = new Float64Array( 4 );
				queries.forEach( ( q, i ) => {

					const cell = cells.locate( q[ 0 ] * 2 ** k, q[ 1 ] * 2 ** k, q[ 2 ] * 2 ** k, - 1, out );
					expect( cell, `2^${k}, query ${i}` ).toBe( expected[ i ].cell );
					expect( Array.from( out.subarray( 1 ) ), `2^${k}, query ${i}` ).toEqual( Array.from( expected[ i ].out.subarray( 1 ) ) );
					expect( out[ 0 ] ).toBe( cell < 0 ? - 1 : expected[ i ].out[ 0 ] * 2 ** k );

				} );

			}

		} );

		it( `${name} × 1e-300 … 1e300: finite weights summing to 1, close to the unit-scale ones`, () => {

			for ( const s of [ 1e-300, 1e-150, 1e-100, 1e100, 1e150, 1e300 ] ) {

				const points = unit.map( ( v ) => v * s );
				const scaled = tetrahedralize( points );
				const cells = new OuterCells( points, hullFaces( scaled.tetrahedra, scaled.neighbors ) );
				const out = new Float64Array( 4 );
				queries.forEach( ( q, i ) => {

					const cell = cells.locate( q[ 0 ] * s, q[ 1 ] * s, q[ 2 ] * s, - 1, out );
					expect( cell, `${s}, query ${i}` ).toBeGreaterThanOrEqual( 0 );
					expect( out.every( Number.isFinite ), `${s}, query ${i}` ).toBe( true );
					expect( Math.abs( out[ 1 ] + out[ 2 ] + out[ 3 ] - 1 ) ).toBeLessThan( 1e-12 );
					expect( Math.abs( cells.signedDistance( cell, q[ 0 ] * s, q[ 1 ] * s, q[ 2 ] * s ) / s ) ).toBeLessThan( 1e3 );
					if ( cell === expected[ i ].cell ) {

						for ( let k = 1; k < 4; k ++ ) expect( Math.abs( out[ k ] - expected[ i ].out[ k ] ) ).toBeLessThan( 1e-9 );

					}

				} );

			}

		} );

	}

} );
