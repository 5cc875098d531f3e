/**
 * Probe placement from meshes: placeFromMeshes on a 100k-triangle mesh (gather the world geometry,
 * candidates from its vertices, TriangleBVH, near-surface and inside classification), and the
 * classification alone on a smaller mesh — with its TriangleBVH versus the same rule on every
 * triangle, and versus the ray-parity vote it replaced (issue 13). Then reduceProbes with fit
 * (re-fit at every insertion, plain and gradient objective, with and without swap passes) on a
 * Sponza-sized synthetic set, against today's reduceProbes (issue 14).
 */

import * as THREE from 'three';
import { placeFromMeshes } from '../src/placement/placeFromMeshes.js';
import { candidatesFromVertices } from '../src/placement/candidatesFromVertices.js';
import { classifyPoints, INSIDE_GEOMETRY, NEAR_SURFACE, OPEN_SPACE, INSIDE_RAY_DIRECTIONS } from '../src/placement/classifyPoints.js';
import { gatherWorldGeometry } from '../src/geometry/gatherWorldGeometry.js';
import { closestPointOnTriangle } from '../src/geometry/closestPointOnTriangle.js';
import { intersectRayTriangle } from '../src/geometry/intersectRayTriangle.js';
import { findClosedShells } from '../src/geometry/findClosedShells.js';
import { facing } from '../src/geometry/windingAlongRay.js';
import { TriangleBVH } from '../src/geometry/TriangleBVH.js';
import { reduceProbes, type ReduceProbesOptions, type ReduceProbesResult } from '../src/placement/reduceProbes.js';
import { irradianceError } from '../src/placement/irradianceError.js';
import { createProbeInterpolator } from '../src/interpolation/createProbeInterpolator.js';
import { evaluateGradientField } from '../src/fitting/evaluateGradientField.js';
import { mulberry32 } from '../src/tetrahedra/spatialOrder.js';
import { timeRuns } from './stats.js';
import type { BenchRow } from './types.js';

export const title = 'Probe placement from meshes (ms, lower is better)';

export const notes = [
	'placeFromMeshes: a TorusKnotGeometry( 1, 0.3, 1000, 50 ) mesh (100,000 triangles) with offset 0.1 and minSpacing 0.06 — '
	+ 'world geometry, drawn sides, vertex candidates, TriangleBVH, then near-surface (minDistance 0.05) and inside classification; '
	+ 'median / min / max of the runs after warm-up. Check: more than 3,000 candidates kept. Target (printed, not asserted): ≤ 5 s.',
	'classifyPoints: vertex candidates of a TorusKnotGeometry( 1, 0.3, 100, 20 ) mesh (4,000 triangles) moved 0.1 out, 0.1 in '
	+ '(inside the tube) and 0.025 out (near the surface), minSpacing 0.06 per set, classified by classifyPoints (its TriangleBVH '
	+ 'built inside the call) and by a brute-force peer running the same tests (closest point, closed shells, 7-ray majority '
	+ 'vote of winding number and first hit with the same early stop) on every triangle. Ratio: ours ÷ brute force. Check: '
	+ 'the same class for every candidate.',
	'Inside test vs ray parity (issue 13): the same candidates classified by classifyPoints and by the vote it replaced '
	+ '(inside when most of the 7 rays cross the triangles an odd number of times, TriangleBVH.countCrossings), each building '
	+ 'its TriangleBVH in the call. Ratio: the new test ÷ parity (the cost of welding corners, finding closed shells and '
	+ 'tracking first hits). Check: the same classes on this closed mesh, where both rules are right.',
	'reduceProbes with fit (issue 14): a Sponza-sized synthetic set — 780 candidates on a jittered 13 × 5 × 12 grid in a 30 × 12 × 18 m '
	+ 'box (each point moved up to 0.3 cell), 1,600 extra fit samples at random in it (fitSamples), reduced to 86 probes; SH from a '
	+ 'synthetic lit room (sky-blue ambient rising with height, a red wall at x = 0 and a green one at x = 30, three coloured point '
	+ 'lamps with 1 / r² falloff and their direction in L1 and L2). Output: the layout\'s mean irradianceError on 3,000 held-out '
	+ 'random points (its own positions, SH and gradients blended as the runtime does), and on the fit set as reduceProbes reports it. '
	+ 'Today\'s reduceProbes (captured SH): strategy \'worst\' (its default) and \'mean\' (placeProbes\' choice). Fit rows: λ by '
	+ 'cross-validation once for the steps and again for the final fit; swaps: the default 2 passes. Ratios: ÷ today\'s \'worst\' and '
	+ '\'mean\'. hullTrials \'local\' rows: trials that move the hull estimated in the edited tetrahedralization, outer cells held (an '
	+ 'option, off by default: other layouts). The last row: the swap passes the experiment runs (swaps: 4, swapTrials: 12). Target '
	+ '(issue 14, printed, not asserted): reduce + fit ≤ 2 s.',
];

const OFFSET = 0.1, MIN_SPACING = 0.06, MIN_DISTANCE = OFFSET / 2;

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const material = new THREE.MeshBasicMaterial();
	const rows: BenchRow[] = [];

	log( 'placeFromMeshes, 100k triangles …' );
	const knot = new THREE.Mesh( new THREE.TorusKnotGeometry( 1, 0.3, 1000, 50 ), material );
	const triangles = gatherWorldGeometry( knot ).triangles.length / 9;
	const placed = timeRuns( () => placeFromMeshes( knot, { offset: OFFSET, minSpacing: MIN_SPACING } ), 20, 5000 );
	const kept = placed.result.length / 3;
	rows.push( {
		case: `${triangles.toLocaleString( 'en-US' )} triangles (torus knot)`, subject: 'ours, placeFromMeshes', unit: 'ms', ...placed.summary,
		output: `${kept.toLocaleString( 'en-US' )} candidates kept`, status: kept > 3000 ? 'valid' : 'too few candidates',
		targets: [ { text: '≤ 5,000 ms', met: placed.summary.median <= 5000 } ],
	} );
	knot.geometry.dispose();

	log( 'classifyPoints vs brute force, 4k triangles …' );
	const small = gatherWorldGeometry( new THREE.Mesh( new THREE.TorusKnotGeometry( 1, 0.3, 100, 20 ), material ) );
	// Moved out (open space), in (inside the tube) and barely out (near the surface): every class occurs.
	const parts = [ OFFSET, - OFFSET, MIN_DISTANCE / 2 ].map( ( offset ) => candidatesFromVertices(
		small.vertexPositions, small.vertexNormals, { offset, minSpacing: MIN_SPACING }
	) );
	const points = new Float64Array( parts.reduce( ( sum, part ) => sum + part.length, 0 ) );
	parts.reduce( ( at, part ) => { points.set( part, at ); return at + part.length; }, 0 );
	const name = `${( small.triangles.length / 9 ).toLocaleString( 'en-US' )} triangles (torus knot), `
		+ `${( points.length / 3 ).toLocaleString( 'en-US' )} candidates`;
	const ours = timeRuns( () => classifyPoints( points, small.triangles, { minDistance: MIN_DISTANCE } ), 50, 3000 );
	const brute = timeRuns( () => classifyBruteForce( points, small.triangles, MIN_DISTANCE ), 10, 5000 );
	const same = ours.result.every( ( c, i ) => c === brute.result[ i ] );
	rows.push( {
		case: name, subject: 'ours, classifyPoints (TriangleBVH)', unit: 'ms', ...ours.summary, output: classCounts( ours.result ),
		status: same ? 'same classes as brute force' : 'DIFFERS from brute force',
		peer: 'brute force', ratio: ours.summary.median / brute.summary.median,
	} );
	rows.push( { case: name, subject: 'brute force (every triangle)', unit: 'ms', ...brute.summary, output: classCounts( brute.result ) } );

	log( 'inside test vs ray parity, 4k triangles …' );
	const parity = timeRuns( () => classifyByParity( points, small.triangles, MIN_DISTANCE ), 50, 3000 );
	const agree = ours.result.every( ( c, i ) => c === parity.result[ i ] );
	rows.push( {
		case: name, subject: 'ours, classifyPoints (inside test)', unit: 'ms', ...ours.summary, output: classCounts( ours.result ),
		status: agree ? 'same classes as parity' : 'DIFFERS from parity', peer: 'ray parity (before issue 13)',
		ratio: ours.summary.median / parity.summary.median,
	} );
	rows.push( { case: name, subject: 'ray parity (before issue 13)', unit: 'ms', ...parity.summary, output: classCounts( parity.result ) } );
	material.dispose();

	log( 'reduceProbes with fit, Sponza-sized synthetic set …' );
	rows.push( ...reduceWithFitRows( log ) );
	return rows;

}

/** The classification before issue 13: near-surface test, then a 7-ray majority vote of crossing parity, on a TriangleBVH. */
function classifyByParity( points: Float64Array, triangles: Float64Array, minDistance: number ): Uint8Array {

	const bvh = new TriangleBVH( triangles ), d = INSIDE_RAY_DIRECTIONS, rays = d.length / 3;
	const classes = new Uint8Array( points.length / 3 );
	for ( let i = 0; i < classes.length; i ++ ) {

		const x = points[ 3 * i ], y = points[ 3 * i + 1 ], z = points[ 3 * i + 2 ];
		if ( bvh.anyWithin( x, y, z, minDistance ) ) {

			classes[ i ] = NEAR_SURFACE;
			continue;

		}

		let odd = 0;
		for ( let r = 0; r < rays; r ++ ) {

			if ( bvh.countCrossings( x, y, z, d[ 3 * r ], d[ 3 * r + 1 ], d[ 3 * r + 2 ] ) % 2 === 1 ) odd ++;
			if ( 2 * odd > rays || 2 * ( r + 1 - odd ) >= rays ) break;

		}

		classes[ i ] = 2 * odd > rays ? INSIDE_GEOMETRY : OPEN_SPACE;

	}

	return classes;

}

/** classifyPoints' tests and vote, run on every triangle instead of a BVH's candidates. */
function classifyBruteForce( points: Float64Array, triangles: Float64Array, minDistance: number ): Uint8Array {

	const count = points.length / 3, triangleCount = triangles.length / 9, rays = INSIDE_RAY_DIRECTIONS.length / 3;
	const d = INSIDE_RAY_DIRECTIONS, r2 = minDistance * minDistance, scratch = new Float64Array( 6 );
	const orientation = findClosedShells( triangles, new Int8Array( triangleCount ).fill( 1 ) ).orientation;
	const classes = new Uint8Array( count );
	for ( let i = 0; i < count; i ++ ) {

		const x = points[ 3 * i ], y = points[ 3 * i + 1 ], z = points[ 3 * i + 2 ];
		let near = false;
		for ( let t = 0; t < triangleCount && ! near; t ++ ) {

			const k = 9 * t;
			near = closestPointOnTriangle(
				x, y, z, triangles[ k ], triangles[ k + 1 ], triangles[ k + 2 ], triangles[ k + 3 ], triangles[ k + 4 ], triangles[ k + 5 ],
				triangles[ k + 6 ], triangles[ k + 7 ], triangles[ k + 8 ], scratch
			) <= r2;

		}

		if ( near ) {

			classes[ i ] = NEAR_SURFACE;
			continue;

		}

		let inside = 0;
		for ( let r = 0; r < rays; r ++ ) {

			// InsideTest's vote: the winding number over the closed shells > 0, or a first hit on an undrawn side (all drawn front here).
			const dx = d[ 3 * r ], dy = d[ 3 * r + 1 ], dz = d[ 3 * r + 2 ];
			let winding = 0, nearest = Infinity, first = - 1;
			for ( let t = 0; t < triangleCount; t ++ ) {

				const hit = intersectRayTriangle( triangles, t, x, y, z, dx, dy, dz );
				if ( hit <= 0 ) continue;
				if ( hit < nearest ) {

					nearest = hit;
					first = t;

				}

				if ( orientation[ t ] !== 0 ) winding += facing( triangles, t, dx, dy, dz ) > 0 ? orientation[ t ] : - orientation[ t ];

			}

			if ( winding > 0 || ( first >= 0 && facing( triangles, first, dx, dy, dz ) > 0 ) ) inside ++;
			if ( 2 * inside > rays || 2 * ( r + 1 - inside ) >= rays ) break;

		}

		classes[ i ] = 2 * inside > rays ? INSIDE_GEOMETRY : OPEN_SPACE;

	}

	return classes;

}

/** `'… open, … inside, … near'`. */
function classCounts( classes: Uint8Array ): string {

	let open = 0, inside = 0, near = 0;
	for ( const c of classes ) {

		if ( c === OPEN_SPACE ) open ++;
		else if ( c === INSIDE_GEOMETRY ) inside ++;
		else near ++;

	}

	return `${open} open, ${inside} inside, ${near} near`;

}

/** The reduceProbes rows of issue 14: today's reduction and the re-fitting one, on the synthetic Sponza-sized set. */
function reduceWithFitRows( log: ( message: string ) => void ): BenchRow[] {

	const set = sponzaSizedSet();
	const count = ( points: Float64Array ): string => ( points.length / 3 ).toLocaleString( 'en-US' );
	const name = `${count( set.dense )} candidates + ${count( set.extra )} fit samples → 86`;
	const heldOut = ( result: ReduceProbesResult ): number => irradianceError( evaluateGradientField(
		createProbeInterpolator( result.positions ), result.positions, result.sh, result.gradients, set.evaluation
	), set.evaluationSH ).mean;
	const percent = ( value: number ): string => `${( 100 * value ).toFixed( 1 )} %`;
	const fitSamples = { positions: set.extra, sh: set.extraSH };
	const cases: { subject: string; options: Partial<ReduceProbesOptions>; fitted: boolean }[] = [
		{ subject: 'today\'s reduceProbes, strategy \'worst\'', options: {}, fitted: false },
		{ subject: 'today\'s reduceProbes, strategy \'mean\'', options: { strategy: 'mean' }, fitted: false },
		{ subject: 'ours, fit (plain), no swaps', options: { fit: true, swaps: false, fitSamples }, fitted: true },
		{ subject: 'ours, fit (plain) + swaps', options: { fit: true, fitSamples }, fitted: true },
		{ subject: 'ours, fit (gradients), no swaps', options: { fit: { gradients: true }, swaps: false, fitSamples }, fitted: true },
		{ subject: 'ours, fit (gradients) + swaps', options: { fit: { gradients: true }, fitSamples }, fitted: true },
		{ subject: 'ours, fit (plain) + swaps, hullTrials \'local\'', options: { fit: true, fitSamples, hullTrials: 'local' }, fitted: true },
		{
			subject: 'ours, fit (gradients) + swaps, hullTrials \'local\'', options: { fit: { gradients: true }, fitSamples, hullTrials: 'local' },
			fitted: true,
		},
		{
			subject: 'ours, fit (gradients) + 4 swap passes × 12 trials (the experiment\'s)',
			options: { fit: { gradients: true }, swaps: 4, swapTrials: 12, fitSamples }, fitted: true,
		},
	];
	const rows: BenchRow[] = [];
	let worst = NaN, mean = NaN;
	for ( const { subject, options, fitted } of cases ) {

		log( `  ${subject} …` );
		const timed = timeRuns( () => reduceProbes( set.dense, set.denseSH, { targetCount: 86, ...options } ), 3, 20_000 );
		const result = timed.result, median = timed.summary.median;
		if ( ! fitted && options.strategy === undefined ) worst = median;
		if ( ! fitted && options.strategy === 'mean' ) mean = median;
		const valid = result.keep.length === 86 && ( fitted ? result.fit !== null : result.fit === null );
		rows.push( {
			case: name, subject, unit: 'ms', ...timed.summary,
			output: `held-out error ${percent( heldOut( result ) )}, fit set ${percent( result.error.mean )}`
				+ ( result.fit ? `, λ ${result.fit.lambda.toPrecision( 2 )}` : '' ),
			status: valid ? 'valid' : `${result.keep.length} probes`,
			...( fitted ? {
				ratios: [ { peer: 'today\'s \'worst\'', ratio: median / worst }, { peer: 'today\'s \'mean\'', ratio: median / mean } ],
				targets: [ { text: '≤ 2,000 ms', met: median <= 2000 } ],
			} : {} ),
		} );

	}

	return rows;

}

/** The synthetic Sponza-sized set of {@link reduceWithFitRows} (seeded: the same numbers every run). */
function sponzaSizedSet(): {
	dense: Float64Array; denseSH: Float32Array; extra: Float64Array; extraSH: Float32Array;
	evaluation: Float64Array; evaluationSH: Float32Array;
} {

	const random = mulberry32( 7 ), box = [ 30, 12, 18 ], cells = [ 13, 5, 12 ];
	const dense: number[] = [];
	for ( let k = 0; k < cells[ 2 ]; k ++ ) for ( let j = 0; j < cells[ 1 ]; j ++ ) for ( let i = 0; i < cells[ 0 ]; i ++ ) {

		[ i, j, k ].forEach( ( c, a ) => dense.push( box[ a ] * ( c + 0.5 + 0.6 * ( random() - 0.5 ) ) / cells[ a ] ) );

	}

	const inBox = ( count: number ): Float64Array => Float64Array.from(
		{ length: 3 * count }, ( _, i ) => box[ i % 3 ] * ( 0.02 + 0.96 * random() )
	);
	const densePositions = Float64Array.from( dense ), extra = inBox( 1600 ), evaluation = inBox( 3000 );
	return {
		dense: densePositions, denseSH: litRoom( densePositions ), extra, extraSH: litRoom( extra ),
		evaluation, evaluationSH: litRoom( evaluation ),
	};

}

/** SH of a synthetic lit room at each point: ambient rising with height, a red and a green wall, three coloured point lamps. */
function litRoom( points: Float64Array ): Float32Array {

	const lamps = [ [ 5, 10, 4, 60, 1, 0.9, 0.7 ], [ 22, 9, 12, 40, 0.6, 0.7, 1 ], [ 15, 3, 9, 15, 1, 0.3, 0.2 ] ];
	const sh = new Float32Array( 9 * points.length );
	for ( let p = 0; p < points.length / 3; p ++ ) {

		const x = points[ 3 * p ], y = points[ 3 * p + 1 ], z = points[ 3 * p + 2 ], o = 27 * p;
		for ( let c = 0; c < 3; c ++ ) {

			const wall = c === 0 ? 0.2 * Math.exp( - x / 3 ) : c === 1 ? 0.2 * Math.exp( - ( 30 - x ) / 3 ) : 0.05;
			sh[ o + c ] = 0.3 + 0.02 * y + wall;

		}

		sh[ o + 3 ] += 0.05; // brighter from above
		for ( const [ lx, ly, lz, power, r, g, b ] of lamps ) {

			const dx = lx - x, dy = ly - y, dz = lz - z, d2 = dx * dx + dy * dy + dz * dz + 0.5, d = Math.sqrt( d2 ), e = power / d2 / 12;
			[ r, g, b ].forEach( ( colour, c ) => {

				sh[ o + c ] += e * colour;
				sh[ o + 3 + c ] += 0.8 * e * colour * dy / d; sh[ o + 6 + c ] += 0.8 * e * colour * dz / d;
				sh[ o + 9 + c ] += 0.8 * e * colour * dx / d;
				sh[ o + 18 + c ] += 0.3 * e * colour * ( 3 * dz * dz / d2 - 1 ) / 2;

			} );

		}

	}

	return sh;

}
