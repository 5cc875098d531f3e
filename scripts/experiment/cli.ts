import { SCENES, type SceneName } from './config.js';

/** Command-line options of the experiment. */
export interface ExperimentOptions {

	scene: SceneName;
	/** Output folder (default experiment/results). */
	out: string;
	/** Seed of the ground-truth samples (default 1). Use another one to tune settings. */
	seed: number;
	/** Seed of the dense candidate set the reduction runs on (default 2, never the ground truth's). */
	denseSeed: number;
	/** Ground-truth sample count M (default 500). */
	samples: number;
	/** Cube face size (default 32). */
	resolution: number;
	/** Also write DIR/<scene>.captures.json: the ground truth's and the dense set's positions and SH, and the fixed layouts'. */
	saveCaptures: boolean;

}

export const USAGE = `Usage: npm run experiment -- --scene <${SCENES.join( '|' )}> [--out DIR] [--seed N] [--dense-seed N] [--samples M] [--resolution R] [--save-captures]

Measures the paper's claim (arbitrary probes + tetrahedra reach a regular grid's lighting with
~20 % of its probes) in headless Chromium: writes DIR/<scene>.json, DIR/<scene>.md and
DIR/<scene>.png (default DIR: experiment/results).

  --seed N         seed of the ground-truth sample points (default 1; tune on another one)
  --dense-seed N   seed of the dense candidate set the automatic reduction runs on (default 2)
  --samples M      ground-truth points (default 500)
  --resolution R   cube face size of every capture (default 32)
  --save-captures  also write DIR/<scene>.captures.json (positions and SH of the ground truth,
                   the dense set and the fixed layouts) for re-analysis

Sponza and Sibenik need the Dabrovic models in the asset folder ../shared/assets/ (or the folder
named by CAPTURE_LIGHTING_ASSETS); Chromium at $CHROME_PATH, else $CHROMIUM_PATH, else /usr/bin/chromium.`;

/** Parses the arguments; throws an Error with a message for the user on bad input. */
export function parseArguments( argv: readonly string[] ): ExperimentOptions | 'help' {

	const options: Partial<ExperimentOptions> = { out: 'experiment/results', seed: 1, denseSeed: 2, samples: 500, resolution: 32, saveCaptures: false };
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
			case '--dense-seed': options.denseSeed = integer( 0, 0xFFFFFFFF ); break;
			case '--samples': options.samples = integer( 10, 100000 ); break;
			case '--resolution': options.resolution = integer( 4, 256 ); break;
			case '--save-captures': options.saveCaptures = true; break;
			default: throw new Error( `unknown argument "${arg}".` );

		}

	}

	if ( ! options.scene ) throw new Error( '--scene is required.' );
	if ( options.seed === options.denseSeed ) throw new Error( `--seed and --dense-seed must differ (both ${options.seed}): the reduction must not see the ground truth's points.` );
	return options as ExperimentOptions;

}
