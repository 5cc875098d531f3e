import { describe, expect, it } from 'vitest';
import { ChangedPoints } from '../../src/placement/ChangedPoints.js';
import { PointGrid } from '../../src/placement/PointGrid.js';
import { readReduceOptions } from '../../src/placement/reduceOptions.js';
import { createRefitContext, fitLayout, type FittedLayout } from '../../src/placement/refitLayout.js';
import { createProbeInterpolator } from '../../src/interpolation/createProbeInterpolator.js';
import { mulberry32 } from '../../src/tetrahedra/spatialOrder.js';
import { bumpField, sampleField } from './fields.js';

/*
 * ChangedPoints.inMesh skips the points whose cell (a tetrahedron, or an outer cell with the same
 * triangle and vertex normals) the edit kept. Checked against brute force: every point located in
 * a fresh interpolator of the edited layout, listed when its weights differ from the layout's (a
 * probe of weight > 0 without a slot of the same weight to 1e-12) or it blended the moved probe.
 */

const SAME_WEIGHT = 1e-12;

/** A jittered 5 × 5 × 5 grid of candidates in the unit cube and 300 extra fit samples. */
function fittedSet(): { layout: FittedLayout; positions: Float64Array; visitOrder: Uint32Array } {

	const random = mulberry32( 5 ), n = 5, dense: number[] = [];
	for ( let k = 0; k < n; k ++ ) for ( let j = 0; j < n; j ++ ) for ( let i = 0; i < n; i ++ ) {

		dense.push( ...[ i, j, k ].map( ( c ) => ( c + 0.5 + 0.5 * ( random() - 0.5 ) ) / n ) );

	}

	const positions = Float64Array.from( dense ), extra = Float64Array.from( { length: 900 }, () => random() );
	const sh = sampleField( bumpField, positions ), extraSH = sampleField( bumpField, extra );
	const settings = readReduceOptions( 'test', positions, sh, positions.length / 3, {
		targetCount: 30, fit: { lambda: 0.1 }, fitSamples: { positions: extra, sh: extraSH },
	} );
	const context = createRefitContext( 'test', settings );
	// An uneven layout of 30 candidates: many probes on the hull, points outside it on every side.
	const order = Array.from( { length: 30 }, ( _, i ) => ( 37 * i + 11 ) % context.denseCount );
	return { layout: fitLayout( context, order, 0.1, 0 ), positions: context.positions, visitOrder: context.visitOrder };

}

/** The brute-force changed points of `edited` (the layout's positions edited) against `layout`. */
function bruteForce( layout: FittedLayout, edited: Float64Array, positions: Float64Array, moved: number ): Map<number, Float64Array> {

	const mesh = createProbeInterpolator( edited ), out = new Map<number, Float64Array>();
	const indices = new Uint32Array( 4 ), weights = new Float64Array( 4 );
	for ( let j = 0; j < positions.length / 3; j ++ ) {

		weights.fill( 0 );
		mesh.interpolate( positions[ 3 * j ], positions[ 3 * j + 1 ], positions[ 3 * j + 2 ], indices, weights, - 1 );
		const dense = new Float64Array( edited.length / 3 + 1 );
		for ( let s = 0; s < 4; s ++ ) dense[ indices[ s ] ] += weights[ s ];
		// The same weights: each probe of weight > 0 has a slot in the layout with its weight (to 1e-12).
		let same = true, usesMoved = false;
		for ( let s = 0; s < 4; s ++ ) {

			if ( layout.slots[ 4 * j + s ] === moved && moved >= 0 ) usesMoved = true;
			if ( weights[ s ] === 0 ) continue;
			let match = false;
			for ( let r = 0; r < 4; r ++ ) {

				const o = 4 * j + r;
				match ||= layout.slots[ o ] === indices[ s ] && Math.abs( layout.slotWeights[ o ] - weights[ s ] ) <= SAME_WEIGHT;

			}

			if ( ! match ) same = false;

		}

		if ( ! same || usesMoved ) out.set( j, dense );

	}

	return out;

}

/** The entries of `changed` as point → weight per local probe. */
function entries( changed: ChangedPoints, probes: number ): Map<number, Float64Array> {

	const out = new Map<number, Float64Array>();
	for ( let f = 0; f < changed.count; f ++ ) {

		const dense = new Float64Array( probes + 1 );
		for ( let s = 0; s < 4; s ++ ) {

			if ( changed.slots[ 4 * f + s ] >= 0 ) dense[ changed.slots[ 4 * f + s ] ] += changed.weights[ 4 * f + s ];

		}

		out.set( changed.points[ f ], dense );

	}

	return out;

}

/**
 * `found` and `truth` list the same points with the same weights, but for the fit points at probes:
 * on a vertex of many cells, which cell a walk returns (and its zero weights' rounding) depends on
 * where the walk started.
 */
function expectSame( found: Map<number, Float64Array>, truth: Map<number, Float64Array>, layout: FittedLayout ): void {

	const listed = ( map: Map<number, Float64Array> ): number[] => [ ...map.keys() ].filter( ( j ) => ! layout.order.includes( j ) )
		.sort( ( a, b ) => a - b );
	expect( listed( found ) ).toEqual( listed( truth ) );
	for ( const [ j, weights ] of truth ) {

		if ( layout.order.includes( j ) ) continue;
		const mine = found.get( j )!;
		for ( let i = 0; i < weights.length; i ++ ) expect( Math.abs( mine[ i ] - weights[ i ] ) ).toBeLessThanOrEqual( 1e-9 );

	}

}

describe( 'ChangedPoints.inMesh', () => {

	it( 'lists exactly the points whose weights a hull-moving edit changes, with their new weights', () => {

		const { layout, positions, visitOrder } = fittedSet();
		const size = layout.order.length;
		expect( layout.outside.some( ( o ) => o === 1 ) ).toBe( true );
		let skipped = 0, moves = 0; // outer points whose weights stay: the ones the kept outer cells spare
		for ( let r = 0; r < size; r ++ ) {

			if ( layout.hullVertex[ r ] !== 1 ) continue;
			// Move the hull vertex a little inward, toward the layout's centre: the hull changes, most outer cells do not.
			const edited = layout.positions.slice();
			for ( let a = 0; a < 3; a ++ ) edited[ 3 * r + a ] += 0.15 * ( 0.5 - edited[ 3 * r + a ] );
			const changed = new ChangedPoints( positions.length / 3 );
			changed.inMesh( createProbeInterpolator( edited ), positions, visitOrder, layout, r );
			const truth = bruteForce( layout, edited, positions, r );
			expectSame( entries( changed, size ), truth, layout );
			for ( let j = 0; j < positions.length / 3; j ++ ) if ( layout.outside[ j ] === 1 && ! truth.has( j ) ) skipped ++;
			moves ++;

		}

		expect( moves ).toBeGreaterThan( 4 );
		expect( skipped ).toBeGreaterThan( 0 );

	} );

	it( 'lists exactly the points an insertion outside the hull changes', () => {

		const { layout, positions, visitOrder } = fittedSet();
		const size = layout.order.length;
		let tried = 0;
		for ( let c = 0; c < positions.length / 3 && tried < 6; c ++ ) {

			if ( layout.outside[ c ] !== 1 ) continue;
			const edited = new Float64Array( 3 * ( size + 1 ) );
			edited.set( layout.positions );
			edited.set( positions.subarray( 3 * c, 3 * c + 3 ), 3 * size );
			const changed = new ChangedPoints( positions.length / 3 );
			changed.inMesh( createProbeInterpolator( edited ), positions, visitOrder, layout, - 1 );
			expectSame( entries( changed, size + 1 ), bruteForce( layout, edited, positions, - 1 ), layout );
			tried ++;

		}

		expect( tried ).toBe( 6 );

	} );

} );

describe( 'PointGrid', () => {

	it( 'keeps each cell\'s coordinates in the order of its points', () => {

		const random = mulberry32( 3 ), positions = Float64Array.from( { length: 3000 }, () => 10 * random() );
		const grid = new PointGrid( positions );
		for ( let q = 0; q < grid.points.length; q ++ ) {

			const j = grid.points[ q ];
			expect( [ ...grid.sorted.subarray( 3 * q, 3 * q + 3 ) ] ).toEqual( [ ...positions.subarray( 3 * j, 3 * j + 3 ) ] );

		}

	} );

} );
