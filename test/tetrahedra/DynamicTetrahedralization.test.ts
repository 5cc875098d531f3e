import { describe, expect, it } from 'vitest';
import { DynamicTetrahedralization, type TetrahedralEdit } from '../../src/tetrahedra/DynamicTetrahedralization.js';
import { tetrahedralize, DegenerateInputError } from '../../src/tetrahedra/tetrahedralize.js';
import { checkDelaunay } from '../helpers/delaunayChecks.js';
import { gridPoints, integerSpherePoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * Independent truth after every edit: the brute-force Delaunay checker (orientation, symmetric
 * neighbours, hull, tiling volume, empty circumspheres) on the active points, and set equality with
 * tetrahedralize() from scratch of the same points — the perturbation ranks points by coordinates,
 * so the perturbed Delaunay tetrahedralization is unique and both must give the same tetrahedra.
 * A mirror updated only through lastEdit checks that a consumer doing O(changed) work stays exact.
 */

/** Sorted tetrahedra as sorted vertex-id lists, after mapping ids through `map`. */
function canonical( tetrahedra: Uint32Array, map?: ArrayLike<number> ): string {

	const cells: string[] = [];
	for ( let t = 0; t < tetrahedra.length; t += 4 ) {

		cells.push( Array.from( tetrahedra.subarray( t, t + 4 ), ( v ) => map ? map[ v ] : v ).sort( ( a, b ) => a - b ).join( ',' ) );

	}

	return cells.sort().join( ';' );

}

/** Hull triangles (rotated to start at their smallest id, orientation kept) with their owner's vertices. */
function canonicalHull( faces: Uint32Array, owners: Uint32Array, tetrahedra: Uint32Array ): string {

	const out: string[] = [];
	for ( let h = 0; h < owners.length; h ++ ) {

		const f = Array.from( faces.subarray( 3 * h, 3 * h + 3 ) );
		const m = f.indexOf( Math.min( ...f ) );
		const rotated = [ f[ m ], f[ ( m + 1 ) % 3 ], f[ ( m + 2 ) % 3 ] ];
		out.push( rotated.join( ',' ) + '@' + Array.from( tetrahedra.subarray( 4 * owners[ h ], 4 * owners[ h ] + 4 ) ).sort( ( a, b ) => a - b ).join( ',' ) );

	}

	return out.sort().join( ';' );

}

/** The hull the way TetrahedralMesh derives it from tetrahedra and neighbours. */
function hullFromCells( tetrahedra: Uint32Array, neighbors: Int32Array ): { faces: Uint32Array; owners: Uint32Array } {

	const faces: number[] = [], owners: number[] = [];
	for ( let t = 0; t < tetrahedra.length / 4; t ++ ) {

		for ( let i = 0; i < 4; i ++ ) {

			if ( neighbors[ 4 * t + i ] !== - 1 ) continue;
			const v = tetrahedra.subarray( 4 * t, 4 * t + 4 );
			if ( i === 0 ) faces.push( v[ 1 ], v[ 2 ], v[ 3 ] );
			else if ( i === 1 ) faces.push( v[ 0 ], v[ 3 ], v[ 2 ] );
			else if ( i === 2 ) faces.push( v[ 0 ], v[ 1 ], v[ 3 ] );
			else faces.push( v[ 0 ], v[ 2 ], v[ 1 ] );
			owners.push( t );

		}

	}

	return { faces: Uint32Array.from( faces ), owners: Uint32Array.from( owners ) };

}

/** What a consumer keeps: copies of per-cell and per-hull-face data, updated only from lastEdit. */
class Mirror {

	tetrahedra: Uint32Array;
	hullFaces: Uint32Array;
	hullFaceCells: Uint32Array;

	constructor( mesh: DynamicTetrahedralization ) {

		this.tetrahedra = mesh.tetrahedra.slice();
		this.hullFaces = mesh.hullFaces.slice();
		this.hullFaceCells = mesh.hullFaceCells.slice();

	}

	apply( mesh: DynamicTetrahedralization, edit: TetrahedralEdit ): void {

		if ( edit.rebuilt ) {

			this.tetrahedra = mesh.tetrahedra.slice();
			this.hullFaces = mesh.hullFaces.slice();
			this.hullFaceCells = mesh.hullFaceCells.slice();
			return;

		}

		const tetrahedra = new Uint32Array( 4 * edit.cellCount );
		tetrahedra.set( this.tetrahedra.subarray( 0, Math.min( this.tetrahedra.length, tetrahedra.length ) ) );
		for ( const c of edit.changedCells ) tetrahedra.set( mesh.tetrahedra.subarray( 4 * c, 4 * c + 4 ), 4 * c );
		this.tetrahedra = tetrahedra;

		const faces = new Uint32Array( 3 * edit.hullFaceCount ), cells = new Uint32Array( edit.hullFaceCount );
		faces.set( this.hullFaces.subarray( 0, Math.min( this.hullFaces.length, faces.length ) ) );
		cells.set( this.hullFaceCells.subarray( 0, Math.min( this.hullFaceCells.length, cells.length ) ) );
		for ( const h of edit.changedHullFaces ) {

			faces.set( mesh.hullFaces.subarray( 3 * h, 3 * h + 3 ), 3 * h );
			cells[ h ] = mesh.hullFaceCells[ h ];

		}

		this.hullFaces = faces;
		this.hullFaceCells = cells;

	}

}

/** Index of the first entry where a and b differ (a length difference counts), or −1. */
function firstDifference( a: ArrayLike<number>, b: ArrayLike<number> ): number {

	for ( let i = 0; i < Math.max( a.length, b.length ); i ++ ) if ( a[ i ] !== b[ i ] ) return i;
	return - 1;

}

function activeIds( mesh: DynamicTetrahedralization ): number[] {

	const ids: number[] = [];
	for ( let i = 0; i < mesh.pointCount; i ++ ) if ( mesh.isActive( i ) ) ids.push( i );
	return ids;

}

/**
 * Every check of the file on the current state; `label` names the edit in failure messages. `far`:
 * points far beyond the initial extent, so the reference is built without tolerances (the mesh keeps
 * its initial ones) and the tiling is checked at unit scale (volumes in the input's units overflow).
 */
function verify( mesh: DynamicTetrahedralization, mirror: Mirror | null, label: string, bruteForce = true, far = false ): void {

	const ids = activeIds( mesh );
	expect( ids.length, label ).toBe( mesh.activeCount );
	const points = new Float64Array( 3 * ids.length );
	ids.forEach( ( id, j ) => points.set( mesh.positions.subarray( 3 * id, 3 * id + 3 ), 3 * j ) );

	const scratch = tetrahedralize( points, far ? { duplicateTolerance: 0, planarTolerance: 0 } : {} );
	expect( canonical( mesh.tetrahedra ), `${label}: same tetrahedra as from scratch` ).toBe( canonical( scratch.tetrahedra, ids ) );

	if ( bruteForce ) {

		const local = new Map( ids.map( ( id, j ) => [ id, j ] ) );
		const report = checkDelaunay( points, Uint32Array.from( mesh.tetrahedra, ( v ) => local.get( v ) ?? - 1 ), mesh.neighbors );
		expect( report.nonPositive, `${label}: flat or inverted` ).toBe( 0 );
		expect( report.asymmetricNeighbors, `${label}: neighbour links` ).toBe( 0 );
		expect( report.mismatchedFaces, `${label}: neighbour faces` ).toBe( 0 );
		expect( report.unusedPoints, `${label}: unused points` ).toBe( 0 );
		expect( report.hullViolations, `${label}: hull` ).toBe( 0 );
		expect( report.emptySphereViolations, `${label}: empty spheres` ).toBe( 0 );
		if ( far ) expect( report.tilingError, `${label}: tiling` ).toBeLessThanOrEqual( 1e-9 );
		else expect( Math.abs( report.volumeSum - report.hullVolume ), `${label}: tiling` ).toBeLessThanOrEqual( 1e-9 * report.hullVolume );

	}

	const hull = hullFromCells( mesh.tetrahedra, mesh.neighbors );
	const expectedHull = canonicalHull( hull.faces, hull.owners, mesh.tetrahedra );
	expect( canonicalHull( mesh.hullFaces, mesh.hullFaceCells, mesh.tetrahedra ), `${label}: hull faces` ).toBe( expectedHull );

	if ( mirror ) {

		mirror.apply( mesh, mesh.lastEdit );
		expect( firstDifference( mirror.tetrahedra, mesh.tetrahedra ), `${label}: lastEdit.changedCells covers every change` ).toBe( - 1 );
		expect( canonicalHull( mirror.hullFaces, mirror.hullFaceCells, mesh.tetrahedra ), `${label}: lastEdit.changedHullFaces` ).toBe( expectedHull );

	}

}

/**
 * `edits` random edits drawn by `next`, verified after each one. `next` returns the edit to make
 * (possibly rejected as degenerate, which must leave the mesh unchanged).
 */
function runSequence(
	mesh: DynamicTetrahedralization, edits: number, next: ( mesh: DynamicTetrahedralization ) => { label: string; apply(): void },
): { rejected: number } {

	const mirror = new Mirror( mesh );
	let rejected = 0;
	for ( let e = 0; e < edits; e ++ ) {

		const edit = next( mesh );
		const before = canonical( mesh.tetrahedra );
		try {

			edit.apply();

		} catch ( error ) {

			if ( ! ( error instanceof DegenerateInputError ) ) throw error;
			rejected ++;
			expect( canonical( mesh.tetrahedra ), `rejected ${edit.label} changed the mesh` ).toBe( before );
			continue;

		}

		verify( mesh, mirror, `edit ${e} (${edit.label})` );

	}

	return { rejected };

}

describe( 'DynamicTetrahedralization: long random edit sequences match tetrahedralize() from scratch', () => {

	for ( const seed of [ 1, 2 ] ) {

		it( `200 random points, 250 random inserts / removes / moves (seed ${seed}; small steps, jumps, points beyond the hull)`, () => {

			const mesh = new DynamicTetrahedralization( randomPoints( 200, seed ) );
			verify( mesh, null, 'constructed' );
			const random = seededRandom( 100 + seed );
			const counts = { insert: 0, remove: 0, move: 0 };
			runSequence( mesh, 250, ( m ) => {

				const ids = activeIds( m );
				const pick = ids[ Math.floor( random() * ids.length ) ];
				const r = random();
				// Coordinates in [−0.1, 1.1): some land outside the current hull, some hull points leave it.
				const x = random() * 1.2 - 0.1, y = random() * 1.2 - 0.1, z = random() * 1.2 - 0.1;
				if ( r < 0.3 ) return { label: 'insert', apply: () => { counts.insert ++; m.insert( x, y, z ); } };
				if ( r < 0.6 ) return { label: `remove ${pick}`, apply: () => { counts.remove ++; m.remove( pick ); } };
				if ( r < 0.8 ) {

					const p = m.positions;
					const step = 0.02;
					return { label: `small move ${pick}`, apply: () => { counts.move ++; m.move( pick, p[ 3 * pick ] + ( random() - 0.5 ) * step, p[ 3 * pick + 1 ] + ( random() - 0.5 ) * step, p[ 3 * pick + 2 ] + ( random() - 0.5 ) * step ); } };

				}

				return { label: `jump ${pick}`, apply: () => { counts.move ++; m.move( pick, x, y, z ); } };

			} );
			expect( counts.insert ).toBeGreaterThan( 50 );
			expect( counts.remove ).toBeGreaterThan( 50 );
			expect( counts.move ).toBeGreaterThan( 80 );

		} );

	}

	/** Edits that keep every point on a lattice: co-spherical cubes everywhere, all the time. */
	function latticeSequence( n: number, spacing: number, slack: number, edits: number, seed: number ): void {

		const mesh = new DynamicTetrahedralization( gridPoints( n, n, n, spacing ) );
		verify( mesh, null, 'constructed' );
		const random = seededRandom( seed );
		const size = n + slack; // free lattice sites around the grid, for inserts and moves
		const taken = new Map<string, number>();
		const key = ( i: number, j: number, k: number ) => `${i},${j},${k}`;
		for ( const id of activeIds( mesh ) ) {

			const p = mesh.positions;
			const cx = Math.round( p[ 3 * id ] / spacing ), cy = Math.round( p[ 3 * id + 1 ] / spacing );
			const cz = Math.round( p[ 3 * id + 2 ] / spacing );
			taken.set( key( cx, cy, cz ), id );

		}

		const freeSite = (): [ number, number, number ] => {

			for ( ;; ) {

				const s: [ number, number, number ] = [
					Math.floor( random() * size ), Math.floor( random() * size ), Math.floor( random() * size ),
				];
				if ( ! taken.has( key( ...s ) ) ) return s;

			}

		};

		const { rejected } = runSequence( mesh, edits, ( m ) => {

			const ids = activeIds( m );
			const pick = ids[ Math.floor( random() * ids.length ) ];
			const p = m.positions;
			const site = ( id: number ) => key(
				Math.round( p[ 3 * id ] / spacing ), Math.round( p[ 3 * id + 1 ] / spacing ), Math.round( p[ 3 * id + 2 ] / spacing ),
			);
			const r = random();
			if ( r < 0.35 ) return { label: `remove ${pick}`, apply: () => { const s = site( pick ); m.remove( pick ); taken.delete( s ); } };
			const [ i, j, k ] = freeSite();
			if ( r < 0.7 ) return { label: `insert at ${i},${j},${k}`, apply: () => { taken.set( key( i, j, k ), m.insert( i * spacing, j * spacing, k * spacing ) ); } };
			return { label: `move ${pick} to ${i},${j},${k}`, apply: () => { const s = site( pick ); m.move( pick, i * spacing, j * spacing, k * spacing ); taken.delete( s ); taken.set( key( i, j, k ), pick ); } };

		} );
		expect( rejected ).toBeLessThan( edits / 10 );

	}

	it( '4x4x4 grid, spacing 1 (exactly co-spherical), 220 lattice edits on a 5³ lattice', () => latticeSequence( 4, 1, 1, 220, 7 ) );

	it( '6x6x6 grid, spacing 0.1 (co-spherical up to rounding), 220 lattice edits on a 7³ lattice', () => latticeSequence( 6, 0.1, 1, 220, 8 ) );

	it( 'the 102 integer points on the sphere of radius 9 plus its centre: 200 removes, re-inserts and moves among sphere points', () => {

		const sphere = integerSpherePoints( 9 );
		const mesh = new DynamicTetrahedralization( Float64Array.from( [ ...sphere, 0, 0, 0 ] ) );
		verify( mesh, null, 'constructed' );
		const random = seededRandom( 21 );
		const sites = sphere.length / 3;
		const onSphere = new Map<number, number>(); // sphere site -> point id
		for ( let s = 0; s < sites; s ++ ) onSphere.set( s, s );
		runSequence( mesh, 200, ( m ) => {

			const used = [ ...onSphere.keys() ];
			const free = Array.from( { length: sites }, ( _, s ) => s ).filter( ( s ) => ! onSphere.has( s ) );
			const from = used[ Math.floor( random() * used.length ) ];
			const id = onSphere.get( from )!;
			const r = random();
			if ( ( r < 0.4 || free.length === 0 ) && used.length > 20 ) return { label: `remove ${id}`, apply: () => { m.remove( id ); onSphere.delete( from ); } };
			const to = free.length ? free[ Math.floor( random() * free.length ) ] : from;
			const [ x, y, z ] = sphere.subarray( 3 * to, 3 * to + 3 );
			if ( r < 0.7 ) return { label: `insert site ${to}`, apply: () => { onSphere.set( to, m.insert( x, y, z ) ); } };
			return { label: `move ${id} to site ${to}`, apply: () => { m.move( id, x, y, z ); onSphere.delete( from ); onSphere.set( to, id ); } };

		} );

	} );

	it( 'points on the faces of a cube (coplanar hull patches): removing and re-inserting hull points', () => {

		const out: number[] = [];
		for ( let i = 0; i <= 4; i ++ ) for ( let j = 0; j <= 4; j ++ ) for ( let k = 0; k <= 4; k ++ ) {

			if ( i === 0 || i === 4 || j === 0 || j === 4 || k === 0 || k === 4 ) out.push( i, j, k );

		}

		out.push( 2, 2, 2 );
		const points = Float64Array.from( out );
		const mesh = new DynamicTetrahedralization( points );
		const random = seededRandom( 31 );
		const removed: number[] = [];
		runSequence( mesh, 150, ( m ) => {

			const ids = activeIds( m );
			if ( removed.length > 0 && ( random() < 0.45 || ids.length < 30 ) ) {

				const id = removed.splice( Math.floor( random() * removed.length ), 1 )[ 0 ];
				const [ x, y, z ] = points.subarray( 3 * id, 3 * id + 3 );
				return { label: `re-insert ${x},${y},${z}`, apply: () => { m.insert( x, y, z ); } };

			}

			const pick = ids[ Math.floor( random() * ids.length ) ];
			return { label: `remove ${pick}`, apply: () => { m.remove( pick ); if ( pick < points.length / 3 ) removed.push( pick ); } };

		} );

	} );

	it( 'removing the apex above a flat top leaves the top as hull faces (a hull vertex with a flat link)', () => {

		const points = Array.from( gridPoints( 3, 3, 2, 1 ) );
		points.push( 1, 1, 2 ); // above the centre of the top face z = 1
		points.push( 0.5, 0.5, - 1 ); // and one below, so the rest stays a volume
		const mesh = new DynamicTetrahedralization( points );
		const mirror = new Mirror( mesh );
		mesh.remove( 18 );
		verify( mesh, mirror, 'apex removed' );
		mesh.insert( 1.2, 0.9, 1.5 );
		verify( mesh, mirror, 'apex re-inserted elsewhere' );
		mesh.remove( 19 );
		verify( mesh, mirror, 'bottom apex removed' );

	} );

} );

describe( 'DynamicTetrahedralization: ids, errors and degenerate edits', () => {

	it( 'keeps point ids stable: insert returns the next id, remove retires one id, move keeps it', () => {

		const points = randomPoints( 20, 3 );
		const mesh = new DynamicTetrahedralization( points );
		expect( mesh.pointCount ).toBe( 20 );
		expect( mesh.insert( 0.5, 0.5, 0.5 ) ).toBe( 20 );
		mesh.remove( 3 );
		expect( mesh.isActive( 3 ) ).toBe( false );
		expect( mesh.activeCount ).toBe( 20 );
		expect( mesh.insert( 0.25, 0.5, 0.5 ) ).toBe( 21 );
		mesh.move( 7, 0.1, 0.2, 0.3 );
		expect( Array.from( mesh.positions.subarray( 21, 24 ) ) ).toEqual( [ 0.1, 0.2, 0.3 ] );
		for ( const i of [ 0, 1, 2, 4, 19 ] ) {

			const given = Array.from( points.subarray( 3 * i, 3 * i + 3 ) );
			expect( Array.from( mesh.positions.subarray( 3 * i, 3 * i + 3 ) ) ).toEqual( given );

		}

		expect( Array.from( mesh.tetrahedra ) ).not.toContain( 3 );
		verify( mesh, null, 'after id edits' );

	} );

	it( 'merges duplicates at construction like tetrahedralize (merged ids inactive) and matches its output exactly', () => {

		const points = Array.from( gridPoints( 3, 3, 3, 1 ) );
		points.push( 1, 1, 1 );
		const mesh = new DynamicTetrahedralization( points );
		const scratch = tetrahedralize( points );
		expect( Array.from( mesh.duplicates ) ).toEqual( [ 27, 13 ] );
		expect( mesh.isActive( 27 ) ).toBe( false );
		expect( mesh.tetrahedra ).toEqual( scratch.tetrahedra );
		expect( mesh.neighbors ).toEqual( scratch.neighbors );
		expect( mesh.lastEdit.rebuilt ).toBe( true );

	} );

	it( 'rejects duplicate inserts and moves onto another point, leaving the mesh unchanged', () => {

		const mesh = new DynamicTetrahedralization( gridPoints( 3, 3, 3, 1 ) );
		const before = canonical( mesh.tetrahedra );
		expect( () => mesh.insert( 1, 1, 1 ) ).toThrow( /insert: .* coincides with point 13/ );
		expect( () => mesh.insert( 2, 2, 2 + 1e-12 ) ).toThrow( DegenerateInputError );
		expect( () => mesh.move( 0, 1, 1, 1 ) ).toThrow( /move: .* coincides with point 13/ );
		expect( () => mesh.move( 12, 1, 1, 1 + 1e-12 ) ).toThrow( /coincides with point 13/ ); // 12 is next to 13: a step shorter than nothing near
		expect( mesh.pointCount ).toBe( 27 );
		expect( canonical( mesh.tetrahedra ) ).toBe( before );
		mesh.insert( 1, 1, 1 + 1e-6 ); // beyond the tolerance: kept
		verify( mesh, null, 'near but distinct' );

	} );

	it( 'refuses to remove down to 3 points or to a coplanar set, and the mesh stays valid', () => {

		const four = new DynamicTetrahedralization( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] );
		expect( () => four.remove( 0 ) ).toThrow( /would leave 3 points; at least 4/ );
		expect( four.cellCount ).toBe( 1 );

		const floor = Array.from( gridPoints( 3, 1, 3, 1 ) ); // y = 0
		floor.push( 1, 1, 1 );
		const pyramid = new DynamicTetrahedralization( floor );
		const before = canonical( pyramid.tetrahedra );
		try {

			pyramid.remove( 9 );
			expect.unreachable();

		} catch ( error ) {

			expect( error ).toBeInstanceOf( DegenerateInputError );
			expect( ( error as DegenerateInputError ).reason ).toBe( 'coplanar' );
			expect( ( error as Error ).message ).toMatch( /DynamicTetrahedralization\.remove: .* one plane/ );

		}

		expect( canonical( pyramid.tetrahedra ) ).toBe( before );
		pyramid.remove( 4 ); // a floor point: fine
		verify( pyramid, null, 'floor point removed' );

	} );

	it( 'moves in tiny or flat sets by rebuilding, and refuses a move that flattens the set', () => {

		const four = new DynamicTetrahedralization( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 ] );
		four.move( 3, 0.2, 0.3, 2 );
		expect( four.lastEdit.rebuilt ).toBe( true );
		verify( four, null, 'four points moved' );
		expect( () => four.move( 3, 0.5, 0.5, 0 ) ).toThrow( /one plane/ );
		expect( Array.from( four.positions.subarray( 9, 12 ) ) ).toEqual( [ 0.2, 0.3, 2 ] );
		verify( four, null, 'after the refused move' );

		const floor = Array.from( gridPoints( 3, 1, 3, 1 ) );
		floor.push( 1, 1, 1 );
		const pyramid = new DynamicTetrahedralization( floor );
		pyramid.move( 9, 0.5, - 2, 0.5 ); // the apex crosses the floor: its removal alone would be flat
		verify( pyramid, null, 'apex moved below' );

	} );

	it( 'rejects bad arguments naming the method', () => {

		const mesh = new DynamicTetrahedralization( randomPoints( 10, 1 ) );
		expect( () => mesh.insert( 0, NaN, 0 ) ).toThrow( /DynamicTetrahedralization\.insert: .*NaN/ );
		expect( () => mesh.remove( 10 ) ).toThrow( /remove: index 10 is not an active point id/ );
		expect( () => mesh.remove( 1.5 ) ).toThrow( RangeError );
		expect( () => mesh.move( 2, 0, 0, Infinity ) ).toThrow( /move: .*Infinity/ );
		expect( () => new DynamicTetrahedralization( gridPoints( 4, 4, 1, 1 ) ) ).toThrow( /DynamicTetrahedralization: .* one plane/ );
		expect( () => new DynamicTetrahedralization( randomPoints( 10, 1 ), { duplicateTolerance: NaN } ) )
			.toThrow( new RangeError( 'DynamicTetrahedralization: options.duplicateTolerance must be a finite number ≥ 0, got NaN.' ) );
		expect( () => new DynamicTetrahedralization( randomPoints( 10, 1 ), { planarTolerance: - 1 } ) )
			.toThrow( /^DynamicTetrahedralization: options.planarTolerance/ );
		expect( () => new DynamicTetrahedralization( randomPoints( 10, 1 ), { seed: 'x' as unknown as number } ) ).toThrow( TypeError );
		verify( mesh, null, 'after bad arguments' );

	} );

	it( 'moves and inserts far beyond the layout (1e20 … 1.7e308) exactly, in a new scale when needed', () => {

		// Moving a point to 1e20 used to give inverted tetrahedra, and later hull faces sharing an edge.
		const mesh = new DynamicTetrahedralization( randomPoints( 40, 3 ) );
		const mirror = new Mirror( mesh );
		for ( const far of [ 1e20, - 1e60, 1e200, 1.7e308 ] ) {

			mesh.move( 5, far, 0.5, 0.5 );
			expect( Array.from( mesh.positions.subarray( 15, 18 ) ) ).toEqual( [ far, 0.5, 0.5 ] );
			verify( mesh, mirror, `moved to ${far}`, true, true );
			const id = mesh.insert( 0.5, - far, 0.25 );
			verify( mesh, mirror, `inserted at ${- far}`, true, true );
			mesh.remove( id );
			mesh.move( 5, 0.3, 0.3, 0.3 );
			verify( mesh, mirror, `back from ${far}` );

		}

	} );

	it( 'refuses an edit float64 cannot hold beside the others (\'unrepresentable\'), leaving everything as it was', () => {

		const mesh = new DynamicTetrahedralization( randomPoints( 30, 4 ).map( ( v ) => v * 1e-300 ) );
		const before = canonical( mesh.tetrahedra ), positions = mesh.positions.slice();
		for ( const edit of [ () => mesh.insert( 1e10, 0, 0 ), () => mesh.move( 3, 0, - 1e10, 0 ) ] ) {

			expect( edit ).toThrow( expect.objectContaining( { name: 'DegenerateInputError', reason: 'unrepresentable' } ) );
			expect( canonical( mesh.tetrahedra ) ).toBe( before );
			expect( Array.from( mesh.positions ) ).toEqual( Array.from( positions ) );
			expect( mesh.pointCount ).toBe( 30 );

		}

		expect( () => mesh.insert( 1e10, 0, 0 ) ).toThrow( /^DynamicTetrahedralization\.insert: .* float64 cannot hold it/ );
		mesh.insert( 5e-301, 5e-301, 5e-301 );
		verify( mesh, null, 'a representable insertion after the refused ones' );

	} );

} );

describe( 'DynamicTetrahedralization: locality', () => {

	it( 'a move in a 5,000-point layout touches about a hundred cells (removed + created), not the ~33,000 of the mesh, and ends equal to from scratch', () => {

		const mesh = new DynamicTetrahedralization( randomPoints( 5000, 41 ) );
		const random = seededRandom( 42 );
		const mirror = new Mirror( mesh );
		let total = 0, max = 0;
		const moves = 300;
		for ( let e = 0; e < moves; e ++ ) {

			const i = Math.floor( random() * 5000 );
			const p = mesh.positions;
			if ( e % 3 === 0 ) mesh.move( i, random(), random(), random() ); // a jump across the layout
			else mesh.move( i, p[ 3 * i ] + ( random() - 0.5 ) * 0.02, p[ 3 * i + 1 ] + ( random() - 0.5 ) * 0.02,
				p[ 3 * i + 2 ] + ( random() - 0.5 ) * 0.02 );
			const touched = mesh.lastEdit.removedCellCount + mesh.lastEdit.createdCellCount;
			expect( mesh.lastEdit.rebuilt ).toBe( false );
			expect( mesh.lastEdit.changedCells.length ).toBeLessThanOrEqual( touched );
			total += touched;
			max = Math.max( max, touched );
			mirror.apply( mesh, mesh.lastEdit );

		}

		// About 27 tetrahedra around a vertex, removed and re-created at both ends; ~32,000 in the mesh.
		expect( total / moves ).toBeLessThan( 200 );
		expect( max ).toBeLessThan( 600 );
		expect( firstDifference( mirror.tetrahedra, mesh.tetrahedra ) ).toBe( - 1 );
		verify( mesh, null, 'after 300 moves' );

	} );

} );
