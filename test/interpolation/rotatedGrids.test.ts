import { describe, expect, it } from 'vitest';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { IncrementalTetrahedralMesh } from '../../src/interpolation/IncrementalTetrahedralMesh.js';
import { isIllConditioned } from '../../src/interpolation/inverseMatrices.js';
import { blendSH } from '../../src/interpolation/blendSH.js';
import { DynamicTetrahedralization } from '../../src/tetrahedra/DynamicTetrahedralization.js';
import { seededRandom } from '../helpers/pointSets.js';

/*
 * Rotated, scaled and offset probe grids (issue 12, "Wrong light"): rounding makes the 4 points of
 * a grid square slightly non-coplanar, so the Delaunay tetrahedralization holds slivers that are
 * positive in exact arithmetic and flat in floating point. Truth: the linear field itself — inside
 * the hull, Σ wᵢ f(pᵢ) must equal f(q), with f evaluated on coordinates relative to the first probe
 * (so the truth keeps its digits at world offsets) and the error measured against the field's
 * variation over the probes. Outside: finite weights, ≥ 0, summing to 1.
 */

/** 4×4×4 unit grid rotated by `degrees` about z; probe i = 16x + 4y + z (x slowest). */
function rotatedUnitGrid( degrees: number ): Float64Array {

	const a = degrees * Math.PI / 180, c = Math.cos( a ), s = Math.sin( a );
	const p: number[] = [];
	for ( let x = 0; x < 4; x ++ ) for ( let y = 0; y < 4; y ++ ) for ( let z = 0; z < 4; z ++ ) p.push( c * x - s * y, s * x + c * y, z );
	return Float64Array.from( p );

}

/** SH of `count` probes with L00 (red) = probe index, the rest 0. */
function indexSH( count: number ): Float32Array {

	const sh = new Float32Array( 27 * count );
	for ( let i = 0; i < count; i ++ ) sh[ 27 * i ] = i;
	return sh;

}

function countIllConditioned( mesh: TetrahedralMesh ): number {

	let n = 0;
	for ( let t = 0; t < mesh.cellCount; t ++ ) if ( isIllConditioned( mesh.inverseMatrices, t ) ) n ++;
	return n;

}

interface Layout {
	positions: Float64Array;
	/** Maps grid coordinates (u, v, w) ∈ [0, n − 1]³ to world coordinates. */
	toWorld: ( u: number, v: number, w: number ) => [ number, number, number ];
	counts: [ number, number, number ];
	/** Grid units by which a point must stay inside the box to be inside the (jittered) hull. */
	margin: [ number, number, number ];
	extent: number;
	center: [ number, number, number ];
}

/**
 * A random grid: 2–5 probes per axis, spacing 1e-3…1e3 (per axis up to 2× apart), rotated about a
 * random axis (or about z, or not at all), offset up to ~1e6 (or at the world coordinate
 * (512345.5, 4012345.25, 87.5) with metre spacing), a third of them jittered.
 */
function randomLayout( random: () => number, index: number, size = 0 ): Layout {

	const count = () => size || 2 + Math.floor( random() * 4 );
	const counts: [ number, number, number ] = [ count(), count(), count() ];
	const world = index % 10 === 0;
	const base = world ? 1 : 10 ** ( random() * 6 - 3 );
	const spacing = [ 0, 1, 2 ].map( () => base * ( index % 2 === 0 ? 1 : 1 + random() ) );
	const offset = world ? [ 512345.5, 4012345.25, 87.5 ]
		: [ 0, 1, 2 ].map( () => ( random() - 0.5 ) * 2 * 10 ** ( random() * 6 ) );

	// Rotation (Rodrigues) about a random axis; every 5th layout about z, as a level built at an angle.
	const kind = index % 5;
	let axis = kind === 1 ? [ 0, 0, 1 ] : [ random() - 0.5, random() - 0.5, random() - 0.5 ];
	const norm = Math.hypot( axis[ 0 ], axis[ 1 ], axis[ 2 ] );
	axis = axis.map( ( value ) => value / norm );
	const angle = index % 50 === 7 ? 0 : random() * 2 * Math.PI;
	const c = Math.cos( angle ), s = Math.sin( angle ), [ ax, ay, az ] = axis;
	const R = [
		c + ax * ax * ( 1 - c ), ax * ay * ( 1 - c ) - az * s, ax * az * ( 1 - c ) + ay * s,
		ay * ax * ( 1 - c ) + az * s, c + ay * ay * ( 1 - c ), ay * az * ( 1 - c ) - ax * s,
		az * ax * ( 1 - c ) - ay * s, az * ay * ( 1 - c ) + ax * s, c + az * az * ( 1 - c ),
	];
	const toWorld = ( u: number, v: number, w: number ): [ number, number, number ] => {

		const x = u * spacing[ 0 ], y = v * spacing[ 1 ], z = w * spacing[ 2 ];
		return [
			offset[ 0 ] + R[ 0 ] * x + R[ 1 ] * y + R[ 2 ] * z,
			offset[ 1 ] + R[ 3 ] * x + R[ 4 ] * y + R[ 5 ] * z,
			offset[ 2 ] + R[ 6 ] * x + R[ 7 ] * y + R[ 8 ] * z,
		];

	};

	// Jitter up to 0.1 of the smallest spacing per coordinate; the box shrunk by the jitter's
	// length (√3 · 0.1) is inside the jittered hull.
	const jitter = index % 3 === 2 ? 0.1 * Math.min( ...spacing ) : 0;
	const positions: number[] = [];
	for ( let w = 0; w < counts[ 2 ]; w ++ ) for ( let v = 0; v < counts[ 1 ]; v ++ ) for ( let u = 0; u < counts[ 0 ]; u ++ ) {

		const p = toWorld( u, v, w );
		for ( let k = 0; k < 3; k ++ ) positions.push( p[ k ] + ( random() - 0.5 ) * 2 * jitter );

	}

	const margin = spacing.map( ( h ) => ( 1.8 * jitter ) / h + 1e-4 ) as [ number, number, number ];
	const extent = Math.hypot( ...counts.map( ( n, k ) => ( n - 1 ) * spacing[ k ] ) );
	const center = toWorld( ( counts[ 0 ] - 1 ) / 2, ( counts[ 1 ] - 1 ) / 2, ( counts[ 2 ] - 1 ) / 2 );
	return { positions: Float64Array.from( positions ), toWorld, counts, margin, extent, center };

}

/** A linear field relative to the first probe o: f(p) = 0.7 + g · (p − o), g of length 1 / extent (differences keep their digits). */
function linearField( random: () => number, layout: Layout ): { f: ( x: number, y: number, z: number ) => number, range: number } {

	const o = layout.positions, g = [ random() - 0.5, random() - 0.5, random() - 0.5 ];
	const n = Math.hypot( g[ 0 ], g[ 1 ], g[ 2 ] ) * layout.extent;
	const f = ( x: number, y: number, z: number ): number =>
		0.7 + ( g[ 0 ] * ( x - o[ 0 ] ) + g[ 1 ] * ( y - o[ 1 ] ) + g[ 2 ] * ( z - o[ 2 ] ) ) / n;
	let min = Infinity, max = - Infinity;
	for ( let i = 0; i < o.length; i += 3 ) {

		const value = f( o[ i ], o[ i + 1 ], o[ i + 2 ] );
		min = Math.min( min, value ); max = Math.max( max, value );

	}

	return { f, range: max - min };

}

/** |det[p0 − p3, p1 − p3, p2 − p3]| / ℓ³ (ℓ the largest edge-vector coordinate) in floating point: ~0 for slivers. */
function flatness( mesh: TetrahedralMesh, t: number ): number {

	const p = mesh.positions, v = Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ), ( i ) => 3 * i );
	const e = [ 0, 1, 2 ].map( ( i ) => [ 0, 1, 2 ].map( ( c ) => p[ v[ i ] + c ] - p[ v[ 3 ] + c ] ) );
	const [ a, b, c ] = e;
	const det = a[ 0 ] * ( b[ 1 ] * c[ 2 ] - b[ 2 ] * c[ 1 ] ) - a[ 1 ] * ( b[ 0 ] * c[ 2 ] - b[ 2 ] * c[ 0 ] )
		+ a[ 2 ] * ( b[ 0 ] * c[ 1 ] - b[ 1 ] * c[ 0 ] );
	const l = Math.max( ...e.flat().map( Math.abs ) );
	return Math.abs( det ) / l / l / l;

}

interface Tally { inside: number, outside: number, slivers: number, worst: number, failures: string[] }

/**
 * Inside and outside queries of one layout on one mesh, and one query in each of up to
 * `sliverCount` of its flattest tetrahedra (a random convex combination of its vertices, rounded:
 * in the sliver or beside it); failures are collected with what went wrong.
 */
function checkLayout(
	mesh: TetrahedralMesh, layout: Layout, random: () => number, insideCount: number, outsideCount: number, tally: Tally, sliverCount = 0,
): void {

	const { f, range } = linearField( random, layout );
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 ), p = mesh.positions;
	let hint = - 1;
	const fail = ( what: string ) => {

		if ( tally.failures.length < 10 ) tally.failures.push( `${what} (${mesh.probeCount} probes, extent ${layout.extent.toPrecision( 3 )}, first ${Array.from( p.subarray( 0, 3 ) )})` );

	};

	const slivers: number[] = [];
	for ( let t = 0; t < mesh.cellCount && slivers.length < sliverCount; t ++ ) if ( flatness( mesh, t ) < 1e-3 ) slivers.push( t );
	for ( let q = 0; q < insideCount + slivers.length; q ++ ) {

		let x: number, y: number, z: number;
		if ( q < insideCount ) {

			const [ nu, nv, nw ] = layout.counts, [ mu, mv, mw ] = layout.margin;
			[ x, y, z ] = layout.toWorld(
				mu + random() * ( nu - 1 - 2 * mu ), mv + random() * ( nv - 1 - 2 * mv ), mw + random() * ( nw - 1 - 2 * mw ) );

		} else {

			const t = slivers[ q - insideCount ], b = [ random(), random(), random(), random() ], bs = b[ 0 ] + b[ 1 ] + b[ 2 ] + b[ 3 ];
			const v = Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ), ( i ) => 3 * i ), o = v[ 3 ];
			// Relative to vertex 3, so the point keeps its digits at world offsets.
			[ x, y, z ] = [ 0, 1, 2 ].map( ( c ) => p[ o + c ] + ( b[ 0 ] * ( p[ v[ 0 ] + c ] - p[ o + c ] )
				+ b[ 1 ] * ( p[ v[ 1 ] + c ] - p[ o + c ] ) + b[ 2 ] * ( p[ v[ 2 ] + c ] - p[ o + c ] ) ) / bs );
			tally.slivers ++;

		}

		hint = mesh.interpolate( x, y, z, indices, weights, q % 3 === 0 ? - 1 : hint );
		let value = 0, sum = 0, negative = false;
		for ( let k = 0; k < 4; k ++ ) {

			const i = 3 * indices[ k ];
			value += weights[ k ] * f( p[ i ], p[ i + 1 ], p[ i + 2 ] );
			sum += weights[ k ];
			if ( ! ( weights[ k ] >= 0 ) ) negative = true;

		}

		const error = Math.abs( value - f( x, y, z ) ) / range, outer = hint >= mesh.cellCount;
		if ( q < insideCount ) tally.inside ++;
		if ( negative || Math.abs( sum - 1 ) > 1e-12 ) fail( `weights ${Array.from( weights )} at (${x}, ${y}, ${z})` );
		// A point in a sliver on the hull may round outside it (by an ulp of the coordinates): the
		// outer cell then answers, exact on the hull, not linear off it.
		else if ( outer && q < insideCount ) fail( `inside point (${x}, ${y}, ${z}) answered by an outer cell` );
		else if ( ! outer ) {

			tally.worst = Math.max( tally.worst, error );
			if ( ! ( error <= 1e-9 ) ) fail( `linear field off by ${error} (relative) at (${x}, ${y}, ${z})` );

		}

	}

	for ( let q = 0; q < outsideCount; q ++ ) {

		// Beyond the bounding sphere (radius extent / 2, plus jitter), up to 10 extents out.
		const d = [ random() - 0.5, random() - 0.5, random() - 0.5 ], n = Math.hypot( d[ 0 ], d[ 1 ], d[ 2 ] );
		const r = layout.extent * ( 0.6 + random() * 9.4 ) / n;
		const x = layout.center[ 0 ] + d[ 0 ] * r, y = layout.center[ 1 ] + d[ 1 ] * r, z = layout.center[ 2 ] + d[ 2 ] * r;
		hint = mesh.interpolate( x, y, z, indices, weights, hint );
		let sum = 0, bad = false;
		for ( let k = 0; k < 4; k ++ ) {

			sum += weights[ k ];
			if ( ! ( weights[ k ] >= 0 && weights[ k ] <= 1 + 1e-12 ) ) bad = true;

		}

		tally.outside ++;
		if ( bad || ! ( Math.abs( sum - 1 ) <= 1e-12 ) ) fail( `outside weights ${Array.from( weights )} at (${x}, ${y}, ${z})` );

	}

}

describe( 'rotated and offset grids (exact weights in slivers flat in floating point)', () => {

	it( 'the issue\'s reproducers: 4×4×4 grid rotated 51° gives 31.5 at the centre; rotated 18.5°, (−12, −12, −9) is finite', () => {

		const sh = indexSH( 64 ), out = new Float32Array( 27 );
		const indices = new Uint32Array( 4 ), weights = new Float32Array( 4 );

		const mesh51 = new TetrahedralMesh( rotatedUnitGrid( 51 ) );
		expect( countIllConditioned( mesh51 ) ).toBeGreaterThan( 0 ); // the fallback is exercised
		const a = 51 * Math.PI / 180, cx = Math.cos( a ) * 1.5 - Math.sin( a ) * 1.5, cy = Math.sin( a ) * 1.5 + Math.cos( a ) * 1.5;
		expect( mesh51.locate( cx, cy, 1.5 ) ).toBeGreaterThanOrEqual( 0 );
		mesh51.interpolate( cx, cy, 1.5, indices, weights, - 1 );
		expect( blendSH( indices, weights, sh, out )[ 0 ] ).toBeCloseTo( 31.5, 4 );

		const mesh18 = new TetrahedralMesh( rotatedUnitGrid( 18.5 ) );
		expect( countIllConditioned( mesh18 ) ).toBeGreaterThan( 0 );
		expect( mesh18.interpolate( - 12, - 12, - 9, indices, weights, - 1 ) ).toBeGreaterThanOrEqual( mesh18.cellCount );
		const value = blendSH( indices, weights, sh, out )[ 0 ];
		expect( Number.isFinite( value ) && value >= 0 && value <= 63 ).toBe( true );

	} );

	it( 'the walk never reads a NaN as a step: every rotation of the 4×4×4 grid about z in 0.5° steps locates the centre (720 grids)', () => {

		const sh = indexSH( 64 ), out = new Float32Array( 27 );
		const indices = new Uint32Array( 4 ), weights = new Float32Array( 4 );
		for ( let step = 0; step < 720; step ++ ) {

			const a = step * 0.5 * Math.PI / 180, mesh = new TetrahedralMesh( rotatedUnitGrid( step * 0.5 ) );
			const cx = Math.cos( a ) * 1.5 - Math.sin( a ) * 1.5, cy = Math.sin( a ) * 1.5 + Math.cos( a ) * 1.5;
			for ( const hint of [ - 1, 0, mesh.cellCount - 1 ] ) {

				const t = mesh.interpolate( cx, cy, 1.5, indices, weights, hint );
				expect( t < mesh.cellCount, `rotated ${step * 0.5}°, hint ${hint}` ).toBe( true );
				expect( blendSH( indices, weights, sh, out )[ 0 ] ).toBeCloseTo( 31.5, 4 );

			}

		}

	} );

	it( '12,000 queries on 800 random grids (2–5 per axis, spacing 1e-3…1e3, any rotation, offsets to 1e6, a third jittered): linear fields exact inside (1e-9), also in up to 3 slivers per grid; finite outside', () => {

		const random = seededRandom( 1212 );
		const tally: Tally = { inside: 0, outside: 0, slivers: 0, worst: 0, failures: [] };
		let flagged = 0;
		for ( let l = 0; l < 800; l ++ ) {

			const layout = randomLayout( random, l );
			const mesh = new TetrahedralMesh( layout.positions );
			flagged += countIllConditioned( mesh );
			checkLayout( mesh, layout, random, 10, 5, tally, 3 );

		}

		expect( tally.failures ).toEqual( [] );
		expect( tally.inside + tally.outside ).toBe( 12000 );
		expect( tally.slivers ).toBeGreaterThan( 500 );
		expect( tally.worst ).toBeLessThanOrEqual( 1e-9 );
		expect( flagged ).toBeGreaterThan( 100 ); // slivers flat in floating point were met

	} );

	it( 'world coordinates (512345.5, 4012345.25, 87.5), metre spacing: 2,000 queries on 100 rotated 5×5×5 grids (and 3 in slivers per grid), the outer-cell and nearest-face modes', () => {

		const random = seededRandom( 5123 );
		const tally: Tally = { inside: 0, outside: 0, slivers: 0, worst: 0, failures: [] };
		for ( let l = 0; l < 100; l ++ ) {

			const layout = randomLayout( random, 0, 5 );
			checkLayout( new TetrahedralMesh( layout.positions, { outside: l % 2 === 0 ? 'outerCells' : 'nearestFace' } ), layout, random, 15, 5, tally, 3 );

		}

		expect( tally.failures ).toEqual( [] );
		expect( tally.inside + tally.outside ).toBe( 2000 );
		expect( tally.slivers ).toBeGreaterThan( 100 );

	} );

	it( 'incremental meshes: 2,400 queries (and 3 in slivers per grid) on 120 rotated grids after 3 probe moves each (inverse matrices of changed cells flagged too)', () => {

		const random = seededRandom( 77 );
		const tally: Tally = { inside: 0, outside: 0, slivers: 0, worst: 0, failures: [] };
		let flagged = 0;
		for ( let l = 0; l < 120; l ++ ) {

			const layout = randomLayout( random, 5 * l + 1 ); // rotations about z, not jittered
			const mesh = new IncrementalTetrahedralMesh( new DynamicTetrahedralization( layout.positions ) );
			// Move 3 probes by a small fraction of a cell and back: the edits recompute the
			// inverses of the cells around them, and the grid (the truth's layout) is unchanged.
			for ( let m = 0; m < 3; m ++ ) {

				const i = Math.floor( random() * mesh.probeCount ), p = layout.positions;
				const [ x, y, z ] = [ p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ] ];
				const h = 0.01 * layout.extent;
				mesh.moveProbe( i, x + h, y - h, z + h );
				mesh.moveProbe( i, x, y, z );

			}

			flagged += countIllConditioned( mesh );
			checkLayout( mesh, layout, random, 15, 5, tally, 3 );

		}

		expect( tally.failures ).toEqual( [] );
		expect( tally.inside + tally.outside ).toBe( 2400 );
		expect( tally.slivers ).toBeGreaterThan( 100 );
		expect( flagged ).toBeGreaterThan( 0 );

	} );

} );
