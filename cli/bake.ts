import { existsSync, statSync, writeFileSync } from 'node:fs';
import { basename, dirname, resolve } from 'node:path';
import type { BakeOptions } from './args.js';
import { captureInBrowser } from './capture.js';
import { encodeVolume, type VolumeData } from './codec.js';
import { CliError } from './errors.js';
import { checkVolumeInput, readLayout, tetrahedralizeLayout } from './layout.js';
import { ProgressBar } from './progress.js';
import { checkScene } from './sceneChecks.js';
import { formatBytes, formatDuration, formatTable } from './table.js';

/** What {@link bake} did, for its summary and for tests. */
export interface BakeSummary {

	probes: number;
	tetrahedra: number;
	captureMs: number;
	totalMs: number;
	bytes: number;
	out: string;
	resolution: number;

}

/**
 * `capture-lighting bake`: checks every input (scene, layout, sky, output folder) before starting a
 * browser, tetrahedralizes the layout, captures SH9 at each probe in headless Chromium, and writes
 * the baked volume.
 * @param options Parsed by `parseArguments`.
 * @param log Where the summary goes (stdout); the progress bar goes to stderr.
 * @throws {CliError} exit code 2 for bad input, 1 for a failure during the capture or the write.
 */
export async function bake( options: BakeOptions, log: ( text: string ) => void = ( text ) => process.stdout.write( text + '\n' ) ): Promise<BakeSummary> {

	const start = performance.now();
	const { kind, files } = checkScene( options.scene );
	if ( resolve( options.out ) === resolve( options.probes ) ) throw new CliError( `--out ${options.out} is the probe layout; choose another name.` );
	if ( files.includes( resolve( options.out ) ) ) throw new CliError( `--out ${options.out} would overwrite a file of the scene ${options.scene}; choose another name.` );
	let skyFile: string | null = null;
	if ( options.sky && 'hdr' in options.sky ) {

		skyFile = options.sky.hdr;
		if ( ! existsSync( skyFile ) || ! statSync( skyFile ).isFile() ) throw new CliError( `--sky: the panorama ${skyFile} was not found.` );

	}

	const outFolder = dirname( resolve( options.out ) );
	if ( ! existsSync( outFolder ) || ! statSync( outFolder ).isDirectory() ) throw new CliError( `--out: the folder ${outFolder} of ${options.out} does not exist.` );
	if ( existsSync( options.out ) && statSync( options.out ).isDirectory() ) throw new CliError( `--out: ${options.out} is a folder; give a file name.` );

	const layout = readLayout( options.probes );
	const tetrahedralization = tetrahedralizeLayout( options.probes, layout );
	checkVolumeInput( options.probes, layout, tetrahedralization );
	const { tetrahedra, neighbors } = tetrahedralization;
	const count = layout.positions.length / 3;

	const bar = new ProgressBar( process.stderr, { quiet: options.quiet } );
	let stage = '';
	const result = await captureInBrowser( {
		kind,
		positions: Array.from( layout.positions ),
		resolution: options.resolution,
		near: options.near,
		far: options.far,
		sky: options.sky && 'color' in options.sky ? options.sky : null,
		sun: options.sun,
		ambient: options.ambient,
	}, {
		scene: options.scene,
		skyFile,
		browser: options.browser,
		onProgress( name, done, total ) {

			if ( name !== stage ) {

				stage = name;
				bar.start( name === 'capturing' ? `capturing ${total} probes at ${options.resolution}²` : `${name} ${options.scene}` );

			}

			bar.update( done, total );

		},
	} );
	bar.finish();

	if ( result.info.triangles === 0 && options.sky === null ) {

		throw new CliError( `scene ${options.scene} has no triangles (${result.info.meshes} meshes) and no --sky is given: nothing to capture; expected a glTF/GLB or OBJ file with geometry.` );

	}

	if ( result.info.nonFiniteVertices > 0 ) {

		throw new CliError( `scene ${options.scene} has ${result.info.nonFiniteVertices} vertices with a NaN or infinite coordinate; every vertex position must be finite.` );

	}

	const bytes = Buffer.from( result.sh, 'base64' );
	const sh = new Float32Array( bytes.buffer.slice( bytes.byteOffset, bytes.byteOffset + bytes.byteLength ) );
	if ( sh.length !== 27 * count ) throw new CliError( `the page returned ${sh.length} SH floats for ${count} probes.`, 1 );

	const data: VolumeData = {
		positions: layout.positions,
		sh,
		tetrahedra,
		neighbors,
		names: layout.names,
		roles: layout.roles,
		zones: layout.zones,
		capture: { resolution: options.resolution, near: options.near, far: options.far, type: 'half', solidAngle: 'exact' },
		// What the format has no field for, for people reading the file later.
		metadata: JSON.stringify( {
			tool: 'capture-lighting bake',
			scene: basename( options.scene ),
			layout: layout.name || basename( options.probes ),
			sky: options.sky ? ( 'color' in options.sky ? '#' + options.sky.color.map( ( c ) => Math.round( c * 255 ).toString( 16 ).padStart( 2, '0' ) ).join( '' ) : basename( options.sky.hdr ) ) : 'black',
			sun: options.sun ? [ ...options.sun.direction, options.sun.intensity ] : null,
			ambient: options.ambient,
			renderer: result.info.renderer,
			date: new Date().toISOString(),
		} ),
	};

	let encoded: Uint8Array;
	try {

		encoded = encodeVolume( data, options.format, options.precision );

	} catch ( error ) {

		const overflow = ( error as { code?: string } ).code === 'float16-overflow';
		throw new CliError( `cannot encode the volume for ${options.out}: ${( error as Error ).message}${overflow ? ' Bake again with --precision float32.' : ''}`, 1 );

	}

	try {

		writeFileSync( options.out, encoded );

	} catch ( error ) {

		throw new CliError( `cannot write ${options.out}: ${( error as Error ).message}`, 1 );

	}

	const summary: BakeSummary = {
		probes: count,
		tetrahedra: tetrahedra.length / 4,
		captureMs: result.captureMs,
		totalMs: performance.now() - start,
		bytes: statSync( options.out ).size,
		out: options.out,
		resolution: options.resolution,
	};

	if ( ! options.quiet ) {

		log( formatTable( [
			[ 'output', `${summary.out} (${options.format}${options.format === 'bin' ? `, SH ${options.precision}` : ''})` ],
			[ 'probes', String( summary.probes ) ],
			[ 'tetrahedra', String( summary.tetrahedra ) ],
			[ 'resolution', `${summary.resolution}² per cube face` ],
			[ 'scene', `${options.scene} (${result.info.meshes} meshes, ${result.info.triangles.toLocaleString( 'en-US' )} triangles, ${result.info.lights} lights${result.info.shadows ? ', shadows' : ''}; loaded in ${formatDuration( result.loadMs )})` ],
			[ 'capture time', `${formatDuration( summary.captureMs )} (${formatDuration( summary.captureMs / count )} per probe; ${result.info.renderer})` ],
			[ 'total time', formatDuration( summary.totalMs ) ],
			[ 'size on disk', formatBytes( summary.bytes ) ],
		] ) );

	}

	return summary;

}
