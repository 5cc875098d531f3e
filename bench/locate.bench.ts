/**
 * Probe lookup throughput: 10,000 objects move through a TetrahedralMesh; each frame every object
 * is located (walking from its previous tetrahedron, or from tetrahedron 0 without hints), its
 * barycentric weights computed and its 4 probes' SH blended. Moving the objects is not timed;
 * the timed loop allocates nothing.
 */

import { gridPoints, mulberry32, randomPoints } from './datasets.js';
import { loadOurs, whyMissing, type OurApi, type OurTetrahedralMesh } from './ours.js';
import { summarize } from './stats.js';
import type { BenchRow, Target } from './types.js';

export const title = 'Probe lookup, 10,000 moving objects (M queries/s, higher is better)';

export const notes = [
	'One query = locate + barycentric + blendSH (27 floats from 4 probes), locate alone, or the per-frame API interpolate() (locate + clamped weights) + blendSH, where marked. Coherent: each object follows a smooth Lissajous path, moving about 0.4 % of the box per frame, and its hint is the tetrahedron it was in last frame; no hint: every walk starts at tetrahedron 0.',
	'Each figure: queries / time of the timed loop, frames repeated until ≥ 0.5 s; median, min, max of 3 such measurements, one core. Target (printed, not asserted): ≥ 5 M/s with hints.',
	'Peer: the regular-grid lookup that three\'s LightProbeGrid and the paper\'s baseline use — GridInterpolator.interpolate (trilinear, 8 probes) + blendSH of the 8 probes (its one-pass 8-probe path), on the same moving objects: the 12×6×6 grid itself, and for the random probes a 10×10×10 grid (1,000 probes) over the same box. Ratio: ours ÷ peer in M queries/s (above 1: ours answers more queries per second).',
	'Outside the hull: the same paths with an amplitude of 90 % of the box instead of 35 %, so most objects are outside the probes\' hull most of the time (share in Check); interpolate() with outer cells (the default: a walk across the cells swept from the hull triangles) and with the nearestFace option (a scan of every hull triangle per query).',
];

const OBJECTS = 10_000;
const MIN_MS = 500;
const REPEATS = 3;
const TARGET = 5; // M queries/s, coherent, with hints

/** What one query does: locate alone, locate + barycentric + blendSH, or interpolate() + blendSH. */
type Query = 'locate' | 'blend' | 'interpolate' | 'grid';
type Mode = { subject: string, hinted: boolean, query: Query, target: boolean, outside?: 'outerCells' | 'nearestFace' };

const MODES: Mode[] = [
	{ subject: 'ours, coherent, hint = previous', hinted: true, query: 'blend', target: true },
	{ subject: 'ours, coherent, locate only', hinted: true, query: 'locate', target: false },
	{ subject: 'ours, coherent, interpolate() + blendSH', hinted: true, query: 'interpolate', target: false },
	{ subject: 'ours, no hint (0)', hinted: false, query: 'blend', target: false },
	{ subject: 'ours, outside the hull: interpolate() (outer cells) + blendSH', hinted: true, query: 'interpolate', target: false, outside: 'outerCells' },
	{ subject: 'ours, outside the hull: interpolate() (nearestFace option) + blendSH', hinted: true, query: 'interpolate', target: false, outside: 'nearestFace' },
	{ subject: 'peer: trilinear grid, interpolate() + blendSH of 8', hinted: false, query: 'grid', target: false },
];

interface Grid {
	positions: Float64Array;
	interpolate( x: number, y: number, z: number, indices: Uint32Array, weights: Float32Array ): number;
}
type GridClass = new ( min: ArrayLike<number>, max: ArrayLike<number>, counts: ArrayLike<number> ) => Grid;

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const meshes = [
		{ name: '1k random probes', points: randomPoints( 'probes', 1000, 11 ).points, gridCounts: [ 10, 10, 10 ] },
		{ name: 'grid 12x6x6 probes', points: gridPoints( 'probes', 12, 6, 6 ).points, gridCounts: [ 12, 6, 6 ] },
	];
	const Grid = ( ( await loadOurs() ).api as { GridInterpolator?: GridClass } ).GridInterpolator;

	const ours = await loadOurs();
	const missing = whyMissing( ours, [ 'TetrahedralMesh', 'blendSH' ] );
	const rows: BenchRow[] = [];

	for ( const { name, points, gridCounts } of meshes ) {

		const caseRows: BenchRow[] = [];
		for ( const mode of MODES ) {

			const row: BenchRow = { case: name, subject: mode.subject, unit: 'M queries/s', median: null, min: null, max: null, runs: 0 };
			const target: Target = { text: `≥ ${TARGET} M/s` };
			if ( mode.target ) row.targets = [ target ];
			caseRows.push( row );
			if ( mode.query === 'grid' ) {

				if ( ! Grid ) {

					row.status = 'not available: src/math.ts does not export GridInterpolator';
					continue;

				}

				row.subject += ` (${gridCounts.join( '×' )} grid)`;
				log( `${name}: ${row.subject} …` );
				const { rates } = measureGrid( Grid, ( ours.api as OurApi ).blendSH, points, gridCounts );
				Object.assign( row, summarize( rates ), { output: `${gridCounts.reduce( ( a, b ) => a * b ).toLocaleString( 'en-US' )} probes` } );
				continue;

			}

			if ( missing || ( mode.query === 'interpolate' && ! ours.api.TetrahedralMesh?.prototype.interpolate ) ) {

				row.status = missing ?? 'not available: TetrahedralMesh has no interpolate()';
				continue;

			}

			log( `${name}: ${mode.subject} …` );
			try {

				const { rates, located, tetrahedra, outside } = measure( ours.api as OurApi, points, mode );
				const status = mode.outside ? `${( outside * 100 ).toFixed( 0 )} % of objects outside the hull (first frame)` : `${( located * 100 ).toFixed( 1 )} % located`;
				Object.assign( row, summarize( rates ), { output: `${tetrahedra.toLocaleString( 'en-US' )} tetrahedra`, status } );
				target.met = row.median! >= TARGET;

			} catch ( error ) {

				row.status = 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ];

			}

		}

		// Ours ÷ the grid peer (throughput: above 1, ours is faster).
		const peer = caseRows[ caseRows.length - 1 ];
		for ( const row of caseRows.slice( 0, - 1 ) ) {

			if ( row.median !== null && peer.median !== null ) Object.assign( row, { peer: 'trilinear grid', ratio: row.median / peer.median } );

		}

		rows.push( ...caseRows );

	}

	return rows;

}

/** Per object: a Lissajous path inside the middle 70 % of the probes' bounding box (or reaching beyond it). */
class MovingObjects {

	readonly positions = new Float64Array( OBJECTS * 3 );
	private readonly center = new Float64Array( 3 );
	private readonly amplitude = new Float64Array( 3 );
	private readonly frequency = new Float64Array( OBJECTS * 3 );
	private readonly phase = new Float64Array( OBJECTS * 3 );

	/** @param reach Path amplitude as a fraction of the box: 0.35 stays inside, 0.9 is mostly outside. */
	constructor( probes: ArrayLike<number>, reach = 0.35 ) {

		for ( let axis = 0; axis < 3; axis ++ ) {

			let min = Infinity, max = - Infinity;
			for ( let i = axis; i < probes.length; i += 3 ) {

				min = Math.min( min, probes[ i ] );
				max = Math.max( max, probes[ i ] );

			}

			this.center[ axis ] = ( min + max ) / 2;
			this.amplitude[ axis ] = reach * ( max - min );

		}

		const random = mulberry32( 42 );
		for ( let i = 0; i < OBJECTS * 3; i ++ ) {

			this.frequency[ i ] = 0.5 + random();
			this.phase[ i ] = 2 * Math.PI * random();

		}

	}

	/** Positions at `frame`; consecutive frames are about 0.4 % of the box apart. */
	moveTo( frame: number ): void {

		const time = frame * 0.01;
		for ( let i = 0; i < OBJECTS * 3; i ++ ) {

			const axis = i % 3;
			this.positions[ i ] = this.center[ axis ] + this.amplitude[ axis ] * Math.sin( this.frequency[ i ] * time + this.phase[ i ] );

		}

	}

}

function measure(
	api: OurApi, probes: Float64Array, mode: Mode
): { rates: number[], located: number, tetrahedra: number, outside: number } {

	const mesh = new api.TetrahedralMesh( probes, mode.outside ? { outside: mode.outside } : undefined );
	const probeCount = probes.length / 3;
	const random = mulberry32( 7 );
	const probeSH = new Float32Array( 27 * probeCount ).map( () => random() );
	const objects = new MovingObjects( probes, mode.outside ? 0.9 : 0.35 );
	const state = {
		hints: new Int32Array( OBJECTS ), indices: new Uint32Array( 4 ), weights: new Float32Array( 4 ), out: new Float32Array( 27 ),
		checksum: 0
	};

	// Start every object in its tetrahedron, as a running application would be.
	let frame = 0;
	objects.moveTo( frame ++ );
	let outside = 0;
	for ( let i = 0; i < OBJECTS; i ++ ) {

		if ( mesh.locate(
			objects.positions[ 3 * i ], objects.positions[ 3 * i + 1 ], objects.positions[ 3 * i + 2 ], - 1
		) < 0 ) outside ++;

	}

	queryAll( api, mesh, objects.positions, probeSH, state, mode );

	const rates: number[] = [];
	let queries = 0, located = 0;
	for ( let repeat = 0; repeat < REPEATS; repeat ++ ) {

		let elapsed = 0, count = 0;
		while ( elapsed < MIN_MS ) {

			objects.moveTo( frame ++ );
			const start = performance.now();
			located += queryAll( api, mesh, objects.positions, probeSH, state, mode );
			elapsed += performance.now() - start;
			count += OBJECTS;

		}

		rates.push( count / elapsed / 1000 ); // queries per ms / 1000 = millions per second
		queries += count;

	}

	if ( ! Number.isFinite( state.checksum ) ) throw new Error( 'blendSH produced a non-finite value' );
	return { rates, located: located / queries, tetrahedra: mesh.tetrahedra.length / 4, outside: outside / OBJECTS };

}

/** The grid peer: a trilinear GridInterpolator over the probes' box, same objects, same loop shape. */
function measureGrid( Grid: GridClass, blendSH: OurApi[ 'blendSH' ], probes: Float64Array, counts: number[] ): { rates: number[] } {

	const min = [ Infinity, Infinity, Infinity ], max = [ - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < probes.length; i ++ ) {

		min[ i % 3 ] = Math.min( min[ i % 3 ], probes[ i ] );
		max[ i % 3 ] = Math.max( max[ i % 3 ], probes[ i ] );

	}

	const grid = new Grid( min, max, counts );
	const random = mulberry32( 7 );
	const probeSH = new Float32Array( 27 * grid.positions.length / 3 ).map( () => random() );
	const objects = new MovingObjects( probes );
	const indices = new Uint32Array( 8 ), weights = new Float32Array( 8 ), out = new Float32Array( 27 );
	let frame = 0, checksum = 0;
	const rates: number[] = [];
	for ( let repeat = 0; repeat < REPEATS; repeat ++ ) {

		let elapsed = 0, count = 0;
		while ( elapsed < MIN_MS ) {

			objects.moveTo( frame ++ );
			const positions = objects.positions;
			const start = performance.now();
			for ( let i = 0; i < OBJECTS; i ++ ) {

				grid.interpolate( positions[ 3 * i ], positions[ 3 * i + 1 ], positions[ 3 * i + 2 ], indices, weights );
				blendSH( indices, weights, probeSH, out, 8 );
				checksum += out[ 0 ];

			}

			elapsed += performance.now() - start;
			count += OBJECTS;

		}

		rates.push( count / elapsed / 1000 );

	}

	if ( ! Number.isFinite( checksum ) ) throw new Error( 'grid blendSH produced a non-finite value' );
	return { rates };

}

/** One frame: every object located (and blended); returns how many were inside the mesh. */
function queryAll(
	api: OurApi, mesh: OurTetrahedralMesh, positions: Float64Array, probeSH: Float32Array,
	state: { hints: Int32Array, indices: Uint32Array, weights: Float32Array, out: Float32Array, checksum: number }, mode: Mode
): number {

	const { hints, indices, weights, out } = state;
	const tetrahedra = mesh.tetrahedra;
	const blendSH = api.blendSH;
	const query = mode.query;
	let located = 0, checksum = 0;

	for ( let i = 0; i < OBJECTS; i ++ ) {

		const x = positions[ 3 * i ], y = positions[ 3 * i + 1 ], z = positions[ 3 * i + 2 ];
		const hint = mode.hinted ? hints[ i ] : 0;

		if ( query === 'interpolate' ) {

			// interpolate() answers outside the hull too (outer cells): every query counts.
			hints[ i ] = mesh.interpolate!( x, y, z, indices, weights, hint );
			blendSH( indices, weights, probeSH, out );
			checksum += out[ 0 ];
			located ++;
			continue;

		}

		const t = mesh.locate( x, y, z, hint );
		if ( t < 0 ) continue;

		hints[ i ] = t;
		located ++;
		if ( query === 'locate' ) continue;

		mesh.barycentric( t, x, y, z, weights );
		indices[ 0 ] = tetrahedra[ 4 * t ];
		indices[ 1 ] = tetrahedra[ 4 * t + 1 ];
		indices[ 2 ] = tetrahedra[ 4 * t + 2 ];
		indices[ 3 ] = tetrahedra[ 4 * t + 3 ];
		blendSH( indices, weights, probeSH, out );
		checksum += out[ 0 ];

	}

	state.checksum += checksum;
	return located;

}
