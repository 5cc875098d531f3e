import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { TetrahedralMesh } from '../../src/interpolation/TetrahedralMesh.js';
import { IncrementalTetrahedralMesh } from '../../src/interpolation/IncrementalTetrahedralMesh.js';
import { DynamicTetrahedralization } from '../../src/tetrahedra/DynamicTetrahedralization.js';
import { gridPoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * IncrementalTetrahedralMesh (moveProbe / addProbe / removeProbe). Truth: a
 * TetrahedralMesh built from scratch on the active probes (ids mapped back), compared by
 * interpolate() at 1,000 random points inside and outside the hull (outer cells), linear fields
 * reproduced exactly inside, and each inverse matrix checked against its tetrahedron's vertices
 * (M⁻¹ (pᵢ − p₃) = eᵢ) rather than against another inverse.
 */

/** The probe → weight map of one interpolate() answer (weights below 1e-12 dropped). */
function weightMap( indices: ArrayLike<number>, weights: ArrayLike<number>, ids: ArrayLike<number> | null ): Map<number, number> {

	const map = new Map<number, number>();
	for ( let k = 0; k < 4; k ++ ) {

		if ( weights[ k ] <= 1e-12 ) continue;
		const id = ids ? ids[ indices[ k ] ] : indices[ k ];
		map.set( id, ( map.get( id ) ?? 0 ) + weights[ k ] );

	}

	return map;

}

interface Comparison { worst: number, outside: number, inside: number, linear: number }

/**
 * Compares `mesh` with a mesh built from scratch on its active probes at `count` random points of
 * the bounding box grown by `margin` on each side; hints are carried from point to point (and
 * from before the last edit, via `hints`).
 */
function compareWithScratch( mesh: TetrahedralMesh, seed: number, count = 1000, margin = 0.5, hints?: Int32Array ): Comparison {

	const ids: number[] = [];
	for ( let i = 0; i < mesh.probeCount; i ++ ) if ( mesh.isActive( i ) ) ids.push( i );
	const p = mesh.positions;
	const compact = new Float64Array( 3 * ids.length );
	ids.forEach( ( id, k ) => compact.set( p.subarray( 3 * id, 3 * id + 3 ), 3 * k ) );
	const scratch = new TetrahedralMesh( compact );
	expect( scratch.duplicates.length ).toBe( 0 );

	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < compact.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], compact[ i ] ); max[ i % 3 ] = Math.max( max[ i % 3 ], compact[ i ] );

	}

	const random = seededRandom( seed );
	const a = new Uint32Array( 4 ), wa = new Float64Array( 4 ), b = new Uint32Array( 4 ), wb = new Float64Array( 4 );
	let worst = 0, outside = 0, inside = 0, linear = 0, hint = - 1, scratchHint = - 1;
	for ( let n = 0; n < count; n ++ ) {

		const q = [ 0, 1, 2 ].map( ( axis ) => {

			const size = max[ axis ] - min[ axis ];
			return min[ axis ] - margin * size + random() * ( 1 + 2 * margin ) * size;

		} );
		const start = hints ? hints[ n ] : hint;
		hint = mesh.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], a, wa, start );
		if ( hints ) hints[ n ] = hint;
		scratchHint = scratch.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], b, wb, scratchHint );
		const mine = weightMap( a, wa, null ), theirs = weightMap( b, wb, ids );
		for ( const id of new Set( [ ...mine.keys(), ...theirs.keys() ] ) ) {

			worst = Math.max( worst, Math.abs( ( mine.get( id ) ?? 0 ) - ( theirs.get( id ) ?? 0 ) ) );

		}

		for ( let k = 0; k < 4; k ++ ) if ( wa[ k ] > 0 ) expect( mesh.isActive( a[ k ] ) ).toBe( true );
		if ( hint >= mesh.cellCount ) { outside ++; continue; }
		inside ++;
		// Inside, a linear field is reproduced exactly.
		for ( let axis = 0; axis < 3; axis ++ ) {

			let value = 0;
			for ( let k = 0; k < 4; k ++ ) value += wa[ k ] * p[ 3 * a[ k ] + axis ];
			linear = Math.max( linear, Math.abs( value - q[ axis ] ) );

		}

	}

	return { worst, outside, inside, linear };

}

/** Largest |M⁻¹ (pᵢ − p₃) − eᵢ| over every tetrahedron: the inverse matrices are current. */
function inverseError( mesh: TetrahedralMesh ): number {

	expect( mesh.inverseMatrices.length ).toBe( 9 * mesh.cellCount );
	const p = mesh.positions, m = mesh.inverseMatrices, t4 = mesh.tetrahedra;
	let worst = 0;
	for ( let t = 0; t < mesh.cellCount; t ++ ) {

		const r = 3 * t4[ 4 * t + 3 ];
		for ( let i = 0; i < 3; i ++ ) {

			const v = 3 * t4[ 4 * t + i ];
			const d = [ p[ v ] - p[ r ], p[ v + 1 ] - p[ r + 1 ], p[ v + 2 ] - p[ r + 2 ] ];
			for ( let row = 0; row < 3; row ++ ) {

				const value = m[ 9 * t + 3 * row ] * d[ 0 ] + m[ 9 * t + 3 * row + 1 ] * d[ 1 ] + m[ 9 * t + 3 * row + 2 ] * d[ 2 ];
				worst = Math.max( worst, Math.abs( value - ( row === i ? 1 : 0 ) ) );

			}

		}

	}

	return worst;

}

/** Hull faces and their owners/slots agree with the tetrahedra (the face is the owner's face opposite the slot). */
function checkHull( mesh: TetrahedralMesh ): void {

	const faces = mesh.hullFaces, owners = mesh.hullFaceTetrahedra, slots = mesh.hullFaceSlots;
	expect( owners.length ).toBe( faces.length / 3 );
	expect( slots.length ).toBe( owners.length );
	expect( mesh.outerCells.count ).toBe( owners.length );
	let hull = 0;
	for ( let i = 0; i < mesh.neighbors.length; i ++ ) if ( mesh.neighbors[ i ] === - 1 ) hull ++;
	expect( owners.length ).toBe( hull );
	for ( let f = 0; f < owners.length; f ++ ) {

		const t = owners[ f ], s = slots[ f ];
		expect( mesh.neighbors[ 4 * t + s ] ).toBe( - 1 );
		const face = [ faces[ 3 * f ], faces[ 3 * f + 1 ], faces[ 3 * f + 2 ] ].sort( ( x, y ) => x - y );
		const rest = [ 0, 1, 2, 3 ].filter( ( k ) => k !== s ).map( ( k ) => mesh.tetrahedra[ 4 * t + k ] ).sort( ( x, y ) => x - y );
		expect( face ).toEqual( rest );

	}

}

type Edit = 'move' | 'jump' | 'add' | 'remove';

/** Applies `steps` random edits (keeping at least `minimum` probes), checking against scratch every `every` edits. */
function runSequence(
	positions: Float64Array, seed: number, steps: number, every: number, minimum: number
): { edits: Record<Edit, number>, worst: Comparison } {

	const dynamic = new DynamicTetrahedralization( positions );
	const mesh = new IncrementalTetrahedralMesh( dynamic );
	const random = seededRandom( seed );
	const edits: Record<Edit, number> = { move: 0, jump: 0, add: 0, remove: 0 };
	const worst: Comparison = { worst: 0, outside: 0, inside: 0, linear: 0 };
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < positions.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], positions[ i ] ); max[ i % 3 ] = Math.max( max[ i % 3 ], positions[ i ] );

	}

	// Points a little beyond the original box, so edits also grow and shrink the hull.
	const somewhere = () => [ 0, 1, 2 ].map( ( a ) => min[ a ] + ( random() * 1.2 - 0.1 ) * ( max[ a ] - min[ a ] ) );
	const hints = new Int32Array( 1000 ).fill( - 1 );
	for ( let step = 1; step <= steps; step ++ ) {

		const active: number[] = [];
		for ( let i = 0; i < mesh.probeCount; i ++ ) if ( mesh.isActive( i ) ) active.push( i );
		const pick = active[ Math.floor( random() * active.length ) ];
		const roll = random();
		const kind: Edit = roll < 0.3 ? 'move' : roll < 0.55 ? 'jump' : roll < 0.8 || active.length <= minimum ? 'add' : 'remove';
		if ( kind === 'move' ) {

			const p = mesh.positions, size = 0.05 * ( max[ 0 ] - min[ 0 ] );
			mesh.moveProbe(
				pick,
				p[ 3 * pick ] + ( random() - 0.5 ) * size,
				p[ 3 * pick + 1 ] + ( random() - 0.5 ) * size,
				p[ 3 * pick + 2 ] + ( random() - 0.5 ) * size
			);

		} else if ( kind === 'jump' ) {

			const [ x, y, z ] = somewhere();
			mesh.moveProbe( pick, x, y, z );

		} else if ( kind === 'add' ) {

			const before = mesh.probeCount;
			const [ x, y, z ] = somewhere();
			expect( mesh.addProbe( x, y, z ) ).toBe( before );
			expect( mesh.probeCount ).toBe( before + 1 );

		} else {

			const before = mesh.probeCount;
			mesh.removeProbe( pick );
			expect( mesh.probeCount ).toBe( before );
			expect( mesh.isActive( pick ) ).toBe( false );
			expect( Array.from( mesh.tetrahedra ) ).not.toContain( pick );

		}

		edits[ kind ] ++;
		if ( step % every !== 0 && step !== steps ) continue;
		expect( inverseError( mesh ) ).toBeLessThan( 1e-9 );
		checkHull( mesh );
		// Hints from before the edits: stale cell ids must still give the right answer.
		const result = compareWithScratch( mesh, seed * 1000 + step, 1000, 0.25, hints );
		worst.worst = Math.max( worst.worst, result.worst );
		worst.linear = Math.max( worst.linear, result.linear );
		worst.outside += result.outside;
		worst.inside += result.inside;

	}

	return { edits, worst };

}

describe( 'incremental TetrahedralMesh', () => {

	it( 'after random moves, adds and removes (60 random probes), interpolate() equals a mesh built from scratch at 1,000 points, inside and outside', () => {

		const { edits, worst } = runSequence( randomPoints( 60, 11, 10 ), 5, 120, 10, 20 );
		expect( Math.min( edits.move, edits.jump, edits.add, edits.remove ) ).toBeGreaterThan( 10 );
		expect( worst.inside ).toBeGreaterThan( 1000 );
		expect( worst.outside ).toBeGreaterThan( 1000 );
		expect( worst.worst ).toBeLessThan( 1e-9 );
		expect( worst.linear ).toBeLessThan( 1e-9 );

	} );

	it( 'on a grid (co-spherical, flat hull faces) and on the Sponza layout', () => {

		const grid = runSequence( gridPoints( 4, 4, 4, 1 ), 7, 60, 6, 20 );
		expect( grid.worst.worst ).toBeLessThan( 1e-9 );
		expect( grid.worst.linear ).toBeLessThan( 1e-9 );
		const sponza = Float64Array.from( ( JSON.parse( readFileSync( new URL( '../../scenes/sponza.json', import.meta.url ), 'utf8' ) ) as { positions: number[] } ).positions );
		const result = runSequence( sponza, 9, 60, 6, 40 );
		expect( result.worst.worst ).toBeLessThan( 1e-9 );
		expect( result.worst.linear ).toBeLessThan( 1e-9 );

	} );

	it( 'a flat random layout (outer-cell normals smoothed by untangle) still equals from scratch after edits', () => {

		const p = randomPoints( 50, 3, 10 );
		for ( let i = 2; i < p.length; i += 3 ) p[ i ] *= 0.05;
		const dynamic = new DynamicTetrahedralization( p );
		const mesh = new IncrementalTetrahedralMesh( dynamic );
		const random = seededRandom( 4 );
		for ( let n = 0; n < 20; n ++ ) {

			const i = Math.floor( random() * 50 );
			mesh.moveProbe( i, random() * 10, random() * 10, random() * 0.5 );

		}

		const result = compareWithScratch( mesh, 77 );
		expect( result.outside ).toBeGreaterThan( 100 );
		expect( result.worst ).toBeLessThan( 1e-9 );

	} );

	it( 'a move changes only the inverse matrices of changed cells; the others stay bit for bit', () => {

		const dynamic = new DynamicTetrahedralization( randomPoints( 200, 21, 10 ) );
		const mesh = new IncrementalTetrahedralMesh( dynamic );
		// Deep inside: the hull does not change, so the outer cells are kept.
		let index = - 1;
		for ( let i = 0; i < 200 && index < 0; i ++ ) {

			const p = mesh.positions;
			if ( [ 0, 1, 2 ].every( ( a ) => p[ 3 * i + a ] > 3 && p[ 3 * i + a ] < 7 ) ) index = i;

		}

		const before = mesh.inverseMatrices.slice(), tetrahedraBefore = mesh.tetrahedra.slice(), outer = mesh.outerCells;
		const p = mesh.positions;
		mesh.moveProbe( index, p[ 3 * index ] + 0.05, p[ 3 * index + 1 ], p[ 3 * index + 2 ] );
		const changed = new Set( dynamic.lastEdit.changedCells );
		expect( changed.size ).toBeGreaterThan( 0 );
		expect( changed.size ).toBeLessThan( mesh.cellCount / 4 );
		expect( dynamic.lastEdit.changedHullFaces.length ).toBe( 0 );
		expect( mesh.outerCells ).toBe( outer );
		for ( let t = 0; t < Math.min( mesh.cellCount, before.length / 9 ); t ++ ) {

			if ( changed.has( t ) ) continue;
			expect( Array.from( mesh.tetrahedra.subarray( 4 * t, 4 * t + 4 ) ) )
				.toEqual( Array.from( tetrahedraBefore.subarray( 4 * t, 4 * t + 4 ) ) );
			expect( Array.from( mesh.inverseMatrices.subarray( 9 * t, 9 * t + 9 ) ) )
				.toEqual( Array.from( before.subarray( 9 * t, 9 * t + 9 ) ) );

		}

		expect( inverseError( mesh ) ).toBeLessThan( 1e-9 );
		expect( compareWithScratch( mesh, 5 ).worst ).toBeLessThan( 1e-9 );

	} );

	it( 'many adds grow the stores (capacity doubling) and stay equal to from scratch', () => {

		const mesh = new IncrementalTetrahedralMesh( new DynamicTetrahedralization( randomPoints( 8, 1, 1 ) ) );
		const random = seededRandom( 2 );
		for ( let n = 0; n < 300; n ++ ) mesh.addProbe( random(), random(), random() );
		expect( mesh.probeCount ).toBe( 308 );
		expect( inverseError( mesh ) ).toBeLessThan( 1e-9 );
		checkHull( mesh );
		const result = compareWithScratch( mesh, 3 );
		expect( result.worst ).toBeLessThan( 1e-9 );
		expect( result.linear ).toBeLessThan( 1e-9 );

	} );

	it( 'edits exist only on incremental meshes, and bad edits leave the mesh unchanged', () => {

		const positions = randomPoints( 30, 8, 1 );
		const plain = new TetrahedralMesh( positions );
		for ( const name of [ 'moveProbe', 'addProbe', 'removeProbe' ] ) expect( name in plain, name ).toBe( false );
		expect( () => new IncrementalTetrahedralMesh( {} as DynamicTetrahedralization ) ).toThrow( /IncrementalTetrahedralMesh: dynamic must be a DynamicTetrahedralization/ );

		const mesh = new IncrementalTetrahedralMesh( new DynamicTetrahedralization( positions ) );
		mesh.removeProbe( 3 );
		const tetrahedra = mesh.tetrahedra.slice();
		expect( () => mesh.removeProbe( 3 ) ).toThrow( RangeError );
		expect( () => mesh.moveProbe( 3, 0.5, 0.5, 0.5 ) ).toThrow( RangeError );
		expect( () => mesh.moveProbe( 0, NaN, 0, 0 ) ).toThrow( RangeError );
		expect( () => mesh.moveProbe( 0, positions[ 3 ], positions[ 4 ], positions[ 5 ] ) ).toThrow( /coincide|duplicate|within/i );
		expect( Array.from( mesh.tetrahedra ) ).toEqual( Array.from( tetrahedra ) );
		expect( compareWithScratch( mesh, 9 ).worst ).toBeLessThan( 1e-9 );

	} );

} );
