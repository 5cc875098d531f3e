import { resolveChromiumPath } from './chromium.js';
import { CliError } from './errors.js';

/** The usage text of `capture-lighting --help`. */
export const USAGE = `Usage:
  capture-lighting bake <scene.glb|scene.gltf|scene.obj> --probes <layout.json> --out <volume.bin|volume.json> [options]
  capture-lighting inspect <volume.bin|volume.json>

bake: loads the scene in headless Chromium (WebGL2 on SwiftShader), captures a cube map at every
probe of the layout, projects it to SH9 on the GPU, tetrahedralizes the probes and writes the baked
volume. The layout is JSON: { "name", "positions": [x, y, z, ...], "names"?: [...], "roles"?: [...] }.
An .obj scene loads the .mtl its mtllib line names, from the same folder.

Options of bake:
  --probes <file>          probe layout (required)
  --out <file>             output file (required)
  --resolution <n>         cube face size in texels, 1..256 (default 128; SwiftShader draws on the CPU,
                           so large scenes at 128 take a while)
  --format bin|json        output format (default: json for a .json --out, bin otherwise)
  --precision float16|float32
                           SH precision of the binary format (default float16)
  --near <m>               near plane of the cube camera (default 0.05)
  --far <m>                far plane of the cube camera (default 1000)
  --sky <#rrggbb|file.hdr> what the captures see at infinity: a colour (sRGB) or an equirectangular
                           Radiance HDR panorama (default black)
  --sun <x,y,z[,i]>        add a directional light with shadows, coming from direction x,y,z
                           (towards the sun), intensity i (default 3)
  --ambient <i>            add a white ambient light of intensity i
  --browser <path>         Chromium executable (default: $CHROME_PATH, else $CHROMIUM_PATH, else
                           /usr/bin/chromium; empty variables count as unset)
  --quiet                  no progress bar and no summary
  --help                   this text

inspect: decodes and validates a baked volume and prints its summary.

Exit codes: 0 ok, 1 failure at run time (or an invalid volume file), 2 bad usage or input.`;

/** The parsed options of `bake`. */
export interface BakeOptions {

	scene: string;
	probes: string;
	out: string;
	resolution: number;
	format: 'bin' | 'json';
	precision: 'float16' | 'float32';
	near: number;
	far: number;
	/** A colour (sRGB components 0..1, as written), an HDR file path, or null (black). */
	sky: { color: [ number, number, number ] } | { hdr: string } | null;
	sun: { direction: [ number, number, number ]; intensity: number } | null;
	ambient: number;
	browser: string;
	quiet: boolean;

}

/** A parsed command line. */
export type Command =
	| { command: 'help' }
	| { command: 'bake'; options: BakeOptions }
	| { command: 'inspect'; file: string };

const BAKE_VALUE_OPTIONS = [ '--probes', '--out', '--resolution', '--format', '--precision', '--near', '--far', '--sky', '--sun', '--ambient', '--browser' ];

/**
 * Parses the arguments after `capture-lighting`.
 * @param argv `process.argv.slice( 2 )`.
 * @param env Environment (for CHROME_PATH / CHROMIUM_PATH).
 * @throws {CliError} exit code 2, naming the bad option.
 */
export function parseArguments( argv: readonly string[], env: Record<string, string | undefined> = process.env ): Command {

	if ( argv.length === 0 ) throw new CliError( 'no command given; expected "bake" or "inspect" (see --help).' );
	if ( argv.includes( '--help' ) || argv.includes( '-h' ) || argv[ 0 ] === 'help' ) return { command: 'help' };
	const [ command, ...rest ] = argv;

	if ( command === 'inspect' ) {

		const unknown = rest.find( ( arg ) => arg.startsWith( '-' ) );
		if ( unknown ) throw new CliError( `unknown option ${unknown} for inspect (see --help).` );
		if ( rest.length !== 1 ) throw new CliError( `inspect takes one file, got ${rest.length} arguments (see --help).` );
		return { command: 'inspect', file: rest[ 0 ] };

	}

	if ( command !== 'bake' ) throw new CliError( `unknown command "${command}"; expected "bake" or "inspect" (see --help).` );

	const values = new Map<string, string>();
	const positional: string[] = [];
	let quiet = false;
	for ( let i = 0; i < rest.length; i ++ ) {

		const arg = rest[ i ];
		if ( arg === '--quiet' ) { quiet = true; continue; }
		if ( arg.startsWith( '-' ) && ! /^-\d/.test( arg ) ) {

			const eq = arg.indexOf( '=' );
			const name = eq > 0 ? arg.slice( 0, eq ) : arg;
			if ( ! BAKE_VALUE_OPTIONS.includes( name ) ) throw new CliError( `unknown option ${name} (see --help).` );
			if ( values.has( name ) ) throw new CliError( `option ${name} is given twice.` );
			let value: string | undefined;
			if ( eq > 0 ) value = arg.slice( eq + 1 );
			else {

				value = rest[ i + 1 ];
				// Negative numbers (--sun -1,2,0) are values, other dashes are the next option.
				if ( value === undefined || ( value.startsWith( '-' ) && ! /^-[\d.]/.test( value ) ) ) throw new CliError( `option ${name} needs a value (see --help).` );
				i ++;

			}

			values.set( name, value );
			continue;

		}

		positional.push( arg );

	}

	if ( positional.length === 0 ) throw new CliError( 'bake needs a scene file (.glb, .gltf or .obj) (see --help).' );
	if ( positional.length > 1 ) throw new CliError( `bake takes one scene file, got ${positional.length}: ${positional.join( ', ' )}.` );
	const probes = values.get( '--probes' );
	if ( ! probes ) throw new CliError( 'bake needs --probes <layout.json>.' );
	const out = values.get( '--out' );
	if ( ! out ) throw new CliError( 'bake needs --out <volume.bin|volume.json>.' );

	const resolutionText = values.get( '--resolution' ) ?? '128';
	const resolution = Number( resolutionText );
	if ( ! /^\d+$/.test( resolutionText ) || ! Number.isInteger( resolution ) || resolution < 1 || resolution > 256 ) {

		throw new CliError( `--resolution must be an integer from 1 to 256, got "${resolutionText}".` );

	}

	const formatText = values.get( '--format' ) ?? ( /\.json$/i.test( out ) ? 'json' : 'bin' );
	if ( formatText !== 'bin' && formatText !== 'json' ) throw new CliError( `--format must be bin or json, got "${formatText}".` );
	const precisionText = values.get( '--precision' ) ?? 'float16';
	if ( precisionText !== 'float16' && precisionText !== 'float32' ) throw new CliError( `--precision must be float16 or float32, got "${precisionText}".` );

	const near = parseNumber( '--near', values.get( '--near' ) ?? '0.05' );
	const far = parseNumber( '--far', values.get( '--far' ) ?? '1000' );
	if ( ! ( near > 0 && far > near ) ) throw new CliError( `need 0 < --near < --far, got near ${near}, far ${far}.` );

	let sky: BakeOptions[ 'sky' ] = null;
	const skyText = values.get( '--sky' );
	if ( skyText !== undefined ) {

		const hex = /^#([0-9a-f]{6})$/i.exec( skyText );
		if ( hex ) {

			const n = parseInt( hex[ 1 ], 16 );
			sky = { color: [ ( n >> 16 & 255 ) / 255, ( n >> 8 & 255 ) / 255, ( n & 255 ) / 255 ] };

		} else if ( /\.hdr$/i.test( skyText ) ) {

			sky = { hdr: skyText };

		} else {

			throw new CliError( `--sky must be a colour #rrggbb or a Radiance .hdr file, got "${skyText}".` );

		}

	}

	let sun: BakeOptions[ 'sun' ] = null;
	const sunText = values.get( '--sun' );
	if ( sunText !== undefined ) {

		const parts = sunText.split( ',' ).map( ( part ) => Number( part.trim() ) );
		if ( ( parts.length !== 3 && parts.length !== 4 ) || parts.some( ( v ) => ! Number.isFinite( v ) ) || sunText.split( ',' ).some( ( part ) => part.trim() === '' ) ) {

			throw new CliError( `--sun must be x,y,z or x,y,z,intensity (finite numbers), got "${sunText}".` );

		}

		const [ x, y, z, intensity = 3 ] = parts;
		if ( x === 0 && y === 0 && z === 0 ) throw new CliError( '--sun direction must not be 0,0,0.' );
		if ( intensity < 0 ) throw new CliError( `--sun intensity must be ≥ 0, got ${intensity}.` );
		sun = { direction: [ x, y, z ], intensity };

	}

	const ambient = parseNumber( '--ambient', values.get( '--ambient' ) ?? '0' );
	if ( ambient < 0 ) throw new CliError( `--ambient must be ≥ 0, got ${ambient}.` );

	const browser = resolveChromiumPath( values.get( '--browser' ), env ).path;

	return {
		command: 'bake',
		options: {
			scene: positional[ 0 ], probes, out, resolution, format: formatText, precision: precisionText,
			near, far, sky, sun, ambient, browser, quiet,
		},
	};

}

function parseNumber( name: string, text: string ): number {

	const value = Number( text );
	if ( text.trim() === '' || ! Number.isFinite( value ) ) throw new CliError( `${name} must be a finite number, got "${text}".` );
	return value;

}
