import { Worker } from 'node:worker_threads';
import { beforeAll, describe, expect, it } from 'vitest';
import { tetrahedralize } from '../../src/tetrahedra/tetrahedralize.js';
import { checkDelaunay } from '../helpers/delaunayChecks.js';
import { randomPoints } from '../helpers/pointSets.js';
import { caseName, scaleCases, type CaseResult } from './scaleCases.js';

/*
 * Magnitudes 1e-300 … 1e300 and powers of two 2^−1070 … 2^1020 on random, jittered, grid and
 * co-spherical sets, exact translations, degenerate layouts and incremental edits at extreme
 * coordinates (scaleCases.ts). Every case runs in a worker thread with a time limit, so that a hang
 * fails its case instead of the suite; each outcome is checked by the independent checker
 * (test/helpers/delaunayChecks.ts). The guarantee tested: docs/robustness.md.
 */

// Per case (the slowest take a few tens of milliseconds alone; the machine may be busy).
const CASE_LIMIT_MS = 10_000;

interface Outcome extends CaseResult { ms: number }

/** Runs every case in worker threads, one after the other; a case over the limit is a failure, and the rest go on in a new worker. */
function runAll( count: number, cases: ReturnType<typeof scaleCases> ): Promise<Outcome[]> {

	const outcomes: Outcome[] = new Array( count );
	return new Promise( ( resolve ) => {

		const start = ( indices: number[] ) => {

			if ( indices.length === 0 ) { resolve( outcomes ); return; }
			const worker = new Worker( new URL( './scaleWorker.mjs', import.meta.url ), { workerData: { cases, indices } } );
			let current = - 1, timer: ReturnType<typeof setTimeout> | undefined, finished = false;
			const rest = () => indices.filter( ( i ) => outcomes[ i ] === undefined );
			const stop = ( failure: string ) => {

				if ( finished ) return;
				finished = true;
				clearTimeout( timer );
				if ( current >= 0 && outcomes[ current ] === undefined ) outcomes[ current ] = { failures: [ failure ], outcome: 'none', ms: CASE_LIMIT_MS };
				void worker.terminate().then( () => start( rest() ) );

			};

			worker.on( 'message', ( message: { type: string; index: number; result?: CaseResult; ms?: number } ) => {

				if ( message.type === 'start' ) {

					current = message.index;
					timer = setTimeout( () => stop( `no result within ${CASE_LIMIT_MS} ms (a hang)` ), CASE_LIMIT_MS );

				} else {

					clearTimeout( timer );
					outcomes[ message.index ] = { ...message.result!, ms: message.ms! };
					if ( rest().length === 0 ) { finished = true; void worker.terminate().then( () => resolve( outcomes ) ); }

				}

			} );
			worker.on( 'error', ( error ) => stop( `the worker failed: ${error.message}` ) );
			worker.on( 'exit', () => stop( 'the worker exited' ) );

		};

		start( Array.from( { length: count }, ( _, i ) => i ) );

	} );

}

describe( 'any scale: the same tetrahedra as at unit scale, or a named error, never a hang', () => {

	const cases = scaleCases();
	let outcomes: Outcome[] = [];
	beforeAll( async () => {

		outcomes = await runAll( cases.length, cases );

	}, 240_000 );

	for ( let i = 0; i < cases.length; i ++ ) {

		it( caseName( cases[ i ] ), () => {

			const outcome = outcomes[ i ];
			expect( outcome, 'the case ran' ).toBeDefined();
			expect( outcome.failures ).toEqual( [] );

		} );

	}

	it( 'covers every kind of case and stays fast', () => {

		const total = outcomes.reduce( ( sum, o ) => sum + ( o?.ms ?? 0 ), 0 );
		expect( cases.length ).toBeGreaterThan( 380 );
		expect( total ).toBeLessThan( 60_000 );

	} );

} );

describe( 'the independent checker catches broken meshes at extreme scales too', () => {

	// Uniform scales, and coordinates far below the extent (robust-predicates could underflow: the
	// checker's BigInt path).
	const variants: [ string, ( v: number, i: number ) => number ][] = [
		[ '× 1e-300', ( v ) => v * 1e-300 ],
		[ '× 1e300', ( v ) => v * 1e300 ],
		[ '× 2^-1070 (subnormal)', ( v ) => Math.round( v * 64 ) * 2 ** - 1070 ],
		[ 'centred × 1.7e308 (the extent overflows)', ( v ) => ( v - 0.5 ) * 1.7e308 * 1.9 ],
		[ 'with coordinates of 1e-200 beside 1', ( v, i ) => i % 7 === 0 ? v * 1e-200 : v ],
	];
	for ( const [ name, map ] of variants ) {

		it( name, () => {

			const points = randomPoints( 40, 9 ).map( map );
			const good = tetrahedralize( points );
			const clean = checkDelaunay( points, good.tetrahedra, good.neighbors );
			const { nonPositive, asymmetricNeighbors, mismatchedFaces, hullViolations, emptySphereViolations } = clean;
			expect( [ nonPositive, asymmetricNeighbors, mismatchedFaces, hullViolations, emptySphereViolations ] )
				.toEqual( [ 0, 0, 0, 0, 0 ] );
			expect( clean.tilingError ).toBeLessThanOrEqual( 1e-9 );

			const inverted = good.tetrahedra.slice();
			[ inverted[ 0 ], inverted[ 1 ] ] = [ inverted[ 1 ], inverted[ 0 ] ];
			expect( checkDelaunay( points, inverted, good.neighbors ).nonPositive ).toBe( 1 );

			const unlinked = good.neighbors.slice();
			unlinked[ unlinked.findIndex( ( u ) => u >= 0 ) ] = - 1;
			const report = checkDelaunay( points, good.tetrahedra, unlinked );
			expect( report.asymmetricNeighbors + report.hullViolations ).toBeGreaterThan( 0 );

			const dropped = checkDelaunay( points, good.tetrahedra.slice( 4 ), good.neighbors.slice( 4 ) );
			expect( dropped.tilingError ).toBeGreaterThan( 1e-9 );

		} );

		it( `${name}: a non-Delaunay flip of a bipyramid`, () => {

			// As in tetrahedralize.test.ts: of the two splits of a triangular bipyramid, the one not
			// chosen puts a point strictly inside a circumsphere.
			const unit = Float64Array.from( [ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1, 0.3, 0.3, - 0.1 ] );
			const bipyramid = unit.map( ( v, i ) => map( v * 0.8 + 0.1, i ) );
			const delaunay = tetrahedralize( bipyramid );
			expect( checkDelaunay( bipyramid, delaunay.tetrahedra, delaunay.neighbors ).emptySphereViolations ).toBe( 0 );
			const chosen = delaunay.tetrahedra.length / 4;
			const other = Uint32Array.from( chosen === 2 ? [ 0, 1, 4, 3, 1, 2, 4, 3, 2, 0, 4, 3 ] : [ 0, 1, 2, 3, 0, 1, 2, 4 ] );
			const none = new Int32Array( other.length ).fill( - 1 );
			for ( let t = 0; t < other.length / 4; t ++ ) {

				const one = other.subarray( 4 * t, 4 * t + 4 );
				const flipped = checkDelaunay( bipyramid, one, none.subarray( 0, 4 ) ).nonPositive > 0;
				if ( flipped ) [ one[ 0 ], one[ 1 ] ] = [ one[ 1 ], one[ 0 ] ];

			}

			const report = checkDelaunay( bipyramid, other, none );
			expect( report.nonPositive ).toBe( 0 );
			expect( report.emptySphereViolations ).toBeGreaterThan( 0 );

		} );

	}

} );
