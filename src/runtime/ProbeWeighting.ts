import { boundsOf } from '../geometry/boundsOf.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import type { ProbeField } from './ProbeField.js';
import type { ProbeZones } from './ProbeZones.js';
import type { VisibilityGuard } from './VisibilityGuard.js';

/** Most (index, weight) pairs an interpolator may write (the grid's 8). */
export const MAX_WEIGHTS = 8;

/**
 * Checks an interpolator passed to a volume: it must index `count` probes and write at most
 * {@link MAX_WEIGHTS} weights. Throws an Error naming `where`.
 */
export function assertInterpolator( where: string, interpolator: ProbeInterpolator, count: number ): ProbeInterpolator {

	if ( typeof interpolator?.interpolate !== 'function' ) {

		throw new TypeError( `${where}: interpolator must implement ProbeInterpolator (interpolate, weightCount, probeCount).` );

	}

	if ( interpolator.probeCount !== count ) {

		throw new RangeError( `${where}: interpolator indexes ${interpolator.probeCount} probes but positions has ${count}.` );

	}

	if ( interpolator.weightCount > MAX_WEIGHTS ) {

		throw new RangeError( `${where}: interpolator.weightCount ${interpolator.weightCount} exceeds ${MAX_WEIGHTS}.` );

	}

	return interpolator;

}

/** What {@link ProbeWeighting} reads from its volume, on every call (probe edits replace positions and interpolator). */
export interface WeightedProbes {

	/** Probe positions, x, y, z per probe id. */
	readonly positions: Float64Array;

	/** The whole volume's interpolator. */
	readonly interpolator: ProbeInterpolator;

	/** The lighting zones, or null. */
	readonly zones: ProbeZones | null;

	/** The visibility guard, or null. */
	readonly visibilityGuard: VisibilityGuard | null;

}

/** A registered object's visibility-guard cache: where the segments were last tested, to which probes, and the result. */
export interface VisibilityCache {

	/** The sampling point of the last test. */
	guardPosition: Float64Array;

	/** The probes weighted at the last test ({@link MAX_WEIGHTS} slots). */
	guardIndices: Uint32Array;

	/** Bit k: slot k's probe was tested; its segment is blocked when bit k of `guardBlocked` is set. */
	guardTested: number;
	guardBlocked: number;

	/** Whether the fields above hold a test. */
	guardValid: boolean;

	/** Nearest visible probe when every weighted probe is blocked: −2 not searched yet, −1 none. */
	guardFallback: number;

}

/** The guard's default re-test distance for probes at `positions`: 1 % of their bounding-box diagonal. */
export function defaultMoveThreshold( positions: ArrayLike<number> ): number {

	const box = boundsOf( positions );
	return 0.01 * Math.hypot( box[ 3 ] - box[ 0 ], box[ 4 ] - box[ 1 ], box[ 5 ] - box[ 2 ] );

}

/** Forgets a cached visibility test (occluders or probes changed). */
export function invalidateVisibility( cache: VisibilityCache ): void {

	cache.guardValid = false;
	cache.guardFallback = - 2;

}

/**
 * Probe indices and weights at a point, with lighting zones and the visibility guard: the zone's
 * interpolator (its indices mapped to the volume's probes) or the volume's, then the guard, which
 * drops the probes behind geometry. Each call overwrites {@link ProbeWeighting.indices},
 * {@link ProbeWeighting.weights} and {@link ProbeWeighting.count}; allocation-free.
 */
export class ProbeWeighting {

	/** Probe ids of the last call, `count` of them. */
	readonly indices = new Uint32Array( MAX_WEIGHTS );

	/** Their weights (≥ 0, summing to 1). */
	readonly weights = new Float32Array( MAX_WEIGHTS );

	/** How many (index, weight) pairs the last call wrote. */
	count = 0;

	private readonly probes: WeightedProbes;
	private readonly defaultMoveThreshold: number;

	/**
	 * @param probes The volume whose probes are weighted.
	 * @param defaultMoveThreshold The guard's re-test distance when it sets none.
	 */
	constructor( probes: WeightedProbes, defaultMoveThreshold: number ) {

		this.probes = probes;
		this.defaultMoveThreshold = defaultMoveThreshold;

	}

	/**
	 * Weighs (x, y, z) in zone `zone` (−1: the whole volume), then applies the visibility guard when
	 * one is set. `cache` carries an object's last guard test (null: test afresh).
	 * @returns The interpolator's cell, as the next hint.
	 */
	weigh( x: number, y: number, z: number, zone: number, hint: number, cache: VisibilityCache | null ): number {

		hint = this.weighZone( x, y, z, zone, hint );
		const guard = this.probes.visibilityGuard;
		if ( guard !== null ) this.applyGuard( guard, x, y, z, zone, cache );
		return hint;

	}

	/** {@link ProbeWeighting.weigh} without the visibility guard: the zone's (or volume's) weights. */
	weighZone( x: number, y: number, z: number, zone: number, hint: number ): number {

		const indices = this.indices, weights = this.weights;
		if ( zone >= 0 ) {

			const { interpolator, probes } = this.probes.zones!.zones[ zone ];
			hint = interpolator.interpolate( x, y, z, indices, weights, hint );
			const count = this.count = interpolator.weightCount;
			for ( let k = 0; k < count; k ++ ) indices[ k ] = probes[ indices[ k ] ];

		} else {

			const interpolator = this.probes.interpolator;
			hint = interpolator.interpolate( x, y, z, indices, weights, hint );
			this.count = interpolator.weightCount;

		}

		return hint;

	}

	private applyGuard( guard: VisibilityGuard, x: number, y: number, z: number, zone: number, entry: VisibilityCache | null ): void {

		const count = this.count, p = this.probes.positions, indices = this.indices, weights = this.weights;
		let cached = false;
		if ( entry !== null && entry.guardValid ) {

			const threshold = guard.moveThreshold ?? this.defaultMoveThreshold;
			const dx = x - entry.guardPosition[ 0 ], dy = y - entry.guardPosition[ 1 ], dz = z - entry.guardPosition[ 2 ];
			cached = dx * dx + dy * dy + dz * dz <= threshold * threshold;
			for ( let k = 0; k < count && cached; k ++ ) {

				// A slot now weighted but not tested last time (or another probe) needs a new test.
				const untested = weights[ k ] > 0 && ( entry.guardTested & ( 1 << k ) ) === 0;
				if ( entry.guardIndices[ k ] !== indices[ k ] || untested ) cached = false;

			}

		}

		let blocked = 0;
		if ( cached ) {

			blocked = entry!.guardBlocked;

		} else {

			let tested = 0;
			for ( let k = 0; k < count; k ++ ) {

				if ( ! ( weights[ k ] > 0 ) ) continue;
				tested |= 1 << k;
				const i = 3 * indices[ k ];
				if ( guard.segmentBlocked( x, y, z, p[ i ], p[ i + 1 ], p[ i + 2 ] ) ) blocked |= 1 << k;

			}

			if ( entry !== null ) {

				entry.guardValid = true;
				entry.guardPosition[ 0 ] = x; entry.guardPosition[ 1 ] = y; entry.guardPosition[ 2 ] = z;
				entry.guardIndices.set( indices );
				entry.guardTested = tested;
				entry.guardBlocked = blocked;
				entry.guardFallback = - 2;

			}

		}

		if ( guard.applyMask( blocked, weights, count ) > 0 ) return;

		// Every weighted probe is behind geometry: the nearest visible one, alone.
		let fallback = entry !== null ? entry.guardFallback : - 2;
		if ( fallback === - 2 ) {

			fallback = guard.nearestVisible( x, y, z, p, zone >= 0 ? this.probes.zones!.zones[ zone ].probes : null );
			if ( entry !== null ) entry.guardFallback = fallback;

		}

		if ( fallback < 0 ) return; // none visible nearby: keep the unguarded weights
		indices[ 0 ] = fallback;
		weights[ 0 ] = 1;
		for ( let k = 1; k < count; k ++ ) { indices[ k ] = fallback; weights[ k ] = 0; }

	}

}

/** What {@link zonedProbeField} samples: a volume, itself a {@link ProbeField}, with its zones. */
export interface ZonedProbes extends ProbeField, WeightedProbes {

	/** Number of probe ids. */
	readonly count: number;

	/** Probe positions, x, y, z per probe id. */
	readonly positions: Float64Array;

}

/**
 * The field large objects sample: the whole volume without zones; with zones, each point (a
 * vertex, a texel) interpolates the probes of the zone whose bounds hold it — or of `fixedZone`
 * — so a floor running under a wall takes each room's light on its side; gradient probes blend
 * with the volume's gradients and positions. Not the visibility guard: vertices lie on surfaces,
 * whose own triangles would block every segment.
 */
export function zonedProbeField( volume: ZonedProbes, fixedZone: number ): ProbeField {

	const zones = volume.zones;
	if ( zones === null ) return volume;
	const weighting = new ProbeWeighting( volume, 0 );
	let lastZone = - 2;
	const interpolator: ProbeInterpolator = {
		get probeCount() { return volume.count; },
		get cellCount() { return volume.interpolator.cellCount; },
		weightCount: Math.max( volume.interpolator.weightCount, ...zones.zones.map( ( zone ) => zone.interpolator.weightCount ) ),
		interpolate( x, y, z, indices, weights, hint = - 1 ) {

			const zone = fixedZone >= 0 ? fixedZone : zones.zoneAt( x, y, z );
			// Cell indices belong to one interpolator: a hint from another zone's would be wrong.
			if ( zone !== lastZone ) { hint = - 1; lastZone = zone; }
			hint = weighting.weighZone( x, y, z, zone, hint );
			const count = weighting.count;
			for ( let k = 0; k < this.weightCount; k ++ ) {

				indices[ k ] = k < count ? weighting.indices[ k ] : 0;
				weights[ k ] = k < count ? weighting.weights[ k ] : 0;

			}

			return hint;

		},
	};
	return {
		interpolator,
		get sh() { return volume.sh; },
		get gradients() { return volume.gradients; },
		get positions() { return volume.positions; },
	};

}
