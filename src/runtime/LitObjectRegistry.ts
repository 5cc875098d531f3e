import type { Object3D, Vector3 } from 'three';
import { assertOptions } from '../validate.js';
import { describeObject } from './chooseLighting.js';
import { GRADIENT_FLOATS } from './gradientProbes.js';
import { GradientTracker } from './gradientTracker.js';
import type { AddOptions, ProbeLighting } from './LightProbeVolumeOptions.js';
import {
	EXPLICIT_SCOPE, assertObject3D, checkAddOptions, createLitObject, disposeLitObject, reportBadBlend, updateLitObject,
	type EntryScope, type LitObject,
} from './litObjects.js';
import { zonedProbeField, type ProbeWeighting, type ZonedProbes } from './ProbeWeighting.js';
import { zoneIndexOf } from './ProbeZones.js';
import { isWithin, planSceneLighting, type LightingPlan } from './sceneLighting.js';

/** What {@link LitObjectRegistry} reads of its volume. */
export interface RegistryVolume extends ZonedProbes {

	/** The typical probe distance, for `add( scene )`'s choice. */
	readonly probeSpacing: number;

	/** The gradients of gradient probes (81 per probe), or null. */
	readonly gradients: Float32Array | null;

}

/**
 * The objects a `LightProbeVolume` lights (`add`, `remove`, `update`, `getLighting` …): explicit
 * registrations (`add( object )`), the many entries of `add( scene )` (mode 'auto') with the root
 * that made them, and the lighting version that tells static entries when to blend again — bumped
 * by {@link LitObjectRegistry.probesChanged} and when `update()` finds the SH changed.
 */
export class LitObjectRegistry {

	/** The entries, in registration order (captures read them: hidden, probe light off). */
	readonly lit: LitObject[] = [];

	private readonly volume: RegistryVolume;
	private readonly weighting: ProbeWeighting;
	private version = 0;
	private staticCount = 0;
	private shCopy: Float32Array | null = null;
	private readonly gradientTracker = new GradientTracker();

	/**
	 * @param volume The volume whose probes light the objects.
	 * @param weighting Its weighting (zones, visibility guard).
	 */
	constructor( volume: RegistryVolume, weighting: ProbeWeighting ) {

		this.volume = volume;
		this.weighting = weighting;

	}

	/** `LightProbeVolume.add`: mode 'auto' (default for a `Scene`) registers a level, any other mode one object. */
	add( object: Object3D, options: AddOptions ): void {

		const where = 'LightProbeVolume.add';
		assertObject3D( where, object );
		assertOptions( where, 'options', options );
		const mode = options.mode ?? ( ( object as { isScene?: boolean } ).isScene === true ? 'auto' : 'object' );
		const fixedZone = options.zone !== undefined ? zoneIndexOf( where, this.volume.zones, options.zone ) : - 1;
		if ( mode === 'auto' ) this.addScene( where, object, options, fixedZone );
		else this.addObject( object, { ...options, mode }, fixedZone );

	}

	/** `LightProbeVolume.remove`: the object's own entry and every entry `add( object )` made in mode 'auto'. */
	remove( object: Object3D ): void {

		assertObject3D( 'LightProbeVolume.remove', object );
		for ( let i = this.lit.length - 1; i >= 0; i -- ) {

			const entry = this.lit[ i ];
			if ( entry.object === object || entry.root === object ) this.drop( i );

		}

	}

	/** The entry registered for exactly this object, or undefined. */
	find( object: Object3D ): LitObject | undefined {

		return this.lit.find( ( entry ) => entry.object === object );

	}

	/** `LightProbeVolume.getAnchor`: an object-mode entry's anchor (its local sampling point) into `target`, else null. */
	anchorOf( object: Object3D, target: Vector3 ): Vector3 | null {

		assertObject3D( 'LightProbeVolume.getAnchor', object );
		const entry = this.find( object );
		if ( entry === undefined || entry.large !== null ) return null;
		return target.set( entry.anchor[ 0 ], entry.anchor[ 1 ], entry.anchor[ 2 ] );

	}

	/** `LightProbeVolume.getZone`: the name of the zone that lit an entry last, or null (the whole volume, not registered). */
	zoneOf( object: Object3D ): string | null {

		assertObject3D( 'LightProbeVolume.getZone', object );
		const zone = this.find( object )?.zone ?? - 1;
		const zones = this.volume.zones;
		return zone >= 0 && zones ? zones.zones[ zone ].name : null;

	}

	/** `LightProbeVolume.getLighting`: how the object is lit — its own entry, or that of an ancestor covering it. */
	lightingOf( object: Object3D ): ProbeLighting | null {

		assertObject3D( 'LightProbeVolume.getLighting', object );
		const own = this.find( object );
		if ( own ) return own.lighting;
		for ( let node = object.parent; node !== null; node = node.parent ) {

			const entry = this.find( node );
			if ( entry ) return entry.subtree ? entry.lighting : null;

		}

		return null;

	}

	/** The probes changed (capture, edits, occluders): static entries blend again on the next `update()`. */
	probesChanged(): void {

		this.version ++;

	}

	/**
	 * `LightProbeVolume.update`: every entry, static ones only when moved or the lighting version
	 * changed (SH and gradients written directly are found by comparing with last frame's copies).
	 * Allocation-free (except the copies' first use and after `addProbe` grew the SH).
	 */
	update( where: string ): void {

		const volume = this.volume, lit = this.lit, weighting = this.weighting, zones = volume.zones, sh = volume.sh;
		const gradients = volume.gradients, positions = volume.positions;
		if ( gradients !== null && gradients.length !== GRADIENT_FLOATS * volume.count ) {

			throw new RangeError( `${where}: gradients has length ${gradients.length}, expected 81 × ${volume.count} probes; use setGradients().` );

		}

		if ( this.staticCount > 0 ) {

			// Both copies are brought up to date every frame: no short-circuit between them.
			const shChanged = this.shChanged( sh );
			if ( this.gradientTracker.changed( where, gradients, positions, 'gradients' ) || shChanged ) this.version ++;

		}

		const version = this.version;
		let bad = - 1;
		for ( let i = 0, n = lit.length; i < n; i ++ ) {

			if ( ! updateLitObject( lit[ i ], weighting, zones, sh, gradients, positions, version ) && bad < 0 ) bad = i;

		}

		if ( bad >= 0 ) reportBadBlend( where, lit[ bad ], sh, gradients );

	}

	/** Unregisters everything, last first. */
	dispose(): void {

		for ( let i = this.lit.length - 1; i >= 0; i -- ) this.drop( i );

	}

	/**
	 * One object in mode 'object', 'vertex' or 'texture'. An entry `add( scene )` made for it, or
	 * for objects below it, gives way (they are restored when this registration fails); one that
	 * covers it as part of a larger object (a marked group, a rig) does not: that is an Error.
	 */
	private addObject( object: Object3D, options: AddOptions, fixedZone: number ): void {

		const existing = this.find( object );
		if ( existing && existing.root === null ) return;
		checkAddOptions( options );
		for ( let node = object.parent; node !== null; node = node.parent ) {

			const cover = this.find( node );
			if ( cover?.root && cover.subtree ) {

				throw new Error( `LightProbeVolume.add: ${describeObject( object )} is lit as part of ${describeObject( node )} (one `
					+ `'${cover.lighting}' object of add( scene )); remove( that object ) first, or mark the objects below it instead.` );

			}

		}

		const yielded = this.lit.filter( ( entry ) => entry.root !== null && isWithin( entry.object, object ) );
		const restore = yielded.map( ( entry ) => ( { entry, options: entry.options } ) );
		for ( const entry of yielded ) this.drop( this.lit.indexOf( entry ) );
		try {

			this.register( object, options, fixedZone, EXPLICIT_SCOPE );

		} catch ( error ) {

			for ( const { entry, options: previous } of restore ) {

				const { root, subtree } = entry;
				this.register( entry.object, previous, entry.fixedZone, { root, subtree, static: entry.static } );

			}

			throw error;

		}

	}

	/** A level: every object {@link planSceneLighting} finds, all or nothing. */
	private addScene( where: string, root: Object3D, options: AddOptions, fixedZone: number ): void {

		for ( const key of [ 'anchor', 'hideInCaptures' ] as const ) {

			if ( options[ key ] !== undefined ) {

				throw new RangeError( `${where}: options.${key} is not taken in mode 'auto' (each object samples at its own centre; `
					+ 'what is lit as \'dynamic\' is hidden in captures); mark objects with userData.probeLighting or options.choose.' );

			}

		}

		if ( options.choose !== undefined && typeof options.choose !== 'function' ) {

			throw new TypeError( `${where}: options.choose must be a function ( object ) => 'dynamic' | 'object' | 'vertex' | 'texture' | `
				+ '\'none\' | \'auto\' | undefined.' );

		}

		checkAddOptions( { ...options, mode: 'object' } );
		const plans = planSceneLighting( where, root, options, this.lit, this.volume.probeSpacing );
		const start = this.lit.length;
		try {

			for ( const plan of plans ) this.register( plan.object, planOptions( plan, options ), fixedZone, scopeOf( plan, root ) );

		} catch ( error ) {

			for ( let i = this.lit.length - 1; i >= start; i -- ) this.drop( i );
			throw error;

		}

	}

	private register( object: Object3D, options: AddOptions, fixedZone: number, scope: EntryScope ): void {

		const entry = createLitObject( object, options, fixedZone, () => zonedProbeField( this.volume, fixedZone ), this.lit, scope );
		this.lit.push( entry );
		if ( entry.static && this.staticCount ++ === 0 ) this.shCopy = Float32Array.from( this.volume.sh );
		const volume = this.volume;
		if ( entry.large === null || entry.static ) {

			updateLitObject( entry, this.weighting, volume.zones, volume.sh, volume.gradients, volume.positions, this.version );

		}

	}

	private drop( index: number ): void {

		const [ entry ] = this.lit.splice( index, 1 );
		if ( entry.static ) this.staticCount --;
		disposeLitObject( entry );

	}

	/** Whether `sh` differs from the copy kept since the last call or the first static entry (and keeps a copy of it). */
	private shChanged( sh: Float32Array ): boolean {

		let copy = this.shCopy;
		if ( copy === null || copy.length !== sh.length ) {

			copy = this.shCopy = new Float32Array( sh.length );
			copy.set( sh );
			return true;

		}

		const n = sh.length;
		let i = 0;
		while ( i < n && ( sh[ i ] === copy[ i ] || ( sh[ i ] !== sh[ i ] && copy[ i ] !== copy[ i ] ) ) ) i ++;
		if ( i === n ) return false;
		copy.set( sh );
		return true;

	}

}

/** The `add()` options of one planned object: the call's common options and the mode of its lighting. */
function planOptions( plan: LightingPlan, options: AddOptions ): AddOptions {

	const { intensity, perVertex, vertexOutput, texelSize, maxResolution } = options;
	switch ( plan.lighting ) {

		case 'dynamic': return { mode: 'object', hideInCaptures: true, intensity, perVertex };
		case 'object': return { mode: 'object', hideInCaptures: false, intensity, perVertex };
		case 'vertex': return { mode: 'vertex', intensity, vertexOutput };
		default: return { mode: 'texture', intensity, texelSize, maxResolution };

	}

}

/** Entries of `add( scene )` remember their root; all but dynamic ones are static. */
function scopeOf( plan: LightingPlan, root: Object3D ): EntryScope {

	return { root, subtree: plan.subtree, static: plan.lighting !== 'dynamic' };

}
