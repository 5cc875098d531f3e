/**
 * Incremental edits of the tetrahedralization: moving one probe with
 * DynamicTetrahedralization.move (local removal + insertion) versus tetrahedralize() of the whole
 * layout from scratch, on the hand-made Sponza layout (85 probes) and 5,000 random probes.
 */

import { readFileSync } from 'node:fs';
import { mulberry32, randomPoints } from './datasets.js';
import { collectGarbage, summarize } from './stats.js';
import type { BenchRow, Target } from './types.js';

export const title = 'Incremental edit: move one probe (µs, lower is better)';

export const notes = [
	'ours, move: DynamicTetrahedralization.move( i, x, y, z ) on a random probe, each call timed alone after a warm-up (200 moves); median / min / max over all moves. Small step: a random offset of up to ±1 % of the layout\'s bounding-box size on each axis, then back; jump: to a random point of the bounding box, then back (the layout stays the same on average).',
	'from scratch: tetrahedralize() of the same layout, the alternative to an incremental update, each call timed alone after 20 warm-up calls (400 calls for Sponza, 21 for 5,000 probes). Ratio: move ÷ from scratch. Output: cells (tetrahedra and hull ghost cells) deleted + created per move, mean and max — the work a consumer (TetrahedralMesh inverse matrices) must redo, via lastEdit.changedCells.',
	'Check: after all moves the mesh equals tetrahedralize() of the final positions as a set of tetrahedra (same perturbation, so the Delaunay tetrahedralization is unique). The consumer-side update (inverse matrices of changed cells) is not included in the times.',
	'Target (printed, not asserted): a small move ≤ 1/20 of from scratch on 5,000 probes.',
];

const MOVES = 2000; // timed moves per row (half out, half back)

interface Dynamic {
	readonly positions: Float64Array;
	readonly tetrahedra: Uint32Array;
	readonly pointCount: number;
	readonly lastEdit: { removedCellCount: number; createdCellCount: number; rebuilt: boolean };
	move( index: number, x: number, y: number, z: number ): void;
}

type Tetrahedralize = ( points: ArrayLike<number> ) => { tetrahedra: Uint32Array };

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const layouts = [
		{ name: 'Sponza, 85 probes', points: Float64Array.from( ( JSON.parse( readFileSync( new URL( '../scenes/sponza.json', import.meta.url ), 'utf8' ) ) as { positions: number[] } ).positions ) },
		{ name: '5,000 random probes', points: scale( randomPoints( 'probes', 5000, 12 ).points, 30 ) },
	];

	let Dynamic: new ( positions: ArrayLike<number> ) => Dynamic;
	let tetrahedralize: Tetrahedralize;
	try {

		( { DynamicTetrahedralization: Dynamic } = await import( '../src/tetrahedra/DynamicTetrahedralization.js' ) );
		( { tetrahedralize } = await import( '../src/tetrahedra/tetrahedralize.js' ) );

	} catch ( error ) {

		const status = 'not available: ' + ( error as Error ).message.split( '\n' )[ 0 ];
		return layouts.map( ( { name } ) => ( { case: name, subject: 'ours, move', unit: 'µs', median: null, min: null, max: null, runs: 0, status } ) );

	}

	const rows: BenchRow[] = [];
	for ( const { name, points } of layouts ) {

		log( `${name}: from scratch …` );
		const count = points.length / 3;
		const scratch = timeScratch( tetrahedralize, points, count > 1000 ? 21 : 400 );
		const scratchRow: BenchRow = {
			case: name, subject: 'tetrahedralize() from scratch', unit: 'µs',
			...scaleSummary( summarize( scratch.times ), 1000 ), output: `${scratch.tetrahedra.toLocaleString( 'en-US' )} tetrahedra`,
		};

		const caseRows: BenchRow[] = [];
		for ( const mode of [ 'small step', 'jump' ] as const ) {

			log( `${name}: ${MOVES} moves, ${mode} …` );
			const row: BenchRow = { case: name, subject: `ours, move (${mode})`, unit: 'µs', median: null, min: null, max: null, runs: 0 };
			try {

				const measured = measureMoves( Dynamic, tetrahedralize, points, mode );
				Object.assign( row, scaleSummary( summarize( measured.times ), 1000 ), {
					output: `${measured.meanTouched.toFixed( 0 )} cells touched (max ${measured.maxTouched})${measured.rebuilds ? `, ${measured.rebuilds} rebuilds` : ''}`,
					status: measured.same ? 'same as from scratch' : 'DIFFERS from scratch',
					peer: 'from scratch',
					ratio: summarize( measured.times ).median * 1000 / scratchRow.median!,
				} );

			} catch ( error ) {

				row.status = 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ];

			}

			if ( count > 1000 && mode === 'small step' ) {

				const target: Target = { text: '≤ 0.05× from scratch' };
				if ( row.ratio !== undefined ) target.met = row.ratio <= 0.05;
				row.targets = [ target ];

			}

			caseRows.push( row );

		}

		rows.push( ...caseRows, scratchRow );

	}

	return rows;

}

/** Each call timed alone, like the moves (no forced GC between calls: both pay their own garbage). */
function timeScratch( tetrahedralize: Tetrahedralize, points: Float64Array, runs: number ): { times: number[]; tetrahedra: number } {

	let tetrahedra = 0;
	for ( let i = 0; i < Math.min( 20, runs ); i ++ ) tetrahedra = tetrahedralize( points ).tetrahedra.length / 4;
	collectGarbage();
	const times: number[] = [];
	for ( let i = 0; i < runs; i ++ ) {

		const start = performance.now();
		tetrahedralize( points );
		times.push( performance.now() - start );

	}

	return { times, tetrahedra };

}

function measureMoves( Dynamic: new ( positions: ArrayLike<number> ) => Dynamic, tetrahedralize: Tetrahedralize, points: Float64Array, mode: 'small step' | 'jump' ) {

	const mesh = new Dynamic( points );
	const count = points.length / 3;
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < points.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], points[ i ] );
		max[ i % 3 ] = Math.max( max[ i % 3 ], points[ i ] );

	}

	const random = mulberry32( mode === 'jump' ? 3 : 2 );
	const target = new Float64Array( 3 );
	const times: number[] = [];
	let touched = 0, maxTouched = 0, rebuilds = 0;
	const warmUp = 200;
	collectGarbage();
	for ( let m = - warmUp; m < MOVES; m += 2 ) {

		const i = Math.floor( random() * count );
		const p = mesh.positions;
		const ox = p[ 3 * i ], oy = p[ 3 * i + 1 ], oz = p[ 3 * i + 2 ];
		for ( let a = 0; a < 3; a ++ ) {

			const size = max[ a ] - min[ a ];
			target[ a ] = mode === 'jump' ? min[ a ] + random() * size : p[ 3 * i + a ] + ( random() * 2 - 1 ) * 0.01 * size;

		}

		for ( const [ x, y, z ] of [ [ target[ 0 ], target[ 1 ], target[ 2 ] ], [ ox, oy, oz ] ] ) {

			const start = performance.now();
			mesh.move( i, x, y, z );
			const elapsed = performance.now() - start;
			if ( m < 0 ) continue;
			times.push( elapsed );
			const edit = mesh.lastEdit;
			const cells = edit.removedCellCount + edit.createdCellCount;
			touched += cells;
			maxTouched = Math.max( maxTouched, cells );
			if ( edit.rebuilt ) rebuilds ++;

		}

	}

	const same = canonical( mesh.tetrahedra ) === canonical( tetrahedralize( mesh.positions ).tetrahedra );
	return { times, meanTouched: touched / times.length, maxTouched, rebuilds, same };

}

function canonical( tetrahedra: Uint32Array ): string {

	const cells: string[] = [];
	for ( let t = 0; t < tetrahedra.length; t += 4 ) cells.push( Array.from( tetrahedra.subarray( t, t + 4 ) ).sort( ( a, b ) => a - b ).join( ',' ) );
	return cells.sort().join( ';' );

}

function scale( points: Float64Array, size: number ): Float64Array {

	return points.map( ( v ) => v * size );

}

function scaleSummary( summary: { median: number; min: number; max: number; runs: number }, factor: number ) {

	return { median: summary.median * factor, min: summary.min * factor, max: summary.max * factor, runs: summary.runs };

}
