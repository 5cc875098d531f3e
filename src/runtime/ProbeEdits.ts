import type { BakedFit } from '../io/index.js';
import { IncrementalTetrahedralMesh } from '../interpolation/IncrementalTetrahedralMesh.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import { checkName, checkRole, runtimeReject, type ProbeRole } from '../roles.js';
import { DynamicTetrahedralization } from '../tetrahedra/DynamicTetrahedralization.js';
import { SH_FLOATS, assertOptions, assertProbeSH } from '../validate.js';
import type { CapturedProbes } from './captureProbes.js';
import { blendProbes } from './gradientBlend.js';
import { GRADIENT_FLOATS, readGradients } from './gradientProbes.js';
import type { AddProbeOptions, ProbePosition } from './LightProbeVolumeOptions.js';
import type { LitObject } from './litObjects.js';
import { MAX_WEIGHTS, invalidateVisibility } from './ProbeWeighting.js';
import type { ProbeZones } from './ProbeZones.js';
import { readPosition } from './volumeArguments.js';
import type { VolumeFit } from './VolumeFit.js';

/** The fields of a `LightProbeVolume` that {@link ProbeEdits} reads and replaces. */
export interface EditedVolume {

	positions: Float64Array;
	sh: Float32Array;
	gradients: Float32Array | null;
	fitSettings: BakedFit | null;
	interpolator: ProbeInterpolator;
	readonly names: string[];
	readonly roles: ProbeRole[];
	readonly zones: ProbeZones | null;
	readonly count: number;

}

const _indices = new Uint32Array( MAX_WEIGHTS );
const _weights = new Float32Array( MAX_WEIGHTS );
const _sh = new Float32Array( SH_FLOATS );

/**
 * Probe editing of a `LightProbeVolume` (`moveProbe`, `addProbe`, `removeProbe`): the first edit
 * turns its `TetrahedralMesh` into an {@link IncrementalTetrahedralMesh} (one full
 * tetrahedralization) updated locally from then on; added probes' SH (and gradients) go into
 * capacity-doubling stores; moved and added probes are remembered as dirty until captured. Edits
 * replace the volume's `positions` (and `sh`, `gradients` when adding), keep its gradients in step
 * (a moved, added or removed probe's gradient is zero: it is plain until refitted) and its objects'
 * walk hints in range.
 */
export class ProbeEdits {

	/** Probes moved or added since they were last captured. */
	readonly dirty = new Set<number>();

	/**
	 * The fit of a fitted volume (captured SH and fit samples, `VolumeFit`), kept so that a capture
	 * after edits refits the edited layout; null when the volume is not fitted.
	 */
	fit: VolumeFit | null = null;

	private readonly volume: EditedVolume;
	private readonly lit: readonly LitObject[];
	/** Capacity-doubling store behind `sh` once a probe was added (null before). */
	private shStore: Float32Array | null = null;
	/** Capacity-doubling store behind `gradients` once a probe was added to a volume with gradients (null before). */
	private gradientStore: Float32Array | null = null;

	/**
	 * @param volume The edited volume.
	 * @param lit Its registered objects (the array itself, whose entries change).
	 */
	constructor( volume: EditedVolume, lit: readonly LitObject[] ) {

		this.volume = volume;
		this.lit = lit;

	}

	/** The dirty probes, ascending. */
	dirtyProbes(): number[] {

		return Array.from( this.dirty ).sort( ( a, b ) => a - b );

	}

	/** Whether probe id `index` is in use (false for removed probes, out-of-range ids and non-integers). */
	isActive( index: number ): boolean {

		if ( ! Number.isInteger( index ) || index < 0 || index >= this.volume.count ) return false;
		const mesh = this.volume.interpolator;
		return mesh instanceof IncrementalTetrahedralMesh ? mesh.isActive( index ) : true;

	}

	/**
	 * Puts a finished capture into the volume, all at once: each captured probe gets its SH and
	 * leaves the dirty set — unless it was removed while the capture ran (skipped) or moved (it
	 * gets the SH but stays dirty). An empty capture changes nothing.
	 * @returns Whether anything was captured.
	 */
	commitCapture( captured: CapturedProbes ): boolean {

		if ( captured.indices.length === 0 ) return false;
		const sh = this.volume.sh, positions = this.volume.positions, at = captured.positions;
		captured.indices.forEach( ( index, k ) => {

			if ( ! this.isActive( index ) ) return;
			sh.set( captured.sh.subarray( SH_FLOATS * k, SH_FLOATS * ( k + 1 ) ), SH_FLOATS * index );
			const moved = positions[ 3 * index ] !== at[ 3 * k ] || positions[ 3 * index + 1 ] !== at[ 3 * k + 1 ]
				|| positions[ 3 * index + 2 ] !== at[ 3 * k + 2 ];
			if ( ! moved ) this.dirty.delete( index );

		} );
		return true;

	}

	/**
	 * `LightProbeVolume.setGradients`: checks them (errors naming `where`, nothing changed), copies them into the volume
	 * with removed probes' gradients zeroed (the next added probe starts a new store from them), or makes the probes plain
	 * with null — which also drops a record of fitted gradients, no longer true.
	 */
	setGradients( where: string, gradients: ArrayLike<number> | null ): void {

		const volume = this.volume;
		const next = gradients === null ? null : readGradients( where, 'gradients', gradients, volume.positions, volume.count );
		this.gradientStore = null;
		for ( let i = 0; next !== null && i < volume.count; i ++ ) {

			if ( ! this.isActive( i ) ) next.fill( 0, GRADIENT_FLOATS * i, GRADIENT_FLOATS * ( i + 1 ) );

		}

		volume.gradients = next;
		// The fit path sets its own record after this call.
		if ( next === null && volume.fitSettings?.gradients === true ) volume.fitSettings = null;

	}

	/** `LightProbeVolume.moveProbe`. */
	move( index: number, position: ProbePosition ): void {

		const where = 'LightProbeVolume.moveProbe';
		const [ x, y, z ] = readPosition( where, position );
		this.assertActive( where, index );
		const mesh = this.editableMesh( where );
		mesh.moveProbe( index, x, y, z );
		this.zeroGradient( index );
		this.afterEdit( mesh );
		this.dirty.add( index );

	}

	/** `LightProbeVolume.addProbe`. */
	add( position: ProbePosition, options: AddProbeOptions ): number {

		const where = 'LightProbeVolume.addProbe', volume = this.volume;
		const [ x, y, z ] = readPosition( where, position );
		assertOptions( where, 'options', options );
		const { name = '', role = 'fill', sh } = options ?? {};
		const reject = runtimeReject( where );
		checkName( name, 'options.name', reject );
		checkRole( role, 'options.role', reject );
		if ( sh !== undefined ) assertProbeSH( where, 'options.sh', sh, 1 );
		const mesh = this.editableMesh( where );
		if ( sh === undefined ) {

			// Before the probe exists, so it does not weigh itself (its SH is still zero); gradient probes by their formula.
			mesh.interpolate( x, y, z, _indices, _weights, - 1 );
			blendProbes( _indices, _weights, mesh.weightCount, volume.sh, volume.gradients, volume.positions, x, y, z, _sh );

		} else {

			_sh.set( sh );

		}

		const index = mesh.addProbe( x, y, z );
		const total = index + 1;
		if ( this.shStore === null || this.shStore.length < SH_FLOATS * total ) {

			const store = new Float32Array( SH_FLOATS * Math.max( 16, 2 * total ) );
			store.set( volume.sh );
			this.shStore = store;

		}

		volume.sh = this.shStore.subarray( 0, SH_FLOATS * total );
		volume.sh.set( _sh, SH_FLOATS * index );
		if ( volume.gradients !== null ) volume.gradients = this.grownGradients( volume.gradients, total );
		volume.names.push( name );
		volume.roles.push( role );
		this.afterEdit( mesh );
		if ( sh === undefined ) this.dirty.add( index );
		return index;

	}

	/** `LightProbeVolume.removeProbe`. */
	remove( index: number ): void {

		const where = 'LightProbeVolume.removeProbe';
		this.assertActive( where, index );
		const mesh = this.editableMesh( where );
		mesh.removeProbe( index );
		this.volume.sh.fill( 0, SH_FLOATS * index, SH_FLOATS * ( index + 1 ) );
		this.zeroGradient( index );
		this.dirty.delete( index );
		this.afterEdit( mesh );

	}

	/** A probe's gradient set to zero (moved, removed: plain until refitted); nothing for plain probes. */
	private zeroGradient( index: number ): void {

		this.volume.gradients?.fill( 0, GRADIENT_FLOATS * index, GRADIENT_FLOATS * ( index + 1 ) );

	}

	/**
	 * `gradients` for `total` probes, the last one (just added) zero: a view of the capacity-doubling store, which is
	 * (re)built from `gradients` when they are not its own view (new gradients were set) or it is full.
	 */
	private grownGradients( gradients: Float32Array, total: number ): Float32Array {

		let store = this.gradientStore;
		if ( store === null || gradients.buffer !== store.buffer || store.length < GRADIENT_FLOATS * total ) {

			store = new Float32Array( GRADIENT_FLOATS * Math.max( 16, 2 * total ) );
			store.set( gradients.subarray( 0, GRADIENT_FLOATS * ( total - 1 ) ) );
			this.gradientStore = store;

		}

		const grown = store.subarray( 0, GRADIENT_FLOATS * total );
		grown.fill( 0, GRADIENT_FLOATS * ( total - 1 ) );
		return grown;

	}

	private assertActive( where: string, index: number ): void {

		if ( ! this.isActive( index ) ) {

			throw new RangeError( `${where}: ${index} is not a probe of this volume (0..${this.volume.count - 1}, not removed).` );

		}

	}

	/**
	 * The incremental mesh edits go through: the volume's own once made incremental, else one built
	 * now over the current positions (a full tetrahedralization, once).
	 */
	private editableMesh( where: string ): IncrementalTetrahedralMesh {

		const volume = this.volume;
		if ( volume.zones !== null ) {

			throw new Error( `${where}: the volume has lighting zones, whose own tetrahedralizations are not edited; `
				+ 'create a new LightProbeVolume with the edited positions.' );

		}

		const current = volume.interpolator;
		if ( ! ( current instanceof TetrahedralMesh ) ) {

			throw new Error( `${where}: probes can be edited only with a tetrahedral interpolator; this volume's is a `
				+ `${current.constructor?.name ?? 'custom interpolator'} (coplanar probes, or one passed in); `
				+ 'create a new LightProbeVolume with the edited positions.' );

		}

		if ( current instanceof IncrementalTetrahedralMesh ) return current;
		const mesh = new IncrementalTetrahedralMesh( new DynamicTetrahedralization( volume.positions ), { outside: current.outside } );
		volume.interpolator = mesh;
		volume.positions = mesh.positions;
		// Cell ids of the old mesh mean nothing in the new one.
		for ( const entry of this.lit ) if ( entry.zone < 0 ) entry.hint = - 1;
		return mesh;

	}

	/** After an edit: new positions, hints kept in range (any in-range hint is a valid walk start), guard caches reset. */
	private afterEdit( mesh: IncrementalTetrahedralMesh ): void {

		this.volume.positions = mesh.positions;
		const limit = mesh.cellCount + mesh.hullFaces.length / 3;
		for ( const entry of this.lit ) {

			if ( entry.zone < 0 && entry.hint >= limit ) entry.hint = - 1;
			invalidateVisibility( entry );

		}

	}

}
