/**
 * Child process of memory.bench.ts, run as `node --expose-gc --import tsx memoryWorker.ts MODE COUNT`
 * so that each measurement starts from a fresh heap. Builds one probe structure of COUNT random
 * probes and prints JSON: the growth of the JS heap (heapUsed), of ArrayBuffer memory (typed
 * arrays' backing stores, outside heapUsed) and of the RSS between a full GC before and after,
 * the build time, and for our volume the byteLength of each of its typed arrays.
 *
 * MODE: `volume` (LightProbeVolume from positions + SH: what an application holds after loading
 * positions and SH and tetrahedralizing), `mesh` (the TetrahedralMesh alone), `three` (the same
 * probes as THREE.LightProbe objects, three's own way of holding probes), `loaded` (a LightProbeVolume
 * loaded from a baked float32 file held in memory: decodeBakedVolume + TetrahedralMesh.fromTetrahedralization,
 * when src/io exists; the file's bytes are made before the first measurement).
 */

import { mulberry32 } from '../src/tetrahedra/spatialOrder.js';

const gc = ( globalThis as { gc?: () => void } ).gc;
if ( ! gc ) throw new Error( 'memoryWorker: run node with --expose-gc' );

const mode = process.argv[ 2 ];
const count = Number( process.argv[ 3 ] ?? 100_000 );

const random = mulberry32( 5 );
const positions = new Float64Array( 3 * count );
for ( let i = 0; i < positions.length; i ++ ) positions[ i ] = 100 * random();
const sh = new Float32Array( 27 * count );
for ( let i = 0; i < sh.length; i ++ ) sh[ i ] = random();
// The inputs stay alive to the end, or V8 may collect them during a build that no longer reads
// them and the growth would come out 13 MB too small.
( globalThis as { inputs?: unknown } ).inputs = { positions, sh };

// Everything the build needs is imported and its input made before the first measurement.
const { LightProbeVolume } = await import( '../src/runtime/LightProbeVolume.js' );
const { TetrahedralMesh } = await import( '../src/interpolation/TetrahedralMesh.js' );
const { LightProbe, SphericalHarmonics3, Vector3 } = await import( 'three' );
let encoded: Uint8Array | null = null;
let io: typeof import( '../src/io/index.js' ) | null = null;
if ( mode === 'loaded' ) {

	// The file is made (and read into memory, as from disk) before the first measurement.
	io = await import( '../src/io/index.js' );
	const build = new TetrahedralMesh( positions );
	encoded = new Uint8Array( io!.encodeBakedVolume( { positions, sh, tetrahedra: build.tetrahedra, neighbors: build.neighbors }, { precision: 'float32' } ) );

}

function measure() {

	gc!(); gc!();
	const usage = process.memoryUsage();
	return { heapUsed: usage.heapUsed, arrayBuffers: usage.arrayBuffers, rss: usage.rss };

}

const before = measure();
const start = performance.now();
let kept: unknown;
const arrays: Record<string, number> = {};

if ( mode === 'volume' || mode === 'mesh' ) {

	const volume = mode === 'volume' ? new LightProbeVolume( { positions, sh } ) : null;
	const mesh = ( volume ? volume.interpolator : new TetrahedralMesh( positions ) ) as InstanceType<typeof TetrahedralMesh>;
	kept = volume ?? mesh;
	if ( volume ) Object.assign( arrays, { positions: volume.positions.byteLength, sh: volume.sh.byteLength } );
	Object.assign( arrays, {
		'mesh.positions': mesh.positions.byteLength, tetrahedra: mesh.tetrahedra.byteLength, neighbors: mesh.neighbors.byteLength,
		inverseMatrices: mesh.inverseMatrices.byteLength, hullFaces: mesh.hullFaces.byteLength,
		hullFaceTetrahedra: mesh.hullFaceTetrahedra.byteLength,
		duplicates: mesh.duplicates.byteLength,
	} );
	arrays.tetrahedronCount = mesh.tetrahedra.length / 4;
	arrays.hullFaceCount = mesh.hullFaces.length / 3;

} else if ( mode === 'three' ) {

	const probes = [];
	const coefficients = new SphericalHarmonics3();
	for ( let i = 0; i < count; i ++ ) {

		for ( let k = 0; k < 9; k ++ ) coefficients.coefficients[ k ].fromArray( sh, 27 * i + 3 * k );
		const probe = new LightProbe( coefficients );
		probe.position.copy( new Vector3().fromArray( positions, 3 * i ) );
		probes.push( probe );

	}

	kept = probes;

} else if ( mode === 'loaded' ) {

	// A volume loaded from a baked file: decode (tetrahedra and neighbours stay views of the
	// file's buffer), the stored tetrahedralization as the interpolator, no tetrahedralizing.
	const data = io!.decodeBakedVolume( encoded! );
	const mesh = TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, data.neighbors, { trusted: true } );
	const volume = new LightProbeVolume( { positions: data.positions, sh: data.sh, interpolator: mesh } );
	kept = volume;
	Object.assign( arrays, {
		positions: volume.positions.byteLength, sh: volume.sh.byteLength, file: encoded!.byteLength,
		'mesh.positions': mesh.positions.byteLength, tetrahedra: mesh.tetrahedra.byteLength, neighbors: mesh.neighbors.byteLength,
		inverseMatrices: mesh.inverseMatrices.byteLength, hullFaces: mesh.hullFaces.byteLength,
		hullFaceTetrahedra: mesh.hullFaceTetrahedra.byteLength,
		duplicates: mesh.duplicates.byteLength,
	} );
	arrays.tetrahedronCount = mesh.tetrahedra.length / 4;
	arrays.hullFaceCount = mesh.hullFaces.length / 3;

} else {

	throw new Error( `memoryWorker: unknown mode ${mode}` );

}

const ms = performance.now() - start;
const after = measure();
process.stdout.write( JSON.stringify( {
	count, ms, arrays,
	heapUsed: after.heapUsed - before.heapUsed,
	arrayBuffers: after.arrayBuffers - before.arrayBuffers,
	rss: after.rss - before.rss,
	kept: kept !== undefined,
} ) + '\n' );
