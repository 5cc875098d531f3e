import type { DynamicTetrahedralization } from '../tetrahedra/DynamicTetrahedralization.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import type { PointGrid } from './PointGrid.js';
import type { FittedLayout } from './refitLayout.js';

// Barycentric slack: a point this far outside a changed cell (in weight units) still belongs to it.
const INSIDE_SLACK = 1e-10;

// A changed cell's box is padded by this fraction of its size before its points get weights (INSIDE_SLACK reaches ~1e-10 of it).
const BOX_PAD = 1e-6;

// Two weights closer than this are the same (the same cell, computed from another inverse).
const SAME_WEIGHT = 1e-12;

// Two unit normals of an outer cell's vertex closer than this per coordinate are the same: the same
// angle-weighted sums taken in another face order (a few ulps). Weights in an outer cell move by
// about the normals' change times the point's distance over the cell's size, far below SAME_WEIGHT.
const SAME_NORMAL = 1e-14;

/**
 * The points of a fit set whose interpolation weights a trial edit of a layout changed, with their
 * new weights: entry f is point `points[ f ]`, blended by local probes `slots[ 4f … 4f + 3 ]` (−1:
 * none) with `weights[ 4f … ]`. Filled by {@link ChangedPoints.inChangedCells} (a local edit of a
 * dynamic tetrahedralization) or {@link ChangedPoints.inMesh} (a new interpolator); reused between
 * trials.
 */
export class ChangedPoints {

	/** Entries found by the last call. */
	count = 0;

	/** Point index of each entry. */
	points = new Int32Array( 64 );

	/** 4 local probes per entry (−1 for a zero weight). */
	slots = new Int32Array( 256 );

	/** 4 weights per entry, ≥ 0, summing to 1. */
	weights = new Float64Array( 256 );

	private readonly seen: Int32Array;
	private stamp = 0;
	private readonly range = new Int32Array( 6 );
	private readonly cellProbes = new Int32Array( 4 );
	private readonly cellMatrix = new Float64Array( 12 );
	private readonly indices = new Uint32Array( 4 );
	private readonly values = new Float64Array( 4 );
	// The kept cells of the last `inMesh` (their cellKeys): an open-addressing table, −1 for empty.
	private table = new Float64Array( 1024 );
	private tableShift = 22;

	/** @param pointCount Points in the fit set. */
	constructor( pointCount: number ) {

		this.seen = new Int32Array( pointCount );

	}

	/**
	 * The points inside the cells `dynamic`'s last edit created (or renumbered) whose weights there
	 * differ from `layout`'s. Points outside the hull are not looked at: the edit must have kept it.
	 * @param idToLocal Local probe of each mesh point id.
	 * @param grid The fit set's points, for "which lie in this cell's box".
	 * @returns The number of entries.
	 */
	inChangedCells( dynamic: DynamicTetrahedralization, idToLocal: Int32Array, grid: PointGrid, layout: FittedLayout ): number {

		const cells = dynamic.lastEdit.changedCells, tetrahedra = dynamic.tetrahedra, p = dynamic.positions;
		const probes = this.cellProbes, matrix = this.cellMatrix, range = this.range;
		const start = grid.start, gridPoints = grid.points, sorted = grid.sorted;
		const stamp = ++ this.stamp;
		this.count = 0;
		for ( let k = 0; k < cells.length; k ++ ) {

			const t = cells[ k ];
			let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = - Infinity, maxY = - Infinity, maxZ = - Infinity;
			for ( let v = 0; v < 4; v ++ ) {

				const id = tetrahedra[ 4 * t + v ], x = p[ 3 * id ], y = p[ 3 * id + 1 ], z = p[ 3 * id + 2 ];
				probes[ v ] = idToLocal[ id ];
				if ( x < minX ) minX = x;
				if ( x > maxX ) maxX = x;
				if ( y < minY ) minY = y;
				if ( y > maxY ) maxY = y;
				if ( z < minZ ) minZ = z;
				if ( z > maxZ ) maxZ = z;

			}

			writeCellInverse( p, tetrahedra, t, matrix );
			// The grid cells overhang the cell's box: a point outside the box (padded far beyond the barycentric
			// slack's reach) cannot be inside the cell, and skips the weights.
			const pad = BOX_PAD * Math.max( maxX - minX, maxY - minY, maxZ - minZ );
			const loX = minX - pad, loY = minY - pad, loZ = minZ - pad, hiX = maxX + pad, hiY = maxY + pad, hiZ = maxZ + pad;
			// The points in the grid cells the cell's box overlaps, read in place.
			grid.cellRange( minX, minY, minZ, maxX, maxY, maxZ, range );
			for ( let gz = range[ 2 ]; gz <= range[ 5 ]; gz ++ ) for ( let gy = range[ 1 ]; gy <= range[ 4 ]; gy ++ ) {

				for ( let gx = range[ 0 ]; gx <= range[ 3 ]; gx ++ ) {

					const c = grid.cellIndex( gx, gy, gz );
					for ( let q = start[ c ], end = start[ c + 1 ]; q < end; q ++ ) {

						const x = sorted[ 3 * q ], y = sorted[ 3 * q + 1 ], z = sorted[ 3 * q + 2 ];
						if ( x < loX || x > hiX || y < loY || y > hiY || z < loZ || z > hiZ ) continue;
						this.tryPoint( gridPoints[ q ], x, y, z, probes, layout, stamp );

					}

				}

			}

		}

		return this.count;

	}

	/**
	 * Records point j, at (x, y, z), when it lies in the cell of `cellMatrix` / `probes` (and was in
	 * no earlier one) and its weights changed.
	 */
	private tryPoint( j: number, x: number, y: number, z: number, probes: Int32Array, layout: FittedLayout, stamp: number ): void {

		const matrix = this.cellMatrix;
		if ( this.seen[ j ] === stamp ) return; // already placed in another changed cell
		const dx = x - matrix[ 9 ], dy = y - matrix[ 10 ], dz = z - matrix[ 11 ];
		const w0 = matrix[ 0 ] * dx + matrix[ 1 ] * dy + matrix[ 2 ] * dz;
		const w1 = matrix[ 3 ] * dx + matrix[ 4 ] * dy + matrix[ 5 ] * dz;
		const w2 = matrix[ 6 ] * dx + matrix[ 7 ] * dy + matrix[ 8 ] * dz;
		const w3 = 1 - w0 - w1 - w2;
		if ( ! ( w0 >= - INSIDE_SLACK && w1 >= - INSIDE_SLACK && w2 >= - INSIDE_SLACK && w3 >= - INSIDE_SLACK ) ) return;
		this.seen[ j ] = stamp;
		this.record( j, probes, w0, w1, w2, w3 );
		if ( ! this.sameAsLayout( layout, j ) ) this.count ++;

	}

	/**
	 * Every point located in `interpolator` (a layout edited in a way that moves the hull, so outer
	 * cells change too), kept when its weights differ from `layout`'s or it blends probe `moved`.
	 * @param visitOrder The points in the order to locate them (short walks).
	 * @param moved Local probe that moved (−1 for none): its points change even at equal weights.
	 * @returns The number of entries.
	 */
	inMesh(
		interpolator: ProbeInterpolator, positions: Float64Array, visitOrder: Uint32Array, layout: FittedLayout, moved: number,
	): number {

		const indices = this.indices, values = this.values, probes = this.cellProbes, slots = layout.slots;
		const kept = interpolator instanceof TetrahedralMesh;
		if ( kept ) this.keepCells( interpolator, moved, layout.order.length );
		const keys = innerKeys( layout );
		const before = layout.interpolator;
		const keptOuter = interpolator instanceof TetrahedralMesh && before instanceof TetrahedralMesh
			? keptOuterCells( interpolator, before, moved ) : null;
		const outerStart = before instanceof TetrahedralMesh ? before.cellCount : 0, cells = layout.cells;
		let hint = - 1;
		this.count = 0;
		for ( let v = 0; v < visitOrder.length; v ++ ) {

			const j = visitOrder[ v ];
			// An inner point whose tetrahedron (all 4 weights > 0) is still a cell keeps its weights; so does
			// an outer point whose outer cell is still one, unchanged.
			const o = 4 * j;
			if ( layout.outside[ j ] === 0 ) {

				if ( kept && keys[ j ] >= 0 && this.hasKey( keys[ j ] ) ) continue;

			} else if ( keptOuter !== null && keptOuter[ cells[ j ] - outerStart ] === 1 ) continue;

			values.fill( 0 );
			hint = interpolator.interpolate( positions[ 3 * j ], positions[ 3 * j + 1 ], positions[ 3 * j + 2 ], indices, values, hint );
			for ( let s = 0; s < 4; s ++ ) probes[ s ] = indices[ s ];
			this.record( j, probes, values[ 0 ], values[ 1 ], values[ 2 ], values[ 3 ] );
			const usesMoved = moved >= 0
				&& ( slots[ o ] === moved || slots[ o + 1 ] === moved || slots[ o + 2 ] === moved || slots[ o + 3 ] === moved );
			if ( usesMoved || ! this.sameAsLayout( layout, j ) ) this.count ++;

		}

		return this.count;

	}

	/**
	 * Fills the table with the cells of `mesh` that the layout's mesh may share: those without the
	 * edited probe (`moved`, or the inserted one, `size`).
	 */
	private keepCells( mesh: TetrahedralMesh, moved: number, size: number ): void {

		const edited = moved >= 0 ? moved : size, t = mesh.tetrahedra, cells = mesh.cellCount;
		let bits = 10;
		while ( ( 1 << bits ) < 4 * cells ) bits ++;
		if ( this.table.length !== 1 << bits ) this.table = new Float64Array( 1 << bits );
		this.table.fill( - 1 );
		this.tableShift = 32 - bits;
		const table = this.table, mask = table.length - 1;
		for ( let k = 0; k < cells; k ++ ) {

			const a = t[ 4 * k ], b = t[ 4 * k + 1 ], c = t[ 4 * k + 2 ], d = t[ 4 * k + 3 ];
			if ( a === edited || b === edited || c === edited || d === edited ) continue;
			const key = cellKey( a, b, c, d );
			if ( key < 0 ) continue;
			let slot = keySlot( key, this.tableShift );
			while ( table[ slot ] >= 0 && table[ slot ] !== key ) slot = ( slot + 1 ) & mask;
			table[ slot ] = key;

		}

	}

	/** Whether cell key `key` is in the table of kept cells. */
	private hasKey( key: number ): boolean {

		const table = this.table, mask = table.length - 1;
		let slot = keySlot( key, this.tableShift );
		for ( ;; ) {

			const entry = table[ slot ];
			if ( entry === key ) return true;
			if ( entry < 0 ) return false;
			slot = ( slot + 1 ) & mask;

		}

	}

	/** Writes entry `count` (not yet counted): point j, the 4 probes and their weights (clamped to ≥ 0, summing to 1). */
	private record( j: number, probes: Int32Array, w0: number, w1: number, w2: number, w3: number ): void {

		const f = this.count;
		if ( this.points.length <= f ) {

			const points = new Int32Array( 2 * f + 64 ), slots = new Int32Array( 8 * f + 256 );
			const weights = new Float64Array( 8 * f + 256 );
			points.set( this.points );
			slots.set( this.slots );
			weights.set( this.weights );
			this.points = points;
			this.slots = slots;
			this.weights = weights;

		}

		w0 = Math.max( w0, 0 ); w1 = Math.max( w1, 0 ); w2 = Math.max( w2, 0 ); w3 = Math.max( w3, 0 );
		const sum = w0 + w1 + w2 + w3, o = 4 * f;
		this.points[ f ] = j;
		this.weights[ o ] = w0 / sum; this.weights[ o + 1 ] = w1 / sum;
		this.weights[ o + 2 ] = w2 / sum; this.weights[ o + 3 ] = w3 / sum;
		for ( let s = 0; s < 4; s ++ ) this.slots[ o + s ] = this.weights[ o + s ] === 0 ? - 1 : probes[ s ];

	}

	/** Whether entry `count` gives point j the weights it has in the layout (a renumbered cell, or a boundary point). */
	private sameAsLayout( layout: FittedLayout, j: number ): boolean {

		const slots = layout.slots, weights = layout.slotWeights, f = this.count;
		for ( let s = 0; s < 4; s ++ ) {

			const i = this.slots[ 4 * f + s ];
			if ( i < 0 ) continue;
			let match = false;
			for ( let r = 0; r < 4 && ! match; r ++ ) {

				match = slots[ 4 * j + r ] === i && Math.abs( weights[ 4 * j + r ] - this.weights[ 4 * f + s ] ) <= SAME_WEIGHT;

			}

			if ( ! match ) return false;

		}

		return true;

	}

}

/**
 * The inverse of [ p0 − p3, p1 − p3, p2 − p3 ] of tetrahedron t (row-major, 9 floats) and p3 (3
 * floats) in `out`: (w0, w1, w2) = inverse · (q − p3).
 */
function writeCellInverse( p: Float64Array, tetrahedra: Uint32Array, t: number, out: Float64Array ): void {

	const a = 3 * tetrahedra[ 4 * t ], b = 3 * tetrahedra[ 4 * t + 1 ], c = 3 * tetrahedra[ 4 * t + 2 ], d = 3 * tetrahedra[ 4 * t + 3 ];
	const m00 = p[ a ] - p[ d ], m10 = p[ a + 1 ] - p[ d + 1 ], m20 = p[ a + 2 ] - p[ d + 2 ];
	const m01 = p[ b ] - p[ d ], m11 = p[ b + 1 ] - p[ d + 1 ], m21 = p[ b + 2 ] - p[ d + 2 ];
	const m02 = p[ c ] - p[ d ], m12 = p[ c + 1 ] - p[ d + 1 ], m22 = p[ c + 2 ] - p[ d + 2 ];
	const c00 = m11 * m22 - m12 * m21, c01 = m02 * m21 - m01 * m22, c02 = m01 * m12 - m02 * m11;
	const c10 = m12 * m20 - m10 * m22, c11 = m00 * m22 - m02 * m20, c12 = m02 * m10 - m00 * m12;
	const c20 = m10 * m21 - m11 * m20, c21 = m01 * m20 - m00 * m21, c22 = m00 * m11 - m01 * m10;
	const inverse = 1 / ( m00 * c00 + m01 * c10 + m02 * c20 );
	out[ 0 ] = c00 * inverse; out[ 1 ] = c01 * inverse; out[ 2 ] = c02 * inverse;
	out[ 3 ] = c10 * inverse; out[ 4 ] = c11 * inverse; out[ 5 ] = c12 * inverse;
	out[ 6 ] = c20 * inverse; out[ 7 ] = c21 * inverse; out[ 8 ] = c22 * inverse;
	out[ 9 ] = p[ d ]; out[ 10 ] = p[ d + 1 ]; out[ 11 ] = p[ d + 2 ];

}

/** A key for the tetrahedron of 4 local probes (any order; −1 in any slot: no key). */
function cellKey( a: number, b: number, c: number, d: number ): number {

	if ( a < 0 || b < 0 || c < 0 || d < 0 ) return - 1;
	// Sorting network for 4, then 13 bits per probe (layouts of up to 8192 probes; larger ones get no keys).
	let t: number;
	if ( a > b ) { t = a; a = b; b = t; }
	if ( c > d ) { t = c; c = d; d = t; }
	if ( a > c ) { t = a; a = c; c = t; }
	if ( b > d ) { t = b; b = d; d = t; }
	if ( b > c ) { t = b; b = c; c = t; }
	if ( d >= 8192 ) return - 1;
	return ( ( a * 8192 + b ) * 8192 + c ) * 8192 + d;

}

/**
 * Per outer cell of `before` (a layout's mesh), 1 when `mesh` (the layout edited) has the same
 * cell: the same hull triangle, none of its vertices the moved probe, and the same outward normals
 * at its vertices (to {@link SAME_NORMAL}: the sums' order) — the same swept region, and weights in it
 * that {@link ChangedPoints.inMesh} would find the same as the layout's.
 * @param moved Local probe that moved (−1 for an insertion: the new probe is in no cell of `before`).
 */
function keptOuterCells( mesh: TetrahedralMesh, before: TetrahedralMesh, moved: number ): Uint8Array {

	const now = mesh.outerCells, then = before.outerCells, kept = new Uint8Array( then.count );
	if ( now.exponent !== then.exponent ) return kept; // another local frame: the normals are not comparable
	const faces = new Map<number, number>();
	for ( let f = 0; f < now.count; f ++ ) faces.set( faceKey( now.faces, f ), f );
	const a = now.normals, b = then.normals;
	for ( let f = 0; f < then.count; f ++ ) {

		if ( ! faces.has( faceKey( then.faces, f ) ) ) continue;
		let same = true;
		for ( let v = 0; v < 3 && same; v ++ ) {

			const i = then.faces[ 3 * f + v ], k = 3 * i;
			same = i !== moved && Math.abs( a[ k ] - b[ k ] ) <= SAME_NORMAL && Math.abs( a[ k + 1 ] - b[ k + 1 ] ) <= SAME_NORMAL
				&& Math.abs( a[ k + 2 ] - b[ k + 2 ] ) <= SAME_NORMAL;

		}

		if ( same ) kept[ f ] = 1;

	}

	return kept;

}

/** A key for hull triangle f of `faces` (its 3 probes in any order; probes below 2²⁰). */
function faceKey( faces: Uint32Array, f: number ): number {

	let a = faces[ 3 * f ], b = faces[ 3 * f + 1 ], c = faces[ 3 * f + 2 ], t: number;
	if ( a > b ) { t = a; a = b; b = t; }
	if ( b > c ) { t = b; b = c; c = t; }
	if ( a > b ) { t = a; a = b; b = t; }
	return ( a * 1048576 + b ) * 1048576 + c;

}

/** The table slot of a cell key (< 2⁵²): its two 32-bit halves mixed, the top bits kept. */
function keySlot( key: number, shift: number ): number {

	const low = key | 0, high = ( key / 4294967296 ) | 0;
	return Math.imul( low ^ Math.imul( high, 0x27d4eb2d ), 0x9e3779b1 ) >>> shift;

}

/** Per point of `layout`, the {@link cellKey} of its tetrahedron (−1 outside the hull or on a cell's boundary). */
function innerKeys( layout: FittedLayout ): Float64Array {

	const known = keyCache.get( layout );
	if ( known ) return known;
	const slots = layout.slots, count = layout.outside.length, out = new Float64Array( count );
	for ( let j = 0; j < count; j ++ ) {

		const o = 4 * j;
		out[ j ] = layout.outside[ j ] === 1 ? - 1 : cellKey( slots[ o ], slots[ o + 1 ], slots[ o + 2 ], slots[ o + 3 ] );

	}

	keyCache.set( layout, out );
	return out;

}

const keyCache = new WeakMap<FittedLayout, Float64Array>();
