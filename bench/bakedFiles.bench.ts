/**
 * Baked volume files (src/io): encode time, load time (read the file, decode, validate) and size on
 * disk, for the binary format with float16 and float32 SH and for the JSON form, on Sponza's 85
 * probes and on a synthetic 100,000-probe volume. The peer is what loading without stored
 * tetrahedra would cost: tetrahedralizing the positions again. The module is imported dynamically,
 * so the suite still runs (with skipped rows) when src/io is absent or its exports differ.
 */

import { mkdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { mulberry32, randomPoints } from './datasets.js';
import { loadOurs } from './ours.js';
import { timeRuns } from './stats.js';
import type { BenchRow } from './types.js';

export const title = 'Baked files: encode, load and size (ms, KiB; lower is better)';

const BUILD_DIR = fileURLToPath( new URL( './build/', import.meta.url ) );
const SPONZA = fileURLToPath( new URL( '../scenes/sponza.json', import.meta.url ) );
const SYNTHETIC = 100_000;

export const notes = [
	'Sponza: the 85 probe positions, names and roles of scenes/sponza.json, tetrahedralized here; its SH are synthetic (seeded random in [0, 1)), which is fine for sizes and load times (a real bake has the same layout and byte count; float16 rounding does not change the size). Synthetic: 100,000 probes uniformly random in a 100 m cube (seed 5), random SH, no names, role fill.',
	'Encode: encodeBakedVolume (validates, then writes) and for JSON bakedVolumeToJSON + JSON.stringify. Load: readFileSync of the file written to bench/build/ + decodeBakedVolume (full validation, incl. exact orientation of every tetrahedron and symmetric neighbours); JSON: readFileSync + JSON.parse + bakedVolumeFromJSON. "load + mesh": load + TetrahedralMesh.fromTetrahedralization( …, { trusted: true } ) as LightProbeVolumeLoader.parse does through LightProbeVolume.fromBakedData (the interpolator, ready to use; the decoder already validated the tetrahedra), against "new TetrahedralMesh( positions )", which tetrahedralizes again — the ratio is what stored tetrahedra save.',
	'Peer rows: tetrahedralize( positions ) alone and new TetrahedralMesh( positions ) (tetrahedralize + inverse matrices + hull), what a file without tetrahedra costs to load on top of its decoding. Sizes: file bytes (min = max); ratio of float16 and JSON against the float32 binary, of the float32 binary against the peer size: the same float32 file without tetrahedra and neighbours.',
	'Times: median / min / max of several runs after warm-up calls, GC before each (bench/stats.ts timeRuns).',
];

type Precision = 'float16' | 'float32';

interface Io {
	encodeBakedVolume( data: unknown, options?: { precision?: Precision } ): ArrayBuffer;
	decodeBakedVolume( buffer: ArrayBuffer | ArrayBufferView ): { positions: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array };
	bakedVolumeToJSON( data: unknown ): unknown;
	bakedVolumeFromJSON( json: unknown ): { positions: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array };
}

interface Mesh { tetrahedra: Uint32Array, neighbors: Int32Array }
interface MeshClass {
	new ( positions: ArrayLike<number> ): Mesh;
	fromTetrahedralization?(
		positions: ArrayLike<number>, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number>, options?: { trusted?: boolean }
	): Mesh;
}

/** Loads src/io; null with the reason when it is absent or lacks a function this bench calls. */
async function loadIo(): Promise<{ io: Io | null, reason: string }> {

	let module: Record<string, unknown>;
	try {

		module = await import( new URL( '../src/io/index.js', import.meta.url ).href ) as Record<string, unknown>;

	} catch ( error ) {

		return { io: null, reason: `skipped: src/io not available (${( error as Error ).message.split( '\n' )[ 0 ]})` };

	}

	const names = [ 'encodeBakedVolume', 'decodeBakedVolume', 'bakedVolumeToJSON', 'bakedVolumeFromJSON' ];
	const missing = names.filter( ( name ) => typeof module[ name ] !== 'function' );
	return missing.length ? { io: null, reason: `skipped: src/io does not export ${missing.join( ', ' )}` } : { io: module as unknown as Io, reason: '' };

}

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const { io, reason } = await loadIo();
	const ours = await loadOurs();
	const TetrahedralMesh = ( ours.api as { TetrahedralMesh?: MeshClass } ).TetrahedralMesh
		?? ( await import( '../src/interpolation/TetrahedralMesh.js' ) ).TetrahedralMesh as unknown as MeshClass;
	const tetrahedralize = ours.api.tetrahedralize ?? ( await import( '../src/tetrahedra/tetrahedralize.js' ) ).tetrahedralize;

	const sponza = JSON.parse( readFileSync( SPONZA, 'utf8' ) ) as { positions: number[], names?: string[], roles?: string[] };
	const volumes = [
		{ name: `Sponza, ${sponza.positions.length / 3} probes`, file: 'sponza', positions: Float64Array.from( sponza.positions ), names: sponza.names, roles: sponza.roles, runs: 15 },
		{ name: `synthetic, ${SYNTHETIC.toLocaleString( 'en-US' )} probes`, file: 'synthetic-100k', positions: randomPoints( 'probes', SYNTHETIC, 5 ).points.map( ( v ) => 100 * v ), names: undefined, roles: undefined, runs: 5 },
	];

	const rows: BenchRow[] = [];
	mkdirSync( BUILD_DIR, { recursive: true } );

	for ( const volume of volumes ) {

		const { name: caseName, positions } = volume;
		const probes = positions.length / 3;
		const ms = ( subject: string ): BenchRow => ( { case: caseName, subject, unit: 'ms', median: null, min: null, max: null, runs: 0 } );
		const timed = <T>( row: BenchRow, fn: () => T, budgetMs = 6000 ): T | null => {

			try {

				const { summary, result } = timeRuns( fn, volume.runs, budgetMs );
				Object.assign( row, summary );
				return result;

			} catch ( error ) {

				row.status = 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ];
				return null;

			}

		};

		// The peers first: they also give the tetrahedra to store.
		log( `${caseName}: re-tetrahedralizing (peer) …` );
		const peerTetrahedralize = ms( 'peer: tetrahedralize( positions ), no stored tets' );
		timed( peerTetrahedralize, () => tetrahedralize( positions ) );
		const peerMesh = ms( 'peer: new TetrahedralMesh( positions )' );
		const mesh = timed( peerMesh, () => new TetrahedralMesh( positions ) );
		if ( ! mesh ) {

			rows.push( peerTetrahedralize, peerMesh );
			continue;

		}

		const tetrahedra = mesh.tetrahedra.length / 4;
		peerMesh.output = peerTetrahedralize.output = `${tetrahedra.toLocaleString( 'en-US' )} tetrahedra`;
		if ( ! io ) {

			rows.push( { ...ms( 'ours: baked files' ), status: reason }, peerTetrahedralize, peerMesh );
			continue;

		}

		const random = mulberry32( 9 );
		const sh = new Float32Array( 27 * probes ).map( () => random() );
		const data = { positions, sh, tetrahedra: mesh.tetrahedra, neighbors: mesh.neighbors, names: volume.names, roles: volume.roles, capture: { resolution: 32, near: 0.05, far: 100, type: 'half' } };

		const encodeRows: BenchRow[] = [], loadRows: BenchRow[] = [], sizeRows: BenchRow[] = [];
		const sizes: Record<string, number> = {};
		const written: string[] = [];
		for ( const format of [ 'float16', 'float32', 'json' ] as const ) {

			const label = format === 'json' ? 'JSON' : `binary ${format}`;
			const path = `${BUILD_DIR}baked-${volume.file}-${format}.${format === 'json' ? 'json' : 'bin'}`;
			written.push( path );
			log( `${caseName}: ${label} …` );

			const encode = ms( `ours: encode, ${label}` );
			encodeRows.push( encode );
			const encoded = timed<string | ArrayBuffer>( encode, format === 'json'
				? () => JSON.stringify( io.bakedVolumeToJSON( data ) )
				: () => io.encodeBakedVolume( data, { precision: format } ), 10_000 );
			if ( encoded === null ) continue;
			writeFileSync( path, typeof encoded === 'string' ? encoded : new Uint8Array( encoded ) );
			sizes[ format ] = statSync( path ).size;

			const load = ms( `ours: load, ${label} (read + decode + validate)` );
			loadRows.push( load );
			const decoded = timed( load, format === 'json'
				? () => io.bakedVolumeFromJSON( JSON.parse( readFileSync( path, 'utf8' ) ) )
				: () => io.decodeBakedVolume( readFileSync( path ) ), 10_000 );
			if ( decoded === null ) continue;
			const same = decoded.tetrahedra.length === mesh.tetrahedra.length &&
				decoded.tetrahedra.every( ( v, i ) => v === mesh.tetrahedra[ i ] );
			load.status = same ? `${( decoded.tetrahedra.length / 4 ).toLocaleString( 'en-US' )} tetrahedra read back` : 'MISMATCH: tetrahedra differ from those written';

			if ( format === 'float32' && typeof TetrahedralMesh.fromTetrahedralization === 'function' ) {

				const fromStored = TetrahedralMesh.fromTetrahedralization.bind( TetrahedralMesh );
				const loadMesh = ms( 'ours: load float32 + TetrahedralMesh.fromTetrahedralization' );
				loadRows.push( loadMesh );
				timed( loadMesh, () => {

					const d = io.decodeBakedVolume( readFileSync( path ) );
					// The runtime's path: the decoder validated the tetrahedra, so the mesh trusts them (issue 11).
					return fromStored( d.positions, d.tetrahedra, d.neighbors, { trusted: true } );

				}, 10_000 );
				if ( loadMesh.median !== null && peerMesh.median !== null ) Object.assign( loadMesh, { peer: 'new TetrahedralMesh( positions )', ratio: loadMesh.median / peerMesh.median } );

			}

			const bytes = sizes[ format ];
			sizeRows.push( { case: caseName, subject: `ours: size, ${label}`, unit: 'KiB', median: bytes / 1024, min: bytes / 1024, max: bytes / 1024, runs: 1, output: `${bytes.toLocaleString( 'en-US' )} B, ${( bytes / probes ).toFixed( 1 )} B/probe` } );

		}

		// Ours ÷ the re-tetrahedralizing peer, for every load; sizes ÷ the float32 file.
		for ( const row of loadRows ) {

			if ( row.median !== null && peerTetrahedralize.median !== null && row.peer === undefined ) Object.assign( row, { peer: 'tetrahedralize( positions )', ratio: row.median / peerTetrahedralize.median } );

		}

		let bare = 0;
		try {

			bare = io.encodeBakedVolume( { positions, sh, names: volume.names, roles: volume.roles }, { precision: 'float32' } ).byteLength;
			sizeRows.push( { case: caseName, subject: 'peer: size, float32 binary without tetrahedra', unit: 'KiB', median: bare / 1024, min: bare / 1024, max: bare / 1024, runs: 1, output: `${bare.toLocaleString( 'en-US' )} B, ${( bare / probes ).toFixed( 1 )} B/probe` } );

		} catch ( error ) {

			sizeRows.push( { case: caseName, subject: 'peer: size, float32 binary without tetrahedra', unit: 'KiB', median: null, min: null, max: null, runs: 0, status: 'threw: ' + ( error as Error ).message.split( '\n' )[ 0 ] } );

		}

		// float16 and JSON ÷ the float32 file; the float32 file ÷ the same without tetrahedra.
		for ( const row of sizeRows ) {

			if ( row.median === null || row.subject.startsWith( 'peer' ) ) continue;
			if ( row.subject.endsWith( 'float32' ) ) {

				if ( bare ) Object.assign( row, { peer: 'file without tetrahedra', ratio: row.median * 1024 / bare } );

			} else if ( sizes.float32 ) {

				Object.assign( row, { peer: 'float32 binary', ratio: row.median * 1024 / sizes.float32 } );

			}

		}

		// The 100k-probe files add up to 150 MB: measured, they go.
		for ( const path of written ) rmSync( path, { force: true } );
		rows.push( ...loadRows, peerTetrahedralize, peerMesh, ...encodeRows, ...sizeRows );

	}

	return rows;

}

