import { existsSync, statSync, writeFileSync } from 'node:fs';
import { basename, dirname, resolve } from 'node:path';
import type { BakeOptions } from './args.js';
import type { BakeResult } from './bakePage/protocol.js';
import { describeLights, describePostProcessing, describeShadows, describeSky } from './bakeSummary.js';
import { bakeWarnings } from './bakeWarnings.js';
import { captureInBrowser } from './capture.js';
import { encodeVolume, type VolumeData } from './codec.js';
import { CliError } from './errors.js';
import { checkVolumeInput, readLayout, tetrahedralizeLayout } from './layout.js';
import { parseLayoutLights } from './layoutLights.js';
import { layoutShape } from './layoutShape.js';
import { ProgressBar } from './progress.js';
import { checkScene } from './sceneChecks.js';
import { formatShStatistics, shStatistics } from './shStatistics.js';
import { formatBytes, formatDuration, formatTable } from './table.js';
import { makeIrradianceNonNegative, windowSH } from '../src/sh/windowSH.js';

/** What {@link bake} did, for its summary and for tests. */
export interface BakeSummary {

	probes: number;
	/** Tetrahedra stored; 0 for a planar or collinear layout (stored without them). */
	tetrahedra: number;
	captureMs: number;
	totalMs: number;
	bytes: number;
	out: string;
	resolution: number;
	/** The `warning: …` texts printed (without the prefix). */
	warnings: string[];

}

/** Where {@link bake} writes: the summary (stdout) and the warnings (stderr). */
export interface BakeOutput {

	log?: ( text: string ) => void;
	warn?: ( text: string ) => void;

}

/**
 * `capture-lighting bake`: checks every input (scene, layout and its lights, sky, output folder)
 * before starting a browser, tetrahedralizes the layout, captures SH9 at each probe in headless
 * Chromium, applies `--deringing` / `--non-negative` as `LightProbeVolume.capture` does, prints the
 * warnings, and writes the baked volume.
 * @param options Parsed by `parseArguments`.
 * @param output Where the summary and the warnings go; the progress bar goes to stderr.
 * @throws {CliError} exit code 2 for bad input, 1 for a failure during the capture or the write, or
 * for a warning under `--strict` (nothing written then).
 */
export async function bake( options: BakeOptions, output: BakeOutput = {} ): Promise<BakeSummary> {

	const {
		log = ( text: string ) => process.stdout.write( text + '\n' ),
		warn = ( text: string ) => process.stderr.write( text + '\n' ),
	} = output;
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
	const layoutLights = parseLayoutLights( options.probes, layout.lights );
	const tetrahedralization = tetrahedralizeLayout( options.probes, layout );
	checkVolumeInput( options.probes, layout, tetrahedralization );
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
		lights: [ ...options.lights, ...layoutLights ],
		ambient: options.ambient,
		prepare: options.prepare,
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

	const sh = capturedSH( options, result, count );
	// As LightProbeVolume.capture (runtime/captureProbes.ts) treats each captured probe.
	let raised = 0;
	if ( options.nonNegative ) raised = makeIrradianceNonNegative( sh, options.deringing );
	else if ( options.deringing > 0 ) windowSH( sh, options.deringing, sh );

	const stats = shStatistics( sh, count );
	const warnings = bakeWarnings( stats, {
		lights: result.info.lights.length + ( options.sky ? 1 : 0 ),
		emissive: result.info.emissiveMaterials + result.info.unlitMaterials,
	} );
	for ( const warning of warnings ) warn( `warning: ${warning}` );
	if ( options.strict && warnings.length > 0 ) {

		throw new CliError( `${warnings.length} warning${warnings.length === 1 ? '' : 's'} (see above) and --strict was given; ${options.out} was not written.`, 1 );

	}

	const data: VolumeData = {
		positions: layout.positions,
		sh,
		tetrahedra: tetrahedralization?.tetrahedra ?? null,
		neighbors: tetrahedralization?.neighbors ?? null,
		names: layout.names,
		roles: layout.roles,
		zones: layout.zones,
		capture: { resolution: options.resolution, near: options.near, far: options.far, type: 'half', solidAngle: 'exact' },
		// What the format has no field for, for people reading the file later.
		metadata: JSON.stringify( {
			tool: 'capture-lighting bake',
			scene: basename( options.scene ),
			layout: layout.name || basename( options.probes ),
			sky: describeSky( options.sky, basename ),
			lights: [ ...options.lights, ...layoutLights ],
			ambient: options.ambient,
			sceneLights: describeLights( result.info ),
			prepareCaptureScene: options.prepare,
			deringing: options.deringing,
			nonNegative: options.nonNegative,
			renderer: result.info.renderer,
			date: new Date().toISOString(),
		} ),
	};

	writeVolume( options, data );
	const tetrahedra = tetrahedralization ? tetrahedralization.tetrahedra.length / 4 : 0;
	const summary: BakeSummary = {
		probes: count, tetrahedra, captureMs: result.captureMs, totalMs: performance.now() - start,
		bytes: statSync( options.out ).size, out: options.out, resolution: options.resolution, warnings,
	};

	if ( ! options.quiet ) {

		const { info } = result;
		const shape = tetrahedralization ? '' : layoutShape( layout.positions ).shape;
		log( formatTable( [
			[ 'output', `${summary.out} (${options.format}${options.format === 'bin' ? `, SH ${options.precision}` : ''})` ],
			[ 'probes', String( summary.probes ) ],
			[ 'tetrahedra', tetrahedralization ? String( tetrahedra )
				: `none: the probes lie ${shape === 'line' ? 'on one line' : 'in one plane'}; the runtime interpolates them ${shape === 'line' ? 'along it' : 'in it'}` ],
			[ 'resolution', `${summary.resolution}² per cube face` ],
			[ 'scene', `${options.scene} (${info.meshes} meshes, ${info.triangles.toLocaleString( 'en-US' )} triangles; loaded in ${formatDuration( result.loadMs )})` ],
			[ 'lights', describeLights( info ) ],
			[ 'sky', describeSky( options.sky, basename ) ],
			[ 'shadows', describeShadows( info, options.prepare ) ],
			[ 'SH', describePostProcessing( options, raised ) ],
			...formatShStatistics( stats ),
			[ 'capture time', `${formatDuration( summary.captureMs )} (${formatDuration( summary.captureMs / count )} per probe; ${info.renderer})` ],
			[ 'total time', formatDuration( summary.totalMs ) ],
			[ 'size on disk', formatBytes( summary.bytes ) ],
		] ) );

	}

	return summary;

}

/** The page's SH as a Float32Array, after the checks that make an empty result bad input. */
function capturedSH( options: BakeOptions, result: BakeResult, count: number ): Float32Array {

	if ( result.info.triangles === 0 && options.sky === null ) {

		throw new CliError( `scene ${options.scene} has no triangles (${result.info.meshes} meshes) and no --sky is given: nothing to capture; `
			+ 'expected a glTF/GLB or OBJ file with geometry.' );

	}

	if ( result.info.nonFiniteVertices > 0 ) {

		throw new CliError( `scene ${options.scene} has ${result.info.nonFiniteVertices} vertices with a NaN or infinite coordinate; every vertex position must be finite.` );

	}

	const bytes = Buffer.from( result.sh, 'base64' );
	const sh = new Float32Array( bytes.buffer.slice( bytes.byteOffset, bytes.byteOffset + bytes.byteLength ) );
	if ( sh.length !== 27 * count ) throw new CliError( `the page returned ${sh.length} SH floats for ${count} probes.`, 1 );
	return sh;

}

function writeVolume( options: BakeOptions, data: VolumeData ): void {

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

}
