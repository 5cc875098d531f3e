import { DynamicTetrahedralization } from '../tetrahedra/DynamicTetrahedralization.js';
import { DegenerateInputError } from '../tetrahedra/DegenerateInputError.js';
import { createProbeInterpolator } from '../interpolation/createProbeInterpolator.js';
import { ChangedPoints } from './ChangedPoints.js';
import { PointGrid } from './PointGrid.js';
import { predictedError, writeUnknownRows, type FittedLayout, type RefitContext } from './refitLayout.js';
import { solveDenseSPD } from './solveDenseSPD.js';

/**
 * Quick estimates of trial edits of a fitted layout, for `reduceProbes`' insertion steps and swap
 * passes: what inserting a candidate (or moving a probe to a candidate) would do to the fitted
 * error, without a global fit. The points whose weights the edit changes are found — by a local
 * edit of a {@link DynamicTetrahedralization} of the layout (the same Delaunay mesh as the layout's
 * `createProbeInterpolator`), or, when the edit moves the hull (outer cells change too), by
 * locating every point in a new interpolator; the edited probe alone is fitted to them, with
 * `fitProbeSH`'s objective and λ and every other probe held at its fit; the error change is summed
 * over those points (and, for a move, the points the probe blended before). Holding the
 * neighbours makes the estimate a little pessimistic; it ranks the trials, and the edit that is
 * kept is then fitted exactly (`fitLayout`).
 */
export class LocalRefit {

	private readonly context: RefitContext;
	private readonly dynamic: DynamicTetrahedralization;
	private readonly grid: PointGrid;
	private readonly changed: ChangedPoints;
	private layout: FittedLayout;
	// Trials that move the hull edit the tetrahedralization in place too (outer cells held): `hullTrials: 'local'`.
	private readonly localHull: boolean;

	// Mesh point id ↔ local probe (a trial id gets the next local index, P, while it lives).
	private idToLocal = new Int32Array( 64 ).fill( - 1 );
	private readonly localToId: number[] = [];

	// Per point: the trial that last listed it, and its entry in `changed` (−1: the layout's weights).
	private readonly pointStamp: Int32Array;
	private readonly pointEntry: Int32Array;

	// The points a trial's estimate sums over (each at most once: at most every point).
	private readonly trialPoints: Int32Array;
	private stamp = 0;

	// The layout's positions, unknowns and unknown rows with room for one probe more: a trial
	// overwrites the edited probe's, and puts them back after a move.
	private trialPositions = new Float64Array( 0 );
	private trialUnknowns = new Float64Array( 0 );
	private trialRows = new Float64Array( 0 );

	// The edited probe's normal equations (stride × stride, 27 right-hand sides) and scratch.
	private readonly matrix = new Float64Array( 16 );
	private readonly matrixCopy = new Float64Array( 16 );
	private readonly rhs = new Float64Array( 4 * 27 );
	private readonly factors = new Float64Array( 4 );
	// The held probes of one point in `solve`: unknown offsets and factors (w, fx, fy, fz).
	private readonly heldBase = new Int32Array( 4 );
	private readonly heldFactors = new Float64Array( 16 );

	private constructor( context: RefitContext, dynamic: DynamicTetrahedralization, layout: FittedLayout, localHull: boolean ) {

		this.context = context;
		this.localHull = localHull;
		this.dynamic = dynamic;
		this.grid = new PointGrid( context.positions );
		const count = context.weights.length;
		this.changed = new ChangedPoints( count );
		this.pointStamp = new Int32Array( count );
		this.pointEntry = new Int32Array( count );
		this.trialPoints = new Int32Array( count );
		for ( let i = 0; i < layout.order.length; i ++ ) this.mapId( i, i );
		this.layout = layout;
		this.copyLayout();

	}

	/**
	 * Trials over `layout`, or null when its probes cannot be tetrahedralized in 3D (a flat layout,
	 * coincident probes): then every trial is fitted exactly.
	 * @param localHull Estimate trials that move the hull in place too, outer cells held (`hullTrials: 'local'`).
	 */
	static create( context: RefitContext, layout: FittedLayout, localHull = false ): LocalRefit | null {

		try {

			const dynamic = new DynamicTetrahedralization( layout.positions );
			return dynamic.duplicates.length === 0 ? new LocalRefit( context, dynamic, layout, localHull ) : null;

		} catch ( error ) {

			if ( error instanceof DegenerateInputError ) return null;
			throw error;

		}

	}

	/** Takes the exact fit of the layout after a committed edit. */
	reset( layout: FittedLayout ): void {

		this.layout = layout;
		this.copyLayout();

	}

	/** Inserts dense candidate c for good (it becomes the layout's next local probe). */
	commitInsert( c: number ): void {

		const p = this.context.positions;
		this.mapId( this.dynamic.insert( p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ] ), this.layout.order.length );

	}

	/** Moves local probe r to dense candidate c for good. */
	commitMove( r: number, c: number ): void {

		const p = this.context.positions;
		this.dynamic.move( this.localToId[ r ], p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ] );

	}

	/**
	 * The estimated change of the weighted mean error when dense candidate c is inserted (NaN when
	 * the edited probe's system is singular: fit it exactly), +Infinity when c coincides with a probe.
	 */
	tryInsert( c: number ): number {

		const { context, layout } = this, p = context.positions, local = layout.order.length;
		if ( layout.outside[ c ] === 1 && ! this.localHull ) {

			const positions = new Float64Array( 3 * ( local + 1 ) );
			positions.set( layout.positions );
			positions.set( p.subarray( 3 * c, 3 * c + 3 ), 3 * local );
			return this.estimateInMesh( positions, local, c, true );

		}

		let id: number;
		try {

			id = this.dynamic.insert( p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ] );

		} catch ( error ) {

			if ( error instanceof DegenerateInputError ) return Infinity;
			throw error;

		}

		this.mapId( id, local );
		this.changed.inChangedCells( this.dynamic, this.idToLocal, this.grid, layout );
		const change = this.estimate( local, c, true );
		this.dynamic.remove( id );
		this.idToLocal[ id ] = - 1;
		return change;

	}

	/**
	 * The estimated change of the weighted mean error when local probe r moves to dense candidate c
	 * (NaN when the moved probe's system is singular: fit it exactly), +Infinity when c coincides with a probe.
	 */
	tryMove( r: number, c: number ): number {

		const { context, layout } = this, p = context.positions, id = this.localToId[ r ], back = layout.positions;
		if ( ( layout.hullVertex[ r ] === 1 || layout.outside[ c ] === 1 ) && ! this.localHull ) {

			const positions = back.slice();
			positions.set( p.subarray( 3 * c, 3 * c + 3 ), 3 * r );
			return this.estimateInMesh( positions, r, c, false );

		}

		try {

			this.dynamic.move( id, p[ 3 * c ], p[ 3 * c + 1 ], p[ 3 * c + 2 ] );

		} catch ( error ) {

			if ( error instanceof DegenerateInputError ) return Infinity;
			throw error;

		}

		this.changed.inChangedCells( this.dynamic, this.idToLocal, this.grid, layout );
		const change = this.estimate( r, c, false );
		this.dynamic.move( id, back[ 3 * r ], back[ 3 * r + 1 ], back[ 3 * r + 2 ] );
		return change;

	}

	private mapId( id: number, local: number ): void {

		if ( id >= this.idToLocal.length ) {

			const grown = new Int32Array( 2 * id + 64 ).fill( - 1 );
			grown.set( this.idToLocal );
			this.idToLocal = grown;

		}

		this.idToLocal[ id ] = local;
		this.localToId[ local ] = id;

	}

	/** {@link LocalRefit.estimate} for an edit that moves the hull: the edited layout `positions` located in a new interpolator. */
	private estimateInMesh( positions: Float64Array, edited: number, c: number, inserted: boolean ): number {

		let interpolator;
		try {

			interpolator = createProbeInterpolator( positions );

		} catch ( error ) {

			if ( error instanceof DegenerateInputError ) return Infinity;
			throw error;

		}

		this.changed.inMesh( interpolator, this.context.positions, this.context.visitOrder, this.layout, inserted ? - 1 : edited );
		return this.estimate( edited, c, inserted );

	}

	/**
	 * With the changed points in `changed`: fits the edited probe (now at dense candidate c) to them
	 * and (for a move) to the points it blended, the other probes held, and sums the error change.
	 * @param edited Local index of the inserted or moved probe.
	 */
	private estimate( edited: number, c: number, inserted: boolean ): number {

		const { context, layout, changed } = this, stamp = ++ this.stamp;
		const points = this.trialPoints;
		let count = 0;
		for ( let f = 0; f < changed.count; f ++ ) {

			const j = changed.points[ f ];
			this.pointStamp[ j ] = stamp;
			this.pointEntry[ j ] = f;
			if ( context.weights[ j ] > 0 ) points[ count ++ ] = j;

		}

		if ( ! inserted ) {

			// A moved probe no longer blends the points it did (unless found again in its new cells).
			for ( let k = layout.adjacencyStart[ edited ], end = layout.adjacencyStart[ edited + 1 ]; k < end; k ++ ) {

				const j = layout.adjacency[ k ];
				if ( this.pointStamp[ j ] === stamp ) continue;
				this.pointStamp[ j ] = stamp;
				this.pointEntry[ j ] = - 1;
				points[ count ++ ] = j;

			}

		}

		const stride = layout.stride, unknowns = this.trialUnknowns, rows = this.trialRows, positions = this.trialPositions;
		positions.set( context.positions.subarray( 3 * c, 3 * c + 3 ), 3 * edited );
		let change = NaN;
		if ( this.solve( points, count, edited, c, inserted ) ) {

			writeUnknownRows( context, unknowns, edited, stride, rows );
			change = 0;
			for ( let q = 0; q < count; q ++ ) {

				const j = points[ q ];
				const f = this.pointEntry[ j ];
				const error = f >= 0
					? predictedError( context, j, changed.slots, changed.weights, positions, rows, stride, layout.lengthScale, 4 * f )
					: predictedError( context, j, layout.slots, layout.slotWeights, positions, rows, stride, layout.lengthScale );
				change += context.weights[ j ] * ( error - layout.errors[ j ] );

			}

			change /= context.totalWeight;

		}

		if ( ! inserted ) this.restoreProbe( edited );
		return change;

	}

	/**
	 * Minimises (1/Σs)·Σ s‖prediction − truth‖² + (λ/n)·‖c − c̄‖² + (λg/n)·‖h·G‖² over the edited
	 * probe's unknowns alone (`fitProbeSH`'s objective, the other probes held), over `points`,
	 * writing them into the trial unknowns.
	 * @returns false when its system stayed singular.
	 */
	private solve( points: Int32Array, count: number, edited: number, c: number, inserted: boolean ): boolean {

		const { context, layout, changed, matrix, rhs, factors, heldBase, heldFactors } = this;
		const stride = layout.stride, h = layout.lengthScale, unknowns = this.trialUnknowns, positions = this.trialPositions;
		const sh = context.sh;
		matrix.fill( 0 );
		rhs.fill( 0 );
		for ( let q = 0; q < count; q ++ ) {

			const j = points[ q ], f = this.pointEntry[ j ];
			const slots = f >= 0 ? changed.slots : layout.slots, weights = f >= 0 ? changed.weights : layout.slotWeights;
			const offset = f >= 0 ? 4 * f : 4 * j;
			const x = context.positions[ 3 * j ], y = context.positions[ 3 * j + 1 ], z = context.positions[ 3 * j + 2 ];
			let blended = false, held = 0;
			for ( let s = 0; s < 4; s ++ ) {

				const i = slots[ offset + s ];
				if ( i < 0 ) continue;
				const w = weights[ offset + s ];
				if ( stride === 1 ) {

					// No gradient unknowns: the weight alone.
					if ( i === edited ) {

						factors[ 0 ] = w;
						blended = true;

					} else {

						heldBase[ held ] = 27 * i;
						heldFactors[ 4 * held ] = w;
						held ++;

					}

					continue;

				}

				const fx = w * ( x - positions[ 3 * i ] ) / h, fy = w * ( y - positions[ 3 * i + 1 ] ) / h;
				const fz = w * ( z - positions[ 3 * i + 2 ] ) / h;
				if ( i === edited ) {

					factors[ 0 ] = w; factors[ 1 ] = fx; factors[ 2 ] = fy; factors[ 3 ] = fz;
					blended = true;
					continue;

				}

				// A probe held at its fit: its part of the prediction moves to the target side (below, in slot order).
				heldBase[ held ] = 27 * stride * i;
				heldFactors[ 4 * held ] = w; heldFactors[ 4 * held + 1 ] = fx;
				heldFactors[ 4 * held + 2 ] = fy; heldFactors[ 4 * held + 3 ] = fz;
				held ++;

			}

			// A point the edited probe does not blend adds nothing: its target is not needed.
			if ( ! blended ) continue;
			const share = context.weights[ j ] / context.totalWeight;
			for ( let u = 0; u < stride; u ++ ) {

				const fu = share * factors[ u ];
				for ( let v = 0; v < stride; v ++ ) matrix[ stride * u + v ] += fu * factors[ v ];

			}

			// Each coefficient's target (the truth less the held probes' parts, in slot order) goes straight into
			// the right-hand sides: the same operations, in the same order, as a target array would take.
			const t0 = 27 * j;
			if ( stride === 1 ) {

				// Unrolled by the number of held probes (0 to 3), subtracted in slot order as a loop would.
				const fu = share * factors[ 0 ];
				const h0 = heldBase[ 0 ], h1 = heldBase[ 1 ], h2 = heldBase[ 2 ];
				const g0 = heldFactors[ 0 ], g1 = heldFactors[ 4 ], g2 = heldFactors[ 8 ];
				if ( held === 3 ) {

					for ( let k = 0; k < 27; k ++ ) {

						let value = sh[ t0 + k ];
						value -= g0 * unknowns[ h0 + k ];
						value -= g1 * unknowns[ h1 + k ];
						value -= g2 * unknowns[ h2 + k ];
						rhs[ k ] += fu * value;

					}

				} else if ( held === 2 ) {

					for ( let k = 0; k < 27; k ++ ) {

						let value = sh[ t0 + k ];
						value -= g0 * unknowns[ h0 + k ];
						value -= g1 * unknowns[ h1 + k ];
						rhs[ k ] += fu * value;

					}

				} else {

					for ( let k = 0; k < 27; k ++ ) {

						let value = sh[ t0 + k ];
						for ( let e = 0; e < held; e ++ ) value -= heldFactors[ 4 * e ] * unknowns[ heldBase[ e ] + k ];
						rhs[ k ] += fu * value;

					}

				}

				continue;

			}

			const f0 = share * factors[ 0 ], f1 = share * factors[ 1 ], f2 = share * factors[ 2 ], f3 = share * factors[ 3 ];
			for ( let k = 0; k < 27; k ++ ) {

				let value = sh[ t0 + k ];
				for ( let e = 0; e < held; e ++ ) {

					const base = heldBase[ e ], o = 4 * e;
					let v = heldFactors[ o ] * unknowns[ base + k ];
					v += heldFactors[ o + 1 ] * unknowns[ base + 27 + k ] + heldFactors[ o + 2 ] * unknowns[ base + 54 + k ]
						+ heldFactors[ o + 3 ] * unknowns[ base + 81 + k ];
					value -= v;

				}

				rhs[ k ] += f0 * value;
				rhs[ 27 + k ] += f1 * value;
				rhs[ 54 + k ] += f2 * value;
				rhs[ 81 + k ] += f3 * value;

			}

		}

		// The pull toward the probe's captured SH and toward zero gradient, as fitProbeSH weighs it per probe.
		const reached = layout.reached + ( inserted ? 1 : 0 );
		const pullC = layout.result.lambda / reached, pullG = layout.result.gradientLambda / reached;
		for ( let u = 0; u < stride; u ++ ) matrix[ stride * u + u ] += u === 0 ? pullC : pullG;
		for ( let k = 0; k < 27; k ++ ) rhs[ k ] += pullC * context.sh[ 27 * c + k ];
		if ( ! solveDenseSPD( matrix, stride, rhs, 27, this.matrixCopy ) ) return false;
		unknowns.set( rhs.subarray( 0, 27 * stride ), 27 * stride * edited );
		return true;

	}

	/** Copies the layout's positions, unknowns and rows into the trial arrays (room for one probe more). */
	private copyLayout(): void {

		const layout = this.layout, size = layout.order.length + 1, stride = layout.stride;
		if ( this.trialPositions.length < 3 * size ) {

			this.trialPositions = new Float64Array( 3 * ( size + 16 ) );
			this.trialUnknowns = new Float64Array( 27 * stride * ( size + 16 ) );
			this.trialRows = new Float64Array( this.context.stride * stride * ( size + 16 ) );

		}

		this.trialPositions.set( layout.positions );
		this.trialUnknowns.set( layout.unknowns );
		this.trialRows.set( layout.rows );

	}

	/** Puts local probe i's layout values back into the trial arrays. */
	private restoreProbe( i: number ): void {

		const layout = this.layout, unknownFloats = 27 * layout.stride, rowFloats = this.context.stride * layout.stride;
		this.trialPositions.set( layout.positions.subarray( 3 * i, 3 * i + 3 ), 3 * i );
		this.trialUnknowns.set( layout.unknowns.subarray( unknownFloats * i, unknownFloats * ( i + 1 ) ), unknownFloats * i );
		this.trialRows.set( layout.rows.subarray( rowFloats * i, rowFloats * ( i + 1 ) ), rowFloats * i );

	}

}
