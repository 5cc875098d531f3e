import { orient } from '../tetrahedra/predicates.js';
import { BakedVolumeError } from './BakedVolumeError.js';
import { crc32 } from './crc32.js';
import { toFloat16Bits, float16Table, FLOAT16_MAX } from './float16.js';

/*
 * The baked light probe volume: a versioned little-endian binary file (and a JSON form that mirrors
 * it) holding everything a LightProbeVolume needs to light a scene without capturing or
 * tetrahedralizing again. The layout is specified in docs/format.md; this file is its reference
 * reader and writer. No three.js here: it runs in plain Node, in workers and in build tools.
 *
 * Loading is defensive: every count is checked against the section lengths, and every section
 * against the buffer, before anything proportional to a count is allocated; then every value is
 * checked (finite numbers, indices in range, positively oriented tetrahedra, symmetric neighbour
 * links that share a face and lie on opposite sides of it). All loops are bounded by the buffer
 * length, so no input can make the reader hang or allocate more than a small multiple of the file.
 */

/** Role of a probe (the same strings as `ProbeRole` of LightProbeVolume). */
export type BakedProbeRole = 'sky' | 'bounce' | 'bleed' | 'fill';

/** Role codes of the ROLE section: the index in this list. */
export const BAKED_ROLES: readonly BakedProbeRole[] = [ 'sky', 'bounce', 'bleed', 'fill' ];

/** Capture settings of one role (the stored subset of `ProbeCaptureSettings`). */
export interface BakedCaptureSettings {

	/** Cube face edge in texels, an integer ≥ 1. */
	resolution?: number;

	/** Near plane, > 0. */
	near?: number;

	/** Far plane, > near. */
	far?: number;

	/** Render target type the capture used. */
	type?: 'half' | 'float';

	/** Texel solid-angle formula of the projection. */
	solidAngle?: 'exact' | 'paper';

}

/** Capture settings a volume was baked with: the common ones plus overrides per role. */
export interface BakedCapture extends BakedCaptureSettings {

	/** Settings per role, over the common ones. */
	roles?: Partial<Record<BakedProbeRole, BakedCaptureSettings>>;

}

/** A named group of probes, with optional boxes where it applies. */
export interface BakedZone {

	/** Zone name. */
	name: string;

	/** Indices of the zone's probes. */
	probes: Uint32Array;

	/** Boxes, 6 floats each: min x, y, z, max x, y, z (empty when the zone has none). */
	bounds: Float64Array;

}

/**
 * A baked volume, as {@link decodeBakedVolume} and {@link bakedVolumeFromJSON} return it: every
 * field present and valid.
 */
export interface BakedVolumeData {

	/** x, y, z per probe, float64: the tetrahedra are valid for exactly these coordinates. */
	positions: Float64Array;

	/** 27 floats per probe, three.js `SphericalHarmonics3` order (coefficient k's r, g, b at 3k..3k+2). */
	sh: Float32Array;

	/** 4 probe indices per tetrahedron, positively oriented; empty when none is stored. */
	tetrahedra: Uint32Array;

	/** `neighbors[4t + i]`: the tetrahedron across the face opposite vertex i, or −1 on the hull. */
	neighbors: Int32Array;

	/** Name per probe ('' when none). */
	names: string[];

	/** Role per probe. */
	roles: BakedProbeRole[];

	/** Named groups of probes. */
	zones: BakedZone[];

	/** The volume's box: min x, y, z, max x, y, z (the positions' box unless given). */
	bounds: Float64Array;

	/** Capture settings the SH were baked with ({} when unknown). */
	capture: BakedCapture;

	/** Free-form text, e.g. the tool and scene that produced the bake ('' when none). */
	metadata: string;

}

/** What {@link encodeBakedVolume} and {@link bakedVolumeToJSON} accept: only positions and SH are required. */
export interface BakedVolumeInput {

	/** x, y, z per probe. Float32 input is widened exactly; the tetrahedra must be valid for the stored values. */
	positions: ArrayLike<number>;

	/** 27 floats per probe. */
	sh: ArrayLike<number>;

	/** 4 indices per tetrahedron (omit for a volume whose reader builds its own interpolator, e.g. a planar one). */
	tetrahedra?: ArrayLike<number>;

	/** 4 per tetrahedron; required with `tetrahedra`. */
	neighbors?: ArrayLike<number>;

	/** Name per probe. */
	names?: readonly string[];

	/** Role per probe; default 'fill'. */
	roles?: readonly BakedProbeRole[];

	/** Named groups of probes. */
	zones?: readonly { name: string; probes: ArrayLike<number>; bounds?: ArrayLike<number> }[];

	/** min x, y, z, max x, y, z; default the positions' box. */
	bounds?: ArrayLike<number>;

	/** Capture settings. */
	capture?: BakedCapture;

	/** Free-form text. */
	metadata?: string;

}

/** Options of {@link encodeBakedVolume}. */
export interface EncodeBakedVolumeOptions {

	/**
	 * Storage of the SH: `'float16'` halves the SH bytes (relative error ≤ 2^−11 for values above
	 * 6.1e−5; throws a `'float16-overflow'` error for values beyond ±65504) or `'float32'` (exact).
	 * Default `'float32'`.
	 */
	precision?: 'float16' | 'float32';

}

/** Major version this code reads and writes. */
export const BAKED_VOLUME_VERSION_MAJOR = 1;

/** Minor version this code writes. */
export const BAKED_VOLUME_VERSION_MINOR = 0;

/** The 8 magic bytes at offset 0: 0xAB 'L' 'P' 'V' '\r' '\n' 0x1A '\n'. */
export const BAKED_VOLUME_MAGIC: readonly number[] = [ 0xAB, 0x4C, 0x50, 0x56, 0x0D, 0x0A, 0x1A, 0x0A ];

/** `format` tag of the JSON form. */
export const BAKED_VOLUME_JSON_FORMAT = 'three-capture-lighting/baked-light-probe-volume';

const HEADER_SIZE = 64;
const ENTRY_SIZE = 16;
const FLAG_SH_FLOAT16 = 1;
const SECTION_REQUIRED = 1;

function fourCC( s: string ): number {

	return ( s.charCodeAt( 0 ) | ( s.charCodeAt( 1 ) << 8 ) | ( s.charCodeAt( 2 ) << 16 ) | ( s.charCodeAt( 3 ) << 24 ) ) >>> 0;

}

/** Section ids: four ASCII characters read as a little-endian u32. */
export const BAKED_SECTION = {
	POSITIONS: fourCC( 'POS ' ),
	SH: fourCC( 'SH  ' ),
	TETRAHEDRA: fourCC( 'TETS' ),
	NEIGHBORS: fourCC( 'NBRS' ),
	ROLES: fourCC( 'ROLE' ),
	NAMES: fourCC( 'NAME' ),
	ZONES: fourCC( 'ZONE' ),
	BOUNDS: fourCC( 'BNDS' ),
	CAPTURE: fourCC( 'CAPT' ),
	METADATA: fourCC( 'META' ),
} as const;

const KNOWN_SECTIONS = new Set<number>( Object.values( BAKED_SECTION ) );

function sectionName( id: number ): string {

	let s = '';
	for ( let k = 0; k < 4; k ++ ) {

		const c = ( id >>> ( 8 * k ) ) & 0xFF;
		s += c >= 0x20 && c < 0x7F ? String.fromCharCode( c ) : '?';

	}

	return `'${s}'`;

}

const LITTLE_ENDIAN = new Uint8Array( new Uint16Array( [ 1 ] ).buffer )[ 0 ] === 1;
const utf8Encoder = new TextEncoder();
const utf8Decoder = new TextDecoder( 'utf-8', { fatal: true, ignoreBOM: true } );

function fail( code: ConstructorParameters<typeof BakedVolumeError>[ 0 ], where: string, message: string ): never {

	throw new BakedVolumeError( code, `${where}: ${message}` );

}

// ---------------------------------------------------------------------------------------------
// Validation shared by the binary reader, the JSON reader and the writers.
// ---------------------------------------------------------------------------------------------

function checkFinite( where: string, name: string, values: ArrayLike<number> ): void {

	for ( let i = 0, n = values.length; i < n; i ++ ) {

		const v = values[ i ];
		// v - v is 0 for finite numbers and NaN for NaN and ±Infinity: one comparison per value.
		if ( v - v !== 0 ) fail( 'nan', where, `${name}[${i}] is ${String( v )}; every value must be a finite number.` );

	}

}

// A lone UTF-16 surrogate has no UTF-8 encoding (TextEncoder would silently write U+FFFD).
const LONE_SURROGATE = /[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/;

function checkText( where: string, name: string, text: string ): void {

	if ( LONE_SURROGATE.test( text ) ) fail( 'utf8', where, `${name} has a lone surrogate and cannot be stored as UTF-8.` );

}

function checkBox( where: string, name: string, box: ArrayLike<number>, offset: number ): void {

	for ( let k = 0; k < 3; k ++ ) {

		if ( ! ( box[ offset + k ] <= box[ offset + 3 + k ] ) ) {

			fail( 'range', where, `${name}[${offset + k}] = ${box[ offset + k ]} exceeds its maximum ${name}[${offset + 3 + k}] = ${box[ offset + 3 + k ]}.` );

		}

	}

}

/**
 * Checks the link f = 4t + i: n = neighbors[f] contains t's face i, links back across it, and lies
 * on the other side of it. Indices are already in range.
 */
function checkLink( where: string, tetrahedra: Uint32Array, neighbors: Int32Array, f: number ): void {

	const t = f >> 2, i = f & 3, n = neighbors[ f ], t4 = 4 * t, n4 = 4 * n;
	// The face opposite slot i, in slot order; its orientation seen from the apex is (−1)^i.
	const a = tetrahedra[ t4 + ( i === 0 ? 1 : 0 ) ], b = tetrahedra[ t4 + ( i <= 1 ? 2 : 1 ) ], c = tetrahedra[ t4 + ( i <= 2 ? 3 : 2 ) ];
	let j = - 1, matched = 0, p0 = 0, p1 = 0, p2 = 0;
	for ( let k = 0; k < 4; k ++ ) {

		const v = tetrahedra[ n4 + k ];
		const position = v === a ? 0 : v === b ? 1 : v === c ? 2 : - 1;
		if ( position < 0 ) j = k;
		else if ( matched === 0 ) { p0 = position; matched = 1; } else if ( matched === 1 ) { p1 = position; matched = 2; } else { p2 = position; matched = 3; }

	}

	if ( matched !== 3 || j < 0 ) {

		fail( 'neighbors', where, `neighbors[${f}]: tetrahedron ${n} does not contain the face of tetrahedron ${t} opposite its vertex ${i}.` );

	}

	if ( neighbors[ n4 + j ] !== t ) {

		fail( 'neighbors', where, `neighbors[${f}] = ${n} but neighbors[${n4 + j}] = ${neighbors[ n4 + j ]}, not ${t}: links must be symmetric.` );

	}

	// Parity of the permutation taking t's face order to n's (both tetrahedra positive): the apexes
	// lie on opposite sides exactly when the induced face orientations differ.
	const inversions = ( p0 > p1 ? 1 : 0 ) + ( p0 > p2 ? 1 : 0 ) + ( p1 > p2 ? 1 : 0 );
	if ( ( inversions + i + j ) % 2 === 0 ) {

		fail( 'neighbors', where, `tetrahedra ${t} and ${n} lie on the same side of their shared face (they overlap).` );

	}

}

/**
 * Checks tetrahedron and neighbour indices given as plain numbers (the JSON form, encoder input)
 * before they are converted to typed arrays, where −1.5 or 2^32 would wrap silently.
 */
function checkIndices( where: string, probeCount: number, tetrahedra: ArrayLike<number>, neighbors: ArrayLike<number> ): void {

	const tetCount = tetrahedra.length / 4;
	for ( let i = 0; i < tetrahedra.length; i ++ ) {

		const v = tetrahedra[ i ];
		if ( ! ( v >= 0 && v < probeCount && v === Math.floor( v ) ) ) {

			fail( 'range', where, `tetrahedra[${i}] = ${v} is not a probe index (0..${probeCount - 1}).` );

		}

	}

	for ( let i = 0; i < neighbors.length; i ++ ) {

		const n = neighbors[ i ];
		if ( ! ( n >= - 1 && n < tetCount && n === Math.floor( n ) ) || n === i >> 2 ) {

			fail( 'range', where, `neighbors[${i}] = ${n} is neither −1 nor another tetrahedron's index (0..${tetCount - 1}).` );

		}

	}

}

/**
 * Checks tetrahedra and neighbour links against the positions: indices in range, every
 * tetrahedron positively oriented (exact predicate on the float64 positions), every link t →(i) n
 * answered by n → t across the same three vertices, with the two apexes on opposite sides of the
 * shared face, no hull face shared. O(tetrahedra).
 */
function checkTetrahedra( where: string, positions: Float64Array, tetrahedra: Uint32Array, neighbors: Int32Array ): void {

	const probeCount = positions.length / 3;
	const tetCount = tetrahedra.length / 4;
	for ( let i = 0; i < tetrahedra.length; i ++ ) {

		if ( tetrahedra[ i ] >= probeCount ) fail( 'range', where, `tetrahedra[${i}] = ${tetrahedra[ i ]} is not a probe index (0..${probeCount - 1}).` );

	}

	for ( let i = 0; i < neighbors.length; i ++ ) {

		const n = neighbors[ i ];
		if ( n < - 1 || n >= tetCount || n === i >> 2 ) {

			fail( 'range', where, `neighbors[${i}] = ${n} is neither −1 nor another tetrahedron's index (0..${tetCount - 1}).` );

		}

	}

	for ( let t = 0; t < tetCount; t ++ ) {

		const t4 = 4 * t;
		if ( ! ( orient( positions, tetrahedra[ t4 ], tetrahedra[ t4 + 1 ], tetrahedra[ t4 + 2 ], tetrahedra[ t4 + 3 ] ) > 0 ) ) {

			fail( 'orientation', where, `tetrahedron ${t} (probes ${tetrahedra[ t4 ]}, ${tetrahedra[ t4 + 1 ]}, ${tetrahedra[ t4 + 2 ]}, ${tetrahedra[ t4 + 3 ]}) is not positively oriented (flat or inverted).` );

		}

	}

	// Each verified link t → n (n > t) also verifies n → t, so links are checked from their lower
	// end only; if that leaves a link unaccounted for, the upper ends are checked too, and one of
	// them fails with a precise message.
	let links = 0, pairs = 0;
	for ( let f = 0; f < neighbors.length; f ++ ) {

		const n = neighbors[ f ];
		if ( n < 0 ) continue;
		links ++;
		if ( n > f >> 2 ) {

			checkLink( where, tetrahedra, neighbors, f );
			pairs ++;

		}

	}

	if ( links !== 2 * pairs ) {

		for ( let f = 0; f < neighbors.length; f ++ ) if ( neighbors[ f ] >= 0 && neighbors[ f ] < f >> 2 ) checkLink( where, tetrahedra, neighbors, f );
		fail( 'neighbors', where, `${links} neighbour links do not pair up (${pairs} symmetric pairs).` );

	}

	checkHullFaces( where, probeCount, tetrahedra, neighbors );

}

function faceKey( tetrahedra: Uint32Array, t: number, i: number ): string {

	let a = - 1, b = - 1, c = - 1;
	for ( let k = 0; k < 4; k ++ ) {

		if ( k === i ) continue;
		const v = tetrahedra[ 4 * t + k ];
		if ( a < 0 ) a = v; else if ( b < 0 ) b = v; else c = v;

	}

	const lo = Math.min( a, b, c ), hi = Math.max( a, b, c );
	return `${lo},${a + b + c - lo - hi},${hi}`;

}

/**
 * Symmetric, face-matched links leave one way for a face to belong to three tetrahedra: a hull
 * face (−1) that is also another tetrahedron's face. Hull faces are few (they and their vertices
 * lie on the convex hull), so they are hashed, and only faces whose three vertices are all hull
 * vertices are looked up.
 */
function checkHullFaces( where: string, probeCount: number, tetrahedra: Uint32Array, neighbors: Int32Array ): void {

	const tetCount = tetrahedra.length / 4;
	const onHull = new Uint8Array( probeCount );
	const hull = new Map<string, number>();
	for ( let f = 0; f < 4 * tetCount; f ++ ) {

		if ( neighbors[ f ] !== - 1 ) continue;
		const t = f >> 2, i = f & 3;
		const key = faceKey( tetrahedra, t, i );
		const other = hull.get( key );
		if ( other !== undefined ) fail( 'neighbors', where, `the hull face ${key} belongs to tetrahedra ${other >> 2} and ${t} (they overlap).` );
		hull.set( key, f );
		for ( let k = 0; k < 4; k ++ ) if ( k !== i ) onHull[ tetrahedra[ 4 * t + k ] ] = 1;

	}

	for ( let f = 0; f < 4 * tetCount; f ++ ) {

		if ( neighbors[ f ] < 0 ) continue;
		const t = f >> 2, i = f & 3;
		let all = true;
		for ( let k = 0; k < 4 && all; k ++ ) if ( k !== i && onHull[ tetrahedra[ 4 * t + k ] ] === 0 ) all = false;
		if ( ! all ) continue;
		const key = faceKey( tetrahedra, t, i );
		const other = hull.get( key );
		if ( other !== undefined ) fail( 'neighbors', where, `face ${key} is a hull face of tetrahedron ${other >> 2} and an inner face of tetrahedron ${t} (they overlap).` );

	}

}

function checkCapture( where: string, capture: unknown ): BakedCapture {

	if ( capture === undefined || capture === null ) return {};
	if ( typeof capture !== 'object' || Array.isArray( capture ) ) fail( 'json', where, 'capture must be an object.' );
	const source = capture as Record<string, unknown>;
	const out: BakedCapture = checkCaptureSettings( where, 'capture', source );
	if ( source.roles !== undefined ) {

		if ( typeof source.roles !== 'object' || source.roles === null || Array.isArray( source.roles ) ) fail( 'json', where, 'capture.roles must be an object.' );
		out.roles = {};
		for ( const [ role, settings ] of Object.entries( source.roles as Record<string, unknown> ) ) {

			if ( ! BAKED_ROLES.includes( role as BakedProbeRole ) ) fail( 'range', where, `capture.roles has the unknown role "${role}"; expected one of ${BAKED_ROLES.join( ', ' )}.` );
			if ( typeof settings !== 'object' || settings === null || Array.isArray( settings ) ) fail( 'json', where, `capture.roles.${role} must be an object.` );
			out.roles[ role as BakedProbeRole ] = checkCaptureSettings( where, `capture.roles.${role}`, settings as Record<string, unknown> );

		}

	}

	return out;

}

function checkCaptureSettings( where: string, name: string, s: Record<string, unknown> ): BakedCaptureSettings {

	const out: BakedCaptureSettings = {};
	const number = ( key: 'resolution' | 'near' | 'far' ): number | undefined => {

		const v = s[ key ];
		if ( v === undefined ) return undefined;
		if ( typeof v !== 'number' || ! Number.isFinite( v ) ) fail( typeof v === 'number' ? 'nan' : 'json', where, `${name}.${key} is ${String( v )}; expected a finite number.` );
		return v;

	};

	const resolution = number( 'resolution' ), near = number( 'near' ), far = number( 'far' );
	if ( resolution !== undefined ) {

		if ( ! Number.isInteger( resolution ) || resolution < 1 ) fail( 'range', where, `${name}.resolution is ${resolution}; expected an integer ≥ 1.` );
		out.resolution = resolution;

	}

	if ( near !== undefined ) {

		if ( ! ( near > 0 ) ) fail( 'range', where, `${name}.near is ${near}; expected > 0.` );
		out.near = near;

	}

	if ( far !== undefined ) {

		if ( ! ( far > ( near ?? 0 ) ) ) fail( 'range', where, `${name}.far is ${far}; expected > near (${near ?? 0}).` );
		out.far = far;

	}

	if ( s.type !== undefined ) {

		if ( s.type !== 'half' && s.type !== 'float' ) fail( 'range', where, `${name}.type is ${JSON.stringify( s.type )}; expected "half" or "float".` );
		out.type = s.type;

	}

	if ( s.solidAngle !== undefined ) {

		if ( s.solidAngle !== 'exact' && s.solidAngle !== 'paper' ) fail( 'range', where, `${name}.solidAngle is ${JSON.stringify( s.solidAngle )}; expected "exact" or "paper".` );
		out.solidAngle = s.solidAngle;

	}

	return out;

}

function isNumberArray( value: unknown ): value is ArrayLike<number> {

	return ArrayBuffer.isView( value ) ? ! ( value instanceof DataView ) : Array.isArray( value );

}

function numbers( where: string, name: string, value: unknown, elementsPer: number ): ArrayLike<number> {

	if ( ! isNumberArray( value ) ) fail( 'argument', where, `${name} must be an array or typed array of numbers.` );
	const array = value as ArrayLike<number>;
	if ( array.length % elementsPer !== 0 ) fail( 'count', where, `${name} has length ${array.length}, not a multiple of ${elementsPer}.` );
	if ( Array.isArray( array ) ) {

		for ( let i = 0; i < array.length; i ++ ) {

			const v = array[ i ];
			// JSON.stringify writes NaN and ±Infinity as null.
			if ( v === null ) fail( 'nan', where, `${name}[${i}] is null (NaN or Infinity written as JSON); every value must be a finite number.` );
			if ( typeof v !== 'number' ) fail( 'argument', where, `${name}[${i}] is ${JSON.stringify( v ) ?? String( v )}, not a number.` );

		}

	}

	return array;

}

function boxOf( positions: Float64Array ): Float64Array {

	const box = new Float64Array( [ Infinity, Infinity, Infinity, - Infinity, - Infinity, - Infinity ] );
	for ( let i = 0; i < positions.length; i += 3 ) {

		for ( let k = 0; k < 3; k ++ ) {

			const v = positions[ i + k ];
			if ( v < box[ k ] ) box[ k ] = v;
			if ( v > box[ 3 + k ] ) box[ 3 + k ] = v;

		}

	}

	return box;

}

/**
 * Checks a volume given as plain data (the encoders' input, the JSON form) and returns it in the
 * normalized {@link BakedVolumeData} shape (typed arrays, defaults filled in). Throws
 * {@link BakedVolumeError} naming the field and index of the first problem.
 * @param where Function name for messages.
 */
export function validateBakedVolume( input: BakedVolumeInput, where = 'validateBakedVolume' ): BakedVolumeData {

	if ( input === null || typeof input !== 'object' ) fail( 'argument', where, 'expected a volume { positions, sh, tetrahedra?, neighbors?, names?, roles?, zones?, bounds?, capture?, metadata? }.' );
	const positionsIn = numbers( where, 'positions', input.positions, 3 );
	const probeCount = positionsIn.length / 3;
	if ( probeCount < 1 ) fail( 'count', where, 'positions holds no probe.' );
	checkFinite( where, 'positions', positionsIn );
	const positions = positionsIn instanceof Float64Array ? positionsIn : Float64Array.from( positionsIn );

	const shIn = numbers( where, 'sh', input.sh, 27 );
	if ( shIn.length !== 27 * probeCount ) fail( 'count', where, `sh has ${shIn.length} values; ${probeCount} probes need 27 each (${27 * probeCount}).` );
	checkFinite( where, 'sh', shIn );
	const sh = shIn instanceof Float32Array ? shIn : Float32Array.from( shIn );
	// Float32 storage: a finite float64 beyond ±3.4e38 would become Infinity.
	if ( ! ( shIn instanceof Float32Array ) ) checkFinite( where, 'sh (as float32)', sh );

	let tetrahedra: Uint32Array = new Uint32Array( 0 ), neighbors: Int32Array = new Int32Array( 0 );
	if ( input.tetrahedra !== undefined || input.neighbors !== undefined ) {

		const tetIn = numbers( where, 'tetrahedra', input.tetrahedra, 4 );
		const nbrIn = numbers( where, 'neighbors', input.neighbors, 4 );
		if ( nbrIn.length !== tetIn.length ) fail( 'count', where, `neighbors has ${nbrIn.length} entries; ${tetIn.length / 4} tetrahedra need 4 each (${tetIn.length}).` );
		checkIndices( where, probeCount, tetIn, nbrIn );
		tetrahedra = tetIn instanceof Uint32Array ? tetIn : Uint32Array.from( tetIn );
		neighbors = nbrIn instanceof Int32Array ? nbrIn : Int32Array.from( nbrIn );
		checkTetrahedra( where, positions, tetrahedra, neighbors );

	}

	const names: string[] = [];
	if ( input.names !== undefined ) {

		if ( ! Array.isArray( input.names ) ) fail( 'argument', where, 'names must be an array of strings.' );
		if ( input.names.length !== probeCount ) fail( 'count', where, `names has ${input.names.length} entries for ${probeCount} probes.` );
		for ( let i = 0; i < probeCount; i ++ ) {

			const name = input.names[ i ];
			if ( typeof name !== 'string' ) fail( 'argument', where, `names[${i}] is not a string.` );
			checkText( where, `names[${i}]`, name );
			names.push( name );

		}

	} else {

		for ( let i = 0; i < probeCount; i ++ ) names.push( '' );

	}

	const roles: BakedProbeRole[] = [];
	if ( input.roles !== undefined ) {

		if ( ! Array.isArray( input.roles ) ) fail( 'argument', where, 'roles must be an array of strings.' );
		if ( input.roles.length !== probeCount ) fail( 'count', where, `roles has ${input.roles.length} entries for ${probeCount} probes.` );
		for ( let i = 0; i < probeCount; i ++ ) {

			const role = input.roles[ i ];
			if ( ! BAKED_ROLES.includes( role ) ) fail( 'range', where, `roles[${i}] is ${JSON.stringify( role ) ?? String( role )}; expected one of ${BAKED_ROLES.join( ', ' )}.` );
			roles.push( role );

		}

	} else {

		for ( let i = 0; i < probeCount; i ++ ) roles.push( 'fill' );

	}

	const zones: BakedZone[] = [];
	if ( input.zones !== undefined ) {

		if ( ! Array.isArray( input.zones ) ) fail( 'argument', where, 'zones must be an array of { name, probes, bounds? }.' );
		for ( let z = 0; z < input.zones.length; z ++ ) {

			const zone = input.zones[ z ];
			if ( zone === null || typeof zone !== 'object' ) fail( 'argument', where, `zones[${z}] must be an object { name, probes, bounds? }.` );
			if ( typeof zone.name !== 'string' ) fail( 'argument', where, `zones[${z}].name must be a string.` );
			checkText( where, `zones[${z}].name`, zone.name );
			const probes = numbers( where, `zones[${z}].probes`, zone.probes, 1 );
			for ( let i = 0; i < probes.length; i ++ ) {

				const p = probes[ i ];
				if ( ! ( p >= 0 && p < probeCount && p === Math.floor( p ) ) ) fail( 'range', where, `zones[${z}].probes[${i}] = ${p} is not a probe index (0..${probeCount - 1}).` );

			}

			const bounds = zone.bounds === undefined ? [] : numbers( where, `zones[${z}].bounds`, zone.bounds, 6 );
			checkFinite( where, `zones[${z}].bounds`, bounds );
			for ( let b = 0; b < bounds.length; b += 6 ) checkBox( where, `zones[${z}].bounds`, bounds, b );
			zones.push( {
				name: zone.name,
				probes: probes instanceof Uint32Array ? probes : Uint32Array.from( probes ),
				bounds: bounds instanceof Float64Array ? bounds : Float64Array.from( bounds ),
			} );

		}

	}

	let bounds: Float64Array;
	if ( input.bounds !== undefined ) {

		const b = numbers( where, 'bounds', input.bounds, 6 );
		if ( b.length !== 6 ) fail( 'count', where, `bounds must hold 6 numbers (min x, y, z, max x, y, z), got ${b.length}.` );
		checkFinite( where, 'bounds', b );
		checkBox( where, 'bounds', b, 0 );
		bounds = b instanceof Float64Array ? b : Float64Array.from( b );

	} else {

		bounds = boxOf( positions );

	}

	const capture = checkCapture( where, input.capture );
	const metadata = input.metadata ?? '';
	if ( typeof metadata !== 'string' ) fail( 'argument', where, 'metadata must be a string.' );
	checkText( where, 'metadata', metadata );

	return { positions, sh, tetrahedra, neighbors, names, roles, zones, bounds, capture, metadata };

}

// ---------------------------------------------------------------------------------------------
// Binary writer.
// ---------------------------------------------------------------------------------------------

// Float arithmetic, not `& ~7`: sizes computed from hostile counts exceed 32 bits.
const align8 = ( n: number ): number => Math.ceil( n / 8 ) * 8;

/**
 * Writes a volume in the binary format of docs/format.md (version 1.0, little-endian).
 * Validates the input first (same rules as the reader), so a written file always loads.
 * @throws {BakedVolumeError} on invalid input, on an SH value beyond ±65504 with `'float16'`
 * (code `'float16-overflow'`), or when the file would exceed 4 GiB.
 */
export function encodeBakedVolume( input: BakedVolumeInput, options: EncodeBakedVolumeOptions = {} ): ArrayBuffer {

	const where = 'encodeBakedVolume';
	const precision = options.precision ?? 'float32';
	if ( precision !== 'float16' && precision !== 'float32' ) fail( 'argument', where, `precision is ${JSON.stringify( precision )}; expected "float16" or "float32".` );
	const data = validateBakedVolume( input, where );
	const probeCount = data.positions.length / 3;
	const tetCount = data.tetrahedra.length / 4;

	// Section payloads that are not plain typed arrays.
	let shBytes: Uint8Array;
	if ( precision === 'float16' ) {

		const half = new Uint16Array( data.sh.length );
		for ( let i = 0; i < half.length; i ++ ) {

			const h = toFloat16Bits( data.sh[ i ] );
			if ( h < 0 ) fail( 'float16-overflow', where, `sh[${i}] = ${data.sh[ i ]} is beyond the float16 range (±${FLOAT16_MAX}); use { precision: 'float32' }.` );
			half[ i ] = h;

		}

		shBytes = new Uint8Array( half.buffer );

	} else {

		shBytes = new Uint8Array( data.sh.buffer, data.sh.byteOffset, data.sh.byteLength );

	}

	const roleBytes = new Uint8Array( probeCount );
	for ( let i = 0; i < probeCount; i ++ ) roleBytes[ i ] = BAKED_ROLES.indexOf( data.roles[ i ] );

	const encodedNames = data.names.map( ( name ) => utf8Encoder.encode( name ) );
	const nameBytes = encodedNames.reduce( ( sum, b ) => sum + b.length, 0 );
	const zoneNames = data.zones.map( ( zone ) => utf8Encoder.encode( zone.name ) );
	const captureText = Object.keys( data.capture ).length > 0 ? utf8Encoder.encode( JSON.stringify( data.capture ) ) : null;
	const metadataText = data.metadata.length > 0 ? utf8Encoder.encode( data.metadata ) : null;

	type Section = { id: number; required: boolean; length: number; write: ( view: DataView, bytes: Uint8Array, at: number ) => void };
	const sections: Section[] = [];
	const typed = ( id: number, array: ArrayBufferView ): Section => ( {
		id, required: true, length: array.byteLength,
		write: ( view, bytes, at ) => writeLE( view, bytes, at, array ),
	} );

	sections.push( typed( BAKED_SECTION.POSITIONS, data.positions ) );
	sections.push( { id: BAKED_SECTION.SH, required: true, length: shBytes.length, write: ( view, bytes, at ) => {

		if ( precision === 'float32' ) writeLE( view, bytes, at, data.sh );
		else writeLE( view, bytes, at, new Uint16Array( shBytes.buffer ) );

	} } );
	if ( tetCount > 0 ) {

		sections.push( typed( BAKED_SECTION.TETRAHEDRA, data.tetrahedra ) );
		sections.push( typed( BAKED_SECTION.NEIGHBORS, data.neighbors ) );

	}

	sections.push( { id: BAKED_SECTION.ROLES, required: true, length: probeCount, write: ( _view, bytes, at ) => bytes.set( roleBytes, at ) } );
	if ( nameBytes > 0 ) {

		sections.push( { id: BAKED_SECTION.NAMES, required: true, length: 4 * probeCount + nameBytes, write: ( view, bytes, at ) => {

			let end = 0, blob = at + 4 * probeCount;
			encodedNames.forEach( ( b, i ) => {

				bytes.set( b, blob + end );
				end += b.length;
				view.setUint32( at + 4 * i, end, true );

			} );

		} } );

	}

	if ( data.zones.length > 0 ) {

		let length = 0;
		data.zones.forEach( ( zone, z ) => length += 16 + align8( zoneNames[ z ].length ) + align8( 4 * zone.probes.length ) + 8 * zone.bounds.length );
		sections.push( { id: BAKED_SECTION.ZONES, required: true, length, write: ( view, bytes, at ) => {

			data.zones.forEach( ( zone, z ) => {

				const boxes = zone.bounds.length / 6;
				view.setUint32( at, zoneNames[ z ].length, true );
				view.setUint32( at + 4, zone.probes.length, true );
				view.setUint32( at + 8, boxes, true );
				at += 16;
				bytes.set( zoneNames[ z ], at );
				at += align8( zoneNames[ z ].length );
				for ( let i = 0; i < zone.probes.length; i ++ ) view.setUint32( at + 4 * i, zone.probes[ i ], true );
				at += align8( 4 * zone.probes.length );
				for ( let i = 0; i < zone.bounds.length; i ++ ) view.setFloat64( at + 8 * i, zone.bounds[ i ], true );
				at += 8 * zone.bounds.length;

			} );

		} } );

	}

	sections.push( typed( BAKED_SECTION.BOUNDS, data.bounds ) );
	if ( captureText ) sections.push( { id: BAKED_SECTION.CAPTURE, required: false, length: captureText.length, write: ( _view, bytes, at ) => bytes.set( captureText, at ) } );
	if ( metadataText ) sections.push( { id: BAKED_SECTION.METADATA, required: false, length: metadataText.length, write: ( _view, bytes, at ) => bytes.set( metadataText, at ) } );

	let offset = align8( HEADER_SIZE + ENTRY_SIZE * sections.length );
	const offsets = sections.map( ( section ) => {

		const at = offset;
		offset = align8( offset + section.length );
		return at;

	} );
	const fileLength = offset;
	if ( fileLength > 0xFFFFFFFF ) fail( 'count', where, `the volume needs ${fileLength} bytes; the format's limit is 4 GiB.` );

	const buffer = new ArrayBuffer( fileLength );
	const view = new DataView( buffer );
	const bytes = new Uint8Array( buffer );
	bytes.set( BAKED_VOLUME_MAGIC, 0 );
	view.setUint16( 8, BAKED_VOLUME_VERSION_MAJOR, true );
	view.setUint16( 10, BAKED_VOLUME_VERSION_MINOR, true );
	view.setUint32( 16, fileLength, true );
	view.setUint32( 20, HEADER_SIZE, true );
	view.setUint32( 24, precision === 'float16' ? FLAG_SH_FLOAT16 : 0, true );
	view.setUint32( 28, probeCount, true );
	view.setUint32( 32, tetCount, true );
	view.setUint32( 36, data.zones.length, true );
	view.setUint32( 40, sections.length, true );
	view.setUint32( 44, nameBytes, true );
	sections.forEach( ( section, s ) => {

		const entry = HEADER_SIZE + ENTRY_SIZE * s;
		view.setUint32( entry, section.id, true );
		view.setUint32( entry + 4, section.required ? SECTION_REQUIRED : 0, true );
		view.setUint32( entry + 8, offsets[ s ], true );
		view.setUint32( entry + 12, section.length, true );
		section.write( view, bytes, offsets[ s ] );

	} );
	view.setUint32( 12, crc32( bytes, 16, fileLength ), true );
	return buffer;

}

/** Copies a typed array's elements little-endian at `at`. */
function writeLE( view: DataView, bytes: Uint8Array, at: number, array: ArrayBufferView ): void {

	if ( LITTLE_ENDIAN ) {

		bytes.set( new Uint8Array( array.buffer, array.byteOffset, array.byteLength ), at );
		return;

	}

	if ( array instanceof Float64Array ) for ( let i = 0; i < array.length; i ++ ) view.setFloat64( at + 8 * i, array[ i ], true );
	else if ( array instanceof Float32Array ) for ( let i = 0; i < array.length; i ++ ) view.setFloat32( at + 4 * i, array[ i ], true );
	else if ( array instanceof Uint32Array ) for ( let i = 0; i < array.length; i ++ ) view.setUint32( at + 4 * i, array[ i ], true );
	else if ( array instanceof Int32Array ) for ( let i = 0; i < array.length; i ++ ) view.setInt32( at + 4 * i, array[ i ], true );
	else if ( array instanceof Uint16Array ) for ( let i = 0; i < array.length; i ++ ) view.setUint16( at + 2 * i, array[ i ], true );

}

// ---------------------------------------------------------------------------------------------
// Binary reader.
// ---------------------------------------------------------------------------------------------

type TypedCtor = Float64ArrayConstructor | Float32ArrayConstructor | Uint32ArrayConstructor | Int32ArrayConstructor | Uint16ArrayConstructor;

/**
 * A typed array over `length` elements at `at`: a view of the buffer when the platform is
 * little-endian and the address is aligned (no copy), else a copy read through the DataView.
 */
function readTyped<T extends TypedCtor>( Ctor: T, view: DataView, at: number, length: number ): InstanceType<T> {

	const size = Ctor.BYTES_PER_ELEMENT;
	const address = view.byteOffset + at;
	if ( LITTLE_ENDIAN && address % size === 0 ) return new Ctor( view.buffer as ArrayBuffer, address, length ) as InstanceType<T>;
	if ( LITTLE_ENDIAN ) return new Ctor( view.buffer.slice( address, address + size * length ) as ArrayBuffer ) as InstanceType<T>;
	const out = new Ctor( length ) as InstanceType<T>;
	for ( let i = 0; i < length; i ++ ) {

		const p = at + size * i;
		out[ i ] = Ctor === Float64Array ? view.getFloat64( p, true ) : Ctor === Float32Array ? view.getFloat32( p, true )
			: Ctor === Uint32Array ? view.getUint32( p, true ) : Ctor === Int32Array ? view.getInt32( p, true ) : view.getUint16( p, true );

	}

	return out;

}

function readString( where: string, name: string, bytes: Uint8Array, at: number, length: number ): string {

	try {

		return utf8Decoder.decode( bytes.subarray( at, at + length ) );

	} catch {

		fail( 'utf8', where, `${name} is not valid UTF-8.` );

	}

}

/**
 * Reads a volume written by {@link encodeBakedVolume} (any 1.x minor version) and checks it
 * completely; see docs/format.md for the layout and the rules. Typed arrays in the result are views
 * of `buffer` where alignment allows (no copy): do not reuse the buffer while the data is in use.
 * Bytes after the declared file length are ignored.
 * @param buffer The file, or a view of it (e.g. a Node `Buffer` or a glTF bufferView).
 * @throws {BakedVolumeError} with `code` naming the failure class; never another error type.
 */
export function decodeBakedVolume( buffer: ArrayBuffer | ArrayBufferView ): BakedVolumeData {

	const where = 'decodeBakedVolume';
	let bytes: Uint8Array;
	if ( buffer instanceof ArrayBuffer ) bytes = new Uint8Array( buffer );
	else if ( ArrayBuffer.isView( buffer ) ) bytes = new Uint8Array( buffer.buffer, buffer.byteOffset, buffer.byteLength );
	else fail( 'argument', where, 'expected an ArrayBuffer or a typed array / DataView of the file.' );
	const view = new DataView( bytes.buffer, bytes.byteOffset, bytes.byteLength );
	const available = bytes.length;

	for ( let i = 0; i < 8; i ++ ) {

		if ( i >= available ) fail( 'truncated', where, `the buffer ends after ${available} bytes, inside the magic bytes.` );
		if ( bytes[ i ] !== BAKED_VOLUME_MAGIC[ i ] ) fail( 'bad-magic', where, 'not a baked light probe volume (the first 8 bytes are not the format\'s magic bytes AB 4C 50 56 0D 0A 1A 0A).' );

	}

	if ( available < HEADER_SIZE ) fail( 'truncated', where, `the buffer is ${available} bytes, shorter than the ${HEADER_SIZE}-byte header.` );
	const major = view.getUint16( 8, true ), minor = view.getUint16( 10, true );
	if ( major > BAKED_VOLUME_VERSION_MAJOR ) fail( 'version', where, `version ${major}.${minor} is newer than this reader (supports ≤ ${BAKED_VOLUME_VERSION_MAJOR}.x).` );
	if ( major < 1 ) fail( 'version', where, `version ${major}.${minor} is not a released version of the format (this reader supports 1.x).` );
	const fileLength = view.getUint32( 16, true );
	if ( fileLength > available ) fail( 'truncated', where, `the header declares ${fileLength} bytes but the buffer holds ${available}: the file is truncated.` );
	if ( fileLength < HEADER_SIZE ) fail( 'header', where, `the declared file length ${fileLength} is shorter than the header.` );
	const storedCRC = view.getUint32( 12, true );
	const computedCRC = crc32( bytes, 16, fileLength );
	if ( storedCRC !== computedCRC ) {

		fail( 'checksum', where, `corrupted: CRC-32 of bytes 16..${fileLength} is 0x${computedCRC.toString( 16 ).padStart( 8, '0' )}, the header says 0x${storedCRC.toString( 16 ).padStart( 8, '0' )}.` );

	}

	const headerSize = view.getUint32( 20, true );
	if ( headerSize < HEADER_SIZE || headerSize % 8 !== 0 || headerSize > fileLength ) fail( 'header', where, `header size ${headerSize} is not a multiple of 8 between ${HEADER_SIZE} and the file length ${fileLength}.` );
	const flags = view.getUint32( 24, true );
	if ( ( flags & ~ FLAG_SH_FLOAT16 ) !== 0 ) fail( 'header', where, `flags 0x${flags.toString( 16 )} set reserved bits (only bit 0, SH as float16, is defined in 1.x).` );
	const probeCount = view.getUint32( 28, true );
	const tetCount = view.getUint32( 32, true );
	const zoneCount = view.getUint32( 36, true );
	const sectionCount = view.getUint32( 40, true );
	const nameBytes = view.getUint32( 44, true );
	if ( sectionCount > ( fileLength - headerSize ) / ENTRY_SIZE ) fail( 'count', where, `sectionCount ${sectionCount} does not fit in the ${fileLength}-byte file.` );
	const tableEnd = headerSize + ENTRY_SIZE * sectionCount;

	// Section table: every section inside the file, after the table, 8-aligned, no overlap, no duplicate.
	const found = new Map<number, { offset: number; length: number }>();
	const spans: [ number, number, number ][] = [];
	for ( let s = 0; s < sectionCount; s ++ ) {

		const entry = headerSize + ENTRY_SIZE * s;
		const id = view.getUint32( entry, true ), sectionFlags = view.getUint32( entry + 4, true );
		const offset = view.getUint32( entry + 8, true ), length = view.getUint32( entry + 12, true );
		if ( offset % 8 !== 0 ) fail( 'section', where, `section ${sectionName( id )} starts at ${offset}, not a multiple of 8.` );
		if ( offset < tableEnd || offset + length > fileLength ) fail( 'section', where, `section ${sectionName( id )} (bytes ${offset}..${offset + length}) is outside the data area ${tableEnd}..${fileLength}.` );
		if ( found.has( id ) ) fail( 'section', where, `section ${sectionName( id )} appears twice.` );
		if ( ! KNOWN_SECTIONS.has( id ) && ( sectionFlags & SECTION_REQUIRED ) ) fail( 'version', where, `section ${sectionName( id )} is required but unknown to this reader (version ${major}.${minor} file).` );
		found.set( id, { offset, length } );
		spans.push( [ offset, offset + length, id ] );

	}

	spans.sort( ( a, b ) => a[ 0 ] - b[ 0 ] );
	for ( let s = 1; s < spans.length; s ++ ) {

		if ( spans[ s ][ 0 ] < spans[ s - 1 ][ 1 ] ) fail( 'section', where, `sections ${sectionName( spans[ s - 1 ][ 2 ] )} and ${sectionName( spans[ s ][ 2 ] )} overlap.` );

	}

	const section = ( id: number, expected: number | null, required: boolean, what: string ): { offset: number; length: number } | null => {

		const entry = found.get( id );
		if ( ! entry ) {

			if ( required ) fail( 'section', where, `the required section ${sectionName( id )} (${what}) is missing.` );
			return null;

		}

		if ( expected !== null && entry.length !== expected ) {

			fail( 'count', where, `section ${sectionName( id )} is ${entry.length} bytes but the header's counts need ${expected} (${what}).` );

		}

		return entry;

	};

	// Counts against section lengths before anything proportional to a count is allocated; the
	// sections are inside the file, so every allocation below is bounded by the file size.
	if ( probeCount < 1 ) fail( 'count', where, 'probeCount is 0; a volume has at least one probe.' );
	const half = ( flags & FLAG_SH_FLOAT16 ) !== 0;
	const pos = section( BAKED_SECTION.POSITIONS, 24 * probeCount, true, `${probeCount} probes × 3 float64` )!;
	const shs = section( BAKED_SECTION.SH, ( half ? 54 : 108 ) * probeCount, true, `${probeCount} probes × 27 ${half ? 'float16' : 'float32'}` )!;
	const tets = section( BAKED_SECTION.TETRAHEDRA, 16 * tetCount, tetCount > 0, `${tetCount} tetrahedra × 4 u32` );
	const nbrs = section( BAKED_SECTION.NEIGHBORS, 16 * tetCount, tetCount > 0, `${tetCount} tetrahedra × 4 i32` );
	const rls = section( BAKED_SECTION.ROLES, probeCount, false, `${probeCount} probes × u8` );
	const nms = section( BAKED_SECTION.NAMES, 4 * probeCount + nameBytes, false, `${probeCount} u32 ends + ${nameBytes} bytes of UTF-8` );
	if ( ! nms && nameBytes !== 0 ) fail( 'count', where, `the header declares ${nameBytes} bytes of names but there is no NAME section.` );
	const zns = section( BAKED_SECTION.ZONES, null, zoneCount > 0, `${zoneCount} zones` );
	if ( zns && zoneCount > zns.length / 16 ) fail( 'count', where, `zoneCount ${zoneCount} does not fit in the ${zns.length}-byte ZONE section.` );
	const bnd = section( BAKED_SECTION.BOUNDS, 48, false, '6 float64' );
	const cpt = section( BAKED_SECTION.CAPTURE, null, false, 'UTF-8 JSON' );
	const mta = section( BAKED_SECTION.METADATA, null, false, 'UTF-8 text' );

	const positions = readTyped( Float64Array, view, pos.offset, 3 * probeCount );
	checkFinite( where, 'positions', positions );

	let sh: Float32Array;
	if ( half ) {

		const bits = readTyped( Uint16Array, view, shs.offset, 27 * probeCount );
		const table = float16Table();
		sh = new Float32Array( bits.length );
		for ( let i = 0; i < bits.length; i ++ ) {

			if ( ( bits[ i ] & 0x7C00 ) === 0x7C00 ) fail( 'nan', where, `sh[${i}] is ${bits[ i ] & 0x3FF ? 'NaN' : 'Infinity'} (float16 bits 0x${bits[ i ].toString( 16 )}); every value must be finite.` );
			sh[ i ] = table[ bits[ i ] ];

		}

	} else {

		sh = readTyped( Float32Array, view, shs.offset, 27 * probeCount );
		checkFinite( where, 'sh', sh );

	}

	let tetrahedra: Uint32Array = new Uint32Array( 0 ), neighbors: Int32Array = new Int32Array( 0 );
	if ( tetCount > 0 ) {

		tetrahedra = readTyped( Uint32Array, view, tets!.offset, 4 * tetCount );
		neighbors = readTyped( Int32Array, view, nbrs!.offset, 4 * tetCount );
		checkTetrahedra( where, positions, tetrahedra, neighbors );

	}

	const roles: BakedProbeRole[] = new Array( probeCount );
	for ( let i = 0; i < probeCount; i ++ ) {

		const code = rls ? bytes[ rls.offset + i ] : 3;
		if ( code >= BAKED_ROLES.length ) fail( 'range', where, `roles[${i}] has code ${code}; expected 0 (sky), 1 (bounce), 2 (bleed) or 3 (fill).` );
		roles[ i ] = BAKED_ROLES[ code ];

	}

	const names: string[] = new Array( probeCount );
	if ( nms ) {

		const blob = nms.offset + 4 * probeCount;
		let start = 0;
		for ( let i = 0; i < probeCount; i ++ ) {

			const end = view.getUint32( nms.offset + 4 * i, true );
			if ( end < start || end > nameBytes ) fail( 'range', where, `names: end offset ${i} is ${end}, outside ${start}..${nameBytes}.` );
			names[ i ] = readString( where, `names[${i}]`, bytes, blob + start, end - start );
			start = end;

		}

		if ( start !== nameBytes ) fail( 'count', where, `names use ${start} of the ${nameBytes} bytes the header declares.` );

	} else {

		names.fill( '' );

	}

	const zones: BakedZone[] = [];
	if ( zns ) {

		let at = zns.offset;
		const end = zns.offset + zns.length;
		for ( let z = 0; z < zoneCount; z ++ ) {

			if ( at + 16 > end ) fail( 'count', where, `zone ${z}'s record starts beyond the ZONE section.` );
			const nameLength = view.getUint32( at, true ), count = view.getUint32( at + 4, true ), boxes = view.getUint32( at + 8, true );
			// Each size is checked against the bytes left before it is used, in float64 arithmetic (no overflow).
			const size = 16 + align8( nameLength ) + align8( 4 * count ) + 48 * boxes;
			if ( size > end - at ) fail( 'count', where, `zone ${z} declares ${nameLength} name bytes, ${count} probes and ${boxes} boxes: ${size} bytes, but ${end - at} are left in the ZONE section.` );
			at += 16;
			const name = readString( where, `zones[${z}].name`, bytes, at, nameLength );
			at += align8( nameLength );
			const probes = readTyped( Uint32Array, view, at, count );
			for ( let i = 0; i < count; i ++ ) if ( probes[ i ] >= probeCount ) fail( 'range', where, `zones[${z}].probes[${i}] = ${probes[ i ]} is not a probe index (0..${probeCount - 1}).` );
			at += align8( 4 * count );
			const zoneBounds = readTyped( Float64Array, view, at, 6 * boxes );
			checkFinite( where, `zones[${z}].bounds`, zoneBounds );
			for ( let b = 0; b < zoneBounds.length; b += 6 ) checkBox( where, `zones[${z}].bounds`, zoneBounds, b );
			at += 48 * boxes;
			zones.push( { name, probes, bounds: zoneBounds } );

		}

		if ( at !== end ) fail( 'count', where, `the ZONE section has ${end - at} bytes after its ${zoneCount} zones.` );

	}

	let bounds: Float64Array;
	if ( bnd ) {

		bounds = readTyped( Float64Array, view, bnd.offset, 6 );
		checkFinite( where, 'bounds', bounds );
		checkBox( where, 'bounds', bounds, 0 );

	} else {

		bounds = boxOf( positions );

	}

	let capture: BakedCapture = {};
	if ( cpt ) {

		const text = readString( where, 'capture settings', bytes, cpt.offset, cpt.length );
		let parsed: unknown;
		try {

			parsed = JSON.parse( text );

		} catch ( error ) {

			fail( 'json', where, `the capture settings are not valid JSON (${( error as Error ).message}).` );

		}

		capture = checkCapture( where, parsed );

	}

	const metadata = mta ? readString( where, 'metadata', bytes, mta.offset, mta.length ) : '';
	return { positions, sh, tetrahedra, neighbors, names, roles, zones, bounds, capture, metadata };

}

// ---------------------------------------------------------------------------------------------
// JSON form.
// ---------------------------------------------------------------------------------------------

/** The JSON form of a baked volume (docs/format.md, "JSON form"): the binary sections as arrays. */
export interface BakedVolumeJSON {

	/** Always {@link BAKED_VOLUME_JSON_FORMAT}. */
	format: string;

	/** [ major, minor ]. */
	version: [ number, number ];

	/** Number of probes (checked against `positions` when read). */
	probeCount: number;

	/** Number of tetrahedra (checked against `tetrahedra` when read). */
	tetrahedronCount: number;

	/** x, y, z per probe. */
	positions: number[];

	/** 27 per probe, three.js `SphericalHarmonics3` order. */
	sh: number[];

	/** 4 probe indices per tetrahedron. */
	tetrahedra: number[];

	/** 4 per tetrahedron, −1 on the hull. */
	neighbors: number[];

	/** Name per probe. */
	names: string[];

	/** Role per probe. */
	roles: BakedProbeRole[];

	/** Zones; `bounds` flat, 6 numbers per box. */
	zones: { name: string; probes: number[]; bounds: number[] }[];

	/** min x, y, z, max x, y, z. */
	bounds: number[];

	/** Capture settings. */
	capture: BakedCapture;

	/** Free-form text. */
	metadata: string;

}

/**
 * The JSON form of a volume: a plain object for `JSON.stringify` (numbers print so that they read
 * back exactly, so the round trip is lossless). Validates the input like {@link encodeBakedVolume}.
 */
export function bakedVolumeToJSON( input: BakedVolumeInput ): BakedVolumeJSON {

	const data = validateBakedVolume( input, 'bakedVolumeToJSON' );
	return {
		format: BAKED_VOLUME_JSON_FORMAT,
		version: [ BAKED_VOLUME_VERSION_MAJOR, BAKED_VOLUME_VERSION_MINOR ],
		probeCount: data.positions.length / 3,
		tetrahedronCount: data.tetrahedra.length / 4,
		positions: Array.from( data.positions ),
		sh: Array.from( data.sh ),
		tetrahedra: Array.from( data.tetrahedra ),
		neighbors: Array.from( data.neighbors ),
		names: data.names.slice(),
		roles: data.roles.slice(),
		zones: data.zones.map( ( zone ) => ( { name: zone.name, probes: Array.from( zone.probes ), bounds: Array.from( zone.bounds ) } ) ),
		bounds: Array.from( data.bounds ),
		capture: JSON.parse( JSON.stringify( data.capture ) ),
		metadata: data.metadata,
	};

}

/**
 * Reads the JSON form (an object, or its text) with the same checks as the binary reader.
 * Members a 1.x writer may add later are ignored.
 * @throws {BakedVolumeError}
 */
export function bakedVolumeFromJSON( json: unknown ): BakedVolumeData {

	const where = 'bakedVolumeFromJSON';
	let value = json;
	if ( typeof value === 'string' ) {

		try {

			value = JSON.parse( value );

		} catch ( error ) {

			fail( 'json', where, `not valid JSON (${( error as Error ).message}).` );

		}

	}

	if ( value === null || typeof value !== 'object' || Array.isArray( value ) ) fail( 'json', where, 'expected a JSON object.' );
	const o = value as Record<string, unknown>;
	if ( o.format !== BAKED_VOLUME_JSON_FORMAT ) fail( 'bad-magic', where, `not a baked light probe volume (format is ${JSON.stringify( o.format ) ?? 'missing'}, expected "${BAKED_VOLUME_JSON_FORMAT}").` );
	const version = o.version;
	if ( ! Array.isArray( version ) || version.length !== 2 || ! version.every( ( v ) => Number.isInteger( v ) && v >= 0 ) ) fail( 'version', where, 'version must be [ major, minor ].' );
	if ( version[ 0 ] > BAKED_VOLUME_VERSION_MAJOR ) fail( 'version', where, `version ${version[ 0 ]}.${version[ 1 ]} is newer than this reader (supports ≤ ${BAKED_VOLUME_VERSION_MAJOR}.x).` );
	if ( version[ 0 ] < 1 ) fail( 'version', where, `version ${version[ 0 ]}.${version[ 1 ]} is not a released version of the format (this reader supports 1.x).` );
	const data = validateBakedVolume( {
		positions: o.positions as number[],
		sh: o.sh as number[],
		tetrahedra: o.tetrahedra as number[] | undefined,
		neighbors: o.neighbors as number[] | undefined,
		names: o.names as string[] | undefined,
		roles: o.roles as BakedProbeRole[] | undefined,
		zones: o.zones as BakedVolumeInput[ 'zones' ],
		bounds: o.bounds as number[] | undefined,
		capture: o.capture as BakedCapture | undefined,
		metadata: o.metadata as string | undefined,
	}, where );
	if ( o.probeCount !== undefined && o.probeCount !== data.positions.length / 3 ) fail( 'count', where, `probeCount is ${o.probeCount} but positions holds ${data.positions.length / 3} probes.` );
	if ( o.tetrahedronCount !== undefined && o.tetrahedronCount !== data.tetrahedra.length / 4 ) fail( 'count', where, `tetrahedronCount is ${o.tetrahedronCount} but tetrahedra holds ${data.tetrahedra.length / 4}.` );
	return data;

}
