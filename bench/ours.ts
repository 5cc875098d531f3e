/**
 * Loads the library under test. The import is dynamic so the benchmarks still run (reporting ours
 * as skipped) while src/ is incomplete; BENCH_OURS=path/to/module.ts benchmarks another build
 * of the same API instead (an older checkout, or a stub while src/ is being written).
 */

import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

export interface Tetrahedralization {
	/** 4 vertex indices per tetrahedron, positively oriented. */
	tetrahedra: Uint32Array;
	/** neighbors[ 4t + i ]: the tetrahedron opposite vertex i of t, or −1. */
	neighbors: Int32Array;
	duplicates: Uint32Array;
}

export interface OurTetrahedralMesh {
	tetrahedra: Uint32Array;
	/** The tetrahedron containing (x, y, z), walking from `hint`; −1 when outside. */
	locate( x: number, y: number, z: number, hint: number ): number;
	/** Writes the 4 barycentric weights of (x, y, z) in tetrahedron t. */
	barycentric( t: number, x: number, y: number, z: number, out: Float32Array ): unknown;
	/** Optional: probes and weights for (x, y, z), returning the tetrahedron to pass back as hint. */
	interpolate?( x: number, y: number, z: number, indices: Uint32Array, weights: Float32Array, hint: number ): number;
}

export interface OurApi {
	tetrahedralize( points: ArrayLike<number> ): Tetrahedralization;
	TetrahedralMesh: new ( positions: ArrayLike<number>, options?: { outside?: 'outerCells' | 'nearestFace' } ) => OurTetrahedralMesh;
	blendSH( indices: ArrayLike<number>, weights: ArrayLike<number>, probeSH: Float32Array, out: Float32Array, count?: number ): unknown;
}

export interface Loaded {
	/** Whatever the module exports (parts of the API may not be written yet). */
	api: Partial<OurApi>;
	/** `'src/index.ts + src/math.ts'`, or the BENCH_OURS override. */
	source: string;
	/** Why the module could not be loaded at all. */
	error?: string;
}

let loading: Promise<Loaded> | null = null;

export function loadOurs(): Promise<Loaded> {

	loading ??= load();
	return loading;

}

/** Null when the loaded module exports every function in `names`, else why a bench must skip ours. */
export function whyMissing( loaded: Loaded, names: ( keyof OurApi )[] ): string | null {

	if ( loaded.error ) return loaded.error;
	const missing = names.filter( ( name ) => typeof loaded.api[ name ] !== 'function' );
	return missing.length ? `not available: ${loaded.source} does not export ${missing.join( ', ' )}` : null;

}

async function load(): Promise<Loaded> {

	const override = process.env.BENCH_OURS;
	// The package's main entry and its pure /math entry (the interpolators and tetrahedralize live there).
	const urls = override
		? [ pathToFileURL( resolve( override ) ).href ]
		: [ new URL( '../src/index.js', import.meta.url ).href, new URL( '../src/math.js', import.meta.url ).href ];
	const source = override ? `BENCH_OURS=${override}` : 'src/index.ts + src/math.ts';
	try {

		const modules = await Promise.all( urls.map( ( url ) => import( url ) ) );
		return { api: Object.assign( {}, ...modules ) as Partial<OurApi>, source };

	} catch ( error ) {

		return { api: {}, source, error: `not available: ${source} failed to load (${( error as Error ).message.split( '\n' )[ 0 ]})` };

	}

}
