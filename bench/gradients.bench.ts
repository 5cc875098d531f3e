/**
 * Gradient probes at run time (issue 14): what blending 4 × 108 floats instead of 4 × 27 costs per object, and what
 * it adds to a frame's `LightProbeVolume.update()`. The shader does not change (it still receives blended SH9), so a
 * frame's render time is the same with and without gradients; the GPU frame loop is capture.bench.ts part 3.
 */

import * as THREE from 'three';
import { blendGradientSH } from '../src/interpolation/blendGradientSH.js';
import { blendSH } from '../src/interpolation/blendSH.js';
import { GridInterpolator } from '../src/interpolation/GridInterpolator.js';
import { TetrahedralMesh } from '../src/interpolation/TetrahedralMesh.js';
import { LightProbeVolume } from '../src/runtime/LightProbeVolume.js';
import { mulberry32, randomPoints } from './datasets.js';
import { collectGarbage, summarize } from './stats.js';
import type { BenchRow } from './types.js';

export const title = 'Gradient probes at run time: blend per object and update() per frame';

export const notes = [
	'1 (blend): 10,000 objects at fixed random points among 1,000 random probes (their tetrahedra\'s indices and weights from TetrahedralMesh.interpolate, computed once), each blended once per pass: blendSH (4 × 27 floats) vs blendGradientSH (4 × 27 SH + 4 × 81 gradient floats and the offsets to the object). A measurement is 100 passes = 1,000,000 blends; plain and gradient measurements alternate, 7 of each; figure: ns per blend, median / min / max. The 8-probe rows do the same with a 10 × 10 × 10 GridInterpolator (trilinear weights). Target (printed, not asserted): gradient ≤ 5× plain (issue 14).',
	'2 (update): LightProbeVolume over the capture bench\'s 4 × 4 × 4 probe layout (a 4 × 3 × 4 m room) with random SH, 500 spheres added in object mode moving on Lissajous paths through the probes (as capture.bench.ts part 3), timed: volume.update() alone (locate from last frame\'s cell, weights, blend, irradiance matrices); moving the spheres is not timed. Plain probes vs the same probes with random gradients (each value uniform in ±0.1 per metre, about 10 % of the SH per probe spacing); the two volumes\' frames alternate; 6 rounds of 200 frames; figure: median of the round medians (ms per update()). The frame cost of gradients is this difference: the rendering is the same.',
];

const OBJECTS = 10_000;
const PASSES = 100;
const MEASUREMENTS = 7;
const BLEND_TARGET = 5;

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const rows: BenchRow[] = [];
	log( 'blend: 4 probes (tetrahedra) …' );
	rows.push( ...blendRows( '1 Blend, 4 probes (tetrahedral), 10k objects × 100 passes (ns/blend)', tetrahedralWeights() ) );
	log( 'blend: 8 probes (grid) …' );
	rows.push( ...blendRows( '1 Blend, 8 probes (trilinear grid), 10k objects × 100 passes (ns/blend)', gridWeights() ) );
	log( 'update(): 500 moving objects …' );
	rows.push( ...updateRows() );
	return rows;

}

/** Per object: probe indices, weights and its position, from an interpolator at fixed random points. */
interface ObjectWeights {
	count: number;
	indices: Uint32Array;
	weights: Float32Array;
	points: Float64Array;
	probes: number;
	positions: Float64Array;
}

function tetrahedralWeights(): ObjectWeights {

	const positions = Float64Array.from( randomPoints( 'probes', 1000, 11 ).points );
	return objectWeights( new TetrahedralMesh( positions ), positions );

}

function gridWeights(): ObjectWeights {

	const grid = new GridInterpolator( [ 0, 0, 0 ], [ 1, 1, 1 ], [ 10, 10, 10 ] );
	return objectWeights( grid, Float64Array.from( grid.positions ) );

}

/** What objectWeights needs of an interpolator. */
interface Weighing {
	weightCount: number;
	interpolate( x: number, y: number, z: number, indices: Uint32Array, weights: Float32Array, hint?: number ): number;
}

function objectWeights( interpolator: Weighing, positions: Float64Array ): ObjectWeights {

	const count = interpolator.weightCount, random = mulberry32( 3 );
	const box = [ Infinity, Infinity, Infinity, - Infinity, - Infinity, - Infinity ];
	for ( let i = 0; i < positions.length; i ++ ) {

		box[ i % 3 ] = Math.min( box[ i % 3 ], positions[ i ] );
		box[ 3 + i % 3 ] = Math.max( box[ 3 + i % 3 ], positions[ i ] );

	}

	const indices = new Uint32Array( count * OBJECTS ), weights = new Float32Array( count * OBJECTS );
	const points = new Float64Array( 3 * OBJECTS );
	const i8 = new Uint32Array( 8 ), w8 = new Float32Array( 8 );
	for ( let o = 0; o < OBJECTS; o ++ ) {

		// The middle 80 % of the box: inside the hull (tetrahedra) or the grid.
		for ( let a = 0; a < 3; a ++ ) points[ 3 * o + a ] = box[ a ] + ( 0.1 + 0.8 * random() ) * ( box[ 3 + a ] - box[ a ] );
		interpolator.interpolate( points[ 3 * o ], points[ 3 * o + 1 ], points[ 3 * o + 2 ], i8, w8, - 1 );
		indices.set( i8.subarray( 0, count ), count * o );
		weights.set( w8.subarray( 0, count ), count * o );

	}

	return { count, indices, weights, points, probes: positions.length / 3, positions };

}

function blendRows( label: string, objects: ObjectWeights ): BenchRow[] {

	const random = mulberry32( 5 );
	const sh = Float32Array.from( { length: 27 * objects.probes }, () => random() );
	const gradients = Float32Array.from( { length: 81 * objects.probes }, () => 0.2 * random() - 0.1 );
	const { count, indices, weights, points, positions } = objects;
	const out = new Float32Array( 27 );
	// Subarray views made once: the timed loops only read them.
	const views = Array.from( { length: OBJECTS }, ( _, o ) => ( {
		indices: indices.subarray( count * o, count * ( o + 1 ) ), weights: weights.subarray( count * o, count * ( o + 1 ) ),
	} ) );
	let checksum = 0;
	const plainPass = () => {

		for ( let o = 0; o < OBJECTS; o ++ ) {

			const v = views[ o ];
			blendSH( v.indices, v.weights, sh, out, count );
			checksum += out[ 0 ];

		}

	};

	const gradientPass = () => {

		for ( let o = 0; o < OBJECTS; o ++ ) {

			const v = views[ o ];
			const x = points[ 3 * o ], y = points[ 3 * o + 1 ], z = points[ 3 * o + 2 ];
			blendGradientSH( v.indices, v.weights, sh, gradients, positions, x, y, z, out, count );
			checksum += out[ 0 ];

		}

	};

	const time = ( pass: () => void ) => {

		const start = performance.now();
		for ( let p = 0; p < PASSES; p ++ ) pass();
		return ( performance.now() - start ) * 1e6 / ( PASSES * OBJECTS ); // ns per blend

	};

	for ( let warm = 0; warm < 3; warm ++ ) { time( plainPass ); time( gradientPass ); }
	const plain: number[] = [], gradient: number[] = [];
	for ( let m = 0; m < MEASUREMENTS; m ++ ) {

		collectGarbage();
		plain.push( time( plainPass ) );
		gradient.push( time( gradientPass ) );

	}

	if ( ! Number.isFinite( checksum ) ) throw new Error( 'a blend produced a non-finite value' );
	const p = summarize( plain ), g = summarize( gradient ), ratio = g.median / p.median;
	const row = ( subject: string, s: ReturnType<typeof summarize> ): BenchRow => ( {
		case: label, subject, unit: 'ns/blend', median: s.median, min: s.min, max: s.max, runs: s.runs,
	} );
	return [
		{ ...row( 'plain probes: blendSH', p ), output: `${count} × 27 floats` },
		{
			...row( 'gradient probes: blendGradientSH', g ), output: `${count} × 108 floats`, peer: 'blendSH', ratio,
			targets: count === 4 ? [ { text: `≤ ${BLEND_TARGET}× blendSH`, met: ratio <= BLEND_TARGET } ] : undefined,
		},
	];

}

const SPHERES = 500;
const ROUNDS = 6;
const FRAMES = 200;

function updateRows(): BenchRow[] {

	// The capture bench's layout: 4 × 4 × 4 probes at the cell centres of a 4 × 3 × 4 m room (centre at y = 1.5).
	const positions: number[] = [];
	for ( let iz = 0; iz < 4; iz ++ ) for ( let iy = 0; iy < 4; iy ++ ) for ( let ix = 0; ix < 4; ix ++ ) {

		positions.push( - 2 + ( ix + 0.5 ), 3 * ( iy + 0.5 ) / 4, - 2 + ( iz + 0.5 ) );

	}

	const random = mulberry32( 9 );
	const sh = Float32Array.from( { length: 27 * 64 }, ( _, k ) => ( k % 27 < 3 ? 1 : 0.2 ) * random() );
	const gradients = Float32Array.from( { length: 81 * 64 }, () => 0.2 * random() - 0.1 );
	const geometry = new THREE.SphereGeometry( 0.08, 16, 12 );
	const phases = Float32Array.from( { length: 6 * SPHERES }, () => random() );
	const setUp = ( withGradients: boolean ) => {

		const volume = new LightProbeVolume( { positions, sh, gradients: withGradients ? gradients : undefined } );
		const spheres = Array.from( { length: SPHERES }, () => new THREE.Mesh( geometry, new THREE.MeshStandardMaterial() ) );
		move( spheres, 0 );
		for ( const sphere of spheres ) volume.add( sphere );
		return { volume, spheres };

	};

	// Lissajous paths inside the probes' hull (x, z in ±1.4, y in 0.45 … 2.55), as in capture.bench.ts part 3.
	const move = ( spheres: THREE.Mesh[], step: number ) => {

		const t = step * 0.02;
		for ( let i = 0; i < spheres.length; i ++ ) {

			const f = phases.subarray( 6 * i, 6 * i + 6 );
			spheres[ i ].position.set(
				1.4 * Math.sin( ( 0.5 + f[ 0 ] ) * t + 6.283 * f[ 1 ] ),
				1.5 + 1.05 * Math.sin( ( 0.5 + f[ 2 ] ) * t + 6.283 * f[ 3 ] ),
				1.4 * Math.sin( ( 0.5 + f[ 4 ] ) * t + 6.283 * f[ 5 ] ),
			);

		}

	};

	const variants = [ setUp( false ), setUp( true ) ];
	const frame = ( v: { volume: LightProbeVolume; spheres: THREE.Mesh[] }, step: number ) => {

		move( v.spheres, step );
		const start = performance.now();
		v.volume.update();
		return performance.now() - start;

	};

	let step = 0;
	for ( let warm = 0; warm < 300; warm ++, step ++ ) for ( const v of variants ) frame( v, step );
	const medians: number[][] = [ [], [] ];
	const pairs: number[] = [];
	for ( let round = 0; round < ROUNDS; round ++ ) {

		collectGarbage();
		const times: number[][] = [ [], [] ];
		for ( let f = 0; f < FRAMES; f ++, step ++ ) {

			// Alternate which variant goes first, so both see the same machine load.
			const order = f % 2 === 0 ? [ 0, 1 ] : [ 1, 0 ];
			for ( const k of order ) times[ k ].push( frame( variants[ k ], step ) );
			pairs.push( times[ 1 ][ f ] / times[ 0 ][ f ] );

		}

		for ( let k = 0; k < 2; k ++ ) medians[ k ].push( summarize( times[ k ] ).median );

	}

	// The uniforms are what the frame renders with: both variants must have written finite matrices.
	for ( const { volume, spheres } of variants ) {

		const matrices = volume.getUniforms( spheres[ 0 ] )!.probeVolumeMatrices.value;
		if ( ! matrices.every( Number.isFinite ) ) throw new Error( 'update() wrote non-finite matrices' );
		volume.dispose();

	}

	geometry.dispose();
	const p = summarize( medians[ 0 ] ), g = summarize( medians[ 1 ] );
	const label = `2 update(), ${SPHERES} moving spheres in object mode, 64 probes (ms/update)`;
	const row = ( subject: string, s: ReturnType<typeof summarize> ): BenchRow => ( {
		case: label, subject, unit: 'ms', median: s.median, min: s.min, max: s.max, runs: s.runs,
	} );
	return [
		{ ...row( 'plain probes', p ), output: `${( p.median * 1e6 / SPHERES ).toFixed( 0 )} ns per object` },
		{
			...row( 'gradient probes (random gradients ±0.1 /m)', g ), peer: 'plain probes', ratio: g.median / p.median,
			output: `${( g.median * 1e6 / SPHERES ).toFixed( 0 )} ns per object; +${( ( g.median - p.median ) * 1e3 ).toFixed( 0 )} µs per frame; `
				+ `paired ${summarize( pairs ).median.toFixed( 2 )}×`,
		},
	];

}
