import { IRRADIANCE_C1, IRRADIANCE_C2, IRRADIANCE_C3, IRRADIANCE_C4, IRRADIANCE_C5 } from '../sh/SHBasis.js';
import { makeIrradianceNonNegative } from '../sh/makeNonNegative.js';
import { minIrradiance } from '../sh/minimumOverSphere.js';
import { GridInterpolator } from '../interpolation/GridInterpolator.js';
import { PlanarMesh } from '../interpolation/PlanarMesh.js';
import { TetrahedralMesh } from '../interpolation/TetrahedralMesh.js';
import type { ProbeInterpolator } from '../interpolation/ProbeInterpolator.js';
import type { SampleDesign } from './sampleDesign.js';

/*
 * The non-negative step after a fit (docs/fitting.md): every probe's SH windowed until its
 * irradiance is ≥ 0 in every direction (makeIrradianceNonNegative), then each gradient probe's G
 * scaled by the largest t ∈ [0, 1] keeping c + t·G·d non-negative for every offset d it must
 * reach: to each probe it shares a cell with, and to each fit sample it blends outside such cells.
 * Irradiance is affine in d, so the cell corners cover the whole cell.
 */

// max over unit normals of |factor of coefficient b| in the irradiance (irradianceAt's c0 … c8):
// an upper bound of how fast a gradient can lower it, for a cheap test before the exact minimum.
const FACTOR_BOUND = [
	IRRADIANCE_C4, 2 * IRRADIANCE_C2, 2 * IRRADIANCE_C2, 2 * IRRADIANCE_C2,
	IRRADIANCE_C1, IRRADIANCE_C1, Math.max( Math.abs( IRRADIANCE_C3 - IRRADIANCE_C5 ), IRRADIANCE_C5 ), IRRADIANCE_C1, IRRADIANCE_C1,
];

// Scratch for one probe at a time.
const shifted = new Float64Array( 27 );
const unscaled = new Float64Array( 81 );
const channelMinimum = new Float64Array( 3 );

/**
 * Makes the fitted field non-negative in irradiance, in place: each probe's `sh`, and with
 * `gradients` each probe's term c + G·(q − p) at its cell neighbours and fit samples.
 * @param samplePositions 3 per sample of `design`.
 */
export function makeFitNonNegative(
	sh: Float32Array, gradients: Float32Array | null, probePositions: ArrayLike<number>,
	interpolator: ProbeInterpolator, design: SampleDesign, samplePositions: Float64Array,
): void {

	makeIrradianceNonNegative( sh );
	if ( gradients === null ) return;
	const neighbours = cellNeighbours( interpolator, design );
	const touching = samplesOfProbes( design, ( j ) => ! insideLinkedCell( interpolator, design, samplePositions, j ) );
	const offsets: number[] = [];
	design.localToGlobal.forEach( ( i, t ) => {

		offsets.length = 0;
		const px = probePositions[ 3 * i ], py = probePositions[ 3 * i + 1 ], pz = probePositions[ 3 * i + 2 ];
		const offsetTo = ( points: ArrayLike<number>, n: number ): void => {

			offsets.push( points[ 3 * n ] - px, points[ 3 * n + 1 ] - py, points[ 3 * n + 2 ] - pz );

		};

		for ( const n of neighbours[ t ] ) offsetTo( probePositions, n );
		for ( const j of touching[ t ] ) offsetTo( samplePositions, j );
		const scale = largestSafeScale( sh, gradients, i, offsets );
		if ( scale < 1 ) scaleGradient( sh, gradients, i, offsets, scale );

	} );

}

/**
 * Stores t·G for probe i, shrinking t a little at a time until the float32-rounded values pass the
 * check themselves (zero gradient, always safe, after 40 tries).
 */
function scaleGradient( sh: Float32Array, gradients: Float32Array, i: number, offsets: number[], scale: number ): void {

	const g = gradients.subarray( 81 * i, 81 * i + 81 );
	unscaled.set( g );
	let t = scale;
	for ( let attempt = 0; attempt <= 40; attempt ++ ) {

		for ( let k = 0; k < 81; k ++ ) g[ k ] = attempt < 40 ? unscaled[ k ] * t : 0;
		if ( attempt === 40 || largestSafeScale( sh, gradients, i, offsets ) === 1 ) return;
		t *= Math.max( 0, 1 - 1e-6 * 2 ** attempt );

	}

}

/**
 * The largest t ≤ 1 with irradiance(c + t·G·d) ≥ 0 in every direction for every offset d;
 * the feasible t of one d form an interval from 0 (irradiance is concave in t at its minimum).
 */
function largestSafeScale( sh: Float32Array, gradients: Float32Array, i: number, offsets: number[] ): number {

	const c = 27 * i, g = 81 * i;
	// Offsets shorter than the radius cannot reach below zero: the channel minimum over the
	// gradient's fastest possible decrease.
	minIrradiance( sh, c, channelMinimum );
	let radius = Infinity;
	for ( let channel = 0; channel < 3; channel ++ ) {

		let rate = 0;
		for ( let b = 0; b < 9; b ++ ) {

			const k = 3 * b + channel;
			const x = gradients[ g + k ], y = gradients[ g + 27 + k ], z = gradients[ g + 54 + k ];
			rate += FACTOR_BOUND[ b ] * Math.sqrt( x * x + y * y + z * z );

		}

		if ( rate > 0 ) radius = Math.min( radius, Math.max( 0, channelMinimum[ channel ] ) / rate );

	}

	let t = 1;
	for ( let o = 0; o < offsets.length; o += 3 ) {

		const dx = offsets[ o ], dy = offsets[ o + 1 ], dz = offsets[ o + 2 ];
		if ( t * Math.sqrt( dx * dx + dy * dy + dz * dz ) <= radius ) continue;
		if ( feasible( sh, gradients, i, t * dx, t * dy, t * dz ) ) continue;
		let lo = 0, hi = t;
		for ( let step = 0; step < 40; step ++ ) {

			const mid = 0.5 * ( lo + hi );
			if ( feasible( sh, gradients, i, mid * dx, mid * dy, mid * dz ) ) lo = mid; else hi = mid;

		}

		t = lo;

	}

	return t;

}

function feasible( sh: Float32Array, gradients: Float32Array, i: number, dx: number, dy: number, dz: number ): boolean {

	const c = 27 * i, g = 81 * i;
	for ( let k = 0; k < 27; k ++ ) {

		shifted[ k ] = sh[ c + k ] + gradients[ g + k ] * dx + gradients[ g + 27 + k ] * dy + gradients[ g + 54 + k ] * dz;

	}

	return minIrradiance( shifted ) >= 0;

}

/** Per local probe, the global probes it shares a cell with: from the samples, and from the mesh's own cells when it has them. */
function cellNeighbours( interpolator: ProbeInterpolator, design: SampleDesign ): Set<number>[] {

	const local = design.localToGlobal.length;
	const neighbours = Array.from( { length: local }, () => new Set<number>() );
	const globalToLocal = new Map<number, number>();
	design.localToGlobal.forEach( ( i, t ) => globalToLocal.set( i, t ) );
	const link = ( cell: ArrayLike<number> ): void => {

		for ( let a = 0; a < cell.length; a ++ ) {

			const t = globalToLocal.get( cell[ a ] );
			if ( t === undefined ) continue;
			for ( let b = 0; b < cell.length; b ++ ) if ( b !== a ) neighbours[ t ].add( cell[ b ] );

		}

	};

	const { slots, probes } = design;
	const cell: number[] = [];
	for ( let j = 0; j < design.count; j ++ ) {

		cell.length = 0;
		for ( let s = 0; s < slots; s ++ ) if ( probes[ slots * j + s ] >= 0 ) cell.push( design.localToGlobal[ probes[ slots * j + s ] ] );
		link( cell );

	}

	if ( interpolator instanceof TetrahedralMesh ) {

		const tetrahedra = interpolator.tetrahedra;
		for ( let c = 0; c < tetrahedra.length; c += 4 ) link( tetrahedra.subarray( c, c + 4 ) );

	} else if ( interpolator instanceof PlanarMesh ) {

		const triangles = interpolator.triangles;
		for ( let c = 0; c < triangles.length; c += 3 ) link( triangles.subarray( c, c + 3 ) );

	} else if ( interpolator instanceof GridInterpolator ) {

		const [ nx, ny, nz ] = interpolator.counts;
		design.localToGlobal.forEach( ( i, t ) => {

			const x = i % nx, y = Math.floor( i / nx ) % ny, z = Math.floor( i / ( nx * ny ) );
			for ( let dz = - 1; dz <= 1; dz ++ ) for ( let dy = - 1; dy <= 1; dy ++ ) for ( let dx = - 1; dx <= 1; dx ++ ) {

				const a = x + dx, b = y + dy, c = z + dz;
				if ( a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz || ( dx === 0 && dy === 0 && dz === 0 ) ) continue;
				neighbours[ t ].add( a + nx * ( b + ny * c ) );

			}

		} );

	}

	return neighbours;

}

/**
 * Whether sample j lies in a cell whose corners {@link cellNeighbours} links (an inner tetrahedron,
 * a grid box): the checks at the corners already cover it, irradiance being affine in the offset.
 */
function insideLinkedCell( interpolator: ProbeInterpolator, design: SampleDesign, samplePositions: Float64Array, j: number ): boolean {

	// Outer cells return cellCount + f; 'nearestFace' returns a tetrahedron for outside points too.
	if ( interpolator instanceof TetrahedralMesh ) {

		return interpolator.outside === 'outerCells' && design.cells[ j ] >= 0 && design.cells[ j ] < interpolator.cellCount;

	}

	if ( ! ( interpolator instanceof GridInterpolator ) ) return false;
	for ( let a = 0; a < 3; a ++ ) {

		const v = samplePositions[ 3 * j + a ];
		if ( ! ( v >= interpolator.min[ a ] && v <= interpolator.max[ a ] ) ) return false;

	}

	return true;

}

/** Per local probe, the samples that give it weight and that `needsCheck` keeps. */
function samplesOfProbes( design: SampleDesign, needsCheck: ( sample: number ) => boolean ): number[][] {

	const touching = Array.from( { length: design.localToGlobal.length }, (): number[] => [] );
	for ( let j = 0; j < design.count; j ++ ) {

		if ( ! needsCheck( j ) ) continue;
		for ( let s = 0; s < design.slots; s ++ ) {

			const t = design.probes[ design.slots * j + s ];
			if ( t >= 0 ) touching[ t ].push( j );

		}

	}

	return touching;

}
