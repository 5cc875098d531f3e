/**
 * The point sets of one run, all computed from the scene's geometry and the seeds before anything
 * is captured: the ground truths (one per seed), the dense candidate set the placements choose
 * from, the extra fit points, the grids and the hand-made layout. Each set has its own seed; the
 * ground truths' are never the others' (cli.ts checks it).
 */

import { placeGrid } from '../../src/index.js';
import type { SceneConfig } from './config.js';
import { subsetPositions } from './evaluate.js';
import type { LoadedScene } from './page.js';
import { OPEN, OpenSpaceTest, jitteredGrid, keepOpen, sampleOpenSpace, thinIndices, vertexCandidates, type OpenSpaceSamples } from './samples.js';

/** What {@link pointSets} makes. */
export interface PointSets {

	box: { min: number[]; max: number[] };
	/** The open-space test of the scene's triangles. */
	open: OpenSpaceTest;
	/** Ground truths by seed, in the order asked (the first is the one reported). */
	truths: { seed: number; samples: OpenSpaceSamples }[];
	/** The dense candidates: jittered grid points first (`fromGrid` of them), then vertex candidates. */
	dense: Float64Array;
	fromGrid: number;
	/** The extra fit points, in the order drawn (a shorter set is a prefix of a longer one). */
	fit: OpenSpaceSamples;
	/** The grid curves' probes (GridInterpolator order). */
	grids: { counts: number[]; positions: Float64Array }[];
	hand: { name: string; positions: Float64Array };

}

/** The point sets of a run on `scene` with these seeds and counts. */
export function pointSets(
	scene: LoadedScene, triangles: Float32Array, sides: Int8Array, config: SceneConfig,
	options: { seeds: number[]; samples: number; denseSeed: number; fitPoints: number; fitSeed: number },
): PointSets {

	const box = { min: scene.grid.min, max: scene.grid.max };
	const open = new OpenSpaceTest( triangles, sides, { minDistance: config.minDistance, maxSky: config.maxSky } );
	const truths = options.seeds.map( ( seed ) => ( { seed, samples: sampleOpenSpace( open, box, options.samples, seed ) } ) );
	const gridCandidates = keepOpen( open, jitteredGrid( box, config.denseSpacing, 0.35, options.denseSeed ) ).positions;
	const vertexPoints = keepOpen( open, vertexCandidates( triangles, sides, box, config.vertexOffset, config.vertexSpacing ) ).positions;
	const all = new Float64Array( gridCandidates.length + vertexPoints.length );
	all.set( gridCandidates );
	all.set( vertexPoints, gridCandidates.length );
	const kept = thinIndices( all, config.denseMinSpacing );
	const fromGrid = kept.filter( ( i ) => 3 * i < gridCandidates.length ).length;
	return {
		box, open, truths,
		dense: subsetPositions( all, kept ), fromGrid,
		fit: sampleOpenSpace( open, box, options.fitPoints, options.fitSeed ),
		grids: config.grids.map( ( counts ) => ( { counts, positions: placeGrid( box.min, box.max, counts ) } ) ),
		hand: { name: scene.hand.name, positions: Float64Array.from( scene.hand.positions ) },
	};

}

/** How many of the points the open-space test rejects. */
export function countNotOpen( open: OpenSpaceTest, positions: ArrayLike<number> ): number {

	let n = 0;
	for ( let i = 0; i < positions.length; i += 3 ) {

		if ( open.classify( positions[ i ], positions[ i + 1 ], positions[ i + 2 ] ) !== OPEN ) n ++;

	}

	return n;

}
