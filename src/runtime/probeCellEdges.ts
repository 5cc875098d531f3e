import { GridInterpolator } from '../interpolation/GridInterpolator.js';
import { PlanarMesh } from '../interpolation/PlanarMesh.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import { ProbeLineInterpolator } from './ProbeLineInterpolator.js';
import type { ProbeZones } from './ProbeZones.js';

/*
 * The cells of a volume as line segments, for LightProbeVolumeHelper: the unique edges of its
 * tetrahedra (or triangles, segments along a line, grid boxes), and the probe spacing that sizes
 * the helper's spheres by default.
 */

/** Slot pairs of a grid box's 12 edges, in GridInterpolator's corner order (x fastest). */
export const GRID_BOX_EDGES = [ 0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7 ];

/**
 * The unique edges of the cells objects are lit by, as pairs of probe ids (smaller id first),
 * sorted: the volume's interpolator, or with zones each zone's own cells (an object in a zone
 * blends only those). A custom interpolator of another kind has no edges to show.
 * @param slots Number of probe id slots (the volume's `count`).
 */
export function cellEdges( interpolator: ProbeInterpolator, zones: ProbeZones | null, slots: number ): Uint32Array {

	const keys = new Set<number>();
	if ( zones === null ) {

		addEdges( interpolator, null, slots, keys );

	} else {

		for ( const zone of zones.zones ) addEdges( zone.interpolator, zone.probes, slots, keys );

	}

	// Keys are a · slots + b with a < b: exact in a double up to 2^26 probes, and sorting them sorts the pairs.
	const sorted = Float64Array.from( keys ).sort();
	const edges = new Uint32Array( 2 * sorted.length );
	for ( let e = 0; e < sorted.length; e ++ ) {

		const a = Math.floor( sorted[ e ] / slots );
		edges[ 2 * e ] = a;
		edges[ 2 * e + 1 ] = sorted[ e ] - a * slots;

	}

	return edges;

}

/** Adds the edges of one interpolator's cells to `keys`, its probe k being `probes[ k ]` (or k). */
function addEdges( interpolator: ProbeInterpolator, probes: Uint32Array | null, slots: number, keys: Set<number> ): void {

	const add = ( a: number, b: number ) => {

		const i = probes ? probes[ a ] : a, j = probes ? probes[ b ] : b;
		if ( i !== j ) keys.add( i < j ? i * slots + j : j * slots + i );

	};

	if ( interpolator instanceof TetrahedralMesh ) {

		const t = interpolator.tetrahedra;
		for ( let k = 0; k < t.length; k += 4 ) {

			add( t[ k ], t[ k + 1 ] ); add( t[ k ], t[ k + 2 ] ); add( t[ k ], t[ k + 3 ] );
			add( t[ k + 1 ], t[ k + 2 ] ); add( t[ k + 1 ], t[ k + 3 ] ); add( t[ k + 2 ], t[ k + 3 ] );

		}

	} else if ( interpolator instanceof PlanarMesh ) {

		const t = interpolator.triangles;
		for ( let k = 0; k < t.length; k += 3 ) { add( t[ k ], t[ k + 1 ] ); add( t[ k + 1 ], t[ k + 2 ] ); add( t[ k + 2 ], t[ k ] ); }

	} else if ( interpolator instanceof ProbeLineInterpolator ) {

		const order = interpolator.order;
		for ( let k = 0; k + 1 < order.length; k ++ ) add( order[ k ], order[ k + 1 ] );

	} else if ( interpolator instanceof GridInterpolator ) {

		const [ nx, ny, nz ] = interpolator.counts;
		for ( let k = 0; k < nz; k ++ ) for ( let j = 0; j < ny; j ++ ) for ( let i = 0; i < nx; i ++ ) {

			const p = i + nx * ( j + ny * k );
			if ( i + 1 < nx ) add( p, p + 1 );
			if ( j + 1 < ny ) add( p, p + nx );
			if ( k + 1 < nz ) add( p, p + nx * ny );

		}

	}

}

/**
 * The median distance from a probe to its nearest neighbour, over the probes on an edge — exact
 * for Delaunay cells, grids and lines, whose edges include every probe's nearest neighbour — or
 * 0 when there are no edges.
 * @param p Probe positions, x, y, z per probe id.
 */
export function medianNearestDistance( p: ArrayLike<number>, edges: Uint32Array, slots: number ): number {

	const nearest = new Float64Array( slots ).fill( Infinity );
	for ( let e = 0; e < edges.length; e += 2 ) {

		const a = 3 * edges[ e ], b = 3 * edges[ e + 1 ];
		const d = Math.hypot( p[ a ] - p[ b ], p[ a + 1 ] - p[ b + 1 ], p[ a + 2 ] - p[ b + 2 ] );
		if ( d < nearest[ edges[ e ] ] ) nearest[ edges[ e ] ] = d;
		if ( d < nearest[ edges[ e + 1 ] ] ) nearest[ edges[ e + 1 ] ] = d;

	}

	const finite = nearest.filter( ( d ) => d < Infinity ).sort();
	if ( finite.length === 0 ) return 0;
	const middle = finite.length >> 1;
	return finite.length % 2 === 1 ? finite[ middle ] : 0.5 * ( finite[ middle - 1 ] + finite[ middle ] );

}
