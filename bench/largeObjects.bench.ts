/**
 * Large objects on the CPU side: what relighting a floor per vertex, or resampling its 3D SH
 * texture, costs when its probes change or it moves — against the one blend per object that the
 * object mode does every frame. Runs in Node (no GPU: the vertex attributes and the texture's data
 * are filled on the CPU; uploading them is the renderer's business).
 */

import * as THREE from 'three';
import { readFileSync } from 'node:fs';
import { LightProbeVolume } from '../src/runtime/LightProbeVolume.js';
import { ProbeVertexLighting } from '../src/runtime/ProbeVertexLighting.js';
import { ProbeVolumeTexture } from '../src/runtime/ProbeVolumeTexture.js';
import { mulberry32 } from '../src/tetrahedra/spatialOrder.js';
import { collectGarbage, summarize } from './stats.js';
import type { BenchRow } from './types.js';

export const title = 'Large objects: per-vertex and 3D-texture lighting, CPU (ms, lower is better)';

export const notes = [
	'Probes: Sponza\'s hand-made layout (scenes/sponza.json, 85 probes, random SH). Floors: a plane over the courtyard, x ∈ [−14, 14], z ∈ [−5.5, 5.5] at y = 1 (inside the probes\' hull) and at y = 0.2 (below the lowest probe, y = 0.54: every vertex extrapolated by the outer cells), tessellated to about 10,000 and 100,000 vertices.',
	'ours, vertex: ProbeVertexLighting.compute() — locate + blend per vertex (walking from the previous vertex\'s cell) and E(n) for its normal (irradiance) or the 27 SH floats (sh). ours, texture: ProbeVolumeTexture.resample() at 32³ nodes over the floor\'s box (half-float texels). Peer: LightProbeVolume.sample() once — the object mode\'s per-frame cost for the whole floor. Each figure: median / min / max of 15 runs after 10 warm-ups. Ratio: time per vertex (per texture node) ÷ the time of one object-mode blend — about 1 means per-vertex lighting costs one object blend per vertex.',
];

const RUNS = 15;

export async function run( log: ( message: string ) => void ): Promise<BenchRow[]> {

	const layout = JSON.parse( readFileSync( new URL( '../scenes/sponza.json', import.meta.url ), 'utf8' ) ) as { positions: number[] };
	const random = mulberry32( 3 );
	const count = layout.positions.length / 3;
	const volume = new LightProbeVolume( { positions: layout.positions, sh: Float32Array.from( { length: 27 * count }, () => random() ) } );
	const rows: BenchRow[] = [];

	const point = [ 0, 1, 0 ], sh = new Float32Array( 27 );
	const objectMode = time( () => volume.sample( point, sh ), 20000 );
	for ( const [ height, where ] of [ [ 1, 'inside the hull' ], [ 0.2, 'below the hull' ] ] as const ) {

		for ( const segments of [ [ 140, 70 ], [ 440, 226 ] ] ) {

			const geometry = new THREE.PlaneGeometry( 28, 11, segments[ 0 ], segments[ 1 ] )
				.rotateX( - Math.PI / 2 ).translate( 0, height, 0 );
			const vertices = geometry.getAttribute( 'position' ).count;
			const name = `floor, ${Math.round( vertices / 1000 ).toLocaleString( 'en-US' )}k vertices, ${where}`;
			for ( const output of [ 'irradiance', 'sh' ] as const ) {

				log( `${name}: vertex ${output} …` );
				const mesh = new THREE.Mesh( geometry.clone(), new THREE.MeshStandardMaterial() );
				const lighting = new ProbeVertexLighting( mesh, volume, { output } );
				const summary = summarize( repeat( () => lighting.compute() ) );
				rows.push( { case: name, subject: `ours, vertex (${output})`, unit: 'ms', ...summary, output: `${( summary.median * 1e6 / vertices ).toFixed( 0 )} ns per vertex`, peer: 'one object-mode blend, per vertex', ratio: summary.median / vertices / objectMode } );
				lighting.dispose();
				mesh.geometry.dispose();

			}

			if ( segments[ 0 ] === 140 ) {

				log( `${name}: texture 32³ …` );
				const texture = new ProbeVolumeTexture( volume, new THREE.Box3().setFromBufferAttribute( geometry.getAttribute( 'position' ) as THREE.BufferAttribute ), { resolution: 32 } );
				const summary = summarize( repeat( () => texture.resample() ) );
				const nodes = texture.resolution.x * texture.resolution.y * texture.resolution.z;
				rows.push( { case: name, subject: 'ours, texture 32³ resample', unit: 'ms', ...summary, output: `${texture.resolution.toArray().join( '×' )} nodes, ${( summary.median * 1e6 / nodes ).toFixed( 0 )} ns per node`, peer: 'one object-mode blend, per node', ratio: summary.median / nodes / objectMode } );
				texture.dispose();

			}

			geometry.dispose();

		}

	}

	rows.push( { case: 'any floor', subject: 'peer: LightProbeVolume.sample(), one blend per object', unit: 'ms', median: objectMode, min: objectMode, max: objectMode, runs: 1, output: `${( objectMode * 1e6 ).toFixed( 0 )} ns per call (median of 9 batches of 20,000)` } );
	return rows;

}

function repeat( work: () => unknown ): number[] {

	for ( let i = 0; i < 10; i ++ ) work();
	const times: number[] = [];
	for ( let i = 0; i < RUNS; i ++ ) {

		collectGarbage();
		const start = performance.now();
		work();
		times.push( performance.now() - start );

	}

	return times;

}

/** Median time of one call, from 9 batches of `calls` calls each (one call is far below a timer tick). */
function time( work: () => unknown, calls: number ): number {

	for ( let i = 0; i < 100; i ++ ) work();
	const times: number[] = [];
	for ( let batch = 0; batch < 9; batch ++ ) {

		const start = performance.now();
		for ( let i = 0; i < calls; i ++ ) work();
		times.push( ( performance.now() - start ) / calls );

	}

	return summarize( times ).median;

}
