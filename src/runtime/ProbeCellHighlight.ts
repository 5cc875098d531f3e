import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments, Vector3, type Object3D } from 'three';
import { GridInterpolator } from '../interpolation/GridInterpolator.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { describeValue } from '../validate.js';
import { anchorInWorld } from './anchorInWorld.js';
import { localBoundsCentre } from './litObjects.js';
import { hideLinesFromCubeCameras } from './cubeCameraHiding.js';
import type { LightProbeVolume, ProbePosition } from './LightProbeVolume.js';
import { GRID_BOX_EDGES } from './probeCellEdges.js';
import { MAX_WEIGHTS } from './ProbeWeighting.js';
import { readPosition } from './volumeArguments.js';

/** At most 12 edges: a grid box; a tetrahedron has 6. */
const MAX_EDGES = 12;

/** Slot pairs of the complete graph on 4 slots: a tetrahedron's edges (a triangle's and a segment's come first). */
const SIMPLEX_EDGES = [ 0, 1, 1, 2, 2, 0, 0, 3, 1, 3, 2, 3 ];

const _world = new Float64Array( 3 );

/** What a highlight follows: an object, a position, or nothing. */
export type HighlightTarget = Object3D | ProbePosition | null;

/**
 * The highlighted cell of a `LightProbeVolumeHelper`: the edges between the probes that an object
 * (or a point) blends — a tetrahedron's 6, a triangle's or outer cell's 3, a segment, or a grid
 * box's 12 — found again before every render (in `updateMatrixWorld`, as three's SkeletonHelper
 * does), without allocating.
 */
export class ProbeCellHighlight extends LineSegments<BufferGeometry, LineBasicMaterial> {

	/** The probes of the cell drawn (`probeCount` of them), before the visibility guard. */
	readonly cellProbes = new Uint32Array( MAX_WEIGHTS );

	/** How many entries of {@link ProbeCellHighlight.cellProbes} are in use (0: nothing drawn). */
	probeCount = 0;

	private readonly volume: LightProbeVolume;
	private target: HighlightTarget = null;
	/** The target object's sampling point in its own frame: its bounding-box centre, as `volume.add()` takes it. */
	private readonly anchor = new Float64Array( 3 );
	private readonly indices = new Uint32Array( MAX_WEIGHTS );
	private readonly weights = new Float64Array( MAX_WEIGHTS );
	private hint = - 1;
	private hintSource: ProbeInterpolator | null = null;
	private drawnPositions: Float64Array | null = null;

	/** @param volume The volume whose cells are highlighted. */
	constructor( volume: LightProbeVolume ) {

		const geometry = new BufferGeometry();
		geometry.setAttribute( 'position', new BufferAttribute( new Float32Array( 6 * MAX_EDGES ), 3 ) );
		geometry.setDrawRange( 0, 0 );
		super( geometry, new LineBasicMaterial( { color: 0xffff00, toneMapped: false } ) );
		this.name = 'cell';
		this.volume = volume;
		this.frustumCulled = false; // the geometry changes every frame; its bounds are not kept
		this.raycast = () => {}; // picking is for the probe spheres
		hideLinesFromCubeCameras( this );

	}

	/**
	 * Follows `target`: an object (the cell it samples at its anchor — its bounding-box centre unless
	 * `add()` was given one — in the zone the volume used for it at the last `update()`), a
	 * position (read again every frame), or null.
	 * @throws TypeError for anything else, leaving the highlight as it was.
	 */
	follow( target: HighlightTarget ): void {

		const where = 'LightProbeVolumeHelper.highlight';
		if ( target !== null && ( target as Object3D ).isObject3D === true ) {

			// Where the volume samples it (its anchor) when registered, else its bounding-box centre as add() would.
			const anchor = this.volume.getAnchor( target as Object3D, new Vector3() );
			if ( anchor !== null ) anchor.toArray( this.anchor );
			else this.anchor.set( localBoundsCentre( target as Object3D, undefined, true ) );

		} else if ( target !== null ) {

			if ( typeof target !== 'object' ) {

				throw new TypeError( `${where}: target must be an Object3D, { x, y, z }, [ x, y, z ] or null, got ${describeValue( target )}.` );

			}

			readPosition( where, target, 'target' );

		}

		this.target = target;
		this.invalidate();

	}

	/** Forgets the cell drawn, so the next refresh writes it again (after the probes changed). */
	invalidate(): void {

		this.hint = - 1;
		this.hintSource = null;
		this.drawnPositions = null;

	}

	/** Finds the target's cell again (allocation-free), then updates the matrices as usual. */
	override updateMatrixWorld( force?: boolean ): void {

		this.refresh();
		super.updateMatrixWorld( force );

	}

	/** Finds the target's cell and writes its edges when it changed. Allocation-free. */
	refresh(): void {

		const changed = this.locate();
		const positions = this.volume.positions;
		if ( ! changed && positions === this.drawnPositions ) return;
		this.drawnPositions = positions;
		this.writeEdges( positions );

	}

	/** Puts the target's cell into `cellProbes` / `probeCount`; returns whether the probes differ from last time. */
	private locate(): boolean {

		const target = this.target, volume = this.volume;
		let x: number, y: number, z: number;
		if ( target === null ) {

			return this.setCell( 0 );

		} else if ( ( target as Object3D ).isObject3D === true ) {

			// The object's matrixWorld as the volume's update() left it (it updates it before sampling).
			const world = anchorInWorld( target as Object3D, this.anchor, _world );
			x = world[ 0 ]; y = world[ 1 ]; z = world[ 2 ];

		} else {

			const p = target as { x: number; y: number; z: number } & ArrayLike<number>;
			if ( 'x' in p ) { x = p.x; y = p.y; z = p.z; } else { x = p[ 0 ]; y = p[ 1 ]; z = p[ 2 ]; }

		}

		// A position edited to NaN after highlight() (or an object far out of range) shows no cell.
		if ( ! ( x - x === 0 && y - y === 0 && z - z === 0 ) ) return this.setCell( 0 );
		const zones = volume.zones;
		let zone = - 1;
		if ( zones !== null ) {

			const name = ( target as Object3D ).isObject3D === true ? volume.getZone( target as Object3D ) : null;
			if ( name === null ) zone = zones.zoneAt( x, y, z );
			else for ( let i = 0; i < zones.zones.length; i ++ ) if ( zones.zones[ i ].name === name ) zone = i;

		}

		const interpolator = zone >= 0 ? zones!.zones[ zone ].interpolator : volume.interpolator;
		if ( interpolator !== this.hintSource ) { this.hint = - 1; this.hintSource = interpolator; }
		const indices = this.indices, weights = this.weights, count = Math.min( interpolator.weightCount, MAX_WEIGHTS );
		this.hint = interpolator.interpolate( x, y, z, indices, weights, this.hint );
		if ( zone >= 0 ) {

			const probes = zones!.zones[ zone ].probes;
			for ( let k = 0; k < count; k ++ ) indices[ k ] = probes[ indices[ k ] ];

		}

		if ( interpolator instanceof GridInterpolator ) {

			// A grid box keeps its 8 corners (in the grid's order) even where some weigh 0.
			return this.setCell( 8 );

		}

		// Otherwise the distinct probes with weight: 4 in a tetrahedron, 3 in a triangle or an outer
		// cell (whose fourth slot is a zero-weight filler), 2 along a segment or a planar boundary.
		let n = 0;
		for ( let k = 0; k < count; k ++ ) {

			if ( ! ( weights[ k ] > 0 ) ) continue;
			let seen = false;
			for ( let j = 0; j < n; j ++ ) if ( indices[ j ] === indices[ k ] ) seen = true;
			if ( ! seen ) indices[ n ++ ] = indices[ k ];

		}

		// A custom interpolator blending more probes than a tetrahedron: its first 4 are drawn.
		return this.setCell( Math.min( n, 4 ) );

	}

	/** Copies the first `n` of `indices` into `cellProbes`; returns whether they differ from the cell held. */
	private setCell( n: number ): boolean {

		let changed = n !== this.probeCount;
		for ( let k = 0; k < n; k ++ ) {

			if ( this.cellProbes[ k ] !== this.indices[ k ] ) changed = true;
			this.cellProbes[ k ] = this.indices[ k ];

		}

		this.probeCount = n;
		return changed;

	}

	/** Writes the cell's edges (a grid box's, or the complete graph on up to 4 probes) from `positions`. */
	private writeEdges( positions: Float64Array ): void {

		const n = this.probeCount, probes = this.cellProbes;
		const pairs = n === 8 ? GRID_BOX_EDGES : SIMPLEX_EDGES;
		const edges = n === 8 ? 12 : ( n * ( n - 1 ) ) >> 1;
		const attribute = this.geometry.getAttribute( 'position' ) as BufferAttribute;
		const out = attribute.array as Float32Array;
		for ( let e = 0; e < edges; e ++ ) {

			for ( let end = 0; end < 2; end ++ ) {

				// A triangle's edges are pairs 0–1, 1–2, 2–0 and a segment's 0–1: the first of SIMPLEX_EDGES.
				const p = 3 * probes[ pairs[ 2 * e + end ] ], o = 6 * e + 3 * end;
				out[ o ] = positions[ p ]; out[ o + 1 ] = positions[ p + 1 ]; out[ o + 2 ] = positions[ p + 2 ];

			}

		}

		this.geometry.setDrawRange( 0, 2 * edges );
		attribute.needsUpdate = true;

	}

}
