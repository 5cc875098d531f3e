import { FloatType } from 'three';
import type { ProbeCaptureSettings } from '../capture/ProbeCapturer.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import type { BakedCapture, BakedCaptureSettings, BakedFit, BakedVolumeData, BakedVolumeInput } from '../io/index.js';
import { PROBE_ROLES, type ProbeRole } from '../roles.js';
import { GRADIENT_FLOATS } from './gradientProbes.js';
import { SH_FLOATS, assertOptions, describeValue } from '../validate.js';
import type { LightProbeVolumeCaptureOptions, LightProbeVolumeParameters } from './LightProbeVolumeOptions.js';
import type { BoxLike, ProbeZones } from './ProbeZones.js';

/*
 * Between a `LightProbeVolume` and the baked format (`src/io`): the data a file holds, the
 * constructor parameters a file gives, and the capture settings stored with a bake.
 */

/** The fields of a `LightProbeVolume` a baked file holds. */
export interface BakedSource {

	readonly positions: Float64Array;
	readonly sh: Float32Array;
	readonly gradients: Float32Array | null;
	readonly fitSettings: BakedFit | null;
	readonly names: readonly string[];
	readonly roles: readonly ProbeRole[];
	readonly interpolator: ProbeInterpolator;
	readonly zones: ProbeZones | null;
	readonly captureSettings: BakedCapture;
	readonly metadata: string;
	readonly count: number;
	isProbeActive( index: number ): boolean;

}

/** The constructor parameters a baked file gives. */
export type BakedParameters = Required<Pick<LightProbeVolumeParameters, 'positions' | 'sh' | 'names' | 'roles'>>
	& Pick<LightProbeVolumeParameters, 'zones' | 'interpolator' | 'gradients'>;

/** The constructor parameters that come from a baked file, so a caller may not pass them. */
const FILE_PARAMETERS: readonly ( keyof BakedParameters )[] = [ 'positions', 'sh', 'names', 'roles', 'zones', 'interpolator', 'gradients' ];

/**
 * Constructor parameters of a volume loaded from a baked file besides those the file gives, e.g.
 * `occluders` and `guard` (`LightProbeVolume.fromBakedData`, `LightProbeVolumeLoader`).
 */
export type BakedVolumeParameters = Omit<LightProbeVolumeParameters, keyof BakedParameters>;

/**
 * Checks the parameters given with a baked file: undefined or an object without the members the
 * file gives (which would be silently replaced by the file's). Values are checked by the constructor.
 */
export function assertBakedVolumeParameters( where: string, parameters: unknown ): asserts parameters is BakedVolumeParameters | undefined {

	assertOptions( where, 'parameters', parameters );
	for ( const name of FILE_PARAMETERS ) {

		const value = ( parameters as Record<string, unknown> | undefined )?.[ name ];
		if ( value !== undefined ) {

			throw new TypeError( `${where}: parameters.${name} (${describeValue( value )}) comes from the baked file; `
				+ 'pass only the other constructor parameters, such as occluders and guard.' );

		}

	}

}

/**
 * `LightProbeVolume.toBakedData`: positions, SH, gradients, the tetrahedralization (when the
 * interpolator is a `TetrahedralMesh`), names, roles, zones, capture settings, the fit record and
 * metadata — the volume's own arrays, except after `removeProbe()`, when the live probes are
 * renumbered into new arrays.
 */
export function toBakedVolumeInput( volume: BakedSource ): BakedVolumeInput {

	const mesh = volume.interpolator instanceof TetrahedralMesh ? volume.interpolator : null;
	const count = volume.count;
	let active = 0;
	for ( let i = 0; i < count; i ++ ) if ( volume.isProbeActive( i ) ) active ++;
	if ( mesh && active < count ) {

		// Probes removed by removeProbe() leave empty id slots: the file holds the live probes
		// only, renumbered in order (tetrahedron ids and neighbour links do not change).
		const id = new Int32Array( count ).fill( - 1 ), keep: number[] = [];
		for ( let i = 0; i < count; i ++ ) if ( volume.isProbeActive( i ) ) { id[ i ] = keep.length; keep.push( i ); }
		const positions = new Float64Array( 3 * active ), sh = new Float32Array( SH_FLOATS * active );
		const gradients = volume.gradients ? new Float32Array( GRADIENT_FLOATS * active ) : null;
		keep.forEach( ( i, k ) => {

			positions.set( volume.positions.subarray( 3 * i, 3 * i + 3 ), 3 * k );
			sh.set( volume.sh.subarray( SH_FLOATS * i, SH_FLOATS * ( i + 1 ) ), SH_FLOATS * k );
			gradients?.set( volume.gradients!.subarray( GRADIENT_FLOATS * i, GRADIENT_FLOATS * ( i + 1 ) ), GRADIENT_FLOATS * k );

		} );
		return {
			positions, sh, gradients, names: keep.map( ( i ) => volume.names[ i ] ), roles: keep.map( ( i ) => volume.roles[ i ] ),
			tetrahedra: mesh.tetrahedra.map( ( v ) => id[ v ] ), neighbors: mesh.neighbors,
			capture: volume.captureSettings, fit: volume.fitSettings, metadata: volume.metadata,
		};

	}

	return {
		positions: volume.positions.subarray( 0, 3 * count ), sh: volume.sh.subarray( 0, SH_FLOATS * count ),
		gradients: volume.gradients?.subarray( 0, GRADIENT_FLOATS * count ) ?? null,
		names: volume.names, roles: volume.roles,
		tetrahedra: mesh?.tetrahedra, neighbors: mesh?.neighbors,
		zones: volume.zones?.zones.map( ( zone ) => ( { name: zone.name, probes: zone.probes, bounds: zone.bounds } ) ),
		capture: volume.captureSettings, fit: volume.fitSettings, metadata: volume.metadata,
	};

}

/**
 * Checks the shape of decoded baked data given to `LightProbeVolume.fromBakedData`: an object
 * with the typed arrays `decodeBakedVolume` returns, tetrahedra and neighbours of one length and
 * every tetrahedron vertex a probe index (so a trusted mesh never reads out of range), bounds,
 * capture settings and metadata. Values are checked by the constructor; the tetrahedra's
 * orientation and links are trusted (the decoder checked them).
 */
export function checkBakedData( where: string, data: unknown ): asserts data is BakedVolumeData {

	const d = data as Partial<Record<keyof BakedVolumeData, unknown>> | null;
	const expect = ( name: string, ok: boolean, what: string ) => {

		if ( ! ok ) throw new TypeError( `${where}: data.${name} must be ${what} (data as decodeBakedVolume or bakedVolumeFromJSON return it).` );

	};

	if ( ! d || typeof d !== 'object' ) throw new TypeError( `${where}: data must be decoded baked data (as decodeBakedVolume returns it).` );
	expect( 'positions', d.positions instanceof Float64Array, 'a Float64Array' );
	expect( 'sh', d.sh instanceof Float32Array, 'a Float32Array' );
	expect( 'tetrahedra', d.tetrahedra instanceof Uint32Array && d.tetrahedra.length % 4 === 0, 'a Uint32Array of 4 indices per tetrahedron' );
	const tetrahedra = d.tetrahedra as Uint32Array, count = ( d.positions as Float64Array ).length / 3;
	expect( 'neighbors', d.neighbors instanceof Int32Array && d.neighbors.length === tetrahedra.length, 'an Int32Array as long as tetrahedra' );
	for ( let i = 0; i < tetrahedra.length; i ++ ) {

		if ( tetrahedra[ i ] >= count ) throw new RangeError( `${where}: data.tetrahedra[${i}] = ${tetrahedra[ i ]} is not a probe index (0..${count - 1}).` );

	}

	expect( 'zones', Array.isArray( d.zones ), 'an array of { name, probes, bounds }' );
	expect( 'bounds', d.bounds instanceof Float64Array && d.bounds.length === 6, 'a Float64Array of 6 numbers' );
	expect( 'capture', d.capture !== null && typeof d.capture === 'object', 'an object' );
	expect( 'metadata', typeof d.metadata === 'string', 'a string' );
	// Absent in data made before version 1.1 of the format: plain probes, not fitted.
	expect( 'gradients', d.gradients == null || ( d.gradients instanceof Float32Array && d.gradients.length === GRADIENT_FLOATS * count ),
		`null or a Float32Array of ${GRADIENT_FLOATS} floats per probe` );
	expect( 'fit', d.fit == null || ( typeof d.fit === 'object' && ! Array.isArray( d.fit ) ), 'null or a fit record object' );
	for ( const [ z, zone ] of ( d.zones as unknown[] ).entries() ) {

		const bounds = ( zone as { bounds?: unknown } | null )?.bounds;
		expect( `zones[${z}].bounds`, bounds instanceof Float64Array && bounds.length % 6 === 0, 'a Float64Array of 6 numbers per box' );

	}

}

/**
 * The constructor parameters of decoded baked data (the gradients among them; the fit record is
 * `fitSettings`, set by `fromBakedData`): the stored tetrahedralization as the
 * interpolator (not checked again: the decoder did), or none (the default interpolator is built) —
 * also when the stored tetrahedra do not fill the probes' convex hull, which the format allows
 * but the outer cells cannot extrapolate from (a warning says so).
 */
export function parametersFromBakedData( data: BakedVolumeData ): BakedParameters {

	let interpolator: ProbeInterpolator | undefined;
	if ( data.tetrahedra.length > 0 ) {

		try {

			interpolator = TetrahedralMesh.fromTetrahedralization( data.positions, data.tetrahedra, data.neighbors, { trusted: true } );

		} catch ( error ) {

			// The format allows tetrahedra that do not fill the probes' convex hull (docs/format.md);
			// the outer cells need a convex tiling, so the runtime builds its own.
			console.warn( `LightProbeVolume.fromBakedData: the stored tetrahedra cannot be used (${( error as Error ).message}); `
				+ 'the tetrahedralization is rebuilt from the positions.' );

		}

	}

	const zones = data.zones.length > 0
		? data.zones.map( ( zone ) => ( { name: zone.name, probes: zone.probes, bounds: boxes( zone.bounds ) } ) )
		: undefined;
	const gradients = data.gradients ?? undefined;
	return { positions: data.positions, sh: data.sh, gradients, names: data.names, roles: data.roles, zones, interpolator };

}

/** The capture settings of `LightProbeVolume.capture` worth storing with a bake, per role too. */
export function bakedCaptureSettings( options: LightProbeVolumeCaptureOptions ): BakedCapture {

	const roles: Partial<Record<ProbeRole, BakedCaptureSettings>> = {};
	for ( const role of PROBE_ROLES ) {

		if ( options.roles?.[ role ] ) roles[ role ] = bakedSettings( { ...options, ...options.roles[ role ] } );

	}

	return { ...bakedSettings( options ), ...( Object.keys( roles ).length > 0 ? { roles } : {} ) };

}

/** The capture settings worth storing with a bake. */
function bakedSettings( settings: ProbeCaptureSettings ): BakedCaptureSettings {

	const out: BakedCaptureSettings = {
		resolution: settings.resolution ?? 32, near: settings.near ?? 0.05, far: settings.far ?? 1000,
		type: settings.type === FloatType ? 'float' : 'half',
	};
	// The format names the two normalised formulas only; 'paper-unnormalized' is left unstated.
	const solidAngle = settings.solidAngle;
	if ( solidAngle === undefined || solidAngle === 'exact' || solidAngle === 'paper' ) out.solidAngle = solidAngle ?? 'exact';
	return out;

}

/** Flat min/max boxes (6 numbers each) as `BoxLike`s. */
function boxes( flat: Float64Array ): BoxLike[] | undefined {

	if ( flat.length === 0 ) return undefined;
	const out: BoxLike[] = [];
	for ( let i = 0; i < flat.length; i += 6 ) {

		out.push( {
			min: { x: flat[ i ], y: flat[ i + 1 ], z: flat[ i + 2 ] },
			max: { x: flat[ i + 3 ], y: flat[ i + 4 ], z: flat[ i + 5 ] },
		} );

	}

	return out;

}
