import { DegenerateInputError, type DegenerateReason } from '../../src/tetrahedra/DegenerateInputError.js';
import { DynamicTetrahedralization } from '../../src/tetrahedra/DynamicTetrahedralization.js';
import { tetrahedralize, type Tetrahedralization } from '../../src/tetrahedra/tetrahedralize.js';
import { checkDelaunay, normalizedCopy } from '../helpers/delaunayChecks.js';
import { gridPoints, integerSpherePoints, randomPoints, seededRandom } from '../helpers/pointSets.js';

/*
 * The cases of scale.test.ts, run in a worker (scaleWorker.mjs) so that a hang fails the case
 * instead of hanging the suite. Each case returns the list of what went wrong (empty when it
 * passed) and what it produced; the test asserts on that.
 */

/** The unit-scale point sets every magnitude is tried on (and two of the reproducers: a 3³ grid, 4 points). */
export type SetName = 'random' | 'jittered' | 'grid' | 'sphere' | 'grid3' | 'four';

export type CaseSpec =
	// U × 2^power: byte for byte the tetrahedra of U (when the copy is exact).
	| { kind: 'power'; set: SetName; power: number }
	// U × 10^exponent (U centred and scaled into [−1, 1] first when centred, and for 1e308 times
	// 1.7, so that the extent overflows): the tetrahedra of its power-of-two-normalised copy.
	| { kind: 'decimal'; set: SetName; exponent: number; centred?: boolean }
	// U + offset, U rounded to multiples of 2^−8 so that the sum is exact: byte for byte U's tetrahedra.
	| { kind: 'translated'; set: SetName; offset: [ number, number, number ] }
	// A degenerate layout at 10^exponent: the named error with the right reason.
	| { kind: 'degenerate'; shape: 'line' | 'plane' | 'few' | 'tinyBesideHuge'; exponent: number; reason: DegenerateReason }
	// Edits of a DynamicTetrahedralization whose points are about 10^exponent.
	| { kind: 'dynamic'; script: 'far' | 'scaled' | 'unrepresentable'; exponent: number };

export interface CaseResult {

	/** What went wrong; empty when the case passed. */
	failures: string[];
	/** 'mesh', or the reason of the DegenerateInputError the case ended with. */
	outcome: string;

}

/** A readable name for a case. */
export function caseName( spec: CaseSpec ): string {

	switch ( spec.kind ) {

		case 'power': return `${spec.set} × 2^${spec.power}`;
		case 'decimal': return `${spec.set}${spec.centred ? ' (centred)' : ''} × 1e${spec.exponent}`;
		case 'translated': return `${spec.set} + (${spec.offset.join( ', ' )})`;
		case 'degenerate': return `${spec.shape} at 1e${spec.exponent} → '${spec.reason}'`;
		case 'dynamic': return `DynamicTetrahedralization, ${spec.script} edits at 1e${spec.exponent}`;

	}

}

/** Every case of the suite. */
export function scaleCases(): CaseSpec[] {

	const sets: SetName[] = [ 'random', 'jittered', 'grid', 'sphere' ];
	const cases: CaseSpec[] = [];
	for ( const set of sets ) {

		for ( let exponent = - 300; exponent <= 300; exponent += 10 ) cases.push( { kind: 'decimal', set, exponent } );
		for ( const exponent of [ - 307, 307, 308 ] ) cases.push( { kind: 'decimal', set, exponent, centred: true } );
		for ( let power = - 1000; power <= 1000; power += 125 ) cases.push( { kind: 'power', set, power } );
		for ( const power of [ - 1070, 1020 ] ) cases.push( { kind: 'power', set, power } );
		const offsets: [ number, number, number ][] = [
			[ 512345.5, 4012345.25, 87.5 ], [ 2 ** 40, - ( 2 ** 41 ), 3 * 2 ** 30 ], [ - 1e6, 1e6, 0.5 ],
		];
		for ( const offset of offsets ) cases.push( { kind: 'translated', set, offset } );

	}

	// Issue 12's reports: a 3³ grid hung at 1e-60, was invalid at 1e-50 and 1e70, "collinear" at
	// 1e-100, "coplanar" at 1e120; 4 points at 1e200 were "1 distinct point".
	for ( const exponent of [ - 60, - 50, 70, - 100, 120 ] ) cases.push( { kind: 'decimal', set: 'grid3', exponent } );
	for ( const exponent of [ 200, - 200 ] ) cases.push( { kind: 'decimal', set: 'four', exponent } );

	for ( const exponent of [ - 300, - 100, - 60, 0, 70, 120, 200, 300 ] ) {

		cases.push( { kind: 'degenerate', shape: 'line', exponent, reason: 'collinear' } );
		cases.push( { kind: 'degenerate', shape: 'plane', exponent, reason: 'coplanar' } );
		cases.push( { kind: 'degenerate', shape: 'few', exponent, reason: 'too-few-points' } );

	}

	for ( const exponent of [ 200, 300 ] ) cases.push( { kind: 'degenerate', shape: 'tinyBesideHuge', exponent, reason: 'unrepresentable' } );
	for ( const exponent of [ 0, - 150, 150 ] ) cases.push( { kind: 'dynamic', script: 'far', exponent } );
	for ( const exponent of [ - 300, - 200, 200, 300 ] ) cases.push( { kind: 'dynamic', script: 'scaled', exponent } );
	for ( const exponent of [ - 300, 300 ] ) cases.push( { kind: 'dynamic', script: 'unrepresentable', exponent } );
	return cases;

}

/** The unit-scale set (extent about 1 to 6, dyadic coordinates for the grids). */
export function unitSet( set: SetName ): Float64Array {

	switch ( set ) {

		case 'random': return randomPoints( 60, 3 );
		case 'grid': return gridPoints( 4, 4, 4, 1 );
		case 'grid3': return gridPoints( 3, 3, 3, 1 );
		case 'four': return Float64Array.of( 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.5, 1 );
		case 'sphere': return Float64Array.from( [ ...integerSpherePoints( 3 ), 0, 0, 0 ] );
		case 'jittered': {

			const random = seededRandom( 21 ), points = gridPoints( 4, 4, 4, 1 );
			for ( let i = 0; i < points.length; i ++ ) points[ i ] += ( random() - 0.5 ) * 0.1;
			return points;

		}

	}

}

/** The set moved to its bounding box's centre and scaled into [−1, 1]. */
function centred( points: Float64Array ): Float64Array {

	const out = points.slice();
	for ( let a = 0; a < 3; a ++ ) {

		let min = Infinity, max = - Infinity;
		for ( let i = a; i < out.length; i += 3 ) { min = Math.min( min, out[ i ] ); max = Math.max( max, out[ i ] ); }
		for ( let i = a; i < out.length; i += 3 ) out[ i ] = ( 2 * out[ i ] - min - max ) / ( max - min );

	}

	return out;

}

/** Runs one case. */
export function runCase( spec: CaseSpec ): CaseResult {

	switch ( spec.kind ) {

		case 'power': {

			const unit = unitSet( spec.set ), points = unit.map( ( v ) => v * 2 ** spec.power );
			const exact = points.every( ( v, i ) => v / 2 ** spec.power === unit[ i ] );
			return meshCase( points, exact ? tetrahedralize( unit ) : null );

		}

		case 'decimal': {

			const unit = spec.centred ? centred( unitSet( spec.set ) ) : unitSet( spec.set );
			const s = 10 ** spec.exponent * ( spec.exponent === 308 ? 1.7 : 1 ), points = unit.map( ( v ) => v * s );
			const result = meshCase( points, tetrahedralize( normalizedCopy( points ).points ) );
			// In general position the Delaunay tetrahedralization does not change under rounding.
			if ( result.outcome === 'mesh' && ( spec.set === 'random' || spec.set === 'jittered' ) ) {

				if ( canonical( tetrahedralize( points ).tetrahedra ) !== canonical( tetrahedralize( unit ).tetrahedra ) ) {

					result.failures.push( 'not the tetrahedra of the unit-scale set' );

				}

			}

			return result;

		}

		case 'translated': {

			const unit = unitSet( spec.set ).map( ( v ) => Math.round( v * 2 ** 8 ) / 2 ** 8 );
			const points = unit.map( ( v, i ) => v + spec.offset[ i % 3 ] );
			const exact = points.every( ( v, i ) => v - spec.offset[ i % 3 ] === unit[ i ] );
			return exact ? meshCase( points, tetrahedralize( unit ) ) : { failures: [ 'the translated copy is not exact' ], outcome: 'none' };

		}

		case 'degenerate': return degenerateCase( spec.shape, 10 ** spec.exponent, spec.reason );
		case 'dynamic': return dynamicCase( spec.script, 10 ** spec.exponent );

	}

}

/** tetrahedralize( points ): a valid Delaunay mesh, byte for byte `reference` when given. */
function meshCase( points: Float64Array, reference: Tetrahedralization | null ): CaseResult {

	let result: Tetrahedralization;
	try {

		result = tetrahedralize( points );

	} catch ( error ) {

		return { failures: [ `threw ${( error as Error ).message}` ], outcome: 'error' };

	}

	const failures = validity( points, result.tetrahedra, result.neighbors );
	if ( result.duplicates.length > 0 ) failures.push( `${result.duplicates.length / 2} points merged as duplicates` );
	if ( reference && ! sameBytes( result, reference ) ) failures.push( 'not byte for byte the reference tetrahedralization' );
	return { failures, outcome: 'mesh' };

}

/** What the independent checker finds wrong with a mesh of `points`. */
function validity( points: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array ): string[] {

	const r = checkDelaunay( points, tetrahedra, neighbors );
	const failures: string[] = [];
	if ( r.tetrahedra === 0 ) failures.push( 'no tetrahedra' );
	if ( r.nonPositive ) failures.push( `${r.nonPositive} flat or inverted` );
	if ( r.asymmetricNeighbors + r.mismatchedFaces ) failures.push( `${r.asymmetricNeighbors + r.mismatchedFaces} bad neighbour links` );
	if ( r.unusedPoints ) failures.push( `${r.unusedPoints} points missing` );
	if ( r.hullViolations ) failures.push( `${r.hullViolations} hull faces not on the convex hull` );
	if ( r.emptySphereViolations ) failures.push( `${r.emptySphereViolations} points strictly inside circumspheres` );
	if ( ! ( r.tilingError <= 1e-9 ) ) failures.push( `volumes do not tile the hull (relative error ${r.tilingError})` );
	return failures;

}

function degenerateCase( shape: string, s: number, reason: DegenerateReason ): CaseResult {

	let points: Float64Array;
	if ( shape === 'line' ) points = Float64Array.from( { length: 30 }, ( _, i ) => Math.floor( i / 3 ) * ( ( i % 3 ) + 1 ) * s );
	else if ( shape === 'plane' ) points = gridPoints( 4, 4, 1, 1 ).map( ( v, i ) => ( i % 3 === 2 ? 0.7 : v ) * s );
	else if ( shape === 'few' ) points = Float64Array.from( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0 ], ( v ) => v * s );
	else {

		points = randomPoints( 30, 5 ).map( ( v ) => v * s );
		points[ 0 ] = 1e-300;

	}

	try {

		tetrahedralize( points );
		return { failures: [ `returned a mesh instead of DegenerateInputError '${reason}'` ], outcome: 'mesh' };

	} catch ( error ) {

		if ( ! ( error instanceof DegenerateInputError ) ) return { failures: [ `threw ${( error as Error ).message}` ], outcome: 'error' };
		const failures = error.reason === reason ? [] : [ `reason '${error.reason}' (${error.message})` ];
		return { failures, outcome: error.reason };

	}

}

/** One edit of a dynamic case: an insertion (index −1), a move or a removal of point `index`. */
interface Edit {

	label: string;
	type: 'insert' | 'move' | 'remove';
	index: number;
	x: number;
	y: number;
	z: number;

}

/**
 * Edits of a DynamicTetrahedralization: each must either work (then the mesh is valid and the
 * tetrahedralization of the same points from scratch) or throw a DegenerateInputError and leave the
 * mesh as it was; 'unrepresentable' exactly when float64 cannot hold the edited set at unit scale.
 */
function dynamicCase( script: string, s: number ): CaseResult {

	const failures: string[] = [];
	const count = script === 'scaled' ? 50 : 30;
	const mesh = new DynamicTetrahedralization( randomPoints( count, 7 ).map( ( v ) => v * s ) );
	const random = seededRandom( 13 );
	const edits: Edit[] = [];
	const insert = ( label: string, x: number, y: number, z: number ) => edits.push( { label, type: 'insert', index: - 1, x, y, z } );
	const move = ( label: string, index: number, x: number, y: number, z: number ) => edits.push( { label, type: 'move', index, x, y, z } );
	if ( script === 'far' ) {

		const huge = Math.min( 1e20 * s, 1e300 );
		move( 'move to 1e17 (within the local frame)', 7, 0.5 * s, 1e17 * s, 0.5 * s );
		move( 'move back from 1e17', 7, 0.5 * s, 0.5 * s, 0.75 * s );
		insert( 'insert far', huge, 0.5 * s, 0.5 * s );
		move( 'move far (negative)', 3, - huge, 0.2 * s, 0.9 * s );
		insert( 'insert 1e100 further', 0.5 * s, Math.min( 1e100 * s, 1e300 ), 0.1 * s );
		move( 'move far back', 3, 0.3 * s, 0.35 * s, 0.4 * s );
		for ( let i = 0; i < 10; i ++ ) move( `small move ${i}`, 5 + i, random() * s, random() * s, random() * s );
		edits.push( { label: 'remove the far point', type: 'remove', index: count, x: 0, y: 0, z: 0 } );
		insert( 'insert at +1.7e308', 1.7e308, 0, 0 );
		insert( 'insert at −1.7e308', - 1.7e308, 1e300, - 1e300 );
		move( 'move into the middle', 4, 0.45 * s, 0.55 * s, 0.5 * s );

	} else if ( script === 'scaled' ) {

		for ( let i = 0; i < 45; i ++ ) {

			const x = random() * 1.2 * s, y = random() * 1.2 * s, z = random() * 1.2 * s, index = Math.floor( random() * count );
			if ( i % 3 === 0 ) insert( `insert ${i}`, x, y, z );
			else if ( i % 3 === 1 ) move( `move ${i}`, index, x, y, z );
			else edits.push( { label: `remove ${i}`, type: 'remove', index, x: 0, y: 0, z: 0 } );

		}

	} else {

		insert( 'insert beyond the range', s < 1 ? 1e10 : 1e-300, 0.5 * s, 0.5 * s );
		move( 'move beyond the range', 2, s < 1 ? - 1e10 : 3e-300, 0.5 * s, 0.25 * s );

	}

	let applied = 0;
	for ( const e of edits ) {

		if ( e.type !== 'insert' && ! mesh.isActive( e.index ) ) continue;
		const before = canonical( mesh.tetrahedra ), positions = mesh.positions.slice();
		const representable = e.type === 'remove' || canNormalise( editedPoints( mesh, e ) );
		let id = e.index;
		try {

			if ( e.type === 'insert' ) id = mesh.insert( e.x, e.y, e.z );
			else if ( e.type === 'move' ) mesh.move( e.index, e.x, e.y, e.z );
			else mesh.remove( e.index );

		} catch ( error ) {

			if ( ! ( error instanceof DegenerateInputError ) ) {

				failures.push( `${e.label}: threw ${( error as Error ).message}` );
				break;

			}

			if ( canonical( mesh.tetrahedra ) !== before || ! sameArray( mesh.positions, positions ) ) failures.push( `${e.label}: refused but changed the mesh` );
			if ( error.reason === 'unrepresentable' && representable ) failures.push( `${e.label}: refused a representable edit (${error.message})` );
			if ( error.reason !== 'unrepresentable' && error.reason !== 'coincident' ) failures.push( `${e.label}: refused with '${error.reason}'` );
			continue;

		}

		applied ++;
		if ( ! representable ) failures.push( `${e.label}: accepted although the set cannot be normalised exactly` );
		const p = mesh.positions;
		if ( e.type !== 'remove' && ( p[ 3 * id ] !== e.x || p[ 3 * id + 1 ] !== e.y || p[ 3 * id + 2 ] !== e.z ) ) failures.push( `${e.label}: positions do not show it` );
		for ( const f of dynamicValidity( mesh ) ) failures.push( `${e.label}: ${f}` );

	}

	if ( script === 'unrepresentable' && applied > 0 ) failures.push( `${applied} unrepresentable edits accepted` );
	if ( script !== 'unrepresentable' && applied < edits.length / 2 ) failures.push( `only ${applied} of ${edits.length} edits worked` );
	return { failures, outcome: 'mesh' };

}

/** Whether float64 holds `points` scaled to unit size exactly. */
function canNormalise( points: Float64Array ): boolean {

	try {

		normalizedCopy( points );
		return true;

	} catch {

		return false;

	}

}

/** The active points after the insertion or move `e` (without applying it). */
function editedPoints( mesh: DynamicTetrahedralization, e: Edit ): Float64Array {

	const out: number[] = [], p = mesh.positions;
	for ( let i = 0; i < mesh.pointCount; i ++ ) {

		if ( ! mesh.isActive( i ) ) continue;
		if ( i === e.index ) out.push( e.x, e.y, e.z );
		else out.push( p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ] );

	}

	if ( e.type === 'insert' ) out.push( e.x, e.y, e.z );
	return Float64Array.from( out );

}

/** The checker on the active points, and equality with tetrahedralize() from scratch. */
function dynamicValidity( mesh: DynamicTetrahedralization ): string[] {

	const ids: number[] = [];
	for ( let i = 0; i < mesh.pointCount; i ++ ) if ( mesh.isActive( i ) ) ids.push( i );
	const points = new Float64Array( 3 * ids.length );
	ids.forEach( ( id, j ) => points.set( mesh.positions.subarray( 3 * id, 3 * id + 3 ), 3 * j ) );
	const local = new Map( ids.map( ( id, j ) => [ id, j ] ) );
	const tetrahedra = Uint32Array.from( mesh.tetrahedra, ( v ) => local.get( v ) ?? 0 );
	const failures = validity( points, tetrahedra, mesh.neighbors );
	// Without tolerances: the mesh keeps its initial ones, which a far point would make coarse.
	const scratch = tetrahedralize( points, { duplicateTolerance: 0, planarTolerance: 0 } );
	if ( canonical( scratch.tetrahedra ) !== canonical( tetrahedra ) ) failures.push( 'not the tetrahedra of tetrahedralize() from scratch' );
	return failures;

}

/** Sorted tetrahedra as sorted vertex lists. */
function canonical( tetrahedra: Uint32Array ): string {

	const cells: string[] = [];
	for ( let t = 0; t < tetrahedra.length; t += 4 ) cells.push( Array.from( tetrahedra.subarray( t, t + 4 ) ).sort( ( a, b ) => a - b ).join( ',' ) );
	return cells.sort().join( ';' );

}

function sameBytes( a: Tetrahedralization, b: Tetrahedralization ): boolean {

	return sameArray( a.tetrahedra, b.tetrahedra ) && sameArray( a.neighbors, b.neighbors ) && sameArray( a.duplicates, b.duplicates );

}

function sameArray( a: ArrayLike<number>, b: ArrayLike<number> ): boolean {

	if ( a.length !== b.length ) return false;
	for ( let i = 0; i < a.length; i ++ ) if ( a[ i ] !== b[ i ] ) return false;
	return true;

}
