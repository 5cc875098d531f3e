/**
 * Memory of a 100,000-probe volume: bytes per probe and per tetrahedron held in the typed arrays
 * of a LightProbeVolume (its positions and SH, its TetrahedralMesh's tetrahedra, neighbors,
 * inverse matrices and hull arrays), and the growth of the JS heap and ArrayBuffer memory while
 * building one, beside the same probes held as THREE.LightProbe objects. Each measurement runs in
 * a fresh `node --expose-gc` child process (memoryWorker.ts), a full GC before and after.
 */

import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { summarize } from './stats.js';
import type { BenchRow } from './types.js';

export const title = 'Memory of a 100,000-probe volume (bytes, lower is better)';

const COUNT = 100_000;
const RUNS = 3;
const WORKER = fileURLToPath( new URL( './memoryWorker.ts', import.meta.url ) );
const IO = fileURLToPath( new URL( '../src/io/index.ts', import.meta.url ) );

export const notes = [
	`Probes: ${COUNT.toLocaleString( 'en-US' )} uniformly random in a 100 m cube (seed 5), random SH. Each figure: median / min / max of ${RUNS} fresh child processes (node --expose-gc), two full GCs before and after the build; inputs are made before the first measurement and kept alive.`,
	'Typed arrays (B/probe, B/tetrahedron): sums of byteLength — deterministic, so min = max. Per probe: positions (Float64 ×3) + SH (Float32 ×27) of the volume; per tetrahedron: tetrahedra (Uint32 ×4) + neighbors (Int32 ×4) + inverseMatrices (Float64 ×9); the mesh also keeps its own Float64 copy of the positions and the hull arrays, counted in "all typed arrays".',
	'Growth (MiB): heapUsed + arrayBuffers after − before (typed arrays\' backing stores are outside heapUsed, so both are added; heap alone in Output). Peer: the same probes as 100,000 THREE.LightProbe objects (Object3D + SphericalHarmonics3 each, positioned), no tetrahedralization — three\'s own way to hold probes. "loaded from a baked file": decodeBakedVolume of a float32 file of the same volume already in memory + TetrahedralMesh.fromTetrahedralization + LightProbeVolume with that interpolator (src/io, when present); the file\'s bytes are in memory before the first measurement, and the decoded tetrahedra and neighbours stay views of them, so the growth leaves out the file itself (34.8 MB at 100k probes, see the baked-files bench) but includes everything built from it.',
	'Build time of each child is in Output; it is not a timing benchmark (see the tetrahedralization bench).',
];

interface WorkerResult { count: number; ms: number; arrays: Record<string, number>; heapUsed: number; arrayBuffers: number; rss: number }

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const rows: BenchRow[] = [];
	const MiB = 2 ** 20;

	const measured: Record<string, WorkerResult[] | string> = {};
	const modes = [ 'volume', 'mesh', 'three', ...( existsSync( IO ) ? [ 'loaded' ] : [] ) ];
	for ( const mode of modes ) {

		log( `${mode}: ${RUNS} child processes …` );
		const results: WorkerResult[] = [];
		try {

			for ( let r = 0; r < RUNS; r ++ ) results.push( await runWorker( mode ) );
			measured[ mode ] = results;

		} catch ( error ) {

			measured[ mode ] = ( error as Error ).message.split( '\n' )[ 0 ];

		}

	}

	const caseName = `${COUNT.toLocaleString( 'en-US' )} random probes`;
	const volume = measured.volume;
	if ( typeof volume === 'string' ) {

		rows.push( { case: caseName, subject: 'LightProbeVolume', unit: 'B', median: null, min: null, max: null, runs: 0, status: 'failed: ' + volume } );

	} else {

		const a = volume[ 0 ].arrays;
		const tetrahedra = a.tetrahedronCount;
		const perProbe = ( a.positions + a.sh ) / COUNT;
		const perTetrahedron = ( a.tetrahedra + a.neighbors + a.inverseMatrices ) / tetrahedra;
		const allArrays = a.positions + a.sh + a[ 'mesh.positions' ] + a.tetrahedra + a.neighbors + a.inverseMatrices + a.hullFaces + a.hullFaceTetrahedra + a.duplicates;
		const fixed = ( subject: string, value: number, output: string, extra: Partial<BenchRow> = {} ): BenchRow => ( { case: caseName, subject, unit: 'B', median: value, min: value, max: value, runs: volume.length, output, ...extra } );
		rows.push(
			fixed( 'ours: typed arrays per probe (positions + SH)', perProbe, `${a.positions / COUNT} + ${a.sh / COUNT} B` ),
			fixed( 'ours: typed arrays per tetrahedron (tets + neighbors + inverses)', perTetrahedron, `${tetrahedra.toLocaleString( 'en-US' )} tetrahedra, ${( tetrahedra / COUNT ).toFixed( 2 )} per probe` ),
			fixed( 'ours: all typed arrays ÷ probes', allArrays / COUNT, `${( allArrays / MiB ).toFixed( 1 )} MiB; hull ${a.hullFaceCount} faces` ),
		);

	}

	const growth = ( mode: string, subject: string ): BenchRow => {

		const results = measured[ mode ];
		const row: BenchRow = { case: caseName, subject, unit: 'MiB', median: null, min: null, max: null, runs: 0 };
		if ( results === undefined ) return { ...row, status: 'skipped: src/io not present' };
		if ( typeof results === 'string' ) return { ...row, status: 'failed: ' + results };
		const summary = summarize( results.map( ( r ) => ( r.heapUsed + r.arrayBuffers ) / MiB ) );
		const heap = summarize( results.map( ( r ) => r.heapUsed / MiB ) ).median;
		const rss = summarize( results.map( ( r ) => r.rss / MiB ) ).median;
		const ms = summarize( results.map( ( r ) => r.ms ) ).median;
		return { ...row, ...summary, output: `heap ${heap.toFixed( 1 )} MiB, RSS +${rss.toFixed( 0 )} MiB; ${( summary.median * MiB / COUNT ).toFixed( 0 )} B/probe; built in ${ms.toFixed( 0 )} ms` };

	};

	const three = growth( 'three', 'three: 100,000 THREE.LightProbe objects, growth' );
	const oursGrowth = [
		growth( 'volume', 'ours: LightProbeVolume, growth (heap + ArrayBuffers)' ),
		growth( 'mesh', 'ours: TetrahedralMesh alone, growth' ),
		...( existsSync( IO ) ? [ growth( 'loaded', 'ours: LightProbeVolume loaded from a baked file, growth' ) ] : [] ),
	];
	for ( const row of oursGrowth ) {

		if ( row.median !== null && three.median !== null ) Object.assign( row, { peer: 'THREE.LightProbe ×100k', ratio: row.median / three.median } );

	}

	// Bytes per probe beside three's: its objects hold no tetrahedra, so this is all it keeps.
	if ( three.median !== null ) {

		const threePerProbe = three.median * MiB / COUNT;
		for ( const row of rows ) {

			if ( row.median !== null && row.subject.includes( 'probe' ) && row.unit === 'B' ) Object.assign( row, { peer: `THREE.LightProbe (${threePerProbe.toFixed( 0 )} B/probe)`, ratio: row.median / threePerProbe } );

		}

	}

	rows.push( ...oursGrowth, three );
	return rows;

}

function runWorker( mode: string ): Promise<WorkerResult> {

	return new Promise( ( resolve, reject ) => {

		const child = spawn( process.execPath, [ '--expose-gc', '--import', 'tsx', WORKER, mode, String( COUNT ) ], { stdio: [ 'ignore', 'pipe', 'pipe' ] } );
		let stdout = '', stderr = '';
		child.stdout.on( 'data', ( chunk ) => stdout += chunk );
		child.stderr.on( 'data', ( chunk ) => stderr += chunk );
		const timer = setTimeout( () => child.kill( 'SIGKILL' ), 120_000 );
		child.on( 'close', ( code ) => {

			clearTimeout( timer );
			if ( code === 0 ) resolve( JSON.parse( stdout ) as WorkerResult );
			else reject( new Error( stderr.trim().split( '\n' ).find( ( line ) => /Error/.test( line ) ) ?? `exit ${code}` ) );

		} );

	} );

}
