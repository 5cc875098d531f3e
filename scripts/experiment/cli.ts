import { SCENES, type SceneName } from './config.js';

/** Command-line options of the experiment. */
export interface ExperimentOptions {

	scene: SceneName;
	/** Output folder (default experiment/results). */
	out: string;
	/** Seed of the ground-truth sample points (default 1). Use another one to tune settings. */
	seed: number;
	/** Seeds of further ground truths the same layouts are judged on (default 3 and 4). */
	checkSeeds: number[];
	/** Seed of the dense candidate set the reduction runs on (default 2, never a ground truth's). */
	denseSeed: number;
	/** Extra captured fit points in open space (null: the scene's default in config.ts). */
	fitPoints: number | null;
	/** Fit points per probe of a fitted layout (null: the scene's default in config.ts, else 0). */
	fitPointsPerProbe: number | null;
	/** Seed of the extra fit points (default 101, never a ground truth's). */
	fitSeed: number;
	/** Ground-truth sample count M (default 500). */
	samples: number;
	/** Cube face size (default 32). */
	resolution: number;
	/** The saved captures file to reuse and add to (null: capture everything, save nothing). */
	captures: string | null;
	/** Never start the browser: every capture from `captures`, no PNG. */
	offline: boolean;
	/** Only make (and save) the captures a run needs; no layouts, no results. */
	captureOnly: boolean;

}

export const USAGE = `Usage: npm run experiment -- --scene <${SCENES.join( '|' )}> [--out DIR] [--seed N] [--check-seeds N,N|none]
       [--dense-seed N] [--fit-points N] [--fit-points-per-probe K] [--fit-seed N] [--samples M] [--resolution R] [--save-captures | --captures FILE] [--offline | --capture-only]

Measures the paper's claim (arbitrary probes + tetrahedra reach a regular grid's lighting with
~20 % of its probes) and what fitting, placement and gradient probes add, in headless Chromium:
writes DIR/<scene>.json, DIR/<scene>.md, DIR/<scene>.svg and DIR/<scene>.png (default DIR:
experiment/results).

  --seed N          seed of the ground-truth sample points (default 1; tune on another one)
  --check-seeds L   further ground-truth seeds the same layouts are judged on (default 3,4; none)
  --dense-seed N    seed of the dense candidate set the automatic reduction runs on (default 2)
  --fit-points N    extra captured points in open space the fits use besides the dense set
                    (default per scene, config.ts)
  --fit-points-per-probe K
                    a fitted layout of n probes fits to the first max(N, K × n) of those points
                    (default per scene, config.ts; else 0)
  --fit-seed N      seed of those points (default 101)
  --samples M       ground-truth points (default 500)
  --resolution R    cube face size of every capture (default 32)
  --save-captures   reuse and extend DIR/<scene>.captures.json: every capture and the scene's
                    geometry, so a later run captures only what is new
  --captures FILE   the same with another file
  --offline         no browser: every capture from the saved captures (an error when one is
                    missing), no PNG
  --capture-only    only make the captures (saved as with --save-captures); no results

Sponza and Sibenik need the Dabrovic models in the asset folder ../shared/assets/ (or the folder
named by CAPTURE_LIGHTING_ASSETS); Chromium at $CHROME_PATH, else $CHROMIUM_PATH, else /usr/bin/chromium.`;

/** Parses the arguments; throws an Error with a message for the user on bad input. */
export function parseArguments( argv: readonly string[] ): ExperimentOptions | 'help' {

	const options: Partial<ExperimentOptions> = {
		out: 'experiment/results', seed: 1, checkSeeds: [ 3, 4 ], denseSeed: 2, fitPoints: null, fitPointsPerProbe: null, fitSeed: 101, samples: 500, resolution: 32,
		captures: null, offline: false, captureOnly: false,
	};
	let saveCaptures = false;
	for ( let i = 0; i < argv.length; i ++ ) {

		const arg = argv[ i ];
		if ( arg === '--help' || arg === '-h' ) return 'help';
		const [ flag, inline ] = arg.includes( '=' ) ? [ arg.slice( 0, arg.indexOf( '=' ) ), arg.slice( arg.indexOf( '=' ) + 1 ) ] : [ arg, undefined ];
		const value = (): string => {

			const v = inline ?? argv[ ++ i ];
			if ( v === undefined || v.startsWith( '--' ) ) throw new Error( `${flag} needs a value.` );
			return v;

		};

		const integer = ( min: number, max: number ): number => {

			const text = value(), n = Number( text );
			if ( ! Number.isInteger( n ) || n < min || n > max ) throw new Error( `${flag} must be an integer in ${min}..${max}, got "${text}".` );
			return n;

		};

		switch ( flag ) {

			case '--scene': {

				const scene = value();
				if ( ! ( SCENES as readonly string[] ).includes( scene ) ) throw new Error( `--scene must be one of ${SCENES.join( ', ' )}, got "${scene}".` );
				options.scene = scene as SceneName;
				break;

			}

			case '--out': options.out = value(); break;
			case '--seed': options.seed = integer( 0, 0xFFFFFFFF ); break;
			case '--check-seeds': {

				const text = value();
				const seeds = text === 'none' ? [] : text.split( ',' ).map( Number );
				if ( ! seeds.every( ( n ) => Number.isInteger( n ) && n >= 0 && n <= 0xFFFFFFFF ) ) throw new Error( `--check-seeds must be integers separated by commas, or none; got "${text}".` );
				options.checkSeeds = seeds;
				break;

			}

			case '--dense-seed': options.denseSeed = integer( 0, 0xFFFFFFFF ); break;
			case '--fit-points': options.fitPoints = integer( 0, 100000 ); break;
			case '--fit-points-per-probe': {

				const k = Number( value() );
				if ( ! Number.isFinite( k ) || k < 0 || k > 1000 ) throw new Error( '--fit-points-per-probe needs a number from 0 to 1000.' );
				options.fitPointsPerProbe = k;
				break;

			}

			case '--fit-seed': options.fitSeed = integer( 0, 0xFFFFFFFF ); break;
			case '--samples': options.samples = integer( 10, 100000 ); break;
			case '--resolution': options.resolution = integer( 4, 256 ); break;
			case '--save-captures': saveCaptures = true; break;
			case '--captures': options.captures = value(); break;
			case '--offline': options.offline = true; break;
			case '--capture-only': options.captureOnly = true; break;
			default: throw new Error( `unknown argument "${arg}".` );

		}

	}

	if ( ! options.scene ) throw new Error( '--scene is required.' );
	if ( saveCaptures && options.captures !== null ) throw new Error( '--save-captures and --captures name two files; give one.' );
	if ( options.captureOnly && options.offline ) throw new Error( '--capture-only and --offline exclude each other.' );
	if ( options.captureOnly && ! saveCaptures && options.captures === null ) saveCaptures = true;
	if ( saveCaptures || ( options.offline && options.captures === null ) ) options.captures = `${options.out}/${options.scene}.captures.json`;
	// The placement and the fits must never see a ground truth's points.
	for ( const truth of [ options.seed!, ...options.checkSeeds! ] ) {

		if ( truth === options.denseSeed ) throw new Error( `--seed/--check-seeds and --dense-seed must differ (both ${truth}): the reduction must not see the ground truth's points.` );
		if ( truth === options.fitSeed ) throw new Error( `--seed/--check-seeds and --fit-seed must differ (both ${truth}): the fits must not see the ground truth's points.` );

	}

	if ( options.denseSeed === options.fitSeed ) throw new Error( `--dense-seed and --fit-seed must differ (both ${options.fitSeed}).` );
	options.checkSeeds = options.checkSeeds!.filter( ( s, i, all ) => s !== options.seed && all.indexOf( s ) === i );
	return options as ExperimentOptions;

}
