import type { Object3D } from 'three';
import { TriangleBVH } from '../geometry/TriangleBVH.js';
import { gatherWorldGeometry } from '../geometry/gatherWorldGeometry.js';
import { assertArrayLike, assertInteger, assertNumber, assertOptions, describeValue } from '../validate.js';

/** How many of the nearest probes {@link VisibilityGuard.nearestVisible} tries before giving up. */
const NEAREST_CANDIDATES = 8;

/** Options of {@link VisibilityGuard}. */
export interface VisibilityGuardOptions {

	/**
	 * Factor applied to the weight of a probe whose segment to the query point is blocked, before
	 * the weights are renormalised: 0 (default) excludes it, e.g. 0.1 keeps a tenth of it (softer
	 * transitions where a wall ends, at the price of some leak).
	 */
	blockedWeight?: number;

	/**
	 * How far (world units) a registered object may move inside the same cell before its probe
	 * visibility is tested again in `LightProbeVolume.update()`. Default: 1 % of the probes'
	 * bounding-box diagonal, filled in by the volume.
	 */
	moveThreshold?: number;

}

/**
 * Static occluders for probe visibility: a BVH over world-space triangles answering "does the
 * segment from a to b pass through geometry?", used by `LightProbeVolume` so that an object does
 * not receive light from probes it cannot see (no light through walls). Build it once from the
 * static meshes of a level — never from the objects the volume lights, which would block their
 * own probes.
 *
 * ```js
 * volume.setOccluders( level );             // or new VisibilityGuard( bvh )
 * volume.update();                          // blocked probes get weight 0, the rest renormalised
 * ```
 */
export class VisibilityGuard {

	/** The triangles tested against. */
	readonly bvh: TriangleBVH;

	/** See {@link VisibilityGuardOptions.blockedWeight}. */
	readonly blockedWeight: number;

	/** See {@link VisibilityGuardOptions.moveThreshold}; undefined lets the volume choose. */
	readonly moveThreshold: number | undefined;

	private readonly nearestIndices = new Int32Array( NEAREST_CANDIDATES );
	private readonly nearestDistances = new Float64Array( NEAREST_CANDIDATES );

	/**
	 * @param occluders A {@link TriangleBVH}, a flat triangle array (9 floats per triangle, world
	 * space), or three.js objects whose meshes are gathered in world space now
	 * (`gatherWorldGeometry`); moving them later does not move the occluders.
	 * @param options See {@link VisibilityGuardOptions}.
	 */
	constructor( occluders: TriangleBVH | ArrayLike<number> | Object3D | readonly Object3D[], options: VisibilityGuardOptions = {} ) {

		assertOptions( 'VisibilityGuard', 'options', options );
		this.bvh = toBVH( occluders );
		const blockedWeight = options.blockedWeight ?? 0;
		assertNumber( 'VisibilityGuard', 'options.blockedWeight', blockedWeight );
		if ( blockedWeight < 0 || blockedWeight >= 1 ) throw new RangeError( `VisibilityGuard: options.blockedWeight must be in [0, 1), got ${blockedWeight}.` );
		this.blockedWeight = blockedWeight;
		if ( options.moveThreshold !== undefined ) {

			assertNumber( 'VisibilityGuard', 'options.moveThreshold', options.moveThreshold );
			if ( options.moveThreshold < 0 ) throw new RangeError( `VisibilityGuard: options.moveThreshold must be ≥ 0, got ${options.moveThreshold}.` );

		}

		this.moveThreshold = options.moveThreshold;

	}

	/**
	 * Whether the open segment from a to b crosses any occluder triangle (hits within 1e-6 of the
	 * segment's length from either end are ignored): {@link TriangleBVH.segmentBlocked}. Allocation-free.
	 */
	segmentBlocked( ax: number, ay: number, az: number, bx: number, by: number, bz: number ): boolean {

		if ( typeof ax !== 'number' || typeof ay !== 'number' || typeof az !== 'number' || typeof bx !== 'number' || typeof by !== 'number'
			|| typeof bz !== 'number' || ( ax + ay + az + bx + by + bz ) * 0 !== 0 ) {

			throw new RangeError( `VisibilityGuard.segmentBlocked: the ends must be six finite numbers, got (${[ ax, ay, az, bx, by, bz ].join( ', ' )}).` );

		}

		return this.bvh.segmentBlocked( ax, ay, az, bx, by, bz );

	}

	/**
	 * Down-weights the probes not visible from (x, y, z) and renormalises, in place:
	 * `weights[k]` is multiplied by {@link VisibilityGuard.blockedWeight} when the segment to probe
	 * `indices[k]` is blocked. Zero weights are not tested. Allocation-free.
	 * @param positions Probe positions, x, y, z per probe.
	 * @param count How many (index, weight) pairs to process.
	 * @returns The sum of the visible probes' weights before renormalising (1 when none is
	 * blocked); 0 means every probe with weight was blocked, and the weights are then left
	 * unchanged (see {@link VisibilityGuard.nearestVisible}).
	 */
	filterWeights(
		x: number, y: number, z: number, positions: ArrayLike<number>, indices: ArrayLike<number>,
		weights: Float32Array | Float64Array | number[], count: number
	): number {

		checkWeights( 'VisibilityGuard.filterWeights', weights, count );
		assertArrayLike( 'VisibilityGuard.filterWeights', 'positions', positions );
		assertArrayLike( 'VisibilityGuard.filterWeights', 'indices', indices );
		if ( indices.length < count ) throw new RangeError( `VisibilityGuard.filterWeights: indices has ${indices.length} entries, fewer than count ${count}.` );
		for ( let k = 0; k < count; k ++ ) {

			const index = indices[ k ];
			if ( ! ( Number.isInteger( index ) && index >= 0 && 3 * index + 2 < positions.length ) ) {

				throw new RangeError( `VisibilityGuard.filterWeights: indices[${k}] = ${index} is not a probe of positions (${positions.length / 3} probes).` );

			}

		}

		let mask = 0;
		for ( let k = 0; k < count; k ++ ) {

			if ( ! ( weights[ k ] > 0 ) ) continue;
			const p = 3 * indices[ k ];
			if ( this.segmentBlocked( x, y, z, positions[ p ], positions[ p + 1 ], positions[ p + 2 ] ) ) mask |= 1 << k;

		}

		return this.applyMask( mask, weights, count );

	}

	/**
	 * The weight change of {@link VisibilityGuard.filterWeights} for a known set of blocked slots
	 * (bit k of `mask` = slot k blocked), so callers can cache the segment tests.
	 * @returns As {@link VisibilityGuard.filterWeights}: 1 when `mask` is 0, else the visible
	 * weights' sum before renormalising (0: all blocked, weights left unchanged).
	 */
	applyMask( mask: number, weights: Float32Array | Float64Array | number[], count: number ): number {

		if ( mask === 0 ) return 1;
		if ( typeof mask !== 'number' || ! Number.isInteger( mask ) ) throw new RangeError( `VisibilityGuard.applyMask: mask must be an integer bit mask, got ${describeValue( mask )}.` );
		checkWeights( 'VisibilityGuard.applyMask', weights, count );
		let visible = 0, total = 0;
		for ( let k = 0; k < count; k ++ ) {

			const w = weights[ k ] > 0 ? weights[ k ] : 0;
			if ( ( mask & ( 1 << k ) ) === 0 ) visible += w;
			total += ( mask & ( 1 << k ) ) === 0 ? w : w * this.blockedWeight;

		}

		if ( ! ( visible > 0 ) ) return 0;
		const s = 1 / total;
		for ( let k = 0; k < count; k ++ ) {

			const w = weights[ k ] > 0 ? weights[ k ] : 0;
			weights[ k ] = ( mask & ( 1 << k ) ) === 0 ? w * s : w * this.blockedWeight * s;

		}

		return visible;

	}

	/**
	 * The nearest probe visible from (x, y, z) among `candidates` (probe indices; all probes when
	 * null), trying only the 8 nearest: a bounded fallback for a point that sees none of its own
	 * cell's probes. Allocation-free.
	 * @returns A probe index, or −1 when none of the 8 nearest is visible.
	 */
	nearestVisible( x: number, y: number, z: number, positions: ArrayLike<number>, candidates: ArrayLike<number> | null ): number {

		const where = 'VisibilityGuard.nearestVisible';
		assertNumber( where, 'x', x );
		assertNumber( where, 'y', y );
		assertNumber( where, 'z', z );
		assertArrayLike( where, 'positions', positions );
		if ( candidates !== null ) assertArrayLike( where, 'candidates', candidates );
		const indices = this.nearestIndices, distances = this.nearestDistances;
		let found = 0;
		const n = candidates ? candidates.length : positions.length / 3;
		for ( let c = 0; c < n; c ++ ) {

			const i = candidates ? candidates[ c ] : c;
			const dx = positions[ 3 * i ] - x, dy = positions[ 3 * i + 1 ] - y, dz = positions[ 3 * i + 2 ] - z;
			const d = dx * dx + dy * dy + dz * dz;
			if ( found === NEAREST_CANDIDATES && d >= distances[ found - 1 ] ) continue;
			// Insertion into the short sorted list.
			let k = found < NEAREST_CANDIDATES ? found ++ : found - 1;
			while ( k > 0 && distances[ k - 1 ] > d ) {

				distances[ k ] = distances[ k - 1 ];
				indices[ k ] = indices[ k - 1 ];
				k --;

			}

			distances[ k ] = d;
			indices[ k ] = i;

		}

		for ( let k = 0; k < found; k ++ ) {

			const p = 3 * indices[ k ];
			if ( ! this.segmentBlocked( x, y, z, positions[ p ], positions[ p + 1 ], positions[ p + 2 ] ) ) return indices[ k ];

		}

		return - 1;

	}

	/**
	 * Diagnostics at bake time: the tetrahedra with at least one edge passing through geometry —
	 * the cells across which light leaks without the guard.
	 * @param positions Probe positions, x, y, z per probe.
	 * @param tetrahedra Four probe indices per tetrahedron (e.g. `TetrahedralMesh.tetrahedra`).
	 * @returns Their indices, ascending.
	 */
	findLeakingTetrahedra( positions: ArrayLike<number>, tetrahedra: ArrayLike<number> ): Uint32Array {

		assertArrayLike( 'VisibilityGuard.findLeakingTetrahedra', 'positions', positions );
		assertArrayLike( 'VisibilityGuard.findLeakingTetrahedra', 'tetrahedra', tetrahedra );
		const edges = new Map<number, boolean>();
		const probes = positions.length / 3;
		const leaking: number[] = [];
		for ( let t = 0, n = Math.floor( tetrahedra.length / 4 ); t < n; t ++ ) {

			let leaks = false;
			for ( let i = 0; i < 4 && ! leaks; i ++ ) {

				for ( let j = i + 1; j < 4 && ! leaks; j ++ ) {

					const a = tetrahedra[ 4 * t + i ], b = tetrahedra[ 4 * t + j ];
					if ( ! ( a >= 0 && a < probes && b >= 0 && b < probes ) ) throw new RangeError( `VisibilityGuard.findLeakingTetrahedra: tetrahedron ${t} names probe ${a < probes ? b : a}, but positions holds ${probes}.` );
					const key = Math.min( a, b ) * probes + Math.max( a, b );
					let blocked = edges.get( key );
					if ( blocked === undefined ) {

						blocked = this.segmentBlocked(
							positions[ 3 * a ], positions[ 3 * a + 1 ], positions[ 3 * a + 2 ],
							positions[ 3 * b ], positions[ 3 * b + 1 ], positions[ 3 * b + 2 ]
						);
						edges.set( key, blocked );

					}

					leaks = blocked;

				}

			}

			if ( leaks ) leaking.push( t );

		}

		return Uint32Array.from( leaking );

	}

}

/** Weights an applyMask / filterWeights call may change: an array of at least `count` (1..32) entries. */
function checkWeights( where: string, weights: unknown, count: unknown ): void {

	assertArrayLike( where, 'weights', weights );
	assertInteger( where, 'count', count, 0, 32 );
	if ( weights.length < count ) throw new RangeError( `${where}: weights has ${weights.length} entries, fewer than count ${count}.` );

}

function toBVH( occluders: TriangleBVH | ArrayLike<number> | Object3D | readonly Object3D[] ): TriangleBVH {

	if ( occluders instanceof TriangleBVH ) return occluders;
	if ( occluders !== null && typeof occluders === 'object' && ( occluders as Object3D ).isObject3D === true ) return new TriangleBVH( gatherWorldGeometry( occluders as Object3D ).triangles );
	if ( Array.isArray( occluders ) && occluders.length > 0 && occluders.every( ( o ) => ( o as Object3D )?.isObject3D === true ) ) {

		const parts = ( occluders as readonly Object3D[] ).map( ( object ) => gatherWorldGeometry( object ).triangles );
		const triangles = new Float64Array( parts.reduce( ( sum, part ) => sum + part.length, 0 ) );
		let offset = 0;
		for ( const part of parts ) { triangles.set( part, offset ); offset += part.length; }
		return new TriangleBVH( triangles );

	}

	if ( occluders === null || typeof occluders !== 'object' || typeof ( occluders as ArrayLike<number> ).length !== 'number' ) {

		throw new TypeError( 'VisibilityGuard: occluders must be a TriangleBVH, a triangle array (9 floats each), an Object3D or an array of Object3D.' );

	}

	return new TriangleBVH( occluders as ArrayLike<number> );

}
