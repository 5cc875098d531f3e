import { checkGridSpec } from './gridSpec.js';
import type { ProbeInterpolator } from './ProbeInterpolator.js';

/**
 * The paper's baseline: probes on a regular grid over a box, blended with 8-probe trilinear
 * weights (the same scheme as three.js's `LightProbeGrid`). Positions outside the box are clamped
 * to it, as a grid texture with clamp-to-edge sampling would do.
 *
 * Probe (i, j, k) has index `i + counts[0] · (j + counts[1] · k)`, x varying fastest.
 */
export class GridInterpolator implements ProbeInterpolator {

	/** Minimum corner of the box; the probe (0, 0, 0) sits here. */
	readonly min: Float64Array;

	/** Maximum corner of the box; the last probe sits here. */
	readonly max: Float64Array;

	/** Probes per axis, each ≥ 2. */
	readonly counts: Uint32Array;

	/** Probe positions, x, y, z per probe, in index order. */
	readonly positions: Float64Array;

	/** Always 8. */
	readonly weightCount = 8;

	/**
	 * @param min Box minimum [x, y, z].
	 * @param max Box maximum [x, y, z]; strictly greater than `min` on every axis.
	 * @param counts Probes per axis [nx, ny, nz], each ≥ 2 (the paper's Basic scene: [4, 4, 4]).
	 */
	constructor( min: ArrayLike<number>, max: ArrayLike<number>, counts: ArrayLike<number> ) {

		checkGridSpec( 'GridInterpolator', min, max, counts );
		this.min = Float64Array.from( min );
		this.max = Float64Array.from( max );
		this.counts = Uint32Array.from( counts );

		const [ nx, ny, nz ] = this.counts;
		this.positions = new Float64Array( 3 * nx * ny * nz );
		for ( let k = 0, o = 0; k < nz; k ++ ) for ( let j = 0; j < ny; j ++ ) for ( let i = 0; i < nx; i ++, o += 3 ) {

			this.positions[ o ] = lerp( this.min[ 0 ], this.max[ 0 ], i / ( nx - 1 ) );
			this.positions[ o + 1 ] = lerp( this.min[ 1 ], this.max[ 1 ], j / ( ny - 1 ) );
			this.positions[ o + 2 ] = lerp( this.min[ 2 ], this.max[ 2 ], k / ( nz - 1 ) );

		}

	}

	/** Number of probes. */
	get probeCount(): number {

		return this.counts[ 0 ] * this.counts[ 1 ] * this.counts[ 2 ];

	}

	/** Number of boxes (cells between 8 probes): the paper's "boxes" column. */
	get cellCount(): number {

		return ( this.counts[ 0 ] - 1 ) * ( this.counts[ 1 ] - 1 ) * ( this.counts[ 2 ] - 1 );

	}

	/**
	 * Writes the 8 corner probes of the box around (x, y, z) and their trilinear weights.
	 * Allocation-free.
	 * @returns The box index, x fastest (the hint is not needed on a grid and is ignored).
	 */
	interpolate(
		x: number, y: number, z: number, indices: Uint32Array | number[], weights: Float32Array | Float64Array | number[],
	): number {

		const nx = this.counts[ 0 ], ny = this.counts[ 1 ], nz = this.counts[ 2 ];
		const fx = cellCoordinate( x, this.min[ 0 ], this.max[ 0 ], nx );
		const fy = cellCoordinate( y, this.min[ 1 ], this.max[ 1 ], ny );
		const fz = cellCoordinate( z, this.min[ 2 ], this.max[ 2 ], nz );
		const i = Math.min( nx - 2, Math.floor( fx ) ), j = Math.min( ny - 2, Math.floor( fy ) ), k = Math.min( nz - 2, Math.floor( fz ) );
		const tx = fx - i, ty = fy - j, tz = fz - k;

		const base = i + nx * ( j + ny * k );
		const sy = nx, sz = nx * ny;
		indices[ 0 ] = base; weights[ 0 ] = ( 1 - tx ) * ( 1 - ty ) * ( 1 - tz );
		indices[ 1 ] = base + 1; weights[ 1 ] = tx * ( 1 - ty ) * ( 1 - tz );
		indices[ 2 ] = base + sy; weights[ 2 ] = ( 1 - tx ) * ty * ( 1 - tz );
		indices[ 3 ] = base + sy + 1; weights[ 3 ] = tx * ty * ( 1 - tz );
		indices[ 4 ] = base + sz; weights[ 4 ] = ( 1 - tx ) * ( 1 - ty ) * tz;
		indices[ 5 ] = base + sz + 1; weights[ 5 ] = tx * ( 1 - ty ) * tz;
		indices[ 6 ] = base + sz + sy; weights[ 6 ] = ( 1 - tx ) * ty * tz;
		indices[ 7 ] = base + sz + sy + 1; weights[ 7 ] = tx * ty * tz;

		return i + ( nx - 1 ) * ( j + ( ny - 1 ) * k );

	}

}

/** Position in grid units along one axis, clamped to [0, n − 1]. */
function cellCoordinate( v: number, min: number, max: number, n: number ): number {

	const f = ( v - min ) / ( max - min ) * ( n - 1 );
	return f > 0 ? ( f < n - 1 ? f : n - 1 ) : 0;

}

function lerp( a: number, b: number, t: number ): number {

	return t === 1 ? b : a + ( b - a ) * t;

}
