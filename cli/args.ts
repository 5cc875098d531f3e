import { resolveChromiumPath } from './chromium.js';
import { CliError } from './errors.js';
import { LIGHT_DEFAULTS, LIGHT_FLAG_SYNTAX, parseHexColor, parsePointFlag, parseSpotFlag, parseSunFlag } from './lightFlags.js';
import type { BakeLight } from './bakePage/protocol.js';
import { CAPTURE_SCENE_DEFAULTS } from '../src/capture/captureSceneDefaults.js';

const D = CAPTURE_SCENE_DEFAULTS;

/** The usage text of `capture-lighting --help`. */
export const USAGE = `Usage:
  capture-lighting bake <scene.glb|scene.gltf|scene.obj> --probes <layout.json> --out <volume.bin|volume.json> [options]
  capture-lighting inspect [--strict] <volume.bin|volume.json>

bake: loads the scene in headless Chromium (WebGL2 on SwiftShader) with three's own loaders, adds the
lights asked for, prepares the scene for capture, captures a cube map at every probe of the layout,
projects it to SH9 on the GPU, tetrahedralizes the probes and writes the baked volume. More:
docs/cli.md.

Scene: a glTF/GLB is read with GLTFLoader: its KHR_lights_punctual lights (directional, point, spot)
and its emissive materials light the captures. An .obj is read with OBJLoader and the .mtl its
mtllib line names (MTLLoader: MeshPhongMaterials, Ke = emission), from the same folder; without one,
OBJLoader's default material (vertex colours when the file has them). Textures are waited for.

Layout (JSON): { "name"?, "positions": [x, y, z, ...], "names"?: [...], "roles"?: [...], "zones"?: [...],
"lights"?: [ { "type": "point" | "spot" | "directional", "position" (point, spot) | "direction"
(directional, towards the light), "target"? (spot; default [0, 0, 0]), "intensity"?, "color"?: "#rrggbb",
"distance"?, "decay"? (default 2), "angle"? (spot, degrees, default 60), "penumbra"? }, ... ] }.
Probes in one plane or on one line are stored without tetrahedra (the runtime interpolates them in
their plane or along their line).

Options of bake:
  --probes <file>          probe layout (required)
  --out <file>             output file (required)
  --resolution <n>         cube face size in texels, 1..256 (default 32, as LightProbeVolume.capture)
  --format bin|json        output format (default: json for a .json --out, bin otherwise)
  --precision float16|float32
                           SH precision of the binary format (default float32, as toArrayBuffer;
                           float16 halves the SH bytes, relative error ≤ 2^-11)
  --near <m>               near plane of the cube camera (default 0.05)
  --far <m>                far plane of the cube camera (default 1000)
  --sky <#rrggbb|file.hdr> what the captures see at infinity: a colour (sRGB) or an equirectangular
                           Radiance HDR panorama (default black)

Lights (each repeatable; added to the scene file's own lights; colours sRGB, default white;
intensities in three's units, lux or candela; decay 2, physically based, as three's default):
  --sun ${LIGHT_FLAG_SYNTAX[ '--sun' ]}
                           a directional light coming from direction x,y,z (towards the sun),
                           default intensity ${LIGHT_DEFAULTS.sunIntensity}
  --point ${LIGHT_FLAG_SYNTAX[ '--point' ]}
                           a point light at x,y,z (intensity default ${LIGHT_DEFAULTS.intensity}; distance 0 = no cut-off)
  --spot ${LIGHT_FLAG_SYNTAX[ '--spot' ]}
                           a spot light at x,y,z aiming at tx,ty,tz; angle° is the cone's half
                           angle in degrees (default ${LIGHT_DEFAULTS.angle}), penumbra 0..1 (default 0)
  --ambient <i>            a white ambient light of intensity i

Scene preparation (prepareCaptureScene from three-capture-lighting/capture, the same call a page
makes before volume.capture() to get the same SH; meshes with only unlit materials, such as lamp
bulbs, are left alone):
  --no-shadows             do not turn shadows on; by default every directional, point and spot light
                           casts shadows and every lit mesh casts and receives them (a capture must not
                           see light through walls; glTF has no shadow flags)
  --shadow-map-size <n>    shadow map size of every shadow-casting light (default ${D.shadowMapSize})
  --shadow-bias <b>        shadow.bias of every shadow-casting light (default ${D.shadowBias})
  --no-shadow-fit          keep directional lights' shadow cameras; by default each is fitted around
                           the scene's lit meshes
  --double-sided-shadows   lit materials render both faces into shadow maps, so a single-sided wall
                           facing the light still blocks it (lit faces then shadow themselves a
                           little); by default materials keep three's shadowSide (back faces)

SH post-processing (as LightProbeVolume.capture's options of the same names):
  --deringing <s>          Hann window of strength s in [0, 1] against ringing (0.1 light, 1/3 strong;
                           default 0)
  --non-negative           raise each probe's window just enough for irradiance ≥ 0 in every direction

Output:
  --strict                 exit 1 when the bake prints a warning (black probes, no light source,
                           negative irradiance); nothing is written then
  --browser <path>         Chromium executable (default: $CHROME_PATH, else $CHROMIUM_PATH, else
                           /usr/bin/chromium; empty variables count as unset)
  --quiet                  no progress bar and no summary (warnings are still printed)
  --help                   this text

inspect: decodes and validates a baked volume and prints its summary, its SH statistics and
warnings; --strict exits 1 when there is a warning.

Exit codes: 0 ok, 1 failure at run time (or an invalid volume file, or a warning under --strict),
2 bad usage or input.`;

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
	/** The lights of --sun, --point and --spot, in that order (each in the order given). */
	lights: BakeLight[];
	ambient: number;
	/** `prepareCaptureScene`'s options. */
	prepare: {
		shadows: boolean; shadowMapSize: number; shadowBias: number; fitShadowCameras: boolean; doubleSidedShadows: boolean;
	};
	/** Window strength, as `LightProbeVolume.capture`'s `deringing`. */
	deringing: number;
	/** As `LightProbeVolume.capture`'s `nonNegative`. */
	nonNegative: boolean;
	/** Warnings are failures (exit 1, nothing written). */
	strict: boolean;
	browser: string;
	quiet: boolean;

}

/** A parsed command line. */
export type Command =
	| { command: 'help' }
	| { command: 'bake'; options: BakeOptions }
	| { command: 'inspect'; file: string; strict: boolean };

const VALUE_OPTIONS = [
	'--probes', '--out', '--resolution', '--format', '--precision', '--near', '--far', '--sky', '--ambient', '--browser',
	'--shadow-map-size', '--shadow-bias', '--deringing',
];
const REPEATABLE_OPTIONS = [ '--sun', '--point', '--spot' ];
const SWITCHES = [ '--quiet', '--strict', '--non-negative', '--no-shadows', '--no-shadow-fit', '--double-sided-shadows' ];

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

		const strict = rest.includes( '--strict' );
		const files = rest.filter( ( arg ) => arg !== '--strict' );
		const unknown = files.find( ( arg ) => arg.startsWith( '-' ) );
		if ( unknown ) throw new CliError( `unknown option ${unknown} for inspect (see --help).` );
		if ( files.length !== 1 ) throw new CliError( `inspect takes one file, got ${files.length} arguments (see --help).` );
		return { command: 'inspect', file: files[ 0 ], strict };

	}

	if ( command !== 'bake' ) throw new CliError( `unknown command "${command}"; expected "bake" or "inspect" (see --help).` );
	const { values, repeated, switches, positional } = splitArguments( rest );

	if ( positional.length === 0 ) throw new CliError( 'bake needs a scene file (.glb, .gltf or .obj) (see --help).' );
	if ( positional.length > 1 ) throw new CliError( `bake takes one scene file, got ${positional.length}: ${positional.join( ', ' )}.` );
	const probes = values.get( '--probes' );
	if ( ! probes ) throw new CliError( 'bake needs --probes <layout.json>.' );
	const out = values.get( '--out' );
	if ( ! out ) throw new CliError( 'bake needs --out <volume.bin|volume.json>.' );

	const resolution = parseInteger( '--resolution', values.get( '--resolution' ) ?? '32', 1, 256 );
	const formatText = values.get( '--format' ) ?? ( /\.json$/i.test( out ) ? 'json' : 'bin' );
	if ( formatText !== 'bin' && formatText !== 'json' ) throw new CliError( `--format must be bin or json, got "${formatText}".` );
	const precisionText = values.get( '--precision' ) ?? 'float32';
	if ( precisionText !== 'float16' && precisionText !== 'float32' ) throw new CliError( `--precision must be float16 or float32, got "${precisionText}".` );

	const near = parseNumber( '--near', values.get( '--near' ) ?? '0.05' );
	const far = parseNumber( '--far', values.get( '--far' ) ?? '1000' );
	if ( ! ( near > 0 && far > near ) ) throw new CliError( `need 0 < --near < --far, got near ${near}, far ${far}.` );

	const lights = [
		...( repeated.get( '--sun' ) ?? [] ).map( parseSunFlag ),
		...( repeated.get( '--point' ) ?? [] ).map( parsePointFlag ),
		...( repeated.get( '--spot' ) ?? [] ).map( parseSpotFlag ),
	];
	const ambient = parseNumber( '--ambient', values.get( '--ambient' ) ?? '0' );
	if ( ambient < 0 ) throw new CliError( `--ambient must be ≥ 0, got ${ambient}.` );

	const shadows = ! switches.has( '--no-shadows' );
	for ( const name of [ '--shadow-map-size', '--shadow-bias', '--no-shadow-fit', '--double-sided-shadows' ] ) {

		if ( ! shadows && ( values.has( name ) || switches.has( name ) ) ) throw new CliError( `${name} has no effect with --no-shadows; give one or the other.` );

	}

	const prepare: BakeOptions[ 'prepare' ] = {
		shadows,
		shadowMapSize: parseInteger( '--shadow-map-size', values.get( '--shadow-map-size' ) ?? String( D.shadowMapSize ), 1, 16384 ),
		shadowBias: parseNumber( '--shadow-bias', values.get( '--shadow-bias' ) ?? String( D.shadowBias ) ),
		fitShadowCameras: ! switches.has( '--no-shadow-fit' ),
		doubleSidedShadows: switches.has( '--double-sided-shadows' ),
	};

	const deringing = parseNumber( '--deringing', values.get( '--deringing' ) ?? '0' );
	if ( ! ( deringing >= 0 && deringing <= 1 ) ) throw new CliError( `--deringing must be a window strength in [0, 1], got ${deringing}.` );

	const browser = resolveChromiumPath( values.get( '--browser' ), env ).path;

	return {
		command: 'bake',
		options: {
			scene: positional[ 0 ], probes, out, resolution, format: formatText, precision: precisionText, near, far,
			sky: parseSky( values.get( '--sky' ) ), lights, ambient, prepare, deringing,
			nonNegative: switches.has( '--non-negative' ), strict: switches.has( '--strict' ),
			browser, quiet: switches.has( '--quiet' ),
		},
	};

}

/** Sorts bake's arguments into single values, repeatable values, switches and the scene file. */
function splitArguments( rest: readonly string[] ): {
	values: Map<string, string>; repeated: Map<string, string[]>; switches: Set<string>; positional: string[];
} {

	const values = new Map<string, string>(), repeated = new Map<string, string[]>();
	const switches = new Set<string>(), positional: string[] = [];
	for ( let i = 0; i < rest.length; i ++ ) {

		const arg = rest[ i ];
		if ( ! arg.startsWith( '-' ) || /^-\d/.test( arg ) ) {

			positional.push( arg );
			continue;

		}

		const eq = arg.indexOf( '=' );
		const name = eq > 0 ? arg.slice( 0, eq ) : arg;
		if ( SWITCHES.includes( name ) ) {

			if ( eq > 0 ) throw new CliError( `option ${name} takes no value, got "${arg}".` );
			switches.add( name );
			continue;

		}

		const repeatable = REPEATABLE_OPTIONS.includes( name );
		if ( ! repeatable && ! VALUE_OPTIONS.includes( name ) ) throw new CliError( `unknown option ${name} (see --help).` );
		if ( ! repeatable && values.has( name ) ) throw new CliError( `option ${name} is given twice.` );
		let value: string | undefined;
		if ( eq > 0 ) value = arg.slice( eq + 1 );
		else {

			value = rest[ i + 1 ];
			// Negative numbers (--sun -1,2,0) are values, other dashes are the next option.
			if ( value === undefined || ( value.startsWith( '-' ) && ! /^-[\d.]/.test( value ) ) ) throw new CliError( `option ${name} needs a value (see --help).` );
			i ++;

		}

		if ( repeatable ) repeated.set( name, [ ...( repeated.get( name ) ?? [] ), value ] );
		else values.set( name, value );

	}

	return { values, repeated, switches, positional };

}

function parseSky( text: string | undefined ): BakeOptions[ 'sky' ] {

	if ( text === undefined ) return null;
	const hex = parseHexColor( text );
	if ( hex !== undefined ) return { color: [ ( hex >> 16 & 255 ) / 255, ( hex >> 8 & 255 ) / 255, ( hex & 255 ) / 255 ] };
	if ( /\.hdr$/i.test( text ) ) return { hdr: text };
	throw new CliError( `--sky must be a colour #rrggbb or a Radiance .hdr file, got "${text}".` );

}

function parseNumber( name: string, text: string ): number {

	const value = Number( text );
	if ( text.trim() === '' || ! Number.isFinite( value ) ) throw new CliError( `${name} must be a finite number, got "${text}".` );
	return value;

}

function parseInteger( name: string, text: string, min: number, max: number ): number {

	const value = Number( text );
	if ( ! /^\d+$/.test( text ) || ! Number.isInteger( value ) || value < min || value > max ) {

		throw new CliError( `${name} must be an integer from ${min} to ${max}, got "${text}".` );

	}

	return value;

}
