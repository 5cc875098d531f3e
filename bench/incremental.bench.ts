/**
 * Incremental edits of the tetrahedralization: moving one probe with
 * DynamicTetrahedralization.move (local removal + insertion) versus tetrahedralize() of the whole
 * layout from scratch, on the hand-made Sponza layout (85 probes) and 5,000 random probes; then
 * the full update a consumer pays — an incremental TetrahedralMesh (inverse matrices of changed
 * cells, outer cells when the hull changed) and LightProbeVolume.moveProbe (without capture) —
 * versus building a TetrahedralMesh / LightProbeVolume from scratch.
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
	'Full update: TetrahedralMesh.moveProbe on an IncrementalTetrahedralMesh (the dynamic move, inverse matrices of lastEdit.changedCells, hull-face slots, and the outer cells rebuilt over the whole hull when a hull face changed), and LightProbeVolume.moveProbe (the same plus the volume\'s bookkeeping; no capture), timed per move like the above; peers: new TetrahedralMesh( positions ) and new LightProbeVolume( { positions } ) from scratch. Output: share of moves that changed the hull (and so rebuilt the outer cells) and the median of those moves. Check: after the moves, interpolate() at 2,000 points in and around the hull equals a TetrahedralMesh from scratch to 1e-9.',
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
		rows.push( ...await fullUpdateRows( name, points, log ) );

	}

	return rows;

}

interface Mesh {
	readonly positions: Float64Array;
	readonly cellCount: number;
	moveProbe( index: number, x: number, y: number, z: number ): void;
	interpolate( x: number, y: number, z: number, indices: Uint32Array, weights: Float64Array, hint?: number ): number;
	readonly dynamic: { lastEdit: { changedHullFaces: Int32Array, rebuilt: boolean } } | null;
}

/** The consumer-side rows: incremental TetrahedralMesh and LightProbeVolume moves vs building them from scratch. */
async function fullUpdateRows( name: string, points: Float64Array, log: ( message: string ) => void ): Promise<BenchRow[]> {

	const count = points.length / 3;
	let modules;
	try {

		modules = {
			...await import( '../src/interpolation/TetrahedralMesh.js' ),
			...await import( '../src/runtime/LightProbeVolume.js' ),
			...await import( '../src/tetrahedra/DynamicTetrahedralization.js' ),
			...await import( '../src/interpolation/IncrementalTetrahedralMesh.js' ),
		};

	} catch ( error ) {

		const status = 'not available: ' + ( error as Error ).message.split( '\n' )[ 0 ];
		return [ { case: name, subject: 'TetrahedralMesh.moveProbe', unit: 'µs', median: null, min: null, max: null, runs: 0, status } ];

	}

	const { TetrahedralMesh, LightProbeVolume, DynamicTetrahedralization, IncrementalTetrahedralMesh } = modules;
	const runs = count > 1000 ? 21 : 400;
	log( `${name}: TetrahedralMesh / LightProbeVolume from scratch …` );
	const meshScratch = timeBuild( () => new TetrahedralMesh( points ), runs );
	const volumeScratch = timeBuild( () => new LightProbeVolume( { positions: points } ), runs );
	const rows: BenchRow[] = [];
	for ( const subject of [ 'TetrahedralMesh.moveProbe', 'LightProbeVolume.moveProbe' ] as const ) {

		const scratch = subject === 'TetrahedralMesh.moveProbe' ? meshScratch : volumeScratch;
		for ( const mode of [ 'small step', 'jump' ] as const ) {

			log( `${name}: ${subject}, ${MOVES} moves, ${mode} …` );
			const row: BenchRow = { case: name, subject: `ours, ${subject} (${mode})`, unit: 'µs', median: null, min: null, max: null, runs: 0 };
			try {

				const mesh = new IncrementalTetrahedralMesh( new DynamicTetrahedralization( points ) ) as unknown as Mesh;
				let move: ( i: number, x: number, y: number, z: number ) => void;
				let current: () => Mesh;
				if ( subject === 'TetrahedralMesh.moveProbe' ) {

					move = ( i, x, y, z ) => mesh.moveProbe( i, x, y, z );
					current = () => mesh;

				} else {

					const volume = new LightProbeVolume( { positions: points } );
					volume.moveProbe( 0, [ points[ 0 ], points[ 1 ], points[ 2 ] ] ); // the one-time switch to an incremental mesh, untimed
					const target = [ 0, 0, 0 ];
					move = ( i, x, y, z ) => { target[ 0 ] = x; target[ 1 ] = y; target[ 2 ] = z; volume.moveProbe( i, target ); };
					current = () => volume.interpolator as unknown as Mesh;

				}

				const measured = measureMeshMoves( current, move, points, mode );
				const median = summarize( measured.times ).median * 1000;
				const hull = measured.hullTimes.length > 0 ? summarize( measured.hullTimes ).median * 1000 : 0;
				Object.assign( row, scaleSummary( summarize( measured.times ), 1000 ), {
					output: `hull changed in ${( 100 * measured.hullTimes.length / measured.times.length ).toFixed( 0 )} % of moves (median ${hull.toFixed( 0 )} µs), ${measured.otherTimes.length > 0 ? `others median ${( summarize( measured.otherTimes ).median * 1000 ).toFixed( 0 )} µs` : 'no others'}`,
					status: checkAgainstScratch( TetrahedralMesh, current() ) ? 'same as from scratch' : 'DIFFERS from scratch',
					peer: subject === 'TetrahedralMesh.moveProbe' ? 'new TetrahedralMesh from scratch' : 'new LightProbeVolume from scratch',
					ratio: median / ( summarize( scratch ).median * 1000 ),
				} );

			} catch ( error ) {

				row.status = 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ];

			}

			rows.push( row );

		}

		rows.push( { case: name, subject: subject === 'TetrahedralMesh.moveProbe' ? 'new TetrahedralMesh() from scratch' : 'new LightProbeVolume() from scratch', unit: 'µs', ...scaleSummary( summarize( scratch ), 1000 ) } );

	}

	return rows;

}

function timeBuild( build: () => unknown, runs: number ): number[] {

	for ( let i = 0; i < Math.min( 20, runs ); i ++ ) build();
	collectGarbage();
	const times: number[] = [];
	for ( let i = 0; i < runs; i ++ ) {

		const start = performance.now();
		build();
		times.push( performance.now() - start );

	}

	return times;

}

function measureMeshMoves( current: () => Mesh, move: ( i: number, x: number, y: number, z: number ) => void, points: Float64Array, mode: 'small step' | 'jump' ) {

	const count = points.length / 3;
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < points.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], points[ i ] );
		max[ i % 3 ] = Math.max( max[ i % 3 ], points[ i ] );

	}

	const random = mulberry32( mode === 'jump' ? 3 : 2 );
	const target = new Float64Array( 3 );
	const times: number[] = [], hullTimes: number[] = [], otherTimes: number[] = [];
	collectGarbage();
	for ( let m = - 200; m < MOVES; m += 2 ) {

		const i = Math.floor( random() * count );
		const p = current().positions;
		const ox = p[ 3 * i ], oy = p[ 3 * i + 1 ], oz = p[ 3 * i + 2 ];
		for ( let a = 0; a < 3; a ++ ) {

			const size = max[ a ] - min[ a ];
			target[ a ] = mode === 'jump' ? min[ a ] + random() * size : p[ 3 * i + a ] + ( random() * 2 - 1 ) * 0.01 * size;

		}

		for ( const [ x, y, z ] of [ [ target[ 0 ], target[ 1 ], target[ 2 ] ], [ ox, oy, oz ] ] ) {

			const start = performance.now();
			move( i, x, y, z );
			const elapsed = performance.now() - start;
			if ( m < 0 ) continue;
			times.push( elapsed );
			const edit = current().dynamic!.lastEdit;
			( edit.changedHullFaces.length > 0 || edit.rebuilt ? hullTimes : otherTimes ).push( elapsed );

		}

	}

	return { times, hullTimes, otherTimes };

}

/** interpolate() at 2,000 points in and around the hull equals a mesh from scratch (all ids active after move-and-back). */
function checkAgainstScratch( TetrahedralMesh: new ( positions: ArrayLike<number> ) => Pick<Mesh, 'interpolate'>, mesh: Mesh ): boolean {

	const p = mesh.positions, scratch = new TetrahedralMesh( p.slice() );
	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < p.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], p[ i ] ); max[ i % 3 ] = Math.max( max[ i % 3 ], p[ i ] );

	}

	const random = mulberry32( 5 );
	const a = new Uint32Array( 4 ), wa = new Float64Array( 4 ), b = new Uint32Array( 4 ), wb = new Float64Array( 4 );
	for ( let n = 0; n < 2000; n ++ ) {

		const q = [ 0, 1, 2 ].map( ( k ) => min[ k ] + ( random() * 1.4 - 0.2 ) * ( max[ k ] - min[ k ] ) );
		mesh.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], a, wa );
		scratch.interpolate( q[ 0 ], q[ 1 ], q[ 2 ], b, wb );
		const weights = new Map<number, number>();
		for ( let k = 0; k < 4; k ++ ) weights.set( a[ k ], ( weights.get( a[ k ] ) ?? 0 ) + wa[ k ] );
		for ( let k = 0; k < 4; k ++ ) weights.set( b[ k ], ( weights.get( b[ k ] ) ?? 0 ) - wb[ k ] );
		for ( const value of weights.values() ) if ( Math.abs( value ) > 1e-9 ) return false;

	}

	return true;

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
