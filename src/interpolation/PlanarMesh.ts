import Delaunator from 'delaunator';
import { boundsOf } from '../geometry/boundsOf.js';
import { assertOptionalNumber, assertPoints } from '../validate.js';
import { DegenerateInputError } from '../tetrahedra/tetrahedralize.js';
import { mergeDuplicates } from '../tetrahedra/mergeDuplicates.js';
import { extentExponent, scaleInPlace, timesPowerOfTwo } from '../tetrahedra/powerOfTwo.js';
import type { ProbeInterpolator } from './ProbeInterpolator.js';

const INSIDE_EPSILON = 1e-12;

// Layouts whose largest side is within 2^±LOCAL_RANGE keep their coordinates; others work in a copy
// scaled by a power of two to unit size (squares and covariances neither over- nor underflow).
const LOCAL_RANGE = 100;
const _weights = new Float64Array( 3 );

/**
 * Interpolation for probes that all lie in one plane — a single floor of probes, or the paper's
 * photo map (Kyoto): a 2D Delaunay triangulation (`delaunator`) in the best-fit plane, with
 * 3-probe barycentric weights. Positions are projected onto the plane first, so the field is
 * constant along the plane's normal; outside the triangulated region the weights are those of
 * the nearest point on its boundary.
 *
 * Output has 4 slots like {@link TetrahedralMesh}; the fourth weight is always 0. Any scale: a
 * layout far from unit size is handled in a copy scaled by 2^−exponent (docs/robustness.md).
 */
export class PlanarMesh implements ProbeInterpolator {

	/** Probe positions, x, y, z per probe. */
	readonly positions: Float64Array;

	/** Probe positions in plane coordinates (u, v per probe), in the local frame. */
	readonly planePositions: Float64Array;

	/** Three probe indices per triangle, counter-clockwise in plane coordinates. */
	readonly triangles: Uint32Array;

	/** `neighbors[3t + e]`: the triangle across edge e (from vertex e to vertex e + 1) of t, or −1. */
	readonly neighbors: Int32Array;

	/** Pairs (merged probe, probe it was merged into). */
	readonly duplicates: Uint32Array;

	/** A point of the plane (the probes' centroid), in the local frame. */
	readonly origin: Float64Array;

	/**
	 * The local frame's power of two: `origin` and `planePositions` are in units of 2^exponent. 0
	 * (the positions' own units) unless the layout's size is beyond 2^±100.
	 */
	readonly exponent: number;

	/** Unit normal of the best-fit plane, and the two unit axes spanning it: n, u, v (9 floats). */
	readonly axes: Float64Array;

	/** Boundary edges as pairs of probe indices, in hull order. */
	readonly hull: Uint32Array;

	/** Always 4 (three weights and a zero). */
	readonly weightCount = 4;

	private readonly inverseMatrices: Float64Array;
	private readonly toLocal: number;

	/**
	 * @param positions Flat x, y, z per probe; at least 3 probes not all on one line.
	 * @param duplicateTolerance Merge distance as a fraction of the bounding-box diagonal.
	 * @throws {RangeError} on NaN/Infinity, a length that is not a multiple of 3, or a tolerance
	 *   that is not a finite number ≥ 0 ({@link TypeError} when it is not a number).
	 */
	constructor( positions: ArrayLike<number>, duplicateTolerance = 1e-9 ) {

		const n = assertPoints( 'PlanarMesh', 'positions', positions );
		assertOptionalNumber( 'PlanarMesh', 'duplicateTolerance', duplicateTolerance, 0 );
		this.positions = Float64Array.from( positions );
		const k = extentExponent( boundsOf( this.positions, n ) );
		this.exponent = Math.abs( k ) <= LOCAL_RANGE ? 0 : Math.min( 1023, Math.max( - 1022, k ) );
		this.toLocal = timesPowerOfTwo( 1, - this.exponent );
		const p = this.exponent === 0 ? this.positions : this.positions.slice();
		scaleInPlace( p, p.length, this.exponent );
		const { unique, duplicates } = mergeDuplicates( p, duplicateTolerance );
		this.duplicates = duplicates;
		if ( unique.length < 3 ) {

			throw new DegenerateInputError( 'too-few-points', `PlanarMesh: positions has ${unique.length} distinct points; at least 3 are needed.` );

		}

		this.origin = new Float64Array( 3 );
		for ( const i of unique ) for ( let a = 0; a < 3; a ++ ) this.origin[ a ] += p[ 3 * i + a ] / unique.length;
		this.axes = bestFitAxes( p, unique, this.origin );

		this.planePositions = new Float64Array( 2 * n );
		for ( let i = 0; i < n; i ++ ) this.project( p[ 3 * i ], p[ 3 * i + 1 ], p[ 3 * i + 2 ], this.planePositions, 2 * i );

		const coords = new Float64Array( 2 * unique.length );
		for ( let k = 0; k < unique.length; k ++ ) {

			coords[ 2 * k ] = this.planePositions[ 2 * unique[ k ] ];
			coords[ 2 * k + 1 ] = this.planePositions[ 2 * unique[ k ] + 1 ];

		}

		const delaunay = new Delaunator( coords );
		if ( delaunay.triangles.length === 0 ) {

			throw new DegenerateInputError( 'collinear', `PlanarMesh: all ${unique.length} distinct probes lie on one line; they span no area.` );

		}

		this.triangles = new Uint32Array( delaunay.triangles.length );
		for ( let i = 0; i < this.triangles.length; i ++ ) this.triangles[ i ] = unique[ delaunay.triangles[ i ] ];
		this.neighbors = new Int32Array( delaunay.halfedges.length );
		for ( let i = 0; i < this.neighbors.length; i ++ ) {

			const h = delaunay.halfedges[ i ];
			this.neighbors[ i ] = h === - 1 ? - 1 : Math.floor( h / 3 );

		}

		const hull = delaunay.hull;
		this.hull = new Uint32Array( 2 * hull.length );
		for ( let i = 0; i < hull.length; i ++ ) {

			this.hull[ 2 * i ] = unique[ hull[ i ] ];
			this.hull[ 2 * i + 1 ] = unique[ hull[ ( i + 1 ) % hull.length ] ];

		}

		this.inverseMatrices = new Float64Array( 4 * ( this.triangles.length / 3 ) );
		const q = this.planePositions;
		for ( let t = 0, m = this.triangles.length / 3; t < m; t ++ ) {

			const a = 2 * this.triangles[ 3 * t ], b = 2 * this.triangles[ 3 * t + 1 ], c = 2 * this.triangles[ 3 * t + 2 ];
			// Columns: a − c, b − c.
			const m00 = q[ a ] - q[ c ], m10 = q[ a + 1 ] - q[ c + 1 ], m01 = q[ b ] - q[ c ], m11 = q[ b + 1 ] - q[ c + 1 ];
			const s = 1 / ( m00 * m11 - m01 * m10 );
			this.inverseMatrices.set( [ m11 * s, - m01 * s, - m10 * s, m00 * s ], 4 * t );

		}

	}

	/** Number of probes. */
	get probeCount(): number {

		return this.positions.length / 3;

	}

	/** Number of triangles. */
	get cellCount(): number {

		return this.triangles.length / 3;

	}

	/**
	 * Probes and weights for (x, y, z) projected onto the plane. Allocation-free.
	 * @returns The triangle used; pass it back as `hint` next time.
	 */
	interpolate(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[], hint = - 1,
	): number {

		const o = this.origin, ax = this.axes, s = this.toLocal;
		const dx = x * s - o[ 0 ], dy = y * s - o[ 1 ], dz = z * s - o[ 2 ];
		const u = dx * ax[ 3 ] + dy * ax[ 4 ] + dz * ax[ 5 ];
		const v = dx * ax[ 6 ] + dy * ax[ 7 ] + dz * ax[ 8 ];

		const count = this.triangles.length / 3;
		let t = hint >= 0 && hint < count ? hint | 0 : 0;
		let inside = false, left = false;
		for ( let steps = 0; steps <= count; steps ++ ) {

			this.barycentric( t, u, v );
			let worst = 0;
			for ( let i = 1; i < 3; i ++ ) if ( _weights[ i ] < _weights[ worst ] ) worst = i;
			if ( _weights[ worst ] >= - INSIDE_EPSILON ) { inside = true; break; }
			// The edge opposite vertex `worst` runs from vertex worst + 1 to worst + 2.
			const next = this.neighbors[ 3 * t + ( worst + 1 ) % 3 ];
			if ( next === - 1 ) { left = true; break; }
			t = next;

		}

		// A walk past its step bound (rounding can make one cycle): a scan of every triangle decides.
		if ( ! inside && ! left ) {

			for ( t = 0; t < count && ! inside; t ++ ) {

				this.barycentric( t, u, v );
				inside = _weights[ 0 ] >= - INSIDE_EPSILON && _weights[ 1 ] >= - INSIDE_EPSILON && _weights[ 2 ] >= - INSIDE_EPSILON;

			}

			t --;

		}

		if ( inside ) {

			let sum = 0;
			for ( let i = 0; i < 3; i ++ ) { _weights[ i ] = Math.max( 0, _weights[ i ] ); sum += _weights[ i ]; }
			for ( let i = 0; i < 3; i ++ ) {

				indices[ i ] = this.triangles[ 3 * t + i ];
				weights[ i ] = _weights[ i ] / sum;

			}

		} else {

			t = this.nearestOnHull( u, v, indices, weights );

		}

		indices[ 3 ] = indices[ 0 ];
		weights[ 3 ] = 0;
		return t;

	}

	private barycentric( t: number, u: number, v: number ): void {

		const q = this.planePositions, m = this.inverseMatrices;
		const c = 2 * this.triangles[ 3 * t + 2 ];
		const du = u - q[ c ], dv = v - q[ c + 1 ];
		const a = m[ 4 * t ] * du + m[ 4 * t + 1 ] * dv;
		const b = m[ 4 * t + 2 ] * du + m[ 4 * t + 3 ] * dv;
		_weights[ 0 ] = a; _weights[ 1 ] = b; _weights[ 2 ] = 1 - a - b;

	}

	/** Nearest point on the boundary polygon: two probes weighted along an edge. */
	private nearestOnHull(
		u: number, v: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[],
	): number {

		const q = this.planePositions, hull = this.hull;
		let best = Infinity;
		for ( let e = 0; e < hull.length; e += 2 ) {

			const a = 2 * hull[ e ], b = 2 * hull[ e + 1 ];
			const ex = q[ b ] - q[ a ], ey = q[ b + 1 ] - q[ a + 1 ];
			const s = Math.min( 1, Math.max( 0, ( ( u - q[ a ] ) * ex + ( v - q[ a + 1 ] ) * ey ) / ( ex * ex + ey * ey ) ) );
			const dx = q[ a ] + s * ex - u, dy = q[ a + 1 ] + s * ey - v;
			const d = dx * dx + dy * dy;
			if ( d < best ) {

				best = d;
				indices[ 0 ] = hull[ e ]; weights[ 0 ] = 1 - s;
				indices[ 1 ] = hull[ e + 1 ]; weights[ 1 ] = s;
				indices[ 2 ] = hull[ e ]; weights[ 2 ] = 0;

			}

		}

		// Any triangle on that edge serves as the hint.
		for ( let t = 0, n = this.triangles.length / 3; t < n; t ++ ) {

			for ( let i = 0; i < 3; i ++ ) if ( this.triangles[ 3 * t + i ] === indices[ 0 ] ) return t;

		}

		return 0;

	}

	private project( x: number, y: number, z: number, out: Float64Array, offset: number ): void {

		const o = this.origin, ax = this.axes;
		const dx = x - o[ 0 ], dy = y - o[ 1 ], dz = z - o[ 2 ];
		out[ offset ] = dx * ax[ 3 ] + dy * ax[ 4 ] + dz * ax[ 5 ];
		out[ offset + 1 ] = dx * ax[ 6 ] + dy * ax[ 7 ] + dz * ax[ 8 ];

	}

}

/**
 * Normal and in-plane axes of the least-squares plane through the points: eigenvectors of their
 * covariance (Jacobi rotations), smallest eigenvalue first.
 */
function bestFitAxes( p: Float64Array, indices: Uint32Array, origin: Float64Array ): Float64Array {

	const c = new Float64Array( 9 );
	for ( const i of indices ) {

		const d = [ p[ 3 * i ] - origin[ 0 ], p[ 3 * i + 1 ] - origin[ 1 ], p[ 3 * i + 2 ] - origin[ 2 ] ];
		for ( let r = 0; r < 3; r ++ ) for ( let s = 0; s < 3; s ++ ) c[ 3 * r + s ] += d[ r ] * d[ s ];

	}

	const vectors = new Float64Array( [ 1, 0, 0, 0, 1, 0, 0, 0, 1 ] ); // columns are eigenvectors
	for ( let sweep = 0; sweep < 50; sweep ++ ) {

		const off = Math.abs( c[ 1 ] ) + Math.abs( c[ 2 ] ) + Math.abs( c[ 5 ] );
		if ( off < 1e-30 * ( Math.abs( c[ 0 ] ) + Math.abs( c[ 4 ] ) + Math.abs( c[ 8 ] ) ) ) break;
		for ( const [ r, s ] of [ [ 0, 1 ], [ 0, 2 ], [ 1, 2 ] ] ) {

			const crs = c[ 3 * r + s ];
			if ( crs === 0 ) continue;
			const theta = ( c[ 3 * s + s ] - c[ 3 * r + r ] ) / ( 2 * crs );
			const t = Math.sign( theta || 1 ) / ( Math.abs( theta ) + Math.sqrt( theta * theta + 1 ) );
			const cos = 1 / Math.sqrt( t * t + 1 ), sin = t * cos;
			for ( let k = 0; k < 3; k ++ ) { // C ← C·J

				const a = c[ 3 * k + r ], b = c[ 3 * k + s ];
				c[ 3 * k + r ] = cos * a - sin * b; c[ 3 * k + s ] = sin * a + cos * b;

			}

			for ( let k = 0; k < 3; k ++ ) { // C ← Jᵀ·C

				const a = c[ 3 * r + k ], b = c[ 3 * s + k ];
				c[ 3 * r + k ] = cos * a - sin * b; c[ 3 * s + k ] = sin * a + cos * b;

			}

			for ( let k = 0; k < 3; k ++ ) {

				const a = vectors[ 3 * k + r ], b = vectors[ 3 * k + s ];
				vectors[ 3 * k + r ] = cos * a - sin * b; vectors[ 3 * k + s ] = sin * a + cos * b;

			}

		}

	}

	const order = [ 0, 1, 2 ].sort( ( a, b ) => c[ 4 * a ] - c[ 4 * b ] );
	const axes = new Float64Array( 9 );

	// A plane facing a coordinate axis (a floor, a wall) gets exact unit axes: plane coordinates
	// are then plain coordinate differences, so probes in a row stay exactly in a row and the 2D
	// triangulation has no sliver triangles from rounding.
	for ( let k = 0; k < 3; k ++ ) {

		const normal = vectors[ 3 * k + order[ 0 ] ];
		if ( Math.abs( normal ) > 1 - 1e-9 ) {

			axes[ k ] = 1;
			axes[ 3 + ( k + 1 ) % 3 ] = 1;
			axes[ 6 + ( k + 2 ) % 3 ] = 1;
			return axes;

		}

	}

	for ( let k = 0; k < 3; k ++ ) for ( let a = 0; a < 3; a ++ ) axes[ 3 * k + a ] = vectors[ 3 * a + order[ k ] ];
	// u × v = n keeps the plane coordinates right-handed.
	const [ nx, ny, nz, ux, uy, uz ] = axes;
	axes[ 6 ] = ny * uz - nz * uy; axes[ 7 ] = nz * ux - nx * uz; axes[ 8 ] = nx * uy - ny * ux;
	return axes;

}
