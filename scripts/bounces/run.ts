/**
 * How irradiance in the Sibenik nave changes per bounce:
 * `node --import tsx scripts/bounces/run.ts [--resolution 32] [--bounces 3] [--output irradiance|sh] [--out experiment/results]`.
 *
 * In headless Chromium (scripts/bounces/page.ts, served by Vite like scripts/experiment/), the
 * Sibenik scene is built by its own scene module; its hand-made 39-probe layout is captured with
 * `captureBounces` (pass 0 = direct light: sun, lamps, stained glass, sky; pass k adds k bounces of
 * diffuse interreflection through the static meshes lit per vertex by the previous pass), with the
 * scene's stand-in for indirect light (every surface glowing with 0.12 × its diffuse colour) turned
 * off. For comparison, the ordinary capture with the stand-in on is taken too. Writes
 * DIR/sibenik-bounces.json and DIR/sibenik-bounces.md.
 *
 * Skips with a message (exit code 0) when the Sibenik assets are not in the asset folder.
 */

import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { evaluateIrradiance } from '../../src/sh/index.js';
import { assetsFolder } from '../assetsPlugin.mjs';
import { fromBase64, openScriptPage, type ScriptPage } from '../experiment/browser.js';
import { CONFIGS } from '../experiment/config.js';
import type { BounceAnswer, BounceApi, BounceRequest, LoadedBounceScene } from './page.js';

const ROOT = resolve( fileURLToPath( new URL( '../..', import.meta.url ) ) );
const USAGE = 'usage: node --import tsx scripts/bounces/run.ts [--resolution 32] [--bounces 3] [--output irradiance|sh] [--out experiment/results]';

interface Options { resolution: number; bounces: number; output: 'irradiance' | 'sh'; out: string }

function parseArguments( argv: string[] ): Options | 'help' {

	const options: Options = { resolution: 32, bounces: 3, output: 'irradiance', out: 'experiment/results' };
	for ( let i = 0; i < argv.length; i ++ ) {

		const name = argv[ i ], value = argv[ i + 1 ];
		if ( name === '--help' || name === '-h' ) return 'help';
		if ( value === undefined ) throw new Error( `${name} needs a value` );
		i ++;
		if ( name === '--resolution' || name === '--bounces' ) {

			const number = Number( value );
			if ( ! Number.isInteger( number ) || number < ( name === '--bounces' ? 0 : 1 ) ) throw new Error( `${name} must be an integer, got "${value}"` );
			options[ name === '--resolution' ? 'resolution' : 'bounces' ] = number;

		} else if ( name === '--output' ) {

			if ( value !== 'irradiance' && value !== 'sh' ) throw new Error( `--output must be irradiance or sh, got "${value}"` );
			options.output = value;

		} else if ( name === '--out' ) {

			options.out = value;

		} else {

			throw new Error( `unknown option ${name}` );

		}

	}

	return options;

}

/** Normals at which the nave's irradiance is reported. */
const NORMALS: Record<string, number[][]> = {
	up: [ [ 0, 1, 0 ] ],
	down: [ [ 0, - 1, 0 ] ],
	horizontal: [ [ 1, 0, 0 ], [ - 1, 0, 0 ], [ 0, 0, 1 ], [ 0, 0, - 1 ] ],
};

type RGB = [ number, number, number ];

interface PassFigures {

	pass: number;
	/** Mean L00 over all probes and over the nave probes, per channel. */
	meanL00: RGB;
	naveL00: RGB;
	/** Mean irradiance at the nave probes per normal group, per channel. */
	naveE: Record<string, RGB>;
	captureMs: number;
	lightingMs: number;

}

function figures( sh: Float32Array, nave: number[], probes: number, pass: BounceAnswer[ 'passes' ][ number ] ): PassFigures {

	const mean = ( indices: number[], value: ( probe: number ) => ArrayLike<number> ): RGB => {

		const sum: RGB = [ 0, 0, 0 ];
		for ( const i of indices ) { const v = value( i ); for ( let c = 0; c < 3; c ++ ) sum[ c ] += v[ c ] / indices.length; }
		return sum;

	};

	const all = Array.from( { length: probes }, ( _, i ) => i );
	const l00 = ( i: number ) => sh.subarray( 27 * i, 27 * i + 3 );
	const naveE: Record<string, RGB> = {};
	for ( const [ group, normals ] of Object.entries( NORMALS ) ) {

		naveE[ group ] = mean( nave, ( i ) => {

			const sum = [ 0, 0, 0 ];
			for ( const normal of normals ) {

				const e = evaluateIrradiance( sh, normal, new Float64Array( 3 ), 27 * i );
				for ( let c = 0; c < 3; c ++ ) sum[ c ] += e[ c ] / normals.length;

			}

			return sum;

		} );

	}

	return {
		pass: pass.pass, meanL00: mean( all, l00 ), naveL00: mean( nave, l00 ), naveE,
		captureMs: pass.captureMs, lightingMs: pass.lightingMs
	};

}

const grey = ( v: RGB ) => ( v[ 0 ] + v[ 1 ] + v[ 2 ] ) / 3;
const percent = ( v: number ) => `${v >= 0 ? '+' : ''}${( 100 * v ).toFixed( 1 )} %`;
const rgb = ( v: RGB ) => v.map( ( x ) => x.toFixed( 3 ) ).join( ' / ' );

function markdown( result: Record<string, unknown> & {
	passes: PassFigures[]; standIn: PassFigures; options: Options; scene: LoadedBounceScene; naveProbes: string[];
	run: { staticMeshes: number; vertices: number; totalMs: number; warmUpMs: number; standInTotalMs: number };
} ): string {

	const { passes, standIn, options, scene, run } = result;
	const lines: string[] = [];
	lines.push( '# Sibenik: irradiance per bounce', '' );
	lines.push( `\`node --import tsx scripts/bounces/run.ts --resolution ${options.resolution} --bounces ${options.bounces} --output ${options.output}\` (${String( result.date ).slice( 0, 10 )}; ${scene.info.renderer}).`, '' );
	lines.push( `Probes: the scene's hand-made layout, "${scene.layout.name}" (${scene.layout.positions.length / 3} probes); "nave" = its ${result.naveProbes.length} probes named nave… (${result.naveProbes.join( '; ' )}).`, '' );
	lines.push( `Pass 0 is the ordinary capture of the direct light (sun with its shadow map, ${Object.entries( scene.lights ).map( ( [ type, n ] ) => `${n} ${type}` ).join( ', ' )}, the stained glass (${scene.glowingMaterials.join( ', ' )}), the sky dome); pass k adds k bounces: the static geometry (${run.staticMeshes} mesh${run.staticMeshes === 1 ? '' : 'es'} with MeshStandardMaterials, ${run.vertices.toLocaleString( 'en' )} vertices — the OBJ's triangles unindexed), lit per vertex (output '${options.output}') by pass k−1's probes, then every probe captured again. Cube faces ${options.resolution}², HalfFloat.`, '' );
	lines.push( `The scene has no AmbientLight or HemisphereLight; its stand-in for indirect light is loadOBJScene's \`ambient: 0.12\` (each of ${scene.standInMaterials.length} materials glows with 0.12 × its diffuse colour and texture). It is **switched off** for every pass below; the last row is the ordinary capture with it on, for comparison.`, '' );
	lines.push( '| pass | mean L00, all probes (r / g / b) | nave L00 (grey) | change per bounce | ratio to pass 0 | nave E up | nave E down | nave E horizontal | capture | vertex lighting |' );
	lines.push( '|---|---|---|---|---|---|---|---|---|---|' );
	passes.forEach( ( pass, k ) => {

		const nave = grey( pass.naveL00 );
		const previous = k > 0 ? grey( passes[ k - 1 ].naveL00 ) : NaN;
		const first = grey( passes[ 0 ].naveL00 );
		lines.push( `| ${k} | ${rgb( pass.meanL00 )} | ${nave.toFixed( 3 )} | ${k > 0 ? percent( nave / previous - 1 ) : '—'} | ${( nave / first ).toFixed( 3 )} | ${grey( pass.naveE.up ).toFixed( 3 )} | ${grey( pass.naveE.down ).toFixed( 3 )} | ${grey( pass.naveE.horizontal ).toFixed( 3 )} | ${( pass.captureMs / 1000 ).toFixed( 1 )} s | ${( pass.lightingMs / 1000 ).toFixed( 2 )} s |` );

	} );
	const s = standIn;
	lines.push( `| stand-in on, no bounce | ${rgb( s.meanL00 )} | ${grey( s.naveL00 ).toFixed( 3 )} | — | ${( grey( s.naveL00 ) / grey( passes[ 0 ].naveL00 ) ).toFixed( 3 )} | ${grey( s.naveE.up ).toFixed( 3 )} | ${grey( s.naveE.down ).toFixed( 3 )} | ${grey( s.naveE.horizontal ).toFixed( 3 )} | ${( s.captureMs / 1000 ).toFixed( 1 )} s | — |` );
	lines.push( '' );
	lines.push( '"grey" = mean of r, g, b. E = irradiance from the probe SH (three\'s getIrradianceAt), averaged over the nave probes; horizontal = mean of ±x, ±z. Change per bounce and ratio are of the nave L00 (grey).', '' );
	const last = passes[ passes.length - 1 ], before = passes[ passes.length - 2 ];
	if ( before ) {

		lines.push( `Per channel, the last bounce changed the nave L00 by ${[ 0, 1, 2 ].map( ( c ) => percent( last.naveL00[ c ] / before.naveL00[ c ] - 1 ) ).join( ' / ' )} (r / g / b); all probes: ${[ 0, 1, 2 ].map( ( c ) => percent( last.meanL00[ c ] / before.meanL00[ c ] - 1 ) ).join( ' / ' )}.`, '' );

	}

	if ( passes.length >= 3 ) {

		// The increments shrink about geometrically (each bounce reflects the previous one's light).
		const value = ( k: number ) => grey( passes[ k ].naveL00 );
		const n = passes.length - 1, step = value( n ) - value( n - 1 ), q = step / ( value( n - 1 ) - value( n - 2 ) );
		const limit = value( n ) + ( q > 0 && q < 1 ? step * q / ( 1 - q ) : NaN );
		lines.push( `Convergence: the nave's increments shrink by ${q.toFixed( 2 )}× from bounce ${n - 1} to ${n}; extrapolated geometrically, the converged nave L00 is ≈ ${limit.toFixed( 3 )} (${( limit / value( 0 ) ).toFixed( 2 )}× pass 0), so pass ${n} is within ${( 100 * ( 1 - value( n ) / limit ) ).toFixed( 1 )} % of it. The stand-in (0.12 × diffuse glow, no bounce) gives ${( grey( standIn.naveL00 ) / limit ).toFixed( 2 )}× that converged value in the nave (E down: ${( grey( standIn.naveE.down ) / grey( passes[ n ].naveE.down ) ).toFixed( 2 )}× pass ${n}'s).`, '' );

	}

	lines.push( `Times: the capture column includes the shader compilation of the patched clones in pass 1; warm-up capture (not counted) ${( run.warmUpMs / 1000 ).toFixed( 1 )} s; captureBounces in all ${( run.totalMs / 1000 ).toFixed( 1 )} s; the whole run ${( Number( result.runMs ) / 1000 ).toFixed( 0 )} s.`, '' );
	lines.push( 'What a pass means: pass k = direct + k bounces of diffuse interreflection, as far as per-vertex sampling of the 39-probe field resolves it (light varies linearly across each triangle; vertices outside the probes\' hull take the outer cells\' extrapolated weights; the visibility guard is not applied). Bounce light reflects only diffusely (three\'s indirect diffuse term, minus the specular share of a MeshStandardMaterial).', '' );
	return lines.join( '\n' );

}

async function main(): Promise<number> {

	let options: Options | 'help';
	try {

		options = parseArguments( process.argv.slice( 2 ) );

	} catch ( error ) {

		console.error( `bounces: ${( error as Error ).message}\n${USAGE}` );
		return 2;

	}

	if ( options === 'help' ) { console.log( USAGE ); return 0; }
	const config = CONFIGS.sibenik;
	const missing = config.assets.filter( ( file ) => ! existsSync( join( assetsFolder, file ) ) );
	if ( missing.length > 0 ) {

		console.log( `bounces: skipped — the Sibenik scene needs ${missing.join( ', ' )} in the asset folder ${assetsFolder}. Get ${config.source}, or set CAPTURE_LIGHTING_ASSETS.` );
		return 0;

	}

	const runStart = performance.now();
	const log = ( message: string ) => console.log( `[${( ( performance.now() - runStart ) / 1000 ).toFixed( 0 ).padStart( 4 )} s] ${message}` );
	let session: ScriptPage<BounceApi> | null = null;
	try {

		session = await openScriptPage<BounceApi>( 'bounces', log );
		const { browserVersion, call } = session;
		log( `${browserVersion}; loading Sibenik` );
		const scene = await call( 'load', '/assets/' );
		log( `${scene.info.renderer}; ${scene.info.meshes} meshes, ${scene.info.vertices} vertices; lights ${JSON.stringify( scene.lights )}; stand-in materials ${scene.standInMaterials.length}, glowing ${scene.glowingMaterials.join( ', ' )}` );
		const nave = scene.layout.names.map( ( name, i ) => ( name.startsWith( 'nave' ) ? i : - 1 ) ).filter( ( i ) => i >= 0 );
		if ( nave.length === 0 ) throw new Error( 'the layout has no probes named nave…' );
		const probes = scene.layout.positions.length / 3;
		const request: BounceRequest = {
			resolution: options.resolution, near: config.near, far: config.far, bounces: options.bounces, standIn: false,
			output: options.output
		};

		log( `bounces 0..${options.bounces}, stand-in off` );
		const answer = await call( 'run', request );
		const passes = answer.passes.map( ( pass, k ) => figures( fromBase64( answer.sh[ k ], Float32Array ), nave, probes, pass ) );
		for ( const pass of passes ) log( `pass ${pass.pass}: nave L00 ${rgb( pass.naveL00 )}, all ${rgb( pass.meanL00 )}; capture ${( pass.captureMs / 1000 ).toFixed( 1 )} s, vertex lighting ${( pass.lightingMs / 1000 ).toFixed( 2 )} s` );

		log( 'ordinary capture with the stand-in on' );
		const ordinary = await call( 'run', { ...request, bounces: 0, standIn: true } );
		const standIn = figures( fromBase64( ordinary.sh[ 0 ], Float32Array ), nave, probes, ordinary.passes[ 0 ] );

		const result = {
			scene: scene,
			naveProbes: nave.map( ( i ) => scene.layout.names[ i ] ),
			options,
			capture: { resolution: options.resolution, near: config.near, far: config.far, type: 'HalfFloat', solidAngle: 'exact' },
			passes,
			standIn,
			run: {
				staticMeshes: answer.staticMeshes, vertices: answer.vertices, totalMs: answer.totalMs, warmUpMs: answer.warmUpMs,
				standInTotalMs: ordinary.totalMs
			},
			environment: { browser: browserVersion, node: process.version, cpus: `${cpus().length} × ${cpus()[ 0 ]?.model ?? '?'}` },
			date: new Date().toISOString(),
			runMs: performance.now() - runStart,
		};
		const out = resolve( ROOT, options.out );
		mkdirSync( out, { recursive: true } );
		writeFileSync( join( out, 'sibenik-bounces.json' ), JSON.stringify( result, null, '\t' ) + '\n' );
		const report = markdown( result );
		writeFileSync( join( out, 'sibenik-bounces.md' ), report );
		console.log( `\n${report}` );
		log( `wrote ${[ 'json', 'md' ].map( ( ext ) => relative( process.cwd(), join( out, `sibenik-bounces.${ext}` ) ) ).join( ', ' )}` );
		return 0;

	} catch ( error ) {

		console.error( `bounces: ${( error as Error ).stack ?? error}` );
		return 1;

	} finally {

		await session?.close();

	}

}

process.exitCode = await main();
